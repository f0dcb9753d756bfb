#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <lithostress/base/input_error.h>
#include <lithostress/boundary_conditions/rigid_body_support.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace lithostress
{
  namespace
  {
    /** Below this value of c^T G c (|c| = 1) a motion is free: a free
     * motion gives round-off (< 1e-25), a held one at least (d/L)^2 for a
     * single constrained point at distance d from the centre of a body of
     * size L, or the fraction of the boundary a spring covers. */
    constexpr double free_threshold = 1e-12;

    std::string
    point_text(const Point<2> &p, const double scale, const std::string &unit)
    {
      std::ostringstream out;
      out << std::setprecision(4) << "(" << p[0] / scale << ", " << p[1] / scale
          << ") " << unit;
      return out.str();
    }
  } // namespace

  template <int dim>
  void
  RigidBodySupport<dim>::check(
    const DoFHandler<dim>                            &dof_handler,
    const FiniteElementSpace<dim>                    &fe_space,
    const AffineConstraints<double>                  &constraints,
    const LoadCollection<dim>                        &loads,
    const double                                      length_scale,
    const std::string                                &length_unit,
    const std::vector<std::pair<Point<dim>, double>> &interface_points)
  {
    static_assert(dim == 2, "rigid-body modes are written for 2-D");
    const MPI_Comm     comm      = dof_handler.get_communicator();
    const unsigned int per_field = 3;
    const unsigned int n_modes   = per_field * fe_space.n_fields();
    const auto        &tria      = dof_handler.get_triangulation();

    // Centre and size of the body: the bounding box of the coarse mesh,
    // whose vertices every rank holds.
    const BoundingBox<dim> box(tria.get_vertices());
    const Point<dim>       centre = box.center();
    const double           size   = box.get_boundary_points().first.distance(
      box.get_boundary_points().second);

    // The modes: mode k of field f is translation x, translation y,
    // rotation (3 f + 0, 1, 2) ...
    const auto mode_value = [&](const unsigned int field,
                                const unsigned int d,
                                const Point<dim>  &x,
                                const unsigned int k) {
      if (k / per_field != field)
        return 0.0;
      const unsigned int m = k % per_field;
      if (m < dim)
        return m == d ? 1.0 : 0.0;
      return (d == 0 ? -(x[1] - centre[1]) : (x[0] - centre[0])) / size;
    };
    // ... at the DoFs the owned constraint lines name (the boundary's, not
    // the whole mesh's: Gmsh meshes can have tens of thousands of coarse
    // cells).
    const IndexSet &owned = dof_handler.locally_owned_dofs();
    std::map<types::global_dof_index, Vector<double>> modes;
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        {
          modes.emplace(line.index, Vector<double>());
          for (const auto &entry : line.entries)
            modes.emplace(entry.first, Vector<double>());
        }
    {
      const Quadrature<dim> support(fe_space.unit_support_points());
      const FE_Q<dim>       scalar(fe_space.degree());
      FEValues<dim>         values(fe_space.mapping(),
                           scalar,
                           support,
                           update_quadrature_points);
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          {
            const auto &fe = cell->get_fe();
            dofs.resize(fe.n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            bool needed = false;
            for (const types::global_dof_index i : dofs)
              {
                const auto m = modes.find(i);
                needed = needed || (m != modes.end() && m->second.size() == 0);
              }
            if (!needed)
              continue;
            values.reinit(
              static_cast<typename Triangulation<dim>::cell_iterator>(cell));
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const auto m = modes.find(dofs[i]);
                if (m == modes.end() || m->second.size() != 0)
                  continue;
                const auto         ci    = fe.system_to_component_index(i);
                const unsigned int field = ci.first / dim;
                const unsigned int d     = ci.first % dim;
                m->second.reinit(n_modes);
                for (unsigned int k = 0; k < n_modes; ++k)
                  m->second[k] =
                    mode_value(field, d, values.quadrature_point(ci.second), k);
              }
          }
    }

    // G from the constraint lines of owned DoFs.
    FullMatrix<double> G(n_modes, n_modes);
    Vector<double>     residual(n_modes);
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        {
          residual = modes.at(line.index);
          for (const auto &[j, a] : line.entries)
            residual.add(-a, modes.at(j));
          for (unsigned int k = 0; k < n_modes; ++k)
            for (unsigned int l = 0; l < n_modes; ++l)
              G(k, l) += residual[k] * residual[l];
        }

    // ... and from the vertical springs on boundary parts.
    std::vector<types::boundary_id> parts;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          parts.push_back(cell->face(f)->boundary_id());
    std::sort(parts.begin(), parts.end());
    parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
    const auto springs = loads.vertical_springs(parts);
    if (!springs.empty())
      {
        const FE_Q<dim>       fe(1);
        const QGauss<dim - 1> quadrature(3);
        FEFaceValues<dim>     face_values(fe_space.mapping(),
                                      fe,
                                      quadrature,
                                      update_quadrature_points |
                                        update_normal_vectors |
                                        update_JxW_values);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int f : cell->face_indices())
              if (cell->face(f)->at_boundary() &&
                  springs.count(cell->face(f)->boundary_id()) != 0 &&
                  springs.at(cell->face(f)->boundary_id()) > 0)
                {
                  face_values.reinit(
                    static_cast<typename Triangulation<dim>::cell_iterator>(
                      cell),
                    f);
                  const unsigned int field =
                    fe_space.field_of(cell->active_fe_index());
                  for (const unsigned int q :
                       face_values.quadrature_point_indices())
                    {
                      const Point<dim> &x = face_values.quadrature_point(q);
                      const double      w =
                        std::abs(face_values.normal_vector(q)[dim - 1]) *
                        face_values.JxW(q) / size;
                      for (unsigned int k = 0; k < n_modes; ++k)
                        for (unsigned int l = 0; l < n_modes; ++l)
                          G(k, l) += w * mode_value(field, dim - 1, x, k) *
                                     mode_value(field, dim - 1, x, l);
                    }
                }
      }
    // ... and from elastic faults: the relative motion of the two fields.
    if (fe_space.n_fields() == 2)
      for (const auto &[x, weight] : interface_points)
        for (unsigned int d = 0; d < dim; ++d)
          for (unsigned int k = 0; k < n_modes; ++k)
            for (unsigned int l = 0; l < n_modes; ++l)
              G(k, l) += weight / size *
                         (mode_value(1, d, x, k) - mode_value(0, d, x, k)) *
                         (mode_value(1, d, x, l) - mode_value(0, d, x, l));
    Utilities::MPI::sum(G, comm, G);

    // The free motions: the null space of G.
    LAPACKFullMatrix<double> lapack(n_modes);
    lapack = G;
    Vector<double>     eigenvalues;
    FullMatrix<double> null_space;
    lapack.compute_eigenvalues_symmetric(
      -1.0, free_threshold, 1e-15, eigenvalues, null_space);
    if (eigenvalues.size() == 0)
      return;

    // Describe the free motions of the first body that has any.
    for (unsigned int field = 0; field < fe_space.n_fields(); ++field)
      {
        std::vector<Vector<double>> free;
        for (unsigned int m = 0; m < eigenvalues.size(); ++m)
          {
            Vector<double> c(per_field);
            for (unsigned int k = 0; k < per_field; ++k)
              c[k] = null_space(field * per_field + k, m);
            if (c.l2_norm() > 1e-6)
              free.push_back(c);
          }
        if (free.empty())
          continue;
        const std::string body =
          fe_space.n_fields() == 1
            ? std::string("the body")
            : "body " + std::to_string(field + 1) + " (the " +
                (field == 0 ? "footwall" : "hanging wall") + ")";
        const double scale = length_scale;
        std::string  what;
        const auto   translation_text = [](const Vector<double> &c) {
          if (std::abs(c[1]) < 1e-6 * std::abs(c[0]))
            return std::string("x");
          if (std::abs(c[0]) < 1e-6 * std::abs(c[1]))
            return std::string("y");
          std::ostringstream out;
          out << std::setprecision(3) << "the direction (" << c[0] << ", "
              << c[1] << ")";
          return out.str();
        };
        const auto rotation_centre = [&](const Vector<double> &c) {
          // u = (t_x - w (y - c_y), t_y + w (x - c_x)) with w = c[2]/size
          // vanishes at the centre of rotation.
          const double w = c[2] / size;
          Point<dim>   p = centre;
          p[0] -= c[1] / w;
          p[1] += c[0] / w;
          // Round-off relative to the body's size is not a coordinate.
          for (unsigned int d = 0; d < dim; ++d)
            if (std::abs(p[d]) < 1e-9 * size)
              p[d] = 0;
          return p;
        };
        if (free.size() == per_field)
          what = body +
                 " is free to move as a rigid body (to translate in x and "
                 "y and to rotate): nothing holds it; prescribe "
                 "displacements on boundary parts or add a spring";
        else if (free.size() == 2)
          {
            // A translation in the free plane: the combination without
            // rotation.
            Vector<double> t(per_field);
            t.add(free[1][2], free[0]);
            t.add(-free[0][2], free[1]);
            if (t.l2_norm() < 1e-6)
              t = free[0];
            t /= t.l2_norm();
            if (std::abs(free[0][2]) < 1e-6 && std::abs(free[1][2]) < 1e-6)
              what = body +
                     " is free to translate in x and y: no part prescribes "
                     "a displacement that holds it (only a rotation is "
                     "held)";
            else
              {
                Vector<double> r = free[0];
                if (std::abs(free[1][2]) > std::abs(r[2]))
                  r = free[1];
                r.add(-(r * t), t);
                what = body + " is free to translate in " +
                       translation_text(t) + " and to rotate about " +
                       point_text(rotation_centre(r), scale, length_unit) +
                       ": prescribe the other displacement component or "
                       "add a spring";
              }
          }
        else
          {
            const Vector<double> &c = free[0];
            if (std::abs(c[2]) < 1e-6 * c.l2_norm())
              {
                const std::string direction = translation_text(c);
                what = body + " is free to translate in " + direction;
                if (direction == "x")
                  what += ": no part prescribes an x-displacement and no "
                          "spring acts horizontally";
                else if (direction == "y")
                  what += ": no part prescribes a y-displacement and no "
                          "spring (isostatic restoring force) holds it "
                          "vertically";
                else
                  what += ": the prescribed displacements are all normal "
                          "to this direction";
              }
            else
              what = body + " is free to rotate about " +
                     point_text(rotation_centre(c), scale, length_unit) +
                     ": the prescribed displacements (rollers) are all "
                     "tangent to circles about that point; prescribe a "
                     "component that a rotation would change";
          }
        throw_input_error("Boundary conditions/Prescribed displacement parts",
                          what);
      }
  }

  template class RigidBodySupport<2>;
} // namespace lithostress

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <lithostress/base/input_error.h>
#include <lithostress/boundary_conditions/rigid_body_support.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
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

    /** The rigid-body modes of the bodies: mode k of body b (k = 3 b +
     * 0, 1, 2) is the translation in x, in y, and the rotation about the
     * centre of the model scaled by its size, so that all modes are O(1);
     * it is zero on the other bodies. The model is the bounding box of the
     * coarse mesh, whose vertices every rank holds. */
    template <int dim>
    struct RigidBodyModes
    {
      static constexpr unsigned int per_body = 3;

      RigidBodyModes(const Triangulation<dim> &tria,
                     const unsigned int        n_bodies)
          : n_modes(per_body * n_bodies)
      {
        const BoundingBox<dim> box(tria.get_vertices());
        centre = box.center();
        size   = box.get_boundary_points().first.distance(
          box.get_boundary_points().second);
      }

      /** Component @p d at @p x of mode @p k, on body @p body. */
      double
      value(const unsigned int body,
            const unsigned int d,
            const Point<dim>  &x,
            const unsigned int k) const
      {
        if (k / per_body != body)
          return 0.0;
        const unsigned int m = k % per_body;
        if (m < dim)
          return m == d ? 1.0 : 0.0;
        return (d == 0 ? -(x[1] - centre[1]) : (x[0] - centre[0])) / size;
      }

      unsigned int n_modes;
      Point<dim>   centre;
      double       size;
    };

    /** The modes at every DoF the owned constraint lines of
     * @p constraints name (the boundary's, not the whole mesh's: Gmsh
     * meshes can have tens of thousands of coarse cells). */
    template <int dim>
    std::map<types::global_dof_index, Vector<double>>
    modes_at_constrained_dofs(const DoFHandler<dim>           &dof_handler,
                              const FiniteElementSpace<dim>   &fe_space,
                              const AffineConstraints<double> &constraints,
                              const RigidBodies<dim>          &bodies,
                              const RigidBodyModes<dim>       &modes)
    {
      const IndexSet &owned = dof_handler.locally_owned_dofs();
      std::map<types::global_dof_index, Vector<double>> at_dofs;
      for (const auto &line : constraints.get_lines())
        if (owned.is_element(line.index))
          {
            at_dofs.emplace(line.index, Vector<double>());
            for (const auto &entry : line.entries)
              at_dofs.emplace(entry.first, Vector<double>());
          }
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
                const auto m = at_dofs.find(i);
                needed =
                  needed || (m != at_dofs.end() && m->second.size() == 0);
              }
            if (!needed)
              continue;
            const typename Triangulation<dim>::cell_iterator tria_cell = cell;
            values.reinit(tria_cell);
            const unsigned int body = bodies.of(tria_cell);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const auto m = at_dofs.find(dofs[i]);
                if (m == at_dofs.end() || m->second.size() != 0)
                  continue;
                const auto         ci = fe.system_to_component_index(i);
                const unsigned int d  = ci.first % dim;
                m->second.reinit(modes.n_modes);
                for (unsigned int k = 0; k < modes.n_modes; ++k)
                  m->second[k] =
                    modes.value(body, d, values.quadrature_point(ci.second), k);
              }
          }
      return at_dofs;
    }

    /** Add to @p G the form of each owned constraint line u_i = Σ_j a_ij
     * u_j + b_i: the outer product of its residual r_k(i) − Σ_j a_ij
     * r_k(j) over the modes. */
    template <int dim>
    void
    add_constraint_forms(
      FullMatrix<double>                                      &G,
      const AffineConstraints<double>                         &constraints,
      const DoFHandler<dim>                                   &dof_handler,
      const std::map<types::global_dof_index, Vector<double>> &at_dofs)
    {
      const IndexSet &owned = dof_handler.locally_owned_dofs();
      Vector<double>  residual(G.m());
      for (const auto &line : constraints.get_lines())
        if (owned.is_element(line.index))
          {
            residual = at_dofs.at(line.index);
            for (const auto &[j, a] : line.entries)
              residual.add(-a, at_dofs.at(j));
            for (unsigned int k = 0; k < G.m(); ++k)
              for (unsigned int l = 0; l < G.n(); ++l)
                G(k, l) += residual[k] * residual[l];
          }
    }

    /** Add to @p G the form min(1, k L / E) ∫ |n_y| r_k,y r_l,y ds / L of
     * each vertical spring k of @p loads on the owned cells' boundary faces,
     * L the size of the body and E @p youngs_modulus: how strongly a spring
     * holds matters only where it is too weak to hold anything. Returns
     * the largest k L / E of the springs (0 without one). */
    template <int dim>
    double
    add_spring_forms(FullMatrix<double>            &G,
                     const DoFHandler<dim>         &dof_handler,
                     const FiniteElementSpace<dim> &fe_space,
                     const LoadCollection<dim>     &loads,
                     const double                   youngs_modulus,
                     const RigidBodies<dim>        &bodies,
                     const RigidBodyModes<dim>     &modes)
    {
      std::vector<types::boundary_id> parts;
      for (const auto &cell :
           dof_handler.get_triangulation().active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            parts.push_back(cell->face(f)->boundary_id());
      std::sort(parts.begin(), parts.end());
      parts.erase(std::unique(parts.begin(), parts.end()), parts.end());
      const auto springs   = loads.vertical_springs(parts);
      double     strongest = 0;
      for (const auto &[part, k] : springs)
        strongest = std::max(strongest, k * modes.size / youngs_modulus);
      if (springs.empty())
        return strongest;
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
                const typename Triangulation<dim>::cell_iterator tria_cell =
                  cell;
                face_values.reinit(tria_cell, f);
                const unsigned int body = bodies.of(tria_cell);
                for (const unsigned int q :
                     face_values.quadrature_point_indices())
                  {
                    const Point<dim> &x = face_values.quadrature_point(q);
                    const double      relative =
                      springs.at(cell->face(f)->boundary_id()) * modes.size /
                      youngs_modulus;
                    const double w =
                      std::min(1.0, relative) *
                      std::abs(face_values.normal_vector(q)[dim - 1]) *
                      face_values.JxW(q) / modes.size;
                    for (unsigned int k = 0; k < modes.n_modes; ++k)
                      for (unsigned int l = 0; l < modes.n_modes; ++l)
                        G(k, l) += w * modes.value(body, dim - 1, x, k) *
                                   modes.value(body, dim - 1, x, l);
                  }
              }
      return strongest;
    }

    /** Add to @p G the form (w / L) [r_k]^T A^T A [r_l] / max(1, |A|^2)
     * of each of @p couplings (weight w, stiffness A), [r] the jump of the
     * modes from its body 0 to its body 1, L the size of the model. */
    template <int dim>
    void
    add_coupling_forms(FullMatrix<double>                   &G,
                       const std::vector<BodyCoupling<dim>> &couplings,
                       const RigidBodyModes<dim>            &modes)
    {
      std::vector<Tensor<1, dim>> jump(modes.n_modes);
      for (const BodyCoupling<dim> &c : couplings)
        {
          const Tensor<2, dim> AA   = transpose(c.stiffness) * c.stiffness;
          const double         norm = AA.norm();
          if (norm == 0)
            continue;
          const double w = c.JxW / modes.size / std::max(1.0, norm);
          for (unsigned int k = 0; k < modes.n_modes; ++k)
            for (unsigned int d = 0; d < dim; ++d)
              jump[k][d] = modes.value(c.body_1, d, c.position, k) -
                           modes.value(c.body_0, d, c.position, k);
          for (unsigned int k = 0; k < modes.n_modes; ++k)
            if (jump[k].norm() > 0)
              for (unsigned int l = 0; l < modes.n_modes; ++l)
                G(k, l) += w * (jump[k] * (AA * jump[l]));
        }
    }

    /** The centre of each of the @p bodies (of its owned active cells'
     * areas, summed over the ranks): where a message says a body is. */
    template <int dim>
    std::vector<Point<dim>>
    body_centres(const DoFHandler<dim>  &dof_handler,
                 const RigidBodies<dim> &bodies)
    {
      std::vector<double> sums(bodies.n * (dim + 1), 0.);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const typename Triangulation<dim>::cell_iterator tria_cell = cell;
            const unsigned int b = bodies.of(tria_cell);
            const double       a = cell->measure();
            for (unsigned int d = 0; d < dim; ++d)
              sums[b * (dim + 1) + d] += a * cell->center()[d];
            sums[b * (dim + 1) + dim] += a;
          }
      Utilities::MPI::sum(sums, dof_handler.get_communicator(), sums);
      std::vector<Point<dim>> centres(bodies.n);
      for (unsigned int b = 0; b < bodies.n; ++b)
        for (unsigned int d = 0; d < dim; ++d)
          centres[b][d] = sums[b * (dim + 1) + d] /
                          std::max(sums[b * (dim + 1) + dim], 1e-300);
      return centres;
    }

    /** The direction of the translation @p c (x and y components): "x",
     * "y" or "the direction (a, b)". */
    std::string
    translation_text(const Vector<double> &c)
    {
      if (std::abs(c[1]) < 1e-6 * std::abs(c[0]))
        return std::string("x");
      if (std::abs(c[0]) < 1e-6 * std::abs(c[1]))
        return std::string("y");
      std::ostringstream out;
      out << std::setprecision(3) << "the direction (" << c[0] << ", " << c[1]
          << ")";
      return out.str();
    }

    /** The centre of rotation of the motion @p c (translations and
     * rotation of one field): u = (t_x − w (y − c_y), t_y + w (x − c_x))
     * with w = c[2]/size vanishes there. */
    template <int dim>
    Point<dim>
    rotation_centre(const Vector<double> &c, const RigidBodyModes<dim> &modes)
    {
      const double w = c[2] / modes.size;
      Point<dim>   p = modes.centre;
      p[0] -= c[1] / w;
      p[1] += c[0] / w;
      // Round-off relative to the body's size is not a coordinate.
      for (unsigned int d = 0; d < dim; ++d)
        if (std::abs(p[d]) < 1e-9 * modes.size)
          p[d] = 0;
      return p;
    }

    /** What leaves @p body free and how to hold it, given its free
     * motions @p free (a basis of them, each the translations and rotation
     * of one field): all three, a translation and a rotation, two
     * translations, one translation or a rotation about a point. */
    template <int dim>
    std::string
    free_motion_text(const std::vector<Vector<double>> &free,
                     const std::string                 &body,
                     const RigidBodyModes<dim>         &modes,
                     const double                       length_scale,
                     const std::string                 &length_unit)
    {
      if (free.size() == RigidBodyModes<dim>::per_body)
        return body + " is free to move as a rigid body (to translate in x and "
                      "y and to rotate): nothing holds it; prescribe "
                      "displacements on boundary parts or add a spring";
      if (free.size() == 2)
        {
          // A translation in the free plane: the combination without
          // rotation.
          Vector<double> t(RigidBodyModes<dim>::per_body);
          t.add(free[1][2], free[0]);
          t.add(-free[0][2], free[1]);
          if (t.l2_norm() < 1e-6)
            t = free[0];
          t /= t.l2_norm();
          if (std::abs(free[0][2]) < 1e-6 && std::abs(free[1][2]) < 1e-6)
            return body +
                   " is free to translate in x and y: no part prescribes "
                   "a displacement that holds it (only a rotation is "
                   "held)";
          Vector<double> r = free[0];
          if (std::abs(free[1][2]) > std::abs(r[2]))
            r = free[1];
          r.add(-(r * t), t);
          return body + " is free to translate in " + translation_text(t) +
                 " and to rotate about " +
                 point_text(rotation_centre(r, modes),
                            length_scale,
                            length_unit) +
                 ": prescribe the other displacement component or "
                 "add a spring";
        }
      const Vector<double> &c = free[0];
      if (std::abs(c[2]) >= 1e-6 * c.l2_norm())
        return body + " is free to rotate about " +
               point_text(rotation_centre(c, modes),
                          length_scale,
                          length_unit) +
               ": the prescribed displacements (rollers) are all "
               "tangent to circles about that point; prescribe a "
               "component that a rotation would change";
      const std::string direction = translation_text(c);
      std::string       what = body + " is free to translate in " + direction;
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
      return what;
    }
  } // namespace

  template <int dim>
  std::string
  RigidBodySupport<dim>::free_motion(
    const DoFHandler<dim>                &dof_handler,
    const FiniteElementSpace<dim>        &fe_space,
    const AffineConstraints<double>      &constraints,
    const LoadCollection<dim>            &loads,
    const double                          youngs_modulus,
    const RigidBodies<dim>               &bodies,
    const std::vector<BodyCoupling<dim>> &couplings,
    const double                          length_scale,
    const std::string                    &length_unit)
  {
    static_assert(dim == 2, "rigid-body modes are written for 2-D");
    const RigidBodyModes<dim> modes(dof_handler.get_triangulation(), bodies.n);
    const unsigned int        per_body = RigidBodyModes<dim>::per_body;

    // G from the constraint lines of owned DoFs, the vertical springs on
    // boundary parts and the couplings between bodies, summed over the
    // ranks.
    FullMatrix<double> G(modes.n_modes, modes.n_modes);
    add_constraint_forms(G,
                         constraints,
                         dof_handler,
                         modes_at_constrained_dofs(
                           dof_handler, fe_space, constraints, bodies, modes));
    const double springs = Utilities::MPI::max(
      add_spring_forms(
        G, dof_handler, fe_space, loads, youngs_modulus, bodies, modes),
      dof_handler.get_communicator());
    add_coupling_forms(G, couplings, modes);
    Utilities::MPI::sum(G, dof_handler.get_communicator(), G);

    // The free motions: the null space of G.
    LAPACKFullMatrix<double> lapack(modes.n_modes);
    lapack = G;
    Vector<double>     eigenvalues;
    FullMatrix<double> null_space;
    lapack.compute_eigenvalues_symmetric(
      -1.0, free_threshold, 1e-15, eigenvalues, null_space);
    if (eigenvalues.size() == 0)
      return "";

    // Describe the free motions of the first body that has any: a basis
    // of the free motions' parts on that body (two bodies free together
    // give each the same part).
    const std::vector<Point<dim>> centres =
      bodies.n > 1 ? body_centres(dof_handler, bodies)
                   : std::vector<Point<dim>>();
    for (unsigned int b = 0; b < bodies.n; ++b)
      {
        std::vector<Vector<double>> free;
        for (unsigned int m = 0; m < eigenvalues.size(); ++m)
          {
            Vector<double> c(per_body);
            for (unsigned int k = 0; k < per_body; ++k)
              c[k] = null_space(b * per_body + k, m);
            for (const Vector<double> &e : free)
              c.add(-(c * e), e);
            if (c.l2_norm() > 1e-6)
              {
                c /= c.l2_norm();
                free.push_back(c);
              }
          }
        if (free.empty())
          continue;
        const std::string body =
          bodies.n == 1 ? std::string("the body")
                        : "the block around " +
                            point_text(centres[b], length_scale, length_unit);
        std::string weak;
        if (springs > 0 && springs < free_threshold)
          {
            std::ostringstream out;
            out << std::setprecision(3)
                << " (the springs are too weak to hold anything: k L / E = "
                << springs << " at most, L the size of the body)";
            weak = out.str();
          }
        return free_motion_text(free, body, modes, length_scale, length_unit) +
               weak;
      }
    return "";
  }

  template <int dim>
  void
  RigidBodySupport<dim>::check(const DoFHandler<dim>           &dof_handler,
                               const FiniteElementSpace<dim>   &fe_space,
                               const AffineConstraints<double> &constraints,
                               const LoadCollection<dim>       &loads,
                               const double                     youngs_modulus,
                               const RigidBodies<dim>          &bodies,
                               const std::vector<BodyCoupling<dim>> &couplings,
                               const double       length_scale,
                               const std::string &length_unit)
  {
    const std::string free = free_motion(dof_handler,
                                         fe_space,
                                         constraints,
                                         loads,
                                         youngs_modulus,
                                         bodies,
                                         couplings,
                                         length_scale,
                                         length_unit);
    if (!free.empty())
      throw_input_error("Boundary conditions/Prescribed displacement parts",
                        free);
  }

  template class RigidBodySupport<2>;
} // namespace lithostress

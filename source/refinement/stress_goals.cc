#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/hp/fe_values.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/refinement/stress_goals.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <tuple>

namespace lithostress
{
  namespace
  {
    /** The goal's component of the stress (in-plane tensor and σ_zz). */
    template <int dim, typename Component>
    double
    component_of(const Component                component,
                 const SymmetricTensor<2, dim> &s,
                 const double                   zz)
    {
      const double mean = (trace(s) + zz) / 3;
      switch (component)
        {
        case Component::sigma_xx:
          return s[0][0];
        case Component::sigma_yy:
          return s[1][1];
        case Component::sigma_xy:
          return s[0][1];
        case Component::sigma_zz:
          return zz;
        case Component::deviatoric_xx:
          return s[0][0] - mean;
        case Component::deviatoric_yy:
          return s[1][1] - mean;
        case Component::u_x:
        case Component::u_y:
          break;
        }
      return 0;
    }

    /** The area of a simple polygon (shoelace formula). */
    template <int dim>
    double
    polygon_area(const std::vector<Point<dim>> &p)
    {
      double a = 0;
      for (unsigned int i = 0; i < p.size(); ++i)
        {
          const Point<dim> &q = p[i], &r = p[(i + 1) % p.size()];
          a += q[0] * r[1] - r[0] * q[1];
        }
      return std::abs(a) / 2;
    }

    /** The centroid of a simple polygon. */
    template <int dim>
    Point<dim>
    polygon_centroid(const std::vector<Point<dim>> &p)
    {
      double     a = 0;
      Point<dim> c;
      for (unsigned int i = 0; i < p.size(); ++i)
        {
          const Point<dim> &q = p[i], &r = p[(i + 1) % p.size()];
          const double      w = q[0] * r[1] - r[0] * q[1];
          a += w;
          c[0] += (q[0] + r[0]) * w;
          c[1] += (q[1] + r[1]) * w;
        }
      return Point<dim>(c[0] / (3 * a), c[1] / (3 * a));
    }

    /** A convex polygon clipped to the box [lower, upper]
     * (Sutherland–Hodgman, one box side at a time). */
    template <int dim>
    std::vector<Point<dim>>
    clip_to_box(std::vector<Point<dim>> polygon,
                const Point<dim>       &lower,
                const Point<dim>       &upper)
    {
      for (unsigned int d = 0; d < dim; ++d)
        for (const int side : {-1, 1})
          {
            const double bound = side < 0 ? lower[d] : upper[d];
            const auto   keeps = [&](const Point<dim> &p) {
              return side < 0 ? p[d] >= bound : p[d] <= bound;
            };
            std::vector<Point<dim>> kept;
            for (unsigned int i = 0; i < polygon.size(); ++i)
              {
                const Point<dim> &a = polygon[i],
                                 &b = polygon[(i + 1) % polygon.size()];
                if (keeps(a))
                  kept.push_back(a);
                if (keeps(a) != keeps(b))
                  {
                    const double t = (bound - a[d]) / (b[d] - a[d]);
                    kept.push_back(a + t * (b - a));
                  }
              }
            polygon = kept;
            if (polygon.size() < 3)
              return {};
          }
      return polygon;
    }

    /** Where a cell lies with respect to a goal's box. */
    enum class BoxRelation
    {
      apart,
      within,
      cut
    };

    /** Where @p cell lies with respect to the box [@p lower, @p upper],
     * judged by its vertices' bounding box widened by a tenth of the
     * cell's diameter (for curved sides). */
    template <int dim, typename CellIterator>
    BoxRelation
    relation_to_box(const CellIterator &cell,
                    const Point<dim>   &lower,
                    const Point<dim>   &upper)
    {
      Point<dim> lo = cell->vertex(0), hi = cell->vertex(0);
      for (const unsigned int v : cell->vertex_indices())
        for (unsigned int d = 0; d < dim; ++d)
          {
            lo[d] = std::min(lo[d], cell->vertex(v)[d]);
            hi[d] = std::max(hi[d], cell->vertex(v)[d]);
          }
      const double margin = 0.1 * cell->diameter();
      bool         apart = false, within = true;
      for (unsigned int d = 0; d < dim; ++d)
        {
          apart =
            apart || hi[d] + margin < lower[d] || lo[d] - margin > upper[d];
          within =
            within && lo[d] - margin >= lower[d] && hi[d] + margin <= upper[d];
        }
      return apart ? BoxRelation::apart
                   : (within ? BoxRelation::within : BoxRelation::cut);
    }

    /**
     * The quadrature (on the unit cell) of the part of a cell inside a
     * box that cuts it: the Gauss rule on the squares of a quadtree of the
     * unit cell, refined (to 2^-7 of the cell) only where a square
     * straddles the box's edges; each finest straddling square contributes
     * one point, at the centroid of its image clipped to the box, with the
     * clipped area. Exact up to those squares, about 1e-5 of the box's
     * area, so that the goals' change between cycles is the solution's,
     * not the quadrature's.
     */
    template <int dim, typename CellIterator>
    class CutCellQuadrature
    {
    public:
      CutCellQuadrature(const Mapping<dim>  &mapping,
                        const CellIterator  &cell,
                        const Point<dim>    &lower,
                        const Point<dim>    &upper,
                        const Quadrature<1> &gauss_1d)
          : mapping(mapping)
          , cell(cell)
          , lower(lower)
          , upper(upper)
          , gauss_1d(gauss_1d)
      {
      }

      /** The quadrature of the whole quadtree. */
      Quadrature<dim>
      build()
      {
        points.clear();
        weights.clear();
        add_square(Point<dim>(), 1.0, 0);
        return Quadrature<dim>(points, weights);
      }

    private:
      static constexpr unsigned int deepest = 7;

      bool
      in_box(const Point<dim> &p) const
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (p[d] < lower[d] || p[d] > upper[d])
            return false;
        return true;
      }

      /** The points of the square of side @p size at @p corner of the
       * unit cell, @p depth levels down the quadtree: none if its image
       * is apart from the box, the Gauss rule if it lies inside (from
       * depth 2), one clipped point at the deepest level, else its four
       * children's. */
      void
      add_square(const Point<dim>  &corner,
                 const double       size,
                 const unsigned int depth)
      {
        // The square's corners and centre in real space, and their
        // bounding box widened by a tenth of its size (curved sides).
        unsigned int inside = 0, tested = 0;
        Point<dim>   lo, hi;
        for (unsigned int i = 0; i <= 2; ++i)
          for (unsigned int j = 0; j <= 2; ++j)
            if ((i + j) % 2 == 0)
              {
                const Point<dim> p = mapping.transform_unit_to_real_cell(
                  cell, corner + Point<dim>(i * size / 2, j * size / 2));
                inside += in_box(p);
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    lo[d] = tested == 0 ? p[d] : std::min(lo[d], p[d]);
                    hi[d] = tested == 0 ? p[d] : std::max(hi[d], p[d]);
                  }
                ++tested;
              }
        const double widen = 0.1 * lo.distance(hi);
        bool         apart = false;
        for (unsigned int d = 0; d < dim; ++d)
          apart = apart || hi[d] + widen < lower[d] || lo[d] - widen > upper[d];
        if (apart)
          return;
        if (depth >= 2 && inside == tested)
          {
            for (unsigned int i = 0; i < gauss_1d.size(); ++i)
              for (unsigned int j = 0; j < gauss_1d.size(); ++j)
                {
                  points.push_back(corner +
                                   Point<dim>(gauss_1d.point(i)[0] * size,
                                              gauss_1d.point(j)[0] * size));
                  weights.push_back(gauss_1d.weight(i) * gauss_1d.weight(j) *
                                    size * size);
                }
            return;
          }
        if (depth == deepest)
          {
            add_clipped_square(corner, size);
            return;
          }
        for (unsigned int i = 0; i < 2; ++i)
          for (unsigned int j = 0; j < 2; ++j)
            add_square(corner + Point<dim>(i * size / 2, j * size / 2),
                       size / 2,
                       depth + 1);
      }

      /** The finest straddling square at @p corner: its image, taken as
       * the quadrilateral of its mapped corners, clipped to the box; one
       * point at the clipped part's centroid with its area. */
      void
      add_clipped_square(const Point<dim> &corner, const double size)
      {
        std::vector<Point<dim>> corners;
        for (const auto &c : {Point<dim>(0, 0),
                              Point<dim>(1, 0),
                              Point<dim>(1, 1),
                              Point<dim>(0, 1)})
          corners.push_back(
            mapping.transform_unit_to_real_cell(cell, corner + size * c));
        const double                  whole = polygon_area(corners);
        const std::vector<Point<dim>> part = clip_to_box(corners, lower, upper);
        const double                  area = polygon_area(part);
        if (area <= 0 || whole <= 0)
          return;
        // The centroid in unit coordinates, through the affine map of the
        // square's first three corners.
        const Point<dim>     c  = polygon_centroid(part);
        const Tensor<1, dim> e0 = corners[1] - corners[0],
                             e1 = corners[3] - corners[0], r = c - corners[0];
        const double det = e0[0] * e1[1] - e0[1] * e1[0];
        const double u   = (r[0] * e1[1] - r[1] * e1[0]) / det,
                     v   = (e0[0] * r[1] - e0[1] * r[0]) / det;
        points.push_back(corner + Point<dim>(size * std::clamp(u, 0.0, 1.0),
                                             size * std::clamp(v, 0.0, 1.0)));
        weights.push_back(size * size * area / whole);
      }

      const Mapping<dim>     &mapping;
      const CellIterator     &cell;
      const Point<dim>       &lower, &upper;
      const Quadrature<1>    &gauss_1d;
      std::vector<Point<dim>> points;
      std::vector<double>     weights;
    };
  } // namespace

  template <int dim>
  std::string
  StressGoals<dim>::component_name(const Component component)
  {
    switch (component)
      {
      case Component::sigma_xx:
        return "sigma_xx";
      case Component::sigma_yy:
        return "sigma_yy";
      case Component::sigma_xy:
        return "sigma_xy";
      case Component::sigma_zz:
        return "sigma_zz";
      case Component::deviatoric_xx:
        return "deviatoric_xx";
      case Component::deviatoric_yy:
        return "deviatoric_yy";
      case Component::u_x:
        return "u_x";
      case Component::u_y:
        return "u_y";
      }
    return "";
  }

  template <int dim>
  void
  StressGoals<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    prm.enter_subsection("Goals");
    prm.declare_entry(
      "Stress averages",
      "",
      Patterns::Anything(),
      "Quantities of interest: means of a stress component over the part of "
      "the body inside a box, `name: component, x_min, x_max, y_min, y_max; "
      "...` (length unit; component sigma_xx, sigma_yy, sigma_xy, sigma_zz, "
      "deviatoric_xx or deviatoric_yy). Reported each cycle in the "
      "convergence table; `Indicator = goal oriented` refines where their "
      "error arises.");
    prm.declare_entry(
      "Displacement averages",
      "",
      Patterns::Anything(),
      "Quantities of interest: means of a displacement component over the "
      "part of the body inside a box, `name: component, x_min, x_max, "
      "y_min, y_max; ...` (length unit; component u_x or u_y); a thin box "
      "under the top is the surface displacement over its width (a buried "
      "fault's uplift). Reported and used like `Stress averages`; the names "
      "of both entries must differ.");
    prm.declare_entry("Stop at relative change",
                      "0",
                      Patterns::Double(0, 1),
                      "Stop the refinement cycles once every goal has "
                      "changed by less than this fraction of its value since "
                      "the last cycle with at most half as many DoFs (0 = "
                      "run all cycles); not reached within `Number of "
                      "cycles` is an error.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  void
  StressGoals<dim>::parse_parameters(ParameterHandler &prm,
                                     const double      length_scale)
  {
    static_assert(dim == 2, "goal boxes are given in 2-D");
    prm.enter_subsection("Mesh refinement");
    prm.enter_subsection("Goals");
    const std::string stresses      = prm.get("Stress averages");
    const std::string displacements = prm.get("Displacement averages");
    tolerance                       = prm.get_double("Stop at relative change");
    prm.leave_subsection();
    prm.leave_subsection();
    goals.clear();
    parse_goals("Mesh refinement/Goals/Stress averages",
                stresses,
                {Component::sigma_xx,
                 Component::sigma_yy,
                 Component::sigma_xy,
                 Component::sigma_zz,
                 Component::deviatoric_xx,
                 Component::deviatoric_yy},
                length_scale);
    parse_goals("Mesh refinement/Goals/Displacement averages",
                displacements,
                {Component::u_x, Component::u_y},
                length_scale);
  }

  template <int dim>
  void
  StressGoals<dim>::parse_goals(const std::string            &entry,
                                const std::string            &text,
                                const std::vector<Component> &allowed,
                                const double                  length_scale)
  {
    std::string names;
    for (const Component c : allowed)
      names += (names.empty() ? "" : ", ") + component_name(c);
    for (const std::string &item : split_list(text, ';'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          throw_input_error(entry,
                            "`" + item +
                              "` is not `name: component, x_min, x_max, "
                              "y_min, y_max`");
        Goal goal;
        goal.name = split_list(item.substr(0, colon)).empty()
                      ? ""
                      : split_list(item.substr(0, colon))[0];
        const std::vector<std::string> fields =
          split_list(item.substr(colon + 1));
        if (goal.name.empty() || goal.name.find(' ') != std::string::npos)
          throw_input_error(entry,
                            "goal `" + item +
                              "`: its name must be one word before the colon");
        for (const Goal &other : goals)
          if (other.name == goal.name)
            throw_input_error(entry,
                              "the goal name `" + goal.name +
                                "` is given twice");
        if (fields.size() != 5)
          throw_input_error(entry,
                            "goal `" + goal.name +
                              "`: expected a component and four numbers "
                              "(x_min, x_max, y_min, y_max), got `" +
                              item.substr(colon + 1) + "`");
        const auto known =
          std::find_if(allowed.begin(), allowed.end(), [&](const Component c) {
            return fields[0] == component_name(c);
          });
        if (known == allowed.end())
          throw_input_error(entry,
                            "goal `" + goal.name + "`: unknown component `" +
                              fields[0] + "` (" + names + ")");
        goal.component = *known;
        double v[4];
        for (unsigned int i = 0; i < 4; ++i)
          v[i] = parse_number(fields[i + 1], entry) * length_scale;
        if (!(v[0] < v[1]) || !(v[2] < v[3]))
          throw_input_error(entry,
                            "goal `" + goal.name +
                              "`: the box needs x_min < x_max and y_min < "
                              "y_max");
        goal.lower = Point<dim>(v[0], v[2]);
        goal.upper = Point<dim>(v[1], v[3]);
        goals.push_back(goal);
      }
  }

  template <int dim>
  template <typename Integrand>
  void
  StressGoals<dim>::integrate(const unsigned int             k,
                              const DoFHandler<dim>         &dof_handler,
                              const FiniteElementSpace<dim> &fe_space,
                              const Integrand               &integrand) const
  {
    const Goal &goal = goals[k];
    // The cached quadratures belong to the mesh they were made on.
    if (!mesh_changed.connected())
      mesh_changed =
        dof_handler.get_triangulation().signals.any_change.connect([this]() {
          for (auto &cells : cut_cells)
            cells.clear();
        });
    cut_cells.resize(goals.size());
    const UpdateFlags flags = update_gradients | update_values |
                              update_quadrature_points | update_JxW_values;
    // Cells inside the box: the usual Gauss rule. Cells the box cuts: the
    // quadtree rule of CutCellQuadrature, kept until the mesh changes.
    const QGauss<dim>    gauss(fe_space.degree() + 1);
    const QGauss<1>      gauss_1d(fe_space.degree() + 1);
    hp::QCollection<dim> whole;
    for (unsigned int f = 0; f < fe_space.fe_collection().size(); ++f)
      whole.push_back(gauss);
    hp::FEValues<dim>   inside_values(fe_space.mapping_collection(),
                                    fe_space.fe_collection(),
                                    whole,
                                    flags);
    const Mapping<dim> &mapping = fe_space.mapping();
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const BoxRelation relation =
            relation_to_box(cell, goal.lower, goal.upper);
          if (relation == BoxRelation::apart)
            continue;
          if (relation == BoxRelation::within)
            {
              inside_values.reinit(cell);
              const FEValues<dim> &fv = inside_values.get_present_fe_values();
              for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                integrand(cell, fv, q);
              continue;
            }
          auto cached = cut_cells[k].find(cell->id());
          if (cached == cut_cells[k].end())
            cached =
              cut_cells[k]
                .emplace(cell->id(),
                         CutCellQuadrature<dim, CellIterator>(
                           mapping, cell, goal.lower, goal.upper, gauss_1d)
                           .build())
                .first;
          if (cached->second.size() == 0)
            continue;
          FEValues<dim> fv(mapping,
                           fe_space.fe_collection()[cell->active_fe_index()],
                           cached->second,
                           flags);
          fv.reinit(cell);
          for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
            integrand(cell, fv, q);
        }
  }

  template <int dim>
  double
  StressGoals<dim>::area(const unsigned int             k,
                         const DoFHandler<dim>         &dof_handler,
                         const FiniteElementSpace<dim> &fe_space) const
  {
    double area = 0;
    integrate(k,
              dof_handler,
              fe_space,
              [&](const auto &, const FEValues<dim> &fv, const unsigned q) {
                area += fv.JxW(q);
              });
    return Utilities::MPI::sum(area, dof_handler.get_communicator());
  }

  template <int dim>
  void
  StressGoals<dim>::check_regions(const DoFHandler<dim>         &dof_handler,
                                  const FiniteElementSpace<dim> &fe_space) const
  {
    for (unsigned int k = 0; k < goals.size(); ++k)
      {
        if (!(area(k, dof_handler, fe_space) > 0))
          throw_input_error(is_displacement(goals[k].component)
                              ? "Mesh refinement/Goals/Displacement averages"
                              : "Mesh refinement/Goals/Stress averages",
                            "the box of goal `" + goals[k].name +
                              "` does not meet the body");
      }
  }

  template <int dim>
  std::vector<double>
  StressGoals<dim>::values(const DoFHandler<dim>               &dof_handler,
                           const FiniteElementSpace<dim>       &fe_space,
                           const StressModel<dim>              &stress_model,
                           const TrilinosWrappers::MPI::Vector &solution) const
  {
    std::vector<double>                            result;
    std::vector<Tensor<2, dim>>                    grads;
    std::vector<Tensor<1, dim>>                    displacements;
    typename DoFHandler<dim>::active_cell_iterator current;
    for (unsigned int k = 0; k < goals.size(); ++k)
      {
        double sums[2] = {0, 0};
        current        = typename DoFHandler<dim>::active_cell_iterator();
        integrate(
          k,
          dof_handler,
          fe_space,
          [&](const auto &cell, const FEValues<dim> &fv, const unsigned q) {
            if (current.state() != IteratorState::valid || cell != current)
              {
                current      = cell;
                const auto u = fe_space.displacement(
                  fe_space.field_of(cell->active_fe_index()));
                // Only what the goal needs: the values for a displacement,
                // the gradients for a stress.
                if (is_displacement(goals[k].component))
                  {
                    displacements.resize(fv.n_quadrature_points);
                    fv[u].get_function_values(solution, displacements);
                  }
                else
                  {
                    grads.resize(fv.n_quadrature_points);
                    fv[u].get_function_gradients(solution, grads);
                  }
              }
            sums[1] += fv.JxW(q);
            if (is_displacement(goals[k].component))
              {
                sums[0] +=
                  displacements[q][displacement_index(goals[k].component)] *
                  fv.JxW(q);
                return;
              }
            const StressState<dim> s =
              stress_model.stress(cell,
                                  fv.get_quadrature().point(q),
                                  fv.quadrature_point(q),
                                  symmetrize(grads[q]));
            sums[0] += component_of<dim>(goals[k].component, s.in_plane, s.zz) *
                       fv.JxW(q);
          });
        Utilities::MPI::sum(sums, dof_handler.get_communicator(), sums);
        result.push_back(sums[0] / sums[1]);
      }
    return result;
  }

  template <int dim>
  std::vector<double>
  StressGoals<dim>::reference_values(
    const DoFHandler<dim>         &dof_handler,
    const FiniteElementSpace<dim> &fe_space,
    const StressModel<dim>        &stress_model,
    const ReferenceSolution<dim>  &reference) const
  {
    std::vector<double> result;
    for (unsigned int k = 0; k < goals.size(); ++k)
      {
        double sums[2] = {0, 0};
        integrate(
          k,
          dof_handler,
          fe_space,
          [&](const auto &cell, const FEValues<dim> &fv, const unsigned q) {
            sums[1] += fv.JxW(q);
            if (is_displacement(goals[k].component))
              {
                sums[0] += reference.displacement(fv.quadrature_point(
                             q))[displacement_index(goals[k].component)] *
                           fv.JxW(q);
                return;
              }
            const ElasticModuli<dim> &moduli =
              stress_model.moduli(cell->material_id());
            const SymmetricTensor<2, dim> s =
              reference.stress(fv.quadrature_point(q));
            const double zz = moduli.sigma_zz(moduli.compliance() * s);
            sums[0] += component_of<dim>(goals[k].component, s, zz) * fv.JxW(q);
          });
        Utilities::MPI::sum(sums, dof_handler.get_communicator(), sums);
        result.push_back(sums[0] / sums[1]);
      }
    return result;
  }

  template <int dim>
  void
  StressGoals<dim>::assemble_dual_rhs(
    const unsigned int               k,
    const DoFHandler<dim>           &dof_handler,
    const FiniteElementSpace<dim>   &fe_space,
    const StressModel<dim>          &stress_model,
    const AffineConstraints<double> &constraints,
    TrilinosWrappers::MPI::Vector   &rhs) const
  {
    rhs = 0;
    // The box's area first: J_k is a mean.
    const double region = area(k, dof_handler, fe_space);
    AssertThrow(region > 0, ExcMessage("a goal's box left the body"));

    // Cell by cell: the local vector of the cell's quadrature points inside
    // the box, distributed when the loop moves to the next cell.
    Vector<double>                                 local;
    std::vector<types::global_dof_index>           dofs;
    typename DoFHandler<dim>::active_cell_iterator current;
    const auto                                     flush = [&]() {
      if (current.state() == IteratorState::valid && local.size() > 0)
        constraints.distribute_local_to_global(local, dofs, rhs);
    };
    integrate(
      k,
      dof_handler,
      fe_space,
      [&](const auto &cell, const FEValues<dim> &fv, const unsigned q) {
        if (current.state() != IteratorState::valid || cell != current)
          {
            flush();
            current = cell;
            local.reinit(fv.get_fe().n_dofs_per_cell());
            dofs.resize(fv.get_fe().n_dofs_per_cell());
            cell->get_dof_indices(dofs);
          }
        const auto u =
          fe_space.displacement(fe_space.field_of(cell->active_fe_index()));
        if (is_displacement(goals[k].component))
          {
            const unsigned int c = displacement_index(goals[k].component);
            for (unsigned int i = 0; i < fv.get_fe().n_dofs_per_cell(); ++i)
              local(i) += fv[u].value(i, q)[c] * fv.JxW(q) / region;
            return;
          }
        const types::material_id  id      = cell->material_id();
        const bool                uniform = stress_model.uniform_tangent(id);
        const ElasticModuli<dim> &moduli  = stress_model.step_moduli(id);
        for (unsigned int i = 0; i < fv.get_fe().n_dofs_per_cell(); ++i)
          {
            const SymmetricTensor<2, dim> strain =
              fv[u].symmetric_gradient(i, q);
            if (strain.norm() == 0)
              continue;
            // (The law is asked only where its tangent varies.)
            StressState<dim> sigma;
            if (uniform)
              {
                sigma.in_plane = moduli.stress(strain);
                sigma.zz       = moduli.sigma_zz(strain);
              }
            else
              sigma =
                stress_model.step_stress(id, fv.quadrature_point(q), strain);
            local(i) +=
              component_of<dim>(goals[k].component, sigma.in_plane, sigma.zz) *
              fv.JxW(q) / region;
          }
      });
    flush();
    rhs.compress(VectorOperation::add);
  }

  template <int dim>
  std::pair<double, std::string>
  StressGoals<dim>::largest_change(const std::vector<double> &previous,
                                   const std::vector<double> &current) const
  {
    std::pair<double, std::string> largest(0, "");
    for (unsigned int k = 0; k < goals.size(); ++k)
      {
        const double change = std::abs(current[k] - previous[k]) /
                              std::max(std::abs(current[k]), 1e-300);
        if (change >= largest.first)
          largest = {change, goals[k].name};
      }
    return largest;
  }

  template <int dim>
  bool
  StressGoals<dim>::converged(const std::vector<double> &previous,
                              const std::vector<double> &current) const
  {
    return tolerance > 0 && !goals.empty() && previous.size() == goals.size() &&
           largest_change(previous, current).first < tolerance;
  }

  template <int dim>
  typename StressGoals<dim>::CycleChange
  StressGoals<dim>::record_cycle(const unsigned long long   dofs,
                                 const std::vector<double> &values)
  {
    CycleChange                result;
    const std::vector<double> *before = nullptr;
    for (const auto &[earlier_dofs, earlier] : history)
      if (2 * earlier_dofs <= dofs)
        {
          before               = &earlier;
          result.compared_with = earlier_dofs;
        }
    if (before)
      {
        std::tie(result.change, result.goal) = largest_change(*before, values);
        result.converged                     = converged(*before, values);
      }
    history.emplace_back(dofs, values);
    return result;
  }

  template <int dim>
  std::vector<double>
  StressGoals<dim>::weights(const std::vector<double> &values)
  {
    double largest = 0;
    for (const double v : values)
      largest = std::max(largest, std::abs(v));
    std::vector<double> result;
    for (const double v : values)
      result.push_back(1 / std::max({std::abs(v), 1e-6 * largest, 1e-300}));
    return result;
  }

  template class StressGoals<2>;
} // namespace lithostress

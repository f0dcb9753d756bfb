#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools_common.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/refinement/mesh_refinement.h>

namespace lithostress
{
  namespace
  {
    /** The stress every result reports (initial strains and creep
     * included), as the stress-recovery indicator takes it. */
    template <int dim>
    typename MeshRefinement<dim>::StressOf
    reported_stress_of(const StressModel<dim> &stress_model)
    {
      return [&stress_model](
               const typename Triangulation<dim>::active_cell_iterator &cell,
               const Point<dim>                                        &unit,
               const Point<dim>                                        &p,
               const SymmetricTensor<2, dim> &strain) {
        return stress_model.stress(cell, unit, p, strain).in_plane;
      };
    }

    /** Component @p c of the stress @p s in the order of the recovered
     * stress field: the diagonal, then the shear components. */
    template <int dim>
    double
    stress_component(const SymmetricTensor<2, dim> &s, const unsigned int c)
    {
      if (c < dim)
        return s[c][c];
      return (dim == 2) ? s[0][1]
                        : (c == 3 ? s[0][1] : (c == 4 ? s[1][2] : s[0][2]));
    }

    /** The groups of cells whose stresses are averaged together: one per
     * law (moduli and Maxwell time; materials of the same law share it)
     * and displacement field. */
    template <int dim>
    struct AveragingGroups
    {
      /** The law of each material: its index among the distinct laws. */
      std::map<types::material_id, unsigned int> law;
      /** The group of each (law, field). */
      std::map<std::pair<unsigned int, unsigned int>, unsigned int> group;
      const FiniteElementSpace<dim>                                *fe_space;

      /** The group of @p cell. */
      template <typename CellIterator>
      unsigned int
      of(const CellIterator &cell) const
      {
        return group.at(
          std::make_pair(law.at(cell->material_id()),
                         fe_space->field_of(cell->active_fe_index())));
      }

      unsigned int
      size() const
      {
        return group.size();
      }
    };

    /** The averaging groups of the materials of @p tria (on all ranks). */
    template <int dim>
    AveragingGroups<dim>
    averaging_groups(const Triangulation<dim>      &tria,
                     const FiniteElementSpace<dim> &fe_space,
                     const StressModel<dim>        &stress_model,
                     const MPI_Comm                 comm)
    {
      std::vector<types::material_id> material_ids;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          material_ids.push_back(cell->material_id());
      material_ids = Utilities::MPI::compute_set_union(material_ids, comm);
      AveragingGroups<dim> groups;
      groups.fe_space = &fe_space;
      for (const auto id : material_ids)
        {
          unsigned int same = groups.law.size();
          for (const auto &[other, index] : groups.law)
            if ((stress_model.moduli(id).stiffness() -
                 stress_model.moduli(other).stiffness())
                    .norm() <=
                  1e-12 * stress_model.moduli(id).stiffness().norm() &&
                stress_model.rheology(id).relaxation_time() ==
                  stress_model.rheology(other).relaxation_time())
              same = std::min(same, index);
          groups.law.emplace(id, same);
        }
      for (const auto &[id, l] : groups.law)
        for (unsigned int f = 0; f < fe_space.n_fields(); ++f)
          groups.group.emplace(std::make_pair(l, f), groups.group.size());
      return groups;
    }

    /** The recovered stress σ* of each averaging group, a continuous Q_p
     * field on @p stress_dofs (ghosted): at each node the mean of the
     * stresses (from @p stress_of) that the group's owned cells have
     * there. Nodes no cell of the group touches keep 0; they are never read
     * for a cell of that group. */
    template <int dim>
    std::vector<TrilinosWrappers::MPI::Vector>
    recovered_stresses(const DoFHandler<dim>               &dof_handler,
                       const DoFHandler<dim>               &stress_dofs,
                       const FiniteElementSpace<dim>       &fe_space,
                       const TrilinosWrappers::MPI::Vector &solution,
                       const typename MeshRefinement<dim>::StressOf &stress_of,
                       const AveragingGroups<dim>                   &groups)
    {
      const MPI_Comm            comm      = dof_handler.get_communicator();
      const FiniteElement<dim> &stress_fe = stress_dofs.get_fe();
      const IndexSet            owned     = stress_dofs.locally_owned_dofs();
      IndexSet                  relevant;
      DoFTools::extract_locally_relevant_dofs(stress_dofs, relevant);
      std::vector<TrilinosWrappers::MPI::Vector> sum(groups.size()),
        weight(groups.size());
      for (unsigned int m = 0; m < groups.size(); ++m)
        {
          sum[m].reinit(owned, relevant, comm, true);
          weight[m].reinit(owned, relevant, comm, true);
        }
      const Quadrature<dim> nodes(
        stress_fe.base_element(0).get_unit_support_points());
      hp::QCollection<dim> node_q;
      for (unsigned int f = 0; f < fe_space.fe_collection().size(); ++f)
        node_q.push_back(nodes);
      hp::FEValues<dim>           at_nodes(fe_space.mapping_collection(),
                                 fe_space.fe_collection(),
                                 node_q,
                                 update_gradients | update_quadrature_points);
      std::vector<Tensor<2, dim>> grads;
      std::vector<types::global_dof_index> stress_indices(
        stress_fe.n_dofs_per_cell());
      auto stress_cell = stress_dofs.begin_active();
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_locally_owned())
            {
              at_nodes.reinit(cell);
              const FEValues<dim> &fv = at_nodes.get_present_fe_values();
              const auto           u  = fe_space.displacement(
                fe_space.field_of(cell->active_fe_index()));
              grads.resize(fv.n_quadrature_points);
              fv[u].get_function_gradients(solution, grads);
              stress_cell->get_dof_indices(stress_indices);
              const unsigned int m = groups.of(cell);
              for (unsigned int i = 0; i < stress_fe.n_dofs_per_cell(); ++i)
                {
                  const auto ci = stress_fe.system_to_component_index(i);
                  const SymmetricTensor<2, dim> s =
                    stress_of(cell,
                              fv.get_quadrature().point(ci.second),
                              fv.quadrature_point(ci.second),
                              symmetrize(grads[ci.second]));
                  sum[m](stress_indices[i]) += stress_component(s, ci.first);
                  weight[m](stress_indices[i]) += 1.0;
                }
            }
          ++stress_cell;
        }
      // No hanging-node constraints: a hanging node keeps the average of
      // the cells that have it (a constraint would fill it from the coarse
      // neighbour's nodes, which belong to another material's average
      // where the coarse neighbour is of another material).
      std::vector<TrilinosWrappers::MPI::Vector> recovered(groups.size());
      for (unsigned int m = 0; m < groups.size(); ++m)
        {
          sum[m].compress(VectorOperation::add);
          weight[m].compress(VectorOperation::add);
          TrilinosWrappers::MPI::Vector average(owned, comm);
          for (const auto i : owned)
            if (weight[m](i) > 0)
              average(i) = sum[m](i) / weight[m](i);
          average.compress(VectorOperation::insert);
          recovered[m].reinit(owned, relevant, comm);
          recovered[m] = average;
        }
      return recovered;
    }

    /** η_K = ‖σ_h − σ*‖_{L2(K)} of every owned cell K (zero on the
     * others), σ_h from @p stress_of and σ* the recovered stress of the
     * cell's averaging group; shear components count twice (σ : σ). */
    template <int dim>
    Vector<float>
    distances_from_recovered(
      const DoFHandler<dim>                            &dof_handler,
      const DoFHandler<dim>                            &stress_dofs,
      const FiniteElementSpace<dim>                    &fe_space,
      const TrilinosWrappers::MPI::Vector              &solution,
      const typename MeshRefinement<dim>::StressOf     &stress_of,
      const AveragingGroups<dim>                       &groups,
      const std::vector<TrilinosWrappers::MPI::Vector> &recovered)
    {
      const unsigned int n_stress = dim * (dim + 1) / 2;
      Vector<float>      eta(dof_handler.get_triangulation().n_active_cells());
      hp::FEValues<dim>  hp_fe_values(fe_space.mapping_collection(),
                                     fe_space.fe_collection(),
                                     fe_space.cell_quadrature(),
                                     update_gradients |
                                       update_quadrature_points |
                                       update_JxW_values);
      const QGauss<dim>  quadrature(fe_space.degree() + 1);
      FEValues<dim>      stress_values(fe_space.mapping(),
                                  stress_dofs.get_fe(),
                                  quadrature,
                                  update_values);
      std::vector<Vector<double>> s_star(quadrature.size(),
                                         Vector<double>(n_stress));
      std::vector<Tensor<2, dim>> grads;
      auto                        stress_cell = stress_dofs.begin_active();
      unsigned int                index       = 0;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (cell->is_locally_owned())
            {
              hp_fe_values.reinit(cell);
              const FEValues<dim> &fv = hp_fe_values.get_present_fe_values();
              const auto           u  = fe_space.displacement(
                fe_space.field_of(cell->active_fe_index()));
              grads.resize(fv.n_quadrature_points);
              fv[u].get_function_gradients(solution, grads);
              stress_values.reinit(stress_cell);
              stress_values.get_function_values(recovered[groups.of(cell)],
                                                s_star);
              double e2 = 0;
              for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
                {
                  const SymmetricTensor<2, dim> s =
                    stress_of(cell,
                              fv.get_quadrature().point(q),
                              fv.quadrature_point(q),
                              symmetrize(grads[q]));
                  for (unsigned int c = 0; c < n_stress; ++c)
                    {
                      const double d = stress_component(s, c) - s_star[q](c);
                      e2 += (c < dim ? 1.0 : 2.0) * d * d * fv.JxW(q);
                    }
                }
              eta(index) = std::sqrt(e2);
            }
          ++stress_cell;
          ++index;
        }
      return eta;
    }
  } // namespace

  template <int dim>
  void
  MeshRefinement<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    prm.declare_entry("Initial global refinement",
                      "0",
                      Patterns::Integer(0, 20),
                      "Global refinements of the coarse mesh before the first "
                      "cycle.");
    prm.declare_entry("Number of cycles",
                      "1",
                      Patterns::Integer(1, 100),
                      "Solve-refine cycles (rows of the convergence table).");
    prm.declare_entry("Strategy",
                      "global",
                      Patterns::Selection("global|adaptive"),
                      "Refine all cells, or by an error indicator.");
    prm.declare_entry("Indicator",
                      "Kelly",
                      Patterns::Selection(
                        "Kelly|stress recovery|goal oriented"),
                      "Adaptive indicator: Kelly (jump of the displacement "
                      "gradient), stress recovery (Zienkiewicz-Zhu), or goal "
                      "oriented (the stress-recovery indicators of the "
                      "solution and of the dual solutions of `Goals/Stress "
                      "averages` multiplied: refines where the goals' error "
                      "arises).");
    prm.declare_entry("Marking",
                      "fraction of error",
                      Patterns::Selection(
                        "fraction of error|fraction of cells"),
                      "Refine the cells that carry the `Refine fraction` of "
                      "the squared error (Doerfler marking, optimal rates at "
                      "singularities), or that fraction of the cells.");
    prm.declare_entry("Refine fraction",
                      "0.3",
                      Patterns::Anything(),
                      "Fraction of the error (or cells) refined per cycle, "
                      "in [0, 1].");
    prm.declare_entry("Coarsen fraction",
                      "0.0",
                      Patterns::Anything(),
                      "Fraction of the error (or cells) coarsened per cycle, "
                      "in [0, 1].");
    prm.declare_entry("Maximum level",
                      "20",
                      Patterns::Integer(0, 30),
                      "No cell is refined beyond this level.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  MeshRefinement<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    initial_global_refinement = prm.get_integer("Initial global refinement");
    n_cycles                  = prm.get_integer("Number of cycles");
    strategy =
      prm.get("Strategy") == "global" ? Strategy::global : Strategy::adaptive;
    indicator     = prm.get("Indicator") == "Kelly" ? Indicator::kelly
                    : prm.get("Indicator") == "goal oriented"
                      ? Indicator::goal_oriented
                      : Indicator::stress_recovery;
    max_level     = prm.get_integer("Maximum level");
    marking       = prm.get("Marking") == "fraction of error"
                      ? Marking::fraction_of_error
                      : Marking::fraction_of_cells;
    auto fraction = [&](const std::string &entry) {
      const std::string text  = prm.get(entry);
      const double      value = parse_number(text, "Mesh refinement/" + entry);
      if (value < 0 || value > 1)
        throw_input_error("Mesh refinement/" + entry,
                          "must lie in [0, 1], got " + text);
      return value;
    };
    refine_fraction  = fraction("Refine fraction");
    coarsen_fraction = fraction("Coarsen fraction");
    if (refine_fraction + coarsen_fraction > 1)
      throw_input_error("Mesh refinement/Refine fraction",
                        "refine and coarsen fractions add up to more than 1");
    prm.leave_subsection();
  }

  template <int dim>
  Vector<float>
  MeshRefinement<dim>::indicators(
    const DoFHandler<dim>                            &dof_handler,
    const FiniteElementSpace<dim>                    &fe_space,
    const StressModel<dim>                           &stress_model,
    const TrilinosWrappers::MPI::Vector              &solution,
    const std::vector<TrilinosWrappers::MPI::Vector> &duals,
    const std::vector<double>                        &weights) const
  {
    const auto    &tria = dof_handler.get_triangulation();
    Vector<float>  eta(tria.n_active_cells());
    const StressOf reported_stress = reported_stress_of(stress_model);
    if (indicator == Indicator::stress_recovery)
      return stress_recovery(
        dof_handler, fe_space, stress_model, solution, reported_stress);
    if (indicator == Indicator::goal_oriented)
      {
        for (const Vector<float> &goal : goal_indicators(
               dof_handler, fe_space, stress_model, solution, duals, weights))
          eta += goal;
        return eta;
      }
    KellyErrorEstimator<dim>::estimate(
      fe_space.mapping(),
      dof_handler,
      fe_space.face_quadrature(),
      std::map<types::boundary_id, const Function<dim> *>(),
      solution,
      eta,
      ComponentMask(),
      nullptr,
      numbers::invalid_unsigned_int,
      tria.locally_owned_subdomain());
    return eta;
  }

  template <int dim>
  std::vector<Vector<float>>
  MeshRefinement<dim>::goal_indicators(
    const DoFHandler<dim>                            &dof_handler,
    const FiniteElementSpace<dim>                    &fe_space,
    const StressModel<dim>                           &stress_model,
    const TrilinosWrappers::MPI::Vector              &solution,
    const std::vector<TrilinosWrappers::MPI::Vector> &duals,
    const std::vector<double>                        &weights) const
  {
    AssertThrow(!duals.empty() && duals.size() == weights.size(),
                ExcMessage("the goal-oriented indicator needs the dual "
                           "solutions of the goals"));
    const Vector<float> primal =
      stress_recovery(dof_handler,
                      fe_space,
                      stress_model,
                      solution,
                      reported_stress_of(stress_model));
    // The dual's stress is the linear law of the operator it solved.
    const auto dual_stress =
      [&](const typename Triangulation<dim>::active_cell_iterator &cell,
          const Point<dim> &,
          const Point<dim>              &p,
          const SymmetricTensor<2, dim> &strain) {
        return stress_model.step_stress(cell->material_id(), p, strain)
          .in_plane;
      };
    std::vector<Vector<float>> result;
    for (unsigned int i = 0; i < duals.size(); ++i)
      {
        Vector<float> eta = stress_recovery(
          dof_handler, fe_space, stress_model, duals[i], dual_stress);
        for (unsigned int c = 0; c < eta.size(); ++c)
          eta(c) *= static_cast<float>(weights[i]) * primal(c);
        result.push_back(std::move(eta));
      }
    return result;
  }

  template <int dim>
  Vector<float>
  MeshRefinement<dim>::stress_recovery(
    const DoFHandler<dim>               &dof_handler,
    const FiniteElementSpace<dim>       &fe_space,
    const StressModel<dim>              &stress_model,
    const TrilinosWrappers::MPI::Vector &solution,
    const StressOf                      &stress_of) const
  {
    // Zienkiewicz–Zhu: average the stress at the nodes of a continuous
    // Q_p field (each cell contributes its stress at the node), then
    // η_K = ‖σ_h − σ*‖_{L2(K)}. The average is taken per law: across an
    // interface between materials of different moduli or viscosity the
    // tangential stress jumps physically (only the traction is
    // continuous), and one average over both sides would report that jump
    // as an error and refine the interface instead of where the solution is
    // poorly resolved. Materials of the same law (two names for the same
    // rock, e.g. an upper and a lower crust that differ only in where they
    // are) share one average, so that a stress gradient across one cell
    // layer of each shows; the two sides of a fault (two fields) never do.
    const auto         &tria     = dof_handler.get_triangulation();
    const unsigned int  n_stress = dim * (dim + 1) / 2;
    const FESystem<dim> stress_fe(FE_Q<dim>(fe_space.degree()), n_stress);
    DoFHandler<dim>     stress_dofs(tria);
    stress_dofs.distribute_dofs(stress_fe);
    const AveragingGroups<dim> groups = averaging_groups(
      tria, fe_space, stress_model, dof_handler.get_communicator());
    const std::vector<TrilinosWrappers::MPI::Vector> recovered =
      recovered_stresses(
        dof_handler, stress_dofs, fe_space, solution, stress_of, groups);
    return distances_from_recovered(dof_handler,
                                    stress_dofs,
                                    fe_space,
                                    solution,
                                    stress_of,
                                    groups,
                                    recovered);
  }

  template <int dim>
  void
  MeshRefinement<dim>::mark_fraction_of_error(
    parallel::distributed::Triangulation<dim> &tria,
    const Vector<float>                       &eta,
    const bool                                 with_coarsening) const
  {
    // Dörfler marking by bisection on the threshold: refine the cells with
    // η_K > t where t is the largest value with Σ_{η_K > t} η_K² ≥ θ Σ η_K²;
    // coarsen the cells with η_K < s, s the largest value with
    // Σ_{η_K < s} η_K² ≤ θ_c Σ η_K². Only sums are communicated.
    // Cells at the Maximum level cannot be refined: the refinement
    // threshold is chosen among the others (else, once the cells at a
    // singularity reach that level, they would hold the fraction and
    // nothing would be refined any more).
    const MPI_Comm comm  = tria.get_communicator();
    double         total = 0, largest = 0;
    double         refinable  = 0;
    auto           can_refine = [&](const auto &cell) {
      return static_cast<unsigned int>(cell->level()) < max_level;
    };
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double e = eta(cell->active_cell_index());
          total += e * e;
          largest = std::max(largest, e);
          if (can_refine(cell))
            refinable += e * e;
        }
    total     = Utilities::MPI::sum(total, comm);
    refinable = Utilities::MPI::sum(refinable, comm);
    largest   = Utilities::MPI::max(largest, comm);
    if (!(total > 0))
      return;
    auto sum_above = [&](const double t, const bool only_refinable) {
      double sum = 0;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned() && (!only_refinable || can_refine(cell)))
          {
            const double e = eta(cell->active_cell_index());
            if (e > t)
              sum += e * e;
          }
      return Utilities::MPI::sum(sum, comm);
    };
    double refine_threshold = largest;
    if (refine_fraction > 0 && refinable > 0)
      {
        double lo = 0, hi = largest;
        for (unsigned int it = 0; it < 60; ++it)
          {
            const double mid = 0.5 * (lo + hi);
            if (sum_above(mid, true) >= refine_fraction * refinable)
              lo = mid;
            else
              hi = mid;
          }
        refine_threshold = lo;
      }
    double coarsen_threshold = 0;
    if (with_coarsening && coarsen_fraction > 0)
      {
        double lo = 0, hi = largest;
        for (unsigned int it = 0; it < 60; ++it)
          {
            const double mid = 0.5 * (lo + hi);
            if (total - sum_above(mid, false) <= coarsen_fraction * total)
              lo = mid;
            else
              hi = mid;
          }
        coarsen_threshold = lo;
      }
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double e = eta(cell->active_cell_index());
          // Cells within a relative 1e-6 of the threshold are treated
          // alike: indicators of mirror-symmetric cells differ only by
          // round-off, which depends on the partition.
          if (refine_fraction > 0 && can_refine(cell) &&
              e > refine_threshold * (1 - 1e-6))
            cell->set_refine_flag();
          else if (e < coarsen_threshold * (1 - 1e-6))
            cell->set_coarsen_flag();
        }
  }

  template <int dim>
  void
  MeshRefinement<dim>::refine(
    parallel::distributed::Triangulation<dim>        &tria,
    const DoFHandler<dim>                            &dof_handler,
    const FiniteElementSpace<dim>                    &fe_space,
    const StressModel<dim>                           &stress_model,
    const TrilinosWrappers::MPI::Vector              &solution,
    const std::function<void(double, unsigned int)>  &check_new_mesh,
    const std::vector<TrilinosWrappers::MPI::Vector> &duals,
    const std::vector<double>                        &weights) const
  {
    if (strategy == Strategy::global)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() &&
              static_cast<unsigned int>(cell->level()) < max_level)
            cell->set_refine_flag();
      }
    else
      {
        if (indicator == Indicator::goal_oriented)
          {
            // Every goal gets its own set of cells (their union is
            // refined): a goal whose error is small against another's in
            // absolute terms still converges (Mommer & Stevenson 2009 mark
            // the union of the primal and dual sets for the same reason).
            // Dörfler: each goal's set carries the refine fraction of its
            // error; fraction of cells: each goal's share of the fraction.
            const std::vector<Vector<float>> per_goal = goal_indicators(
              dof_handler, fe_space, stress_model, solution, duals, weights);
            Vector<float> eta(per_goal[0].size());
            for (const Vector<float> &goal : per_goal)
              eta += goal;
            if (marking == Marking::fraction_of_error)
              {
                mark_fraction_of_error(tria, eta);
                for (const Vector<float> &goal : per_goal)
                  mark_fraction_of_error(tria, goal, false);
              }
            else
              {
                for (const Vector<float> &goal : per_goal)
                  parallel::distributed::GridRefinement::
                    refine_and_coarsen_fixed_number(
                      tria, goal, refine_fraction / per_goal.size(), 0);
                for (const auto &cell : tria.active_cell_iterators())
                  if (cell->is_locally_owned())
                    cell->clear_coarsen_flag();
                if (coarsen_fraction > 0)
                  parallel::distributed::GridRefinement::
                    refine_and_coarsen_fixed_number(tria,
                                                    eta,
                                                    0,
                                                    coarsen_fraction);
              }
            for (const auto &cell : tria.active_cell_iterators())
              if (cell->is_locally_owned() && cell->refine_flag_set())
                cell->clear_coarsen_flag();
          }
        else
          {
            const Vector<float> eta = indicators(
              dof_handler, fe_space, stress_model, solution, duals, weights);
            if (marking == Marking::fraction_of_cells)
              parallel::distributed::GridRefinement::
                refine_and_coarsen_fixed_number(tria,
                                                eta,
                                                refine_fraction,
                                                coarsen_fraction);
            else
              mark_fraction_of_error(tria, eta);
          }
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() && cell->refine_flag_set() &&
              static_cast<unsigned int>(cell->level()) >= max_level)
            cell->clear_refine_flag();
      }
    // The new mesh's size from the flags: each refined cell becomes 2^dim,
    // each family of 2^dim coarsened cells one.
    tria.prepare_coarsening_and_refinement();
    double       refined = 0, coarsened = 0;
    unsigned int deepest = 0;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          refined += cell->refine_flag_set() ? 1 : 0;
          coarsened += cell->coarsen_flag_set() ? 1 : 0;
          deepest =
            std::max<unsigned int>(deepest,
                                   cell->level() +
                                     (cell->refine_flag_set() ? 1 : 0) -
                                     (cell->coarsen_flag_set() ? 1 : 0));
        }
    const unsigned int children = GeometryInfo<dim>::max_children_per_cell;
    check_new_mesh(tria.n_global_active_cells() +
                     Utilities::MPI::sum((children - 1) *
                                           (refined - coarsened / children),
                                         tria.get_communicator()),
                   Utilities::MPI::max(deepest, tria.get_communicator()) + 1);
    tria.execute_coarsening_and_refinement();
  }

  template class MeshRefinement<2>;
} // namespace lithostress

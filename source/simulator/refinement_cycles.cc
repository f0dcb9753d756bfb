#include <lithostress/base/input_error.h>
#include <lithostress/base/interruption.h>
#include <lithostress/base/output_file.h>
#include <lithostress/simulator/refinement_cycles.h>

#include <iomanip>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  RefinementCycles<dim>::declare_parameters(ParameterHandler &prm)
  {
    MeshRefinement<dim>::declare_parameters(prm);
    StressGoals<dim>::declare_parameters(prm);
  }

  template <int dim>
  void
  RefinementCycles<dim>::parse_parameters(ParameterHandler &prm,
                                          const double      length_scale)
  {
    refinement.parse_parameters(prm);
    stress_goals.parse_parameters(prm, length_scale);
    if (refinement.strategy == MeshRefinement<dim>::Strategy::adaptive &&
        refinement.indicator == MeshRefinement<dim>::Indicator::goal_oriented &&
        stress_goals.empty())
      throw_input_error("Mesh refinement/Indicator",
                        "`goal oriented` needs the goals in Mesh "
                        "refinement/Goals/Stress averages or Displacement "
                        "averages");
    if (stress_goals.stop_tolerance() > 0 && stress_goals.empty())
      throw_input_error("Mesh refinement/Goals/Stop at relative change",
                        "needs the goals in Mesh refinement/Goals/Stress "
                        "averages or Displacement averages");
  }

  template <int dim>
  void
  RefinementCycles<dim>::refine_initially(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    if (refinement.initial_global_refinement > 0)
      tria.refine_global(refinement.initial_global_refinement);
  }

  template <int dim>
  void
  RefinementCycles<dim>::run(ElasticProblem<dim>         &problem,
                             PostprocessorList<dim>      &postprocessors,
                             const SimulatorAccess<dim>  &access,
                             const std::function<void()> &accepted,
                             const bool                   cycle_output)
  {
    for (present_cycle = 0;; ++present_cycle)
      {
        if (present_cycle > 0)
          refine_mesh(problem,
                      access,
                      "the mesh of cycle " + std::to_string(present_cycle));
        compute_cycle(problem, postprocessors, access, accepted);
        const bool last = last_cycle(access);
        if (cycle_output)
          postprocessors.cycle_output(access, present_cycle, last);
        if (last)
          break;
      }
  }

  template <int dim>
  void
  RefinementCycles<dim>::compute_cycle(ElasticProblem<dim>    &problem,
                                       PostprocessorList<dim> &postprocessors,
                                       const SimulatorAccess<dim>  &access,
                                       const std::function<void()> &accepted)
  {
    const MPI_Comm comm = access.communicator;
    interruption::stop_if_requested(comm, "set-up");
    // An elastic cycle solves the load from the undeformed state: the
    // fault's slip starts from zero on every mesh.
    problem.reset_slip();
    problem.setup(0);
    if (present_cycle == 0)
      stress_goals.check_regions(problem.dof_handler(), access.fe_space);
    interruption::stop_if_requested(comm, "assembly");
    problem.assemble(0);
    // The first assembly has evaluated every load on the first mesh:
    // the model is accepted, and only now is anything written.
    if (present_cycle == 0 && accepted)
      accepted();
    interruption::stop_if_requested(comm, "solve");
    problem.solve(true, [&]() { postprocessors.solve_failed(access); });
    interruption::stop_if_requested(comm, "postprocessing");
    {
      TimerOutput::Scope     t(access.timer, "postprocess");
      const CycleStatistics &s = problem.statistics();
      study.start_row(present_cycle, s.cells, s.dofs);
      std::ostringstream progress;
      progress << "cycle " << present_cycle << ": " << s.cells << " cells, "
               << s.dofs << " DoFs, " << s.solver.solver << ' '
               << s.solver.iterations << " it";
      postprocessors.cycle_finished(access, present_cycle, study, progress);
      access.log << progress.str() << std::endl;
      if (!stress_goals.empty())
        record_goals(access);
    }
    // The table so far, after every cycle: a run stopped by an error
    // in a later cycle keeps the cycles it finished.
    on_all_ranks(comm, [&]() {
      if (!study.empty() && access.root())
        {
          OutputFile csv(access.path("convergence.csv"));
          study.write_csv(csv);
          csv.commit();
        }
    });
  }

  template <int dim>
  void
  RefinementCycles<dim>::record_goals(const SimulatorAccess<dim> &a)
  {
    const std::vector<double> values = stress_goals.values(a.dof_handler,
                                                           a.fe_space,
                                                           a.stress_model,
                                                           a.solution);
    std::vector<double>       exact;
    if (a.reference)
      exact = stress_goals.reference_values(a.dof_handler,
                                            a.fe_space,
                                            a.stress_model,
                                            *a.reference);
    std::ostringstream line;
    line << "  goals:" << std::setprecision(6);
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        const std::string &name = stress_goals.list()[k].name;
        study.add(name, values[k], ConvergenceStudy::Kind::functional);
        line << (k > 0 ? "," : "") << ' ' << name << ' ' << values[k];
        if (a.reference)
          study.add("rel_err_" + name,
                    std::abs(values[k] - exact[k]) /
                      std::max(std::abs(exact[k]), 1e-300),
                    ConvergenceStudy::Kind::error);
      }
    const auto change = stress_goals.record_cycle(a.statistics.dofs, values);
    if (change.compared_with > 0)
      line << "; largest change since " << change.compared_with << " DoFs "
           << std::setprecision(3) << 100 * change.change << " % ("
           << change.goal << ")";
    goals_converged = change.converged;
    a.log << line.str() << std::endl;
  }

  template <int dim>
  bool
  RefinementCycles<dim>::last_cycle(const SimulatorAccess<dim> &a) const
  {
    if (goals_converged)
      {
        a.log << "  the goals changed by less than "
              << 100 * stress_goals.stop_tolerance()
              << " % while the DoFs at least doubled: refinement cycles done"
              << std::endl;
        return true;
      }
    if (present_cycle + 1 < refinement.n_cycles)
      return false;
    // A single cycle has nothing to compare with (said in the log's
    // header); more cycles that did not converge are an error.
    if (stress_goals.stop_tolerance() > 0 && refinement.n_cycles > 1)
      {
        std::ostringstream message;
        message << "the goals (Mesh refinement/Goals) did not converge to "
                << 100 * stress_goals.stop_tolerance() << " % within "
                << refinement.n_cycles
                << " cycles; the results of every cycle are in "
                << a.output_directory
                << " (convergence.csv); raise Mesh refinement/Number of "
                   "cycles";
        throw ComputationError(message.str());
      }
    return true;
  }

  template <int dim>
  void
  RefinementCycles<dim>::refine_mesh(ElasticProblem<dim>         &problem,
                                     const SimulatorAccess<dim>  &access,
                                     const std::string           &mesh,
                                     const std::function<void()> &before_change)
  {
    const DoFHandler<dim> &dofs = problem.dof_handler();
    auto                  &tria = problem.triangulation();
    const MPI_Comm         comm = access.communicator;
    interruption::stop_if_requested(comm, "mesh refinement");
    RunLog            &log = access.log;
    TimerOutput::Scope t(access.timer, "refine");
    Timer              clock(comm, true);
    const double       dofs_per_cell =
      static_cast<double>(dofs.n_dofs()) / tria.n_global_active_cells();
    const FiniteElementSpace<dim> &fe_space     = access.fe_space;
    const StressModel<dim>        &stress_model = access.stress_model;
    // Goal-oriented refinement: the goals' dual solutions on the present
    // operator, weighted by 1/|J_i| (relative accuracy of every goal).
    std::vector<TrilinosWrappers::MPI::Vector> duals;
    std::vector<double>                        weights;
    if (refinement.strategy == MeshRefinement<dim>::Strategy::adaptive &&
        refinement.indicator == MeshRefinement<dim>::Indicator::goal_oriented)
      {
        weights = StressGoals<dim>::weights(stress_goals.values(
          dofs, fe_space, stress_model, problem.solution()));
        SolverReport report;
        duals = problem.solve_dual_problems(stress_goals, report);
        log << "  goal-oriented refinement: " << duals.size()
            << " dual solutions, " << report.solver << ' ' << report.iterations
            << " it" << std::endl;
      }
    const LinearSolver<dim> &solver = problem.linear_solver();
    refinement.refine(
      tria,
      dofs,
      fe_space,
      stress_model,
      problem.solution(),
      [&](const double cells, const unsigned int levels) {
        const double level_bytes =
          solver.memory_of_levels(tria.n_global_coarse_cells(), levels);
        memory_budget->check(
          mesh,
          cells,
          dofs_per_cell * cells,
          solver.name(),
          solver.memory_per_dof(dofs_per_cell * cells),
          level_bytes,
          "Mesh refinement/Number of cycles, Refine fraction "
          "or Maximum level" +
            std::string(level_bytes > 0 ? " (or take Solver/Multigrid "
                                          "hierarchy = local smoothing)"
                                        : ""));
        problem.carry_solution_to_next_mesh();
        if (before_change)
          before_change();
      },
      duals,
      weights);
    problem.statistics().mesh_time = clock.wall_time();
  }

  template class RefinementCycles<2>;
} // namespace lithostress

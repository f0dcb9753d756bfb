#include <deal.II/dofs/dof_tools.h>

#include <lithostress/analysis/force_balance.h>
#include <lithostress/assembly/elastic_assembler.h>
#include <lithostress/base/input_error.h>
#include <lithostress/base/interruption.h>
#include <lithostress/refinement/dual_solutions.h>
#include <lithostress/simulator/elastic_problem.h>

#include <cmath>

namespace lithostress
{
  template <int dim>
  ElasticProblem<dim>::ElasticProblem(
    const Model                       &model,
    std::unique_ptr<LinearSolver<dim>> linear_solver,
    FrictionalSlidingSolver<dim>      &sliding_solver,
    RunLog                            &log,
    TimerOutput                       &timer)
      : model(model)
      , solver(std::move(linear_solver))
      , sliding_solver(sliding_solver)
      , log(log)
      , timer(timer)
      , dofs(model.triangulation)
  {
  }

  template <int dim>
  void
  ElasticProblem<dim>::setup(const double time)
  {
    TimerOutput::Scope t(timer, "setup");
    const MPI_Comm     comm = model.communicator;
    Timer              clock(comm, true), part(comm, true);
    stats.setup_phases.clear();
    const auto phase_done = [&](const std::string &name) {
      stats.setup_phases.emplace_back(name, part.wall_time());
      // The set-up is the longest phase without CG iterations: a safe
      // point after each of its parts.
      interruption::stop_if_requested(comm, "set-up (" + name + ")");
      part.restart();
    };
    model.faults.set_active_fe_indices(dofs);
    dofs.distribute_dofs(model.fe_space.fe_collection());
    phase_done("DoFs");
    solver->prepare_dof_handler(dofs);
    phase_done("level DoFs");
    system.locally_owned = dofs.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dofs, system.locally_relevant);
    if (solution_transfer)
      {
        TrilinosWrappers::MPI::Vector start(system.locally_owned, comm);
        solution_transfer->interpolate(start);
        solution_transfer.reset();
        sliding_solver.start_next_solve_from(start);
      }
    make_constraints(time);
    phase_done("constraints");
    system.reinit(dofs,
                  comm,
                  needs_model_matrix(),
                  model.faults.has_face_terms() && needs_model_matrix()
                    ? model.faults.interface_cliques(dofs)
                    : std::vector<std::vector<types::global_dof_index>>());
    ++mesh_version;
    phase_done("sparsity pattern and matrix");
    // The previous mesh's solution; solve() sizes it anew.
    present_solution.clear();
    predictor.clear();
    stats.dofs       = dofs.n_dofs();
    stats.cells      = model.triangulation.n_global_active_cells();
    stats.setup_time = clock.wall_time();
  }

  template <int dim>
  void
  ElasticProblem<dim>::carry_solution_to_next_mesh()
  {
    using Method = typename FrictionalSlidingSolver<dim>::Method;
    if (!model.faults.needs_sliding_solver() ||
        sliding_solver.settings().method != Method::newton ||
        present_solution.size() != dofs.n_dofs())
      return;
    solution_transfer =
      std::make_unique<parallel::distributed::
                         SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>(
        dofs);
    solution_transfer->prepare_for_coarsening_and_refinement(present_solution);
  }

  template <int dim>
  void
  ElasticProblem<dim>::update_constraints(const double time)
  {
    TimerOutput::Scope t(timer, "setup");
    make_constraints(time);
    // The solver released the right-hand side.
    system.rhs.reinit(system.locally_owned, model.communicator);
  }

  template <int dim>
  bool
  ElasticProblem<dim>::start_from_prediction(const double time)
  {
    // One solution known: it is the start itself, whose prescribed values
    // moved to those of @p time would strain the boundary's cells alone.
    if (!keep_setup || !predictor.extrapolates())
      return false;
    update_constraints(time);
    TrilinosWrappers::MPI::Vector guess;
    predictor.predict(time, guess);
    system.constraints.distribute(guess);
    present_solution = guess;
    return true;
  }

  template <int dim>
  void
  ElasticProblem<dim>::make_constraints(const double time)
  {
    system.constraints.clear();
    system.constraints.reinit(system.locally_relevant);
    DoFTools::make_hanging_node_constraints(dofs, system.constraints);
    on_all_ranks(model.communicator, [&]() {
      model.prescribed_displacement.apply(dofs,
                                          model.fe_space,
                                          system.constraints,
                                          time);
      model.faults.add_constraints(dofs,
                                   model.fe_space,
                                   system.constraints,
                                   time);
    });
    system.constraints.close();
  }

  template <int dim>
  void
  ElasticProblem<dim>::assemble(const double            time,
                                const CellHistory<dim> *history)
  {
    TimerOutput::Scope   t(timer, "assemble");
    Timer                clock(model.communicator, true);
    LoadCollection<dim> &loads = model.loads;
    // Mesh integrals of the loads once per mesh, not once per time step;
    // a slab pull that balances the other loads measures them there.
    const bool new_mesh = loads_prepared_for != mesh_version;
    if (new_mesh)
      for (const auto &load : loads.loads())
        load->prepare_for_mesh(model.triangulation,
                               model.fe_space.mapping(),
                               model.fe_space.face_quadrature()[0]);
    loads_prepared_for = mesh_version;
    for (const auto &load : loads.loads())
      load->set_time(time);
    if (new_mesh && loads.balances_vertical_loads())
      {
        TrilinosWrappers::MPI::Vector at_rest(dofs.locally_owned_dofs(),
                                              system.locally_relevant,
                                              model.communicator);
        std::vector<Tensor<1, dim>>   resultants;
        for (const auto &load :
             compute_force_balance(dofs,
                                   model.fe_space,
                                   model.stress_model,
                                   loads,
                                   model.prescribed_displacement,
                                   at_rest)
               .loads)
          resultants.push_back(load.second);
        loads.balance(resultants);
      }
    ElasticAssembler<dim> assembler(model.fe_space, model.stress_model, loads);
    assembler.set_cell_history(history);
    assembled_history = history;
    assembled_time    = time;
    // The matrix only where the operator changed (the time loop assembles
    // many right-hand sides for one operator).
    const bool with_matrix =
      needs_model_matrix() && matrix_version != operator_version();
    assembler.assemble(dofs, system, with_matrix);
    model.faults.assemble(dofs,
                          model.fe_space,
                          system.constraints,
                          with_matrix ? &system.matrix : nullptr,
                          system.rhs);
    if (with_matrix)
      matrix_version = operator_version();
    stats.assemble_time = clock.wall_time();
  }

  template <int dim>
  void
  ElasticProblem<dim>::solve(const bool                   commit,
                             const std::function<void()> &on_failure)
  {
    TimerOutput::Scope t(timer, "solve");
    Timer              clock(model.communicator, true);
    // The solver sizes owned_solution when its own vectors are gone, and
    // the ghosted solution is made after it: the peak memory of the solve
    // holds neither.
    TrilinosWrappers::MPI::Vector owned_solution;
    // In the time loop, iterative solves and Newton's method start from
    // the last steps' solutions extrapolated to this step.
    DiscreteProblem<dim>          problem = discrete_problem();
    TrilinosWrappers::MPI::Vector guess;
    if (keep_setup && predictor.available())
      {
        predictor.predict(assembled_time, guess);
        system.constraints.distribute(guess);
        problem.initial_guess = &guess;
      }
    if (model.faults.needs_sliding_solver())
      solve_sliding(problem, owned_solution, commit, on_failure);
    else
      stats.solver = solver->solve(problem, owned_solution);
    guess.clear();
    system.constraints.distribute(owned_solution);
    if (keep_setup)
      predictor.record(assembled_time, owned_solution);
    const double norm = owned_solution.l2_norm();
    if (!std::isfinite(norm))
      throw ComputationError("the solution of the linear system is not "
                             "finite (norm " +
                             std::to_string(norm) + ", " + stats.solver.solver +
                             ")");
    present_solution.reinit(system.locally_owned,
                            system.locally_relevant,
                            model.communicator);
    present_solution = owned_solution;
    stats.solve_time = clock.wall_time() - stats.solver.benchmark_time;
    stats.benchmark_time += stats.solver.benchmark_time;
  }

  template <int dim>
  void
  ElasticProblem<dim>::solve_sliding(
    const DiscreteProblem<dim>    &problem,
    TrilinosWrappers::MPI::Vector &owned_solution,
    const bool                     commit,
    const std::function<void()>   &on_failure)
  {
    try
      {
        sliding_solver.solve(problem,
                             model.faults,
                             interface_history,
                             owned_solution,
                             stats.solver,
                             [&](const std::string &line) {
                               log << line << std::endl;
                             });
        if (commit)
          interface_history.commit();
      }
    catch (const ComputationError &)
      {
        // The last iterate, for the user to look at, if it is one (a
        // diverged iteration has none).
        if (owned_solution.size() == dofs.n_dofs() &&
            std::isfinite(owned_solution.l2_norm()))
          {
            present_solution.reinit(system.locally_owned,
                                    system.locally_relevant,
                                    model.communicator);
            present_solution = owned_solution;
            if (on_failure)
              on_failure();
          }
        throw;
      }
  }

  template <int dim>
  DiscreteProblem<dim>
  ElasticProblem<dim>::discrete_problem()
  {
    DiscreteProblem<dim> problem{dofs,
                                 model.fe_space,
                                 system,
                                 model.stress_model,
                                 model.loads,
                                 model.prescribed_displacement,
                                 keep_setup,
                                 operator_version(),
                                 assembled_history};
    problem.symmetric = model.stress_model.symmetric_operator();
    return problem;
  }

  template <int dim>
  std::vector<TrilinosWrappers::MPI::Vector>
  ElasticProblem<dim>::solve_dual_problems(const StressGoals<dim> &goals,
                                           SolverReport           &report)
  {
    return lithostress::solve_dual_problems(goals,
                                            discrete_problem(),
                                            *solver,
                                            model.faults,
                                            sliding_solver.settings(),
                                            report);
  }

  template class ElasticProblem<2>;
} // namespace lithostress

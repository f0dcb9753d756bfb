#include <lithostress/faults/sliding_context.h>

namespace lithostress
{

  template <int dim>
  void
  FrictionalSlidingSolver<dim>::solve(
    const DiscreteProblem<dim>             &problem,
    const FaultInterface<dim>              &faults,
    FaultHistory                           &history,
    TrilinosWrappers::MPI::Vector          &solution,
    SolverReport                           &report,
    const std::function<void(std::string)> &progress)
  {
    const bool newton    = parameters.method == Method::newton;
    report               = SolverReport();
    report.solver        = newton ? "newton" : "thesis";
    report.linear_solves = 0;
    Timer timer(problem.dof_handler.get_communicator(), true);
    if (!kept || !kept->made_for(problem))
      kept = std::make_unique<KeptSlidingOperator<dim>>(
        problem, TrilinosWrappers::MPI::Vector());
    // Newton starts from a coarser mesh's solution (nested iteration), or
    // in the time loop from the last steps' extrapolation
    // (SolutionPredictor), or from the kept operator's last solution.
    kept->predicted_start = false;
    if (next_start.size() == problem.dof_handler.n_dofs())
      kept->solution = next_start;
    else if (problem.initial_guess != nullptr && newton)
      {
        kept->solution        = *problem.initial_guess;
        kept->predicted_start = true;
      }
    next_start.clear();
    Settings                                      settings = parameters;
    const TrilinosWrappers::MPI::Vector           start    = kept->solution;
    std::unique_ptr<sliding::SlidingContext<dim>> context;
    bool                                          converged           = false;
    unsigned int                                  diverged_iterations = 0;
    for (;;)
      {
        context = std::make_unique<sliding::SlidingContext<dim>>(
          settings, problem, faults, history, report, progress, *kept);
        try
          {
            converged = newton ? sliding::solve_by_newton(*context)
                               : sliding::solve_by_thesis_iteration(*context);
          }
        catch (...)
          {
            // The kept operator may be half updated.
            context.reset();
            kept.reset();
            throw;
          }
        if (!context->diverged)
          break;
        std::ostringstream line;
        line << std::setprecision(3)
             << "  sliding: Newton with the reaction in the tangent diverged "
                "(residual "
             << context->r_norm / context->f << " of the load in iteration "
             << context->iteration
             << "); solving again with the reactions taken as given";
        progress(line.str());
        diverged_iterations += context->iteration;
        context->add_phase_times(report.phases);
        // Afresh from the start: the kept operator holds the diverged
        // active set.
        context.reset();
        kept = std::make_unique<KeptSlidingOperator<dim>>(problem, start);
        settings.reaction_in_tangent = false;
      }
    sliding::SlidingContext<dim> &c = *context;
    // The last iterate's slip and states: the trial history, committed by
    // the caller (or, if not converged, shown).
    for (unsigned int i = 0; i < c.n_points; ++i)
      {
        history.set_trial(i, c.responses[i].history);
        history.trial_states[i]    = c.responses[i].state;
        history.normal_traction[i] = c.responses[i].normal_traction;
      }
    report.nonlinear_iterations =
      diverged_iterations + std::min(c.iteration, parameters.max_iterations);
    report.final_residual = c.r_norm / c.f;
    report.solve_time     = timer.wall_time();
    report.memory_bytes   = c.preconditioner_memory();
    c.add_phase_times(report.phases);
    solution = c.u;
    if (converged && newton)
      {
        kept->solution = c.u;
        kept->converged_states.resize(c.n_points);
        for (unsigned int i = 0; i < c.n_points; ++i)
          kept->converged_states[i] = c.responses[i].state;
        kept->has_converged_states = true;
      }
    if (!converged)
      {
        std::ostringstream state;
        state << std::setprecision(3) << "residual " << c.r_norm / c.f
              << " of the load, excess shear " << c.excess << " Pa";
        if (newton)
          throw ComputationError(
            sliding::newton_method(c).failure_message(state.str()));
        throw ComputationError(
          "the frictional sliding on " + faults.frictional_names() +
          " did not converge in " + std::to_string(parameters.max_iterations) +
          " thesis iterations (" + state.str() +
          "); the last iterate is written out. Raise Faults/Sliding "
          "solver/Maximum iterations, or change the Convergence factor "
          "(raise it while the excess shear falls steadily, lower it where "
          "it oscillates near the factor at which the iteration diverges)");
      }
  }

  template <int dim>
  FrictionalSlidingSolver<dim>::FrictionalSlidingSolver() = default;

  template <int dim>
  FrictionalSlidingSolver<dim>::~FrictionalSlidingSolver() = default;

  template <int dim>
  typename FrictionalSlidingSolver<dim>::Preconditioner
  FrictionalSlidingSolver<dim>::chosen_preconditioner(
    const Settings               &settings,
    const bool                    contact,
    const types::global_dof_index n_dofs,
    const unsigned int            n_ranks)
  {
    if (settings.preconditioner != Preconditioner::automatic)
      return settings.preconditioner;
    if (n_ranks == 1 && n_dofs <= settings.direct_limit &&
        (!contact || n_dofs <= settings.multigrid_limit))
      return Preconditioner::direct;
    // The two fields' multigrid where no factorisation is taken, in exact
    // contact (the spring's stiff pairs need the AMG's ILU smoothing): on
    // 2 ranks the thrust fault at 106 k DoFs took 7.5 s with it (206 CG
    // iterations) against 15.7 s with the AMG (1 138).
    return contact ? Preconditioner::multigrid : Preconditioner::amg;
  }

  template <int dim>
  bool
  FrictionalSlidingSolver<dim>::hands_over_to_direct(
    const Settings               &settings,
    const bool                    contact,
    const types::global_dof_index n_dofs,
    const unsigned int            n_ranks)
  {
    return settings.preconditioner == Preconditioner::automatic && contact &&
           n_ranks == 1 && n_dofs > settings.multigrid_limit &&
           n_dofs <= settings.direct_limit;
  }

  template class FrictionalSlidingSolver<2>;
} // namespace lithostress

#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/dofs/dof_tools.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/interruption.h>
#include <lithostress/base/output_file.h>
#include <lithostress/simulator/viscoelastic_time_loop.h>

#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

namespace lithostress
{
  namespace
  {
    /** @p names separated by commas. */
    std::string
    listed(const std::vector<std::string> &names)
    {
      std::string text;
      for (const std::string &name : names)
        text += (text.empty() ? "" : ", ") + name;
      return text;
    }
  } // namespace

  template <int dim>
  ViscoelasticTimeLoop<dim>::ViscoelasticTimeLoop(const TimeStepping &settings,
                                                  const Parts        &parts)
      : settings(settings)
      , parts(parts)
      , wall_clock(parts.access.communicator, true)
  {
  }

  template <int dim>
  unsigned int
  ViscoelasticTimeLoop<dim>::solve_system(const bool              new_mesh,
                                          const double            time,
                                          const CellHistory<dim> *history,
                                          const bool              commit_slip)
  {
    ElasticProblem<dim> &problem = parts.problem;
    const MPI_Comm       comm    = parts.access.communicator;
    if (new_mesh)
      problem.setup(time);
    else
      problem.update_constraints(time);
    interruption::stop_if_requested(comm, "assembly");
    problem.assemble(time, history);
    interruption::stop_if_requested(comm, "solve");
    problem.solve(commit_slip,
                  [&]() { parts.postprocessors.solve_failed(parts.access); });
    linear_solves += problem.statistics().solver.linear_solves;
    return problem.statistics().solver.iterations;
  }

  template <int dim>
  bool
  ViscoelasticTimeLoop<dim>::attempt_step(const double t_new,
                                          StepRecord  &record)
  {
    CreepIntegrator<dim> &creep   = parts.creep;
    StressModel<dim>     &model   = parts.stress_model;
    ElasticProblem<dim>  &problem = parts.problem;
    const double          h       = t_new - t;
    double                weight  = 0;
    {
      TimerOutput::Scope timer(parts.access.timer, "creep update");
      creep.keep_start();
      start_solution = problem.solution();
      weight         = creep.begin_step(problem.dof_handler(),
                                parts.access.fe_space,
                                model,
                                problem.solution(),
                                h,
                                settings.scheme,
                                settings.theta);
    }
    // A frictional fault's slip of this step counts only if it is accepted.
    typename CreepIntegrator<dim>::Increment increment;
    newton_failed = false;
    if (settings.scheme != TimeStepping::Scheme::thesis)
      {
        model.set_time_step(h, weight);
        if (!model.has_nonlinear_material())
          {
            record.linear_iterations +=
              solve_system(false, t_new, &creep.step_history(), false);
            record.nonlinear_iterations = 1;
          }
        else if (!newton_iteration(t_new, record))
          {
            newton_failed = true;
            creep.restore_start();
            problem.solution() = start_solution;
            return false;
          }
        TimerOutput::Scope timer(parts.access.timer, "creep update");
        increment = creep.finish_implicit_step(problem.dof_handler(),
                                               parts.access.fe_space,
                                               model,
                                               problem.solution());
      }
    else
      increment = thesis_iteration(t_new, record);
    record.creep_increment = increment.creep_change;
    // Relative to the largest elastic strain of the run: errors of a
    // relaxing stress are measured against its initial size, so that the
    // steps grow as the relaxation ends.
    const double scale    = std::max(strain_scale, increment.elastic_strain);
    record.error_estimate = increment.relative_error(scale);
    if (settings.adaptive && record.error_estimate > settings.tolerance)
      {
        // Undo: the creep strain and solution of the start of the step.
        creep.restore_start();
        problem.solution() = start_solution;
        return false;
      }
    strain_scale = scale;
    creep.accept_step();
    problem.commit_slip();
    return true;
  }

  template <int dim>
  bool
  ViscoelasticTimeLoop<dim>::newton_iteration(const double t_new,
                                              StepRecord  &record)
  {
    CreepIntegrator<dim> &creep                 = parts.creep;
    StressModel<dim>     &model                 = parts.stress_model;
    ElasticProblem<dim>  &problem               = parts.problem;
    const auto            linearise_at_solution = [&](const bool first) {
      TimerOutput::Scope timer(parts.access.timer, "creep update");
      const double       missed = creep.linearise(problem.dof_handler(),
                                            parts.access.fe_space,
                                            model,
                                            problem.solution(),
                                            first);
      model.attach_linearisation(&creep.linearisation());
      return missed;
    };
    // The first iterate is the last solutions' extrapolation to t_new (the
    // solution of the start of the step where none is known).
    if (settings.newton_from_extrapolation)
      problem.start_from_prediction(t_new);
    linearise_at_solution(true);
    std::ostringstream residuals;
    for (record.nonlinear_iterations = 1;; ++record.nonlinear_iterations)
      {
        record.linear_iterations +=
          solve_system(false, t_new, &creep.step_history(), false);
        const double missed = linearise_at_solution(false);
        residuals << (record.nonlinear_iterations > 1 ? ", " : "")
                  << std::setprecision(2) << missed;
        record.newton_residual = missed;
        if (missed <= settings.newton_tolerance)
          break;
        if (record.nonlinear_iterations >= settings.newton_max_iterations)
          {
            parts.access.log << "  Newton's iteration of the step to t = "
                             << settings.format(t_new)
                             << " has not converged (relative residuals "
                             << residuals.str() << "); the step is halved"
                             << std::endl;
            return false;
          }
      }
    record.newton_residuals = residuals.str();
    return true;
  }

  template <int dim>
  typename CreepIntegrator<dim>::Increment
  ViscoelasticTimeLoop<dim>::thesis_iteration(const double t_new,
                                              StepRecord  &record)
  {
    CreepIntegrator<dim> &creep   = parts.creep;
    StressModel<dim>     &model   = parts.stress_model;
    ElasticProblem<dim>  &problem = parts.problem;
    model.set_time_step(0, settings.theta);
    double change = std::numeric_limits<double>::infinity();
    for (record.nonlinear_iterations = 1;; ++record.nonlinear_iterations)
      {
        record.linear_iterations +=
          solve_system(false, t_new, &creep.step_history(), false);
        TimerOutput::Scope timer(parts.access.timer, "creep update");
        change = creep.update_thesis_history(problem.dof_handler(),
                                             parts.access.fe_space,
                                             model,
                                             problem.solution(),
                                             stress_scale);
        if (change <= settings.fixed_point_tolerance)
          break;
        if (record.nonlinear_iterations >= settings.fixed_point_max_iterations)
          {
            std::ostringstream message;
            message << "the thesis scheme's fixed-point iteration of the "
                       "step from t = "
                    << settings.format(t) << " to " << settings.format(t_new)
                    << " did not converge in "
                    << settings.fixed_point_max_iterations
                    << " iterations (relative stress change "
                    << std::setprecision(3) << change << " > "
                    << settings.fixed_point_tolerance
                    << "); shorten the step (Time stepping/Creep strain "
                       "tolerance or Maximum time step) or use Scheme = "
                       "BDF2. The results up to t = "
                    << settings.format(t) << " are complete.";
            throw ComputationError(message.str());
          }
      }
    return creep.finish_thesis_step(model);
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::refine_mesh()
  {
    CreepIntegrator<dim> &creep = parts.creep;
    parts.cycles.refine_mesh(parts.problem,
                             parts.access,
                             "the mesh of step " + std::to_string(step),
                             [&]() { creep.prepare_for_mesh_change(); });
    creep.finish_mesh_change();
    // Equilibrium on the new mesh for the transferred creep strain at the
    // current time: the elastic moduli with the creep strain as initial
    // strain.
    parts.stress_model.set_time_step(0, settings.theta);
    solve_system(true, t, &creep.cell_history(), true);
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::write_output(const unsigned int index)
  {
    TimerOutput::Scope timer(parts.access.timer, "output");
    parts.postprocessors.output_time(parts.access, index, t);
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::write_time_steps() const
  {
    const SimulatorAccess<dim> &a = parts.access;
    on_all_ranks(a.communicator, [&]() {
      if (!a.root())
        return;
      OutputFile csv(a.path("time_steps.csv"));
      csv << "step,time,dt,dofs,cells,linear_iterations,nonlinear_iterations,"
             "rejected_steps,creep_strain_increment,error_estimate,"
             "wall_time,newton_residual\n";
      for (const StepRecord &r : steps)
        csv << r.step << ',' << std::setprecision(12) << r.time << ',' << r.dt
            << ',' << r.dofs << ',' << r.cells << ',' << r.linear_iterations
            << ',' << r.nonlinear_iterations << ',' << r.rejected << ','
            << std::setprecision(6) << r.creep_increment << ','
            << r.error_estimate << ',' << r.wall_time << ','
            << r.newton_residual << '\n';
      csv.commit();
    });
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::report_step(const StepRecord &r)
  {
    std::ostringstream line;
    line << "step " << r.step << ": t = " << settings.format(r.time)
         << ", dt = " << settings.format(r.dt) << ", " << r.dofs << " DoFs, "
         << parts.problem.statistics().solver.solver << ' '
         << r.linear_iterations << " it";
    if (settings.scheme == TimeStepping::Scheme::thesis)
      line << " in " << r.nonlinear_iterations << " fixed-point iterations";
    else if (parts.stress_model.has_nonlinear_material())
      line << " in " << r.nonlinear_iterations
           << " Newton iterations (relative residuals " << r.newton_residuals
           << ")";
    line << ", creep increment " << std::setprecision(3) << r.creep_increment
         << ", error estimate " << r.error_estimate;
    if (r.rejected > 0)
      line << " (" << r.rejected << " rejected)";
    parts.access.log << line.str() << std::endl;
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::start()
  {
    StressModel<dim>     &model = parts.stress_model;
    CreepIntegrator<dim> &creep = parts.creep;
    // The elastic response at t = 0 on the mesh of the refinement cycles.
    t = 0;
    model.set_time_step(0, settings.theta);
    parts.cycles.run(parts.problem,
                     parts.postprocessors,
                     parts.access,
                     parts.start_output,
                     false);
    ++linear_solves;
    creep.start_history();
    model.attach_cell_history(&creep.cell_history());
    model.attach_flow_state(&creep.flow_state());
    if (settings.output_at_zero)
      write_output(0);

    double shortest_maxwell_time = std::numeric_limits<double>::infinity();
    for (const Material &m : parts.access.materials.materials())
      if (model.rheology(m.id).creeps())
        shortest_maxwell_time =
          std::min(shortest_maxwell_time,
                   model.rheology(m.id).relaxation_time());
    dt = settings.first_step > 0
           ? settings.first_step
           : (std::isfinite(shortest_maxwell_time)
                ? std::sqrt(2 * settings.tolerance) * shortest_maxwell_time
                : settings.end_time / 100);
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::write_checkpoint()
  {
    const SimulatorAccess<dim> &a = parts.access;
    TimerOutput::Scope          timer(a.timer, "checkpoint");
    const MPI_Comm              comm = a.communicator;
    const std::string           directory =
      a.path("checkpoint-" + Utilities::int_to_string(step, 6));
    on_all_ranks(comm, [&]() {
      if (a.root())
        {
          std::filesystem::remove_all(directory);
          std::filesystem::create_directories(directory);
        }
    });
    // The mesh with its fields: readable on any number of ranks.
    parts.creep.prepare_for_checkpoint();
    // The displacement, then the predictor's solutions (ghosted copies:
    // the transfer reads every DoF of the owned cells).
    const SolutionPredictor &predictor = parts.problem.solution_predictor();
    std::vector<TrilinosWrappers::MPI::Vector> ghosted;
    for (const auto *v : predictor.solutions())
      {
        ghosted.push_back(parts.problem.solution());
        ghosted.back() = *v;
      }
    std::vector<const TrilinosWrappers::MPI::Vector *> attached = {
      &parts.problem.solution()};
    for (const auto &v : ghosted)
      attached.push_back(&v);
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      displacement(parts.problem.dof_handler());
    displacement.prepare_for_serialization(attached);
    parts.problem.triangulation().save(directory + "/mesh");
    LoopState state;
    state.predictor_times = predictor.times();
    state.fault_history   = parts.problem.fault_history().gather(comm);
    state.cell_history    = parts.creep.cell_history().names();
    state.step            = step;
    state.linear_solves   = linear_solves;
    state.time            = t;
    state.dt              = dt;
    state.strain_scale    = strain_scale;
    state.stress_scale    = stress_scale;
    state.previous_dt     = parts.creep.previous_step_length();
    state.steps           = steps;
    parts.postprocessors.save(state.postprocessors);
    on_all_ranks(comm, [&]() {
      if (a.root())
        Checkpoint::write_state(directory,
                                state,
                                Checkpoint::model_text(parts.prm));
    });
    // Every rank's part of the mesh is written: only now does the pointer
    // move to the new checkpoint.
    MPI_Barrier(comm);
    on_all_ranks(comm, [&]() {
      if (a.root())
        Checkpoint::make_current(a.output_directory, directory);
    });
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::resume()
  {
    const SimulatorAccess<dim> &a       = parts.access;
    ElasticProblem<dim>        &problem = parts.problem;
    const std::string directory = Checkpoint::current(a.output_directory);
    const LoopState   state     = Checkpoint::read_state(directory);
    step                        = state.step;
    linear_solves               = state.linear_solves;
    t                           = state.time;
    dt                          = state.dt;
    strain_scale                = state.strain_scale;
    stress_scale                = state.stress_scale;
    steps                       = state.steps;
    // The mesh and the fields, in the order they were attached.
    if (state.cell_history != parts.creep.cell_history().names())
      throw ComputationError(
        "the checkpoint " + directory + " holds the history components <" +
        listed(state.cell_history) + "> at the cells, but the " +
        "model's rock laws keep <" +
        listed(parts.creep.cell_history().names()) + "> (start the run anew)");
    problem.fault_history().restore(state.fault_history);
    problem.triangulation().load(directory + "/mesh");
    parts.stress_model.set_time_step(0, settings.theta);
    problem.setup(t);
    parts.creep.load_from_checkpoint(state.previous_dt);
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      displacement(problem.dof_handler());
    std::vector<TrilinosWrappers::MPI::Vector> fields(
      1 + state.predictor_times.size(),
      TrilinosWrappers::MPI::Vector(problem.dof_handler().locally_owned_dofs(),
                                    a.communicator));
    std::vector<TrilinosWrappers::MPI::Vector *> into;
    for (auto &v : fields)
      into.push_back(&v);
    displacement.deserialize(into);
    const TrilinosWrappers::MPI::Vector owned = std::move(fields[0]);
    fields.erase(fields.begin());
    problem.solution_predictor().restore(state.predictor_times, fields);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(problem.dof_handler(), relevant);
    problem.solution().reinit(problem.dof_handler().locally_owned_dofs(),
                              relevant,
                              a.communicator);
    problem.solution() = owned;
    parts.stress_model.attach_cell_history(&parts.creep.cell_history());
    parts.stress_model.attach_flow_state(&parts.creep.flow_state());
    parts.start_output();
    a.log << "Resumed from " << directory << ": step " << step
          << ", t = " << settings.format(t) << " (" << t << " s), "
          << a.triangulation.n_global_active_cells() << " cells\n";
    write_time_steps();
    parts.postprocessors.load(a, state.postprocessors);
  }

  template <int dim>
  double
  ViscoelasticTimeLoop<dim>::step_limit(const double proposed) const
  {
    // Variable-step BDF2 is zero-stable for step ratios below 1 + √2:
    // after a short step (one that landed on an output time) the steps
    // grow back by doublings.
    const double previous = parts.creep.previous_step_length();
    if (settings.scheme == TimeStepping::Scheme::bdf2 && previous > 0)
      return std::min(proposed, 2 * previous);
    return proposed;
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::run()
  {
    parts.access.log << "Visco-elastic time loop to "
                     << settings.format(settings.end_time) << " ("
                     << settings.end_time << " s; every output time in s), "
                     << (settings.scheme == TimeStepping::Scheme::thesis
                           ? std::string("thesis initial-strain scheme")
                         : settings.scheme == TimeStepping::Scheme::bdf2
                           ? std::string("BDF2")
                           : "generalized midpoint rule, theta = " +
                               std::to_string(settings.theta))
                     << '\n';
    if (settings.scheme == TimeStepping::Scheme::thesis &&
        parts.stress_model.has_nonlinear_material())
      throw_input_error("Time stepping/Scheme",
                        "is thesis, whose fixed-point iteration is made for "
                        "linear Maxwell creep; a non-linear rheology "
                        "(visco-elasto-plastic) needs BDF2 or midpoint");
    parts.problem.keep_solver_setup(true);
    if (settings.resume)
      resume();
    else
      start();

    while (t < settings.end_time)
      try
        {
          take_step();
        }
      catch (const RunInterrupted &stop)
        {
          // Name the step of a stop inside it (assembly, solve, CG).
          if (stop.where().rfind("time step", 0) == 0)
            throw;
          throw RunInterrupted(stop.signal(),
                               "time step " + std::to_string(step + 1) + " (" +
                                 stop.where() + ")");
        }
    write_checkpoint();
    parts.access.log << "Time loop: " << step << " steps, " << linear_solves
                     << " linear solves, " << std::setprecision(4)
                     << wall_clock.wall_time() << " s\n";
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::take_step()
  {
    interruption::stop_if_requested(parts.access.communicator,
                                    "time step " + std::to_string(step + 1));
    StepRecord record;
    Timer      clock(parts.access.communicator, true);
    double     t_new = settings.next_time(t, step_limit(dt));
    while (!attempt_step(t_new, record))
      {
        ++record.rejected;
        // The estimate grows as Δt^(p+1) for a method of order p: aim
        // at half the tolerance.
        const double h     = t_new - t;
        const double power = parts.creep.second_order_step() ? 3 : 2;
        dt                 = newton_failed ? 0.5 * h
                                           : h * std::max(0.1,
                                          std::pow(0.5 * settings.tolerance /
                                                     record.error_estimate,
                                                   1 / power));
        if (dt < settings.minimum_step)
          throw ComputationError(
            "the time step from t = " + settings.format(t) +
            " would have to be shorter than the Minimum time step (" +
            settings.format(settings.minimum_step) + ") " +
            (newton_failed
               ? "for Newton's iteration to converge (raise Time "
                 "stepping/Maximum Newton iterations or Newton tolerance)"
               : "to keep the creep-strain increment below the tolerance"));
        t_new = settings.next_time(t, step_limit(dt));
      }
    record.dt    = t_new - t;
    t            = t_new;
    record.time  = t;
    record.step  = ++step;
    record.dofs  = parts.problem.dof_handler().n_dofs();
    record.cells = parts.access.triangulation.n_global_active_cells();
    // Double the step while the estimate (∝ Δt², or Δt³ for BDF2)
    // stays below a quarter (an eighth) of the tolerance; otherwise
    // keep it, so that the solver's set-up for the step stays valid.
    const double growth_margin = parts.creep.second_order_step() ? 0.125 : 0.25;
    if (settings.adaptive &&
        record.error_estimate < growth_margin * settings.tolerance &&
        record.dt >= 0.99 * dt)
      dt *= 2;
    // Fixed steps halved for Newton's iteration grow back by doublings
    // to the First time step.
    if (!settings.adaptive && dt < settings.first_step)
      dt = std::min(2 * dt, settings.first_step);
    const int output = settings.output_index(t);
    if (output >= 0)
      write_output(output);
    record.wall_time = clock.wall_time();
    steps.push_back(record);
    write_time_steps();
    report_step(record);
    if (settings.refinement_interval > 0 &&
        step % settings.refinement_interval == 0 && t < settings.end_time)
      refine_mesh();
    if (settings.checkpoint_interval > 0 &&
        step % settings.checkpoint_interval == 0 && t < settings.end_time)
      write_checkpoint();
  }

  template class ViscoelasticTimeLoop<2>;
} // namespace lithostress

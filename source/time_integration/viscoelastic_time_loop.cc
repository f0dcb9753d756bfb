#include <lithostress/base/input_error.h>
#include <lithostress/output/output_file.h>
#include <lithostress/postprocess/point_values.h>
#include <lithostress/time_integration/checkpoint.h>
#include <lithostress/time_integration/viscoelastic_time_loop.h>

#include <deal.II/distributed/solution_transfer.h>

#include <filesystem>
#include <fstream>

#include <iomanip>
#include <limits>
#include <sstream>

namespace lithostress
{
  template <int dim>
  ViscoelasticTimeLoop<dim>::ViscoelasticTimeLoop(Simulator<dim> &simulator)
      : sim(simulator)
      , settings(simulator.time_stepping)
      , wall_clock(simulator.communicator, true)
  {
  }

  template <int dim>
  unsigned int
  ViscoelasticTimeLoop<dim>::solve_system(const bool new_mesh)
  {
    if (new_mesh)
      sim.setup_dofs();
    else
      {
        // The same mesh: new prescribed values at the new time (the
        // structure of the constraints, and so the matrix's, is the same);
        // the solver released the right-hand side.
        TimerOutput::Scope t(*sim.timer, "setup");
        sim.make_constraints();
        sim.system.rhs.reinit(sim.system.locally_owned, sim.communicator);
      }
    sim.stop_if_requested("assembly");
    sim.assemble_system();
    sim.stop_if_requested("solve");
    sim.solve();
    linear_solves += sim.statistics.solver.linear_solves;
    return sim.statistics.solver.iterations;
  }

  template <int dim>
  bool
  ViscoelasticTimeLoop<dim>::attempt_step(const double t_new,
                                          StepRecord  &record)
  {
    CreepIntegrator<dim> &creep = *sim.creep;
    StressModel<dim>     &model = *sim.stress_model;
    const double          h     = t_new - t;
    const bool thesis = settings.scheme == TimeStepping::Scheme::thesis;
    double     weight = 0;
    {
      TimerOutput::Scope timer(*sim.timer, "creep update");
      creep.keep_start();
      start_solution = sim.solution;
      weight         = creep.begin_step(sim.dof_handler,
                                *sim.fe_space,
                                model,
                                sim.solution,
                                h,
                                settings.scheme,
                                settings.theta);
    }
    sim.time           = t_new;
    sim.history_strain = &creep.history_strain();
    // A frictional fault's slip of this step counts only if it is accepted.
    sim.defer_slip_commit = true;
    typename CreepIntegrator<dim>::Increment increment;
    if (!thesis)
      {
        model.set_time_step(h, weight);
        record.linear_iterations += solve_system(false);
        record.nonlinear_iterations = 1;
        TimerOutput::Scope timer(*sim.timer, "creep update");
        increment = creep.finish_implicit_step(sim.dof_handler,
                                               *sim.fe_space,
                                               model,
                                               sim.solution);
      }
    else
      {
        model.set_time_step(0, settings.theta);
        double change = std::numeric_limits<double>::infinity();
        for (record.nonlinear_iterations = 1;; ++record.nonlinear_iterations)
          {
            record.linear_iterations += solve_system(false);
            TimerOutput::Scope timer(*sim.timer, "creep update");
            change = creep.update_thesis_history(sim.dof_handler,
                                                 *sim.fe_space,
                                                 model,
                                                 sim.solution,
                                                 stress_scale);
            if (change <= settings.fixed_point_tolerance)
              break;
            if (record.nonlinear_iterations >=
                settings.fixed_point_max_iterations)
              {
                std::ostringstream message;
                message << "the thesis scheme's fixed-point iteration of the "
                           "step from t = "
                        << settings.format(t) << " to "
                        << settings.format(t_new) << " did not converge in "
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
        increment = creep.finish_thesis_step(model);
      }
    sim.history_strain     = nullptr;
    sim.defer_slip_commit  = false;
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
        sim.solution = start_solution;
        sim.time     = t;
        return false;
      }
    strain_scale = scale;
    creep.accept_step();
    sim.slip_history.commit();
    return true;
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::refine_mesh()
  {
    CreepIntegrator<dim> &creep = *sim.creep;
    sim.refine_mesh("the mesh of step " + std::to_string(step),
                    [&]() { creep.prepare_for_mesh_change(); });
    creep.finish_mesh_change();
    // Equilibrium on the new mesh for the transferred creep strain at the
    // current time: the elastic moduli with the creep strain as initial
    // strain.
    sim.stress_model->set_time_step(0, settings.theta);
    sim.history_strain = &creep.creep_strain();
    solve_system(true);
    sim.history_strain = nullptr;
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::write_output(const unsigned int index)
  {
    TimerOutput::Scope timer(*sim.timer, "output");
    sim.solution_output.write(sim.output_directory,
                              index,
                              t,
                              sim.dof_handler,
                              *sim.fe_space,
                              *sim.stress_model,
                              sim.griffith,
                              sim.solution);
    if (sim.faults.has_face_terms())
      sim.write_fault_results(index);
    if (sim.points.empty())
      return;
    const auto values = evaluate_at_points(sim.dof_handler,
                                           *sim.fe_space,
                                           *sim.stress_model,
                                           sim.solution,
                                           sim.points);
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        std::ostringstream row;
        row << std::setprecision(10) << t << ',' << k + 1 << ','
            << values[k].point[0] << ',' << values[k].point[1] << ','
            << values[k].displacement[0] << ',' << values[k].displacement[1]
            << ',' << values[k].stress[0][0] << ',' << values[k].stress[1][1]
            << ',' << values[k].stress[0][1] << ',' << values[k].sigma_zz;
        point_history.push_back(row.str());
      }
    write_point_history();
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::write_point_history() const
  {
    on_all_ranks(sim.communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(sim.communicator) != 0 ||
          sim.points.empty())
        return;
      OutputFile csv(sim.output_directory + "/point_history.csv");
      csv << "time,point,x,y,u_x,u_y,s_xx,s_yy,s_xy,s_zz\n";
      for (const std::string &row : point_history)
        csv << row << '\n';
      csv.commit();
    });
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::write_time_steps() const
  {
    on_all_ranks(sim.communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(sim.communicator) != 0)
        return;
      OutputFile csv(sim.output_directory + "/time_steps.csv");
      csv << "step,time,dt,dofs,cells,linear_iterations,nonlinear_iterations,"
             "rejected_steps,creep_strain_increment,error_estimate,"
             "wall_time\n";
      for (const StepRecord &r : steps)
        csv << r.step << ',' << std::setprecision(12) << r.time << ',' << r.dt
            << ',' << r.dofs << ',' << r.cells << ',' << r.linear_iterations
            << ',' << r.nonlinear_iterations << ',' << r.rejected << ','
            << std::setprecision(6) << r.creep_increment << ','
            << r.error_estimate << ',' << r.wall_time << '\n';
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
         << sim.statistics.solver.solver << ' ' << r.linear_iterations << " it";
    if (settings.scheme == TimeStepping::Scheme::thesis)
      line << " in " << r.nonlinear_iterations << " fixed-point iterations";
    line << ", creep increment " << std::setprecision(3) << r.creep_increment
         << ", error estimate " << r.error_estimate;
    if (r.rejected > 0)
      line << " (" << r.rejected << " rejected)";
    sim.log << line.str() << std::endl;
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::start()
  {
    StressModel<dim>     &model = *sim.stress_model;
    CreepIntegrator<dim> &creep = *sim.creep;
    // The elastic response at t = 0 on the mesh of the refinement cycles.
    sim.time = 0;
    model.set_time_step(0, settings.theta);
    for (sim.cycle = 0;; ++sim.cycle)
      {
        if (sim.cycle > 0)
          sim.refine_mesh("the mesh of cycle " + std::to_string(sim.cycle));
        sim.compute_cycle();
        if (sim.last_cycle())
          break;
      }
    ++linear_solves;
    creep.start_history();
    model.attach_creep_strain(&creep.creep_strain());
    if (settings.output_at_zero)
      write_output(0);

    double shortest_maxwell_time = std::numeric_limits<double>::infinity();
    for (const Material &m : sim.materials.materials())
      if (model.maxwell(m.id).is_viscous())
        shortest_maxwell_time =
          std::min(shortest_maxwell_time, model.maxwell(m.id).maxwell_time());
    dt = settings.first_step > 0
           ? settings.first_step
           : (std::isfinite(shortest_maxwell_time)
                ? std::sqrt(2 * settings.tolerance) * shortest_maxwell_time
                : settings.end_time / 100);
  }

  namespace
  {
    /** Exact text of a double (hexadecimal), read back by std::stod. */
    std::string
    exact(const double x)
    {
      std::ostringstream out;
      out << std::hexfloat << x;
      return out.str();
    }
  } // namespace

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::write_checkpoint()
  {
    TimerOutput::Scope timer(*sim.timer, "checkpoint");
    const MPI_Comm     comm = sim.communicator;
    const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string  directory =
      sim.output_directory + "/checkpoint-" + Utilities::int_to_string(step, 6);
    on_all_ranks(comm, [&]() {
      if (root)
        {
          std::filesystem::remove_all(directory);
          std::filesystem::create_directories(directory);
        }
    });
    // The mesh with its fields: readable on any number of ranks.
    sim.creep->prepare_for_checkpoint();
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
      displacement(sim.dof_handler);
    displacement.prepare_for_serialization(sim.solution);
    sim.triangulation.save(directory + "/mesh");
    const std::vector<FaultSlipHistory::Record> fault_slip =
      sim.slip_history.gather(comm);

    on_all_ranks(comm, [&]() {
      if (!root)
        return;
      std::ostringstream state;
      state << "lithostress-checkpoint 2\n"
            << "step " << step << "\ntime " << exact(t) << "\ndt " << exact(dt)
            << "\nstrain_scale " << exact(strain_scale) << "\nstress_scale "
            << exact(stress_scale) << "\nprevious_dt "
            << exact(sim.creep->previous_step_length()) << "\nlinear_solves "
            << linear_solves << "\nrecords "
            << sim.solution_output.records.size() << '\n';
      for (const auto &[time, file] : sim.solution_output.records)
        state << exact(time) << ' ' << file << '\n';
      state << "steps " << steps.size() << '\n';
      for (const StepRecord &r : steps)
        state << r.step << ' ' << exact(r.time) << ' ' << exact(r.dt) << ' '
              << r.dofs << ' ' << r.cells << ' ' << r.linear_iterations << ' '
              << r.nonlinear_iterations << ' ' << r.rejected << ' '
              << exact(r.creep_increment) << ' ' << exact(r.error_estimate)
              << ' ' << exact(r.wall_time) << '\n';
      state << "history " << point_history.size() << '\n';
      for (const std::string &row : point_history)
        state << row << '\n';
      state << "fault_slip " << fault_slip.size() << '\n';
      for (const auto &r : fault_slip)
        state << exact(r[0]) << ' ' << exact(r[1]) << ' ' << r[2] << ' ' << r[3]
              << '\n';
      write_file_atomically(directory + "/state.txt", state.str(), false);
      write_file_atomically(directory + "/model.prm",
                            Checkpoint::model_text(sim.prm),
                            false);
    });
    // Every rank's part of the mesh is written: only now does the pointer
    // move to the new checkpoint.
    MPI_Barrier(comm);
    on_all_ranks(comm, [&]() {
      if (root)
        Checkpoint::make_current(sim.output_directory, directory);
    });
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::resume()
  {
    StressModel<dim>     &model     = *sim.stress_model;
    CreepIntegrator<dim> &creep     = *sim.creep;
    const std::string     directory = Checkpoint::current(sim.output_directory);
    std::ifstream         in(directory + "/state.txt");
    std::string           word;
    unsigned int          version = 0, n = 0;
    const auto            expect = [&](const std::string &key) {
      in >> word;
      if (word != key)
        throw ComputationError("the checkpoint " + directory +
                               "/state.txt is damaged (expected <" + key +
                               ">, found <" + word + ">)");
    };
    const auto number = [&]() {
      in >> word;
      return std::stod(word);
    };
    expect("lithostress-checkpoint");
    in >> version;
    if (version != 2)
      throw ComputationError("the checkpoint " + directory +
                             "/state.txt has format " +
                             std::to_string(version) +
                             "; this lithostress reads format 2 (start the "
                             "run anew)");
    expect("step");
    in >> step;
    expect("time");
    t = number();
    expect("dt");
    dt = number();
    expect("strain_scale");
    strain_scale = number();
    expect("stress_scale");
    stress_scale = number();
    expect("previous_dt");
    const double previous_dt = number();
    expect("linear_solves");
    in >> linear_solves;
    expect("records");
    in >> n;
    sim.solution_output.records.clear();
    for (unsigned int k = 0; k < n; ++k)
      {
        const double time = number();
        in >> word;
        sim.solution_output.records.emplace_back(time, word);
      }
    expect("steps");
    in >> n;
    steps.resize(n);
    for (StepRecord &r : steps)
      {
        in >> r.step;
        r.time = number();
        r.dt   = number();
        in >> r.dofs >> r.cells >> r.linear_iterations >>
          r.nonlinear_iterations >> r.rejected;
        r.creep_increment = number();
        r.error_estimate  = number();
        r.wall_time       = number();
      }
    expect("history");
    in >> n;
    std::getline(in, word);
    point_history.resize(n);
    for (std::string &row : point_history)
      std::getline(in, row);
    // A frictional fault's slip along it (absent in older checkpoints).
    std::vector<FaultSlipHistory::Record> fault_slip;
    if (in >> word)
      {
        if (word != "fault_slip")
          throw ComputationError("the checkpoint " + directory +
                                 "/state.txt is damaged (expected "
                                 "<fault_slip>, found <" +
                                 word + ">)");
        in >> n;
        fault_slip.resize(n);
        for (auto &r : fault_slip)
          {
            r[0] = number();
            r[1] = number();
            in >> r[2] >> r[3];
          }
      }
    else
      in.clear();
    if (!in)
      throw ComputationError("the checkpoint " + directory +
                             "/state.txt is damaged (truncated)");

    // The mesh and the fields, in the order they were attached.
    sim.slip_history.restore(fault_slip);
    sim.triangulation.load(directory + "/mesh");
    sim.time = t;
    model.set_time_step(0, settings.theta);
    sim.setup_dofs();
    creep.load_from_checkpoint(previous_dt);
    parallel::distributed::SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
                                  displacement(sim.dof_handler);
    TrilinosWrappers::MPI::Vector owned(sim.system.locally_owned,
                                        sim.communicator);
    displacement.deserialize(owned);
    sim.solution.reinit(sim.system.locally_owned,
                        sim.system.locally_relevant,
                        sim.communicator);
    sim.solution = owned;
    model.attach_creep_strain(&creep.creep_strain());
    sim.start_output();
    sim.log << "Resumed from " << directory << ": step " << step
            << ", t = " << settings.format(t) << " (" << t << " s), "
            << sim.triangulation.n_global_active_cells() << " cells\n";
    write_time_steps();
    write_point_history();
  }

  template <int dim>
  double
  ViscoelasticTimeLoop<dim>::step_limit(const double proposed) const
  {
    // Variable-step BDF2 is zero-stable for step ratios below 1 + √2:
    // after a short step (one that landed on an output time) the steps
    // grow back by doublings.
    const double previous = sim.creep->previous_step_length();
    if (settings.scheme == TimeStepping::Scheme::bdf2 && previous > 0)
      return std::min(proposed, 2 * previous);
    return proposed;
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::run()
  {
    sim.write_run_header(!settings.resume);
    sim.log << "Visco-elastic time loop to "
            << settings.format(settings.end_time) << " (" << settings.end_time
            << " s; every output time in s), "
            << (settings.scheme == TimeStepping::Scheme::thesis
                  ? std::string("thesis initial-strain scheme")
                : settings.scheme == TimeStepping::Scheme::bdf2
                  ? std::string("BDF2")
                  : "generalized midpoint rule, theta = " +
                      std::to_string(settings.theta))
            << '\n';
    sim.keep_solver_setup = true;
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
    sim.log << "Time loop: " << step << " steps, " << linear_solves
            << " linear solves, " << std::setprecision(4)
            << wall_clock.wall_time() << " s\n";
    sim.write_final_results();
  }

  template <int dim>
  void
  ViscoelasticTimeLoop<dim>::take_step()
  {
    sim.stop_if_requested("time step " + std::to_string(step + 1));
    StepRecord record;
    Timer      clock(sim.communicator, true);
    double     t_new = settings.next_time(t, step_limit(dt));
    while (!attempt_step(t_new, record))
      {
        ++record.rejected;
        // The estimate grows as Δt^(p+1) for a method of order p: aim
        // at half the tolerance.
        const double h     = t_new - t;
        const double power = sim.creep->second_order_step() ? 3 : 2;
        dt                 = h *
             std::max(0.1,
                      std::pow(0.5 * settings.tolerance / record.error_estimate,
                               1 / power));
        if (dt < settings.minimum_step)
          throw ComputationError(
            "the time step from t = " + settings.format(t) +
            " would have to be shorter than the Minimum time step (" +
            settings.format(settings.minimum_step) +
            ") to keep the creep-strain increment below the tolerance");
        t_new = settings.next_time(t, step_limit(dt));
      }
    record.dt    = t_new - t;
    t            = t_new;
    record.time  = t;
    record.step  = ++step;
    record.dofs  = sim.dof_handler.n_dofs();
    record.cells = sim.triangulation.n_global_active_cells();
    // Double the step while the estimate (∝ Δt², or Δt³ for BDF2)
    // stays below a quarter (an eighth) of the tolerance; otherwise
    // keep it, so that the solver's set-up for the step stays valid.
    const double growth_margin = sim.creep->second_order_step() ? 0.125 : 0.25;
    if (settings.adaptive &&
        record.error_estimate < growth_margin * settings.tolerance &&
        record.dt >= 0.99 * dt)
      dt *= 2;
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

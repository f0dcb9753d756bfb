#ifndef lithostress_simulator_viscoelastic_time_loop_h
#define lithostress_simulator_viscoelastic_time_loop_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/postprocessors/postprocessor.h>
#include <lithostress/simulator/elastic_problem.h>
#include <lithostress/simulator/refinement_cycles.h>
#include <lithostress/time_integration/checkpoint.h>
#include <lithostress/time_integration/creep_integrator.h>
#include <lithostress/time_integration/time_stepping.h>

#include <functional>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The visco-elastic time loop (thesis §3.9, §4.5, §7): the elastic
   * response at t = 0 on the mesh of the refinement cycles, then steps of
   * Maxwell creep to the end time with the integrator and the step-size
   * control of TimeStepping, the creep history in CreepIntegrator,
   * adaptive refinement with history transfer every few steps, the
   * postprocessors at every output time (a ParaView step in
   * `solution.pvd`, `point_history.csv`, fault output), `time_steps.csv`
   * (one row per step) and checkpoints. It owns the model time t and the
   * step Δt; it works on the parts it is given, not on the Simulator.
   */
  template <int dim>
  class ViscoelasticTimeLoop
  {
  public:
    /** What the loop drives. */
    struct Parts
    {
      ElasticProblem<dim>        &problem;
      RefinementCycles<dim>      &cycles;
      PostprocessorList<dim>     &postprocessors;
      const SimulatorAccess<dim> &access;
      CreepIntegrator<dim>       &creep;
      /** Its step moduli are set per step, the laws' history attached. */
      StressModel<dim> &stress_model;
      /** The model's parameters (kept with every checkpoint). */
      ParameterHandler &prm;
      /** Open log.txt and write parameters.prm (the Simulator's). */
      std::function<void()> start_output;
    };

    ViscoelasticTimeLoop(const TimeStepping &settings, const Parts &parts);

    /** Run from t = 0 (or the checkpoint) to the end time. */
    void
    run();

  private:
    /** Set up (on a new mesh) or update the constraints, assemble at time
     * t with the history strain @p history, and solve; the slip of a
     * frictional fault is committed if @p commit_slip. Returns the linear
     * iterations. */
    unsigned int
    solve_system(const bool              new_mesh,
                 const double            time,
                 const CellHistory<dim> *history,
                 const bool              commit_slip);

    /** Try the step from t to @p t_new; false if the step control rejects
     * it (everything is then as before). */
    bool
    attempt_step(const double t_new, StepRecord &record);

    /** Newton's iteration of the step to @p t_new for non-linear laws
     * (doc/equations.md §12): each iteration linearises the laws at the
     * iterate (CreepIntegrator::linearise()) and solves the linear problem
     * of the linearisation; false if it has not converged within the
     * Maximum Newton iterations. */
    bool
    newton_iteration(const double t_new, StepRecord &record);

    /** The thesis scheme's fixed-point iteration of the step to
     * @p t_new (thesis §3.9, ELVIS and CREEPS); returns the increment. */
    typename CreepIntegrator<dim>::Increment
    thesis_iteration(const double t_new, StepRecord &record);

    /** One accepted step from t (with its rejected attempts), its output,
     * and the refinement and checkpoint that fall on it. */
    void
    take_step();

    /** The step to take when the controller proposes @p proposed: BDF2
     * steps grow by at most a factor 2 (its zero-stability). */
    double
    step_limit(const double proposed) const;

    /** Refine and coarsen, transfer the creep strain, and re-establish
     * equilibrium on the new mesh at the current time. */
    void
    refine_mesh();

    /** The postprocessors of output time number @p index. */
    void
    write_output(const unsigned int index);

    /** Rewrite time_steps.csv with all steps so far. */
    void
    write_time_steps() const;

    /** The elastic response at t = 0 on the mesh of the refinement
     * cycles: the start of a new run. */
    void
    start();

    /** Continue from the current checkpoint (Checkpoint): mesh, fields
     * and the loop's state; the outputs are rewritten up to it. */
    void
    resume();

    /** Write a checkpoint of the current state (collective). */
    void
    write_checkpoint();

    /** One line per step on screen and in log.txt. */
    void
    report_step(const StepRecord &record);

    const TimeStepping &settings;
    Parts               parts;
    double              t = 0, dt = 0;
    /** The largest elastic deviatoric strain max‖s/(2G)‖ of the run so
     * far: the scale of the step's error estimate. */
    double strain_scale = 0;
    /** The largest deviatoric stress of the run so far: the scale of the
     * thesis scheme's fixed-point test. */
    double       stress_scale = 0;
    unsigned int step = 0, linear_solves = 0;
    /** Whether the last attempt_step() failed in Newton's iteration (the
     * step is then halved). */
    bool                    newton_failed = false;
    std::vector<StepRecord> steps;
    /** The solution at the start of a step (restored when the step is
     * rejected). */
    TrilinosWrappers::MPI::Vector start_solution;
    Timer                         wall_clock;
  };
} // namespace lithostress

#endif

#ifndef lithostress_time_integration_viscoelastic_time_loop_h
#define lithostress_time_integration_viscoelastic_time_loop_h

#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/simulator.h>

#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The visco-elastic time loop (SPEC §3.3; thesis §3.9, §4.5, §7): the
   * elastic response at t = 0 on the mesh of the refinement cycles, then
   * steps of Maxwell creep to the end time with the integrator and the
   * step-size control of TimeStepping, the creep history in
   * CreepIntegrator, adaptive refinement with history transfer every few
   * steps, and the outputs of a time series: a ParaView step per output
   * time in `solution.pvd`, `time_steps.csv` (one row per step) and
   * `point_history.csv` (one row per output time and report point).
   *
   * It drives the Simulator's parts (set-up, assembly, solve, output) as
   * the elastic cycles do; the Simulator stays a short driver that hands
   * the run to this class when `Time stepping/Enabled` is set.
   */
  template <int dim>
  class ViscoelasticTimeLoop
  {
  public:
    explicit ViscoelasticTimeLoop(Simulator<dim> &simulator);

    /** Run from t = 0 (or the checkpoint) to the end time. */
    void
    run();

  private:
    /** What one accepted step did: a row of time_steps.csv. */
    struct StepRecord
    {
      unsigned int       step = 0;
      double             time = 0, dt = 0;
      unsigned long long dofs = 0, cells = 0;
      unsigned int       linear_iterations = 0, nonlinear_iterations = 0;
      unsigned int       rejected = 0;
      /** max ‖Δc‖ and the step's relative local error estimate. */
      double creep_increment = 0, error_estimate = 0;
      double wall_time = 0;
    };

    /** Set up, assemble and solve at the simulator's current time with its
     * current step moduli and history strain. Returns the CG iterations. */
    unsigned int
    solve_system(const bool new_mesh);

    /** Try the step from t to @p t_new; false if the step control rejects
     * it (everything is then as before). */
    bool
    attempt_step(const double t_new, StepRecord &record);

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

    /** Write the ParaView step and the point history of output time
     * number @p index. */
    void
    write_output(const unsigned int index);

    /** Rewrite point_history.csv with all rows so far. */
    void
    write_point_history() const;

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

    Simulator<dim>     &sim;
    const TimeStepping &settings;
    double              t = 0, dt = 0;
    /** The largest elastic deviatoric strain max‖s/(2G)‖ of the run so
     * far: the scale of the step's error estimate. */
    double strain_scale = 0;
    /** The largest deviatoric stress of the run so far: the scale of the
     * thesis scheme's fixed-point test. */
    double                   stress_scale = 0;
    unsigned int             step = 0, linear_solves = 0;
    std::vector<StepRecord>  steps;
    std::vector<std::string> point_history;
    /** The solution at the start of a step (restored when the step is
     * rejected). */
    TrilinosWrappers::MPI::Vector start_solution;
    Timer                         wall_clock;
  };
} // namespace lithostress

#endif

#ifndef lithostress_simulator_h
#define lithostress_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/base/memory_budget.h>
#include <lithostress/boundary_conditions/prescribed_displacement.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/discretization/linear_system.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/faults/fault_slip_history.h>
#include <lithostress/faults/frictional_sliding_solver.h>
#include <lithostress/geometry/geometry_model.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/material.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/output/figures.h>
#include <lithostress/output/run_log.h>
#include <lithostress/output/solution_output.h>
#include <lithostress/postprocess/convergence_study.h>
#include <lithostress/postprocess/griffith_failure.h>
#include <lithostress/postprocess/stress_depth_profiles.h>
#include <lithostress/postprocess/thin_plate_flexure.h>
#include <lithostress/reference_solutions/reference_solution.h>
#include <lithostress/refinement/dual_solutions.h>
#include <lithostress/refinement/mesh_refinement.h>
#include <lithostress/refinement/stress_goals.h>
#include <lithostress/solvers/linear_solver.h>
#include <lithostress/time_integration/creep_integrator.h>
#include <lithostress/time_integration/time_stepping.h>

#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  template <int dim>
  class ViscoelasticTimeLoop;

  /**
   * The lithostress simulator: wires geometry, materials, loads, boundary
   * conditions, discretization, solver, refinement and output, in the spirit
   * of deal.II step-40 and ASPECT's Simulator. The constructor reads and
   * checks the whole model — so that bad input is reported before anything
   * is written — and run() performs the refinement cycles: set up, assemble,
   * solve, postprocess, output, refine.
   */
  template <int dim>
  class Simulator
  {
  public:
    /** Declare every parameter of the program (see ParameterFile). */
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);

    /** Read the model from @p prm and check it against the mesh. */
    Simulator(const MPI_Comm communicator, ParameterHandler &prm);

    /** Run all cycles; writes into the output directory. */
    void
    run();

    /** The convergence table after run(). */
    const ConvergenceStudy &
    convergence_study() const
    {
      return study;
    }

    /** Timings and sizes of the last cycle, for the benchmark. */
    struct CycleStatistics
    {
      unsigned long long dofs = 0, cells = 0;
      SolverReport       solver;
      double mesh_time = 0, setup_time = 0, assemble_time = 0, solve_time = 0;
      /** Wall time of all cycles spent timing matrix-vector products for
       * the benchmark; left out of solve_s and total_s. */
      double benchmark_time = 0;
      /** The set-up split into its parts (name, seconds): DoFs,
       * constraints, sparsity pattern and matrix. */
      std::vector<std::pair<std::string, double>> setup_phases;
    };

    const CycleStatistics &
    last_cycle() const
    {
      return statistics;
    }

  private:
    void
    setup_dofs();
    /** Hanging-node constraints and the prescribed displacements at the
     * current time. */
    void
    make_constraints();
    void
    assemble_system();
    void
    solve();
    /** The discrete problem of the present mesh, operator and system, for
     * the solvers (the solution's and the goals' dual problems). */
    DiscreteProblem<dim>
    discrete_problem();
    void
    postprocess(const unsigned int cycle);
    /** The goals' values of this cycle: convergence table, log, and
     * whether they have converged (Mesh refinement/Goals). */
    void
    record_goals();
    /** Whether the cycle just computed is the last: the goals have
     * converged, or it is the last of `Number of cycles` (then throws a
     * ComputationError if the goals were to converge and have not). */
    bool
    last_cycle();
    /** fault.csv and fault_summary.json of each elastic or frictional
     * fault (faults/fault_output.h; fault_<name>.csv and
     * fault_summary_<name>.json when the model has several faults); in the
     * time loop also fault-NNNNN.csv (fault_<name>-NNNNN.csv) of output step
     * @p output_index. */
    void
    write_fault_results(const int output_index = -1);
    void
    check_output_directory() const;
    /**
     * Before anything is written: every rigid-body motion is held
     * (RigidBodySupport, on the coarse mesh) and the first mesh — with
     * global refinement also the last — fits in memory (MemoryBudget).
     */
    void
    check_well_posed(const std::string &length_unit);
    /** Open log.txt and write parameters.prm: called once the first
     * assembly has accepted the model. */
    void
    start_output();
    /** Stop all ranks with RunInterrupted if any received SIGINT or
     * SIGTERM (a safe point before @p phase of the current cycle). */
    void
    stop_if_requested(const std::string &phase) const;
    /** Write the last cycle's sizes, timings and peak memory as
     * `statistics.json` (read by bench/run). */
    void
    write_statistics() const;
    /** Read and check the model (the constructor's work). */
    void
    read_model();
    /** The log's header and (if @p refine_initially) the initial global
     * refinement. */
    void
    write_run_header(const bool refine_initially = true);
    /** Refine the mesh once (Mesh refinement section); @p mesh names it
     * in the memory check, @p before_change runs once the cells are
     * marked, before the mesh changes (to attach data to transfer). */
    void
    refine_mesh(const std::string           &mesh,
                const std::function<void()> &before_change = {});
    /** Set up, assemble, solve and postprocess the current cycle. */
    void
    compute_cycle();
    /** The refinement cycles (run()'s work). */
    void
    run_cycles();
    /** After the last cycle or time step: convergence table, force
     * balance, profiles and figures, statistics and the timing table. */
    void
    write_final_results();

    MPI_Comm                     communicator;
    ParameterHandler            &prm;
    RunLog                       log;
    std::ostringstream           timer_text;
    ConditionalOStream           timer_stream;
    std::unique_ptr<TimerOutput> timer;

    std::string                               output_directory;
    PlaneState                                plane_state;
    double                                    length_scale;
    std::unique_ptr<GeometryModel<dim>>       geometry;
    parallel::distributed::Triangulation<dim> triangulation;
    MaterialLibrary                           materials;
    std::unique_ptr<ReferenceSolution<dim>>   reference;
    LoadCollection<dim>                       loads;
    PrescribedDisplacement<dim>               prescribed_displacement;
    FaultInterface<dim>                       faults;
    FrictionalSlidingSolver<dim>              sliding_solver;
    /** The frictional faults' accumulated slip (their history). */
    FaultSlipHistory slip_history;
    /** Whether solve() leaves the slip of a frictional fault uncommitted
     * (the time loop commits it with an accepted step). */
    bool                                     defer_slip_commit = false;
    std::unique_ptr<StressModel<dim>>        stress_model;
    std::unique_ptr<FiniteElementSpace<dim>> fe_space;
    DoFHandler<dim>                          dof_handler;
    LinearSystem<dim>                        system;
    TrilinosWrappers::MPI::Vector            solution;
    std::unique_ptr<LinearSolver<dim>>       linear_solver;
    MeshRefinement<dim>                      refinement;
    /** Quantities of interest: goal-oriented refinement and the stopping
     * test of the cycles. */
    StressGoals<dim> goals;
    /** Whether the last cycle's goals changed by less than the stop
     * tolerance (StressGoals::record_cycle()). */
    bool         goals_converged = false;
    MemoryBudget memory_budget;
    /** The cycle being computed (for the message of an interrupted run). */
    unsigned int cycle = 0;
    /** The model time [s] at which loads and prescribed displacements are
     * evaluated. */
    double time = 0;
    /** The visco-elastic time loop's settings and creep history (the
     * history only if the loop runs). */
    TimeStepping                          time_stepping;
    std::unique_ptr<CreepIntegrator<dim>> creep;
    /** Counts the meshes set up (setup_dofs()). */
    unsigned long long mesh_version = 0;
    /** The mesh the loads' mesh integrals were computed on. */
    unsigned long long loads_prepared_for = ~0ULL;
    /** The operator version the assembled matrix belongs to. */
    unsigned long long matrix_version = ~0ULL;
    /** Whether solvers keep their set-up between solves (time loop). */
    bool keep_solver_setup = false;
    /** The version of the operator: mesh and step moduli. */
    unsigned long long
    operator_version() const
    {
      return (mesh_version << 32) + stress_model->moduli_version();
    }
    /** The history strain of the time step being assembled, or nullptr. */
    const CreepStrain<dim> *history_strain = nullptr;

    friend class ViscoelasticTimeLoop<dim>;
    SolutionOutput<dim>      solution_output;
    std::vector<Point<dim>>  points;
    types::boundary_id       surface_boundary   = numbers::invalid_boundary_id;
    bool                     with_force_balance = true;
    ThinPlateFlexure         thin_plate;
    GriffithFailure          griffith;
    StressDepthProfiles<dim> profiles;
    Figures<dim>             figures;
    std::vector<std::array<double, 5>> thin_plate_profile;
    ConvergenceStudy                   study;
    CycleStatistics                    statistics;
    Timer                              wall_clock;
  };
} // namespace lithostress

#endif

#ifndef lithostress_simulator_simulator_h
#define lithostress_simulator_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>

#include <lithostress/analysis/griffith_failure.h>
#include <lithostress/base/memory_budget.h>
#include <lithostress/base/run_log.h>
#include <lithostress/boundary_conditions/prescribed_displacement.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/faults/frictional_sliding_solver.h>
#include <lithostress/geometry/geometry_model.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/materials/material.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/postprocessors/postprocessor.h>
#include <lithostress/reference_solutions/reference_solution.h>
#include <lithostress/simulator/elastic_problem.h>
#include <lithostress/simulator/refinement_cycles.h>
#include <lithostress/temperature/temperature_model.h>
#include <lithostress/time_integration/creep_integrator.h>
#include <lithostress/time_integration/time_stepping.h>

#include <memory>
#include <sstream>
#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * The lithostress simulator, a short driver in the spirit of deal.II
   * step-40 and ASPECT's Simulator. The constructor reads and checks the
   * whole model — geometry and mesh, materials, loads, boundary conditions
   * and faults, which it owns — so that bad input is reported before
   * anything is written. run() hands the discrete problem (ElasticProblem)
   * to the refinement cycles (RefinementCycles) or to the visco-elastic
   * loop (ViscoelasticTimeLoop), and the postprocessors
   * (PostprocessorList) write the results through a read-only
   * SimulatorAccess.
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

    /** Run all cycles, or the time loop; writes into the output
     * directory. */
    void
    run();

    /** The convergence table after run(). */
    const ConvergenceStudy &
    convergence_study() const
    {
      return cycles.convergence_study();
    }

    /** Timings and sizes of the last solve, for the benchmark. */
    const CycleStatistics &
    last_cycle() const
    {
      return problem->statistics();
    }

  private:
    /** Read and check the model (the constructor's work). */
    void
    read_model();
    /** The geometry, its coarse mesh, the faults on it and the finite
     * element space. */
    void
    read_geometry();
    /** Materials, reference solution, loads, boundary conditions and the
     * failure criterion. */
    void
    read_physics();
    /** Refinement, time stepping, solver and memory: the discrete problem,
     * then the postprocessors. */
    void
    read_numerics();
    /**
     * Before anything is written: every rigid-body motion is held
     * (RigidBodySupport, on the coarse mesh) and the first mesh — with
     * global refinement also the last — fits in memory (MemoryBudget).
     */
    void
    check_well_posed();
    /** Open log.txt and write parameters.prm: called once the first
     * assembly has accepted the model. */
    void
    start_output();
    /** The log's header and (if @p refine_initially) the initial global
     * refinement. */
    void
    write_run_header(const bool refine_initially);
    /** The message of a run stopped at a safe point of @p where. */
    std::string
    interruption_message(const std::string &where) const;

    MPI_Comm                     communicator;
    ParameterHandler            &prm;
    RunLog                       log;
    std::ostringstream           timer_text;
    ConditionalOStream           timer_stream;
    std::unique_ptr<TimerOutput> timer;
    Timer                        wall_clock;

    std::string                               output_directory;
    PlaneState                                plane_state;
    double                                    length_scale = 1;
    std::string                               length_unit;
    std::unique_ptr<GeometryModel<dim>>       geometry;
    parallel::distributed::Triangulation<dim> triangulation;
    std::unique_ptr<FiniteElementSpace<dim>>  fe_space;
    FaultInterface<dim>                       faults;
    FrictionalSlidingSolver<dim>              sliding_solver;
    MaterialLibrary                           materials;
    std::unique_ptr<ReferenceSolution<dim>>   reference;
    ModelDescription<dim>                     model;
    LoadCollection<dim>                       loads;
    PrescribedDisplacement<dim>               prescribed_displacement;
    /** `Temperature` (null: none); the stress model reads it. */
    std::unique_ptr<TemperatureModel<dim>> temperature;
    std::unique_ptr<StressModel<dim>>      stress_model;
    GriffithFailure                        griffith;
    MemoryBudget                           memory_budget;
    TimeStepping                           time_stepping;
    /** The creep history (only if the time loop runs). */
    std::unique_ptr<CreepIntegrator<dim>> creep;
    RefinementCycles<dim>                 cycles;
    std::unique_ptr<ElasticProblem<dim>>  problem;
    std::unique_ptr<SimulatorAccess<dim>> access;
    PostprocessorList<dim>                postprocessors;
  };
} // namespace lithostress

#endif

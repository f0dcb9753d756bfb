#ifndef lithostress_postprocessors_simulator_access_h
#define lithostress_postprocessors_simulator_access_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/analysis/convergence_study.h>
#include <lithostress/analysis/griffith_failure.h>
#include <lithostress/base/run_log.h>
#include <lithostress/boundary_conditions/prescribed_displacement.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/faults/fault_history.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/reference_solutions/reference_solution.h>
#include <lithostress/solvers/linear_solver.h>

#include <string>
#include <utility>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /** Sizes and timings of the last solve on the current mesh (written to
   * `statistics.json` and read by bench/run). */
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

  /**
   * What a postprocessor may read of a run: the model, the present mesh
   * and solution, and where to write. A read-only view in the spirit of
   * ASPECT's SimulatorAccess: its owners are the Simulator (the model),
   * ElasticProblem (mesh, DoFs, solution, fault slip, statistics) and
   * RefinementCycles (the convergence table); a postprocessor changes none
   * of them. Only the log and the timer are writable.
   */
  template <int dim>
  struct SimulatorAccess
  {
    MPI_Comm           communicator;
    const std::string &output_directory;
    RunLog            &log;
    TimerOutput       &timer;
    /** Metres per input length unit, and the unit's name. */
    const double                                     length_scale;
    const std::string                                length_unit;
    const ModelDescription<dim>                     &model;
    const parallel::distributed::Triangulation<dim> &triangulation;
    const DoFHandler<dim>                           &dof_handler;
    const FiniteElementSpace<dim>                   &fe_space;
    const MaterialLibrary                           &materials;
    const StressModel<dim>                          &stress_model;
    const LoadCollection<dim>                       &loads;
    const PrescribedDisplacement<dim>               &prescribed_displacement;
    const FaultInterface<dim>                       &faults;
    const FaultHistory                              &fault_history;
    const GriffithFailure                           &griffith;
    /** The exact solution of the experiment, or nullptr. */
    const ReferenceSolution<dim> *reference;
    /** The present solution (ghosted). */
    const TrilinosWrappers::MPI::Vector &solution;
    const CycleStatistics               &statistics;
    /** The refinement cycles' table (DoFs, errors, point values, goals). */
    const ConvergenceStudy &convergence_study;
    /** The wall clock of the whole run. */
    const Timer &wall_clock;

    /** Whether this is the rank that writes files. */
    bool
    root() const
    {
      return Utilities::MPI::this_mpi_process(communicator) == 0;
    }

    /** The path of @p file in the output directory. */
    std::string
    path(const std::string &file) const
    {
      return output_directory + "/" + file;
    }
  };
} // namespace lithostress

#endif

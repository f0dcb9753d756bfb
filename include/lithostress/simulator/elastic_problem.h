#ifndef lithostress_simulator_elastic_problem_h
#define lithostress_simulator_elastic_problem_h

#include <deal.II/base/timer.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/base/run_log.h>
#include <lithostress/boundary_conditions/prescribed_displacement.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/discretization/linear_system.h>
#include <lithostress/faults/fault_history.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/faults/frictional_sliding_solver.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/postprocessors/simulator_access.h>
#include <lithostress/refinement/stress_goals.h>
#include <lithostress/solvers/linear_solver.h>
#include <lithostress/time_integration/solution_predictor.h>

#include <functional>
#include <memory>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The discrete elastic problem on the present mesh: DoFs, constraints,
   * the linear system and its solution, the frictional faults' slip
   * history, and the solvers. It sets up, assembles and solves at a model
   * time with a given history strain (thesis §3.6–3.9: one linear solve,
   * or the sliding iteration of §5.5); the refinement cycles and the
   * visco-elastic loop drive it. It owns the mesh-dependent state; the
   * model (materials, loads, boundary conditions, faults) is the
   * Simulator's and is only read here.
   */
  template <int dim>
  class ElasticProblem
  {
  public:
    /** What the problem works on: the model's parts (read-only, except the
     * stress model's step moduli, which the time loop sets). */
    struct Model
    {
      MPI_Comm                                   communicator;
      parallel::distributed::Triangulation<dim> &triangulation;
      const FiniteElementSpace<dim>             &fe_space;
      const StressModel<dim>                    &stress_model;
      LoadCollection<dim>                       &loads;
      const PrescribedDisplacement<dim>         &prescribed_displacement;
      const FaultInterface<dim>                 &faults;
    };

    ElasticProblem(const Model                       &model,
                   std::unique_ptr<LinearSolver<dim>> linear_solver,
                   FrictionalSlidingSolver<dim>      &sliding_solver,
                   RunLog                            &log,
                   TimerOutput                       &timer);

    /** Distribute the DoFs on the present mesh and build the constraints
     * and the system at model time @p time. */
    void
    setup(const double time);

    /** New prescribed values at @p time on the same mesh (the structure of
     * the constraints, and so of the matrix, is unchanged). */
    void
    update_constraints(const double time);

    /** Make the solution the last solutions' extrapolation to model time
     * @p time (SolutionPredictor), with the prescribed values of @p time:
     * where a non-linear step's Newton iteration starts. Returns false,
     * changing nothing, where fewer than two solutions of this mesh are
     * known (outside the time loop, the first step on a new mesh). */
    bool
    start_from_prediction(const double time);

    /**
     * Assemble at model time @p time with the laws' history @p history of
     * a time step (nullptr: none): the loads' mesh integrals once per mesh,
     * the matrix only when the operator changed.
     */
    void
    assemble(const double time, const CellHistory<dim> *history = nullptr);

    /**
     * Solve. A frictional fault's slip is committed to its history if
     * @p commit_slip (a time step commits it once the step is accepted:
     * commit_slip()). If the sliding solve stops with an error, its last
     * iterate becomes the solution and @p on_failure is called before the
     * error is passed on.
     */
    void
    solve(const bool commit_slip, const std::function<void()> &on_failure = {});

    /** Commit the slip of the last solve to the faults' history. */
    void
    commit_slip()
    {
      interface_history.commit();
    }

    /**
     * Call once the mesh's refinement flags are set, before it changes:
     * the solution is carried onto the next mesh, where setup()
     * interpolates it and the frictional Newton iteration starts from it
     * (nested iteration: the coarse mesh has found nearly the fine mesh's
     * sliding and open points, where each Newton step is cheap). Nothing
     * is kept without a frictional fault solved by Newton's method.
     */
    void
    carry_solution_to_next_mesh();

    /** Start the faults' slip from zero (an elastic cycle solves the load
     * from the undeformed state on every mesh). */
    void
    reset_slip()
    {
      interface_history = FaultHistory();
    }

    /** The discrete problem for the solvers (the solution's and the
     * goals' dual problems). */
    DiscreteProblem<dim>
    discrete_problem();

    /** The dual solutions of @p goals on the present operator
     * (goal-oriented refinement; refinement/dual_solutions.h). */
    std::vector<TrilinosWrappers::MPI::Vector>
    solve_dual_problems(const StressGoals<dim> &goals, SolverReport &report);

    /** Whether solvers keep their set-up between solves (the time loop
     * solves many right-hand sides with one operator). */
    void
    keep_solver_setup(const bool keep)
    {
      keep_setup = keep;
    }

    /** The mesh (refined by RefinementCycles, saved and loaded by the
     * time loop's checkpoints). */
    parallel::distributed::Triangulation<dim> &
    triangulation()
    {
      return model.triangulation;
    }

    const DoFHandler<dim> &
    dof_handler() const
    {
      return dofs;
    }

    /** The solution (ghosted); the time loop restores it after a rejected
     * step. */
    TrilinosWrappers::MPI::Vector &
    solution()
    {
      return present_solution;
    }

    const TrilinosWrappers::MPI::Vector &
    solution() const
    {
      return present_solution;
    }

    /** The last solutions the time loop's iterative solves and Newton
     * steps start from (saved and restored by its checkpoints). */
    SolutionPredictor &
    solution_predictor()
    {
      return predictor;
    }

    FaultHistory &
    fault_history()
    {
      return interface_history;
    }

    const FaultHistory &
    fault_history() const
    {
      return interface_history;
    }

    const LinearSolver<dim> &
    linear_solver() const
    {
      return *solver;
    }

    CycleStatistics &
    statistics()
    {
      return stats;
    }

    const CycleStatistics &
    statistics() const
    {
      return stats;
    }

  private:
    /** Hanging-node constraints, prescribed displacements and locked or
     * kinematic faults at @p time. */
    void
    make_constraints(const double time);

    /** Solve @p problem with the sliding iteration of the frictional
     * faults. */
    void
    solve_sliding(const DiscreteProblem<dim>    &problem,
                  TrilinosWrappers::MPI::Vector &owned_solution,
                  const bool                     commit,
                  const std::function<void()>   &on_failure);

    /** Whether the model's matrix is assembled: the solver asks for it,
     * unless the faults are in exact contact, whose sliding solve makes
     * its own linearised matrix and reads the model's stiffness from it
     * and the strip along the faults (FaultStripStiffness). */
    bool
    needs_model_matrix() const
    {
      return solver->needs_matrix() && !model.faults.contact();
    }

    /** The version of the operator: mesh and step moduli. */
    unsigned long long
    operator_version() const
    {
      return (mesh_version << 32) + model.stress_model.moduli_version();
    }

    Model                              model;
    std::unique_ptr<LinearSolver<dim>> solver;
    FrictionalSlidingSolver<dim>      &sliding_solver;
    RunLog                            &log;
    TimerOutput                       &timer;
    DoFHandler<dim>                    dofs;
    LinearSystem<dim>                  system;
    TrilinosWrappers::MPI::Vector      present_solution;
    /** The solution on its way to the next mesh
     * (carry_solution_to_next_mesh()). */
    std::unique_ptr<parallel::distributed::
                      SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>>
      solution_transfer;
    /** The frictional faults' accumulated slip (their history). */
    FaultHistory    interface_history;
    CycleStatistics stats;
    bool            keep_setup = false;
    /** Counts the meshes set up. */
    unsigned long long mesh_version = 0;
    /** The mesh the loads' mesh integrals were computed on. */
    unsigned long long loads_prepared_for = ~0ULL;
    /** The operator version the assembled matrix belongs to. */
    unsigned long long matrix_version = ~0ULL;
    /** The laws' history of the last assembly (nullptr: none). */
    const CellHistory<dim> *assembled_history = nullptr;
    /** The model time of the last assembly. */
    double assembled_time = 0;
    /** The time loop's last solutions on this mesh, where its iterative
     * solves and the faults' Newton method start from (kept only while
     * solvers keep their set-up). */
    SolutionPredictor predictor;
  };
} // namespace lithostress

#endif

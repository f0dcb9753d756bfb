#ifndef lithostress_solvers_linear_solver_h
#define lithostress_solvers_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/base/interruption.h>
#include <lithostress/base/plugin_registry.h>
#include <lithostress/boundary_conditions/prescribed_displacement.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/discretization/linear_system.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/materials/cell_history.h>
#include <lithostress/materials/stress_model.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lithostress
{
  /** What a solve did: for the progress line and the benchmark. */
  struct SolverReport
  {
    std::string  solver;
    unsigned int iterations = 0;
    /** Nonlinear iterations and linear solves (a frictional fault's
     * sliding solver; 0 and 1 for a linear solve). */
    unsigned int nonlinear_iterations = 0, linear_solves = 1;
    double       setup_time     = 0;
    double       solve_time     = 0;
    double       final_residual = 0;
    /** Time of one product with the system matrix (or operator), if
     * measured: the fastest of 20, which filters the machine's noise. */
    double matrix_vector_product_time = 0;
    /** The same for the finest multigrid level's operator (in the level
     * precision); 0 for solvers without levels. */
    double level_matrix_vector_product_time = 0;
    /** Wall time spent on those measurements (not part of the solve). */
    double benchmark_time = 0;
    /** Set-up and solve time split by phase (name, seconds), for the log
     * and the benchmark: where the time goes. */
    std::vector<std::pair<std::string, double>> phases;
    /** Memory of the solver's data (matrix or matrix-free data, multigrid
     * levels, preconditioner) [bytes], where it can be measured. */
    double memory_bytes = 0;
  };

  /**
   * Check the norm @p norm of a right-hand side before a solve: a NaN or
   * infinity (from a load that overflowed) is a ComputationError on all
   * ranks (the norm is collective), instead of a solve that returns garbage.
   */
  void
  check_right_hand_side(const double norm);

  /**
   * The iterations @p control counted, or 0 if it never checked a residual
   * (a zero right-hand side): never deal.II's invalid_unsigned_int, which
   * prints as 4294967295.
   */
  unsigned int
  iterations_of(const SolverControl &control);

  /**
   * Let @p solver (a deal.II iterative solver) stop between two iterations
   * when any rank of @p communicator has received SIGINT or SIGTERM: it
   * then throws SolverControl::NoConvergence, which the caller turns into
   * RunInterrupted through rethrow_solver_failure(). The slot returns
   * `success` for "no objection": deal.II combines the states of the
   * SolverControl and the slots, iterating while any says `iterate`.
   */
  template <typename IterativeSolver>
  void
  stop_on_signal(IterativeSolver &solver, const MPI_Comm communicator)
  {
    solver.connect(
      [communicator](const unsigned int, const double, const auto &) {
        return interruption::signal_on_any_rank(communicator) != 0
                 ? SolverControl::failure
                 : SolverControl::success;
      });
  }

  /**
   * Report a solver's failure truthfully: RunInterrupted if a signal
   * stopped it (in @p where), else a ComputationError naming @p solver, the
   * iterations and the relative residual of @p failure, and @p advice.
   */
  [[noreturn]] void
  rethrow_solver_failure(const SolverControl::NoConvergence &failure,
                         const MPI_Comm                      communicator,
                         const std::string                  &solver,
                         const double                        rhs_norm,
                         const std::string                  &advice);

  /** Wall time [s] of the fastest of @p n calls of @p operation, each
   * timed over all ranks of @p communicator (benchmark figures: the minimum
   * filters the noise of a shared machine). */
  double
  fastest_of(const unsigned int           n,
             const MPI_Comm               communicator,
             const std::function<void()> &operation);

  /**
   * Everything a solver may need about the discrete elasticity problem of
   * one solve: the DoFs and element space, the assembled system (the
   * matrix only if the solver asked for it), and the model the operator is
   * made of — moduli, loads that add stiffness, prescribed displacements —
   * for solvers that apply the operator without a matrix. The system is
   * not const: a solver that copies the right-hand side into a vector of
   * its own releases `system.rhs` (nothing reads it after the solve), so
   * that the two copies do not both count in the peak memory.
   */
  template <int dim>
  struct DiscreteProblem
  {
    const DoFHandler<dim>             &dof_handler;
    const FiniteElementSpace<dim>     &fe_space;
    LinearSystem<dim>                 &system;
    const StressModel<dim>            &stress_model;
    const LoadCollection<dim>         &loads;
    const PrescribedDisplacement<dim> &prescribed_displacement;
    /**
     * Whether the solver may keep its set-up (operators, hierarchy,
     * smoothers, AMG) after the solve, for the next solve of the same
     * operator: the visco-elastic loop solves many right-hand sides on one
     * mesh with one step size. Elastic cycles release it, so that it does
     * not count in the peak memory of the next mesh.
     */
    bool keep_setup = false;
    /** Changes whenever the operator does (a new mesh, other moduli): a
     * kept set-up of another version is rebuilt. */
    unsigned long long operator_version = 0;
    /** The laws' history of a visco-elastic step the system was assembled
     * with (nullptr: none), for a solver that assembles again with other
     * constraints (exact fault contact). */
    const CellHistory<dim> *cell_history = nullptr;
    /** Where an iterative solver starts (owned entries, constraints
     * distributed; nullptr: from zero): the time loop's prediction of the
     * solution from its last steps (SolutionPredictor). CG on the
     * condensed system zeroes the constrained DoFs of its copy (the
     * system decouples them); direct solvers ignore it. */
    const TrilinosWrappers::MPI::Vector *initial_guess = nullptr;
    /** Whether the operator is symmetric (CG applies); a non-associated
     * flow rule's Newton step is not, and the Krylov solvers then run
     * GMRES (StressModel::symmetric_operator()). */
    bool symmetric = true;
  };

  /**
   * A solver for the elasticity system. The rest of the program sees only
   * this interface, so that the AMG-preconditioned CG, a direct solver and
   * (next issue) a matrix-free geometric multigrid are interchangeable.
   * A solver that does not need the assembled matrix says so, and the
   * simulator then skips building it.
   */
  template <int dim>
  class LinearSolver
  {
  public:
    virtual ~LinearSolver() = default;

    /** Solve for the owned entries of @p solution, which the solver sizes
     * to the owned DoFs — as late as it can, after its own work vectors
     * are released (constraints are distributed by the caller). Throws
     * ComputationError if the solver does not converge. */
    virtual SolverReport
    solve(const DiscreteProblem<dim>    &problem,
          TrilinosWrappers::MPI::Vector &solution) = 0;

    /** Whether this solver needs LinearSystem::matrix. */
    virtual bool
    needs_matrix() const
    {
      return true;
    }

    /** The solver's name in messages ("CG with AMG"). */
    virtual std::string
    name() const = 0;

    /**
     * Peak memory per DoF of a run with this solver on a mesh of
     * @p n_dofs DoFs [bytes], beyond the fixed footprint per rank:
     * measured (doc/performance.md), for the memory check before each
     * mesh.
     */
    virtual double
    memory_per_dof(const double n_dofs) const = 0;

    /**
     * Memory the solver needs for a mesh of @p n_levels levels on
     * @p n_coarse_cells coarse cells, whatever its DoFs [bytes, whole run]:
     * zero unless the solver's set-up grows with the depth of the mesh
     * (the global-coarsening multigrid of deal.II 9.4).
     */
    virtual double
    memory_of_levels(const double       n_coarse_cells,
                     const unsigned int n_levels) const
    {
      (void)n_coarse_cells;
      (void)n_levels;
      return 0;
    }

    /** Prepare the DoF handler after distribute_dofs() (a geometric
     * multigrid numbers the DoFs of every level). */
    virtual void
    prepare_dof_handler(DoFHandler<dim> &) const
    {
    }
  };

  /** The linear solvers `Solver/Type` selects (besides `automatic`), made
   * from the `Solver` subsection and the model's element space. */
  template <int dim>
  using LinearSolverRegistry = PluginRegistry<LinearSolver<dim>,
                                              ParameterHandler &,
                                              const FiniteElementSpace<dim> &>;

  /**
   * The `Solver` section: which solver and its settings. `automatic` takes
   * the matrix-free geometric multigrid wherever the model allows it (one
   * displacement field, degree 1-3, stiffness terms it knows) and CG with
   * AMG otherwise.
   */
  template <int dim>
  class LinearSolverSelector
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /** Whether the triangulation must keep its multigrid hierarchy: the
     * `Type` may select the multigrid with local smoothing (read before the
     * mesh is built). */
    static bool
    may_use_multigrid(ParameterHandler &prm);

    /** The solver for a model with element space @p fe_space and loads
     * @p loads; throws InputError if the requested solver cannot handle it.
     * A non-empty @p constraint_obstacle says why the model's constraints
     * rule out the matrix-free multigrid (e.g. a rigid edge). With
     * @p unsymmetric_tangent (a non-associated flow rule) `automatic`
     * does not choose the multigrid: GMRES with it stops converging as
     * yielding spreads (doc/performance.md, "A lithosphere that creeps and
     * yields"), so the direct solver on one rank and AMG on several are
     * taken; the multigrid can still be chosen by name. */
    static std::unique_ptr<LinearSolver<dim>>
    create(ParameterHandler              &prm,
           const FiniteElementSpace<dim> &fe_space,
           const LoadCollection<dim>     &loads,
           const std::string             &constraint_obstacle = "",
           const bool                     unsymmetric_tangent = false);
  };
} // namespace lithostress

/**
 * Register the linear solver class template @p classname as `Solver/Type =
 * name`: it has a static `declare_parameters(ParameterHandler &)` for its
 * own entries of `Solver` and a static `create(ParameterHandler &, const
 * FiniteElementSpace<2> &)` that reads them (and the shared `Relative
 * tolerance`, `Maximum iterations`, `Time matrix-vector product`); one line
 * in its source file.
 */
#define LITHOSTRESS_REGISTER_LINEAR_SOLVER(classname, name, description)       \
  LITHOSTRESS_REGISTER_PLUGIN(::lithostress::LinearSolverRegistry<2>,          \
                              {name,                                           \
                               description,                                    \
                               [](ParameterHandler &prm, ParameterHandler *) { \
                                 classname<2>::declare_parameters(prm);        \
                               },                                              \
                               [](ParameterHandler            &prm,            \
                                  const FiniteElementSpace<2> &fe_space) {     \
                                 return classname<2>::create(prm, fe_space);   \
                               }})

#endif

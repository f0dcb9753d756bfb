#ifndef lithostress_solvers_linear_solver_h
#define lithostress_solvers_linear_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/discretization/linear_system.h>

#include <memory>
#include <string>

namespace lithostress
{
  /** What a solve did: for the progress line and the benchmark. */
  struct SolverReport
  {
    std::string  solver;
    unsigned int iterations     = 0;
    double       setup_time     = 0;
    double       solve_time     = 0;
    double       final_residual = 0;
    /** Time of one product with the system matrix, if measured. */
    double matrix_vector_product_time = 0;
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

    /** Solve for the owned entries of @p solution (constraints are
     * distributed by the caller). Throws ComputationError if the solver
     * does not converge. */
    virtual SolverReport
    solve(const DoFHandler<dim>         &dof_handler,
          const FiniteElementSpace<dim> &fe_space,
          const LinearSystem<dim>       &system,
          TrilinosWrappers::MPI::Vector &solution) = 0;

    /** Whether this solver needs LinearSystem::matrix. */
    virtual bool
    needs_matrix() const
    {
      return true;
    }
  };

  /** The `Solver` section: which solver and its settings. */
  template <int dim>
  class LinearSolverSelector
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    static std::unique_ptr<LinearSolver<dim>>
    create(ParameterHandler &prm);
  };
} // namespace lithostress

#endif

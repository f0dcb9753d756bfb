#ifndef lithostress_solvers_direct_solver_h
#define lithostress_solvers_direct_solver_h

#include <lithostress/solvers/linear_solver.h>

#include <string>

namespace lithostress
{
  /**
   * A sparse direct solver (Trilinos Amesos, KLU by default) for small or
   * ill-conditioned problems.
   */
  template <int dim>
  class DirectSolver : public LinearSolver<dim>
  {
  public:
    std::string
    name() const override
    {
      return "direct solver";
    }

    /** Not measured: an allowance for the factor fill-in of a 2-D sparse direct
     * solver (3-4x the matrix). */
    double
    memory_per_dof() const override
    {
      return 4000;
    }

    explicit DirectSolver(const std::string &amesos_solver);

    SolverReport
    solve(const DiscreteProblem<dim>    &problem,
          TrilinosWrappers::MPI::Vector &solution) override;

  private:
    std::string amesos_solver;
  };
} // namespace lithostress

#endif

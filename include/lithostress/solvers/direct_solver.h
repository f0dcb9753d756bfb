#ifndef lithostress_solvers_direct_solver_h
#define lithostress_solvers_direct_solver_h

#include <lithostress/solvers/linear_solver.h>

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
    explicit DirectSolver(const std::string &amesos_solver);

    SolverReport
    solve(const DiscreteProblem<dim>    &problem,
          TrilinosWrappers::MPI::Vector &solution) override;

  private:
    std::string amesos_solver;
  };
} // namespace lithostress

#endif

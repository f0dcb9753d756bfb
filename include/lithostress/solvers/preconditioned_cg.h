#ifndef lithostress_solvers_preconditioned_cg_h
#define lithostress_solvers_preconditioned_cg_h

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include <lithostress/solvers/linear_solver.h>

#include <string>

namespace lithostress
{
  /**
   * Solve @p matrix x = @p rhs with @p preconditioner by CG, or where the
   * operator is not @p symmetric (a non-associated flow rule's Newton step)
   * by GMRES with right preconditioning (restart 100), so that @p control
   * sees the unpreconditioned residual either way; stops on a signal.
   */
  template <typename VectorType, typename Matrix, typename Preconditioner>
  void
  solve_by_krylov(SolverControl        &control,
                  const bool            symmetric,
                  const MPI_Comm        communicator,
                  const Matrix         &matrix,
                  VectorType           &x,
                  const VectorType     &rhs,
                  const Preconditioner &preconditioner)
  {
    if (symmetric)
      {
        SolverCG<VectorType> cg(control);
        stop_on_signal(cg, communicator);
        cg.solve(matrix, x, rhs, preconditioner);
        return;
      }
    typename SolverGMRES<VectorType>::AdditionalData data(100, true);
    SolverGMRES<VectorType>                          gmres(control, data);
    stop_on_signal(gmres, communicator);
    gmres.solve(matrix, x, rhs, preconditioner);
  }

  /**
   * CG on @p system's matrix from @p initial_guess (nullptr: zero; its
   * constrained DoFs set to zero), preconditioned by @p preconditioner,
   * until ‖r‖ ≤ @p relative_tolerance ‖f‖ (unpreconditioned residual), at
   * most @p max_iterations; @p solution is sized to the owned DoFs. The
   * iterations and the final relative residual go to @p report. A solve that
   * does not converge throws ComputationError naming @p name and the entries to
   * change; an interrupted one RunInterrupted (stop_on_signal()). GMRES
   * instead where the operator is not @p symmetric (solve_by_krylov()).
   */
  template <int dim, typename Preconditioner>
  void
  solve_by_preconditioned_cg(const LinearSystem<dim>       &system,
                             const Preconditioner          &preconditioner,
                             const double                   relative_tolerance,
                             const unsigned int             max_iterations,
                             const std::string             &name,
                             const MPI_Comm                 communicator,
                             TrilinosWrappers::MPI::Vector &solution,
                             SolverReport                  &report,
                             const TrilinosWrappers::MPI::Vector *initial_guess,
                             const bool symmetric = true)
  {
    solution.reinit(system.locally_owned, communicator);
    if (initial_guess != nullptr)
      {
        solution = *initial_guess;
        system.constraints.set_zero(solution);
      }
    const double rhs_norm = system.rhs.l2_norm();
    check_right_hand_side(rhs_norm);
    SolverControl control(max_iterations,
                          relative_tolerance * rhs_norm,
                          false,
                          false);
    if (rhs_norm == 0)
      solution = 0;
    else
      {
        try
          {
            solve_by_krylov(control,
                            symmetric,
                            communicator,
                            system.matrix,
                            solution,
                            system.rhs,
                            preconditioner);
          }
        catch (const SolverControl::NoConvergence &exc)
          {
            rethrow_solver_failure(exc,
                                   communicator,
                                   name,
                                   rhs_norm,
                                   "raise Solver/Maximum iterations or use "
                                   "Solver/Type = direct");
          }
      }
    report.iterations     = iterations_of(control);
    report.final_residual = rhs_norm > 0 ? control.last_value() / rhs_norm : 0;
  }
} // namespace lithostress

#endif

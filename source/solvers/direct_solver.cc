#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/direct_solver.h>

namespace lithostress
{
  template <int dim>
  DirectSolver<dim>::DirectSolver(const std::string &amesos_solver)
      : amesos_solver(amesos_solver)
  {
  }

  template <int dim>
  SolverReport
  DirectSolver<dim>::solve(const DiscreteProblem<dim>    &problem,
                           TrilinosWrappers::MPI::Vector &solution)
  {
    const DoFHandler<dim>   &dof_handler = problem.dof_handler;
    const LinearSystem<dim> &system      = problem.system;
    SolverReport             report;
    report.solver = "direct";
    Timer         timer(dof_handler.get_communicator(), true);
    SolverControl control(1, 0);
    TrilinosWrappers::SolverDirect::AdditionalData data(false, amesos_solver);
    TrilinosWrappers::SolverDirect                 solver(control, data);
    solution.reinit(system.locally_owned, dof_handler.get_communicator());
    try
      {
        solver.solve(system.matrix, solution, system.rhs);
      }
    catch (const std::exception &exc)
      {
        throw ComputationError(std::string("the direct solver failed: ") +
                               exc.what());
      }
    report.solve_time = timer.wall_time();
    report.iterations = 1;
    return report;
  }

  template class DirectSolver<2>;
} // namespace lithostress

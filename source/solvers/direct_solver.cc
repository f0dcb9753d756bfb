#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/solvers/direct_solver.h>

#include <Amesos.h>

namespace lithostress
{
  template <int dim>
  DirectSolver<dim>::DirectSolver(const std::string &package)
      : package(package)
  {
  }

  template <int dim>
  double
  DirectSolver<dim>::memory_per_dof(const double) const
  {
    return 3000;
  }

  template <int dim>
  void
  DirectSolver<dim>::solve_with_amesos(
    const LinearSystem<dim>       &system,
    const std::string             &amesos_package,
    TrilinosWrappers::MPI::Vector &solution) const
  {
    SolverControl                                  control(1, 0);
    TrilinosWrappers::SolverDirect::AdditionalData data(false, amesos_package);
    TrilinosWrappers::SolverDirect                 solver(control, data);
    try
      {
        solver.solve(system.matrix, solution, system.rhs);
      }
    catch (const std::exception &exc)
      {
        const auto *dealii_error = dynamic_cast<const ExceptionBase *>(&exc);
        throw ComputationError(std::string("the direct solver failed: ") +
                               (dealii_error ? one_line_message(*dealii_error)
                                             : one_line(exc.what())));
      }
  }

  template <int dim>
  SolverReport
  DirectSolver<dim>::solve(const DiscreteProblem<dim>    &problem,
                           TrilinosWrappers::MPI::Vector &solution)
  {
    const LinearSystem<dim> &system = problem.system;
    const MPI_Comm communicator     = problem.dof_handler.get_communicator();
    SolverReport   report;
    report.solver     = "direct";
    report.iterations = 1;
    Timer timer(communicator, true);
    solution.reinit(system.locally_owned, communicator);

    // Cholesky reads one triangle: an unsymmetric operator (a
    // non-associated flow rule's Newton step) is factorised by KLU.
    const bool cholesky = package == "Cholesky" &&
                          Utilities::MPI::n_mpi_processes(communicator) == 1 &&
                          problem.symmetric;
    if (!cholesky)
      solve_with_amesos(system,
                        package == "Cholesky" ? "Amesos_Klu" : package,
                        solution);
    else
      {
        std::unique_ptr<SparseCholesky> factor;
        if (kept_cholesky && kept_version == problem.operator_version)
          factor = std::move(kept_cholesky);
        kept_cholesky.reset();
        try
          {
            if (!factor)
              {
                factor = std::make_unique<SparseCholesky>();
                factor->factorize(system.matrix);
              }
            factor->vmult(solution, system.rhs);
            report.solver       = "direct (Cholesky)";
            report.memory_bytes = factor->memory_consumption();
          }
        catch (const ComputationError &)
          {
            // Not positive definite (a load with unsymmetric stiffness?):
            // an LU factorisation instead.
            factor.reset();
            solve_with_amesos(system, "Amesos_Klu", solution);
            report.solver = "direct (KLU: the Cholesky factorisation failed)";
          }
        if (problem.keep_setup && factor)
          {
            kept_cholesky = std::move(factor);
            kept_version  = problem.operator_version;
          }
      }
    report.solve_time = timer.wall_time();
    return report;
  }

  template <int dim>
  FactorisationOrIterativeSolver<dim>::FactorisationOrIterativeSolver(
    std::unique_ptr<LinearSolver<dim>> direct,
    std::unique_ptr<LinearSolver<dim>> iterative,
    const double                       direct_limit)
      : direct(std::move(direct))
      , iterative(std::move(iterative))
      , direct_limit(direct_limit)
  {
  }

  template <int dim>
  bool
  FactorisationOrIterativeSolver<dim>::factorises(const double n_dofs) const
  {
    // The program runs on MPI_COMM_WORLD.
    return Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1 &&
           n_dofs <= direct_limit;
  }

  template <int dim>
  double
  FactorisationOrIterativeSolver<dim>::memory_per_dof(const double n_dofs) const
  {
    return factorises(n_dofs) ? direct->memory_per_dof(n_dofs)
                              : iterative->memory_per_dof(n_dofs);
  }

  template <int dim>
  SolverReport
  FactorisationOrIterativeSolver<dim>::solve(
    const DiscreteProblem<dim>    &problem,
    TrilinosWrappers::MPI::Vector &solution)
  {
    return factorises(problem.dof_handler.n_dofs())
             ? direct->solve(problem, solution)
             : iterative->solve(problem, solution);
  }

  template <int dim>
  void
  DirectSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Direct solver",
                      "Cholesky",
                      Patterns::Selection("Cholesky|Amesos_Klu|Amesos_Mumps|"
                                          "Amesos_Superludist"),
                      "The direct solver's factorisation: Cholesky "
                      "(SuiteSparse CHOLMOD, one rank, the factor kept "
                      "across the time steps of one operator; Amesos KLU "
                      "on several ranks or if the matrix is not positive "
                      "definite), or a Trilinos Amesos package.");
  }

  template <int dim>
  std::unique_ptr<LinearSolver<dim>>
  DirectSolver<dim>::create(ParameterHandler              &prm,
                            const FiniteElementSpace<dim> &fe_space)
  {
    (void)fe_space;
    const std::string package = prm.get("Direct solver");
    // The Amesos packages Debian's Trilinos was built with (KLU and MUMPS,
    // not SuperLU_DIST): an unavailable one is named before anything is
    // solved, not by Trilinos's exception in the first solve.
    Amesos factory;
    if (package != "Cholesky" && !factory.Query(package))
      {
        std::string available = "Cholesky";
        for (const char *p :
             {"Amesos_Klu", "Amesos_Mumps", "Amesos_Superludist"})
          if (factory.Query(p))
            available += std::string(", ") + p;
        throw_input_error("Solver/Direct solver",
                          "<" + package +
                            "> is not in this build's Trilinos; available: " +
                            available);
      }
    return std::make_unique<DirectSolver<dim>>(package);
  }

  template class DirectSolver<2>;
  LITHOSTRESS_REGISTER_LINEAR_SOLVER(DirectSolver,
                                     "direct",
                                     "a sparse direct solver (Direct solver)")
  template class FactorisationOrIterativeSolver<2>;
} // namespace lithostress

#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/amg_solver.h>
#include <lithostress/solvers/rigid_body_modes.h>

#include <Teuchos_ParameterList.hpp>

namespace lithostress
{
  template <int dim>
  AMGSolver<dim>::AMGSolver(const Settings &settings)
    : settings(settings)
  {}

  template <int dim>
  SolverReport
  AMGSolver<dim>::solve(const DoFHandler<dim> &         dof_handler,
                        const FiniteElementSpace<dim> &fe_space,
                        const LinearSystem<dim> &      system,
                        TrilinosWrappers::MPI::Vector &solution)
  {
    SolverReport report;
    report.solver = "amg";
    Timer timer(dof_handler.get_communicator(), true);

    const Epetra_CrsMatrix &matrix = system.matrix.trilinos_matrix();
    std::unique_ptr<Epetra_MultiVector> modes =
      make_rigid_body_modes(dof_handler, fe_space, matrix.DomainMap());

    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = true;
    data.smoother_sweeps       = settings.smoother_sweeps;
    data.aggregation_threshold = settings.aggregation_threshold;
    data.smoother_type         = "Chebyshev";
    data.coarse_type           = "Amesos-KLU";
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> unused_modes;
    data.set_parameters(parameters, unused_modes, system.matrix);
    parameters.set("null space: type", "pre-computed");
    parameters.set("null space: dimension", modes->NumVectors());
    parameters.set("null space: vectors", modes->Values());
    parameters.set("PDE equations", dim);

    TrilinosWrappers::PreconditionAMG preconditioner;
    preconditioner.initialize(system.matrix, parameters);
    report.setup_time = timer.wall_time();

    timer.restart();
    const double  rhs_norm = system.rhs.l2_norm();
    SolverControl control(settings.max_iterations,
                          settings.relative_tolerance * rhs_norm,
                          false,
                          false);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    if (rhs_norm == 0)
      solution = 0;
    else
      {
        try
          {
            cg.solve(system.matrix, solution, system.rhs, preconditioner);
          }
        catch (const SolverControl::NoConvergence &exc)
          {
            throw ComputationError(
              "CG with AMG did not converge: residual " +
              std::to_string(exc.last_residual / rhs_norm) +
              " (relative) after " + std::to_string(exc.last_step) +
              " iterations; raise Solver/Maximum iterations or use "
              "Solver/Type = direct");
          }
      }
    report.iterations     = control.last_step();
    report.final_residual = rhs_norm > 0 ? control.last_value() / rhs_norm : 0;
    report.solve_time     = timer.wall_time();
    return report;
  }

  template <int dim>
  DirectSolver<dim>::DirectSolver(const std::string &amesos_solver)
    : amesos_solver(amesos_solver)
  {}

  template <int dim>
  SolverReport
  DirectSolver<dim>::solve(const DoFHandler<dim> &dof_handler,
                           const FiniteElementSpace<dim> &,
                           const LinearSystem<dim> &      system,
                           TrilinosWrappers::MPI::Vector &solution)
  {
    SolverReport report;
    report.solver = "direct";
    Timer         timer(dof_handler.get_communicator(), true);
    SolverControl control(1, 0);
    TrilinosWrappers::SolverDirect::AdditionalData data(false, amesos_solver);
    TrilinosWrappers::SolverDirect solver(control, data);
    solver.solve(system.matrix, solution, system.rhs);
    report.solve_time = timer.wall_time();
    report.iterations = 1;
    return report;
  }

  template <int dim>
  void
  LinearSolverSelector<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry("Type", "AMG", Patterns::Selection("AMG|direct"),
                      "CG with algebraic multigrid (all rigid-body modes as "
                      "near-null space), or a sparse direct solver.");
    prm.declare_entry("Relative tolerance", "1e-10", Patterns::Double(0, 1),
                      "CG stops when |r| <= tol |f| (unpreconditioned).");
    prm.declare_entry("Maximum iterations", "1000", Patterns::Integer(1),
                      "CG iteration limit; reaching it is an error.");
    prm.declare_entry("AMG smoother sweeps", "2", Patterns::Integer(1),
                      "Chebyshev smoother degree in the AMG V-cycle.");
    prm.declare_entry("AMG aggregation threshold", "0.02",
                      Patterns::Double(0, 1),
                      "ML aggregation threshold (strength of connection).");
    prm.declare_entry("Direct solver", "Amesos_Klu",
                      Patterns::Selection("Amesos_Klu|Amesos_Mumps|"
                                          "Amesos_Superludist"),
                      "Trilinos Amesos package used by the direct solver.");
    prm.leave_subsection();
  }

  template <int dim>
  std::unique_ptr<LinearSolver<dim>>
  LinearSolverSelector<dim>::create(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    std::unique_ptr<LinearSolver<dim>> solver;
    if (prm.get("Type") == "AMG")
      {
        typename AMGSolver<dim>::Settings s;
        s.relative_tolerance    = prm.get_double("Relative tolerance");
        s.max_iterations        = prm.get_integer("Maximum iterations");
        s.smoother_sweeps       = prm.get_integer("AMG smoother sweeps");
        s.aggregation_threshold = prm.get_double("AMG aggregation threshold");
        solver                  = std::make_unique<AMGSolver<dim>>(s);
      }
    else
      solver = std::make_unique<DirectSolver<dim>>(prm.get("Direct solver"));
    prm.leave_subsection();
    return solver;
  }

  template class AMGSolver<2>;
  template class DirectSolver<2>;
  template class LinearSolverSelector<2>;
} // namespace lithostress

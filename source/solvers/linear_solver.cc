#include <lithostress/solvers/amg_solver.h>
#include <lithostress/solvers/direct_solver.h>
#include <lithostress/solvers/linear_solver.h>

namespace lithostress
{
  template <int dim>
  void
  LinearSolverSelector<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry("Type",
                      "AMG",
                      Patterns::Selection("AMG|direct"),
                      "CG with algebraic multigrid (all rigid-body modes as "
                      "near-null space), or a sparse direct solver.");
    prm.declare_entry("Relative tolerance",
                      "1e-10",
                      Patterns::Double(1e-16, 1),
                      "CG stops when |r| <= tol |f| (unpreconditioned).");
    prm.declare_entry("Maximum iterations",
                      "1000",
                      Patterns::Integer(1),
                      "CG iteration limit; reaching it is an error.");
    prm.declare_entry("AMG smoother",
                      "Chebyshev",
                      Patterns::Selection("Chebyshev|symmetric Gauss-Seidel"),
                      "Smoother of the AMG V-cycle.");
    prm.declare_entry("AMG smoother sweeps",
                      "2",
                      Patterns::Integer(1),
                      "Smoother sweeps (Chebyshev degree) in the V-cycle.");
    prm.declare_entry("AMG aggregation threshold",
                      "1e-4",
                      Patterns::Double(0, 1),
                      "ML aggregation threshold (strength of connection).");
    prm.declare_entry("Time matrix-vector product",
                      "false",
                      Patterns::Bool(),
                      "Measure one product with the stiffness matrix after "
                      "the solve and report it in statistics.json (bench).");
    prm.declare_entry("Direct solver",
                      "Amesos_Klu",
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
        s.smoother              = prm.get("AMG smoother");
        s.time_matrix_vector_product =
          prm.get_bool("Time matrix-vector product");
        solver = std::make_unique<AMGSolver<dim>>(s);
      }
    else
      solver = std::make_unique<DirectSolver<dim>>(prm.get("Direct solver"));
    prm.leave_subsection();
    return solver;
  }

  template class LinearSolverSelector<2>;
} // namespace lithostress

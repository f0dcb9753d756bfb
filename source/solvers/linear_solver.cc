#include <deal.II/base/timer.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/amg_solver.h>
#include <lithostress/solvers/direct_solver.h>
#include <lithostress/solvers/linear_solver.h>
#include <lithostress/solvers/multigrid_solver.h>
#include <lithostress/solvers/two_field_multigrid_solver.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace lithostress
{
  void
  check_right_hand_side(const double norm)
  {
    if (!std::isfinite(norm))
      throw ComputationError(
        "the right-hand side of the linear system is not finite (norm " +
        std::to_string(norm) + "): a load evaluates to a NaN or infinity");
  }

  unsigned int
  iterations_of(const SolverControl &control)
  {
    return control.last_step() == numbers::invalid_unsigned_int
             ? 0
             : control.last_step();
  }

  void
  rethrow_solver_failure(const SolverControl::NoConvergence &failure,
                         const MPI_Comm                      communicator,
                         const std::string                  &solver,
                         const double                        rhs_norm,
                         const std::string                  &advice)
  {
    const int signal = interruption::signal_on_any_rank(communicator);
    if (signal != 0)
      throw RunInterrupted(signal,
                           solver + " iteration " +
                             std::to_string(failure.last_step));
    std::ostringstream message;
    message << solver << " did not converge: relative residual "
            << std::setprecision(3) << failure.last_residual / rhs_norm
            << " after " << failure.last_step << " iterations; " << advice;
    throw ComputationError(message.str());
  }

  double
  fastest_of(const unsigned int           n,
             const MPI_Comm               communicator,
             const std::function<void()> &operation)
  {
    double fastest = std::numeric_limits<double>::max();
    for (unsigned int k = 0; k < n; ++k)
      {
        Timer timer(communicator, true);
        operation();
        timer.stop();
        fastest = std::min(fastest, timer.wall_time());
      }
    return fastest;
  }

  template <int dim>
  void
  LinearSolverSelector<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    prm.declare_entry(
      "Type",
      "automatic",
      Patterns::Selection(
        "automatic|matrix-free multigrid|two-field multigrid|AMG|direct"),
      "matrix-free multigrid: CG with a matrix-free geometric multigrid "
      "V-cycle (no matrix is assembled; one displacement field of degree "
      "1-3); two-field multigrid: CG with a geometric multigrid V-cycle on "
      "the assembled matrix, Galerkin coarse levels (faulted models whose "
      "faults are locked or slip by a prescribed amount; a stiff normal "
      "spring defeats its smoother); "
      "AMG: CG with algebraic multigrid on the assembled matrix (all "
      "rigid-body modes as near-null space); direct: a sparse direct "
      "solver (Direct solver); automatic: the matrix-free multigrid wherever "
      "it applies, otherwise the direct solver on one rank up to Direct "
      "solver limit DoFs and AMG above it and on several ranks.");
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
    prm.declare_entry("Multigrid smoother degree",
                      "5",
                      Patterns::Integer(1, 20),
                      "Degree of the Chebyshev smoother on each level of "
                      "the matrix-free multigrid (operator products per "
                      "smoothing step). Type = two-field multigrid smooths "
                      "with degree 4 and range 20; the sliding solver's "
                      "multigrid with Faults/Sliding solver/Multigrid "
                      "smoother degree.");
    prm.declare_entry("Multigrid smoothing range",
                      "20",
                      Patterns::Double(1.5),
                      "Ratio of the largest eigenvalue to the smallest one "
                      "the matrix-free multigrid's Chebyshev smoother "
                      "damps.");
    prm.declare_entry("Multigrid level precision",
                      "single",
                      Patterns::Selection("single|double"),
                      "Floating-point precision of the multigrid levels "
                      "(the outer CG is always double precision).");
    prm.declare_entry("Multigrid coarse solver",
                      "direct",
                      Patterns::Selection("direct|AMG"),
                      "Solver of the multigrid's coarsest level (the coarse "
                      "mesh): a sparse direct factorisation (Amesos KLU), or "
                      "CG with AMG to a relative residual of 1e-8 in every "
                      "V-cycle, for coarse meshes too large to factorise "
                      "(tens of thousands of cells).");
    prm.declare_entry("Multigrid hierarchy",
                      "local smoothing",
                      Patterns::Selection("local smoothing|global coarsening"),
                      "Levels of the multigrid: the levels of the refined "
                      "mesh's cell hierarchy, smoothed only where they are "
                      "refined (local smoothing, with edge terms at "
                      "refinement edges), or a sequence of meshes each "
                      "coarsened once globally from the one above (global "
                      "coarsening: every level covers the whole domain, "
                      "hanging nodes on the levels). The same answer to the "
                      "solver tolerance; see doc/performance.md for when "
                      "each is faster.");
    prm.declare_entry("Time matrix-vector product",
                      "false",
                      Patterns::Bool(),
                      "Measure one product with the stiffness matrix (or "
                      "the matrix-free operator) after the solve and report "
                      "it in statistics.json (bench).");
    prm.declare_entry("Direct solver",
                      "Cholesky",
                      Patterns::Selection("Cholesky|Amesos_Klu|Amesos_Mumps|"
                                          "Amesos_Superludist"),
                      "The direct solver's factorisation: Cholesky "
                      "(SuiteSparse CHOLMOD, one rank, the factor kept "
                      "across the time steps of one operator; Amesos KLU "
                      "on several ranks or if the matrix is not positive "
                      "definite), or a Trilinos Amesos package.");
    prm.declare_entry("Direct solver limit",
                      "2e6",
                      Patterns::Double(0),
                      "Type = automatic, where the matrix-free multigrid "
                      "does not apply: the largest model [DoFs] solved by "
                      "the direct solver on one rank (above it, and on "
                      "several ranks, CG with AMG). The factorisation "
                      "needs about 3 KB per DoF.");
    prm.leave_subsection();
  }

  template <int dim>
  bool
  LinearSolverSelector<dim>::may_use_multigrid(ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    const std::string type = prm.get("Type");
    const bool        local_smoothing =
      prm.get("Multigrid hierarchy") == "local smoothing";
    prm.leave_subsection();
    return (type == "automatic" || type == "matrix-free multigrid") &&
           local_smoothing;
  }

  template <int dim>
  std::unique_ptr<LinearSolver<dim>>
  LinearSolverSelector<dim>::create(ParameterHandler              &prm,
                                    const FiniteElementSpace<dim> &fe_space,
                                    const LoadCollection<dim>     &loads,
                                    const std::string &constraint_obstacle)
  {
    prm.enter_subsection("Solver");
    std::string type = prm.get("Type");
    std::string reason;
    bool        multigrid_applies =
      MatrixFreeMultigridSolver<dim>::applies_to(fe_space, loads, reason);
    if (multigrid_applies && !constraint_obstacle.empty())
      {
        multigrid_applies = false;
        reason            = constraint_obstacle;
      }
    if (type == "matrix-free multigrid" && !multigrid_applies)
      {
        prm.leave_subsection();
        throw_input_error("Solver/Type",
                          "the matrix-free multigrid cannot solve this "
                          "model: " +
                            reason + "; use AMG or automatic");
      }
    const bool automatic = type == "automatic";
    if (automatic)
      type = multigrid_applies ? "matrix-free multigrid" : "AMG";

    std::unique_ptr<LinearSolver<dim>> solver;
    if (type == "matrix-free multigrid")
      {
        typename MatrixFreeMultigridSolver<dim>::Settings s;
        s.relative_tolerance = prm.get_double("Relative tolerance");
        s.max_iterations     = prm.get_integer("Maximum iterations");
        s.smoother_degree    = prm.get_integer("Multigrid smoother degree");
        s.smoothing_range    = prm.get_double("Multigrid smoothing range");
        s.single_precision_levels =
          prm.get("Multigrid level precision") == "single";
        s.coarse_solver_amg = prm.get("Multigrid coarse solver") == "AMG";
        s.global_coarsening =
          prm.get("Multigrid hierarchy") == "global coarsening";
        s.time_matrix_vector_product =
          prm.get_bool("Time matrix-vector product");
        solver =
          std::make_unique<MatrixFreeMultigridSolver<dim>>(s,
                                                           fe_space.degree());
      }
    else if (type == "two-field multigrid")
      {
        typename TwoFieldMultigridSolver<dim>::Settings s;
        s.relative_tolerance = prm.get_double("Relative tolerance");
        s.max_iterations     = prm.get_integer("Maximum iterations");
        solver = std::make_unique<TwoFieldMultigridSolver<dim>>(s);
      }
    else if (type == "AMG")
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
        if (automatic)
          solver = std::make_unique<FactorisationOrIterativeSolver<dim>>(
            std::make_unique<DirectSolver<dim>>(prm.get("Direct solver")),
            std::move(solver),
            prm.get_double("Direct solver limit"));
      }
    else
      solver = std::make_unique<DirectSolver<dim>>(prm.get("Direct solver"));
    prm.leave_subsection();
    return solver;
  }

  template class LinearSolverSelector<2>;
} // namespace lithostress

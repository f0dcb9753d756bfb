#include <deal.II/base/timer.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/direct_solver.h>
#include <lithostress/solvers/linear_solver.h>
#include <lithostress/solvers/multigrid_solver.h>

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
      Patterns::Selection("automatic|" + LinearSolverRegistry<dim>::names()),
      LinearSolverRegistry<dim>::documentation() +
        "; automatic: the matrix-free multigrid wherever it applies (but "
        "not to a non-associated flow rule, Dilation angle below Friction "
        "angle, whose unsymmetric tangent it preconditions badly), "
        "otherwise the direct solver on one rank up to Direct solver limit "
        "DoFs and AMG above it and on several ranks.");
    prm.declare_entry("Relative tolerance",
                      "1e-10",
                      Patterns::Double(1e-16, 1),
                      "CG stops when |r| <= tol |f| (unpreconditioned).");
    prm.declare_entry("Maximum iterations",
                      "1000",
                      Patterns::Integer(1),
                      "CG iteration limit; reaching it is an error.");
    prm.declare_entry("Time matrix-vector product",
                      "false",
                      Patterns::Bool(),
                      "Measure one product with the stiffness matrix (or "
                      "the matrix-free operator) after the solve and report "
                      "it in statistics.json (bench).");
    LinearSolverRegistry<dim>::declare_parameters(prm);
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
                                    const std::string &constraint_obstacle,
                                    const bool         unsymmetric_tangent)
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
      type = multigrid_applies && !unsymmetric_tangent ? "matrix-free multigrid"
                                                       : "AMG";

    std::unique_ptr<LinearSolver<dim>> solver =
      LinearSolverRegistry<dim>::find(type, "Solver/Type")
        .create(prm, fe_space);
    if (automatic && type == "AMG")
      solver = std::make_unique<FactorisationOrIterativeSolver<dim>>(
        DirectSolver<dim>::create(prm, fe_space),
        std::move(solver),
        prm.get_double("Direct solver limit"));
    prm.leave_subsection();
    return solver;
  }

  template class LinearSolverSelector<2>;
} // namespace lithostress

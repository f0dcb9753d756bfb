#ifndef lithostress_solvers_newton_method_h
#define lithostress_solvers_newton_method_h

#include <string>

namespace lithostress
{
  /** What Newton's method does with an iterate after a step. */
  enum class NewtonVerdict
  {
    /** Take another step. */
    go_on,
    /** The iterate is the solution. */
    converged,
    /** The iteration goes astray: give up (the caller may try otherwise). */
    diverged
  };

  /** Where Newton's method is after a step, for the problem's hooks. */
  struct NewtonIterate
  {
    /** The step just taken (1, 2, ...). */
    unsigned int iteration = 0;
    /** ‖F‖ at the new iterate, at the last one and at the start. */
    double residual = 0, previous_residual = 0, start_residual = 0;
    /** The step length the line search took (1: the whole Newton step). */
    double step_length = 1;
  };

  /**
   * A nonlinear problem F(u) = 0 as Newton's method sees it: its residual
   * norm, its linearisation and solve at an iterate, and the hooks that an
   * active set (exact contact, a yield surface) or a law's states need:
   * whether a step must be taken whole, what follows a step, extra
   * conditions for convergence and special endings.
   */
  template <typename VectorType>
  class NewtonProblem
  {
  public:
    virtual ~NewtonProblem() = default;

    /** ‖F(@p u)‖, the law evaluated at @p u (its states become the
     * iterate's). */
    virtual double
    residual_norm(const VectorType &u) = 0;

    /** The Newton step @p step at the iterate @p u of iteration
     * @p iteration: the tangent at @p u and the solve of J step = −F(u),
     * to a tolerance of the problem's choosing (an inexact Newton
     * method's forcing). */
    virtual void
    newton_step(const VectorType  &u,
                const unsigned int iteration,
                VectorType        &step) = 0;

    /** Whether the step of iteration @p iteration is taken whole, without
     * line search (an elastic predictor; a step after the active set
     * changed, which satisfies other constraints than the iterate). */
    virtual bool
    take_whole_step(const unsigned int iteration) const
    {
      (void)iteration;
      return false;
    }

    /** What follows a step to @p iterate: the active set's update, the
     * states' bookkeeping, a progress line. */
    virtual void
    step_taken(const NewtonIterate &iterate)
    {
      (void)iterate;
    }

    /** Conditions beyond the residual tolerance for convergence at
     * @p iterate (a law's own tolerance, a settled active set). */
    virtual bool
    converged_otherwise(const NewtonIterate &iterate) const
    {
      (void)iterate;
      return true;
    }

    /** An ending the residual test does not see (divergence, a residual
     * at round-off), judged after it at @p iterate. */
    virtual NewtonVerdict
    judge(const NewtonIterate &iterate)
    {
      (void)iterate;
      return NewtonVerdict::go_on;
    }
  };

  /**
   * Newton's method with a backtracking (Armijo) line search on the
   * residual norm, for any NewtonProblem: the iteration, the step halving,
   * the convergence test ‖F‖ ≤ tolerance · reference together with the
   * problem's own conditions, the check that the residual stays finite, and
   * the messages of a failure naming the entry to change. The frictional
   * sliding solver's semi-smooth Newton method (doc/faults.md) is one
   * problem; a nonlinear rheology in a time step is another.
   */
  template <typename VectorType>
  class NewtonMethod
  {
  public:
    /** The iteration's settings. */
    struct Settings
    {
      /** The most iterations. */
      unsigned int max_iterations = 50;
      /** ‖F‖ at which the iteration stops, relative to the reference
       * given to solve(). */
      double residual_tolerance = 1e-9;
      /** Whether a step that does not reduce ‖F‖ by the fraction
       * sufficient_decrease of its length is halved (up to max_halvings
       * times). */
      bool         line_search         = true;
      unsigned int max_halvings        = 6;
      double       sufficient_decrease = 1e-4;
      /** What is solved, for messages ("the sliding on fault <f>"), and the
       * entry of max_iterations. */
      std::string what, iterations_entry;
    };

    /** How the iteration ended. */
    struct Result
    {
      NewtonVerdict verdict = NewtonVerdict::go_on;
      /** The iterations taken and the last residual norm. */
      unsigned int iterations = 0;
      double       residual   = 0;
    };

    explicit NewtonMethod(const Settings &settings)
        : settings(settings)
    {
    }

    /**
     * Solve @p problem from @p u (overwritten by the last iterate) with
     * ‖F‖ measured against @p reference (the load's norm), and ‖F(u)‖ =
     * @p start_residual if that is known (negative: evaluated). The
     * verdict is
     * `converged`, `diverged` (the problem's judge()), or `go_on` if
     * max_iterations did not suffice. Throws ComputationError if the
     * residual is not finite.
     */
    Result
    solve(NewtonProblem<VectorType> &problem,
          VectorType                &u,
          const double               reference,
          const double               start_residual = -1) const;

    /** "<what> did not converge in <n> newton iterations (<state>); the
     * last iterate is written out. Raise <iterations_entry>": the message
     * of a `go_on` result, with the state @p state of the last iterate. */
    std::string
    failure_message(const std::string &state) const;

  private:
    Settings settings;
  };
} // namespace lithostress

#endif

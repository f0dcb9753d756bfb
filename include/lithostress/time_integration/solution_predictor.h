#ifndef lithostress_time_integration_solution_predictor_h
#define lithostress_time_integration_solution_predictor_h

#include <deal.II/lac/trilinos_vector.h>

#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The iterative solvers' starting point for the next solve of the
   * visco-elastic loop on one mesh: the last three solutions extrapolated
   * to the new time by the quadratic through them (Lagrange's form), or
   * the last two linearly, u(t) ≈ u₂ + (t − t₂)/(t₂ − t₁) (u₂ − u₁) (one
   * solution: u₂ itself). The displacement relaxes smoothly between steps
   * that the step control keeps within its creep tolerance, so the
   * extrapolation leaves an initial residual of the order of the steps'
   * third (linearly: second) difference instead of the whole right-hand
   * side, and CG reaches the same stopping rule ‖r‖ ≤ tol ‖f‖ in fewer
   * iterations; the answer is unchanged to that tolerance. The frictional
   * faults' Newton method starts from it as well.
   *
   * The quadratic is taken only for a step forward (t > t₂) at most four
   * times the last step, after two steps whose lengths differ by at most a
   * factor of four. Otherwise the linear ratio (t − t₂)/(t₂ − t₁) is
   * clamped to [−1, 4]: a step retried after a rejection (t₁ < t < t₂)
   * interpolates between the accepted and the rejected solution, and an
   * erratic history cannot throw the guess far.
   */
  class SolutionPredictor
  {
  public:
    /** Forget the solutions (a new mesh: other DoFs). */
    void
    clear();

    /** Remember @p solution (owned entries, constraints distributed), the
     * solution at model time @p time; it replaces a solution of the same
     * time (the previous Newton iterate of a non-linear step). */
    void
    record(const double time, const TrilinosWrappers::MPI::Vector &solution);

    /** Whether a solution of the present mesh is known. */
    bool
    available() const
    {
      return !history.empty();
    }

    /** Whether two or more solutions are known: the guess is then an
     * extrapolation, not the last solution itself. */
    bool
    extrapolates() const
    {
      return history.size() >= 2;
    }

    /** The guess at @p time into @p guess (sized here; owned entries);
     * requires available(). */
    void
    predict(const double time, TrilinosWrappers::MPI::Vector &guess) const;

    /** The times of the solutions known, oldest first (a checkpoint
     * stores them with solutions(), so that a resumed run starts its
     * next solve where the uninterrupted one would). */
    std::vector<double>
    times() const;

    /** The solutions known, oldest first. */
    std::vector<const TrilinosWrappers::MPI::Vector *>
    solutions() const;

    /** Start again from the @p times and @p solutions of a checkpoint (at
     * most three, oldest first). */
    void
    restore(const std::vector<double>                        &times,
            const std::vector<TrilinosWrappers::MPI::Vector> &solutions);

  private:
    /** The last solutions, oldest first (u₀, u₁, u₂: at most three), and
     * their times t₀ < t₁ < t₂. */
    std::vector<TrilinosWrappers::MPI::Vector> history;
    std::vector<double>                        history_times;
  };
} // namespace lithostress

#endif

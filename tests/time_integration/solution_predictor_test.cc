/**
 * The time loop's starting guesses (SolutionPredictor), on one rank:
 * 1. A solution linear in time, u(t) = a + b t, recorded at t = 1 and 2,
 *    is predicted exactly (to round-off) at t = 3 and, for a step retried
 *    after a rejection, at t = 1.5 (interpolation).
 * 2. Far ahead (t = 100) the ratio (t − t₂)/(t₂ − t₁) is clamped to 4:
 *    the guess is u(6).
 * 3. With one solution recorded the guess is that solution.
 * 4. Restored from times() and solutions() (a checkpoint's contents), it
 *    predicts the same guess bit for bit, so that a resumed run starts its
 *    next solve where the uninterrupted one would.
 * 5. With three solutions of u(t) = a + b t + c t² at t = 1, 2, 2.5 the
 *    quadratic through them predicts u exactly (to round-off) at t = 3.5;
 *    a step retried (t = 2.2), a step more than four times the last
 *    (t = 5), or steps whose lengths differ by more than four (t = 1, 2,
 *    10) take the linear extrapolation of the last two instead; restored
 *    from its three times and solutions it predicts bit for bit.
 * 6. A solution recorded at the time of the last one (Newton's next
 *    iterate of the same step) replaces it: after u(1), a wrong u at
 *    t = 2 and then u(2), the guess at t = 3 is u(3) exactly, and the
 *    times are 1 and 2.
 * Prints "FAILED" and exits 1 on any failure.
 */
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>

#include <lithostress/time_integration/solution_predictor.h>

#include <cmath>
#include <iostream>

using namespace dealii;
using namespace lithostress;

namespace
{
  constexpr unsigned int n      = 12;
  bool                   failed = false;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok   " : "FAILED ") << what << std::endl;
    failed = failed || !ok;
  }

  /** u(t) = a + b t with a_i = sin(i), b_i = cos(3 i). */
  TrilinosWrappers::MPI::Vector
  linear_in_time(const IndexSet &owned, const double t)
  {
    TrilinosWrappers::MPI::Vector u(owned, MPI_COMM_SELF);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = std::sin(i) + std::cos(3. * i) * t;
    u.compress(VectorOperation::insert);
    return u;
  }

  /** u(t) = a + b t + c t² with c_i = 0.3 sin(2 i + 1). */
  TrilinosWrappers::MPI::Vector
  quadratic_in_time(const IndexSet &owned, const double t)
  {
    TrilinosWrappers::MPI::Vector u(owned, MPI_COMM_SELF);
    for (unsigned int i = 0; i < n; ++i)
      u[i] = std::sin(i) + std::cos(3. * i) * t +
             0.3 * std::sin(2. * i + 1.) * t * t;
    u.compress(VectorOperation::insert);
    return u;
  }

  /** Largest |a_i − b_i|. */
  double
  difference(const TrilinosWrappers::MPI::Vector &a,
             const TrilinosWrappers::MPI::Vector &b)
  {
    double e = 0;
    for (unsigned int i = 0; i < n; ++i)
      e = std::max(e, std::abs(a[i] - b[i]));
    return e;
  }

  /** The linear extrapolation of u at t1 and t2 to t. */
  TrilinosWrappers::MPI::Vector
  linear_guess(const IndexSet &owned,
               const double    t1,
               const double    t2,
               const double    t)
  {
    const double                  r = (t - t2) / (t2 - t1);
    TrilinosWrappers::MPI::Vector g = quadratic_in_time(owned, t2);
    g.sadd(1. + r, -r, quadratic_in_time(owned, t1));
    return g;
  }

  /** Whether a predictor restored from @p predictor's times() and
   * solutions() (a checkpoint's contents) predicts the same guess at @p t
   * bit for bit. */
  bool
  resumes_bit_for_bit(const SolutionPredictor &predictor,
                      const IndexSet          &owned,
                      const double             t)
  {
    std::vector<TrilinosWrappers::MPI::Vector> saved;
    for (const auto *v : predictor.solutions())
      saved.push_back(*v);
    SolutionPredictor resumed;
    resumed.restore(predictor.times(), saved);
    TrilinosWrappers::MPI::Vector guess(owned, MPI_COMM_SELF);
    TrilinosWrappers::MPI::Vector again(owned, MPI_COMM_SELF);
    predictor.predict(t, guess);
    resumed.predict(t, again);
    return difference(guess, again) == 0;
  }

  /** Checks 5 (the quadratic through three solutions). */
  void
  check_three_solutions(const IndexSet &owned)
  {
    TrilinosWrappers::MPI::Vector guess(owned, MPI_COMM_SELF);
    SolutionPredictor             predictor;
    for (const double t : {1., 2., 2.5})
      predictor.record(t, quadratic_in_time(owned, t));
    predictor.predict(3.5, guess);
    check(difference(guess, quadratic_in_time(owned, 3.5)) < 1e-13,
          "three solutions of a quadratic in time: extrapolated exactly to "
          "t = 3.5");
    predictor.predict(2.2, guess);
    check(difference(guess, linear_guess(owned, 2., 2.5, 2.2)) < 1e-14,
          "a step retried (t = 2.2) interpolates the last two linearly");
    predictor.predict(5., guess);
    check(difference(guess, linear_guess(owned, 2., 2.5, 4.5)) < 1e-13,
          "a step five times the last takes the clamped linear guess");

    check(resumes_bit_for_bit(predictor, owned, 3.1) &&
            predictor.times() == std::vector<double>({1., 2., 2.5}),
          "restored from three times and solutions it predicts the same "
          "guess bit for bit");

    SolutionPredictor uneven;
    for (const double t : {1., 2., 10.})
      uneven.record(t, quadratic_in_time(owned, t));
    uneven.predict(12., guess);
    check(difference(guess, linear_guess(owned, 2., 10., 12.)) < 1e-12,
          "after steps of 1 and 8 the guess is the linear one");
  }

  /** Largest |guess_i − u_i(t)|. */
  double
  error(const TrilinosWrappers::MPI::Vector &guess,
        const IndexSet                      &owned,
        const double                         t)
  {
    const auto exact = linear_in_time(owned, t);
    double     e     = 0;
    for (unsigned int i = 0; i < n; ++i)
      e = std::max(e, std::abs(guess[i] - exact[i]));
    return e;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  IndexSet                         owned = complete_index_set(n);
  TrilinosWrappers::MPI::Vector    guess(owned, MPI_COMM_SELF);

  SolutionPredictor predictor;
  check(!predictor.available(), "nothing recorded: no guess");
  predictor.record(1., linear_in_time(owned, 1.));
  predictor.predict(4., guess);
  check(error(guess, owned, 1.) == 0,
        "one solution recorded: the guess is that solution");

  predictor.record(2., linear_in_time(owned, 2.));
  predictor.predict(3., guess);
  check(error(guess, owned, 3.) < 1e-14,
        "a solution linear in time is extrapolated exactly to t = 3");
  predictor.predict(1.5, guess);
  check(error(guess, owned, 1.5) < 1e-14,
        "and interpolated exactly at t = 1.5 (a step retried)");
  predictor.predict(100., guess);
  check(error(guess, owned, 6.) < 1e-13,
        "far ahead the ratio is clamped to 4: the guess at t = 100 is u(6)");

  check(resumes_bit_for_bit(predictor, owned, 2.7) &&
          predictor.times() == std::vector<double>({1., 2.}),
        "restored from its times and solutions it predicts the same guess "
        "bit for bit");

  predictor.clear();
  check(!predictor.available(), "a new mesh: no guess");
  check_three_solutions(owned);

  SolutionPredictor iterates;
  iterates.record(1., linear_in_time(owned, 1.));
  iterates.record(2., linear_in_time(owned, 7.));
  iterates.record(2., linear_in_time(owned, 2.));
  iterates.predict(3., guess);
  check(error(guess, owned, 3.) < 1e-14 &&
          iterates.times() == std::vector<double>({1., 2.}),
        "a solution of the last one's time replaces it (Newton's iterates "
        "of one step): the guess at t = 3 is u(3), the times 1 and 2");
  if (failed)
    {
      std::cout << "FAILED" << std::endl;
      return 1;
    }
  std::cout << "all checks passed" << std::endl;
  return 0;
}

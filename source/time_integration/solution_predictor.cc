#include <lithostress/time_integration/solution_predictor.h>

#include <algorithm>

namespace lithostress
{
  void
  SolutionPredictor::clear()
  {
    last.clear();
    before.clear();
    earliest.clear();
    n_recorded = 0;
  }

  void
  SolutionPredictor::record(const double                         time,
                            const TrilinosWrappers::MPI::Vector &solution)
  {
    if (n_recorded > 0 && last.size() != solution.size())
      clear();
    if (n_recorded > 1)
      {
        std::swap(earliest, before);
        earliest_time = before_time;
      }
    if (n_recorded > 0)
      {
        std::swap(before, last);
        before_time = last_time;
      }
    last       = solution;
    last_time  = time;
    n_recorded = std::min(n_recorded + 1, 3u);
  }

  void
  SolutionPredictor::predict(const double                   time,
                             TrilinosWrappers::MPI::Vector &guess) const
  {
    Assert(available(), ExcInternalError());
    guess = last;
    if (n_recorded == 1 || !(last_time > before_time))
      return;
    const double ratio = (time - last_time) / (last_time - before_time);
    // Through the last three solutions where the steps run forward at
    // comparable lengths: the error is then of the order of the steps'
    // third difference.
    if (n_recorded == 3 && before_time > earliest_time && ratio > 0 &&
        ratio <= 4)
      {
        const double t0 = earliest_time, t1 = before_time, t2 = last_time;
        const double previous = (t2 - t1) / (t1 - t0);
        if (previous >= 0.25 && previous <= 4)
          {
            guess *= (time - t0) * (time - t1) / ((t2 - t0) * (t2 - t1));
            guess.add((time - t0) * (time - t2) / ((t1 - t0) * (t1 - t2)),
                      before,
                      (time - t1) * (time - t2) / ((t0 - t1) * (t0 - t2)),
                      earliest);
            return;
          }
      }
    const double clamped = std::clamp(ratio, -1., 4.);
    guess.sadd(1. + clamped, -clamped, before);
  }

  std::vector<double>
  SolutionPredictor::times() const
  {
    if (n_recorded == 3)
      return {earliest_time, before_time, last_time};
    if (n_recorded == 2)
      return {before_time, last_time};
    if (n_recorded == 1)
      return {last_time};
    return {};
  }

  std::vector<const TrilinosWrappers::MPI::Vector *>
  SolutionPredictor::solutions() const
  {
    if (n_recorded == 3)
      return {&earliest, &before, &last};
    if (n_recorded == 2)
      return {&before, &last};
    if (n_recorded == 1)
      return {&last};
    return {};
  }

  void
  SolutionPredictor::restore(
    const std::vector<double>                        &times,
    const std::vector<TrilinosWrappers::MPI::Vector> &solutions)
  {
    AssertThrow(times.size() == solutions.size() && times.size() <= 3,
                ExcInternalError());
    clear();
    for (unsigned int k = 0; k < times.size(); ++k)
      record(times[k], solutions[k]);
  }
} // namespace lithostress

#include <lithostress/time_integration/solution_predictor.h>

#include <algorithm>

namespace lithostress
{
  void
  SolutionPredictor::clear()
  {
    history.clear();
    history_times.clear();
  }

  void
  SolutionPredictor::record(const double                         time,
                            const TrilinosWrappers::MPI::Vector &solution)
  {
    if (!history.empty() && history.back().size() != solution.size())
      clear();
    // Newton's iterates of one step share its time: the latest stands for
    // it, so the history keeps three distinct times to extrapolate from.
    if (!history.empty() && history_times.back() == time)
      {
        history.back() = solution;
        return;
      }
    if (history.size() < 3)
      {
        history.push_back(solution);
        history_times.push_back(time);
        return;
      }
    // The oldest vector takes the new solution (its memory reused).
    std::rotate(history.begin(), history.begin() + 1, history.end());
    std::rotate(history_times.begin(),
                history_times.begin() + 1,
                history_times.end());
    history.back()       = solution;
    history_times.back() = time;
  }

  void
  SolutionPredictor::predict(const double                   time,
                             TrilinosWrappers::MPI::Vector &guess) const
  {
    Assert(available(), ExcInternalError());
    const std::size_t n = history.size();
    guess               = history[n - 1];
    if (n == 1 || !(history_times[n - 1] > history_times[n - 2]))
      return;
    const double t2 = history_times[n - 1], t1 = history_times[n - 2];
    const double ratio = (time - t2) / (t2 - t1);
    // Through the last three solutions where the steps run forward at
    // comparable lengths: the error is then of the order of the steps'
    // third difference.
    if (n == 3 && t1 > history_times[0] && ratio > 0 && ratio <= 4)
      {
        const double t0       = history_times[0];
        const double previous = (t2 - t1) / (t1 - t0);
        if (previous >= 0.25 && previous <= 4)
          {
            guess *= (time - t0) * (time - t1) / ((t2 - t0) * (t2 - t1));
            guess.add((time - t0) * (time - t2) / ((t1 - t0) * (t1 - t2)),
                      history[1],
                      (time - t1) * (time - t2) / ((t0 - t1) * (t0 - t2)),
                      history[0]);
            return;
          }
      }
    const double clamped = std::clamp(ratio, -1., 4.);
    guess.sadd(1. + clamped, -clamped, history[n - 2]);
  }

  std::vector<double>
  SolutionPredictor::times() const
  {
    return history_times;
  }

  std::vector<const TrilinosWrappers::MPI::Vector *>
  SolutionPredictor::solutions() const
  {
    std::vector<const TrilinosWrappers::MPI::Vector *> result;
    for (const auto &solution : history)
      result.push_back(&solution);
    return result;
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

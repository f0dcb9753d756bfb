#include <lithostress/time_integration/solution_predictor.h>

#include <algorithm>

namespace lithostress
{
  void
  SolutionPredictor::clear()
  {
    last.clear();
    before.clear();
    n_recorded = 0;
  }

  void
  SolutionPredictor::record(const double                         time,
                            const TrilinosWrappers::MPI::Vector &solution)
  {
    if (n_recorded > 0 && last.size() != solution.size())
      clear();
    if (n_recorded > 0)
      {
        std::swap(before, last);
        before_time = last_time;
      }
    last       = solution;
    last_time  = time;
    n_recorded = std::min(n_recorded + 1, 2u);
  }

  void
  SolutionPredictor::predict(const double                   time,
                             TrilinosWrappers::MPI::Vector &guess) const
  {
    Assert(available(), ExcInternalError());
    guess = last;
    if (n_recorded == 2 && last_time > before_time)
      {
        const double ratio =
          std::clamp((time - last_time) / (last_time - before_time), -1., 4.);
        guess.sadd(1. + ratio, -ratio, before);
      }
  }

  std::vector<double>
  SolutionPredictor::times() const
  {
    if (n_recorded == 2)
      return {before_time, last_time};
    if (n_recorded == 1)
      return {last_time};
    return {};
  }

  std::vector<const TrilinosWrappers::MPI::Vector *>
  SolutionPredictor::solutions() const
  {
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
    AssertThrow(times.size() == solutions.size() && times.size() <= 2,
                ExcInternalError());
    clear();
    for (unsigned int k = 0; k < times.size(); ++k)
      record(times[k], solutions[k]);
  }
} // namespace lithostress

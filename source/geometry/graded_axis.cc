#include <lithostress/geometry/graded_axis.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lithostress
{
  double
  GradedAxis::size(const double t) const
  {
    if (fine_set.empty())
      return coarsest;
    double distance = std::numeric_limits<double>::infinity();
    for (const auto &[lower, upper] : fine_set)
      distance = std::min(distance, std::max({0.0, lower - t, t - upper}));
    return std::min(coarsest, fine + (growth - 1) * distance);
  }

  std::vector<double>
  GradedAxis::nodes(const double a, const double b) const
  {
    // Φ by the trapezoidal rule on samples a sixteenth of the local size
    // apart (Φ's integrand 1/s changes by at most a factor
    // 1 + (growth - 1)/16 between two samples).
    std::vector<double> t = {a}, phi = {0.0};
    while (t.back() < b)
      {
        const double next = std::min(b, t.back() + size(t.back()) / 16);
        phi.push_back(phi.back() + 0.5 * (next - t.back()) *
                                     (1 / size(t.back()) + 1 / size(next)));
        t.push_back(next);
      }
    const unsigned int  n      = std::max<long>(1, std::lround(phi.back()));
    std::vector<double> result = {a};
    unsigned int        j      = 0;
    for (unsigned int i = 1; i < n; ++i)
      {
        const double target = phi.back() * i / n;
        while (phi[j + 1] < target)
          ++j;
        const double w = (target - phi[j]) / (phi[j + 1] - phi[j]);
        result.push_back(t[j] + w * (t[j + 1] - t[j]));
      }
    result.push_back(b);
    return result;
  }
} // namespace lithostress

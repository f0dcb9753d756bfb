#include <lithostress/faults/fault_trace.h>

#include <cmath>

namespace lithostress
{
  double
  FaultTrace::x_at(const double y) const
  {
    return surface_x + direction * (top_y - y) / std::tan(dip);
  }

  bool
  FaultTrace::in_hanging_wall(const Point<2> &p) const
  {
    return direction * (p[0] - x_at(p[1])) > 0;
  }

  double
  FaultTrace::distance_along(const Point<2> &p) const
  {
    return depth(p) / std::sin(dip);
  }

  Tensor<1, 2>
  FaultTrace::down_dip() const
  {
    Tensor<1, 2> d;
    d[0] = direction * std::cos(dip);
    d[1] = -std::sin(dip);
    return d;
  }
} // namespace lithostress

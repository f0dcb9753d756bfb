#include <lithostress/faults/fault_trace.h>

#include <cmath>

namespace lithostress
{
  void
  FaultTrace::choose_branch(const double depth)
  {
    // On the branch x = c_x + b sqrt(R² − (y − c_y)²), going down (y
    // decreasing) moves x by b sign(y − c_y) per unit of the root's growth.
    const double y = top_y - depth;
    branch         = direction * (y > arc_centre[1] ? 1 : -1);
  }

  double
  FaultTrace::x_at(const double y) const
  {
    if (has_arc && top_y - y >= arc_from_depth)
      {
        const double dy = y - arc_centre[1];
        return arc_centre[0] +
               branch *
                 std::sqrt(std::max(0.0, arc_radius * arc_radius - dy * dy));
      }
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
    const double d = depth(p);
    if (!has_arc || d < arc_from_depth)
      return d / std::sin(dip);
    // The planar part, then the arc from the junction to the point.
    const double planar =
      arc_from_depth > 0 ? arc_from_depth / std::sin(dip) : 0;
    const double   y0 = top_y - arc_from_depth;
    const Point<2> a(x_at(y0), y0), b(x_at(p[1]), p[1]);
    const double   angle =
      std::abs(std::atan2((a - arc_centre)[0] * (b - arc_centre)[1] -
                            (a - arc_centre)[1] * (b - arc_centre)[0],
                          (a - arc_centre) * (b - arc_centre)));
    return planar + arc_radius * angle;
  }

  Tensor<1, 2>
  FaultTrace::down_dip(const Point<2> &p) const
  {
    Tensor<1, 2> d;
    if (!on_arc(p))
      {
        d[0] = direction * std::cos(dip);
        d[1] = -std::sin(dip);
        return d;
      }
    // Perpendicular to the radius, pointing down.
    const Point<2>     on(x_at(p[1]), p[1]);
    const Tensor<1, 2> r = on - arc_centre;
    d[0]                 = -r[1];
    d[1]                 = r[0];
    if (d[1] > 0 || (d[1] == 0 && direction * d[0] < 0))
      d = -d;
    return d / d.norm();
  }
} // namespace lithostress

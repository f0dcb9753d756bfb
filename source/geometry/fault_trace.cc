#include <lithostress/geometry/fault_trace.h>

#include <cmath>
#include <limits>

namespace lithostress
{
  namespace
  {
    double
    cross(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return a[0] * b[1] - a[1] * b[0];
    }

    /** The signed angle from @p a to @p b (both from the centre). */
    double
    angle_between(const Tensor<1, 2> &a, const Tensor<1, 2> &b)
    {
      return std::atan2(cross(a, b), a * b);
    }
  } // namespace

  void
  FaultTrace::set_polyline(const std::vector<Point<2>> &vertices,
                           const bool                   arc,
                           const Point<2>              &centre)
  {
    polyline       = vertices;
    has_arc        = arc;
    arc_centre     = centre;
    arc_from_depth = 0;
    arc_radius     = arc ? vertices.front().distance(centre) : 0;
    surface_x      = vertices.front()[0];
    top_y          = vertices.front()[1];
    direction      = vertices.back()[0] < vertices.front()[0] ? -1 : 1;
  }

  FaultTrace::Projection
  FaultTrace::project(const Point<2> &p) const
  {
    Projection best;
    double     closest = std::numeric_limits<double>::max(), s = 0;
    for (unsigned int i = 0; i + 1 < polyline.size(); ++i)
      {
        const Point<2> &a = polyline[i], &b = polyline[i + 1];
        double          t = 0, length = 0;
        Point<2>        q;
        if (has_arc)
          {
            const Tensor<1, 2> ra = a - arc_centre, rb = b - arc_centre,
                               rp = p - arc_centre;
            const double total    = angle_between(ra, rb);
            length                = arc_radius * std::abs(total);
            t                = total == 0 ? 0 : angle_between(ra, rp) / total;
            t                = std::clamp(t, 0.0, 1.0);
            const double phi = t * total;
            q                = arc_centre +
                Tensor<1, 2>({ra[0] * std::cos(phi) - ra[1] * std::sin(phi),
                              ra[0] * std::sin(phi) + ra[1] * std::cos(phi)});
          }
        else
          {
            const Tensor<1, 2> ab = b - a;
            length                = ab.norm();
            t = std::clamp((p - a) * ab / (length * length), 0.0, 1.0);
            q = a + t * ab;
          }
        if (p.distance(q) < closest)
          {
            closest      = p.distance(q);
            best.segment = i;
            best.t       = t;
            best.point   = q;
            best.s       = s + t * length;
          }
        s += length;
      }
    return best;
  }

  void
  FaultTrace::choose_branch(const double depth)
  {
    // On the branch x = c_x + b sqrt(R² − (y − c_y)²), going down (y
    // decreasing) moves x by b sign(y − c_y) per unit of the root's growth.
    const double y = top_y - depth;
    branch         = direction * (y > arc_centre[1] ? 1 : -1);
  }

  double
  FaultTrace::x_at(double y) const
  {
    y = std::max(y, top_y - vertical_below_depth);
    if (has_arc && top_y - y >= arc_from_depth)
      {
        const double dy = y - arc_centre[1];
        return arc_centre[0] +
               branch *
                 std::sqrt(std::max(0.0, arc_radius * arc_radius - dy * dy));
      }
    return surface_x + direction * (top_y - y) / std::tan(dip);
  }

  double
  FaultTrace::distance_to(const Point<2> &p) const
  {
    if (!polyline.empty())
      return p.distance(project(p).point);
    return std::abs(p[0] - x_at(p[1]));
  }

  bool
  FaultTrace::in_hanging_wall(const Point<2> &p) const
  {
    if (!polyline.empty())
      {
        const Point<2> q = project(p).point;
        return (p - q) * hanging_wall_normal(q) > 0;
      }
    return direction * (p[0] - x_at(p[1])) > 0;
  }

  double
  FaultTrace::trace_distance(const Point<2> &p) const
  {
    if (!polyline.empty())
      return project(p).s;
    const double d = depth(p);
    if (d > vertical_below_depth)
      return trace_distance(point_at_depth(vertical_below_depth)) +
             (d - vertical_below_depth);
    if (!has_arc || d < arc_from_depth)
      return d / std::sin(dip);
    // The planar part, then the arc from the junction to the point.
    const double planar =
      arc_from_depth > 0 ? arc_from_depth / std::sin(dip) : 0;
    const double   y0 = top_y - arc_from_depth;
    const Point<2> a(x_at(y0), y0), b(x_at(p[1]), p[1]);
    return planar +
           arc_radius * std::abs(angle_between(a - arc_centre, b - arc_centre));
  }

  Tensor<1, 2>
  FaultTrace::down_dip(const Point<2> &p) const
  {
    Tensor<1, 2> d;
    if (!polyline.empty())
      {
        const Projection   q = project(p);
        const Tensor<1, 2> chord =
          polyline[q.segment + 1] - polyline[q.segment];
        if (!has_arc)
          return chord / chord.norm();
        // Perpendicular to the radius, along the chord.
        const Tensor<1, 2> r = q.point - arc_centre;
        d[0]                 = -r[1];
        d[1]                 = r[0];
        if (d * chord < 0)
          d = -d;
        return d / d.norm();
      }
    if (depth(p) > vertical_below_depth)
      {
        d[1] = -1;
        return d;
      }
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

  Tensor<1, 2>
  FaultTrace::hanging_wall_normal(const Point<2> &p) const
  {
    // Of the two normals, the one on the side the fault dips towards, and
    // upwards: n·(direction, 1) > 0 for every dip from 0 to 90 degrees.
    const Tensor<1, 2> d = down_dip(p);
    Tensor<1, 2>       n;
    n[0] = -d[1];
    n[1] = d[0];
    if (n[0] * direction + n[1] < 0)
      n = -n;
    return n;
  }
} // namespace lithostress

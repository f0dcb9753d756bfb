#ifndef lithostress_geometry_fault_trace_h
#define lithostress_geometry_fault_trace_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <limits>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The trace of a fault in the cross section (thesis §6.1–6.3, §7.2):
   * a curve from the top surface through the whole model that separates
   * it into a footwall and a hanging wall, and is a graph x_f(y). It is
   * planar — through the surface point (x_s, y_top), dipping at the angle
   * δ towards +x or −x, x_f(y) = x_s ± (y_top − y)/tan δ — down to the
   * depth `arc_from_depth`, and below it, if `has_arc`, a circular arc
   * (centre c, radius R; thesis §6.2's listric fault: planar to 10 km, then
   * an arc; §6.3.2 and §7.2: an arc from the surface). The hanging wall is
   * the side the fault dips towards (it lies above the fault); the fault's
   * jump is w = u(hanging wall) − u(footwall).
   *
   * A fault read from a mesh (a Gmsh physical curve) is instead a chain of
   * the coarse mesh's edges, `polyline`, from its upper end down: straight
   * segments, or arcs about `arc_centre` if `has_arc` (the whole fault is
   * then on that circle). Its surface trace is the upper end, depth is
   * measured from there, and it dips towards the side of its lower end
   * (towards +x if it is vertical).
   *
   * A fault may end inside the body (a buried tip): then only the part of
   * the trace from `begin_s` to `end_s` (distances along it from its
   * upper end) is the fault, and the rest is a welded extension to the
   * boundary whose two sides are tied exactly (FaultInterface), so that
   * the trace still splits the body into the blocks of the two
   * displacement fields while the displacement is continuous across the
   * extension and the jump vanishes at the tips.
   */
  struct FaultTrace
  {
    /** The point of a polyline trace closest to a given point: its
     * segment, the parameter in [0, 1] along it, the point, and the
     * distance along the fault from the upper end there [m]. */
    struct Projection
    {
      unsigned int segment = 0;
      double       t       = 0;
      Point<2>     point;
      double       s = 0;
    };

    /** The projection of @p p onto the polyline. */
    Projection
    project(const Point<2> &p) const;

    /** The fault's name (its subsection of `Faults`). */
    std::string name;
    /** x of the surface trace and y of the top surface [m]. */
    double surface_x = 0, top_y = 0;
    /** Dip δ of the planar part [rad], in (0, π/2]. */
    double dip = 0;
    /** +1 if the fault dips towards +x, −1 towards −x. */
    int direction = 1;
    /** Whether the fault is a circular arc below arc_from_depth [m]. */
    bool     has_arc        = false;
    double   arc_from_depth = 0;
    Point<2> arc_centre;
    double   arc_radius = 0;
    /** The arc's branch: x = c_x + branch sqrt(R² − (y − c_y)²). */
    int branch = 1;
    /** A fault read from a mesh: its vertices from the upper end down
     * (empty for the planar or listric trace above). */
    std::vector<Point<2>> polyline;
    /** The fault's own part: from begin_s to end_s along the trace from
     * its upper end [m]; outside it the trace is a welded extension. The
     * default is the whole trace. */
    double begin_s = 0, end_s = std::numeric_limits<double>::infinity();
    /** Below this depth [m] the planar or listric trace goes straight down
     * (x_f(y) = x_f at that depth): the welded extension below a buried
     * lower tip whose plane would leave the box through a side before the
     * base (LayeredBox). Infinite (the default): the trace follows its
     * plane or arc to the base. */
    double vertical_below_depth = std::numeric_limits<double>::infinity();

    /** Whether the fault ends inside the body above (a buried upper tip). */
    bool
    buried_top() const
    {
      return begin_s > 0;
    }

    /** Whether the fault ends inside the body below (a buried lower tip). */
    bool
    buried_bottom() const
    {
      return end_s < std::numeric_limits<double>::infinity();
    }

    /** Whether the point @p p of the trace lies on the fault's own part
     * (within @p tolerance [m] of it), not on its welded extension. */
    bool
    on_fault_part(const Point<2> &p, const double tolerance) const
    {
      const double s = trace_distance(p);
      return s >= begin_s - tolerance && s <= end_s + tolerance;
    }

    /** The point of the planar or listric trace at @p depth [m] below the
     * top surface. */
    Point<2>
    point_at_depth(const double depth) const
    {
      return Point<2>(x_at(top_y - depth), top_y - depth);
    }

    /** Make a trace of @p vertices (from the upper end down; arcs about
     * @p centre if @p arc): sets the surface point and direction. */
    void
    set_polyline(const std::vector<Point<2>> &vertices,
                 const bool                   arc,
                 const Point<2>              &centre);

    /** Choose the arc's branch so that the fault dips towards
     * `direction` at depth @p depth [m] (set has_arc and the arc first). */
    void
    choose_branch(const double depth);

    /** x of the fault at height @p y (the planar or listric trace, and
     * straight down below `vertical_below_depth`). */
    double
    x_at(double y) const;

    /** Whether @p p lies in the hanging wall (else in the footwall). */
    bool
    in_hanging_wall(const Point<2> &p) const;

    /** Distance along the fault from its upper end (the surface trace,
     * or the buried upper tip) to the point of the fault nearest @p p
     * (at the height of @p p for the planar or listric trace) [m]:
     * s of the fault's slip and output (negative on an extension above a
     * buried tip). */
    double
    distance_along(const Point<2> &p) const
    {
      return trace_distance(p) - begin_s;
    }

    /** Distance along the whole trace, extensions included, from its
     * upper end to the point of the trace nearest @p p [m]. */
    double
    trace_distance(const Point<2> &p) const;

    /** Depth of @p p below the top surface [m]. */
    double
    depth(const Point<2> &p) const
    {
      return top_y - p[1];
    }

    /** Whether the fault at the height of @p p is on its arc. */
    bool
    on_arc(const Point<2> &p) const
    {
      return has_arc && (!polyline.empty() || depth(p) >= arc_from_depth);
    }

    /** Distance from @p p to the fault [m] (horizontal for the planar or
     * listric trace, which is a graph x(y)). */
    double
    distance_to(const Point<2> &p) const;

    /** The unit normal of the fault near @p p pointing into the hanging
     * wall. */
    Tensor<1, 2>
    hanging_wall_normal(const Point<2> &p) const;

    /** The unit vector along the fault at the height of @p p pointing
     * down dip: slip w·d > 0 moves the hanging wall down (normal sense),
     * < 0 up (reverse). */
    Tensor<1, 2>
    down_dip(const Point<2> &p) const;
  };
} // namespace lithostress

#endif

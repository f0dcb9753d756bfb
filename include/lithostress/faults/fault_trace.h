#ifndef lithostress_faults_fault_trace_h
#define lithostress_faults_fault_trace_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * The trace of a fault in the cross section (SPEC §3.4, thesis §6.1–6.3):
   * a curve from the top surface through the whole model that separates
   * it into a footwall and a hanging wall, and is a graph x_f(y). It is
   * planar — through the surface point (x_s, y_top), dipping at the angle
   * δ towards +x or −x, x_f(y) = x_s ± (y_top − y)/tan δ — down to the
   * depth `arc_from_depth`, and below it, if `has_arc`, a circular arc
   * (centre c, radius R; thesis §6.2's listric fault: planar to 10 km, then
   * an arc; §6.3.2 and §7.2: an arc from the surface). The hanging wall is
   * the side the fault dips towards (it lies above the fault); the fault's
   * jump is w = u(hanging wall) − u(footwall).
   */
  struct FaultTrace
  {
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

    /** Choose the arc's branch so that the fault dips towards
     * `direction` at depth @p depth [m] (set has_arc and the arc first). */
    void
    choose_branch(const double depth);

    /** x of the fault at height @p y. */
    double
    x_at(const double y) const;

    /** Whether @p p lies in the hanging wall (else in the footwall). */
    bool
    in_hanging_wall(const Point<2> &p) const;

    /** Distance along the fault from its surface trace to the point of
     * the fault at the height of @p p [m]. */
    double
    distance_along(const Point<2> &p) const;

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
      return has_arc && depth(p) >= arc_from_depth;
    }

    /** The unit vector along the fault at the height of @p p pointing
     * down dip: slip w·d > 0 moves the hanging wall down (normal sense),
     * < 0 up (reverse). */
    Tensor<1, 2>
    down_dip(const Point<2> &p) const;
  };
} // namespace lithostress

#endif

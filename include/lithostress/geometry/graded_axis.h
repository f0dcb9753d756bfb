#ifndef lithostress_geometry_graded_axis_h
#define lithostress_geometry_graded_axis_h

#include <utility>
#include <vector>

namespace lithostress
{
  /**
   * The nodes of a coarse mesh's axis graded from a fine set: a coordinate
   * interval [a, b] divided into cells of the size
   *
   *   s(t) = min(coarsest, fine + (growth − 1) dist(t, F)),
   *
   * which is `fine` on the set F (a union of intervals) and grows by the
   * factor `growth` from one cell to the next away from it (a cell of size
   * s at the distance d ends where the next has (growth − 1)(d + s) + fine
   * = growth s), up to `coarsest`. The nodes are the points where
   * Φ(t) = ∫_a^t dτ / s(τ) takes n equal steps, n = round(Φ(b)) (at least
   * one cell): the size function is followed to within the rounding of n,
   * and the nodes are a smooth function of the interval's ends. Used for
   * the layered box's rows and columns around a buried fault, whose
   * surface displacement converges only with cells of the tip's size from
   * the surface to the tip (doc/faults.md, "Graded coarse mesh").
   */
  struct GradedAxis
  {
    /** Cell size on the fine set and the largest cell size (same unit as
     * the coordinate), and the growth factor per cell (> 1). */
    double fine = 1, coarsest = 1, growth = 1.5;
    /** The fine set F: intervals [lower, upper] of the coordinate (a point
     * is an interval of zero length). Empty: cells of `coarsest`. */
    std::vector<std::pair<double, double>> fine_set;

    /** The cell size s(t) at @p t. */
    double
    size(const double t) const;

    /** The nodes a = t_0 < … < t_n = b. */
    std::vector<double>
    nodes(const double a, const double b) const;
  };
} // namespace lithostress

#endif

#ifndef lithostress_base_gravity_field_h
#define lithostress_base_gravity_field_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

namespace lithostress
{
  using namespace dealii;

  /**
   * The model's gravity: the acceleration g and the height of zero depth
   * (sea level), declared once (`Gravity field`) and used by every
   * component that needs them — the body force (thesis §3.7.1), density
   * stripping (§7.3), the isostatic restoring force (§3.7.2.3), the
   * fault's lithostatic normal stress and pore pressure (§5.5, FSHEAR),
   * the Griffith test's lithostatic pressure (FAIL), the thin-plate
   * comparison (§6.1.2) and the lithostatic column's exact solution
   * (§4.4) — so that a model cannot use two values.
   */
  struct GravityField
  {
    /** g [m/s^2]. */
    double acceleration = 9.81;
    /** y [m] at which depth is zero. */
    double depth_origin = 0;

    /** Declare `Gravity field/Acceleration` and `Depth origin`. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read them; @p length_scale converts the depth origin to metres. */
    static GravityField
    parse_parameters(ParameterHandler &prm, const double length_scale);

    /** The depth of @p p below the depth origin [m] (negative above it). */
    template <int dim>
    double
    depth(const Point<dim> &p) const
    {
      return depth_origin - p[dim - 1];
    }
  };
} // namespace lithostress

#endif

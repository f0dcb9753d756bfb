#include <lithostress/base/gravity_field.h>

namespace lithostress
{
  void
  GravityField::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Gravity field");
    prm.declare_entry("Acceleration",
                      "9.81",
                      Patterns::Double(0),
                      "Gravitational acceleration g [m/s^2] of every term "
                      "that has one: the body force, density stripping, the "
                      "isostatic restoring force, the faults' lithostatic "
                      "normal stress and pore pressure, the Griffith test's "
                      "lithostatic pressure, the thin-plate comparison and "
                      "the lithostatic column's exact solution.");
    prm.declare_entry("Depth origin",
                      "0",
                      Patterns::Double(),
                      "y [length unit] at which depth is zero (sea level): "
                      "depth = origin - y, for density stripping, the "
                      "faults' lithostatic and pore pressures and the "
                      "Griffith test's lithostatic pressure.");
    prm.leave_subsection();
  }

  GravityField
  GravityField::parse_parameters(ParameterHandler &prm,
                                 const double      length_scale)
  {
    GravityField gravity;
    prm.enter_subsection("Gravity field");
    gravity.acceleration = prm.get_double("Acceleration");
    gravity.depth_origin = prm.get_double("Depth origin") * length_scale;
    prm.leave_subsection();
    return gravity;
  }
} // namespace lithostress

#include <lithostress/base/input_error.h>
#include <lithostress/temperature/plate_cooling.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace lithostress
{
  namespace
  {
    /** A million Julian years [s]. */
    constexpr double seconds_per_myr = 1e6 * 365.25 * 24 * 3600;
  } // namespace

  template <int dim>
  void
  PlateCoolingTemperature<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Plate cooling");
    prm.declare_entry("Plate age",
                      "",
                      Patterns::Anything(),
                      "Model = plate cooling: the age of the plate [Myr] as "
                      "a function of x [m] (muparser; y is 0), so that a "
                      "plate can age towards a trench; at least 0.");
    prm.declare_entry("Constants",
                      "",
                      Patterns::Anything(),
                      "Constants for Plate age: name=value, ...");
    prm.declare_entry("Surface temperature",
                      "273",
                      Patterns::Double(0),
                      "The temperature of the plate's top [K], above 0.");
    prm.declare_entry("Mantle temperature",
                      "1623",
                      Patterns::Double(0),
                      "The temperature of the mantle the plate cooled from "
                      "[K], at least the Surface temperature.");
    prm.declare_entry("Plate thickness",
                      "0",
                      Patterns::Double(0),
                      "The thickness L of the plate model [Length unit], "
                      "whose base is held at the Mantle temperature "
                      "(Parsons & Sclater 1977: 125 km); 0 = half-space "
                      "cooling.");
    prm.declare_entry("Thermal diffusivity",
                      "1e-6",
                      Patterns::Double(0),
                      "kappa [m^2/s], above 0.");
    prm.declare_entry("Depth origin",
                      "0",
                      Patterns::Double(),
                      "The y of the plate's top [Length unit]: depths are "
                      "measured down from it.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  PlateCoolingTemperature<dim>::parse_parameters(ParameterHandler &prm,
                                                 const double      length_scale)
  {
    prm.enter_subsection("Plate cooling");
    const std::string entry = "Temperature/Plate cooling/";
    const std::string age   = Utilities::trim(prm.get("Plate age"));
    if (age.empty())
      throw_input_error(entry + "Plate age",
                        "is empty; Model = plate cooling needs the plate's "
                        "age [Myr] as a function of x [m]");
    plate_age           = std::make_unique<ParsedExpression<dim>>(age,
                                                        prm.get("Constants"),
                                                        entry + "Plate age");
    surface_temperature = prm.get_double("Surface temperature");
    mantle_temperature  = prm.get_double("Mantle temperature");
    thickness           = prm.get_double("Plate thickness") * length_scale;
    diffusivity         = prm.get_double("Thermal diffusivity");
    depth_origin        = prm.get_double("Depth origin") * length_scale;
    prm.leave_subsection();
    if (!(surface_temperature > 0))
      throw_input_error(entry + "Surface temperature",
                        "must be above 0 K (an absolute temperature)");
    if (mantle_temperature < surface_temperature)
      throw_input_error(entry + "Mantle temperature",
                        "is below the Surface temperature: a plate cools "
                        "from the mantle at its top");
    if (!(diffusivity > 0))
      throw_input_error(entry + "Thermal diffusivity", "must be above 0");
  }

  template <int dim>
  double
  PlateCoolingTemperature<dim>::age(const double x) const
  {
    Point<dim> p;
    p[0]             = x;
    const double myr = plate_age->value(p);
    if (myr < 0)
      {
        std::ostringstream what;
        what << std::setprecision(6) << "is " << myr << " Myr at x = " << x
             << " m; a plate's age is at least 0";
        throw_input_error("Temperature/Plate cooling/Plate age", what.str());
      }
    return myr * seconds_per_myr;
  }

  template <int dim>
  double
  PlateCoolingTemperature<dim>::value(const Point<dim> &p) const
  {
    const double t     = age(p[0]);
    const double d     = depth_origin - p[dim - 1];
    const double range = mantle_temperature - surface_temperature;
    if (d <= 0)
      return surface_temperature;
    if (thickness > 0 && d >= thickness)
      return mantle_temperature;
    if (t == 0)
      return mantle_temperature;
    const double kt = diffusivity * t;
    if (thickness == 0 || kt < 1e-3 * thickness * thickness)
      return surface_temperature + range * std::erf(d / (2 * std::sqrt(kt)));
    // Terms until e^(−κ n² π² t / L²) < 1e-17: at most 64 where κt/L² ≥
    // 1e-3.
    const double decay = kt * numbers::PI * numbers::PI / thickness / thickness;
    const unsigned int n_terms =
      static_cast<unsigned int>(std::ceil(std::sqrt(39.2 / decay)));
    double sum = 0;
    for (unsigned int n = 1; n <= n_terms; ++n)
      sum += std::exp(-decay * n * n) / n *
             std::sin(n * numbers::PI * d / thickness);
    return surface_temperature +
           range * (d / thickness + 2 / numbers::PI * sum);
  }

  template class PlateCoolingTemperature<2>;

  LITHOSTRESS_REGISTER_TEMPERATURE_MODEL(
    PlateCoolingTemperature,
    "plate cooling",
    "an oceanic plate cooled from the mantle for its age, by half-space or "
    "plate cooling (Temperature/Plate cooling)");
} // namespace lithostress

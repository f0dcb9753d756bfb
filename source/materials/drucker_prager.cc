#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/materials/drucker_prager.h>

#include <algorithm>
#include <cmath>

namespace lithostress
{
  namespace
  {
    /** The number @p text, or @p fallback if it is empty; throws
     * InputError naming @p entry if it is not a finite number. */
    double
    optional_number(const std::string &text,
                    const std::string &entry,
                    const double       fallback)
    {
      if (text.find_first_not_of(" \t") == std::string::npos)
        return fallback;
      try
        {
          std::size_t  used  = 0;
          const double value = std::stod(text, &used);
          if (text.find_first_not_of(" \t", used) == std::string::npos &&
              std::isfinite(value))
            return value;
        }
      catch (const std::exception &)
        {
        }
      throw_input_error(entry, "must be a number or empty, not <" + text + ">");
    }
  } // namespace

  void
  DruckerPrager::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Friction angle",
                      "0",
                      Patterns::Double(0, 90),
                      "Drucker-Prager yield tau_II = C cos(phi) + P sin(phi) "
                      "[degrees] (Rheology = visco-elasto-plastic; with "
                      "Cohesion = 0 as well: no plasticity)");
    prm.declare_entry("Cohesion",
                      "0",
                      Patterns::Double(0),
                      "C of the Drucker-Prager yield [Pa]");
    prm.declare_entry("Friction angle after softening",
                      "",
                      Patterns::Anything(),
                      "The friction angle once the accumulated plastic "
                      "strain reaches the end of Softening plastic strain "
                      "[degrees]; empty: no softening of the angle");
    prm.declare_entry("Cohesion after softening",
                      "",
                      Patterns::Anything(),
                      "The cohesion once the accumulated plastic strain "
                      "reaches the end of Softening plastic strain [Pa]; "
                      "empty: no softening of the cohesion");
    prm.declare_entry("Softening plastic strain",
                      "0, 1",
                      Patterns::Anything(),
                      "Start, end: the accumulated plastic strain over "
                      "which cohesion and friction angle fall linearly to "
                      "their values after softening");
    prm.declare_entry("Dilation angle",
                      "0",
                      Patterns::Double(0, 90),
                      "psi of the plastic potential tau_II - P sin(psi) "
                      "[degrees]; 0: incompressible plastic flow; at most "
                      "the friction angle");
  }

  void
  DruckerPrager::parse_parameters(ParameterHandler  &prm,
                                  const std::string &material,
                                  const double       tensile_strength)
  {
    this->tensile_strength    = tensile_strength;
    const std::string entry   = "Materials/" + material + "/";
    const double      degrees = M_PI / 180;
    friction                  = prm.get_double("Friction angle") * degrees;
    cohesion                  = prm.get_double("Cohesion");
    dilation                  = prm.get_double("Dilation angle") * degrees;
    softened_friction =
      optional_number(prm.get("Friction angle after softening"),
                      entry + "Friction angle after softening",
                      friction / degrees) *
      degrees;
    softened_cohesion = optional_number(prm.get("Cohesion after softening"),
                                        entry + "Cohesion after softening",
                                        cohesion);
    if (!(softened_friction >= 0 && softened_friction <= friction))
      throw_input_error(entry + "Friction angle after softening",
                        "must lie between 0 and the Friction angle");
    if (!(softened_cohesion >= 0 && softened_cohesion <= cohesion))
      throw_input_error(entry + "Cohesion after softening",
                        "must lie between 0 and the Cohesion");
    if (dilation > friction)
      throw_input_error(entry + "Dilation angle",
                        "exceeds the Friction angle (the plastic flow "
                        "would create energy)");
    const std::vector<std::string> interval =
      split_list(prm.get("Softening plastic strain"));
    const std::string softening_entry = entry + "Softening plastic strain";
    if (interval.size() != 2)
      throw_input_error(softening_entry, "needs two numbers: start, end");
    softening_start = optional_number(interval[0], softening_entry, 0);
    softening_end   = optional_number(interval[1], softening_entry, 0);
    if (!(softening_start >= 0 && softening_end > softening_start))
      throw_input_error(softening_entry,
                        "must be two increasing numbers, the first at "
                        "least 0");
    // The material's Tensile strength (also the Griffith test's).
    tension_cutoff = active() && tensile_strength > 0;
  }

  DruckerPrager::Strength
  DruckerPrager::strength(const double plastic_strain) const
  {
    // The weight of the softened values, linear in the plastic strain.
    double       w = 0, dw = 0;
    const double span = softening_end - softening_start;
    if (plastic_strain >= softening_end)
      w = 1;
    else if (plastic_strain > softening_start)
      {
        w  = (plastic_strain - softening_start) / span;
        dw = 1 / span;
      }
    const double phi  = friction + w * (softened_friction - friction);
    const double c    = cohesion + w * (softened_cohesion - cohesion);
    const double dphi = dw * (softened_friction - friction);
    const double dc   = dw * (softened_cohesion - cohesion);
    Strength     s;
    s.sin_friction    = std::sin(phi);
    s.cohesion_term   = c * std::cos(phi);
    s.d_sin_friction  = std::cos(phi) * dphi;
    s.d_cohesion_term = dc * std::cos(phi) - c * std::sin(phi) * dphi;
    return s;
  }
} // namespace lithostress

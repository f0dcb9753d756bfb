#include <deal.II/base/exceptions.h>

#include <lithostress/base/input_error.h>
#include <lithostress/analysis/griffith_failure.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

namespace lithostress
{
  namespace
  {
    /** @p x in the shortest decimal form that reads back exactly. */
    std::string
    number(const double x)
    {
      std::string text;
      for (int digits = 1; digits <= std::numeric_limits<double>::max_digits10;
           ++digits)
        {
          std::ostringstream out;
          out.precision(digits);
          out << x;
          text = out.str();
          if (std::strtod(text.c_str(), nullptr) == x)
            break;
        }
      return text;
    }
  } // namespace

  void
  GriffithFailure::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Griffith failure");
    prm.declare_entry(
      "Crack closure stress ratio",
      "-4.19",
      Patterns::Double(),
      "sigma_c/T: the stress that closes the Griffith cracks, as a multiple "
      "of each material's tensile strength T (tension positive, so "
      "negative). FAIL in the thesis listing uses -4.19; the thesis text "
      "quotes -10. Together with the crack friction mu_F it must satisfy "
      "mu_F^2 (1 - sigma_c/T) >= 1, or the failure envelope is "
      "discontinuous.");
    prm.declare_entry("Crack friction",
                      "1.0",
                      Patterns::Double(),
                      "mu_F: the coefficient of friction on closed Griffith "
                      "cracks, > 0. FAIL in the thesis listing uses 1.0; the "
                      "thesis text quotes 0.1, which with sigma_c/T = -10 "
                      "makes the failure envelope discontinuous.");
    prm.declare_entry(
      "Lithostatic pressure",
      "automatic",
      Patterns::Selection("automatic|added|not added"),
      "Whether the lithostatic stress -rho g depth of each point's own "
      "material is added to the principal stresses before the test, as FAIL "
      "does. automatic = added when the model has no full body force "
      "(gravity off, or densities stripped), since its stresses then lack "
      "the overburden.");
    prm.leave_subsection();
  }

  void
  GriffithFailure::parse_parameters(ParameterHandler   &prm,
                                    const GravityField &gravity_field)
  {
    prm.enter_subsection("Griffith failure");
    const double new_ratio    = prm.get_double("Crack closure stress ratio");
    const double new_friction = prm.get_double("Crack friction");
    lithostatic_choice        = prm.get("Lithostatic pressure");
    depth_origin              = gravity_field.depth_origin;
    gravity                   = gravity_field.acceleration;
    prm.leave_subsection();

    if (!(new_ratio < 0) || !std::isfinite(new_ratio))
      throw_input_error("Griffith failure/Crack closure stress ratio",
                        "sigma_c/T must be negative (cracks close under "
                        "compression; tension is positive), got " +
                          number(new_ratio));
    if (!(new_friction > 0) || !std::isfinite(new_friction))
      throw_input_error("Griffith failure/Crack friction",
                        "mu_F must be positive, got " + number(new_friction));
    // The intermediate regime σc − 2μF√(T(T − σc)) ≤ σm < σc − 2T exists,
    // and the envelope is continuous, only if μF²(1 − σc/T) ≥ 1
    // (doc/griffith.md).
    const double validity = new_friction * new_friction * (1.0 - new_ratio);
    if (!(validity >= 1.0))
      throw_input_error(
        "Griffith failure/Crack friction",
        "mu_F = " + number(new_friction) +
          " with Crack closure stress ratio sigma_c/T = " + number(new_ratio) +
          " gives mu_F^2 (1 - sigma_c/T) = " + number(validity) +
          " < 1: the intermediate regime is empty and the failure envelope "
          "jumps at sigma_m = sigma_c - 2T; use mu_F >= " +
          number(1.0 / std::sqrt(1.0 - new_ratio)) +
          " or a more negative sigma_c/T (see doc/griffith.md)");

    ratio    = new_ratio;
    friction = new_friction;
  }

  void
  GriffithFailure::resolve_lithostatic_pressure(const bool without_body_force)
  {
    add_lithostatic = lithostatic_choice == "added" ||
                      (lithostatic_choice == "automatic" && without_body_force);
  }

  double
  GriffithFailure::lithostatic_stress(const double density,
                                      const double y) const
  {
    if (!add_lithostatic)
      return 0.0;
    return -density * gravity * std::max(0.0, depth_origin - y);
  }

  std::array<double, 3>
  GriffithFailure::regime_boundaries(const double tensile_strength) const
  {
    const double T       = tensile_strength;
    const double sigma_c = ratio * T;
    // K = 2√(T(T − σc)) = 2T√(1 − σc/T) for T > 0.
    const double K = 2.0 * T * std::sqrt(1.0 - ratio);
    return {{-T, sigma_c - 2.0 * T, sigma_c - friction * K}};
  }

  GriffithFailure::Result
  GriffithFailure::evaluate(const double sigma_1,
                            const double sigma_2,
                            const double tensile_strength) const
  {
    AssertThrow(tensile_strength >= 0 && std::isfinite(tensile_strength),
                ExcMessage("GriffithFailure::evaluate: the tensile strength "
                           "must be finite and non-negative, got " +
                           number(tensile_strength)));
    Assert(std::isfinite(sigma_1) && std::isfinite(sigma_2),
           ExcMessage("GriffithFailure::evaluate: non-finite stress"));

    Result result;
    if (tensile_strength == 0)
      {
        result.regime            = Regime::not_tested;
        result.degree_of_failure = std::numeric_limits<double>::infinity();
        result.envelope          = std::numeric_limits<double>::infinity();
        result.fracture_angle    = 0;
        result.failed            = false;
        return result;
      }

    const double T       = tensile_strength;
    const double sigma_c = ratio * T;
    const double K       = 2.0 * T * std::sqrt(1.0 - ratio);
    const double s1      = std::max(sigma_1, sigma_2);
    const double s2      = std::min(sigma_1, sigma_2);
    const double sigma_m = 0.5 * (s1 + s2);
    const double tau_m   = 0.5 * (s1 - s2);

    const std::array<double, 3> boundary = regime_boundaries(T);

    if (sigma_m >= boundary[0])
      {
        result.regime         = Regime::tensile;
        result.fracture_angle = 0;
        if (sigma_m >= T)
          {
            // Every τm ≥ 0 fails; FAIL's measure of how far (IFAIL = −1).
            result.envelope          = 0;
            result.degree_of_failure = (T - sigma_m) / T;
          }
        else
          {
            result.envelope          = T - sigma_m;
            result.degree_of_failure = 1.0 - tau_m / result.envelope;
          }
      }
    else if (sigma_m >= boundary[1])
      {
        // σm ≤ −T < 0, and √(T/(−σm)) = −r/(2σm) ≤ 1 as in FAIL.
        result.regime            = Regime::open_crack_shear;
        result.envelope          = std::sqrt(-4.0 * T * sigma_m);
        result.degree_of_failure = 1.0 - tau_m / result.envelope;
        result.fracture_angle =
          0.5 * std::acos(std::min(1.0, std::sqrt(T / (-sigma_m))));
      }
    else if (sigma_m >= boundary[2])
      {
        // σc − σm > 2T > 0.
        const double x           = sigma_c - sigma_m;
        result.regime            = Regime::intermediate;
        result.envelope          = std::sqrt(x * x + K * K);
        result.degree_of_failure = 1.0 - tau_m / result.envelope;
        result.fracture_angle    = 0.5 * std::atan2(K, x);
      }
    else
      {
        const double x = sigma_c - sigma_m;
        result.regime  = Regime::closed_crack_shear;
        result.envelope =
          (friction * x + K) / std::sqrt(1.0 + friction * friction);
        result.degree_of_failure = 1.0 - tau_m / result.envelope;
        result.fracture_angle    = 0.5 * std::atan(1.0 / friction);
      }

    result.failed = (result.degree_of_failure <= 0);
    return result;
  }

  double
  GriffithFailure::closure_stress_ratio() const
  {
    return ratio;
  }

  double
  GriffithFailure::crack_friction() const
  {
    return friction;
  }

  std::string
  regime_name(const GriffithFailure::Regime regime)
  {
    switch (regime)
      {
      case GriffithFailure::Regime::tensile:
        return "tensile";
      case GriffithFailure::Regime::open_crack_shear:
        return "open crack shear";
      case GriffithFailure::Regime::intermediate:
        return "intermediate";
      case GriffithFailure::Regime::closed_crack_shear:
        return "closed crack shear";
      case GriffithFailure::Regime::not_tested:
        return "not tested";
      }
    return "unknown";
  }
} // namespace lithostress

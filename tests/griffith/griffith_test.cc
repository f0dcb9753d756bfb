// Unit test of the modified Griffith failure criterion (thesis §2.5.1,
// doc/griffith.md): continuity of the failure envelope at every regime
// boundary, hand-computed stress states, FAIL's algebraic forms, and the
// rejection of parameters that make the envelope discontinuous. Prints one
// "ok ..." or "FAIL ..." line per check and returns non-zero on a failure.

#include <deal.II/base/parameter_handler.h>

#include <lithostress/base/input_error.h>
#include <lithostress/analysis/griffith_failure.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace lithostress;
using Regime = GriffithFailure::Regime;

namespace
{
  unsigned int n_failed = 0;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok " : "FAIL ") << what << std::endl;
    if (!ok)
      ++n_failed;
  }

  std::string
  str(const double x)
  {
    std::ostringstream out;
    out.precision(std::numeric_limits<double>::max_digits10);
    out << x;
    return out.str();
  }

  bool
  agrees(const double a, const double b, const double tolerance)
  {
    return std::abs(a - b) <= tolerance;
  }

  /** A GriffithFailure read from a ParameterHandler with these entries. */
  GriffithFailure
  make(const double ratio, const double friction)
  {
    ParameterHandler prm;
    GriffithFailure::declare_parameters(prm);
    prm.parse_input_from_string("subsection Griffith failure\n"
                                "  set Crack closure stress ratio = " +
                                str(ratio) +
                                "\n"
                                "  set Crack friction = " +
                                str(friction) +
                                "\n"
                                "end\n");
    GriffithFailure griffith;
    griffith.parse_parameters(prm);
    return griffith;
  }

  /** The envelope r(σm): the τm at failure, from the state σ1 = σ2 = σm. */
  GriffithFailure::Result
  at_mean_stress(const GriffithFailure &griffith,
                 const double           sigma_m,
                 const double           T)
  {
    return griffith.evaluate(sigma_m, sigma_m, T);
  }

  /**
   * (a) Continuity of r(σm) and of the angle across the three boundaries,
   * and a scan showing that r is increasing with compression and
   * 1-Lipschitz (|r'| ≤ 1 in every regime, doc/griffith.md) over the whole
   * range: no jump anywhere.
   */
  void
  check_continuity(const double ratio, const double friction, const double T)
  {
    const std::string name = "sigma_c/T = " + str(ratio) +
                             ", mu_F = " + str(friction) + ", T = " + str(T);
    const GriffithFailure griffith = make(ratio, friction);

    // The boundaries, by hand (doc/griffith.md): −T, σc − 2T,
    // σc − 2μF√(T² − Tσc).
    const double sigma_c    = ratio * T;
    const double root       = std::sqrt(T * T - T * sigma_c);
    const double b[3]       = {-T,
                               sigma_c - 2.0 * T,
                               sigma_c - 2.0 * friction * root};
    const bool   degenerate = !(b[2] < b[1]); // μF²(1 − σc/T) = 1
    const std::array<double, 3> library = griffith.regime_boundaries(T);
    for (unsigned int k = 0; k < 3; ++k)
      check(agrees(library[k], b[k], 1e-12 * T * std::max(1.0, -b[k] / T)),
            name + ": boundary " + std::to_string(k) + " at sigma_m = " +
              str(library[k]) + " (by hand " + str(b[k]) + ")");

    const Regime above[3] = {Regime::tensile,
                             Regime::open_crack_shear,
                             degenerate ? Regime::open_crack_shear
                                        : Regime::intermediate};
    const Regime below[3] = {Regime::open_crack_shear,
                             degenerate ? Regime::closed_crack_shear
                                        : Regime::intermediate,
                             Regime::closed_crack_shear};
    // δ = 1e-11 T: the envelope's slope is at most 1, so a continuous r
    // changes by at most 2e-11 T across the probe. The angle is continuous
    // but, at σm = −T, behaves like ½√((−T − σm)/T): it changes by ~1.6e-6
    // there, hence its looser tolerance.
    const double delta = 1e-11 * T;
    for (unsigned int k = 0; k < 3; ++k)
      {
        const GriffithFailure::Result up =
          at_mean_stress(griffith, b[k] + delta, T);
        const GriffithFailure::Result down =
          at_mean_stress(griffith, b[k] - delta, T);
        const double jump = std::abs(up.envelope - down.envelope) / T;
        check(up.regime == above[k] && down.regime == below[k],
              name + ": regimes <" + regime_name(up.regime) + "> above and <" +
                regime_name(down.regime) + "> below boundary " +
                std::to_string(k));
        check(jump < 1e-9,
              name + ": envelope jump " + str(jump) + " T at boundary " +
                std::to_string(k) + " (r = " + str(up.envelope / T) + " T)");
        check(std::abs(up.fracture_angle - down.fracture_angle) < 1e-5,
              name + ": angle jump " +
                str(std::abs(up.fracture_angle - down.fracture_angle)) +
                " rad at boundary " + std::to_string(k));
      }

    // Scan σm from 0.999 T down to 10 T below the last boundary.
    const double       top    = 0.999 * T;
    const double       bottom = b[2] - 10.0 * T;
    const unsigned int n      = 20000;
    const double       h      = (top - bottom) / n;
    double worst_excess       = 0; // max(r(σm − h) − r(σm) − h, 0)/T
    bool   increasing         = true;
    double previous           = at_mean_stress(griffith, top, T).envelope;
    for (unsigned int i = 1; i <= n; ++i)
      {
        const double sigma_m = top - i * h;
        const double r       = at_mean_stress(griffith, sigma_m, T).envelope;
        increasing           = increasing && (r > previous);
        worst_excess         = std::max(worst_excess, (r - previous - h) / T);
        previous             = r;
      }
    check(increasing,
          name + ": r(sigma_m) increases with compression on the scan");
    check(worst_excess < 1e-9,
          name + ": r(sigma_m) is 1-Lipschitz on the scan (excess " +
            str(worst_excess) + " T)");
  }

  /**
   * (b) One stress state against hand-computed values (T = 1, or scaled).
   */
  void
  check_state(const GriffithFailure &griffith,
              const std::string     &name,
              const double           sigma_1,
              const double           sigma_2,
              const double           T,
              const Regime           regime,
              const double           C,
              const double           envelope,
              const double           angle,
              const bool             failed)
  {
    const GriffithFailure::Result result =
      griffith.evaluate(sigma_1, sigma_2, T);
    const bool ok =
      result.regime == regime && agrees(result.degree_of_failure, C, 1e-12) &&
      agrees(result.envelope, envelope, 1e-12 * T) &&
      agrees(result.fracture_angle, angle, 1e-12) && result.failed == failed;
    check(ok,
          name + ": regime <" + regime_name(result.regime) + "> (expected <" +
            regime_name(regime) + ">), C = " + str(result.degree_of_failure) +
            " (" + str(C) + "), r = " + str(result.envelope) + " (" +
            str(envelope) + "), angle = " + str(result.fracture_angle) + " (" +
            str(angle) + "), failed = " + std::to_string(result.failed));
  }

  void
  check_known_states()
  {
    const GriffithFailure griffith = make(-4.19, 1.0);
    const double          pi       = std::acos(-1.0);
    // Defaults, T = 1: σc = −4.19, K = 2√(T(T − σc)) = 2√5.19 = 4.55631...
    const double K = 2.0 * std::sqrt(5.19);

    // Uniaxial tension σ1 = T: σm = τm = T/2, tensile regime, r = T − σm =
    // T/2, C = 0: exactly at failure, which counts as failed.
    check_state(
      griffith, "uniaxial tension", 1, 0, 1, Regime::tensile, 0, 0.5, 0, true);
    // Pure shear σ1 = −σ2 = T: σm = 0, τm = T, tensile regime (σm ≥ −T),
    // r = T − 0 = T, C = 1 − T/T = 0: at failure (σ1 = T), failed.
    check_state(
      griffith, "pure shear tau = T", 1, -1, 1, Regime::tensile, 0, 1, 0, true);
    // Pure shear τm = T/2: r = T, C = 1/2, intact.
    check_state(griffith,
                "pure shear tau = T/2",
                0.5,
                -0.5,
                1,
                Regime::tensile,
                0.5,
                1,
                0,
                false);
    // σm = −T is the lower boundary of the tensile regime (as in FAIL):
    // τm = 1, r = T − σm = 2, C = 1/2.
    check_state(griffith,
                "sigma_m = -T, tau_m = T",
                0,
                -2,
                1,
                Regime::tensile,
                0.5,
                2,
                0,
                false);
    // σm = −2, τm = 1: open-crack shear (−6.19 ≤ σm < −1), r = √(−4Tσm) = √8,
    // C = 1 − 1/√8 = 0.646447, θ = ½ arccos(√(T/−σm)) = ½ arccos(1/√2) = π/8.
    check_state(griffith,
                "open crack shear",
                -1,
                -3,
                1,
                Regime::open_crack_shear,
                1 - 1 / std::sqrt(8.0),
                std::sqrt(8.0),
                pi / 8,
                false);
    // The same state with σ1 and σ2 given the other way round.
    check_state(griffith,
                "open crack shear, sigma_1 < sigma_2",
                -3,
                -1,
                1,
                Regime::open_crack_shear,
                1 - 1 / std::sqrt(8.0),
                std::sqrt(8.0),
                pi / 8,
                false);
    // σm = −7, τm = 2: intermediate (−8.7463 ≤ σm < −6.19),
    // r = √((σc − σm)² + 4T(T − σc)) = √(2.81² + 20.76) = 5.353139,
    // C = 1 − 2/r = 0.626387, θ = ½ arctan(K/2.81) = 0.509084 (29.17°).
    check_state(griffith,
                "intermediate",
                -5,
                -9,
                1,
                Regime::intermediate,
                1 - 2 / std::sqrt(2.81 * 2.81 + 20.76),
                std::sqrt(2.81 * 2.81 + 20.76),
                0.5 * std::atan(K / 2.81),
                false);
    // σm = −30, τm = 10: closed-crack shear (σm < −8.7463),
    // r = (μF(σc − σm) + K)/√(μF² + 1) = (25.81 + 4.556314)/√2 = 21.472227,
    // C = 1 − 10/r = 0.534282, θ = ½ arctan(1/μF) = π/8.
    check_state(griffith,
                "closed crack shear, intact",
                -20,
                -40,
                1,
                Regime::closed_crack_shear,
                1 - 10 / ((25.81 + K) / std::sqrt(2.0)),
                (25.81 + K) / std::sqrt(2.0),
                pi / 8,
                false);
    // σm = −40, τm = 30: r = (35.81 + 4.556314)/√2 = 28.543295,
    // C = 1 − 30/r = −0.051035: failed.
    check_state(griffith,
                "closed crack shear, failed",
                -10,
                -70,
                1,
                Regime::closed_crack_shear,
                1 - 30 / ((35.81 + K) / std::sqrt(2.0)),
                (35.81 + K) / std::sqrt(2.0),
                pi / 8,
                true);
    // The same, in Pa with T = 12 MPa: C and θ are scale-free, r scales.
    const double T = 12e6;
    check_state(griffith,
                "closed crack shear, failed, T = 12 MPa",
                -10 * T,
                -70 * T,
                T,
                Regime::closed_crack_shear,
                1 - 30 / ((35.81 + K) / std::sqrt(2.0)),
                T * (35.81 + K) / std::sqrt(2.0),
                pi / 8,
                true);
    // σm = 1.5 T ≥ T: every τm fails; FAIL's C = (T − σm)/T = −0.5, r = 0.
    check_state(
      griffith, "sigma_m beyond T", 2, 1, 1, Regime::tensile, -0.5, 0, 0, true);
    // Isotropic tension below T: τm = 0, C = 1.
    check_state(griffith,
                "isotropic tension T/2",
                0.5,
                0.5,
                1,
                Regime::tensile,
                1,
                0.5,
                0,
                false);

    // T = 0: not tested.
    const GriffithFailure::Result untested = griffith.evaluate(-5, -9, 0);
    check(untested.regime == Regime::not_tested && !untested.failed &&
            std::isinf(untested.degree_of_failure) &&
            untested.degree_of_failure > 0,
          "T = 0 is <" + regime_name(untested.regime) + ">, never failed");
    // T < 0: a caller error.
    bool thrown = false;
    try
      {
        griffith.evaluate(-5, -9, -1);
      }
    catch (const std::exception &)
      {
        thrown = true;
      }
    check(thrown, "T < 0 throws");

    check(regime_name(Regime::tensile) == "tensile" &&
            regime_name(Regime::open_crack_shear) == "open crack shear" &&
            regime_name(Regime::intermediate) == "intermediate" &&
            regime_name(Regime::closed_crack_shear) == "closed crack shear",
          "regime names");
  }

  /**
   * (b') Over a grid of states, C agrees with FAIL's own algebraic forms
   * (β = (2/μF)√(1 − σc/T) + σc/T, TC = βμF T − μF σc, α = √(1 + μF²)/μF),
   * and "failed" agrees with the failure condition as printed in the thesis
   * (§2.5.1) for the regime chosen. FAIL's intermediate/closed boundary SB is
   * not used (see doc/griffith.md: it has a sign error).
   */
  void
  check_against_fail(const double ratio, const double friction)
  {
    const std::string name =
      "sigma_c/T = " + str(ratio) + ", mu_F = " + str(friction);
    const GriffithFailure griffith = make(ratio, friction);
    const double          T        = 1;
    const double          SC       = ratio * T;
    const double          FMU      = friction;
    const double          BETA  = 2.0 / FMU * std::sqrt(1.0 - SC / T) + SC / T;
    const double          TC    = BETA * FMU * T - FMU * SC;
    const double          ALPHA = std::sqrt(1.0 + FMU * FMU) / FMU;

    double       worst_C    = 0; // relative to max(1, |C|)
    unsigned int mismatches = 0;
    unsigned int n_states   = 0;
    for (int i = 0; i <= 400; ++i)
      for (int j = 0; j <= 60; ++j)
        {
          // A state (σ1, σ3); SM and TB formed from it as FAIL forms them.
          const double S1 = (0.9 - i * 0.1) + j * 0.5; // σm down to −39.1 T
          const double S3 = (0.9 - i * 0.1) - j * 0.5; // τm up to 30 T
          const double SM = (S1 + S3) / 2.0;
          const double TB = (S1 - S3) / 2.0;
          const GriffithFailure::Result result = griffith.evaluate(S1, S3, T);
          double                        fail_C = 0;
          bool                          printed_failure = false;
          switch (result.regime)
            {
            case Regime::tensile:
              fail_C          = (T - S1) / (T - SM);
              printed_failure = TB >= T - SM;
              break;
            case Regime::open_crack_shear:
              fail_C          = 1.0 - TB / std::sqrt(-4.0 * T * SM);
              printed_failure = TB * TB >= -4.0 * T * SM;
              break;
            case Regime::intermediate:
              fail_C = 1.0 - TB / std::sqrt((SM - SC) * (SM - SC) + TC * TC);
              printed_failure =
                TB * TB >= (SC - SM) * (SC - SM) + 4.0 * T * (T - SC);
              break;
            case Regime::closed_crack_shear:
              fail_C = 1.0 - ALPHA * TB / (BETA * T - SM);
              printed_failure =
                TB >= (FMU * (SC - SM) + 2.0 * std::sqrt(T * T - T * SC)) /
                        std::sqrt(FMU * FMU + 1.0);
              break;
            case Regime::not_tested:
              break;
            }
          worst_C = std::max(worst_C,
                             std::abs(result.degree_of_failure - fail_C) /
                               std::max(1.0, std::abs(fail_C)));
          // Skip states within rounding of the envelope.
          if (std::abs(result.degree_of_failure) > 1e-9 &&
              result.failed != printed_failure)
            ++mismatches;
          ++n_states;
        }
    check(worst_C < 1e-12,
          name + ": C agrees with FAIL's formulas on " +
            std::to_string(n_states) + " states (worst relative difference " +
            str(worst_C) + ")");
    check(mismatches == 0,
          name + ": failed agrees with the printed failure conditions (" +
            std::to_string(mismatches) + " mismatches)");
  }

  /** (c) parse_parameters() accepts or rejects (σc/T, μF). */
  void
  check_parse(const double       ratio,
              const double       friction,
              const bool         valid,
              const std::string &entry)
  {
    const std::string name =
      "sigma_c/T = " + str(ratio) + ", mu_F = " + str(friction);
    try
      {
        const GriffithFailure griffith = make(ratio, friction);
        check(valid && griffith.closure_stress_ratio() == ratio &&
                griffith.crack_friction() == friction,
              name + (valid ? " accepted" : " accepted but should not be"));
      }
    catch (const InputError &e)
      {
        const std::string message = e.what();
        check(!valid && message.find(entry) != std::string::npos,
              name + " rejected: " + message);
      }
  }
} // namespace


int
main()
{
  try
    {
      // The defaults are FAIL's constants.
      {
        ParameterHandler prm;
        GriffithFailure::declare_parameters(prm);
        GriffithFailure griffith;
        griffith.parse_parameters(prm);
        check(griffith.closure_stress_ratio() == -4.19 &&
                griffith.crack_friction() == 1.0,
              "defaults sigma_c/T = -4.19, mu_F = 1.0");
      }

      // (a) Continuity for the defaults and a grid of valid pairs; the pair
      // (−3, 0.5) has μF²(1 − σc/T) = 1 exactly: the intermediate regime is
      // a point, and the envelope is still continuous.
      check_continuity(-4.19, 1.0, 1.0);
      check_continuity(-4.19, 1.0, 12e6);
      check_continuity(-4.19, 1.0, 50e6);
      check_continuity(-3, 0.5, 1.0);
      for (const double ratio : {-3.0, -4.19, -6.0, -10.0})
        for (const double friction : {0.6, 1.0, 1.5})
          if (friction * friction * (1.0 - ratio) >= 1.0)
            check_continuity(ratio, friction, 1.0);

      // (b) Known states, and FAIL's formulas.
      check_known_states();
      check_against_fail(-4.19, 1.0);
      check_against_fail(-10.0, 0.6);
      check_against_fail(-3.0, 1.5);

      // (c) The thesis text's σc = −10 T, μF = 0.1 (μF²(1 − σc/T) = 0.11):
      // the envelope would jump by 0.129 T (1.9 %) at σm = −12 T.
      check_parse(-10, 0.1, false, "Griffith failure/Crack friction");
      check_parse(-4.19, 0.1, false, "Griffith failure/Crack friction");
      check_parse(0, 1.0, false, "Griffith failure/Crack closure stress ratio");
      check_parse(0.5,
                  1.0,
                  false,
                  "Griffith failure/Crack closure stress ratio");
      check_parse(-4.19, 0, false, "Griffith failure/Crack friction");
      check_parse(-4.19, -1, false, "Griffith failure/Crack friction");
      check_parse(-3, 0.5, true, "");
      check_parse(-10, 0.6, true, "");
    }
  catch (const std::exception &e)
    {
      check(false, std::string("unexpected exception: ") + e.what());
    }

  std::cout << (n_failed == 0 ? "all checks passed"
                              : std::to_string(n_failed) + " checks failed")
            << std::endl;
  return n_failed == 0 ? 0 : 1;
}

#ifndef lithostress_analysis_griffith_failure_h
#define lithostress_analysis_griffith_failure_h

#include <deal.II/base/parameter_handler.h>

#include <lithostress/base/gravity_field.h>

#include <array>
#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * The modified Griffith failure criterion (thesis §2.5.1 and
   * subroutine FAIL), written down in doc/griffith.md.
   *
   * Tension is positive. From the in-plane principal stresses σ1 ≥ σ2 the
   * test forms σm = (σ1 + σ2)/2 and τm = (σ1 − σ2)/2 ≥ 0. With the tensile
   * strength T > 0, the crack-closure stress σc = (σc/T)·T < 0, the crack
   * friction μF > 0 and K = 2√(T(T − σc)), the failure envelope r(σm) (the
   * τm at which failure occurs for this σm) and the fracture angle θ are, as
   * in FAIL, chosen by σm alone (each regime includes its lower boundary):
   *
   * - tensile, σm ≥ −T: r = T − σm (0 when σm ≥ T), θ = 0;
   * - open-crack shear, σc − 2T ≤ σm < −T: r = √(−4Tσm),
   *   θ = ½ arccos(√(T/(−σm)));
   * - intermediate, σc − μF K ≤ σm < σc − 2T: r = √((σc − σm)² + K²),
   *   θ = ½ arctan(K/(σc − σm));
   * - closed-crack shear, σm < σc − μF K: r = (μF(σc − σm) + K)/√(μF² + 1),
   *   θ = ½ arctan(1/μF).
   *
   * The degree of failure is C = 1 − τm/r(σm) (C > 0 intact, C ≤ 0 failed),
   * except for σm ≥ T, where r ≤ 0 and FAIL's C = (T − σm)/T ≤ 0 is used.
   * θ is the angle between the fracture plane and the direction of σ2 (the
   * most compressive principal stress), evaluated, as in FAIL, on the
   * envelope at this σm: the orientation of the fracture that forms when the
   * stress state reaches failure.
   *
   * r(σm) is continuous (indeed continuously differentiable) at every regime
   * boundary if and only if μF²(1 − σc/T) ≥ 1, that is, if the intermediate
   * regime is not empty (at equality it shrinks to the point σc − 2T).
   * parse_parameters() rejects parameters that violate this (the thesis
   * text's σc = −10 T, μF = 0.1 do).
   */
  class GriffithFailure
  {
  public:
    /** The regimes of the criterion, from tension to deep compression. */
    enum class Regime
    {
      tensile,
      open_crack_shear,
      intermediate,
      closed_crack_shear,
      /** The material has tensile strength T = 0: it is not tested. */
      not_tested
    };

    /** The outcome of the test for one stress state. */
    struct Result
    {
      /** The regime selected by σm. */
      Regime regime = Regime::not_tested;
      /** The degree of failure C: > 0 intact, ≤ 0 failed. */
      double degree_of_failure = 0;
      /** r(σm), the τm at failure for this σm (≥ 0) [stress units]. */
      double envelope = 0;
      /**
       * The angle between the fracture plane and the direction of σ2
       * [radians, in [0, π/4)].
       */
      double fracture_angle = 0;
      /** Whether C ≤ 0. */
      bool failed = false;
    };

    /**
     * Declare the subsection `Griffith failure` with the entries `Crack
     * closure stress ratio` (σc/T, default −4.19) and `Crack friction` (μF,
     * default 1.0): FAIL's constants.
     */
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Read the subsection `Griffith failure`. Throws an InputError naming the
     * entry unless σc/T < 0, μF > 0 and μF²(1 − σc/T) ≥ 1 (continuous
     * envelope). The lithostatic pressure takes g and the depth origin of
     * @p gravity_field.
     */
    void
    parse_parameters(ParameterHandler   &prm,
                     const GravityField &gravity_field = GravityField());

    /**
     * Decide whether the lithostatic stress is added before the test
     * (`Lithostatic pressure`): with `automatic`, when
     * @p without_body_force — the model's stresses then lack the overburden
     * (no gravity, or densities stripped), and FAIL adds it.
     */
    void
    resolve_lithostatic_pressure(const bool without_body_force);

    /** Whether the lithostatic stress is added. */
    bool
    adds_lithostatic_pressure() const
    {
      return add_lithostatic;
    }

    /**
     * The lithostatic stress −ρ g max(0, y0 − y) [Pa] (compressive, tension
     * positive) at height @p y [m] in a material of density @p density, to
     * be added to σ1 and σ2 before evaluate(); 0 when not added.
     */
    double
    lithostatic_stress(const double density, const double y) const;

    /**
     * Test the stress state with in-plane principal stresses @p sigma_1 and
     * @p sigma_2 (in either order; tension positive) of a material with
     * tensile strength @p tensile_strength, in the same units. A tensile
     * strength of 0 means "not tested" (regime not_tested, C = +∞, envelope
     * +∞, angle 0, not failed); a negative or non-finite one is a caller
     * error (an exception is thrown).
     */
    Result
    evaluate(const double sigma_1,
             const double sigma_2,
             const double tensile_strength) const;

    /**
     * The values of σm at the three regime boundaries, from the top: −T
     * (tensile | open-crack shear), σc − 2T (open-crack shear |
     * intermediate) and σc − 2μF√(T(T − σc)) (intermediate | closed-crack
     * shear). Each regime includes its lower boundary. @p tensile_strength
     * must be positive.
     */
    std::array<double, 3>
    regime_boundaries(const double tensile_strength) const;

    /** σc/T. */
    double
    closure_stress_ratio() const;

    /** μF. */
    double
    crack_friction() const;

  private:
    /** σc/T < 0. */
    double ratio = -4.19;
    /** μF > 0. */
    double friction = 1.0;
    /** `Lithostatic pressure` as given, and its resolution. */
    std::string lithostatic_choice = "automatic";
    bool        add_lithostatic    = false;
    /** y of zero depth [m] and g [m s⁻²] of the lithostatic stress. */
    double depth_origin = 0, gravity = 9.81;
  };

  /**
   * The name of @p regime, as in the thesis: "tensile", "open crack shear",
   * "intermediate", "closed crack shear" or "not tested".
   */
  std::string
  regime_name(const GriffithFailure::Regime regime);
} // namespace lithostress

#endif

#ifndef lithostress_materials_drucker_prager_h
#define lithostress_materials_drucker_prager_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * The Drucker–Prager yield strength of a visco-elasto-plastic material
   * (doc/equations.md §13): yield where
   *   τ_II = C cos φ + P sin φ
   * (τ_II the second invariant of the 3-D deviatoric stress, P the pressure,
   * compression positive; the plane-strain form of Mohr–Coulomb that
   * continuum lithosphere codes use, e.g. ASPECT's `visco_plastic`), with
   * cohesion C and friction angle φ softening linearly with the
   * accumulated plastic strain ε_p between the two values of `Softening
   * plastic strain`; the plastic flow follows the potential
   * τ_II − P sin ψ (`Dilation angle` ψ, 0: incompressible flow), and the
   * mean stress is bounded by the material's `Tensile strength` where that
   * is positive (the entry the Griffith test reads too). Entries of a
   * material's subsection; Cohesion = Friction angle = 0 (the defaults)
   * switch plasticity off.
   */
  struct DruckerPrager
  {
    /** Declare the entries. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read them for material @p material (its subsection entered), whose
     * `Tensile strength` is @p tensile_strength (> 0: the cut-off);
     * throws InputError naming the entry. */
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &material,
                     const double       tensile_strength);

    /** Whether the material yields at all. */
    bool
    active() const
    {
      return cohesion > 0 || friction > 0;
    }

    /** Whether the return's consistent tangent is symmetric: associated
     * flow (ψ = φ) without softening. */
    bool
    symmetric_tangent() const
    {
      return !active() || (dilation == friction && !softens());
    }

    /** Whether C or φ change with the plastic strain. */
    bool
    softens() const
    {
      return softened_cohesion != cohesion || softened_friction != friction;
    }

    /** sin φ and C cos φ at plastic strain @p plastic_strain, and their
     * derivatives with respect to it. */
    struct Strength
    {
      double sin_friction = 0, cohesion_term = 0;
      double d_sin_friction = 0, d_cohesion_term = 0;

      /** τ_y = C cos φ + P sin φ at pressure @p pressure (not below 0:
       * the apex of the cone). */
      double
      at(const double pressure) const
      {
        const double tau = cohesion_term + pressure * sin_friction;
        return tau > 0 ? tau : 0.0;
      }
    };

    /** The strength parameters at accumulated plastic strain
     * @p plastic_strain. */
    Strength
    strength(const double plastic_strain) const;

    /** Cohesion [Pa] and friction angle [rad], before and after softening;
     * the softening interval of the plastic strain; the dilation angle
     * [rad]. */
    double cohesion = 0, friction = 0;
    double softened_cohesion = 0, softened_friction = 0;
    double softening_start = 0, softening_end = 0;
    double dilation = 0;
    /** Whether the mean stress −P is cut off at the tensile strength [Pa]
     * (a plastic material whose Tensile strength is positive). */
    bool   tension_cutoff   = false;
    double tensile_strength = 0;
  };
} // namespace lithostress

#endif

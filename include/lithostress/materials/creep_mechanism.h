#ifndef lithostress_materials_creep_mechanism_h
#define lithostress_materials_creep_mechanism_h

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * One temperature-activated creep mechanism in the invariant form of
   * doc/equations.md §12 (Goetze & Evans 1979; Hirth & Kohlstedt 2003):
   *   ε̇_II = A τ_II^n exp(−(E + P V)/(R T)),
   * with τ_II = √(½ τ:τ) and ε̇_II = √(½ ε̇:ε̇) the second invariants of the
   * 3-D deviatoric stress and creep strain rate, P the pressure
   * (compression positive), R = 8.314 J/(mol K). Its entries are
   * `<name> prefactor` [Pa⁻ⁿ s⁻¹], `<name> stress exponent`,
   * `<name> activation energy` [J/mol] and `<name> activation volume`
   * [m³/mol] of a material's subsection; a prefactor of 0 switches the
   * mechanism off.
   */
  struct CreepMechanism
  {
    /** The gas constant [J/(mol K)]. */
    static constexpr double gas_constant = 8.314;

    /** "Dislocation creep", "Diffusion creep". */
    std::string name;
    double      prefactor = 0, exponent = 1, activation_energy = 0,
           activation_volume = 0;

    /** Declare the four entries of mechanism @p name with the stress
     * exponent @p default_exponent. */
    static void
    declare_parameters(ParameterHandler  &prm,
                       const std::string &name,
                       const double       default_exponent);

    /** Read mechanism @p name of material @p material (its subsection
     * entered); throws InputError naming the entry (negative prefactor,
     * exponent below 1, negative activation energy). */
    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &name,
                     const std::string &material);

    /** Whether the mechanism acts (prefactor > 0). */
    bool
    active() const
    {
      return prefactor > 0;
    }

    /** Whether it depends on temperature (E or V nonzero). */
    bool
    activated() const
    {
      return active() && (activation_energy != 0 || activation_volume != 0);
    }

    /** A_T = A exp(−(E + P V)/(R T)) at temperature @p temperature [K] and
     * pressure @p pressure [Pa]: ε̇_II = A_T τ^n. */
    double
    rate_factor(const double temperature, const double pressure) const;
  };
} // namespace lithostress

#endif

#ifndef lithostress_materials_visco_elasto_plastic_rheology_h
#define lithostress_materials_visco_elasto_plastic_rheology_h

#include <lithostress/materials/creep_mechanism.h>
#include <lithostress/materials/drucker_prager.h>
#include <lithostress/materials/rheology.h>

#include <optional>

namespace lithostress
{
  /**
   * The visco-elasto-plastic lithosphere of doc/equations.md §12–13:
   * elasticity in series with a linear `Viscosity`, diffusion creep and
   * dislocation creep (CreepMechanism, each ε̇_II = A_T τ_II^n), which act
   * on the 3-D deviator s (σ_zz included) along s/τ_II,
   *   ε̇_II(τ) = τ/(2η) + A_T,diff τ^n_diff + A_T,disl τ^n_disl,
   * the effective viscosity τ/(2 ε̇_II) bounded by `Minimum viscosity` and
   * `Maximum viscosity`; and Drucker–Prager plasticity (DruckerPrager) that
   * caps τ_II at C cos φ + P sin φ. The history is the inelastic strain c
   * (CreepStrain, shared with MaxwellRheology; creep and plastic strain
   * together) and, with plasticity, the accumulated plastic strain ε_p.
   *
   * A step with history c* and weight w (CreepIntegrator) is a return
   * mapping from the trial state σ_tr = C (ε − c*) + σ_init: creep scales
   * the trial deviator to s = (τ/τ_tr) s_tr, τ the root of
   * τ + 2 G w Δt ε̇_II(τ) = τ_tr; where that τ exceeds the yield strength,
   * a plastic increment Δγ brings it back to the yield surface (with the
   * pressure change of dilation and the strength of ε_p + Δγ). The
   * consistent tangent is C_k = 2Gα P_dev + ŝ ⊗ (∂τ/∂ε − αG ŝ) − 1 ⊗ ∂P/∂ε
   * (α = τ/τ_tr, ŝ = s_tr/τ_tr): symmetric for creep and associated
   * plasticity without softening. The activation volume's pressure
   * dependence is left out of it. Plane strain only.
   * `Rheology = visco-elasto-plastic`.
   */
  template <int dim>
  class ViscoElastoPlasticRheology : public Rheology<dim>
  {
  public:
    /** The creep entries (CreepMechanism) and the viscosity bounds. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Throws InputError naming the entry: no mechanism at all, bounds in
     * the wrong order, plane stress. */
    void
    parse_parameters(ParameterHandler &prm,
                     const Material   &material,
                     const PlaneState  plane_state) override;

    /** The inelastic strain's xx, yy, xy and zz (2-D), and with
     * plasticity `plastic_strain`. */
    std::vector<std::string>
    history_names() const override;

    /** The norm of the 3-D inelastic-strain tensor. */
    double
    history_norm(const ArrayView<const double> &h) const override;

    const ElasticModuli<dim> &
    elastic_moduli() const override
    {
      return *elastic;
    }

    bool
    creeps() const override
    {
      return true;
    }

    bool
    uniform_tangent() const override
    {
      return false;
    }

    bool
    nonlinear() const override
    {
      return true;
    }

    bool
    needs_temperature() const override;

    /** False for non-associated plasticity or softening (DruckerPrager),
     * and for creep with an activation volume (the creep rate's pressure
     * derivative couples the deviator to the volume change): the linear
     * solvers then use GMRES. */
    bool
    symmetric_tangent() const override;

    /** η/G of the linear viscosity or of the Minimum viscosity; infinite
     * where neither is given (the stress sets the relaxation time). */
    double
    relaxation_time() const override;

    /** The elastic moduli: a step's tangent comes per point from
     * evaluate(). */
    const ElasticModuli<dim> &
    step_moduli() const override
    {
      return *elastic;
    }

    void
    set_time_step(const double, const double) override
    {
    }

    /** The brittle branch C cos φ + P sin φ with the intact rock's C and φ
     * (no plasticity: infinite) and the ductile τ with ε̇_II(τ) =
     * @p strain_rate (the mechanisms in series with their bounds; infinite
     * where they cannot reach it below 1e15 Pa). */
    StrengthEnvelope
    strength_envelope(const double temperature,
                      const double pressure,
                      const double strain_rate) const override;

    /** The stress of evaluate(). */
    StressState<dim>
    stress(const RheologyInputs<dim> &in) const override;

    /** The radial return of the class description, its tangent, the creep
     * rate at the step's end and the creep strain there. */
    void
    evaluate(const RheologyInputs<dim> &in,
             RheologyOutputs<dim>      &out) const override;

    /** The creep rate ε̇_II(τ) of the mechanisms in series, bounded by the
     * viscosity limits, at temperature @p temperature and pressure
     * @p pressure, and its derivative dε̇_II/dτ. */
    std::pair<double, double>
    flow(const double tau,
         const double temperature,
         const double pressure) const;

  private:
    /** The creep rate ε̇_II of flow() and its derivatives by τ and P. */
    struct FlowRate
    {
      double rate = 0, d_tau = 0, d_pressure = 0;
    };

    /** flow() with the pressure derivative: −V/(R T) times each
     * mechanism's rate, 0 where a viscosity bound holds the rate. */
    FlowRate
    flow_rate(const double tau,
              const double temperature,
              const double pressure) const;

    /** τ with τ + k ε̇_II(τ) = τ_tr (k = 2 G w Δt ≥ 0). */
    double
    return_stress(const double tau_trial,
                  const double k,
                  const double temperature,
                  const double pressure) const;

    /** The return of one point: the stress invariant, pressure and plastic
     * increment of the step, and their derivatives with respect to the
     * strain (in-plane) for the tangent. */
    struct Return
    {
      double tau = 0, pressure = 0, plastic_increment = 0;
      /** The volumetric plastic strain of the tension cut-off. */
      double tension_opening = 0;
      bool   yielding = false, tension = false;
      /** ∂τ/∂ε and ∂P/∂ε. */
      SymmetricTensor<2, dim> d_tau, d_pressure;
    };

    /** The return of a step from τ_tr and P_tr with trial direction ŝ
     * (in-plane part @p direction), history ε_p* = @p plastic_strain, at
     * @p temperature, with k = 2 G w Δt (0: a state, no return) and the
     * pressure @p extra_pressure added for the laws. */
    Return
    return_mapping(const double                   tau_trial,
                   const double                   pressure_trial,
                   const SymmetricTensor<2, dim> &direction,
                   const double                   plastic_strain,
                   const double                   temperature,
                   const double                   extra_pressure,
                   const double                   k) const;

    /** The plastic increment Δγ at the yield surface (with the pressure
     * @p pressure before dilation), and dτ/dΔγ there. */
    std::pair<double, double>
    plastic_increment(const double tau_trial,
                      const double pressure,
                      const double plastic_strain,
                      const double temperature,
                      const double k,
                      const bool   tension) const;

    double                            viscosity = 0, shear_modulus = 0;
    double                            bulk_modulus      = 0;
    double                            minimum_viscosity = 0;
    double                            maximum_viscosity = 0;
    CreepMechanism                    diffusion, dislocation;
    DruckerPrager                     plasticity;
    std::optional<ElasticModuli<dim>> elastic;
  };
} // namespace lithostress

#endif

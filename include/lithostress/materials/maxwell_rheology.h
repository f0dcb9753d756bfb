#ifndef lithostress_materials_maxwell_rheology_h
#define lithostress_materials_maxwell_rheology_h

#include <lithostress/materials/rheology.h>

#include <optional>

namespace lithostress
{
  /**
   * Maxwell visco-elasticity (thesis §2.6, §3.9): an elastic bulk response
   * and, on the 3-D deviator (σ_zz included), ė' = ṡ/(2G) + s/(2η). The
   * history is the deviatoric creep strain c (components xx, yy, xy, zz in
   * 2-D, CreepStrain); the stress is σ = K tr ε I + 2G (e − c) with e the
   * deviator of the total strain.
   *
   * In a step with history strain c* and weight w (CreepIntegrator's
   * schemes, doc/equations.md §10), c_{n+1} = c* + w Δt s_{n+1}/(2η) gives
   *   s_{n+1} = 2 G̃ (e_{n+1} − c*),   G̃ = G / (1 + w Δt G/η),
   * an elastic law with the relaxed ("algorithmic") shear modulus G̃, the
   * bulk modulus K unchanged, and the initial strain c*: one linear solve
   * per step, whose tangent is the same at every point of the material.
   * `Rheology = maxwell`, the default of a material with a viscosity.
   */
  template <int dim>
  class MaxwellRheology : public Rheology<dim>
  {
  public:
    /** No entries of its own: the viscosity is the material's. */
    static void
    declare_parameters(ParameterHandler &)
    {
    }

    /** Needs `Viscosity` > 0 (InputError naming it otherwise). */
    void
    parse_parameters(ParameterHandler &prm,
                     const Material   &material,
                     const PlaneState  plane_state) override;

    /** The creep strain's xx, yy, xy and zz (2-D). */
    std::vector<std::string>
    history_names() const override;

    /** The norm of the 3-D creep-strain tensor. */
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

    /** The Maxwell time η/G [s]. */
    double
    relaxation_time() const override
    {
      return viscosity / shear_modulus;
    }

    const ElasticModuli<dim> &
    step_moduli() const override
    {
      return *step;
    }

    /** K and G̃ = G/(1 + w Δt G/η). */
    void
    set_time_step(const double dt, const double weight) override;

    /** σ = C (ε − c*) + initial stress, C elastic or relaxed. */
    StressState<dim>
    stress(const RheologyInputs<dim> &in) const override;

    /** With ḣ = s/(2η) of that stress and h = c* + w Δt ḣ; the tangent is
     * the step's C, the effective viscosity η. */
    void
    evaluate(const RheologyInputs<dim> &in,
             RheologyOutputs<dim>      &out) const override;

  private:
    double                            viscosity = 0, shear_modulus = 0;
    double                            bulk_modulus = 0;
    PlaneState                        plane_state  = PlaneState::plane_strain;
    std::optional<ElasticModuli<dim>> elastic, step;
  };
} // namespace lithostress

#endif

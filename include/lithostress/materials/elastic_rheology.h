#ifndef lithostress_materials_elastic_rheology_h
#define lithostress_materials_elastic_rheology_h

#include <lithostress/materials/rheology.h>

#include <optional>

namespace lithostress
{
  /**
   * Isotropic linear elasticity (thesis §3.6): σ = C ε plus the loads'
   * initial stresses, in the model's plane state; no history. The law of a
   * material without a viscosity (`Rheology = elastic`).
   */
  template <int dim>
  class ElasticRheology : public Rheology<dim>
  {
  public:
    /** No entries of its own: E and ν are the material's. */
    static void
    declare_parameters(ParameterHandler &)
    {
    }

    void
    parse_parameters(ParameterHandler &prm,
                     const Material   &material,
                     const PlaneState  plane_state) override;

    const ElasticModuli<dim> &
    elastic_moduli() const override
    {
      return *moduli;
    }

    const ElasticModuli<dim> &
    step_moduli() const override
    {
      return *moduli;
    }

    void
    set_time_step(const double, const double) override
    {
    }

    StressState<dim>
    stress(const RheologyInputs<dim> &in) const override;

    void
    evaluate(const RheologyInputs<dim> &in,
             RheologyOutputs<dim>      &out) const override;

  private:
    std::optional<ElasticModuli<dim>> moduli;
  };
} // namespace lithostress

#endif

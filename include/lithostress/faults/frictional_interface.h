#ifndef lithostress_faults_frictional_interface_h
#define lithostress_faults_frictional_interface_h

#include <lithostress/faults/elastic_interface.h>

namespace lithostress
{
  /**
   * `Interface law = frictional`: the elastic law until the shear traction
   * reaches τ_F = μ max(0, −σ_n,eff), then Coulomb sliding (thesis §5.5,
   * FSHEAR; CoulombFriction's return mapping with its consistent tangent),
   * with σ_n,eff the model's normal traction less the overburden (ρ_l −
   * ρ_w) g d. Its history at a point is the accumulated slip p
   * ("plastic slip" [m]). Nonlinear: solved by FrictionalSlidingSolver.
   */
  template <int dim>
  class FrictionalInterface : public ElasticInterface<dim>
  {
  public:
    /** `Friction coefficient`, `Lithostatic density`, `Pore fluid
     * density`, `Overburden depth from` (the stiffnesses are the elastic
     * law's entries). */
    static void
    declare_parameters(ParameterHandler &prm);

    /** The stiffnesses and the friction; InputError naming the entry. */
    void
    parse_parameters(ParameterHandler   &prm,
                     const std::string  &fault,
                     const GravityField &gravity,
                     const double        length_scale) override;

    /** {"plastic slip"}. */
    std::vector<std::string>
    history_names() const override
    {
      return {"plastic slip"};
    }

    bool
    nonlinear() const override
    {
      return true;
    }

    bool
    overburden_from_sea_level() const override
    {
      return from_sea_level;
    }

    /** (ρ_l − ρ_w) g d. */
    double
    overburden(const double depth) const override
    {
      return this->friction.overburden(depth);
    }

    /** The return mapping from the history's slip (CoulombFriction). */
    InterfaceResponse
    evaluate(const InterfaceLawInputs &in) const override;

  private:
    /** Whether the overburden's depth is measured from y = 0. */
    bool from_sea_level = false;
  };
} // namespace lithostress

#endif

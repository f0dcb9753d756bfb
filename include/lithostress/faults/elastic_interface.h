#ifndef lithostress_faults_elastic_interface_h
#define lithostress_faults_elastic_interface_h

#include <lithostress/faults/coulomb_friction.h>
#include <lithostress/faults/interface_law.h>

namespace lithostress
{
  /**
   * `Interface law = elastic`: the traction K w with K = diag(k_s, k_n)
   * per unit fault area [Pa/m] in the fault's (shear, normal) frame
   * (thesis §5.4's fault element springs), or with `Normal stiffness =
   * exact` the shear spring alone and exact normal contact (the normal jump
   * held at zero by constraints whose reactions are the normal traction).
   * It never slides; FrictionalInterface adds Coulomb sliding to it. No
   * history.
   */
  template <int dim>
  class ElasticInterface : public InterfaceLaw<dim>
  {
  public:
    /** `Shear stiffness`, `Normal stiffness`, `Thesis element length`
     * (shared with FrictionalInterface). */
    static void
    declare_parameters(ParameterHandler &prm);

    /** The stiffnesses; InputError naming the entry. */
    void
    parse_parameters(ParameterHandler   &prm,
                     const std::string  &fault,
                     const GravityField &gravity,
                     const double        length_scale) override;

    bool
    has_face_terms() const override
    {
      return true;
    }

    bool
    exact_contact() const override
    {
      return friction.exact_contact;
    }

    /** diag(k_s, k_n), k_n = 0 in exact contact. */
    Tensor<2, 2>
    stuck_stiffness() const override;

    /** t_s = k_s (w_s − p), t_n = k_n w_n (0 in exact contact) with p the
     * history's slip (none: 0). */
    InterfaceResponse
    predictor(const InterfaceLawInputs &in) const override;

    /** The stuck response: K w (in exact contact the reaction as t_n). */
    InterfaceResponse
    evaluate(const InterfaceLawInputs &in) const override;

    /** The stiffnesses and (FrictionalInterface) the friction, as the
     * thesis's iteration and FSHEAR's element stresses read them (thesis
     * §5.5). */
    const CoulombFriction &
    coulomb() const
    {
      return friction;
    }

  protected:
    /** parse_parameters() of the law called @p law (for messages). */
    void
    parse_stiffnesses(ParameterHandler  &prm,
                      const std::string &fault,
                      const std::string &law,
                      const double       length_scale);

    /** CoulombFriction's return mapping at @p in from the slip @p p_old,
     * as an InterfaceResponse without history. */
    InterfaceResponse
    respond(const InterfaceLawInputs &in, const double p_old) const;

    /** k_s, k_n and whether the law slides; the friction's terms. */
    CoulombFriction friction;
  };
} // namespace lithostress

#endif

#ifndef lithostress_faults_coulomb_friction_h
#define lithostress_faults_coulomb_friction_h

#include <deal.II/base/tensor.h>

#include <lithostress/faults/interface_law.h>

#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * Coulomb friction on a fault as an elastic–perfectly-plastic interface
   * law (thesis §5.5 and FSHEAR), in the fault's local frame:
   * w = (w_s, w_n) the jump u(hanging wall) − u(footwall) along the shear
   * direction s and the normal n (from the footwall into the hanging wall),
   * p the accumulated (plastic) slip, a history variable. The model's
   * tractions are
   *
   *   t_n = k_n w_n,   t_s = k_s (w_s − p),
   *
   * and the friction sees the effective normal stress
   *   σ_n,eff = t_n − (ρ_l − ρ_w) g d
   * at depth d: the model's traction, plus an optional lithostatic term
   * (the thesis's ρ_l = 2911 kg m⁻³ where body forces are not in the model)
   * less an optional hydrostatic pore pressure (ρ_w = 1000 kg m⁻³).
   * The shear traction may not exceed τ_F = μ max(0, −σ_n,eff); a fault in
   * tension (σ_n,eff ≥ 0) carries no shear (FSHEAR's SNAV = 0), its normal
   * spring stays. respond() is the return mapping from the slip @p p_old of
   * the last converged state; its tangent is the consistent one
   * (non-symmetric while sliding: the limit depends on w_n).
   */
  struct CoulombFriction
  {
    /** k_s, k_n per unit fault area [Pa/m]. */
    double shear_stiffness = 0, normal_stiffness = 0;
    /** μ. */
    double friction_coefficient = 0.1;
    /** False for an elastic fault (Interface law = elastic): always stuck,
     * the traction K w whatever its size or sign. */
    bool slides = true;
    /** Exact normal contact (`Normal stiffness = exact`): no normal spring;
     * where the fault is closed its normal jump is zero, by constraints,
     * and t_n is their reaction (respond_in_contact()). */
    bool exact_contact = false;
    /** ρ_l and ρ_w [kg m⁻³] (0 = no such term) and g [m s⁻²]. */
    double lithostatic_density = 2911, pore_fluid_density = 1000,
           gravity = 9.81;

    /** The response at one point of the fault. */
    struct Response
    {
      /** t_s and the model's t_n [Pa]. */
      double shear_traction = 0, normal_traction = 0;
      /** σ_n,eff and τ_F [Pa]. */
      double effective_normal_stress = 0, friction_limit = 0;
      /** d(t_s, t_n)/d(w_s, w_n): index 0 = shear, 1 = normal. */
      Tensor<2, 2> tangent;
      /** The accumulated slip p after this response [m]. */
      double    plastic_slip = 0;
      SlipState state        = SlipState::stuck;
    };

    /** (ρ_l − ρ_w) g d: what the lithostatic load less the pore pressure
     * adds to the compression at depth @p depth [Pa]. */
    double
    overburden(const double depth) const
    {
      return (lithostatic_density - pore_fluid_density) * gravity * depth;
    }

    /** The response at a welded point (a buried tip, whose jump is held
     * at zero): stuck, with the stuck law's shear traction for the shear
     * jump @p w_s from the slip @p p_old and its tangent; no normal
     * traction (the weld's reaction is not the law's). */
    Response
    welded(const double w_s, const double p_old) const
    {
      Response r;
      r.shear_traction = shear_stiffness * (w_s - p_old);
      r.tangent[0][0]  = shear_stiffness;
      r.tangent[1][1]  = exact_contact ? 0. : normal_stiffness;
      r.plastic_slip   = p_old;
      return r;
    }

    /** The return mapping for the jump (@p w_s, @p w_n) at @p depth, from
     * the accumulated slip @p p_old. */
    Response
    respond(const double w_s,
            const double w_n,
            const double p_old,
            const double depth) const;

    /**
     * The return mapping in exact normal contact: at a @p closed point the
     * normal jump is held at zero and @p t_n is the normal traction that
     * holds it (the constraint's reaction); an open point carries no total
     * normal traction (its model traction t_n = (ρ_l − ρ_w) g d cancels the
     * overburden, so σ_n,eff = 0) and no shear. The tangent is the shear
     * part only: k_s while stuck, 0 while sliding or open (the friction
     * limit is taken at the given t_n).
     */
    Response
    respond_in_contact(const double w_s,
                       const double t_n,
                       const bool   closed,
                       const double p_old,
                       const double depth) const;

  private:
    /** A response with the model's normal traction @p t_n at @p depth:
     * σ_n,eff and τ_F. */
    Response
    with_normal_traction(const double t_n, const double depth) const;

    /** The return mapping of the shear from @p p_old at the jump @p w_s,
     * into @p r (which has τ_F): @p open (no shear, if the law slides),
     * stuck, or sliding at the limit, whose derivative by w_n is
     * @p limit_slope (μ k_n with the normal spring, 0 in exact contact,
     * where the limit is taken at the given reaction). */
    void
    return_map(Response    &r,
               const double w_s,
               const double p_old,
               const bool   open,
               const double limit_slope) const;
  };
} // namespace lithostress

#endif

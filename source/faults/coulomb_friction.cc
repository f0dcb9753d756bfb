#include <lithostress/faults/coulomb_friction.h>

#include <cmath>

namespace lithostress
{
  CoulombFriction::Response
  CoulombFriction::respond(const double w_s,
                           const double w_n,
                           const double p_old,
                           const double depth) const
  {
    Response r      = with_normal_traction(normal_stiffness * w_n, depth);
    r.tangent[1][1] = normal_stiffness;
    // In tension: no shear. The limit grows with compression:
    // dτ_F/dw_n = -μ k_n while sliding.
    return_map(r,
               w_s,
               p_old,
               r.effective_normal_stress >= 0,
               friction_coefficient * normal_stiffness);
    return r;
  }

  CoulombFriction::Response
  CoulombFriction::respond_in_contact(const double w_s,
                                      const double t_n,
                                      const bool   closed,
                                      const double p_old,
                                      const double depth) const
  {
    Response r = with_normal_traction(closed ? t_n : overburden(depth), depth);
    return_map(r, w_s, p_old, !closed || r.effective_normal_stress >= 0, 0);
    return r;
  }

  CoulombFriction::Response
  CoulombFriction::with_normal_traction(const double t_n,
                                        const double depth) const
  {
    Response r;
    r.normal_traction         = t_n;
    r.effective_normal_stress = t_n - overburden(depth);
    r.friction_limit =
      friction_coefficient * std::max(0.0, -r.effective_normal_stress);
    return r;
  }

  void
  CoulombFriction::return_map(Response    &r,
                              const double w_s,
                              const double p_old,
                              const bool   open,
                              const double limit_slope) const
  {
    const double trial_s = shear_stiffness * (w_s - p_old);
    if (slides && open)
      {
        // No shear; the slip follows the jump.
        r.state          = SlipState::open;
        r.shear_traction = 0;
        r.plastic_slip   = w_s;
      }
    else if (!slides || std::abs(trial_s) <= r.friction_limit)
      {
        r.state          = SlipState::stuck;
        r.shear_traction = trial_s;
        r.plastic_slip   = p_old;
        r.tangent[0][0]  = shear_stiffness;
      }
    else
      {
        // Back to the limit in the trial's direction.
        const double sign = trial_s > 0 ? 1. : -1.;
        r.state           = SlipState::sliding;
        r.shear_traction  = sign * r.friction_limit;
        r.plastic_slip    = w_s - r.shear_traction / shear_stiffness;
        r.tangent[0][1]   = -sign * limit_slope;
      }
  }
} // namespace lithostress

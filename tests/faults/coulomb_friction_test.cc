// Unit test of the Coulomb friction law of a fault point (thesis §5.5 and
// FSHEAR; doc/faults.md): the return mapping in each state (stuck, sliding,
// open, and the elastic law that never slides), the consistency of the
// returned slip with the traction, continuity of the traction where the
// state changes, and the consistent tangent against central differences.
// Prints one "ok ..." or "FAIL ..." line per check and returns non-zero on
// a failure.

#include <lithostress/faults/coulomb_friction.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace lithostress;

namespace
{
  unsigned int n_failed = 0;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok " : "FAIL ") << what << std::endl;
    if (!ok)
      ++n_failed;
  }

  /** |a − b| ≤ tol · max(|b|, scale). */
  bool
  close(const double a, const double b, const double tol, const double scale)
  {
    return std::abs(a - b) <= tol * std::max(std::abs(b), scale);
  }

  /** The thesis's plane normal fault: k_s = 5e10 N/m and k_n = 1e15 N/m
   * per 11.18 km element, μ = 0.1, FSHEAR's 2911 and 1000 kg/m³. */
  CoulombFriction
  thesis_law()
  {
    CoulombFriction law;
    law.shear_stiffness      = 5e10 / 11.18e3;
    law.normal_stiffness     = 1e15 / 11.18e3;
    law.friction_coefficient = 0.1;
    return law;
  }

  /** The tangent by central differences of step h in w_s and w_n. */
  Tensor<2, 2>
  difference_tangent(const CoulombFriction &law,
                     const double           w_s,
                     const double           w_n,
                     const double           p_old,
                     const double           depth,
                     const double           h)
  {
    Tensor<2, 2> d;
    for (unsigned int j = 0; j < 2; ++j)
      {
        const double dws = j == 0 ? h : 0, dwn = j == 1 ? h : 0;
        const auto   plus  = law.respond(w_s + dws, w_n + dwn, p_old, depth);
        const auto   minus = law.respond(w_s - dws, w_n - dwn, p_old, depth);
        d[0][j] = (plus.shear_traction - minus.shear_traction) / (2 * h);
        d[1][j] = (plus.normal_traction - minus.normal_traction) / (2 * h);
      }
    return d;
  }

  /** The returned tangent equals the differences (the law is piecewise
   * linear in w away from the state boundaries: exact up to round-off). */
  void
  check_tangent(const CoulombFriction &law,
                const double           w_s,
                const double           w_n,
                const double           p_old,
                const double           depth,
                const std::string     &where)
  {
    const auto         r = law.respond(w_s, w_n, p_old, depth);
    const Tensor<2, 2> d =
      difference_tangent(law, w_s, w_n, p_old, depth, 1e-9);
    const double scale = law.normal_stiffness;
    bool         ok    = true;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        ok = ok && std::abs(r.tangent[i][j] - d[i][j]) <= 1e-6 * scale;
    check(ok, "consistent tangent " + where);
  }
} // namespace

int
main()
{
  const CoulombFriction law   = thesis_law();
  const double          depth = 10e3;
  // The overburden (ρ_l − ρ_w) g d = 1911 · 9.81 · 10 km = 187.5 MPa.
  const double overburden = law.overburden(depth);
  check(close(overburden, 1911 * 9.81 * 10e3, 1e-15, 1),
        "overburden (rho_l - rho_w) g d");

  // Stuck: a small shear jump under compression keeps the slip.
  const double w_n = -1e5 / law.normal_stiffness; // t_n = −0.1 MPa
  {
    const double p_old = 0.5;
    const double w_s   = p_old + 1e6 / law.shear_stiffness; // τ = 1 MPa
    const auto   r     = law.respond(w_s, w_n, p_old, depth);
    check(r.state == SlipState::stuck, "stuck below the friction limit");
    check(close(r.shear_traction, 1e6, 1e-12, 1), "stuck: t_s = k_s (w_s - p)");
    check(close(r.normal_traction, -1e5, 1e-12, 1), "stuck: t_n = k_n w_n");
    check(r.plastic_slip == p_old, "stuck: the slip stays");
    check(close(r.friction_limit, 0.1 * (1e5 + overburden), 1e-12, 1),
          "friction limit mu |sigma_n,eff|");
    check_tangent(law, w_s, w_n, p_old, depth, "(stuck)");
  }

  // Sliding: the traction returns to the limit, and the slip makes the
  // elastic part carry exactly that traction.
  for (const double sign : {1.0, -1.0})
    {
      const double      p_old = 0.2;
      const double      w_s   = p_old + sign * 1e8 / law.shear_stiffness;
      const auto        r     = law.respond(w_s, w_n, p_old, depth);
      const double      limit = 0.1 * (1e5 + overburden);
      const std::string s =
        sign > 0 ? " (positive shear)" : " (negative shear)";
      check(r.state == SlipState::sliding, "sliding above the limit" + s);
      check(close(r.shear_traction, sign * limit, 1e-12, 1),
            "sliding: |t_s| = tau_F" + s);
      check(close(law.shear_stiffness * (w_s - r.plastic_slip),
                  r.shear_traction,
                  1e-9,
                  1),
            "sliding: k_s (w_s - p_new) = t_s" + s);
      check(sign * (r.plastic_slip - p_old) > 0,
            "sliding: the slip grows in the direction of the shear" + s);
      check_tangent(law, w_s, w_n, p_old, depth, "(sliding" + s + ")");
    }

  // Open: in net tension the fault carries no shear and the slip follows
  // the jump.
  {
    const double w_open = (overburden + 1e6) / law.normal_stiffness;
    const auto   r      = law.respond(0.3, w_open, 0.1, depth);
    check(r.state == SlipState::open, "open in net tension");
    check(r.shear_traction == 0, "open: no shear traction");
    check(r.plastic_slip == 0.3, "open: the slip follows the jump");
    check_tangent(law, 0.3, w_open, 0.1, depth, "(open)");
  }

  // The traction is continuous where stuck turns into sliding: just below
  // and just above the limit it differs by the jump's step only.
  {
    const double limit = 0.1 * (1e5 + overburden);
    const double w_at  = limit / law.shear_stiffness;
    const double eps   = 1e-9 * w_at;
    const auto   below = law.respond(w_at - eps, w_n, 0, depth);
    const auto   above = law.respond(w_at + eps, w_n, 0, depth);
    check(below.state == SlipState::stuck && above.state == SlipState::sliding,
          "stuck below and sliding above the limit");
    check(close(below.shear_traction, above.shear_traction, 1e-8, 1),
          "traction continuous from stuck to sliding");
  }

  // The elastic law never slides or opens: t = K w for any jump.
  {
    CoulombFriction elastic = law;
    elastic.slides          = false;
    const auto r            = elastic.respond(3.0, 1e-3, 0, depth);
    check(r.state == SlipState::stuck, "elastic law: always stuck");
    check(close(r.shear_traction, 3.0 * elastic.shear_stiffness, 1e-15, 1),
          "elastic law: t_s = k_s w_s");
    check_tangent(elastic, 3.0, 1e-3, 0, depth, "(elastic law)");
  }

  std::cout << (n_failed == 0 ? "all checks passed"
                              : std::to_string(n_failed) + " check(s) failed")
            << std::endl;
  return n_failed == 0 ? 0 : 1;
}

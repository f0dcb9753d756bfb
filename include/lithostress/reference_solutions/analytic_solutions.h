#ifndef lithostress_reference_solutions_analytic_solutions_h
#define lithostress_reference_solutions_analytic_solutions_h

#include <lithostress/reference_solutions/reference_solution.h>

namespace lithostress
{
  /**
   * The lithostatic column of thesis §4.4: a laterally confined layer under
   * gravity, top at y_t, base at y_b fixed vertically. σ_yy = ρ g (y − y_t),
   * σ_xx = λ/(λ + 2μ) σ_yy (ν/(1 − ν) σ_yy in plane strain) and
   * u_y = ρ g ((y − y_t)² − H²) / 2(λ + 2μ); the top subsides 12.71 m for the
   * thesis data. Uses the first material of `Materials/Names`.
   */
  template <int dim>
  class LithostaticColumn : public ReferenceSolution<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &,
                     const MaterialLibrary &,
                     const PlaneState,
                     const double) override;
    Tensor<1, dim>
    displacement(const Point<dim> &p) const override;
    SymmetricTensor<2, dim>
    stress(const Point<dim> &p) const override;

  private:
    double top, base, rho_g, lateral_ratio, p_modulus;
  };

  /**
   * The end-loaded cantilever of Timoshenko & Goodier (1970, §21), thesis
   * §4.3, with y up: x ∈ [0, l], y ∈ [−c, c], a downward end load P at
   * x = 0 carried by a parabolic shear traction, and the support at x = l
   * that fixes u = v = 0 and ∂v/∂x = 0 at (l, 0) (horizontal element of the
   * neutral fibre clamped). Plane stress as printed; plane strain with
   * E' = E/(1 − ν²), ν' = ν/(1 − ν). Uses the first material.
   */
  template <int dim>
  class TimoshenkoCantilever : public ReferenceSolution<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &,
                     const MaterialLibrary &,
                     const PlaneState,
                     const double) override;
    Tensor<1, dim>
    displacement(const Point<dim> &p) const override;
    SymmetricTensor<2, dim>
    stress(const Point<dim> &p) const override;

  private:
    double P, l, c, E, nu, G, I;
  };

  /**
   * Lamé's thick-walled cylinder a ≤ r ≤ b under internal pressure p, with
   * an optional bonded outer shell b ≤ r ≤ b + t of another material and a
   * free outer surface: u_r = A_i r + B_i / r in each layer, the four
   * constants from σ_rr(a) = −p, continuity of u_r and σ_rr at b and
   * σ_rr(b + t) = 0. The body is the first material of `Materials/Names`,
   * the shell the second.
   */
  template <int dim>
  class LameCylinder : public ReferenceSolution<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &,
                     const MaterialLibrary &,
                     const PlaneState,
                     const double) override;
    Tensor<1, dim>
    displacement(const Point<dim> &p) const override;
    SymmetricTensor<2, dim>
    stress(const Point<dim> &p) const override;

  private:
    double a, b, t;
    /** Per layer: A, B, in-plane λ, μ. */
    double A[2], B[2], lambda[2], mu[2];
  };

  /**
   * The mode-I Williams eigen-solution at the re-entrant corner of the
   * L-shaped domain (material wedge of opening 2ω = 3π/2 centred on the
   * direction 225°): u = A r^λ/(2G) (...), σ ∝ r^{λ−1}, λ = 0.5444837 the
   * smallest root of sin(2λω) + λ sin 2ω = 0 (Szabó & Babuška 1991, §
   * "Linear elasticity", eqs. for the symmetric mode). Traction-free on the
   * notch faces; prescribed on the outer boundary it makes an exact
   * singular solution with u ∈ H^{1+λ}. Uses the first material.
   */
  template <int dim>
  class WilliamsCornerSolution : public ReferenceSolution<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &,
                     const MaterialLibrary &,
                     const PlaneState,
                     const double) override;
    Tensor<1, dim>
    displacement(const Point<dim> &p) const override;
    SymmetricTensor<2, dim>
    stress(const Point<dim> &p) const override;

    /** The exponent λ. */
    double
    exponent() const
    {
      return lambda;
    }

  private:
    /** Local polar coordinates about the corner, θ from the bisector. */
    void
    local_coordinates(const Point<dim> &p, double &r, double &theta) const;

    double amplitude, lambda, omega, Q, kappa, G;
  };
} // namespace lithostress

#endif

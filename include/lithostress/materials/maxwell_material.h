#ifndef lithostress_materials_maxwell_material_h
#define lithostress_materials_maxwell_material_h

#include <deal.II/base/symmetric_tensor.h>

#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/material.h>

namespace lithostress
{
  using namespace dealii;

  /**
   * Maxwell visco-elasticity of one material (thesis §2.6, §3.9):
   * an elastic bulk response and, on the 3-D deviator (σ_zz included),
   * ė' = ṡ/(2G) + s/(2η). The creep strain c is deviatoric; the stress is
   * σ = K tr ε I + 2G (e − c) with e the deviator of the total strain.
   *
   * Time-discrete with the generalised midpoint rule (doc/equations.md):
   *   c_{n+1} = c_n + Δt [(1 − θ) s_n + θ s_{n+1}] / (2η),
   * which with the history strain c* = c_n + (1 − θ) Δt s_n/(2η) gives
   *   s_{n+1} = 2 G̃ (e_{n+1} − c*),   G̃ = G / (1 + θ Δt G/η),
   * an elastic law with the relaxed ("algorithmic") shear modulus G̃, the
   * bulk modulus K unchanged, and the initial strain c*: one linear solve
   * per step. θ = 1 is backward Euler (first order, L-stable), θ = 1/2 the
   * trapezoidal rule (second order, A-stable).
   */
  template <int dim>
  class MaxwellMaterial
  {
  public:
    MaxwellMaterial(const Material &material, const PlaneState plane_state);

    /** Whether the material creeps (η > 0). */
    bool
    is_viscous() const
    {
      return viscosity > 0;
    }

    /** The Maxwell relaxation time η/G [s]; 0 for an elastic material. */
    double
    maxwell_time() const
    {
      return is_viscous() ? viscosity / shear_modulus : 0.0;
    }

    /** The moduli of a step of length @p dt with weight @p theta: K and
     * G̃ = G/(1 + θ Δt G/η); the elastic moduli if dt = 0 or η = 0. */
    ElasticModuli<dim>
    step_moduli(const double dt, const double theta) const;

    /** The creep-strain rate s/(2η) for the 3-D stress @p stress (only its
     * deviator creeps); zero for an elastic material. */
    SymmetricTensor<2, 3>
    creep_rate(const SymmetricTensor<2, 3> &stress) const;

  private:
    double     viscosity, shear_modulus, bulk_modulus;
    PlaneState plane_state;
  };
} // namespace lithostress

#endif

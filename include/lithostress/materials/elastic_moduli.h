#ifndef lithostress_materials_elastic_moduli_h
#define lithostress_materials_elastic_moduli_h

#include <deal.II/base/symmetric_tensor.h>

#include <lithostress/materials/material.h>

#include <string>
#include <utility>

namespace lithostress
{
  /**
   * The 2-D idealisation of the third direction (thesis card NST):
   * plane strain (ε_zz = 0, σ_zz reported) or plane stress (σ_zz = 0).
   */
  enum class PlaneState
  {
    plane_strain,
    plane_stress
  };

  /**
   * Lamé parameters of the in-plane law σ = λ tr(ε) I + 2 μ ε at one point:
   * λ is the plane-state λ (λ* = 2λμ/(λ + 2μ) in plane stress, thesis
   * §3.6.2). What the stiffness kernels need, per cell or per quadrature point.
   */
  struct LameParameters
  {
    double lambda = 0;
    double mu     = 0;
  };

  /** Parse "plane strain" / "plane stress". */
  PlaneState
  parse_plane_state(const std::string &text);

  /**
   * Isotropic linear elasticity of one material in the chosen plane state
   * (thesis §3.6.2): the in-plane stiffness tensor, its inverse, and the
   * out-of-plane stress σ_zz. In plane stress the in-plane law is the 3-D
   * law with λ replaced by λ* = 2λμ/(λ + 2μ).
   */
  template <int dim>
  class ElasticModuli
  {
  public:
    ElasticModuli(const Material &material, const PlaneState plane_state);

    /** The moduli with 3-D Lamé parameters @p lambda_3d and @p mu (the
     * relaxed moduli of a Maxwell time step, MaxwellRheology). */
    ElasticModuli(const double     lambda_3d,
                  const double     mu,
                  const PlaneState plane_state);

    /** The in-plane stiffness C: σ = C ε. */
    const SymmetricTensor<4, dim> &
    stiffness() const
    {
      return C;
    }

    /** The in-plane compliance C⁻¹: ε = C⁻¹ σ. */
    SymmetricTensor<4, dim>
    compliance() const;

    /** σ = C ε. */
    SymmetricTensor<2, dim>
    stress(const SymmetricTensor<2, dim> &strain) const
    {
      return C * strain;
    }

    /** σ_zz for in-plane strain @p strain: λ tr ε (plane strain), 0 (plane
     * stress). */
    double
    sigma_zz(const SymmetricTensor<2, dim> &strain) const;

    /**
     * The stress of an isotropic 3-D initial strain ε0 I (thermal expansion,
     * thesis §3.8) when the total strain is zero: σ = −C ε0. Returns the
     * in-plane diagonal value and σ_zz: −(3λ + 2μ) ε0 for both in plane
     * strain (ε_zz = 0), −E/(1 − ν) ε0 and 0 in plane stress (σ_zz = 0, free
     * expansion in z).
     */
    std::pair<double, double>
    isotropic_initial_strain_stress(const double initial_strain) const;

    /**
     * The stress −C ε0 of a general 3-D initial strain @p initial_strain
     * (a creep strain) when the in-plane strain is zero: the in-plane part
     * and σ_zz. Plane strain keeps ε_zz = 0; plane stress lets ε_zz adjust
     * so that σ_zz = 0, which adds λ δε_zz to the in-plane diagonal.
     */
    std::pair<SymmetricTensor<2, dim>, double>
    initial_strain_stress(const SymmetricTensor<2, 3> &initial_strain) const;

    /** The in-plane Lamé parameters (λ_in_plane, μ). */
    LameParameters
    lame_parameters() const
    {
      return {lambda_in_plane, mu};
    }

    /** Effective in-plane Lamé λ (λ or λ*) and μ. */
    double lambda_in_plane, mu;

    /** 3-D λ (σ_zz in plane strain). */
    double lambda_3d;

    PlaneState plane_state;

  private:
    SymmetricTensor<4, dim> C;
  };
} // namespace lithostress

#endif

#include <lithostress/base/input_error.h>
#include <lithostress/materials/elastic_moduli.h>

namespace lithostress
{
  PlaneState
  parse_plane_state(const std::string &text)
  {
    if (text == "plane strain")
      return PlaneState::plane_strain;
    if (text == "plane stress")
      return PlaneState::plane_stress;
    throw_input_error("Plane state",
                      "<" + text +
                        "> is neither plane strain nor plane stress");
  }

  template <int dim>
  ElasticModuli<dim>::ElasticModuli(const Material  &material,
                                    const PlaneState plane_state)
      : ElasticModuli(material.lame_lambda(),
                      material.shear_modulus(),
                      plane_state)
  {
  }

  template <int dim>
  ElasticModuli<dim>::ElasticModuli(const double     lambda_3d,
                                    const double     mu,
                                    const PlaneState plane_state)
      : mu(mu)
      , lambda_3d(lambda_3d)
      , plane_state(plane_state)
  {
    lambda_in_plane = (plane_state == PlaneState::plane_strain || dim == 3)
                        ? lambda_3d
                        : 2.0 * lambda_3d * mu / (lambda_3d + 2.0 * mu);
    const SymmetricTensor<2, dim> I = unit_symmetric_tensor<dim>();
    C =
      lambda_in_plane * outer_product(I, I) + 2.0 * mu * identity_tensor<dim>();
  }

  template <int dim>
  SymmetricTensor<4, dim>
  ElasticModuli<dim>::compliance() const
  {
    // Inverse of λ I⊗I + 2μ 𝕀 is (1/2μ)(𝕀 − λ/(dim λ + 2μ) I⊗I).
    const SymmetricTensor<2, dim> I = unit_symmetric_tensor<dim>();
    return (1.0 / (2.0 * mu)) *
           (identity_tensor<dim>() - lambda_in_plane /
                                       (dim * lambda_in_plane + 2.0 * mu) *
                                       outer_product(I, I));
  }

  template <int dim>
  double
  ElasticModuli<dim>::sigma_zz(const SymmetricTensor<2, dim> &strain) const
  {
    if (plane_state == PlaneState::plane_stress || dim == 3)
      return 0.0;
    return lambda_3d * trace(strain);
  }

  template <int dim>
  std::pair<double, double>
  ElasticModuli<dim>::isotropic_initial_strain_stress(
    const double initial_strain) const
  {
    const double bulk3 = 3.0 * lambda_3d + 2.0 * mu; // 3K
    if (plane_state == PlaneState::plane_stress && dim == 2)
      // E/(1 − ν) = 2(λ* + μ) = 2μ(3λ + 2μ)/(λ + 2μ).
      return {-2.0 * mu * bulk3 / (lambda_3d + 2.0 * mu) * initial_strain, 0.0};
    return {-bulk3 * initial_strain, -bulk3 * initial_strain};
  }

  template <int dim>
  std::pair<SymmetricTensor<2, dim>, double>
  ElasticModuli<dim>::initial_strain_stress(
    const SymmetricTensor<2, 3> &initial_strain) const
  {
    // The 3-D stress −(λ tr ε0 I + 2μ ε0) at zero total strain.
    const double            volumetric = lambda_3d * trace(initial_strain);
    SymmetricTensor<2, dim> in_plane;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        in_plane[i][j] =
          -2.0 * mu * initial_strain[i][j] - (i == j ? volumetric : 0.0);
    double zz = -2.0 * mu * initial_strain[2][2] - volumetric;
    if (plane_state == PlaneState::plane_stress && dim == 2)
      {
        // ε_zz = −σ_zz/(λ + 2μ) removes σ_zz and adds λ ε_zz in plane.
        const double strain_zz = -zz / (lambda_3d + 2.0 * mu);
        for (unsigned int i = 0; i < dim; ++i)
          in_plane[i][i] += lambda_3d * strain_zz;
        zz = 0;
      }
    return {in_plane, zz};
  }

  template class ElasticModuli<2>;
  template class ElasticModuli<3>;
} // namespace lithostress

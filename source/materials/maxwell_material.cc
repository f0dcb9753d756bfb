#include <lithostress/materials/maxwell_material.h>

namespace lithostress
{
  template <int dim>
  MaxwellMaterial<dim>::MaxwellMaterial(const Material  &material,
                                        const PlaneState plane_state)
      : viscosity(material.viscosity)
      , shear_modulus(material.shear_modulus())
      , bulk_modulus(material.lame_lambda() + 2.0 / 3.0 * shear_modulus)
      , plane_state(plane_state)
  {
  }

  template <int dim>
  ElasticModuli<dim>
  MaxwellMaterial<dim>::step_moduli(const double dt, const double theta) const
  {
    const double relaxed =
      is_viscous() ? shear_modulus / (1.0 + theta * dt / maxwell_time())
                   : shear_modulus;
    return ElasticModuli<dim>(bulk_modulus - 2.0 / 3.0 * relaxed,
                              relaxed,
                              plane_state);
  }

  template <int dim>
  SymmetricTensor<2, 3>
  MaxwellMaterial<dim>::creep_rate(const SymmetricTensor<2, 3> &stress) const
  {
    if (!is_viscous())
      return SymmetricTensor<2, 3>();
    return deviator(stress) / (2.0 * viscosity);
  }

  template class MaxwellMaterial<2>;
} // namespace lithostress

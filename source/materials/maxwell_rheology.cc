#include <lithostress/base/input_error.h>
#include <lithostress/materials/creep_strain.h>
#include <lithostress/materials/maxwell_rheology.h>

namespace lithostress
{
  template <int dim>
  void
  MaxwellRheology<dim>::parse_parameters(ParameterHandler &,
                                         const Material  &material,
                                         const PlaneState plane_state)
  {
    if (!(material.viscosity > 0))
      throw_input_error("Materials/" + material.name + "/Viscosity",
                        "must be positive for Rheology = maxwell");
    viscosity         = material.viscosity;
    shear_modulus     = material.shear_modulus();
    bulk_modulus      = material.lame_lambda() + 2.0 / 3.0 * shear_modulus;
    this->plane_state = plane_state;
    elastic.emplace(material, plane_state);
    step.emplace(*elastic);
  }

  template <int dim>
  std::vector<std::string>
  MaxwellRheology<dim>::history_names() const
  {
    return CreepStrain<dim>::names();
  }

  template <int dim>
  double
  MaxwellRheology<dim>::history_norm(const ArrayView<const double> &h) const
  {
    return CreepStrain<dim>::tensor(h).norm();
  }

  template <int dim>
  void
  MaxwellRheology<dim>::set_time_step(const double dt, const double weight)
  {
    // Δt = 0 is the state's response: exactly the elastic moduli.
    if (dt == 0)
      {
        step.emplace(*elastic);
        return;
      }
    const double relaxed =
      shear_modulus / (1.0 + weight * dt / relaxation_time());
    step.emplace(bulk_modulus - 2.0 / 3.0 * relaxed, relaxed, plane_state);
  }

  template <int dim>
  StressState<dim>
  MaxwellRheology<dim>::stress(const RheologyInputs<dim> &in) const
  {
    const ElasticModuli<dim> &m = this->moduli_for(in);
    StressState<dim>          s;
    s.in_plane = m.stress(in.strain);
    s.zz       = m.sigma_zz(in.strain);
    const auto [sigma, zz] =
      m.initial_strain_stress(CreepStrain<dim>::tensor(in.history));
    s.in_plane += sigma;
    s.zz += zz;
    s.in_plane += in.initial_stress.in_plane;
    s.zz += in.initial_stress.zz;
    return s;
  }

  template <int dim>
  void
  MaxwellRheology<dim>::evaluate(const RheologyInputs<dim> &in,
                                 RheologyOutputs<dim>      &out) const
  {
    out.stress  = stress(in);
    out.tangent = this->moduli_for(in).stiffness();
    SymmetricTensor<2, 3> sigma;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        sigma[i][j] = out.stress.in_plane[i][j];
    if (dim == 2)
      sigma[2][2] = out.stress.zz;
    const SymmetricTensor<2, 3> rate = deviator(sigma) / (2.0 * viscosity);
    const SymmetricTensor<2, 3> c_new =
      CreepStrain<dim>::tensor(in.history) + in.weight * in.time_step * rate;
    out.history_rate.resize(CreepStrain<dim>::n_components);
    out.history.resize(CreepStrain<dim>::n_components);
    CreepStrain<dim>::components(rate, make_array_view(out.history_rate));
    CreepStrain<dim>::components(c_new, make_array_view(out.history));
    out.effective_viscosity = viscosity;
    out.elastic_strain      = deviator(sigma).norm() / (2 * shear_modulus);
  }

  template class MaxwellRheology<2>;
  LITHOSTRESS_REGISTER_RHEOLOGY(
    MaxwellRheology,
    "maxwell",
    "Maxwell visco-elasticity with the material's Viscosity (thesis §3.9)")
} // namespace lithostress

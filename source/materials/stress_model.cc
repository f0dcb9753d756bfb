#include <lithostress/materials/stress_model.h>

namespace lithostress
{
  template <int dim>
  StressModel<dim>::StressModel(
    const MaterialLibrary                               &materials,
    const PlaneState                                     plane_state,
    const std::vector<const InitialStressSource<dim> *> &sources)
      : materials(materials)
      , plane_state(plane_state)
  {
    for (const Material &m : materials.materials())
      {
        moduli_of.emplace(m.id, ElasticModuli<dim>(m, plane_state));
        maxwell_of.emplace(m.id, MaxwellMaterial<dim>(m, plane_state));
      }
    step_moduli_of = moduli_of;
    for (const InitialStressSource<dim> *source : sources)
      if (source->has_initial_stress())
        initial_stress_loads.push_back(source);
  }

  template <int dim>
  StressState<dim>
  StressModel<dim>::stress(const types::material_id       id,
                           const Point<dim>              &p,
                           const SymmetricTensor<2, dim> &strain) const
  {
    const ElasticModuli<dim> &m = moduli_of.at(id);
    StressState<dim>          s;
    s.in_plane = m.stress(strain);
    s.zz       = m.sigma_zz(strain);
    for (const InitialStressSource<dim> *load : initial_stress_loads)
      load->add_initial_stress(p, materials(id), m, s.in_plane, s.zz);
    return s;
  }

  namespace
  {
    /** σ = C ε + (stress of the initial strain @p initial) + thermal. */
    template <int dim>
    StressState<dim>
    stress_with_initial_strain(
      const ElasticModuli<dim>                            &m,
      const Material                                      &material,
      const std::vector<const InitialStressSource<dim> *> &loads,
      const Point<dim>                                    &p,
      const SymmetricTensor<2, dim>                       &strain,
      const SymmetricTensor<2, 3>                         &initial)
    {
      StressState<dim> s;
      s.in_plane             = m.stress(strain);
      s.zz                   = m.sigma_zz(strain);
      const auto [sigma, zz] = m.initial_strain_stress(initial);
      s.in_plane += sigma;
      s.zz += zz;
      for (const InitialStressSource<dim> *load : loads)
        load->add_initial_stress(p, material, m, s.in_plane, s.zz);
      return s;
    }
  } // namespace

  template <int dim>
  StressState<dim>
  StressModel<dim>::stress(const types::material_id       id,
                           const Point<dim>              &p,
                           const SymmetricTensor<2, dim> &strain,
                           const SymmetricTensor<2, 3>   &creep) const
  {
    return stress_with_initial_strain(
      moduli_of.at(id), materials(id), initial_stress_loads, p, strain, creep);
  }

  template <int dim>
  StressState<dim>
  StressModel<dim>::stress(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const Point<dim>                                        &unit,
    const Point<dim>                                        &p,
    const SymmetricTensor<2, dim>                           &strain) const
  {
    if (creep_strain == nullptr ||
        !maxwell_of.at(cell->material_id()).is_viscous())
      return stress(cell->material_id(), p, strain);
    return stress(cell->material_id(),
                  p,
                  strain,
                  creep_strain->value(cell, unit));
  }

  template <int dim>
  StressState<dim>
  StressModel<dim>::step_stress(const types::material_id       id,
                                const Point<dim>              &p,
                                const SymmetricTensor<2, dim> &strain,
                                const SymmetricTensor<2, 3>   &history) const
  {
    return stress_with_initial_strain(step_moduli_of.at(id),
                                      materials(id),
                                      initial_stress_loads,
                                      p,
                                      strain,
                                      history);
  }

  template <int dim>
  bool
  StressModel<dim>::has_viscous_material() const
  {
    for (const auto &[id, law] : maxwell_of)
      if (law.is_viscous())
        return true;
    return false;
  }

  template <int dim>
  void
  StressModel<dim>::set_time_step(const double dt, const double theta)
  {
    if (dt == step_length && theta == step_theta)
      return;
    ++version;
    step_length = dt;
    step_theta  = theta;
    step_moduli_of.clear();
    for (const auto &[id, law] : maxwell_of)
      step_moduli_of.emplace(id,
                             law.is_viscous() ? law.step_moduli(dt, theta)
                                              : moduli_of.at(id));
  }

  template class StressModel<2>;
} // namespace lithostress

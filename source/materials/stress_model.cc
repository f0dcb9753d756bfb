#include <lithostress/materials/stress_model.h>

namespace lithostress
{
  template <int dim>
  StressModel<dim>::StressModel(const MaterialLibrary     &materials,
                                const PlaneState           plane_state,
                                const LoadCollection<dim> &loads)
      : materials(materials)
      , plane_state(plane_state)
  {
    for (const Material &m : materials.materials())
      moduli_of.emplace(m.id, ElasticModuli<dim>(m, plane_state));
    for (const auto &load : loads.loads())
      if (load->has_initial_stress())
        initial_stress_loads.push_back(load.get());
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
    for (const Load<dim> *load : initial_stress_loads)
      load->add_initial_stress(p, materials(id), m, s.in_plane, s.zz);
    return s;
  }

  template class StressModel<2>;
} // namespace lithostress

#include <lithostress/materials/elastic_rheology.h>

namespace lithostress
{
  template <int dim>
  void
  ElasticRheology<dim>::parse_parameters(ParameterHandler &,
                                         const Material  &material,
                                         const PlaneState plane_state)
  {
    moduli.emplace(material, plane_state);
  }

  template <int dim>
  StressState<dim>
  ElasticRheology<dim>::stress(const RheologyInputs<dim> &in) const
  {
    StressState<dim> s;
    s.in_plane = moduli->stress(in.strain);
    s.zz       = moduli->sigma_zz(in.strain);
    s.in_plane += in.initial_stress.in_plane;
    s.zz += in.initial_stress.zz;
    return s;
  }

  template <int dim>
  void
  ElasticRheology<dim>::evaluate(const RheologyInputs<dim> &in,
                                 RheologyOutputs<dim>      &out) const
  {
    out.stress  = stress(in);
    out.tangent = moduli->stiffness();
    out.history.clear();
    out.history_rate.clear();
    out.effective_viscosity = 0;
  }

  template class ElasticRheology<2>;
  LITHOSTRESS_REGISTER_RHEOLOGY(ElasticRheology,
                                "elastic",
                                "isotropic linear elasticity (thesis §3.6)")
} // namespace lithostress

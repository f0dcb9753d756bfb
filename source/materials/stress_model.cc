#include <lithostress/base/input_error.h>
#include <lithostress/materials/stress_model.h>

#include <array>
#include <stdexcept>

namespace lithostress
{
  template <int dim>
  StressModel<dim>::StressModel(
    ParameterHandler                                    &prm,
    const MaterialLibrary                               &materials,
    const PlaneState                                     plane_state,
    const std::vector<const InitialStressSource<dim> *> &sources)
      : materials(materials)
      , plane_state(plane_state)
  {
    prm.enter_subsection("Materials");
    for (const Material &m : materials.materials())
      {
        std::unique_ptr<Rheology<dim>> law =
          RheologyRegistry<dim>::find(m.rheology,
                                      "Materials/" + m.name + "/Rheology")
            .create();
        prm.enter_subsection(m.name);
        law->parse_parameters(prm, m, plane_state);
        prm.leave_subsection();
        // The time loop carries a creeping law's history as the deviatoric
        // creep strain (CreepStrain) and assembles it as an initial strain.
        if (law->creeps() &&
            law->history_names().size() != CreepStrain<dim>::n_components)
          throw std::logic_error(
            "the rock law <" + m.rheology + "> creeps with " +
            std::to_string(law->history_names().size()) +
            " history components, but the time loop carries the " +
            std::to_string(CreepStrain<dim>::n_components) +
            " of a deviatoric creep strain");
        if (m.viscosity > 0 && !law->creeps())
          throw_input_error("Materials/" + m.name + "/Viscosity",
                            "is given, but Rheology = " + m.rheology +
                              " does not creep: remove the viscosity or "
                              "choose a law that uses it (maxwell)");
        history_size_of[m.id] = law->history_names().size();
        rheology_of.emplace(m.id, std::move(law));
      }
    prm.leave_subsection();
    for (const auto &[id, n] : history_size_of)
      if (n > zero_history.size())
        zero_history.resize(n, 0.0);
    for (const InitialStressSource<dim> *source : sources)
      if (source->has_initial_stress())
        initial_stress_loads.push_back(source);
  }

  template <int dim>
  StressState<dim>
  StressModel<dim>::initial_stress(const types::material_id  id,
                                   const Point<dim>         &p,
                                   const ElasticModuli<dim> &moduli) const
  {
    StressState<dim> s;
    for (const InitialStressSource<dim> *load : initial_stress_loads)
      load->add_initial_stress(p, materials(id), moduli, s.in_plane, s.zz);
    return s;
  }

  template <int dim>
  StressState<dim>
  StressModel<dim>::stress(const types::material_id       id,
                           const Point<dim>              &p,
                           const SymmetricTensor<2, dim> &strain) const
  {
    const Rheology<dim> &law = *rheology_of.at(id);
    RheologyInputs<dim>  in;
    in.position = p;
    in.strain   = strain;
    in.history =
      ArrayView<const double>(zero_history.data(), history_size_of.at(id));
    in.initial_stress = initial_stress(id, p, law.moduli_for(in));
    return law.stress(in);
  }

  template <int dim>
  StressState<dim>
  StressModel<dim>::stress(const types::material_id       id,
                           const Point<dim>              &p,
                           const SymmetricTensor<2, dim> &strain,
                           const SymmetricTensor<2, 3>   &creep) const
  {
    std::array<double, CreepStrain<dim>::n_components> c;
    CreepStrain<dim>::components(creep, ArrayView<double>(c.data(), c.size()));
    const Rheology<dim> &law = *rheology_of.at(id);
    RheologyInputs<dim>  in;
    in.position       = p;
    in.strain         = strain;
    in.history        = ArrayView<const double>(c.data(), c.size());
    in.initial_stress = initial_stress(id, p, law.moduli_for(in));
    return law.stress(in);
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
        !rheology_of.at(cell->material_id())->creeps())
      return stress(cell->material_id(), p, strain);
    return stress(cell->material_id(),
                  p,
                  strain,
                  creep_strain->value(cell, unit));
  }

  template <int dim>
  void
  StressModel<dim>::evaluate(const types::material_id id,
                             RheologyInputs<dim>     &in,
                             RheologyOutputs<dim>    &out) const
  {
    const Rheology<dim> &law = *rheology_of.at(id);
    in.initial_stress = initial_stress(id, in.position, law.moduli_for(in));
    law.evaluate(in, out);
  }

  template <int dim>
  bool
  StressModel<dim>::uniform_tangents() const
  {
    for (const auto &[id, law] : rheology_of)
      if (!law->uniform_tangent())
        return false;
    return true;
  }

  template <int dim>
  SymmetricTensor<4, dim>
  StressModel<dim>::tangent(const types::material_id id,
                            const Point<dim>        &p,
                            const bool               of_state) const
  {
    const Rheology<dim> &law = *rheology_of.at(id);
    if (law.uniform_tangent())
      return of_state ? law.elastic_moduli().stiffness()
                      : law.step_moduli().stiffness();
    RheologyInputs<dim> in;
    in.position  = p;
    in.time_step = of_state ? 0. : step_length;
    in.weight    = step_theta;
    in.history =
      ArrayView<const double>(zero_history.data(), history_size_of.at(id));
    RheologyOutputs<dim> out;
    evaluate(id, in, out);
    return out.tangent;
  }

  template <int dim>
  StressState<dim>
  StressModel<dim>::step_stress(const types::material_id       id,
                                const Point<dim>              &p,
                                const SymmetricTensor<2, dim> &strain) const
  {
    const Rheology<dim> &law = *rheology_of.at(id);
    if (law.uniform_tangent())
      {
        StressState<dim> s;
        s.in_plane = law.step_moduli().stress(strain);
        s.zz       = law.step_moduli().sigma_zz(strain);
        return s;
      }
    RheologyInputs<dim> in;
    in.position  = p;
    in.strain    = strain;
    in.time_step = step_length;
    in.weight    = step_theta;
    in.history =
      ArrayView<const double>(zero_history.data(), history_size_of.at(id));
    return law.stress(in);
  }

  template <int dim>
  bool
  StressModel<dim>::has_viscous_material() const
  {
    for (const auto &[id, law] : rheology_of)
      if (law->creeps())
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
    for (const auto &[id, law] : rheology_of)
      law->set_time_step(dt, theta);
  }

  template class StressModel<2>;
} // namespace lithostress

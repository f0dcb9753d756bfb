#include <lithostress/base/input_error.h>
#include <lithostress/materials/law_entries.h>
#include <lithostress/materials/stress_model.h>

#include <algorithm>
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
        refuse_entries_of_other_laws(prm,
                                     m.rheology,
                                     "Materials/" + m.name + "/");
        law->parse_parameters(prm, m, plane_state);
        prm.leave_subsection();
        if (m.viscosity > 0 && !law->creeps())
          throw_input_error("Materials/" + m.name + "/Viscosity",
                            "is given, but Rheology = " + m.rheology +
                              " does not creep: remove the viscosity or "
                              "choose a law that uses it (maxwell)");
        layout.add(m.id, law->history_names());
        zero_history.resize(std::max<std::size_t>(zero_history.size(),
                                                  layout.size(m.id)),
                            0.0);
        rheology_of.emplace(m.id, std::move(law));
      }
    prm.leave_subsection();
    all_sources = sources;
    for (const InitialStressSource<dim> *source : sources)
      if (source->has_initial_stress())
        initial_stress_loads.push_back(source);
  }

  template <int dim>
  double
  StressModel<dim>::reference_pressure(const Point<dim> &p) const
  {
    double pressure = 0;
    for (const InitialStressSource<dim> *source : all_sources)
      pressure += source->reference_pressure(p);
    return pressure;
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
    in.history  = ArrayView<const double>(zero_history.data(), layout.size(id));
    in.initial_stress = initial_stress(id, p, law.moduli_for(in));
    return law.stress(in);
  }

  template <int dim>
  StressState<dim>
  StressModel<dim>::stress(const types::material_id       id,
                           const Point<dim>              &p,
                           const SymmetricTensor<2, dim> &strain,
                           const ArrayView<const double> &history) const
  {
    AssertDimension(history.size(), layout.size(id));
    const Rheology<dim> &law = *rheology_of.at(id);
    RheologyInputs<dim>  in;
    in.position       = p;
    in.strain         = strain;
    in.history        = history;
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
    const types::material_id id = cell->material_id();
    if (cell_history == nullptr || !has_history(id))
      return stress(id, p, strain);
    Vector<double>      record;
    std::vector<double> scratch;
    cell_history->value(cell, unit, record);
    return stress(id, p, strain, layout.of(id, record, scratch));
  }

  template <int dim>
  StressState<dim>
  StressModel<dim>::history_stress(const types::material_id       id,
                                   const Point<dim>              &p,
                                   const ArrayView<const double> &history,
                                   const bool of_state) const
  {
    AssertDimension(history.size(), layout.size(id));
    RheologyInputs<dim> in;
    in.position  = p;
    in.time_step = of_state ? 0. : step_length;
    in.weight    = step_theta;
    in.history   = history;
    return rheology_of.at(id)->stress(in);
  }

  template <int dim>
  void
  StressModel<dim>::evaluate(const types::material_id id,
                             RheologyInputs<dim>     &in,
                             RheologyOutputs<dim>    &out) const
  {
    const Rheology<dim> &law = *rheology_of.at(id);
    in.initial_stress = initial_stress(id, in.position, law.moduli_for(in));
    in.pressure       = reference_pressure(in.position);
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
    in.history = ArrayView<const double>(zero_history.data(), layout.size(id));
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
    in.history = ArrayView<const double>(zero_history.data(), layout.size(id));
    return law.stress(in);
  }

  template <int dim>
  void
  StressModel<dim>::linearisation_at(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    std::vector<LinearisedStress<dim>>                      &values) const
  {
    Assert(linearised(cell->material_id()), ExcInternalError());
    std::vector<Vector<double>> records;
    linearisation->get(cell, records);
    values.resize(records.size());
    for (unsigned int q = 0; q < records.size(); ++q)
      values[q] = LinearisedStress<dim>::from(records[q]);
  }

  template <int dim>
  void
  StressModel<dim>::attach_temperature(const TemperatureModel<dim> *model)
  {
    temperature = model;
    if (model != nullptr)
      return;
    for (const auto &[id, law] : rheology_of)
      if (law->needs_temperature())
        throw_input_error("Temperature/Model",
                          "is none, but the creep law of material " +
                            materials(id).name +
                            " has an activation energy or volume and needs "
                            "a temperature (choose a model)");
  }

  template <int dim>
  bool
  StressModel<dim>::symmetric_operator() const
  {
    for (const auto &[id, law] : rheology_of)
      if (linearised(id) && !law->symmetric_tangent())
        return false;
    return true;
  }

  template <int dim>
  bool
  StressModel<dim>::may_be_unsymmetric() const
  {
    for (const auto &[id, law] : rheology_of)
      if (!law->symmetric_tangent())
        return true;
    return false;
  }

  template <int dim>
  bool
  StressModel<dim>::has_nonlinear_material() const
  {
    for (const auto &[id, law] : rheology_of)
      if (law->nonlinear())
        return true;
    return false;
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

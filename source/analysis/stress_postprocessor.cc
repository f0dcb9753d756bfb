#include <deal.II/dofs/dof_handler.h>

#include <lithostress/analysis/stress_postprocessor.h>

namespace lithostress
{
  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(
    const StressModel<dim> &stress_model,
    const Mapping<dim>     &mapping,
    const unsigned int      n_fields,
    const GriffithFailure  &griffith)
      : stress_model(stress_model)
      , mapping(mapping)
      , n_fields(n_fields)
      , griffith(griffith)
  {
  }

  template <int dim>
  std::vector<std::string>
  StressPostprocessor<dim>::get_names() const
  {
    std::vector<std::string> names(dim, "displacement");
    for (unsigned int i = 0; i < dim * dim; ++i)
      names.emplace_back("stress");
    names.emplace_back("sigma_zz");
    names.emplace_back("sigma_1");
    names.emplace_back("sigma_2");
    for (unsigned int d = 0; d < dim; ++d)
      names.emplace_back("sigma_1_direction");
    names.emplace_back("deviatoric_xx");
    names.emplace_back("deviatoric_yy");
    names.emplace_back("deviatoric_zz");
    names.emplace_back("deviatoric_xy");
    names.emplace_back("griffith_degree_of_failure");
    names.emplace_back("griffith_regime");
    names.emplace_back("griffith_fracture_angle");
    if (stress_model.temperature_model() != nullptr)
      names.emplace_back("temperature");
    return names;
  }

  template <int dim>
  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor<dim>::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation> i(
      dim, DataComponentInterpretation::component_is_part_of_vector);
    for (unsigned int k = 0; k < dim * dim; ++k)
      i.push_back(DataComponentInterpretation::component_is_part_of_tensor);
    for (unsigned int k = 0; k < 3; ++k)
      i.push_back(DataComponentInterpretation::component_is_scalar);
    for (unsigned int d = 0; d < dim; ++d)
      i.push_back(DataComponentInterpretation::component_is_part_of_vector);
    for (unsigned int k = 0; k < 7; ++k)
      i.push_back(DataComponentInterpretation::component_is_scalar);
    if (stress_model.temperature_model() != nullptr)
      i.push_back(DataComponentInterpretation::component_is_scalar);
    return i;
  }

  template <int dim>
  UpdateFlags
  StressPostprocessor<dim>::get_needed_update_flags() const
  {
    return update_values | update_gradients | update_quadrature_points;
  }

  template <int dim>
  void
  StressPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed) const
  {
    const auto      cell     = inputs.template get_cell<dim>();
    const Material &material = stress_model.materials(cell->material_id());
    const TemperatureModel<dim> *temperature = stress_model.temperature_model();
    std::vector<double>          temperatures;
    if (temperature != nullptr)
      temperature->values(cell, inputs.evaluation_points, temperatures);
    for (unsigned int q = 0; q < computed.size(); ++q)
      {
        Tensor<1, dim> u;
        Tensor<2, dim> grad;
        for (unsigned int f = 0; f < n_fields; ++f)
          for (unsigned int d = 0; d < dim; ++d)
            {
              u[d] += inputs.solution_values[q][f * dim + d];
              grad[d] += inputs.solution_gradients[q][f * dim + d];
            }
        const Point<dim> &p = inputs.evaluation_points[q];
        // The history lives on the unit cell: locate the point there.
        const bool with_creep =
          stress_model.attached_cell_history() != nullptr &&
          stress_model.has_history(material.id);
        const StressState<dim> s =
          with_creep
            ? stress_model.stress(cell,
                                  mapping.transform_real_to_unit_cell(cell, p),
                                  p,
                                  symmetrize(grad))
            : stress_model.stress(material.id, p, symmetrize(grad));
        const StressAnalysis a = analyse_stress(s, material, p, griffith);
        for (unsigned int d = 0; d < dim; ++d)
          computed[q][d] = u[d];
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            computed[q][dim + i * dim + j] = s.in_plane[i][j];
        unsigned int k   = dim + dim * dim;
        computed[q][k++] = s.zz;
        computed[q][k++] = a.principal.sigma_1;
        computed[q][k++] = a.principal.sigma_2;
        computed[q][k++] = std::cos(a.principal.angle_1);
        computed[q][k++] = std::sin(a.principal.angle_1);
        computed[q][k++] = a.deviatoric_xx;
        computed[q][k++] = a.deviatoric_yy;
        computed[q][k++] = a.deviatoric_zz;
        computed[q][k++] = a.deviatoric_xy;
        computed[q][k++] = a.degree_of_failure;
        computed[q][k++] = a.regime;
        computed[q][k++] = a.fracture_angle;
        if (temperature != nullptr)
          computed[q][k++] = temperatures[q];
      }
  }

  template <int dim>
  StressAnalysis
  analyse_stress(const StressState<dim> &s,
                 const Material         &material,
                 const Point<dim>       &p,
                 const GriffithFailure  &griffith)
  {
    StressAnalysis a;
    a.principal       = principal_stresses(s.in_plane);
    const double mean = (s.in_plane[0][0] + s.in_plane[1][1] + s.zz) / 3;
    a.deviatoric_xx   = s.in_plane[0][0] - mean;
    a.deviatoric_yy   = s.in_plane[1][1] - mean;
    a.deviatoric_zz   = s.zz - mean;
    a.deviatoric_xy   = s.in_plane[0][1];
    const double lithostatic =
      griffith.lithostatic_stress(material.density, p[dim - 1]);
    const GriffithFailure::Result g =
      griffith.evaluate(a.principal.sigma_1 + lithostatic,
                        a.principal.sigma_2 + lithostatic,
                        material.tensile_strength);
    const bool tested   = g.regime != GriffithFailure::Regime::not_tested;
    a.degree_of_failure = tested ? g.degree_of_failure : 1.0;
    a.regime            = tested ? static_cast<double>(g.regime) : -1.0;
    a.fracture_angle    = tested ? g.fracture_angle * 180 / numbers::PI : 0.0;
    return a;
  }

  PrincipalStresses
  principal_stresses(const SymmetricTensor<2, 2> &s)
  {
    const double centre = 0.5 * (s[0][0] + s[1][1]);
    const double radius = std::sqrt(
      0.25 * (s[0][0] - s[1][1]) * (s[0][0] - s[1][1]) + s[0][1] * s[0][1]);
    PrincipalStresses p;
    p.sigma_1 = centre + radius;
    p.sigma_2 = centre - radius;
    // tan 2θ = 2σxy / (σxx − σyy): the direction of σ1 from the x axis.
    p.angle_1 = 0.5 * std::atan2(2 * s[0][1], s[0][0] - s[1][1]);
    return p;
  }

  template class StressPostprocessor<2>;
  template StressAnalysis
  analyse_stress<2>(const StressState<2> &,
                    const Material &,
                    const Point<2> &,
                    const GriffithFailure &);
} // namespace lithostress

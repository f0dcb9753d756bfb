#include <deal.II/dofs/dof_handler.h>

#include <lithostress/postprocess/stress_postprocessor.h>

namespace lithostress
{
  template <int dim>
  StressPostprocessor<dim>::StressPostprocessor(
    const MaterialLibrary &materials,
    const PlaneState       plane_state,
    const unsigned int     n_fields,
    const GriffithFailure &griffith)
      : materials(materials)
      , plane_state(plane_state)
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
    return i;
  }

  template <int dim>
  UpdateFlags
  StressPostprocessor<dim>::get_needed_update_flags() const
  {
    return update_values | update_gradients;
  }

  template <int dim>
  void
  StressPostprocessor<dim>::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<dim> &inputs,
    std::vector<Vector<double>>                &computed) const
  {
    const auto               cell     = inputs.template get_cell<dim>();
    const Material          &material = materials(cell->material_id());
    const ElasticModuli<dim> moduli(material, plane_state);
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
        const SymmetricTensor<2, dim> strain = symmetrize(grad);
        const SymmetricTensor<2, dim> stress = moduli.stress(strain);
        for (unsigned int d = 0; d < dim; ++d)
          computed[q][d] = u[d];
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = 0; b < dim; ++b)
            computed[q][dim + a * dim + b] = stress[a][b];
        const double sigma_zz     = moduli.sigma_zz(strain);
        unsigned int k            = dim + dim * dim;
        computed[q][k++]          = sigma_zz;
        const PrincipalStresses p = principal_stresses(stress);
        computed[q][k++]          = p.sigma_1;
        computed[q][k++]          = p.sigma_2;
        computed[q][k++]          = std::cos(p.angle_1);
        computed[q][k++]          = std::sin(p.angle_1);
        const double mean = (stress[0][0] + stress[1][1] + sigma_zz) / 3;
        computed[q][k++]  = stress[0][0] - mean;
        computed[q][k++]  = stress[1][1] - mean;
        computed[q][k++]  = sigma_zz - mean;
        computed[q][k++]  = stress[0][1];
        const GriffithFailure::Result g =
          griffith.evaluate(p.sigma_1, p.sigma_2, material.tensile_strength);
        const bool tested = g.regime != GriffithFailure::Regime::not_tested;
        computed[q][k++]  = tested ? g.degree_of_failure : 1.0;
        computed[q][k++]  = tested ? static_cast<double>(g.regime) : -1.0;
        computed[q][k++]  = tested ? g.fracture_angle * 180 / numbers::PI : 0.0;
      }
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
} // namespace lithostress

#include <lithostress/loads/gravity.h>
#include <lithostress/loads/load_collection.h>

namespace lithostress
{
  template <int dim>
  void
  Gravity<dim>::declare_parameters(ParameterHandler &prm, ParameterHandler *)
  {
    prm.enter_subsection("Gravity");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Apply the body force -rho g in y to every material.");
    prm.leave_subsection();
  }

  template <int dim>
  bool
  Gravity<dim>::parse_parameters(ParameterHandler            &prm,
                                 const ModelDescription<dim> &model)
  {
    prm.enter_subsection("Gravity");
    const bool enabled = prm.get_bool("Enabled");
    acceleration       = model.gravity.acceleration;
    prm.leave_subsection();
    return enabled;
  }

  template <int dim>
  void
  Gravity<dim>::add_cell_terms(const FEValues<dim>              &fe_values,
                               const FEValuesExtractors::Vector &displacement,
                               const Material                   &material,
                               const ElasticModuli<dim> &,
                               FullMatrix<double> &,
                               Vector<double> &cell_rhs) const
  {
    const double rho_g = material.density * acceleration;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double JxW = fe_values.JxW(q);
        for (const unsigned int i : fe_values.dof_indices())
          cell_rhs(i) -=
            rho_g * fe_values[displacement].value(i, q)[dim - 1] * JxW;
      }
  }

  template <int dim>
  std::string
  Gravity<dim>::description() const
  {
    return "gravity: body force -rho g in y, g = " +
           std::to_string(acceleration) + " m/s^2";
  }

  template class Gravity<2>;
  LITHOSTRESS_REGISTER_LOAD(Gravity,
                            "gravity",
                            "the body force ρ g (thesis §3.7)",
                            10)
} // namespace lithostress

#include <lithostress/base/input_error.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/loads/thermal_strain.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  ThermalStrain<dim>::declare_parameters(ParameterHandler &prm,
                                         ParameterHandler *)
  {
    prm.enter_subsection("Thermal strain");
    prm.declare_entry("Temperature change",
                      "",
                      Patterns::Anything(),
                      "Temperature change Delta T [K] as a function of x, y "
                      "[m] (and t [s]); `temperature model`: Delta T = T - "
                      "Reference temperature with T of Temperature/Model "
                      "(function or plate cooling); empty = no thermal "
                      "load.");
    prm.declare_entry("Reference temperature",
                      "273",
                      Patterns::Double(0),
                      "T_ref [K] of Temperature change = temperature model: "
                      "the temperature at which the body is unstrained.");
    prm.declare_entry("Constants",
                      "",
                      Patterns::Anything(),
                      "Constants for the expression: name=value, ...");
    prm.declare_entry("Expansion coefficient",
                      "1e-5",
                      Patterns::Double(0),
                      "Thermal expansion coefficient alpha [1/K], read as "
                      "Coefficient type says.");
    prm.declare_entry("Coefficient type",
                      "",
                      Patterns::Anything(),
                      "How alpha is read: `linear` (each length grows by "
                      "alpha Delta T) or `volumetric` (the volume grows by "
                      "alpha Delta T, so the linear strain is alpha Delta T / "
                      "3). Required with a temperature change: the thesis "
                      "calls its alpha = 1e-5 a volume coefficient (section "
                      "7.6.2) but its TANOM routine uses it as a linear one.");
    prm.leave_subsection();
  }

  template <int dim>
  bool
  ThermalStrain<dim>::parse_parameters(ParameterHandler            &prm,
                                       const ModelDescription<dim> &model)
  {
    const std::string where = "Loads/Thermal strain/";
    prm.enter_subsection("Thermal strain");
    const std::string expression =
      Utilities::trim(prm.get("Temperature change"));
    const std::string constants = prm.get("Constants");
    coefficient                 = prm.get_double("Expansion coefficient");
    const std::string type      = Utilities::trim(prm.get("Coefficient type"));
    reference_temperature       = prm.get_double("Reference temperature");
    prm.leave_subsection();
    if (expression.empty())
      return false;
    if (expression == "temperature model")
      {
        temperature =
          dynamic_cast<const PointwiseTemperature<dim> *>(model.temperature);
        if (temperature == nullptr)
          throw_input_error(where + "Temperature change",
                            "is `temperature model`, but " +
                              std::string(model.temperature == nullptr
                                            ? "Temperature/Model is none"
                                            : "the Temperature/Model is not a "
                                              "closed form of position") +
                              " (choose function or plate cooling)");
      }
    else
      temperature_change =
        std::make_unique<ParsedExpression<dim>>(expression,
                                                constants,
                                                where + "Temperature change");
    if (type == "linear")
      volumetric = false;
    else if (type == "volumetric")
      volumetric = true;
    else
      throw_input_error(where + "Coefficient type",
                        "must be `linear` or `volumetric` when a temperature "
                        "change is given, got <" +
                          type + ">");
    return true;
  }

  template <int dim>
  double
  ThermalStrain<dim>::initial_strain(const Point<dim> &p) const
  {
    const double delta_t = temperature != nullptr
                             ? temperature->value(p) - reference_temperature
                             : temperature_change->value(p, this->time());
    return (volumetric ? coefficient / 3.0 : coefficient) * delta_t;
  }

  template <int dim>
  void
  ThermalStrain<dim>::add_initial_stress(const Point<dim> &p,
                                         const Material &,
                                         const ElasticModuli<dim> &moduli,
                                         SymmetricTensor<2, dim>  &stress,
                                         double &sigma_zz) const
  {
    const auto s = moduli.isotropic_initial_strain_stress(initial_strain(p));
    for (unsigned int d = 0; d < dim; ++d)
      stress[d][d] += s.first;
    sigma_zz += s.second;
  }

  template <int dim>
  void
  ThermalStrain<dim>::add_cell_terms(
    const FEValues<dim>              &fe_values,
    const FEValuesExtractors::Vector &displacement,
    const Material &,
    const ElasticModuli<dim> &moduli,
    FullMatrix<double> &,
    Vector<double> &cell_rhs) const
  {
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        // σ0 = s I in plane: −∫ σ0 : ε(v) = −∫ s div v.
        const double s = moduli
                           .isotropic_initial_strain_stress(
                             initial_strain(fe_values.quadrature_point(q)))
                           .first *
                         fe_values.JxW(q);
        for (const unsigned int i : fe_values.dof_indices())
          cell_rhs(i) -= s * fe_values[displacement].divergence(i, q);
      }
  }

  template <int dim>
  void
  ThermalStrain<dim>::prepare_for_mesh(const Triangulation<dim> &tria,
                                       const Mapping<dim>       &mapping,
                                       const Quadrature<dim - 1> &)
  {
    const FE_Q<dim>          fe(1);
    const QGaussLobatto<dim> support(3);
    FEValues<dim> values(mapping, fe, support, update_quadrature_points);
    on_all_ranks(tria.get_communicator(), [&]() {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            values.reinit(cell);
            for (const Point<dim> &p : values.get_quadrature_points())
              initial_strain(p);
          }
    });
  }

  template <int dim>
  std::string
  ThermalStrain<dim>::description() const
  {
    std::ostringstream out;
    out << "thermal strain: Delta T = "
        << (temperature != nullptr
              ? "T - " + std::to_string(reference_temperature) +
                  " (Temperature/Model)"
              : temperature_change->text())
        << " K, alpha = " << coefficient
        << (volumetric ? " /K (volumetric, linear strain alpha Delta T / 3)"
                       : " /K (linear)");
    return out.str();
  }

  template class ThermalStrain<2>;
  LITHOSTRESS_REGISTER_LOAD(
    ThermalStrain,
    "thermal strain",
    "the initial strain of a temperature change (thesis §3.8, TANOM)",
    30)
} // namespace lithostress

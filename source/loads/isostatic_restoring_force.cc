#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/loads/isostatic_restoring_force.h>
#include <lithostress/loads/load_collection.h>

namespace lithostress
{
  template <int dim>
  void
  IsostaticRestoringForce<dim>::declare_parameters(ParameterHandler &prm,
                                                   ParameterHandler *)
  {
    prm.enter_subsection("Isostatic restoring force");
    prm.declare_entry("Boundary parts",
                      "",
                      Patterns::Anything(),
                      "Comma separated boundary parts in contact with a "
                      "fluid (e.g. base: mantle, top: water or sediment).");
    prm.declare_entry("Fluid densities",
                      "",
                      Patterns::Anything(),
                      "Density rho_f [kg/m^3] of the fluid on each part, in "
                      "the same order; > 0.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  IsostaticRestoringForce<dim>::read_parameters(
    ParameterHandler            &prm,
    const ModelDescription<dim> &model)
  {
    const std::string where = "Loads/Isostatic restoring force/";
    parts.clear();
    this->names.clear();
    prm.enter_subsection("Isostatic restoring force");
    const auto   names     = split_list(prm.get("Boundary parts"));
    const auto   densities = split_list(prm.get("Fluid densities"));
    const double g         = model.gravity.acceleration;
    prm.leave_subsection();
    if (names.size() != densities.size())
      throw_input_error(where + "Fluid densities",
                        "needs one density per boundary part (" +
                          std::to_string(names.size()) + ")");
    for (unsigned int i = 0; i < names.size(); ++i)
      {
        const double rho =
          parse_number(densities[i], where + "Fluid densities");
        if (!(rho > 0))
          throw_input_error(where + "Fluid densities",
                            "the density of the fluid on <" + names[i] +
                              "> must be positive, got " + densities[i]);
        this->names.push_back(names[i] + " (rho_f = " + densities[i] +
                              " kg/m^3)");
        parts.emplace_back(model.boundary_id(names[i],
                                             where + "Boundary parts"),
                           rho * g);
      }
  }

  template <int dim>
  bool
  IsostaticRestoringForce<dim>::acts_on_boundary(
    const types::boundary_id id) const
  {
    return stiffness(id) > 0;
  }

  template <int dim>
  double
  IsostaticRestoringForce<dim>::stiffness(const types::boundary_id id) const
  {
    for (const auto &part : parts)
      if (part.first == id)
        return part.second;
    return 0;
  }

  template <int dim>
  void
  IsostaticRestoringForce<dim>::add_boundary_terms(
    const FEFaceValues<dim>          &fe_face_values,
    const types::boundary_id          id,
    const FEValuesExtractors::Vector &displacement,
    FullMatrix<double>               &cell_matrix,
    Vector<double> &) const
  {
    this->add_vertical_spring_terms(fe_face_values,
                                    stiffness(id),
                                    displacement,
                                    cell_matrix);
  }

  template <int dim>
  std::string
  IsostaticRestoringForce<dim>::description() const
  {
    std::string text = "isostatic restoring force rho_f g u_y on";
    for (const std::string &name : names)
      text += " " + name;
    return text;
  }

  template class IsostaticRestoringForce<2>;
  LITHOSTRESS_REGISTER_LOAD(
    IsostaticRestoringForce,
    "isostatic restoring force",
    "a Winkler foundation of a fluid on boundary parts (ISOS)",
    50)
} // namespace lithostress

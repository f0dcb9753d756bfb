#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/loads/boundary_traction.h>
#include <lithostress/reference_solutions/reference_solution.h>

namespace lithostress
{
  template <int dim>
  void
  BoundaryTraction<dim>::declare_parameters(ParameterHandler &prm,
                                            ParameterHandler *first_pass)
  {
    const std::vector<std::string> names = ParameterFile::names_from(
      first_pass, {"Loads", "Tractions"}, "Boundary parts", {"top"});
    prm.enter_subsection("Tractions");
    prm.declare_entry("Boundary parts",
                      "",
                      Patterns::Anything(),
                      "Comma separated boundary parts that carry a traction; "
                      "each gets a subsection of this name.");
    for (const std::string &name : names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Normal traction",
                          "0",
                          Patterns::Anything(),
                          "Normal traction [Pa] as a function of x, y [m] "
                          "and t [s]; positive = tension (pulls outward).");
        prm.declare_entry("Shear traction",
                          "0",
                          Patterns::Anything(),
                          "Shear traction [Pa] along s = (n_y, -n_x), the "
                          "outward normal turned clockwise.");
        prm.declare_entry("Constants",
                          "",
                          Patterns::Anything(),
                          "Constants for the expressions: name=value, ...");
        prm.declare_entry("Use reference solution",
                          "false",
                          Patterns::Bool(),
                          "Apply the traction sigma.n of the reference "
                          "solution instead of the expressions.");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  template <int dim>
  void
  BoundaryTraction<dim>::parse_parameters(ParameterHandler            &prm,
                                          const ModelDescription<dim> &model)
  {
    parts.clear();
    reference = model.reference;
    prm.enter_subsection("Tractions");
    for (const std::string &name : split_list(prm.get("Boundary parts")))
      {
        const std::string where = "Loads/Tractions/" + name + "/";
        Part              part;
        part.id = model.boundary_id(name, "Loads/Tractions/Boundary parts");
        prm.enter_subsection(name);
        part.from_reference         = prm.get_bool("Use reference solution");
        const std::string constants = prm.get("Constants");
        part.normal =
          std::make_unique<ParsedExpression<dim>>(prm.get("Normal traction"),
                                                  constants,
                                                  where + "Normal traction");
        part.shear =
          std::make_unique<ParsedExpression<dim>>(prm.get("Shear traction"),
                                                  constants,
                                                  where + "Shear traction");
        prm.leave_subsection();
        if (part.from_reference && reference == nullptr)
          throw_input_error(where + "Use reference solution",
                            "is true but Convergence study/Reference "
                            "solution is none");
        parts.push_back(std::move(part));
      }
    prm.leave_subsection();
  }

  template <int dim>
  bool
  BoundaryTraction<dim>::acts_on_boundary(const types::boundary_id id) const
  {
    for (const Part &part : parts)
      if (part.id == id)
        return true;
    return false;
  }

  template <int dim>
  Tensor<1, dim>
  BoundaryTraction<dim>::traction(const types::boundary_id id,
                                  const Point<dim>        &p,
                                  const Tensor<1, dim>    &n) const
  {
    for (const Part &part : parts)
      if (part.id == id)
        {
          if (part.from_reference)
            return reference->stress(p) * n;
          Tensor<1, dim> s;
          s[0] = n[1];
          s[1] = -n[0];
          return part.normal->value(p) * n + part.shear->value(p) * s;
        }
    return Tensor<1, dim>();
  }

  template <int dim>
  void
  BoundaryTraction<dim>::add_boundary_terms(
    const FEFaceValues<dim>          &fe_face_values,
    const types::boundary_id          id,
    const FEValuesExtractors::Vector &displacement,
    FullMatrix<double> &,
    Vector<double> &cell_rhs) const
  {
    for (const unsigned int q : fe_face_values.quadrature_point_indices())
      {
        const Tensor<1, dim> t = traction(id,
                                          fe_face_values.quadrature_point(q),
                                          fe_face_values.normal_vector(q)) *
                                 fe_face_values.JxW(q);
        for (const unsigned int i : fe_face_values.dof_indices())
          cell_rhs(i) += fe_face_values[displacement].value(i, q) * t;
      }
  }

  template class BoundaryTraction<2>;
} // namespace lithostress

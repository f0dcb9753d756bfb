#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/loads/boundary_traction.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/reference_solutions/reference_solution.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_q.h>

#include <cmath>
#include <limits>
#include <sstream>

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
        prm.declare_entry("Resultant force",
                          "",
                          Patterns::Anything(),
                          "Set the traction by force instead: the total "
                          "force `F_x, F_y` [N per m out of plane] on this "
                          "part, spread by the Resultant profile. Empty = "
                          "use the normal and shear tractions.");
        prm.declare_entry("Resultant profile",
                          "1",
                          Patterns::Anything(),
                          "Weight w(x, y) >= 0 [-] by which the resultant is "
                          "spread: t = F w / (integral of w over the part); "
                          "1 = uniform.");
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
  BoundaryTraction<dim>::read_parameters(ParameterHandler            &prm,
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
        part.name                   = name;
        part.from_reference         = prm.get_bool("Use reference solution");
        const std::string constants = prm.get("Constants");
        const auto        resultant = split_list(prm.get("Resultant force"));
        if (!resultant.empty())
          {
            if (resultant.size() != dim)
              throw_input_error(where + "Resultant force",
                                "needs " + std::to_string(dim) +
                                  " components F_x, F_y [N/m]");
            part.by_resultant = true;
            for (unsigned int d = 0; d < dim; ++d)
              part.resultant[d] =
                parse_number(resultant[d], where + "Resultant force");
            part.profile = std::make_unique<ParsedExpression<dim>>(
              prm.get("Resultant profile"),
              constants,
              where + "Resultant profile");
            if (Utilities::trim(prm.get("Normal traction")) != "0" ||
                Utilities::trim(prm.get("Shear traction")) != "0" ||
                part.from_reference)
              throw_input_error(where + "Resultant force",
                                "a part is loaded either by a resultant or "
                                "by normal/shear tractions (or the "
                                "reference solution), not both");
          }
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
          if (part.by_resultant)
            return part.resultant *
                   (part.profile->value(p) / part.profile_integral);
          Tensor<1, dim> s;
          s[0] = n[1];
          s[1] = -n[0];
          return part.normal->value(p, this->time()) * n +
                 part.shear->value(p, this->time()) * s;
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
    add_traction_terms(
      fe_face_values,
      displacement,
      [&](const unsigned int q) {
        return traction(id,
                        fe_face_values.quadrature_point(q),
                        fe_face_values.normal_vector(q));
      },
      cell_rhs);
  }

  template <int dim>
  void
  BoundaryTraction<dim>::add_traction_terms(
    const FEFaceValues<dim>                           &fe_face_values,
    const FEValuesExtractors::Vector                  &displacement,
    const std::function<Tensor<1, dim>(unsigned int)> &traction_at,
    Vector<double>                                    &cell_rhs)
  {
    for (const unsigned int q : fe_face_values.quadrature_point_indices())
      {
        const Tensor<1, dim> t = traction_at(q) * fe_face_values.JxW(q);
        for (const unsigned int i : fe_face_values.dof_indices())
          cell_rhs(i) += fe_face_values[displacement].value(i, q) * t;
      }
  }

  template <int dim>
  void
  BoundaryTraction<dim>::prepare_for_mesh(
    const Triangulation<dim>  &tria,
    const Mapping<dim>        &mapping,
    const Quadrature<dim - 1> &face_quadrature)
  {
    for (Part &part : parts)
      if (part.by_resultant)
        part.profile_integral =
          boundary_profile_integral(tria,
                                    mapping,
                                    face_quadrature,
                                    part.id,
                                    *part.profile,
                                    "Loads/Tractions/" + part.name +
                                      "/Resultant profile");
  }

  template <int dim>
  std::string
  BoundaryTraction<dim>::description() const
  {
    std::ostringstream out;
    out << "tractions on";
    for (const Part &part : parts)
      {
        out << " " << part.name << " (";
        if (part.from_reference)
          out << "reference solution";
        else if (part.by_resultant)
          out << "resultant " << part.resultant << " N/m, profile "
              << part.profile->text();
        else
          out << "normal " << part.normal->text() << " Pa, shear "
              << part.shear->text() << " Pa";
        out << ")";
      }
    return out.str();
  }

  template class BoundaryTraction<2>;
  LITHOSTRESS_REGISTER_LOAD(BoundaryTraction,
                            "boundary traction",
                            "normal and shear tractions on boundary parts",
                            40)
} // namespace lithostress

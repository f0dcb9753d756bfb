#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/loads/boundary_traction.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/loads/slab_pull.h>

#include <cmath>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  SlabPull<dim>::declare_parameters(ParameterHandler &prm, ParameterHandler *)
  {
    prm.enter_subsection("Slab pull");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Apply the pull of the truncated slab (thesis §7.4).");
    prm.declare_entry("Boundary part",
                      "base",
                      Patterns::Anything(),
                      "Boundary part on which the slab is truncated.");
    prm.declare_entry("Profile",
                      "1",
                      Patterns::Anything(),
                      "Weight w(x, y) >= 0 [-] spreading the force over the "
                      "part, t = F w / (integral of w); e.g. an indicator "
                      "of the truncated slab's section A-A.");
    prm.declare_entry("Constants",
                      "",
                      Patterns::Anything(),
                      "Constants for the profile: name=value, ...");
    prm.declare_entry("Vertical force",
                      "balance",
                      Patterns::Anything(),
                      "The downward pull P [N/m], or `balance`: the net "
                      "upthrust of all other loads, so that the applied "
                      "vertical forces sum to zero (the thesis's intent; it "
                      "quotes 8.95e12 and 3.95e12 N/m), measured on every new "
                      "mesh at the time it is made (loads that change in "
                      "time are balanced as they are then).");
    prm.declare_entry("Dip",
                      "90",
                      Patterns::Double(),
                      "Dip I of the pull [degrees], 0 < I <= 90: F_x = P / "
                      "tan(I) towards +x (down-dip), F_y = -P.");
    TimeFactor::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  bool
  SlabPull<dim>::parse_parameters(ParameterHandler            &prm,
                                  const ModelDescription<dim> &model)
  {
    const std::string where = "Loads/Slab pull/";
    prm.enter_subsection("Slab pull");
    const bool enabled             = prm.get_bool("Enabled");
    part_name                      = Utilities::trim(prm.get("Boundary part"));
    const std::string force_text   = Utilities::trim(prm.get("Vertical force"));
    const double      dip_degrees  = prm.get_double("Dip");
    const std::string profile_text = prm.get("Profile");
    const std::string constants    = prm.get("Constants");
    time_factor.parse_parameters(prm, where + "Time factor");
    prm.leave_subsection();
    if (!enabled)
      return false;

    part      = model.boundary_id(part_name, where + "Boundary part");
    profile   = std::make_unique<ParsedExpression<dim>>(profile_text,
                                                      constants,
                                                      where + "Profile");
    balancing = force_text == "balance";
    if (!balancing)
      {
        vertical_pull = parse_number(force_text, where + "Vertical force");
        if (!(vertical_pull > 0))
          throw_input_error(where + "Vertical force",
                            "must be `balance` or a positive downward pull "
                            "[N/m]");
      }
    if (!(dip_degrees > 0 && dip_degrees <= 90))
      throw_input_error(where + "Dip", "must lie in (0, 90] degrees");
    dip = dip_degrees * numbers::PI / 180;
    return true;
  }

  template <int dim>
  void
  SlabPull<dim>::balance(const double upthrust)
  {
    if (!(upthrust > 0))
      throw_input_error("Loads/Slab pull/Vertical force",
                        "is `balance`, but the other loads' net vertical "
                        "force is " +
                          std::to_string(upthrust) +
                          " N/m, not an upthrust: a slab pull cannot "
                          "balance it");
    vertical_pull = upthrust;
  }

  template <int dim>
  Tensor<1, dim>
  SlabPull<dim>::force() const
  {
    Tensor<1, dim> f;
    f[0]       = dip < 0.5 * numbers::PI ? vertical_pull / std::tan(dip) : 0;
    f[dim - 1] = -vertical_pull;
    return time_factor.value(this->time()) * f;
  }

  template <int dim>
  bool
  SlabPull<dim>::acts_on_boundary(const types::boundary_id id) const
  {
    return id == part;
  }

  template <int dim>
  void
  SlabPull<dim>::add_boundary_terms(
    const FEFaceValues<dim>          &fe_face_values,
    const types::boundary_id          id,
    const FEValuesExtractors::Vector &displacement,
    FullMatrix<double> &,
    Vector<double> &cell_rhs) const
  {
    if (id != part)
      return;
    const Tensor<1, dim> per_weight = force() / profile_integral;
    BoundaryTraction<dim>::add_traction_terms(
      fe_face_values,
      displacement,
      [&](const unsigned int q) {
        return per_weight * profile->value(fe_face_values.quadrature_point(q));
      },
      cell_rhs);
  }

  template <int dim>
  void
  SlabPull<dim>::prepare_for_mesh(const Triangulation<dim>  &tria,
                                  const Mapping<dim>        &mapping,
                                  const Quadrature<dim - 1> &face_quadrature)
  {
    profile_integral = boundary_profile_integral(tria,
                                                 mapping,
                                                 face_quadrature,
                                                 part,
                                                 *profile,
                                                 "Loads/Slab pull/Profile");
  }

  template <int dim>
  std::string
  SlabPull<dim>::description() const
  {
    std::ostringstream out;
    out << "slab pull on " << part_name << " (dip " << dip * 180 / numbers::PI
        << " deg, vertical "
        << (balancing ? "balancing the other loads" : "given") << ", profile "
        << profile->text()
        << (time_factor.is_one() ? "" : ", times " + time_factor.text()) << ")";
    return out.str();
  }

  template class SlabPull<2>;
  LITHOSTRESS_REGISTER_LOAD(
    SlabPull,
    "slab pull",
    "a resultant pull spread over a boundary part (thesis §7.4)",
    70)
} // namespace lithostress

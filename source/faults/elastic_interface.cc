#include <lithostress/base/input_error.h>
#include <lithostress/faults/elastic_interface.h>

#include <cctype>
#include <cmath>
#include <sstream>
#include <utility>

namespace lithostress
{
  namespace
  {
    /** The largest stiffness per unit area of an interface [Pa/m]. */
    constexpr double max_stiffness = 1e30;
  } // namespace

  template <int dim>
  void
  ElasticInterface<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Shear stiffness",
                      "",
                      Patterns::Anything(),
                      "k_s per unit fault area [Pa/m] (elastic law): "
                      "the shear traction per metre of slip. The "
                      "thesis's element stiffness [N/m] is k_s times "
                      "its fault element's length (thesis §5.4).");
    prm.declare_entry(
      "Normal stiffness",
      "exact",
      Patterns::Anything(),
      "exact = exact normal contact (elastic and frictional laws): "
      "the two sides neither open nor interpenetrate where the fault "
      "is in compression (constraints on the normal jump, whose "
      "reactions are the normal traction), and a frictional fault "
      "opens where the normal traction would be tensile; or k_n per "
      "unit fault area [Pa/m]: the thesis's normal spring (thesis "
      "§5.4), the normal traction per metre of opening.");
    prm.declare_entry("Thesis element length",
                      "",
                      Patterns::Anything(),
                      "For the thesis's input (thesis §5.4): if set, the "
                      "two stiffnesses are the thesis's element "
                      "stiffnesses [N/m] of fault elements of this "
                      "length l [length unit], and the stiffness per "
                      "unit area is k/l. Empty = per unit area.");
  }

  template <int dim>
  void
  ElasticInterface<dim>::parse_parameters(ParameterHandler  &prm,
                                          const std::string &fault,
                                          const GravityField &,
                                          const double length_scale)
  {
    parse_stiffnesses(prm, fault, "elastic", length_scale);
    friction.slides = false;
  }

  template <int dim>
  void
  ElasticInterface<dim>::parse_stiffnesses(ParameterHandler  &prm,
                                           const std::string &fault,
                                           const std::string &law,
                                           const double       length_scale)
  {
    const auto number = [&](const std::string &name) {
      return fault_law_number(prm, fault, name, law, 0, false);
    };
    CoulombFriction &f       = friction;
    f.shear_stiffness        = number("Shear stiffness");
    const std::string normal = Utilities::trim(prm.get("Normal stiffness"));
    f.exact_contact          = normal == "exact";
    if (!f.exact_contact && !normal.empty() &&
        !std::isdigit(static_cast<unsigned char>(normal[0])) &&
        normal[0] != '.' && normal[0] != '+' && normal[0] != '-')
      throw_input_error("Faults/" + fault + "/Normal stiffness",
                        "must be `exact` or a stiffness per unit "
                        "area [Pa/m], got <" +
                          normal + ">");
    if (!f.exact_contact)
      f.normal_stiffness = number("Normal stiffness");
    if (!Utilities::trim(prm.get("Thesis element length")).empty())
      {
        const double l = number("Thesis element length") * length_scale;
        f.shear_stiffness /= l;
        f.normal_stiffness /= l;
      }
    // A stiffness per area the assembly would overflow with (a Thesis
    // element length of 1e-300 km turns 5e10 N/m into 5e307 Pa/m, and the
    // tangent into infinities) is named here. 1e30 Pa/m is 1e16 times a
    // rock's E per metre: far stiffer than any fault needs to be (a locked
    // one is `Interface law = locked`).
    for (const auto &[k, name] :
         {std::make_pair(f.shear_stiffness, "Shear stiffness"),
          std::make_pair(f.normal_stiffness, "Normal stiffness")})
      if (!(std::abs(k) <= max_stiffness))
        {
          std::ostringstream what;
          what << "gives a stiffness per unit area of " << k << " Pa/m, beyond "
               << max_stiffness
               << " Pa/m (for a fault that does not slip use Interface "
                  "law = locked)";
          throw_input_error(
            "Faults/" + fault + "/" +
              (Utilities::trim(prm.get("Thesis element length")).empty()
                 ? std::string(name)
                 : std::string("Thesis element length")),
            what.str());
        }
  }

  template <int dim>
  Tensor<2, 2>
  ElasticInterface<dim>::stuck_stiffness() const
  {
    Tensor<2, 2> K;
    K[0][0] = friction.shear_stiffness;
    K[1][1] = friction.exact_contact ? 0. : friction.normal_stiffness;
    return K;
  }

  template <int dim>
  InterfaceResponse
  ElasticInterface<dim>::predictor(const InterfaceLawInputs &in) const
  {
    InterfaceResponse r;
    const double      p = in.history.size() == 0 ? 0. : in.history[0];
    r.tangent           = stuck_stiffness();
    r.shear_traction    = friction.shear_stiffness * (in.shear_jump - p);
    r.normal_traction   = r.tangent[1][1] * in.normal_jump;
    r.history.assign(in.history.begin(), in.history.end());
    return r;
  }

  template <int dim>
  InterfaceResponse
  ElasticInterface<dim>::evaluate(const InterfaceLawInputs &in) const
  {
    return respond(in, 0);
  }

  template <int dim>
  InterfaceResponse
  ElasticInterface<dim>::respond(const InterfaceLawInputs &in,
                                 const double              p_old) const
  {
    const CoulombFriction::Response c =
      in.welded       ? friction.welded(in.shear_jump, p_old)
      : in.in_contact ? friction.respond_in_contact(in.shear_jump,
                                                    in.contact_traction,
                                                    in.closed,
                                                    p_old,
                                                    in.overburden_depth)
                      : friction.respond(in.shear_jump,
                                         in.normal_jump,
                                         p_old,
                                         in.overburden_depth);
    InterfaceResponse r;
    r.shear_traction          = c.shear_traction;
    r.normal_traction         = c.normal_traction;
    r.effective_normal_stress = c.effective_normal_stress;
    r.friction_limit          = c.friction_limit;
    r.friction_coefficient =
      friction.slides ? friction.friction_coefficient : 0.;
    r.tangent = c.tangent;
    r.state   = c.state;
    if (friction.slides)
      r.history = {c.plastic_slip};
    return r;
  }

  template class ElasticInterface<2>;
  LITHOSTRESS_REGISTER_INTERFACE_LAW(
    ElasticInterface,
    "elastic",
    "the traction is K w, w = u(hanging wall) - u(footwall), K = "
    "diag(Shear stiffness, Normal stiffness) in the fault's (shear, normal) "
    "frame (thesis §5.4)",
    10)
} // namespace lithostress

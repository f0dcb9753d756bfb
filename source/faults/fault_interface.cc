#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/faults/fault_interface.h>

#include <algorithm>
#include <cctype>
#include <map>

// FaultInterface's parameters and queries; the topology is in
// fault_topology.cc, the constraints in fault_constraints.cc and the
// interface quadrature with its face terms in fault_assembly.cc.

namespace lithostress
{
  template <int dim>
  void
  FaultInterface<dim>::declare_parameters(ParameterHandler &prm,
                                          ParameterHandler *first_pass)
  {
    const std::vector<std::string> names =
      ParameterFile::names_from(first_pass, {"Faults"}, "Names", {"fault"});
    prm.enter_subsection("Faults");
    prm.declare_entry("Names",
                      "",
                      Patterns::Anything(),
                      "Comma separated names of the geometry's faults (a "
                      "layered box with `Fault surface x` has one, `fault`); "
                      "each gets a subsection with its interface law.");
    for (const std::string &name : names)
      {
        prm.enter_subsection(name);
        prm.declare_entry("Interface law",
                          "locked",
                          Patterns::Selection(
                            "locked|elastic|frictional|prescribed slip"),
                          "locked = the displacement is continuous across "
                          "the fault (exact constraints, thesis §5's "
                          "k = 1e15 N/m without its penalty); elastic = the "
                          "traction is K w, w = u(hanging wall) - "
                          "u(footwall), K = diag(Shear stiffness, Normal "
                          "stiffness) in the fault's (shear, normal) frame; "
                          "frictional = elastic until the shear traction "
                          "reaches mu |sigma_n,eff|, then Coulomb sliding "
                          "(thesis §5.5; solved by the Sliding solver); "
                          "prescribed slip = the jump is Slip along the dip "
                          "plus Opening along the normal (kinematic, exact "
                          "constraints).");
        prm.declare_entry(
          "Slip",
          "0",
          Patterns::Anything(),
          "Prescribed slip: the slip [m] down the dip "
          "(positive = normal sense, hanging wall down) as a "
          "function of s, the distance along the fault from "
          "its upper end (the surface trace or a buried tip) [m], and t [s].");
        prm.declare_entry("Opening",
                          "0",
                          Patterns::Anything(),
                          "Prescribed slip: the opening [m] along the normal "
                          "(into the hanging wall) as a function of s [m] and "
                          "t [s].");
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
        prm.declare_entry("Friction coefficient",
                          "0.1",
                          Patterns::Anything(),
                          "mu of the frictional law (thesis: 0.1).");
        prm.declare_entry(
          "Lithostatic density",
          "2911",
          Patterns::Anything(),
          "rho_l [kg/m^3] of the lithostatic normal stress rho_l g depth "
          "that the frictional law adds to the model's normal traction "
          "(FSHEAR's 2911, for models without body forces); 0 = none, for "
          "models whose stresses include gravity.");
        prm.declare_entry("Pore fluid density",
                          "1000",
                          Patterns::Anything(),
                          "rho_w [kg/m^3] of the hydrostatic pore pressure "
                          "rho_w g depth subtracted from the compression "
                          "(FSHEAR's 1000); 0 = dry.");
        prm.declare_entry(
          "Overburden depth from",
          "fault top",
          Patterns::Selection("fault top|sea level"),
          "Where the depth of the lithostatic and pore pressures is "
          "measured from: fault top = the upper end of the fault's trace "
          "(on the top surface; above a buried tip, where its welded "
          "extension meets the surface); sea level = y = 0, as FSHEAR "
          "measures both (thesis appendix: SLITH = 2911 g y and POREP = "
          "1000 g y with y the coordinate below sea level), which adds the "
          "water depth above a submarine fault's trace to both.");
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }

  template <int dim>
  void
  FaultInterface<dim>::parse_parameters(ParameterHandler              &prm,
                                        const std::vector<FaultTrace> &traces,
                                        const GravityField            &gravity,
                                        const double length_scale)
  {
    faults.clear();
    prm.enter_subsection("Faults");
    const std::vector<std::string> names = split_list(prm.get("Names"));
    std::string                    trace_names;
    for (const FaultTrace &trace : traces)
      trace_names += (trace_names.empty() ? "<" : ", <") + trace.name + ">";
    for (const std::string &name : names)
      {
        bool known = false;
        for (const FaultTrace &trace : traces)
          known = known || trace.name == name;
        if (!known)
          throw_input_error("Faults/Names",
                            "<" + name + "> is not a fault of the geometry" +
                              (traces.empty()
                                 ? std::string(" (it has none)")
                                 : " (its faults: " + trace_names + ")"));
      }
    for (const FaultTrace &trace : traces)
      {
        if (std::find(names.begin(), names.end(), trace.name) == names.end())
          throw_input_error("Faults/Names",
                            "the geometry has the fault <" + trace.name +
                              ">: name it here and give its Interface law");
        prm.enter_subsection(trace.name);
        Fault fault;
        fault.trace           = trace;
        const std::string law = prm.get("Interface law");
        fault.law             = law == "elastic"           ? Law::elastic
                                : law == "frictional"      ? Law::frictional
                                : law == "prescribed slip" ? Law::prescribed_slip
                                                           : Law::locked;
        if (fault.law == Law::prescribed_slip)
          {
            const auto function = [&](const std::string &name) {
              auto f = std::make_shared<FunctionParser<1>>(1, 0.0);
              try
                {
                  f->initialize("s,t",
                                prm.get(name),
                                std::map<std::string, double>(),
                                true);
                }
              catch (const std::exception &e)
                {
                  throw_input_error("Faults/" + trace.name + "/" + name,
                                    "<" + prm.get(name) +
                                      "> is not an expression of s and t");
                }
              return f;
            };
            fault.slip    = function("Slip");
            fault.opening = function("Opening");
          }
        const auto entry = [&](const std::string &name) {
          return "Faults/" + trace.name + "/" + name;
        };
        const auto number = [&](const std::string &name,
                                const double       lowest,
                                const bool         inclusive) {
          const std::string text = Utilities::trim(prm.get(name));
          if (text.empty())
            throw_input_error(entry(name), "is needed by the " + law + " law");
          const double value = parse_number(text, entry(name));
          if (inclusive ? !(value >= lowest) : !(value > lowest))
            throw_input_error(entry(name),
                              std::string("must be ") +
                                (inclusive ? "at least " : "greater than ") +
                                (lowest == 0 ? "0" : std::to_string(lowest)) +
                                ", got " + text);
          return value;
        };
        if (fault.law == Law::elastic || fault.law == Law::frictional)
          {
            CoulombFriction &f = fault.friction;
            f.shear_stiffness  = number("Shear stiffness", 0, false);
            f.exact_contact =
              Utilities::trim(prm.get("Normal stiffness")) == "exact";
            const std::string normal =
              Utilities::trim(prm.get("Normal stiffness"));
            if (!f.exact_contact && !normal.empty() &&
                !std::isdigit(static_cast<unsigned char>(normal[0])) &&
                normal[0] != '.' && normal[0] != '+' && normal[0] != '-')
              throw_input_error(entry("Normal stiffness"),
                                "must be `exact` or a stiffness per unit "
                                "area [Pa/m], got <" +
                                  normal + ">");
            if (!f.exact_contact)
              f.normal_stiffness = number("Normal stiffness", 0, false);
            const std::string length =
              Utilities::trim(prm.get("Thesis element length"));
            if (!length.empty())
              {
                const double l =
                  number("Thesis element length", 0, false) * length_scale;
                f.shear_stiffness /= l;
                f.normal_stiffness /= l;
              }
          }
        fault.friction.slides = fault.law == Law::frictional;
        if (fault.law == Law::frictional)
          {
            CoulombFriction &f     = fault.friction;
            f.friction_coefficient = number("Friction coefficient", 0, true);
            f.lithostatic_density  = number("Lithostatic density", 0, true);
            f.pore_fluid_density   = number("Pore fluid density", 0, true);
            f.gravity              = gravity.acceleration;
            fault.overburden_from_sea_level =
              prm.get("Overburden depth from") == "sea level";
          }
        prm.leave_subsection();
        faults.push_back(fault);
      }
    prm.leave_subsection();
  }

  template <int dim>
  bool
  FaultInterface<dim>::has_face_terms() const
  {
    for (const Fault &fault : faults)
      if (fault.law == Law::elastic || fault.law == Law::frictional)
        return true;
    return false;
  }

  template <int dim>
  bool
  FaultInterface<dim>::frictional() const
  {
    for (const Fault &fault : faults)
      if (fault.law == Law::frictional)
        return true;
    return false;
  }

  template <int dim>
  bool
  FaultInterface<dim>::contact() const
  {
    for (const Fault &fault : faults)
      if ((fault.law == Law::elastic || fault.law == Law::frictional) &&
          fault.friction.exact_contact)
        return true;
    return false;
  }

  template <int dim>
  std::string
  FaultInterface<dim>::frictional_names() const
  {
    std::string  names;
    unsigned int n = 0;
    for (const Fault &fault : faults)
      if (fault.law == Law::frictional ||
          (fault.law == Law::elastic && fault.friction.exact_contact))
        names += (n++ == 0 ? "<" : ", <") + fault.trace.name + ">";
    return (n > 1 ? "faults " : "fault ") + names;
  }

  // The members defined here and in the header; fault_topology.cc,
  // fault_constraints.cc and fault_assembly.cc instantiate their own.
  template class FaultInterface<2>;
} // namespace lithostress

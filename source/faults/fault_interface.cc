#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/faults/elastic_interface.h>
#include <lithostress/faults/fault_interface.h>

#include <algorithm>
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
                            InterfaceLawRegistry<dim>::names()),
                          InterfaceLawRegistry<dim>::documentation() + ".");
        InterfaceLawRegistry<dim>::declare_parameters(prm, first_pass);
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
        fault.trace    = trace;
        fault.law_name = prm.get("Interface law");
        fault.law      = InterfaceLawRegistry<dim>::find(fault.law_name,
                                                    "Faults/" + trace.name +
                                                      "/Interface law")
                      .create();
        fault.law->parse_parameters(prm, trace.name, gravity, length_scale);
        prm.leave_subsection();
        faults.push_back(fault);
      }
    prm.leave_subsection();
  }

  template <int dim>
  bool
  FaultInterface<dim>::has_face_terms() const
  {
    return std::any_of(faults.begin(), faults.end(), [](const Fault &fault) {
      return fault.law->has_face_terms();
    });
  }

  template <int dim>
  bool
  FaultInterface<dim>::frictional() const
  {
    return std::any_of(faults.begin(), faults.end(), [](const Fault &fault) {
      return fault.law->nonlinear();
    });
  }

  template <int dim>
  bool
  FaultInterface<dim>::contact() const
  {
    return std::any_of(faults.begin(), faults.end(), [](const Fault &fault) {
      return fault.law->has_face_terms() && fault.law->exact_contact();
    });
  }

  template <int dim>
  std::vector<std::vector<std::string>>
  FaultInterface<dim>::history_names() const
  {
    std::vector<std::vector<std::string>> names;
    for (const Fault &fault : faults)
      names.push_back(fault.law->history_names());
    return names;
  }

  template <int dim>
  const CoulombFriction &
  FaultInterface<dim>::coulomb_friction(const unsigned int k) const
  {
    const auto *spring =
      dynamic_cast<const ElasticInterface<dim> *>(faults[k].law.get());
    if (spring == nullptr)
      throw ComputationError("the thesis's iteration and element stresses "
                             "need Coulomb friction, and fault <" +
                             faults[k].trace.name + "> has the law <" +
                             faults[k].law_name +
                             ">: set Faults/Sliding solver/Method = newton");
    return spring->coulomb();
  }

  template <int dim>
  std::string
  FaultInterface<dim>::frictional_names() const
  {
    std::string  names;
    unsigned int n = 0;
    for (const Fault &fault : faults)
      if (fault.law->nonlinear() ||
          (fault.law->has_face_terms() && fault.law->exact_contact()))
        names += (n++ == 0 ? "<" : ", <") + fault.trace.name + ">";
    return (n > 1 ? "faults " : "fault ") + names;
  }

  // The members defined here and in the header; fault_topology.cc,
  // fault_constraints.cc and fault_assembly.cc instantiate their own.
  template class FaultInterface<2>;
} // namespace lithostress

#include <lithostress/base/input_error.h>
#include <lithostress/faults/prescribed_slip_interface.h>

#include <map>

namespace lithostress
{
  template <int dim>
  void
  PrescribedSlipInterface<dim>::declare_parameters(ParameterHandler &prm)
  {
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
  }

  template <int dim>
  void
  PrescribedSlipInterface<dim>::parse_parameters(ParameterHandler  &prm,
                                                 const std::string &fault,
                                                 const GravityField &,
                                                 const double)
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
          throw_input_error("Faults/" + fault + "/" + name,
                            "<" + prm.get(name) +
                              "> is not an expression of s and t");
        }
      return f;
    };
    slip    = function("Slip");
    opening = function("Opening");
  }

  template <int dim>
  Tensor<1, 2>
  PrescribedSlipInterface<dim>::prescribed_jump(const double s,
                                                const double time) const
  {
    const Point<1> at(s);
    slip->set_time(time);
    opening->set_time(time);
    Tensor<1, 2> jump;
    jump[0] = slip->value(at);
    jump[1] = opening->value(at);
    return jump;
  }

  template class PrescribedSlipInterface<2>;
  LITHOSTRESS_REGISTER_INTERFACE_LAW(
    PrescribedSlipInterface,
    "prescribed slip",
    "the jump is Slip along the dip plus Opening along the normal "
    "(kinematic, exact constraints)",
    30)
} // namespace lithostress

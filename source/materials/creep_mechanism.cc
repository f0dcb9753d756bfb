#include <lithostress/base/input_error.h>
#include <lithostress/materials/creep_mechanism.h>

#include <cmath>

namespace lithostress
{
  void
  CreepMechanism::declare_parameters(ParameterHandler  &prm,
                                     const std::string &name,
                                     const double       default_exponent)
  {
    prm.declare_entry(name + " prefactor",
                      "0",
                      Patterns::Double(0),
                      "A of " + name +
                        " in the invariant form eps_II = A tau_II^n "
                        "exp(-(E + P V)/(R T)) [Pa^-n s^-1]; 0: none "
                        "(Rheology = visco-elasto-plastic; doc/equations.md "
                        "converts laboratory flow laws to this form)");
    prm.declare_entry(name + " stress exponent",
                      std::to_string(default_exponent),
                      Patterns::Double(1),
                      "n of " + name + " (at least 1)");
    prm.declare_entry(name + " activation energy",
                      "0",
                      Patterns::Double(0),
                      "E of " + name + " [J/mol]");
    prm.declare_entry(name + " activation volume",
                      "0",
                      Patterns::Double(),
                      "V of " + name + " [m^3/mol]");
  }

  void
  CreepMechanism::parse_parameters(ParameterHandler  &prm,
                                   const std::string &name,
                                   const std::string &material)
  {
    this->name              = name;
    prefactor               = prm.get_double(name + " prefactor");
    exponent                = prm.get_double(name + " stress exponent");
    activation_energy       = prm.get_double(name + " activation energy");
    activation_volume       = prm.get_double(name + " activation volume");
    const std::string entry = "Materials/" + material + "/" + name;
    if (!std::isfinite(prefactor) || prefactor < 0)
      throw_input_error(entry + " prefactor", "must be zero or positive");
    if (!(exponent >= 1) || exponent > 20)
      throw_input_error(entry + " stress exponent",
                        "must lie between 1 and 20");
  }

  double
  CreepMechanism::rate_factor(const double temperature,
                              const double pressure) const
  {
    if (activation_energy == 0 && activation_volume == 0)
      return prefactor;
    // The limit T → 0 of a temperature-activated law: no creep.
    if (!(temperature > 0))
      return 0;
    return prefactor *
           std::exp(-(activation_energy + pressure * activation_volume) /
                    (gas_constant * temperature));
  }
} // namespace lithostress

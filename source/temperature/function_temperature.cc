#include <lithostress/base/input_error.h>
#include <lithostress/temperature/function_temperature.h>

#include <iomanip>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  FunctionTemperature<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Function");
    prm.declare_entry("Expression",
                      "",
                      Patterns::Anything(),
                      "Model = function: the temperature [K] as a function "
                      "of x, y [m] (muparser), above 0 K everywhere in the "
                      "model.");
    prm.declare_entry("Constants",
                      "",
                      Patterns::Anything(),
                      "Constants for the expression: name=value, ...");
    prm.leave_subsection();
  }

  template <int dim>
  void
  FunctionTemperature<dim>::parse_parameters(ParameterHandler &prm,
                                             const double)
  {
    prm.enter_subsection("Function");
    const std::string text = Utilities::trim(prm.get("Expression"));
    if (text.empty())
      throw_input_error("Temperature/Function/Expression",
                        "is empty; Model = function needs the temperature "
                        "[K] as a function of x, y [m]");
    expression = std::make_unique<ParsedExpression<dim>>(
      text, prm.get("Constants"), "Temperature/Function/Expression");
    prm.leave_subsection();
  }

  template <int dim>
  double
  FunctionTemperature<dim>::value(const Point<dim> &p) const
  {
    const double t = expression->value(p);
    if (!(t > 0))
      {
        std::ostringstream what;
        what << std::setprecision(6) << "gives " << t << " K at (x, y) = ("
             << p[0] << ", " << p[1]
             << ") m; an absolute temperature must be above 0 K";
        throw_input_error("Temperature/Function/Expression", what.str());
      }
    return t;
  }

  template class FunctionTemperature<2>;

  LITHOSTRESS_REGISTER_TEMPERATURE_MODEL(
    FunctionTemperature,
    "function",
    "the temperature as a function of x and y (Temperature/Function)");
} // namespace lithostress

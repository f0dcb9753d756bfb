#include <deal.II/base/utilities.h>

#include <lithostress/base/time_units.h>
#include <lithostress/loads/time_factor.h>

#include <iomanip>
#include <sstream>

namespace lithostress
{
  void
  TimeFactor::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Time factor",
                      "1",
                      Patterns::Anything(),
                      "Factor f(t) [-] on these loads in the time loop, a "
                      "function of t [s] with the constants yr and Myr [s], "
                      "e.g. min(t/(0.1*Myr), 1): load steps that raise a load "
                      "beyond the yield strength from zero.");
  }

  void
  TimeFactor::parse_parameters(ParameterHandler &prm, const std::string &entry)
  {
    const std::string text = Utilities::trim(prm.get("Time factor"));
    if (text == "1")
      {
        expression.reset();
        return;
      }
    std::ostringstream constants;
    constants << std::setprecision(17) << "yr=" << seconds_per_year
              << ", Myr=" << 1e6 * seconds_per_year;
    expression =
      std::make_unique<ParsedExpression<2>>(text, constants.str(), entry);
  }

  double
  TimeFactor::value(const double time) const
  {
    return expression ? expression->value(Point<2>(), time) : 1.0;
  }

  std::string
  TimeFactor::text() const
  {
    return expression ? expression->text() : "1";
  }
} // namespace lithostress

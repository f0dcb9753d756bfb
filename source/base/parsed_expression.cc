#include <deal.II/base/utilities.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/base/parsed_expression.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace lithostress
{
  template <int dim>
  ParsedExpression<dim>::ParsedExpression(const std::string &text,
                                          const std::string &constants_text,
                                          const std::string &entry)
      : expression(text)
      , entry(entry)
  {
    std::map<std::string, double> constants;
    for (const std::string &item : split_list(constants_text))
      {
        const auto equal = item.find('=');
        if (equal == std::string::npos)
          throw_input_error(entry,
                            "constant <" + item +
                              "> is not of the form name=number");
        const double value = parse_number(item.substr(equal + 1), entry);
        constants[Utilities::trim(item.substr(0, equal))] = value;
      }
    const std::string variables = (dim == 2) ? "x,y,t" : "x,y,z,t";
    // muparser's own report goes to std::cerr; keep it out of the one-line
    // error message.
    std::ostringstream    muparser_report;
    std::streambuf *const cerr_buffer =
      std::cerr.rdbuf(muparser_report.rdbuf());
    try
      {
        function = std::make_unique<FunctionParser<dim>>(1);
        function->initialize(variables, expression, constants, true);
        function->value(Point<dim>());
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (const ExceptionBase &exc)
      {
        std::cerr.rdbuf(cerr_buffer);
        const std::string m =
          one_line_message(exc) + " " + one_line(muparser_report.str());
        throw_input_error(entry,
                          "cannot parse the expression <" + expression +
                            ">: " + m);
      }
  }

  template <int dim>
  double
  ParsedExpression<dim>::value(const Point<dim> &p, const double time) const
  {
    function->set_time(time);
    const double v = function->value(p);
    if (!std::isfinite(v))
      {
        std::ostringstream where;
        where << std::setprecision(6) << "(x, y) = (" << p[0];
        for (unsigned int d = 1; d < dim; ++d)
          where << ", " << p[d];
        where << ") m, t = " << time << " s";
        throw_input_error(entry,
                          "the expression <" + expression + "> is " +
                            (std::isnan(v) ? "not a number" : "infinite") +
                            " at " + where.str());
      }
    return v;
  }

  template class ParsedExpression<2>;
} // namespace lithostress

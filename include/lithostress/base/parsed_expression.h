#ifndef lithostress_base_parsed_expression_h
#define lithostress_base_parsed_expression_h

#include <deal.II/base/function_parser.h>

#include <memory>
#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * A scalar function of position (x, y in metres) and time t, given in the
   * input as a muparser expression with optional constants
   * ("P=5e4, c=1.25"). Parsed and evaluated once when configured, so that a
   * malformed expression is an input error naming its entry.
   */
  template <int dim>
  class ParsedExpression
  {
  public:
    /** Parse @p expression; @p entry names it in error messages. */
    ParsedExpression(const std::string &expression,
                     const std::string &constants,
                     const std::string &entry);

    double
    value(const Point<dim> &p, const double time = 0) const;

    const std::string &
    text() const
    {
      return expression;
    }

  private:
    std::string                          expression;
    std::unique_ptr<FunctionParser<dim>> function;
  };
} // namespace lithostress

#endif

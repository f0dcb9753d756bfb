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
   * malformed expression is an input error naming its entry. Every value is
   * checked where it is evaluated: a NaN or an infinity (`1/0`, `sqrt(-1)`
   * somewhere in the body) is an InputError naming the entry, the point and
   * the time.
   */
  template <int dim>
  class ParsedExpression
  {
  public:
    /** Parse @p expression; @p entry names it in error messages. */
    ParsedExpression(const std::string &expression,
                     const std::string &constants,
                     const std::string &entry);

    /** The value at @p p [m] and @p time [s]; InputError if not finite. */
    double
    value(const Point<dim> &p, const double time = 0) const;

    const std::string &
    text() const
    {
      return expression;
    }

  private:
    std::string                          expression;
    std::string                          entry;
    std::unique_ptr<FunctionParser<dim>> function;
  };
} // namespace lithostress

#endif

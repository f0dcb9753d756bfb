#ifndef lithostress_temperature_function_temperature_h
#define lithostress_temperature_function_temperature_h

#include <lithostress/base/parsed_expression.h>
#include <lithostress/temperature/temperature_model.h>

#include <memory>

namespace lithostress
{
  /**
   * `Temperature/Model = function`: the temperature [K] as a muparser
   * expression of x, y [m] (`Temperature/Function/Expression`, with
   * `Constants`), e.g. a geotherm read off a published profile. Every value
   * must be a finite absolute temperature, above 0 K.
   */
  template <int dim>
  class FunctionTemperature : public PointwiseTemperature<dim>
  {
  public:
    /** Declare the subsection `Function`. */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const double length_scale) override;

    double
    value(const Point<dim> &p) const override;

  private:
    std::unique_ptr<ParsedExpression<dim>> expression;
  };
} // namespace lithostress

#endif

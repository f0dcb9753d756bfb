#ifndef lithostress_loads_time_factor_h
#define lithostress_loads_time_factor_h

#include <deal.II/base/parameter_handler.h>

#include <lithostress/base/parsed_expression.h>

#include <memory>
#include <string>

namespace lithostress
{
  /**
   * The factor f(t) by which a load of fixed size (line forces, the slab
   * pull) is scaled in the time loop: `Time factor`, a muparser expression
   * of t [s] with the constants yr and Myr [s] (e.g. `min(t/(0.1*Myr),
   * 1)`). It turns the time loop into load steps (doc/equations.md §13): a
   * load beyond the yield strength is raised from f(0) = 0, so that each
   * step's Newton iteration starts near its solution, and a step that does
   * not converge is repeated with a shorter one, i.e. a smaller load
   * increment.
   */
  class TimeFactor
  {
  public:
    /** Declare `Time factor` (default 1) in the current subsection. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read it; @p entry names it in error messages. */
    void
    parse_parameters(ParameterHandler &prm, const std::string &entry);

    /** f(@p time [s]); an InputError naming the entry if not finite. */
    double
    value(const double time) const;

    /** The expression as given. */
    std::string
    text() const;

    /** Whether the factor is the constant 1 (the default). */
    bool
    is_one() const
    {
      return !expression;
    }

  private:
    std::unique_ptr<ParsedExpression<2>> expression;
  };
} // namespace lithostress

#endif

#ifndef lithostress_postprocessors_force_balance_output_h
#define lithostress_postprocessors_force_balance_output_h

#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  /** The resultant of every load and the reaction of every part with
   * prescribed displacement after the last cycle (`Output/Force
   * balance`): printed and written to force_balance.csv [N/m]. */
  template <int dim>
  class ForceBalanceOutput : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler           &prm,
                     const SimulatorAccess<dim> &access) override;

    void
    finish(const SimulatorAccess<dim> &access) override;

  private:
    bool enabled = true;
  };
} // namespace lithostress

#endif

#ifndef lithostress_postprocessors_convergence_table_h
#define lithostress_postprocessors_convergence_table_h

#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  /** The convergence table of the refinement cycles (DoFs, errors and
   * rates, point values, goals), printed at the end of the run; the
   * cycles write it to convergence.csv as they go (RefinementCycles). */
  template <int dim>
  class ConvergenceTableReport : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {}

    void
    finish(const SimulatorAccess<dim> &access) override;
  };
} // namespace lithostress

#endif

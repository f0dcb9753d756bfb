#ifndef lithostress_postprocessors_error_norms_report_h
#define lithostress_postprocessors_error_norms_report_h

#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  /** With a reference solution (Convergence study/Reference solution):
   * the L2 errors of displacement and stress and the energy error, absolute
   * and relative, as columns of the convergence table and in the cycle's
   * progress line (thesis §4.3–4.5 compare with exact solutions). */
  template <int dim>
  class ErrorNormsReport : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {}

    void
    cycle_finished(const SimulatorAccess<dim> &access,
                   const unsigned int          cycle,
                   ConvergenceStudy           &study,
                   std::ostream               &progress) override;
  };
} // namespace lithostress

#endif

#ifndef lithostress_postprocessors_run_statistics_h
#define lithostress_postprocessors_run_statistics_h

#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  /** The solver's wall time by phase (printed) and statistics.json:
   * sizes, iterations, timings and peak memory of the last solve, read by
   * bench/run; also written when a run is interrupted. */
  template <int dim>
  class RunStatistics : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {}

    void
    finish(const SimulatorAccess<dim> &access) override;

    void
    interrupted(const SimulatorAccess<dim> &access) override;
  };

  /** Write statistics.json (collective; rank 0 writes). */
  template <int dim>
  void
  write_statistics(const SimulatorAccess<dim> &access);
} // namespace lithostress

#endif

#ifndef lithostress_postprocessors_fault_results_output_h
#define lithostress_postprocessors_fault_results_output_h

#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  /** Each elastic or frictional fault's fault.csv (slip, opening,
   * tractions, state along it) and fault_summary.json (throw, sliding
   * depth, iterations, distance of tensile failure; thesis §6.1);
   * fault_<name>.csv and fault_summary_<name>.json when the model has
   * several faults, and in the time loop also fault-NNNNN.csv per output
   * time. Also written with the last iterate of a failed sliding solve. */
  template <int dim>
  class FaultResultsOutput : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {}

    void
    parse_parameters(ParameterHandler           &prm,
                     const SimulatorAccess<dim> &access) override;

    void
    cycle_finished(const SimulatorAccess<dim> &access,
                   const unsigned int          cycle,
                   ConvergenceStudy           &study,
                   std::ostream               &progress) override;

    void
    output_time(const SimulatorAccess<dim> &access,
                const unsigned int          index,
                const double                time) override;

    void
    solve_failed(const SimulatorAccess<dim> &access) override;

  private:
    /** Write the files; @p output_index ≥ 0 adds the numbered copy. */
    void
    write(const SimulatorAccess<dim> &access, const int output_index) const;

    types::boundary_id top = numbers::invalid_boundary_id;
  };
} // namespace lithostress

#endif

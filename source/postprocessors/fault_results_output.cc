#include <lithostress/analysis/fault_output.h>
#include <lithostress/base/input_error.h>
#include <lithostress/postprocessors/fault_results_output.h>
#include <lithostress/postprocessors/surface_profile_output.h>

#include <cmath>

namespace lithostress
{
  template <int dim>
  void
  FaultResultsOutput<dim>::parse_parameters(ParameterHandler           &prm,
                                            const SimulatorAccess<dim> &a)
  {
    // The surface on which the distance of tensile failure is sought.
    top = surface_boundary(prm, a);
  }

  template <int dim>
  void
  FaultResultsOutput<dim>::cycle_finished(const SimulatorAccess<dim> &a,
                                          const unsigned int,
                                          ConvergenceStudy &,
                                          std::ostream &)
  {
    if (a.faults.has_face_terms())
      write(a, -1);
  }

  template <int dim>
  void
  FaultResultsOutput<dim>::output_time(const SimulatorAccess<dim> &a,
                                       const unsigned int          index,
                                       const double)
  {
    if (a.faults.has_face_terms())
      write(a, index);
  }

  template <int dim>
  void
  FaultResultsOutput<dim>::solve_failed(const SimulatorAccess<dim> &a)
  {
    if (a.faults.has_face_terms())
      write(a, -1);
  }

  template <int dim>
  void
  FaultResultsOutput<dim>::write(const SimulatorAccess<dim> &a,
                                 const int                   output_index) const
  {
    const std::vector<FaultSample> all = sample_fault(
      a.faults, a.dof_handler, a.fe_space, a.solution, a.fault_history);
    for (unsigned int k = 0; k < a.faults.n_faults(); ++k)
      {
        if (!a.faults.has_face_terms(k))
          continue;
        std::vector<FaultSample> samples;
        for (const FaultSample &sample : all)
          if (sample.fault == k)
            samples.push_back(sample);
        FaultSummary summary = summarize_fault(samples, a.faults.trace(k));
        summary.nonlinear_iterations = a.statistics.solver.nonlinear_iterations;
        summary.linear_solves        = a.statistics.solver.linear_solves;
        summary.tensile_failure_distance_m =
          top == numbers::invalid_boundary_id
            ? std::nan("")
            : tensile_failure_distance(a.faults.trace(k),
                                       a.faults.trace(k).buried_top()
                                         ? summary.max_slip_offset_m
                                         : summary.throw_m,
                                       a.dof_handler,
                                       a.fe_space,
                                       a.stress_model,
                                       a.griffith,
                                       a.solution,
                                       top);
        // fault.csv for the model's one fault, fault_<name>.csv for each of
        // several.
        const std::string suffix =
          a.faults.n_faults() == 1 ? "" : "_" + a.faults.trace(k).name;
        on_all_ranks(a.communicator, [&]() {
          if (!a.root())
            return;
          write_fault_csv(a.path("fault" + suffix + ".csv"), samples);
          if (output_index >= 0)
            write_fault_csv(a.path("fault" + suffix + "-" +
                                   Utilities::int_to_string(output_index, 5) +
                                   ".csv"),
                            samples);
          write_fault_summary(a.path("fault_summary" + suffix + ".json"),
                              summary);
        });
      }
  }

  template class FaultResultsOutput<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(FaultResultsOutput,
                                     "fault results",
                                     "slip and tractions along the faults",
                                     90)
} // namespace lithostress

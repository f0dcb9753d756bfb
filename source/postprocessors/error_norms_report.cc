#include <lithostress/analysis/error_norms.h>
#include <lithostress/postprocessors/error_norms_report.h>

#include <algorithm>
#include <iomanip>

namespace lithostress
{
  template <int dim>
  void
  ErrorNormsReport<dim>::cycle_finished(const SimulatorAccess<dim> &a,
                                        const unsigned int,
                                        ConvergenceStudy &study,
                                        std::ostream     &progress)
  {
    if (!a.reference)
      return;
    const ErrorNorms e = compute_error_norms(
      a.dof_handler, a.fe_space, a.stress_model, a.solution, *a.reference);
    using Kind = ConvergenceStudy::Kind;
    study.add("L2(u)", e.displacement_l2, Kind::error);
    study.add("energy", e.energy, Kind::error);
    study.add("L2(stress)", e.stress_l2, Kind::error);
    study.add("rel_L2(u)",
              e.displacement_l2 / std::max(e.displacement_l2_norm, 1e-300),
              Kind::error);
    study.add("rel_energy",
              e.energy / std::max(e.energy_norm, 1e-300),
              Kind::error);
    study.add("rel_L2(stress)",
              e.stress_l2 / std::max(e.stress_l2_norm, 1e-300),
              Kind::error);
    progress << ", relative errors: L2(u) " << std::setprecision(3)
             << e.displacement_l2 / e.displacement_l2_norm << ", energy "
             << e.energy / e.energy_norm;
  }

  template class ErrorNormsReport<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(ErrorNormsReport,
                                     "error norms",
                                     "the error against the reference solution",
                                     20)
} // namespace lithostress

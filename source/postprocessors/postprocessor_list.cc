#include <lithostress/postprocessors/convergence_table.h>
#include <lithostress/postprocessors/error_norms_report.h>
#include <lithostress/postprocessors/fault_results_output.h>
#include <lithostress/postprocessors/figure_plots.h>
#include <lithostress/postprocessors/force_balance_output.h>
#include <lithostress/postprocessors/paraview_output.h>
#include <lithostress/postprocessors/point_values_output.h>
#include <lithostress/postprocessors/run_statistics.h>
#include <lithostress/postprocessors/stress_depth_output.h>
#include <lithostress/postprocessors/surface_profile_output.h>
#include <lithostress/postprocessors/thin_plate_output.h>

namespace lithostress
{
  template <int dim>
  std::vector<typename PostprocessorList<dim>::Entry>
  PostprocessorList<dim>::registered()
  {
    // The calling order: the convergence table's columns and the log's
    // lines come out in this order.
    return {entry<ConvergenceTableReport<dim>>(),
            entry<ErrorNormsReport<dim>>(),
            entry<PointValuesOutput<dim>>(),
            entry<SurfaceProfileOutput<dim>>(),
            entry<ParaviewOutput<dim>>(),
            entry<ForceBalanceOutput<dim>>(),
            entry<StressDepthOutput<dim>>(),
            entry<ThinPlateOutput<dim>>(),
            entry<FaultResultsOutput<dim>>(),
            entry<FigurePlots<dim>>(),
            entry<RunStatistics<dim>>()};
  }

  template <int dim>
  void
  PostprocessorList<dim>::declare_parameters(ParameterHandler &prm)
  {
    for (const Entry &e : registered())
      e.declare(prm);
  }

  template <int dim>
  void
  PostprocessorList<dim>::parse_parameters(ParameterHandler           &prm,
                                           const SimulatorAccess<dim> &access)
  {
    postprocessors.clear();
    for (const Entry &e : registered())
      {
        postprocessors.push_back(e.create());
        postprocessors.back()->parse_parameters(prm, access);
      }
  }

  template <int dim>
  void
  PostprocessorList<dim>::cycle_finished(const SimulatorAccess<dim> &access,
                                         const unsigned int          cycle,
                                         ConvergenceStudy           &study,
                                         std::ostream               &progress)
  {
    for (const auto &p : postprocessors)
      p->cycle_finished(access, cycle, study, progress);
  }

  template <int dim>
  void
  PostprocessorList<dim>::cycle_output(const SimulatorAccess<dim> &access,
                                       const unsigned int          cycle,
                                       const bool                  last)
  {
    for (const auto &p : postprocessors)
      p->cycle_output(access, cycle, last);
  }

  template <int dim>
  void
  PostprocessorList<dim>::output_time(const SimulatorAccess<dim> &access,
                                      const unsigned int          index,
                                      const double                time)
  {
    for (const auto &p : postprocessors)
      p->output_time(access, index, time);
  }

  template <int dim>
  void
  PostprocessorList<dim>::solve_failed(const SimulatorAccess<dim> &access)
  {
    for (const auto &p : postprocessors)
      p->solve_failed(access);
  }

  template <int dim>
  void
  PostprocessorList<dim>::finish(const SimulatorAccess<dim> &access)
  {
    for (const auto &p : postprocessors)
      p->finish(access);
  }

  template <int dim>
  void
  PostprocessorList<dim>::interrupted(const SimulatorAccess<dim> &access)
  {
    for (const auto &p : postprocessors)
      p->interrupted(access);
  }

  template <int dim>
  void
  PostprocessorList<dim>::save(std::map<std::string, std::string> &state) const
  {
    for (const auto &p : postprocessors)
      p->save(state);
  }

  template <int dim>
  void
  PostprocessorList<dim>::load(const SimulatorAccess<dim>               &access,
                               const std::map<std::string, std::string> &state)
  {
    for (const auto &p : postprocessors)
      p->load(access, state);
  }

  template class PostprocessorList<2>;
} // namespace lithostress

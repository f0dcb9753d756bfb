#include <lithostress/postprocessors/figure_plots.h>

namespace lithostress
{
  template <int dim>
  void
  FigurePlots<dim>::parse_parameters(ParameterHandler           &prm,
                                     const SimulatorAccess<dim> &a)
  {
    figures.parse_parameters(prm, a.length_scale, a.length_unit);
  }

  template <int dim>
  void
  FigurePlots<dim>::finish(const SimulatorAccess<dim> &a)
  {
    if (!figures.enabled)
      return;
    TimerOutput::Scope t(a.timer, "profiles and figures");
    figures.plot(a.output_directory, a.log);
  }

  template class FigurePlots<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(FigurePlots,
                                     "figures",
                                     "the figure data and PNG figures",
                                     100)
} // namespace lithostress

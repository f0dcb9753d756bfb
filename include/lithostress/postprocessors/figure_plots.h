#ifndef lithostress_postprocessors_figure_plots_h
#define lithostress_postprocessors_figure_plots_h

#include <lithostress/postprocessors/figures.h>
#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  /** The PNG figures in the style of the thesis (principal-stress crosses,
   * surface profile, stress–depth profiles), drawn at the end of the run
   * from the data StressDepthOutput wrote (scripts/plot_figures.py). */
  template <int dim>
  class FigurePlots : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {}

    void
    parse_parameters(ParameterHandler           &prm,
                     const SimulatorAccess<dim> &access) override;

    void
    finish(const SimulatorAccess<dim> &access) override;

  private:
    Figures<dim> figures;
  };
} // namespace lithostress

#endif

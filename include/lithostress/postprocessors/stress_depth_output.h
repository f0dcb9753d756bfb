#ifndef lithostress_postprocessors_stress_depth_output_h
#define lithostress_postprocessors_stress_depth_output_h

#include <lithostress/postprocessors/figures.h>
#include <lithostress/analysis/stress_depth_profiles.h>
#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  /** After the last cycle: the stress–depth profiles
   * (stress_depth_x<x>.csv) and the data of the figures (principal
   * stresses, mesh outline, figures.json) that FigurePlots draws. */
  template <int dim>
  class StressDepthOutput : public Postprocessor<dim>
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
    StressDepthProfiles<dim> profiles;
    Figures<dim>             figures;
  };
} // namespace lithostress

#endif

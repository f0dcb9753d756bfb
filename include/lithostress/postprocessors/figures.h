#ifndef lithostress_postprocessors_figures_h
#define lithostress_postprocessors_figures_h

#include <deal.II/base/parameter_handler.h>

#include <lithostress/analysis/stress_sampling.h>
#include <lithostress/base/run_log.h>

#include <string>

namespace lithostress
{
  /**
   * Figures in the style of the thesis after the last cycle: the data
   * (`mesh_outline.csv`, the boundary of the body as straight segments
   * through the mapping; `principal_stresses.csv`, stresses on a regular
   * grid of points for principal-stress crosses; `figures.json`, units and
   * title), and the PNGs drawn from them and from the surface and
   * stress–depth profiles by `scripts/plot_figures.py` (Debian's
   * matplotlib). Without python3 or matplotlib the run goes on with a
   * warning.
   */
  template <int dim>
  class Figures
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler  &prm,
                     const double       length_scale,
                     const std::string &length_unit);

    /** Write the figure data (collective; rank 0 writes), with the
     * strength envelope at @p envelope_strain_rate [1/s] in
     * principal_stresses.csv where a rock yields or creeps (0: none). */
    void
    write_data(const std::string                   &directory,
               const std::string                   &title,
               const DoFHandler<dim>               &dof_handler,
               const FiniteElementSpace<dim>       &fe_space,
               const StressModel<dim>              &stress_model,
               const GriffithFailure               &griffith,
               const TrilinosWrappers::MPI::Vector &solution,
               const double envelope_strain_rate = 0) const;

    /** Run the plotting script on rank 0; its messages go to @p log. */
    void
    plot(const std::string &directory, RunLog &log) const;

    bool enabled = true;

  private:
    /** Spacing of the stress-cross grid [m]; 0 = automatic. */
    double      cross_spacing = 0;
    double      length_scale  = 1;
    std::string length_unit   = "m";
  };
} // namespace lithostress

#endif

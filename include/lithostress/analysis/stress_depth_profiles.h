#ifndef lithostress_analysis_stress_depth_profiles_h
#define lithostress_analysis_stress_depth_profiles_h

#include <deal.II/base/parameter_handler.h>

#include <lithostress/analysis/stress_sampling.h>

#include <string>
#include <vector>

namespace lithostress
{
  /**
   * Stress–depth profiles along vertical lines (thesis chapters 6–7 plot
   * them beside the principal-stress crosses): at each given x, equally
   * spaced points from the top of the body to its base, written as
   * `stress_depth_x<x>.csv` (depth below the body's top at that x; columns of
   * write_stress_samples()).
   */
  template <int dim>
  class StressDepthProfiles
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const double length_scale);

    /** Sample and write every profile (collective; rank 0 writes). Throws
     * InputError if a line misses the body. */
    void
    write(const std::string                   &directory,
          const DoFHandler<dim>               &dof_handler,
          const FiniteElementSpace<dim>       &fe_space,
          const StressModel<dim>              &stress_model,
          const GriffithFailure               &griffith,
          const TrilinosWrappers::MPI::Vector &solution) const;

    /** Every line must cross the coarse mesh's x range (InputError). */
    void
    check_against_mesh(const Triangulation<dim> &tria) const;

    bool
    empty() const
    {
      return positions.empty();
    }

    /** The strain rate [1/s] of the strength envelope (Output/Strength
     * envelope strain rate; 0: none). */
    double
    strength_envelope_strain_rate() const
    {
      return envelope_strain_rate;
    }

  private:
    /** x of each line [m] and its label in the file name. */
    std::vector<double>      positions;
    std::vector<std::string> labels;
    unsigned int             n_points = 101;
    /** The strain rate of the strength envelope [1/s] (0: none). */
    double envelope_strain_rate = 1e-15;
    double length_scale         = 1;
  };
} // namespace lithostress

#endif

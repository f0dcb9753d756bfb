#ifndef lithostress_analysis_stress_sampling_h
#define lithostress_analysis_stress_sampling_h

#include <lithostress/analysis/griffith_failure.h>
#include <lithostress/analysis/point_values.h>
#include <lithostress/analysis/stress_postprocessor.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace lithostress
{
  /** The solution and its stress analysis at one point. */
  template <int dim>
  struct StressSample
  {
    PointValue<dim> value;
    StressAnalysis  analysis;
    /** τ_II of the sample's stress and the strength envelope of its rock
     * (add_strength_envelope(); NaN where not computed, infinite where the
     * rock has no such branch). */
    double tau_ii           = std::numeric_limits<double>::quiet_NaN();
    double brittle_strength = std::numeric_limits<double>::quiet_NaN();
    double ductile_strength = std::numeric_limits<double>::quiet_NaN();
  };

  /**
   * The strength envelope (Goetze & Evans 1979) at every sample inside the
   * body: τ_II of the stress, and the brittle and ductile strength of its
   * material's rock law at the sample's temperature and pressure P = −tr σ/3
   * for the strain rate @p strain_rate [1/s]
   * (Rheology::strength_envelope()). Where no law has a strength, nothing
   * is set.
   */
  template <int dim>
  void
  add_strength_envelope(std::vector<StressSample<dim>> &samples,
                        const StressModel<dim>         &stress_model,
                        const double                    strain_rate);

  /**
   * Evaluate displacement, stress and the stress analysis (principal and
   * deviatoric stresses, Griffith test) at @p points, on all ranks; points
   * outside the body are an error unless @p allow_outside (then they are
   * returned with `value.inside = false`).
   */
  template <int dim>
  std::vector<StressSample<dim>>
  sample_stresses(const DoFHandler<dim>               &dof_handler,
                  const FiniteElementSpace<dim>       &fe_space,
                  const StressModel<dim>              &stress_model,
                  const GriffithFailure               &griffith,
                  const TrilinosWrappers::MPI::Vector &solution,
                  const std::vector<Point<dim>>       &points,
                  const bool                           allow_outside = false);

  /**
   * Write the samples inside the body as CSV (SI units: m, Pa, degrees):
   * `x, y, [depth,] u_x, u_y, sigma_xx, sigma_yy, sigma_xy, sigma_zz,
   * sigma_1, sigma_2, angle_1, deviatoric_xx, deviatoric_yy, deviatoric_zz,
   * deviatoric_xy, griffith_C, griffith_regime, fracture_angle[,
   * temperature]`; the depth column (below @p surface_y) only when it is
   * given, the temperature [K] only where the model has one. angle_1 is the
   * direction of σ1 from the x axis; griffith_C is 1 and the regime −1 where
   * the material is not tested (T = 0).
   */
  template <int dim>
  void
  write_stress_samples(const std::string                    &file_name,
                       const std::vector<StressSample<dim>> &samples,
                       const std::optional<double>           surface_y = {});
} // namespace lithostress

#endif

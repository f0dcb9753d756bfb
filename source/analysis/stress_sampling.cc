#include <lithostress/analysis/stress_sampling.h>
#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>

#include <algorithm>
#include <cmath>

#include <fstream>
#include <iomanip>

namespace lithostress
{
  template <int dim>
  std::vector<StressSample<dim>>
  sample_stresses(const DoFHandler<dim>               &dof_handler,
                  const FiniteElementSpace<dim>       &fe_space,
                  const StressModel<dim>              &stress_model,
                  const GriffithFailure               &griffith,
                  const TrilinosWrappers::MPI::Vector &solution,
                  const std::vector<Point<dim>>       &points,
                  const bool                           allow_outside)
  {
    const auto values = evaluate_at_points(
      dof_handler, fe_space, stress_model, solution, points, allow_outside);
    std::vector<StressSample<dim>> samples(values.size());
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        samples[k].value = values[k];
        if (!values[k].inside)
          continue;
        StressState<dim> s;
        s.in_plane = values[k].stress;
        s.zz       = values[k].sigma_zz;
        samples[k].analysis =
          analyse_stress(s,
                         stress_model.materials(values[k].material_id),
                         values[k].point,
                         griffith);
      }
    return samples;
  }

  template <int dim>
  void
  add_strength_envelope(std::vector<StressSample<dim>> &samples,
                        const StressModel<dim>         &stress_model,
                        const double                    strain_rate)
  {
    for (StressSample<dim> &sample : samples)
      {
        const PointValue<dim> &v = sample.value;
        if (!v.inside)
          continue;
        const double mean = (v.stress[0][0] + v.stress[1][1] + v.sigma_zz) / 3;
        const StrengthEnvelope envelope =
          stress_model.rheology(v.material_id)
            .strength_envelope(std::isnan(v.temperature) ? 0.0 : v.temperature,
                               stress_model.reference_pressure(v.point) - mean,
                               strain_rate);
        if (std::isinf(envelope.brittle) && std::isinf(envelope.ductile))
          continue;
        const double dxx = v.stress[0][0] - mean, dyy = v.stress[1][1] - mean,
                     dzz = v.sigma_zz - mean;
        sample.tau_ii    = std::sqrt(0.5 * (dxx * dxx + dyy * dyy + dzz * dzz) +
                                  v.stress[0][1] * v.stress[0][1]);
        sample.brittle_strength = envelope.brittle;
        sample.ductile_strength = envelope.ductile;
      }
  }

  template <int dim>
  void
  write_stress_samples(const std::string                    &file_name,
                       const std::vector<StressSample<dim>> &samples,
                       const std::optional<double>           surface_y)
  {
    // The temperature is known at every sample or at none.
    const bool with_temperature =
      std::any_of(samples.begin(), samples.end(), [](const auto &sample) {
        return sample.value.inside && !std::isnan(sample.value.temperature);
      });
    const bool with_strength =
      std::any_of(samples.begin(), samples.end(), [](const auto &sample) {
        return !std::isnan(sample.tau_ii);
      });
    const bool with_yielding =
      std::any_of(samples.begin(), samples.end(), [](const auto &sample) {
        return sample.value.inside && !std::isnan(sample.value.yielding);
      });
    // An infinite strength (no such branch) is an empty field.
    const auto strength = [](std::ostream &out, const double value) {
      if (std::isfinite(value))
        out << value;
    };
    OutputFile out(file_name);
    out << "x,y," << (surface_y ? "depth," : "")
        << "u_x,u_y,sigma_xx,sigma_yy,sigma_xy,sigma_zz,sigma_1,sigma_2,"
           "angle_1,deviatoric_xx,deviatoric_yy,deviatoric_zz,deviatoric_xy,"
           "griffith_C,griffith_regime,fracture_angle"
        << (with_temperature ? ",temperature" : "")
        << (with_strength ? ",tau_II,strength_brittle,strength_ductile,"
                            "strength"
                          : "")
        << (with_yielding ? ",plastic_strain,yielding,effective_viscosity,"
                            "strain_rate_II\n"
                          : "\n")
        << std::setprecision(10);
    for (const StressSample<dim> &sample : samples)
      if (sample.value.inside)
        {
          const PointValue<dim> &v = sample.value;
          const StressAnalysis  &a = sample.analysis;
          out << v.point[0] << ',' << v.point[1] << ',';
          if (surface_y)
            out << *surface_y - v.point[1] << ',';
          out << v.displacement[0] << ',' << v.displacement[1] << ','
              << v.stress[0][0] << ',' << v.stress[1][1] << ','
              << v.stress[0][1] << ',' << v.sigma_zz << ','
              << a.principal.sigma_1 << ',' << a.principal.sigma_2 << ','
              << a.principal.angle_1 * 180 / numbers::PI << ','
              << a.deviatoric_xx << ',' << a.deviatoric_yy << ','
              << a.deviatoric_zz << ',' << a.deviatoric_xy << ',';
          // C is infinite where a material is not tested (no tensile
          // strength): an empty field, as every number is finite.
          if (std::isfinite(a.degree_of_failure))
            out << a.degree_of_failure;
          out << ',' << a.regime << ',' << a.fracture_angle;
          if (with_temperature)
            out << ',' << v.temperature;
          if (with_strength)
            {
              out << ',';
              if (!std::isnan(sample.tau_ii))
                out << sample.tau_ii;
              out << ',';
              strength(out, sample.brittle_strength);
              out << ',';
              strength(out, sample.ductile_strength);
              out << ',';
              strength(out,
                       std::min(sample.brittle_strength,
                                sample.ductile_strength));
            }
          // Empty where the point's material keeps no plastic strain.
          if (with_yielding)
            {
              out << ',';
              if (!std::isnan(v.plastic_strain))
                out << v.plastic_strain;
              out << ',' << v.yielding << ',' << v.effective_viscosity << ','
                  << v.strain_rate_ii;
            }
          out << '\n';
        }
    out.commit();
  }

  template std::vector<StressSample<2>>
  sample_stresses<2>(const DoFHandler<2> &,
                     const FiniteElementSpace<2> &,
                     const StressModel<2> &,
                     const GriffithFailure &,
                     const TrilinosWrappers::MPI::Vector &,
                     const std::vector<Point<2>> &,
                     const bool);
  template void
  add_strength_envelope<2>(std::vector<StressSample<2>> &,
                           const StressModel<2> &,
                           const double);
  template void
  write_stress_samples<2>(const std::string &,
                          const std::vector<StressSample<2>> &,
                          const std::optional<double>);
} // namespace lithostress

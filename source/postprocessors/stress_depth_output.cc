#include <lithostress/postprocessors/stress_depth_output.h>

#include <filesystem>

namespace lithostress
{
  template <int dim>
  void
  StressDepthOutput<dim>::declare_parameters(ParameterHandler &prm)
  {
    StressDepthProfiles<dim>::declare_parameters(prm);
    Figures<dim>::declare_parameters(prm);
  }

  template <int dim>
  void
  StressDepthOutput<dim>::parse_parameters(ParameterHandler           &prm,
                                           const SimulatorAccess<dim> &a)
  {
    profiles.parse_parameters(prm, a.length_scale);
    profiles.check_against_mesh(a.triangulation);
    figures.parse_parameters(prm, a.length_scale, a.length_unit);
  }

  template <int dim>
  void
  StressDepthOutput<dim>::finish(const SimulatorAccess<dim> &a)
  {
    TimerOutput::Scope t(a.timer, "profiles and figures");
    profiles.write(a.output_directory,
                   a.dof_handler,
                   a.fe_space,
                   a.stress_model,
                   a.griffith,
                   a.solution);
    figures.write_data(
      a.output_directory,
      std::filesystem::path(a.output_directory).filename().string(),
      a.dof_handler,
      a.fe_space,
      a.stress_model,
      a.griffith,
      a.solution,
      profiles.strength_envelope_strain_rate());
  }

  template class StressDepthOutput<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(
    StressDepthOutput,
    "stress-depth profiles",
    "stress against depth along vertical lines",
    70)
} // namespace lithostress

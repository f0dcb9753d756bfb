#include <lithostress/base/input_error.h>
#include <lithostress/analysis/surface_profile.h>
#include <lithostress/postprocessors/surface_profile_output.h>
#include <lithostress/postprocessors/thin_plate_output.h>

namespace lithostress
{
  template <int dim>
  void
  ThinPlateOutput<dim>::declare_parameters(ParameterHandler &prm)
  {
    ThinPlateFlexure::declare_parameters(prm);
  }

  template <int dim>
  void
  ThinPlateOutput<dim>::parse_parameters(ParameterHandler           &prm,
                                         const SimulatorAccess<dim> &a)
  {
    thin_plate.parse_parameters(prm,
                                a.materials,
                                a.length_scale,
                                a.model.gravity.acceleration);
    boundary = surface_boundary(prm, a);
    if (thin_plate.enabled && boundary == numbers::invalid_boundary_id)
      throw_input_error("Thin plate comparison/Enabled",
                        "needs Output/Surface profile boundary");
  }

  template <int dim>
  void
  ThinPlateOutput<dim>::cycle_finished(const SimulatorAccess<dim> &a,
                                       const unsigned int,
                                       ConvergenceStudy &,
                                       std::ostream &)
  {
    // The profile of the refinement cycles' last mesh (the elastic
    // response, also when a time loop follows).
    if (thin_plate.enabled)
      profile =
        surface_profile(a.dof_handler, a.fe_space, a.solution, boundary);
  }

  template <int dim>
  void
  ThinPlateOutput<dim>::finish(const SimulatorAccess<dim> &a)
  {
    if (!thin_plate.enabled)
      return;
    on_all_ranks(a.communicator, [&]() {
      thin_plate.report(profile,
                        a.log,
                        a.root() ? a.path("thin_plate_comparison.csv")
                                 : std::string());
    });
  }

  template class ThinPlateOutput<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(ThinPlateOutput,
                                     "thin-plate comparison",
                                     "the flexure against thin-plate theory",
                                     80)
} // namespace lithostress

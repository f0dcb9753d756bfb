#include <lithostress/analysis/surface_profile.h>
#include <lithostress/base/input_error.h>
#include <lithostress/postprocessors/surface_profile_output.h>

namespace lithostress
{
  template <int dim>
  types::boundary_id
  surface_boundary(ParameterHandler &prm, const SimulatorAccess<dim> &a)
  {
    prm.enter_subsection("Output");
    const std::string name =
      Utilities::trim(prm.get("Surface profile boundary"));
    prm.leave_subsection();
    if (name.empty())
      return numbers::invalid_boundary_id;
    return a.model.boundary_id(name, "Output/Surface profile boundary");
  }

  template <int dim>
  void
  SurfaceProfileOutput<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Surface profile boundary",
                      "",
                      Patterns::Anything(),
                      "Boundary part whose displacement is written to "
                      "surface_profile.csv (x, u_x, u_y, y in m, sorted by "
                      "x) each cycle, and in the time loop at each output "
                      "time to surface_profile-<index>.csv as well (the "
                      "index of the ParaView file); empty = none.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  SurfaceProfileOutput<dim>::parse_parameters(ParameterHandler           &prm,
                                              const SimulatorAccess<dim> &a)
  {
    boundary = surface_boundary(prm, a);
  }

  template <int dim>
  void
  SurfaceProfileOutput<dim>::cycle_finished(const SimulatorAccess<dim> &a,
                                            const unsigned int,
                                            ConvergenceStudy &,
                                            std::ostream &)
  {
    write(a, {"surface_profile.csv"});
  }

  template <int dim>
  void
  SurfaceProfileOutput<dim>::output_time(const SimulatorAccess<dim> &a,
                                         const unsigned int          index,
                                         const double)
  {
    write(a,
          {"surface_profile-" + Utilities::int_to_string(index, 5) + ".csv",
           "surface_profile.csv"});
  }

  template <int dim>
  void
  SurfaceProfileOutput<dim>::write(
    const SimulatorAccess<dim>     &a,
    const std::vector<std::string> &file_names) const
  {
    if (boundary == numbers::invalid_boundary_id)
      return;
    const auto profile =
      surface_profile(a.dof_handler, a.fe_space, a.solution, boundary);
    on_all_ranks(a.communicator, [&]() {
      if (a.root())
        for (const std::string &name : file_names)
          write_surface_profile<dim>(a.path(name), profile);
    });
  }

  template class SurfaceProfileOutput<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(SurfaceProfileOutput,
                                     "surface profile",
                                     "the displacement along the top surface",
                                     40)
  template types::boundary_id
  surface_boundary(ParameterHandler &, const SimulatorAccess<2> &);
} // namespace lithostress

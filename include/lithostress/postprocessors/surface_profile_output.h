#ifndef lithostress_postprocessors_surface_profile_output_h
#define lithostress_postprocessors_surface_profile_output_h

#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  /** The displacement along the boundary part `Output/Surface profile
   * boundary` each cycle: surface_profile.csv (x, u_x, u_y, y [m], sorted
   * by x), the thesis's surface-uplift profiles (chapters 6 and 7). */
  template <int dim>
  class SurfaceProfileOutput : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler           &prm,
                     const SimulatorAccess<dim> &access) override;

    void
    cycle_finished(const SimulatorAccess<dim> &access,
                   const unsigned int          cycle,
                   ConvergenceStudy           &study,
                   std::ostream               &progress) override;

    /** At output time @p index of the visco-elastic loop:
     * surface_profile-<index>.csv (five digits, the index of the ParaView
     * file of that time), and surface_profile.csv again, so that it holds
     * the latest time. */
    void
    output_time(const SimulatorAccess<dim> &access,
                const unsigned int          index,
                const double                time) override;

  private:
    /** Write the profile of the current solution to @p file_names. */
    void
    write(const SimulatorAccess<dim>     &access,
          const std::vector<std::string> &file_names) const;

    types::boundary_id boundary = numbers::invalid_boundary_id;
  };

  /** The boundary part named by `Output/Surface profile boundary`, or
   * invalid_boundary_id if none (InputError for an unknown name). */
  template <int dim>
  types::boundary_id
  surface_boundary(ParameterHandler &prm, const SimulatorAccess<dim> &access);
} // namespace lithostress

#endif

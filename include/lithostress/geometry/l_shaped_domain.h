#ifndef lithostress_geometry_l_shaped_domain_h
#define lithostress_geometry_l_shaped_domain_h

#include <lithostress/geometry/geometry_model.h>

namespace lithostress
{
  /**
   * The L-shaped domain [−s, s]² without the quadrant (0, s)², with the
   * re-entrant corner at the origin: the classical test of adaptive
   * refinement for a corner singularity. Boundary parts: `notch` (the two
   * faces meeting at the re-entrant corner) and `outer` (the rest).
   */
  template <int dim>
  class LShapedDomain : public GeometryModel<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm, const double length_scale) override;
    void
    create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &tria) const override;
    std::map<std::string, types::boundary_id>
    boundary_parts() const override;
    std::string
    mesh_entry() const override
    {
      return "Geometry/L-shaped domain";
    }

  private:
    double half_size;
  };
} // namespace lithostress

#endif

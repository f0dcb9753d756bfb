#ifndef lithostress_geometry_quarter_annulus_h
#define lithostress_geometry_quarter_annulus_h

#include <lithostress/geometry/geometry_model.h>

namespace lithostress
{
  /**
   * A quarter of a thick-walled cylinder a ≤ r ≤ b, 0 ≤ θ ≤ π/2, centred on
   * the origin, optionally inside an outer shell b ≤ r ≤ b + t (thesis §4.5:
   * the visco-elastic cylinder in a thin elastic shell; Lamé's problem when
   * t = 0). The body is material id 0, the shell id 1. Boundary parts:
   * `inner` (r = a), `outer` (r = b + t), `left` (x = 0), `base` (y = 0).
   *
   * All cells carry a PolarManifold: lines of constant θ are straight and
   * lines of constant r are arcs in it, so the description is exact
   * everywhere and refinement places new vertices on the arcs.
   */
  template <int dim>
  class QuarterAnnulus : public GeometryModel<dim>
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
      return "Geometry/Quarter annulus";
    }
    std::map<std::string, types::material_id>
    named_regions() const override;

  private:
    double       inner_radius, outer_radius, shell_thickness;
    unsigned int cells_around, cells_radial, cells_in_shell;
  };
} // namespace lithostress

#endif

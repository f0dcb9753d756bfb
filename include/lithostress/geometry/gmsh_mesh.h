#ifndef lithostress_geometry_gmsh_mesh_h
#define lithostress_geometry_gmsh_mesh_h

#include <deal.II/base/point.h>

#include <lithostress/geometry/geometry_model.h>

#include <vector>

namespace lithostress
{
  /**
   * A quadrilateral mesh read from a Gmsh `.msh` file (ASCII, format 2 or
   * 4). Physical groups become material ids (surfaces) and boundary ids
   * (lines); their names, from `$PhysicalNames`, name the regions and the
   * boundary parts. Boundary parts that are circular arcs, given with their
   * centres in the input, get a PolarManifold, and the cells next to them a
   * TransfiniteInterpolationManifold (as in deal.II step-65), so refinement
   * follows the true curve.
   */
  template <int dim>
  class GmshMesh : public GeometryModel<dim>
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
    std::map<std::string, types::material_id>
    named_regions() const override;

  private:
    /** Read `$PhysicalNames` from the file. */
    void
    read_physical_names();

    std::string                                     mesh_file;
    double                                          scale;
    std::vector<std::pair<std::string, Point<dim>>> arcs;
    std::map<std::string, types::boundary_id>       boundary_names;
    std::map<std::string, types::material_id>       region_names;
  };
} // namespace lithostress

#endif

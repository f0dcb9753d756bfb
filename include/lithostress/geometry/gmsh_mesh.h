#ifndef lithostress_geometry_gmsh_mesh_h
#define lithostress_geometry_gmsh_mesh_h

#include <deal.II/base/point.h>

#include <lithostress/geometry/geometry_model.h>

#include <set>
#include <string>
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
   *
   * Faults: physical curves named in `Fault curves` are interior lines
   * of the mesh (format 2) along which the displacement may jump; each
   * becomes a fault of that name (a FaultTrace polyline from its upper end
   * down, on a circle if it has a centre in `Fault arc centres`, which
   * then also carries a PolarManifold). deal.II refuses boundary ids on
   * interior lines, so these lines are taken out of what it reads.
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
    std::vector<FaultTrace>
    fault_traces() const override;

  private:
    /** Read `$PhysicalNames` from the file. */
    void
    read_physical_names();

    /** Read the lines of each fault curve and chain them into its trace
     * (`faults`). Throws InputError naming the entry. */
    void
    read_fault_curves(const std::map<std::string, Point<dim>> &centres);

    /** The mesh file without the fault curves' line elements. */
    std::string
    text_without_fault_lines() const;

    std::vector<FaultTrace> faults;
    /** The physical tags of the fault curves. */
    std::set<int>                                   fault_tags;
    std::string                                     mesh_file;
    double                                          scale;
    std::vector<std::pair<std::string, Point<dim>>> arcs;
    /** `Concentric arcs`: the centre and radii [m]. */
    Point<dim>                                concentric_centre;
    std::vector<double>                       concentric_radii;
    std::map<std::string, types::boundary_id> boundary_names;
    std::map<std::string, types::material_id> region_names;
  };
} // namespace lithostress

#endif

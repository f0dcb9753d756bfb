#ifndef lithostress_geometry_gmsh_mesh_h
#define lithostress_geometry_gmsh_mesh_h

#include <deal.II/base/point.h>

#include <lithostress/geometry/geometry_model.h>
#include <lithostress/geometry/mesh_check.h>

#include <map>
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
    /** `Geometry/Gmsh/Mesh file`. */
    std::string
    mesh_entry() const override;
    /** "<file>: element <number>": the number of the coarse cell's
     * element in the mesh file. */
    std::string
    cell_name(const unsigned int index) const override;
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

    /** The edges of the file's quadrilaterals: each node's neighbours,
     * the nodes on the boundary (on an edge of one cell) and every node's
     * position [m]. */
    struct MeshEdges
    {
      std::map<long, std::set<long>> next;
      std::set<long>                 boundary;
      std::map<long, Point<2>>       position;
    };

    /** The edges of `file_cells`. */
    MeshEdges
    mesh_edges() const;

    /** The nodes that continue the fault curve @p chain (its node
     * numbers from the upper end down) from its upper (@p upper) or lower
     * end to the boundary along the mesh's @p edges, each step the edge
     * that turns least, avoiding the nodes @p avoid of the fault curves:
     * the welded extension beyond a buried tip (none if the end is on the
     * boundary). Throws InputError naming @p what if there is none. */
    std::vector<long>
    extension_to_boundary(const MeshEdges         &edges,
                          const std::vector<long> &chain,
                          const bool               upper,
                          const std::set<long>    &avoid,
                          const std::string       &what) const;

    /** The mesh file without the fault curves' line elements. */
    std::string
    text_without_fault_lines() const;

    /** A 2-D element of the mesh file. */
    struct FileCell
    {
      /** Its element number in the file. */
      long number = 0;
      /** Whether it is a quadrilateral whose four nodes the file has (of
       * the others GridIn says what is wrong). */
      bool checkable = false;
      /** Its corners [m] and their node numbers, in the file's order. */
      Quadrilateral       corners;
      std::array<long, 4> nodes;
    };

    /** Read the 2-D elements of the file into `file_cells`, in the order
     * of the coarse cells GridIn makes of them; none if the file is not
     * ASCII MSH 2 or 4.1 (GridIn then says what is wrong). Never throws. */
    void
    read_file_cells();

    /** Throw an InputError if a `$Section` of the file has no `$End`
     * (a file cut off) or an `$End` closes no open section. */
    void
    check_sections() const;

    /** Throw an InputError naming the element number and the vertices of
     * the first quadrilateral of the file that is inverted or degenerate
     * (check_quadrilaterals()), before GridIn would refuse it with a
     * message that names neither. */
    void
    check_element_shapes() const;

    /** Read the file with GridIn (without the fault curves' lines) into
     * @p tria, coordinates in metres. */
    void
    read_triangulation(parallel::distributed::Triangulation<dim> &tria) const;

    /** The `Circular arcs`: a PolarManifold on arc k (id 2k + 1), a
     * TransfiniteInterpolationManifold id (2k + 2) on its cells. */
    void
    attach_boundary_arcs(parallel::distributed::Triangulation<dim> &tria) const;

    /** The curved faults: a PolarManifold on the faces of fault j (id
     * 2(n + j) + 1 after n boundary arcs), id 2(n + j) + 2 on their
     * cells. */
    void
    attach_fault_arcs(parallel::distributed::Triangulation<dim> &tria) const;

    /** The `Concentric arcs`: one PolarManifold on every line on the
     * circles, inside or on the boundary (after the arcs' and faults'
     * ids), the next id on their cells (the slab's layers of thesis §7.2).
     * Throws an InputError if no line lies on them. */
    void
    attach_concentric_arcs(
      parallel::distributed::Triangulation<dim> &tria) const;

    /** The TransfiniteInterpolationManifolds of the cells next to arcs,
     * made once every manifold id is set. */
    void
    attach_transfinite_interpolation(
      parallel::distributed::Triangulation<dim> &tria) const;

    std::vector<FaultTrace> faults;
    /** The physical tags of the fault curves. */
    std::set<int> fault_tags;
    std::string   mesh_file;
    double        scale;
    /** The `Length unit` (m or km), for messages. */
    std::string                                     length_unit;
    std::vector<std::pair<std::string, Point<dim>>> arcs;
    /** `Concentric arcs`: the centre and radii [m]. */
    Point<dim>                                concentric_centre;
    std::vector<double>                       concentric_radii;
    std::map<std::string, types::boundary_id> boundary_names;
    std::map<std::string, types::material_id> region_names;
    /** The 2-D elements of the file, coarse cell i being element i. */
    std::vector<FileCell> file_cells;
  };
} // namespace lithostress

#endif

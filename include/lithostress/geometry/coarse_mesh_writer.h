#ifndef lithostress_geometry_coarse_mesh_writer_h
#define lithostress_geometry_coarse_mesh_writer_h

#include <deal.II/grid/tria.h>

#include <lithostress/geometry/fault_trace.h>

#include <map>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * Write the coarse mesh of @p tria as a Gmsh MSH 2.2 file that
   * `Geometry/Model = gmsh` reads back into the same model: the vertices in
   * the input's length unit (coordinates divided by @p length_scale, 17
   * digits), the cells as quadrilaterals in physical surfaces named after
   * @p regions, the boundary faces as lines in physical curves named after
   * @p boundary_parts, and the interior faces on each of @p faults as lines
   * in a physical curve of the fault's name (for `Geometry/Gmsh/Fault
   * curves`). Physical tags are the ids plus 1 (boundary parts, regions)
   * and 1001, 1002, ... (faults). Exports a generated section (the
   * subduction zone of thesis §7.2) for editing in Gmsh, and is how the
   * Gmsh twin of that section is made.
   */
  template <int dim>
  void
  write_coarse_mesh_msh(
    const Triangulation<dim>                        &tria,
    const std::map<std::string, types::boundary_id> &boundary_parts,
    const std::map<std::string, types::material_id> &regions,
    const std::vector<FaultTrace>                   &faults,
    const double                                     length_scale,
    const std::string                               &file_name);
} // namespace lithostress

#endif

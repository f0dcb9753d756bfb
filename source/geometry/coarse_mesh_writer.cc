#include <deal.II/grid/grid_tools.h>

#include <lithostress/base/input_error.h>
#include <lithostress/geometry/coarse_mesh_writer.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  write_coarse_mesh_msh(
    const Triangulation<dim>                        &tria,
    const std::map<std::string, types::boundary_id> &boundary_parts,
    const std::map<std::string, types::material_id> &regions,
    const std::vector<FaultTrace>                   &faults,
    const double                                     length_scale,
    const std::string                               &file_name)
  {
    static_assert(dim == 2, "Gmsh export is implemented in 2-D");
    std::ostringstream elements;
    unsigned int       n_elements = 0;
    const auto         element    = [&](const int                        type,
                             const unsigned int               tag,
                             const std::vector<unsigned int> &nodes) {
      elements << ++n_elements << ' ' << type << " 2 " << tag << ' ' << tag;
      for (const unsigned int n : nodes)
        elements << ' ' << n + 1;
      elements << '\n';
    };
    const double tolerance = 1e-9 * GridTools::diameter(tria);
    for (const auto &cell : tria.cell_iterators_on_level(0))
      {
        // Gmsh orders a quadrilateral's vertices around it, deal.II
        // lexicographically.
        element(3,
                cell->material_id() + 1,
                {cell->vertex_index(0),
                 cell->vertex_index(1),
                 cell->vertex_index(3),
                 cell->vertex_index(2)});
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            element(1,
                    face->boundary_id() + 1,
                    {face->vertex_index(0), face->vertex_index(1)});
          else if (cell->index() <
                   cell->neighbor(cell->face_iterator_to_index(face))->index())
            for (unsigned int j = 0; j < faults.size(); ++j)
              if (faults[j].distance_to(face->vertex(0)) < tolerance &&
                  faults[j].distance_to(face->vertex(1)) < tolerance)
                element(1,
                        1001 + j,
                        {face->vertex_index(0), face->vertex_index(1)});
      }

    std::ofstream out(file_name);
    if (!out)
      throw_input_error("Geometry/Write coarse mesh",
                        "cannot write <" + file_name + ">");
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n"
        << boundary_parts.size() + faults.size() + regions.size() << '\n';
    for (const auto &[name, id] : boundary_parts)
      out << "1 " << id + 1 << " \"" << name << "\"\n";
    for (unsigned int j = 0; j < faults.size(); ++j)
      out << "1 " << 1001 + j << " \"" << faults[j].name << "\"\n";
    for (const auto &[name, id] : regions)
      out << "2 " << id + 1 << " \"" << name << "\"\n";
    out << "$EndPhysicalNames\n$Nodes\n"
        << tria.n_vertices() << '\n'
        << std::setprecision(17);
    const std::vector<Point<dim>> &vertices = tria.get_vertices();
    for (unsigned int v = 0; v < vertices.size(); ++v)
      out << v + 1 << ' ' << vertices[v][0] / length_scale << ' '
          << vertices[v][1] / length_scale << " 0\n";
    out << "$EndNodes\n$Elements\n"
        << n_elements << '\n'
        << elements.str() << "$EndElements\n";
  }

  template void
  write_coarse_mesh_msh<2>(const Triangulation<2> &,
                           const std::map<std::string, types::boundary_id> &,
                           const std::map<std::string, types::material_id> &,
                           const std::vector<FaultTrace> &,
                           const double,
                           const std::string &);
} // namespace lithostress

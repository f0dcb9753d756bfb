#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/geometry/gmsh_mesh.h>

#include <fstream>
#include <set>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  GmshMesh<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Gmsh");
    prm.declare_entry("Mesh file",
                      "",
                      Patterns::Anything(),
                      "Path of a quadrilateral Gmsh .msh file (ASCII, format "
                      "2 or 4), relative to the working directory.");
    prm.declare_entry("Circular arcs",
                      "",
                      Patterns::Anything(),
                      "Boundary parts that are circular arcs, with their "
                      "centres: `name: x, y; name2: x, y` [length unit].");
    prm.leave_subsection();
  }

  template <int dim>
  void
  GmshMesh<dim>::parse_parameters(ParameterHandler &prm, const double s)
  {
    scale = s;
    prm.enter_subsection("Gmsh");
    mesh_file              = prm.get("Mesh file");
    const std::string text = prm.get("Circular arcs");
    prm.leave_subsection();
    if (mesh_file.empty())
      throw_input_error("Geometry/Gmsh/Mesh file", "is empty");
    if (!std::ifstream(mesh_file))
      throw_input_error("Geometry/Gmsh/Mesh file",
                        "cannot open the mesh file <" + mesh_file + ">");
    read_physical_names();
    arcs.clear();
    for (const std::string &item : split_list(text, ';'))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          throw_input_error("Geometry/Gmsh/Circular arcs",
                            "<" + item + "> is not of the form name: x, y");
        const std::string name = Utilities::trim(item.substr(0, colon));
        if (boundary_names.count(name) == 0)
          throw_input_error("Geometry/Gmsh/Circular arcs",
                            "the mesh has no boundary part <" + name + ">");
        const auto centre = parse_point_list<dim>(item.substr(colon + 1),
                                                  "Geometry/Gmsh/Circular arcs",
                                                  scale);
        arcs.emplace_back(name, centre[0]);
      }
  }

  template <int dim>
  void
  GmshMesh<dim>::read_physical_names()
  {
    boundary_names.clear();
    region_names.clear();
    std::ifstream in(mesh_file);
    std::string   line;
    while (std::getline(in, line))
      if (Utilities::trim(line) == "$PhysicalNames")
        {
          unsigned int n = 0;
          in >> n;
          for (unsigned int i = 0; i < n; ++i)
            {
              int         group_dim = 0, tag = 0;
              std::string name;
              in >> group_dim >> tag;
              std::getline(in, name);
              name = Utilities::trim(name);
              if (name.size() >= 2 && name.front() == '"')
                name = name.substr(1, name.size() - 2);
              if (group_dim == dim)
                region_names[name] = tag;
              else if (group_dim == dim - 1)
                boundary_names[name] = tag;
            }
          break;
        }
  }

  template <int dim>
  void
  GmshMesh<dim>::create_coarse_mesh(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    // Same mesh smoothing: copy_triangulation() takes it from the copy.
    Triangulation<dim> serial(tria.get_mesh_smoothing());
    GridIn<dim>        grid_in;
    grid_in.attach_triangulation(serial);
    // Every $Section must end: a file cut off (a copy or a mesher that
    // stopped half-way) is named as such, not by what the reader trips on.
    {
      std::ifstream            text(mesh_file);
      std::string              line;
      std::vector<std::string> open_sections;
      unsigned int             number = 0;
      while (std::getline(text, line))
        {
          ++number;
          line = Utilities::trim(line);
          if (line.size() < 2 || line[0] != '$')
            continue;
          if (line.compare(0, 4, "$End") == 0)
            {
              if (open_sections.empty() ||
                  open_sections.back() != line.substr(4))
                throw_input_error("Geometry/Gmsh/Mesh file",
                                  "<" + mesh_file + ">: line " +
                                    std::to_string(number) + " (" + line +
                                    ") closes a section that is not open");
              open_sections.pop_back();
            }
          else
            open_sections.push_back(line.substr(1));
        }
      if (!open_sections.empty())
        throw_input_error("Geometry/Gmsh/Mesh file",
                          "<" + mesh_file + "> is truncated: its $" +
                            open_sections.back() + " section has no $End" +
                            open_sections.back() + " (the file ends at line " +
                            std::to_string(number) + ")");
    }
    std::ifstream in(mesh_file);
    try
      {
        grid_in.read_msh(in);
      }
    catch (const ExceptionBase &exc)
      {
        throw_input_error("Geometry/Gmsh/Mesh file",
                          "cannot read <" + mesh_file +
                            ">: " + one_line_message(exc));
      }
    if (!serial.all_reference_cells_are_hyper_cube())
      throw_input_error("Geometry/Gmsh/Mesh file",
                        "<" + mesh_file +
                          "> has triangles; lithostress needs quadrilaterals "
                          "(use Recombine in Gmsh)");
    if (scale != 1.0)
      GridTools::scale(scale, serial);
    tria.copy_triangulation(serial);

    // Manifolds: an arc gets id 2k+1 (polar), its neighbour cells 2k+2
    // (transfinite interpolation).
    std::vector<TransfiniteInterpolationManifold<dim>> transfinite(arcs.size());
    for (unsigned int k = 0; k < arcs.size(); ++k)
      {
        const types::boundary_id b       = boundary_names.at(arcs[k].first);
        const types::manifold_id arc_id  = 2 * k + 1;
        const types::manifold_id cell_id = 2 * k + 2;
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == b)
              {
                cell->set_manifold_id(cell_id);
                for (const auto &f : cell->face_iterators())
                  if (f->manifold_id() == numbers::flat_manifold_id)
                    f->set_manifold_id(cell_id);
                face->set_manifold_id(arc_id);
              }
        tria.set_manifold(arc_id, PolarManifold<dim>(arcs[k].second));
      }
    for (unsigned int k = 0; k < arcs.size(); ++k)
      {
        transfinite[k].initialize(tria);
        tria.set_manifold(2 * k + 2, transfinite[k]);
      }
  }

  template <int dim>
  std::map<std::string, types::boundary_id>
  GmshMesh<dim>::boundary_parts() const
  {
    return boundary_names;
  }

  template <int dim>
  std::map<std::string, types::material_id>
  GmshMesh<dim>::named_regions() const
  {
    return region_names;
  }

  template class GmshMesh<2>;
} // namespace lithostress

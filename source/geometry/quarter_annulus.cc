#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria_description.h>

#include <lithostress/base/input_error.h>
#include <lithostress/geometry/quarter_annulus.h>

#include <cmath>

namespace lithostress
{
  template <int dim>
  void
  QuarterAnnulus<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Quarter annulus");
    prm.declare_entry("Inner radius",
                      "2",
                      Patterns::Double(),
                      "Inner radius a [length unit].");
    prm.declare_entry("Outer radius",
                      "4",
                      Patterns::Double(),
                      "Outer radius b of the body [length unit].");
    prm.declare_entry("Shell thickness",
                      "0",
                      Patterns::Double(0),
                      "Thickness t of an outer shell b < r < b + t "
                      "(material id 1); 0 = no shell [length unit].");
    prm.declare_entry("Cells around",
                      "2",
                      Patterns::Integer(1),
                      "Coarse cells along the quarter circle.");
    prm.declare_entry("Cells radially",
                      "2",
                      Patterns::Integer(1),
                      "Coarse cells across the body a < r < b.");
    prm.declare_entry("Cells in shell",
                      "1",
                      Patterns::Integer(1),
                      "Coarse cells across the shell.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  QuarterAnnulus<dim>::parse_parameters(ParameterHandler &prm,
                                        const double      scale)
  {
    prm.enter_subsection("Quarter annulus");
    inner_radius    = prm.get_double("Inner radius") * scale;
    outer_radius    = prm.get_double("Outer radius") * scale;
    shell_thickness = prm.get_double("Shell thickness") * scale;
    cells_around    = prm.get_integer("Cells around");
    cells_radial    = prm.get_integer("Cells radially");
    cells_in_shell  = prm.get_integer("Cells in shell");
    prm.leave_subsection();
    if (!(inner_radius > 0))
      throw_input_error("Geometry/Quarter annulus/Inner radius",
                        "must be positive");
    if (!(outer_radius > inner_radius))
      throw_input_error("Geometry/Quarter annulus/Outer radius",
                        "must be greater than the inner radius");
  }

  template <int dim>
  void
  QuarterAnnulus<dim>::create_coarse_mesh(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    std::vector<double> radii;
    for (unsigned int i = 0; i <= cells_radial; ++i)
      radii.push_back(inner_radius +
                      (outer_radius - inner_radius) * i / cells_radial);
    if (shell_thickness > 0)
      for (unsigned int i = 1; i <= cells_in_shell; ++i)
        radii.push_back(outer_radius + shell_thickness * i / cells_in_shell);

    const unsigned int    n_r = radii.size();
    std::vector<Point<2>> vertices;
    for (unsigned int j = 0; j <= cells_around; ++j)
      {
        const double theta = 0.5 * numbers::PI * j / cells_around;
        for (unsigned int i = 0; i < n_r; ++i)
          vertices.emplace_back(radii[i] * std::cos(theta),
                                radii[i] * std::sin(theta));
      }
    std::vector<CellData<2>> cells;
    for (unsigned int j = 0; j < cells_around; ++j)
      for (unsigned int i = 0; i + 1 < n_r; ++i)
        {
          CellData<2> cell;
          cell.vertices    = {j * n_r + i,
                              j * n_r + i + 1,
                              (j + 1) * n_r + i,
                              (j + 1) * n_r + i + 1};
          cell.material_id = (radii[i] < outer_radius * (1 - 1e-12)) ? 0 : 1;
          cells.push_back(cell);
        }
    tria.create_triangulation(vertices, cells, SubCellData());

    const double tol = 1e-8 * outer_radius;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          {
            const Point<2> c = face->center();
            const double   r =
              (face->vertex(0).norm() + face->vertex(1).norm()) / 2;
            if (std::abs(c[0]) < tol)
              face->set_boundary_id(2);
            else if (std::abs(c[1]) < tol)
              face->set_boundary_id(3);
            else if (std::abs(r - inner_radius) < tol)
              face->set_boundary_id(0);
            else
              face->set_boundary_id(1);
          }
    tria.set_all_manifold_ids(0);
    tria.set_manifold(0, PolarManifold<2>(Point<2>()));
  }

  template <int dim>
  std::map<std::string, types::boundary_id>
  QuarterAnnulus<dim>::boundary_parts() const
  {
    return {{"inner", 0}, {"outer", 1}, {"left", 2}, {"base", 3}};
  }

  template <int dim>
  std::map<std::string, types::material_id>
  QuarterAnnulus<dim>::named_regions() const
  {
    if (shell_thickness > 0)
      return {{"body", 0}, {"shell", 1}};
    return {{"body", 0}};
  }

  template class QuarterAnnulus<2>;

  LITHOSTRESS_REGISTER_GEOMETRY(
    QuarterAnnulus,
    "quarter annulus",
    "a quarter of a thick-walled cylinder, optionally in a shell (thesis "
    "§4.5)")
} // namespace lithostress

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/geometry/rectangular_geometries.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace lithostress
{
  std::map<std::string, types::boundary_id>
  rectangle_boundary_parts()
  {
    // The ids of GridGenerator's colorized rectangle.
    return {{"left", 0}, {"right", 1}, {"base", 2}, {"top", 3}};
  }

  unsigned int
  positive_count(ParameterHandler  &prm,
                 const std::string &entry,
                 const std::string &where)
  {
    const long value = prm.get_integer(entry);
    if (value < 1)
      throw_input_error(where + entry, "must be at least 1");
    return static_cast<unsigned int>(value);
  }

  double
  positive_length(ParameterHandler  &prm,
                  const std::string &entry,
                  const std::string &where,
                  const double       scale)
  {
    const double value = prm.get_double(entry) * scale;
    if (!(value > 0))
      throw_input_error(where + entry, "must be positive");
    return value;
  }

  namespace
  {
    void
    make_rectangle(Triangulation<2>  &tria,
                   const Point<2>    &p0,
                   const Point<2>    &p1,
                   const unsigned int nx,
                   const unsigned int ny)
    {
      GridGenerator::subdivided_hyper_rectangle(tria, {nx, ny}, p0, p1, true);
      // Colorizing also numbers the cells; the block is one material.
      for (const auto &cell : tria.active_cell_iterators())
        cell->set_material_id(0);
    }

  } // namespace

  // ------------------------------------------------------------ block
  template <int dim>
  void
  RectangularBlock<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Rectangular block");
    prm.declare_entry("X extent",
                      "0, 10",
                      Patterns::List(Patterns::Double(), 2, 2),
                      "Left and right x of the block [length unit].");
    prm.declare_entry("Y extent",
                      "-10, 0",
                      Patterns::List(Patterns::Double(), 2, 2),
                      "Base and top y of the block [length unit].");
    prm.declare_entry("Cells",
                      "1, 1",
                      Patterns::List(Patterns::Integer(1), 2, 2),
                      "Coarse cells in x and in y.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  RectangularBlock<dim>::parse_parameters(ParameterHandler &prm,
                                          const double      scale)
  {
    prm.enter_subsection("Rectangular block");
    const auto xs =
      Utilities::string_to_double(split_list(prm.get("X extent")));
    const auto ys =
      Utilities::string_to_double(split_list(prm.get("Y extent")));
    const auto n = Utilities::string_to_int(split_list(prm.get("Cells")));
    prm.leave_subsection();
    x0 = xs[0] * scale;
    x1 = xs[1] * scale;
    y0 = ys[0] * scale;
    y1 = ys[1] * scale;
    nx = n[0];
    ny = n[1];
    if (!(x1 > x0))
      throw_input_error("Geometry/Rectangular block/X extent",
                        "right must be greater than left");
    if (!(y1 > y0))
      throw_input_error("Geometry/Rectangular block/Y extent",
                        "top must be greater than base");
  }

  template <int dim>
  void
  RectangularBlock<dim>::create_coarse_mesh(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    make_rectangle(tria, Point<2>(x0, y0), Point<2>(x1, y1), nx, ny);
  }

  template <int dim>
  std::map<std::string, types::boundary_id>
  RectangularBlock<dim>::boundary_parts() const
  {
    return rectangle_boundary_parts();
  }

  // ------------------------------------------------------------ cantilever
  template <int dim>
  void
  CantileverBeam<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cantilever beam");
    prm.declare_entry("Length",
                      "10",
                      Patterns::Double(),
                      "Length l of the beam, x in [0, l] [length unit].");
    prm.declare_entry("Depth",
                      "2.5",
                      Patterns::Double(),
                      "Depth 2c of the beam, y in [-c, c] [length unit].");
    prm.declare_entry("Cells along length",
                      "4",
                      Patterns::Integer(),
                      "Coarse cells along the beam.");
    prm.declare_entry("Cells through depth",
                      "1",
                      Patterns::Integer(),
                      "Coarse cells through the depth.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  CantileverBeam<dim>::parse_parameters(ParameterHandler &prm,
                                        const double      scale)
  {
    const std::string where = "Geometry/Cantilever beam/";
    prm.enter_subsection("Cantilever beam");
    length        = positive_length(prm, "Length", where, scale);
    depth         = positive_length(prm, "Depth", where, scale);
    cells_along   = positive_count(prm, "Cells along length", where);
    cells_through = positive_count(prm, "Cells through depth", where);
    prm.leave_subsection();
  }

  template <int dim>
  void
  CantileverBeam<dim>::create_coarse_mesh(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    make_rectangle(tria,
                   Point<2>(0, -depth / 2),
                   Point<2>(length, depth / 2),
                   cells_along,
                   cells_through);
  }

  template <int dim>
  std::map<std::string, types::boundary_id>
  CantileverBeam<dim>::boundary_parts() const
  {
    return rectangle_boundary_parts();
  }

  // ------------------------------------------------------------ thin plate
  template <int dim>
  void
  ThinPlate<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Thin plate");
    prm.declare_entry("Length",
                      "1000",
                      Patterns::Double(),
                      "Plate length L, x in [0, L] [length unit].");
    prm.declare_entry("Thickness",
                      "20",
                      Patterns::Double(),
                      "Plate thickness h, y in [-h, 0] [length unit].");
    prm.declare_entry("Cells through thickness",
                      "1",
                      Patterns::Integer(),
                      "Coarse cells through the thickness; the cells along "
                      "the plate follow from L/h so that cells are square.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ThinPlate<dim>::parse_parameters(ParameterHandler &prm, const double scale)
  {
    const std::string where = "Geometry/Thin plate/";
    prm.enter_subsection("Thin plate");
    length        = positive_length(prm, "Length", where, scale);
    thickness     = positive_length(prm, "Thickness", where, scale);
    cells_through = positive_count(prm, "Cells through thickness", where);
    prm.leave_subsection();
  }

  template <int dim>
  void
  ThinPlate<dim>::create_coarse_mesh(
    parallel::distributed::Triangulation<dim> &tria) const
  {
    const unsigned int along =
      std::max<unsigned int>(1,
                             std::lround(length / thickness * cells_through));
    make_rectangle(
      tria, Point<2>(0, -thickness), Point<2>(length, 0), along, cells_through);
  }

  template <int dim>
  std::map<std::string, types::boundary_id>
  ThinPlate<dim>::boundary_parts() const
  {
    return rectangle_boundary_parts();
  }

  template class RectangularBlock<2>;
  template class CantileverBeam<2>;
  template class ThinPlate<2>;

  LITHOSTRESS_REGISTER_GEOMETRY(RectangularBlock,
                                "rectangular block",
                                "a block of one material (thesis §4.4)")
  LITHOSTRESS_REGISTER_GEOMETRY(CantileverBeam,
                                "cantilever beam",
                                "the cantilever of thesis §4.3")
  LITHOSTRESS_REGISTER_GEOMETRY(ThinPlate,
                                "thin plate",
                                "a long thin plate (thesis §6.1.2)")
} // namespace lithostress

#ifndef lithostress_geometry_mesh_check_h
#define lithostress_geometry_mesh_check_h

#include <deal.II/base/point.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <lithostress/geometry/geometry_model.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * Check that every cell of a coarse mesh is a proper cell: the Jacobian
   * determinant of @p mapping (the MappingQ of the run's mapping degree,
   * with the geometry's manifolds attached, so that curved cells are
   * checked as the computation sees them) is positive at every point of a
   * 5 × 5 Gauss rule on the cell (the assembly rule of the highest
   * polynomial degree). An inverted cell, or a flat one (zero area, e.g.
   * coincident vertices), would give negative or infinite stiffness and
   * meaningless stresses without any warning. The coarse mesh is the same
   * on every rank, so every rank reaches the same verdict without
   * communicating.
   *
   * Throws an InputError for @p source_description (the entry that gives
   * the mesh, e.g. `Geometry/Gmsh/Mesh file`) naming the first bad cell
   * with @p cell_name (by default "coarse cell <index>") and its vertices,
   * counterclockwise, in the input's unit: divided by @p length_scale and
   * followed by @p length_unit.
   */
  template <int dim>
  void
  check_coarse_cells(
    const Triangulation<dim>                             &triangulation,
    const Mapping<dim>                                   &mapping,
    const std::string                                    &source_description,
    const double                                          length_scale,
    const std::string                                    &length_unit,
    const std::function<std::string(const unsigned int)> &cell_name = {});

  /**
   * check_coarse_cells() with the entry and the cell names of @p geometry
   * (a Gmsh file's element numbers).
   */
  template <int dim>
  void
  check_coarse_cells(const Triangulation<dim> &triangulation,
                     const Mapping<dim>       &mapping,
                     const GeometryModel<dim> &geometry,
                     const double              length_scale,
                     const std::string        &length_unit);

  /** A straight-sided quadrilateral: its corners in cyclic order (as a
   * mesh file lists them), in metres. */
  using Quadrilateral = std::array<Point<2>, 4>;

  /**
   * The check of check_coarse_cells() on straight-sided cells given by
   * their corners, before deal.II makes a triangulation of them: deal.II
   * 9.4.1 takes a cell of zero area (the solver then fails on NaN) and
   * turns a clockwise cell round, so that a cell folded over its
   * neighbours comes to overlap them (the run crashes or computes
   * nonsense), and names neither the entry nor the cell. The Jacobian is
   * that of the bilinear map of each cell.
   *
   * Without @p node_numbers every cell must run counterclockwise. With
   * them (the cells' node numbers, as a mesh file lists them) a cell may be
   * listed in either direction, as deal.II's GridIn accepts (it turns the
   * clockwise ones round): the direction a cell is listed in is taken
   * from its neighbours (a side two cells share runs one way in one and
   * the other way in the other), and a cell is bad if, so listed, it is
   * not oriented as most cells of its piece of the mesh at every point (a
   * cell folded over its neighbours, whose nodes have crossed a side) or
   * if its Jacobian vanishes somewhere.
   */
  void
  check_quadrilaterals(
    const std::vector<Quadrilateral>                     &cells,
    const std::vector<std::array<long, 4>>               &node_numbers,
    const std::string                                    &source_description,
    const double                                          length_scale,
    const std::string                                    &length_unit,
    const std::function<std::string(const unsigned int)> &cell_name = {});
} // namespace lithostress

#endif

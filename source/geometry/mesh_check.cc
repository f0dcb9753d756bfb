#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <lithostress/base/input_error.h>
#include <lithostress/geometry/mesh_check.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace lithostress
{
  namespace
  {
    /** Gauss points per direction at which a cell's Jacobian is checked:
     * the assembly rule of the highest polynomial degree (4). */
    constexpr unsigned int points_per_direction = 5;

    /**
     * The points of the closed unit cell at which a Jacobian is checked:
     * the Gauss points of the assembly (an inverted cell) and the Gauss–
     * Lobatto points, which include the corners and points on every edge
     * (a cell with two coincident corners, a triangle, has a positive
     * Jacobian at every Gauss point and zero at those corners).
     */
    template <int dim>
    Quadrature<dim>
    closed_cell_points()
    {
      const QGauss<dim>        gauss(points_per_direction);
      const QGaussLobatto<dim> lobatto(points_per_direction);
      std::vector<Point<dim>>  points = gauss.get_points();
      points.insert(points.end(),
                    lobatto.get_points().begin(),
                    lobatto.get_points().end());
      return Quadrature<dim>(points);
    }

    /** A determinant of at most this times the square of the cell's
     * diameter is a flat cell's (round-off of zero). */
    constexpr double flat = 1e-12;

    /** The one line that names a bad cell: @p name, and @p corners
     * (counterclockwise, in metres) in the input's unit. */
    std::string
    bad_cell_text(const std::string           &name,
                  const std::vector<Point<2>> &corners,
                  const double                 length_scale,
                  const std::string           &length_unit)
    {
      std::ostringstream out;
      out << name
          << " is inverted or degenerate (Jacobian <= 0 at a point of the "
             "closed cell); vertices ";
      for (unsigned int v = 0; v < corners.size(); ++v)
        out << (v > 0 ? ", " : "") << "(" << corners[v][0] / length_scale
            << ", " << corners[v][1] / length_scale << ")";
      out << " " << length_unit;
      return out.str();
    }

    /** The name of coarse cell @p index in messages. */
    std::string
    name_of(const unsigned int                                    index,
            const std::function<std::string(const unsigned int)> &cell_name)
    {
      return cell_name ? cell_name(index)
                       : "coarse cell " + std::to_string(index);
    }

    /** The Jacobian determinant of the bilinear map of the unit square
     * onto @p cell at @p xi. */
    double
    bilinear_jacobian(const Quadrilateral &cell, const Point<2> &xi)
    {
      const Tensor<1, 2> d_xi =
        (1 - xi[1]) * (cell[1] - cell[0]) + xi[1] * (cell[2] - cell[3]);
      const Tensor<1, 2> d_eta =
        (1 - xi[0]) * (cell[3] - cell[0]) + xi[0] * (cell[2] - cell[1]);
      return d_xi[0] * d_eta[1] - d_xi[1] * d_eta[0];
    }

    /** +1 if the Jacobian of @p cell is positive at every point of
     * @p points, −1 if it is negative at every point, 0 otherwise (a
     * flat or twisted cell). */
    int
    orientation(const Quadrilateral &cell, const Quadrature<2> &points)
    {
      double diameter = 0;
      for (unsigned int i = 0; i < 4; ++i)
        for (unsigned int j = 0; j < i; ++j)
          diameter = std::max(diameter, cell[i].distance(cell[j]));
      const double zero     = flat * diameter * diameter;
      bool         positive = true, negative = true;
      for (const Point<2> &xi : points.get_points())
        {
          const double jacobian = bilinear_jacobian(cell, xi);
          positive              = positive && jacobian > zero;
          negative              = negative && jacobian < -zero;
        }
      return positive ? 1 : (negative ? -1 : 0);
    }

    /**
     * The direction each cell is listed in relative to the others of its
     * piece of the mesh (@p direction ±1; a side shared by two cells runs
     * one way in one and the other way in the other once the cells of
     * direction −1 are turned round) and the piece it belongs to
     * (@p piece), from the cells' node numbers. False if the cells cannot
     * be so listed (a side of more than two cells, a Möbius strip): then
     * every cell counts as listed as given, in one piece.
     */
    bool
    listing_directions(const std::vector<std::array<long, 4>> &node_numbers,
                       std::vector<int>                       &direction,
                       std::vector<unsigned int>              &piece)
    {
      const unsigned int n = node_numbers.size();
      // The cells on each side, and whether they list it from the lower
      // node number to the higher.
      std::map<std::pair<long, long>, std::vector<std::pair<unsigned, bool>>>
        sides;
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int v = 0; v < 4; ++v)
          {
            const long a = node_numbers[i][v], b = node_numbers[i][(v + 1) % 4];
            sides[std::minmax(a, b)].emplace_back(i, a < b);
          }
      std::vector<std::vector<std::pair<unsigned int, int>>> neighbours(n);
      for (const auto &[side, on] : sides)
        {
          if (on.size() > 2)
            return false;
          if (on.size() == 2)
            {
              // Listed alike: one of the two is turned round.
              const int relative = on[0].second == on[1].second ? -1 : 1;
              neighbours[on[0].first].emplace_back(on[1].first, relative);
              neighbours[on[1].first].emplace_back(on[0].first, relative);
            }
        }
      direction.assign(n, 0);
      piece.assign(n, 0);
      unsigned int n_pieces = 0;
      for (unsigned int first = 0; first < n; ++first)
        if (direction[first] == 0)
          {
            direction[first]               = 1;
            piece[first]                   = n_pieces;
            std::vector<unsigned int> next = {first};
            while (!next.empty())
              {
                const unsigned int i = next.back();
                next.pop_back();
                for (const auto &[j, relative] : neighbours[i])
                  if (direction[j] == 0)
                    {
                      direction[j] = relative * direction[i];
                      piece[j]     = n_pieces;
                      next.push_back(j);
                    }
                  else if (direction[j] != relative * direction[i])
                    return false;
              }
            ++n_pieces;
          }
      return true;
    }
  } // namespace

  template <int dim>
  void
  check_coarse_cells(
    const Triangulation<dim>                             &triangulation,
    const Mapping<dim>                                   &mapping,
    const std::string                                    &source_description,
    const double                                          length_scale,
    const std::string                                    &length_unit,
    const std::function<std::string(const unsigned int)> &cell_name)
  {
    static_assert(dim == 2, "the mesh check is written for quadrilaterals");
    const Quadrature<dim> quadrature = closed_cell_points<dim>();
    const FE_Q<dim>       fe(1);
    // Only the Jacobians: with JxW the mapping would itself assert (in
    // debug mode) on the cells this is to find.
    FEValues<dim> values(mapping, fe, quadrature, update_jacobians);
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      {
        values.reinit(cell);
        const double zero   = flat * cell->diameter() * cell->diameter();
        bool         proper = true;
        for (const unsigned int q : values.quadrature_point_indices())
          proper = proper && values.jacobian(q).determinant() > zero;
        if (!proper)
          throw_input_error(source_description,
                            bad_cell_text(name_of(cell->index(), cell_name),
                                          {cell->vertex(0),
                                           cell->vertex(1),
                                           cell->vertex(3),
                                           cell->vertex(2)},
                                          length_scale,
                                          length_unit));
      }
  }

  template <int dim>
  void
  check_coarse_cells(const Triangulation<dim> &triangulation,
                     const Mapping<dim>       &mapping,
                     const GeometryModel<dim> &geometry,
                     const double              length_scale,
                     const std::string        &length_unit)
  {
    check_coarse_cells(triangulation,
                       mapping,
                       geometry.mesh_entry(),
                       length_scale,
                       length_unit,
                       [&geometry](const unsigned int index) {
                         return geometry.cell_name(index);
                       });
  }

  void
  check_quadrilaterals(
    const std::vector<Quadrilateral>                     &cells,
    const std::vector<std::array<long, 4>>               &node_numbers,
    const std::string                                    &source_description,
    const double                                          length_scale,
    const std::string                                    &length_unit,
    const std::function<std::string(const unsigned int)> &cell_name)
  {
    const Quadrature<2>       points = closed_cell_points<2>();
    std::vector<int>          direction(cells.size(), 1);
    std::vector<unsigned int> piece(cells.size(), 0);
    if (!node_numbers.empty() &&
        !listing_directions(node_numbers, direction, piece))
      {
        direction.assign(cells.size(), 1);
        piece.assign(cells.size(), 0);
      }
    // Each cell's orientation as listed consistently with its neighbours,
    // and the balance of orientations in each piece.
    std::vector<int>         sign(cells.size());
    std::map<unsigned, long> balance;
    for (unsigned int i = 0; i < cells.size(); ++i)
      {
        sign[i] = orientation(cells[i], points) * direction[i];
        balance[piece[i]] += sign[i];
      }
    for (unsigned int i = 0; i < cells.size(); ++i)
      {
        const int right =
          (!node_numbers.empty() && balance[piece[i]] < 0) ? -1 : 1;
        if (sign[i] != right)
          throw_input_error(source_description,
                            bad_cell_text(name_of(i, cell_name),
                                          {cells[i].begin(), cells[i].end()},
                                          length_scale,
                                          length_unit));
      }
  }

  template void
  check_coarse_cells<2>(const Triangulation<2> &,
                        const Mapping<2> &,
                        const std::string &,
                        const double,
                        const std::string &,
                        const std::function<std::string(const unsigned int)> &);
  template void
  check_coarse_cells<2>(const Triangulation<2> &,
                        const Mapping<2> &,
                        const GeometryModel<2> &,
                        const double,
                        const std::string &);
} // namespace lithostress

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include <lithostress/geometry/block_mesh.h>
#include <lithostress/geometry/mesh_check.h>

#include <cmath>

namespace lithostress
{
  SectionCurve
  SectionCurve::line(const Point<2> &a, const Point<2> &b)
  {
    return {[a, b](const double s) { return Point<2>(a + s * (b - a)); }};
  }

  SectionCurve
  SectionCurve::arc(const Point<2> &centre,
                    const Point<2> &a,
                    const Point<2> &b)
  {
    const Tensor<1, 2> ra = a - centre, rb = b - centre;
    const double       radius = ra.norm();
    const double       phi_a  = std::atan2(ra[1], ra[0]);
    double             sweep  = std::atan2(rb[1], rb[0]) - phi_a;
    if (sweep > numbers::PI)
      sweep -= 2 * numbers::PI;
    if (sweep < -numbers::PI)
      sweep += 2 * numbers::PI;
    return {[=](const double s) {
      const double phi = phi_a + s * sweep;
      return Point<2>(centre[0] + radius * std::cos(phi),
                      centre[1] + radius * std::sin(phi));
    }};
  }

  SectionCurve
  SectionCurve::piece(const double s0, const double s1) const
  {
    const auto f = at;
    return {[f, s0, s1](const double s) { return f(s0 + s * (s1 - s0)); }};
  }

  SectionCurve
  SectionCurve::join(const SectionCurve &first,
                     const SectionCurve &second,
                     const double        fraction)
  {
    const auto f = first.at, g = second.at;
    return {[f, g, fraction](const double s) {
      return s <= fraction ? f(s / fraction)
                           : g((s - fraction) / (1 - fraction));
    }};
  }

  void
  BlockMesh::add_block(const SectionCurve      &side0,
                       const SectionCurve      &side1,
                       const SectionCurve      &side2,
                       const SectionCurve      &side3,
                       const unsigned int       n_along,
                       const unsigned int       n_across,
                       const types::material_id material)
  {
    // The Coons patch of the four sides in the block's (s, t): bottom
    // side0 (s), right side1 (t), top side2 reversed, left side3 reversed.
    const auto     bottom = [&](const double s) { return side0.at(s); };
    const auto     right  = [&](const double t) { return side1.at(t); };
    const auto     top    = [&](const double s) { return side2.at(1 - s); };
    const auto     left   = [&](const double t) { return side3.at(1 - t); };
    const Point<2> c00 = bottom(0), c10 = bottom(1), c01 = top(0), c11 = top(1);
    const unsigned int first = vertices.size();
    for (unsigned int j = 0; j <= n_across; ++j)
      for (unsigned int i = 0; i <= n_along; ++i)
        {
          const double s = double(i) / n_along, t = double(j) / n_across;
          Point<2>     p;
          if (j == 0)
            p = bottom(s);
          else if (j == n_across)
            p = top(s);
          else if (i == 0)
            p = left(t);
          else if (i == n_along)
            p = right(t);
          else
            p = Point<2>((1 - t) * bottom(s) + t * top(s) + (1 - s) * left(t) +
                         s * right(t) -
                         ((1 - s) * (1 - t) * c00 + s * (1 - t) * c10 +
                          (1 - s) * t * c01 + s * t * c11));
          vertices.push_back(p);
        }
    const unsigned int row = n_along + 1;
    for (unsigned int j = 0; j < n_across; ++j)
      for (unsigned int i = 0; i < n_along; ++i)
        {
          const unsigned int v = first + j * row + i;
          cells.push_back({{{v, v + 1, v + row, v + row + 1}}, material});
        }
  }

  void
  BlockMesh::add_triangle(const SectionCurve      &ab,
                          const SectionCurve      &bc,
                          const SectionCurve      &ca,
                          const unsigned int       n,
                          const types::material_id material)
  {
    Assert(n % 2 == 0, ExcMessage("add_triangle needs an even count"));
    const Point<2> m_ab = ab.at(0.5), m_bc = bc.at(0.5), m_ca = ca.at(0.5);
    const Point<2> g(
      (ab.start() + bc.start() + ca.start() + m_ab + m_bc + m_ca) / 6.);
    const unsigned int h = n / 2;
    add_block(ab.piece(0, 0.5),
              SectionCurve::line(m_ab, g),
              SectionCurve::line(g, m_ca),
              ca.piece(0.5, 1),
              h,
              h,
              material);
    add_block(bc.piece(0, 0.5),
              SectionCurve::line(m_bc, g),
              SectionCurve::line(g, m_ab),
              ab.piece(0.5, 1),
              h,
              h,
              material);
    add_block(ca.piece(0, 0.5),
              SectionCurve::line(m_ca, g),
              SectionCurve::line(g, m_bc),
              bc.piece(0.5, 1),
              h,
              h,
              material);
  }

  void
  BlockMesh::create(Triangulation<2>  &triangulation,
                    const double       tolerance,
                    const std::string &entry,
                    const double       length_scale,
                    const std::string &length_unit) const
  {
    std::vector<Point<2>>    points = vertices;
    std::vector<CellData<2>> cell_data;
    for (const auto &[v, material] : cells)
      {
        CellData<2> cell;
        cell.vertices    = {v[0], v[1], v[2], v[3]};
        cell.material_id = material;
        cell_data.push_back(cell);
      }
    SubCellData               none;
    std::vector<unsigned int> considered;
    GridTools::delete_duplicated_vertices(
      points, cell_data, none, considered, tolerance);
    GridTools::delete_unused_vertices(points, cell_data, none);
    // Blocks meet with different local orientations; deal.II needs every
    // line seen in the same direction by both its cells (as GridIn does).
    GridTools::consistently_order_cells(cell_data);
    // deal.II would take a flat cell, or turn an inverted one round, without
    // a word: name the cell and the entry instead.
    std::vector<Quadrilateral> corners;
    for (const CellData<2> &cell : cell_data)
      corners.push_back({{points[cell.vertices[0]],
                          points[cell.vertices[1]],
                          points[cell.vertices[3]],
                          points[cell.vertices[2]]}});
    check_quadrilaterals(corners, {}, entry, length_scale, length_unit);
    triangulation.create_triangulation(points, cell_data, none);
  }
} // namespace lithostress

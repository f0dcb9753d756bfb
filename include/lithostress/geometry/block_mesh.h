#ifndef lithostress_geometry_block_mesh_h
#define lithostress_geometry_block_mesh_h

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <functional>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * A curve in the cross section, parametrised on [0, 1]: a segment, or a
   * circular arc (uniform in angle), or a piece of either. Blocks that
   * share a side use the same curve (or pieces of it), so their vertices
   * coincide.
   */
  struct SectionCurve
  {
    std::function<Point<2>(double)> at;

    /** The segment from @p a to @p b. */
    static SectionCurve
    line(const Point<2> &a, const Point<2> &b);

    /** The shorter arc about @p centre from @p a to @p b (both at the same
     * distance from it). */
    static SectionCurve
    arc(const Point<2> &centre, const Point<2> &a, const Point<2> &b);

    /** The piece of this curve from parameter @p s0 to @p s1 (s1 < s0
     * reverses it). */
    SectionCurve
    piece(const double s0, const double s1) const;

    /** @p first then @p second (which starts where @p first ends), with
     * the corner at parameter @p fraction: a block side of n cells whose
     * first n·fraction cells lie on @p first has a vertex at the corner. */
    static SectionCurve
    join(const SectionCurve &first,
         const SectionCurve &second,
         const double        fraction);

    Point<2>
    start() const
    {
      return at(0);
    }

    Point<2>
    end() const
    {
      return at(1);
    }
  };

  /**
   * A coarse mesh assembled from four-sided blocks with curved sides, each
   * divided into cells by transfinite (Coons) interpolation of its sides,
   * as multi-block structured meshers do; the blocks' shared vertices are
   * merged. Curved three-sided regions are split into three four-sided
   * blocks at their centroid. The geometry generators of curved sections
   * (the subduction zone of thesis §7.2) build their coarse meshes with it
   * and then attach manifolds to the curved faces.
   */
  class BlockMesh
  {
  public:
    /**
     * Add a block whose sides, counterclockwise, run c0 → c1 (@p side0),
     * c1 → c2, c2 → c3, c3 → c0, each a curve from its start to its end;
     * @p n_along cells along sides 0 and 2, @p n_across along sides 1
     * and 3; its cells get @p material.
     */
    void
    add_block(const SectionCurve      &side0,
              const SectionCurve      &side1,
              const SectionCurve      &side2,
              const SectionCurve      &side3,
              const unsigned int       n_along,
              const unsigned int       n_across,
              const types::material_id material);

    /**
     * Add a three-sided region with counterclockwise sides A → B (@p ab),
     * B → C, C → A as three blocks meeting at its centroid, with
     * @p n cells (even) along every side.
     */
    void
    add_triangle(const SectionCurve      &ab,
                 const SectionCurve      &bc,
                 const SectionCurve      &ca,
                 const unsigned int       n,
                 const types::material_id material);

    /** Create the coarse mesh in the empty @p triangulation (vertices
     * closer than @p tolerance [m] merged). An inverted or degenerate cell
     * (blocks whose sides cross) is an InputError for @p entry, its
     * vertices given in the input's unit (@p length_scale,
     * @p length_unit; check_quadrilaterals()). */
    void
    create(Triangulation<2>  &triangulation,
           const double       tolerance,
           const std::string &entry,
           const double       length_scale,
           const std::string &length_unit) const;

  private:
    std::vector<Point<2>> vertices;
    std::vector<std::pair<std::array<unsigned int, 4>, types::material_id>>
      cells;
  };
} // namespace lithostress

#endif

/**
 * The mapping that keeps each cell's support points (CachedMappingQ) maps
 * every cell exactly as MappingQ does, bit for bit, on a disc whose
 * boundary is a SphericalManifold and whose interior is a
 * TransfiniteInterpolationManifold (the subduction zone's kind of mesh):
 * 1. after attach(), on every cell of every level;
 * 2. after global refinement, adaptive refinement and coarsening, which
 *    renumber the cells (the cache is filled again after each change);
 * 3. in FEValues: the quadrature points and JxW of every active cell;
 * 4. for a cell of another triangulation it was not attached to, and
 *    after it was attached to another mesh.
 * Prints "FAILED" and exits 1 on any failure.
 */
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <lithostress/discretization/cached_mapping.h>

#include <iostream>

using namespace dealii;
using namespace lithostress;

namespace
{
  bool failed = false;

  /** MappingQ with its (protected) support points open to the test. */
  struct ReferenceMapping : public MappingQ<2>
  {
    using MappingQ<2>::MappingQ;
    using MappingQ<2>::compute_mapping_support_points;
  };

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok   " : "FAILED ") << what << std::endl;
    failed = failed || !ok;
  }

  /** Whether @p cached maps every cell of @p tria (all levels) to the
   * same support points as @p reference, and every active cell to the
   * same quadrature points and JxW. */
  bool
  same_mapping(const Triangulation<2>  &tria,
               const CachedMappingQ<2> &cached,
               const ReferenceMapping  &reference)
  {
    for (const auto &cell : tria.cell_iterators())
      if (cached.compute_mapping_support_points(cell) !=
          reference.compute_mapping_support_points(cell))
        return false;
    const FE_Q<2>     fe(1);
    const QGauss<2>   quadrature(3);
    const UpdateFlags flags = update_quadrature_points | update_JxW_values;
    FEValues<2>       a(cached, fe, quadrature, flags);
    FEValues<2>       b(reference, fe, quadrature, flags);
    for (const auto &cell : tria.active_cell_iterators())
      {
        a.reinit(cell);
        b.reinit(cell);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          if (a.quadrature_point(q) != b.quadrature_point(q) ||
              a.JxW(q) != b.JxW(q))
            return false;
      }
    return true;
  }
} // namespace

int
main()
{
  Triangulation<2> disc;
  GridGenerator::hyper_ball(disc, Point<2>(), 3.);
  CachedMappingQ<2>      mapping(2);
  const ReferenceMapping reference(2);
  mapping.attach(disc);
  check(mapping.holds(disc), "the disc's points come from the cache");
  // A copy (as hp::MappingCollection makes) shares the cache.
  const auto copy = mapping.clone();
  check(same_mapping(disc, mapping, reference), "coarse disc");

  disc.refine_global(2);
  check(same_mapping(disc, mapping, reference), "refined twice globally");
  check(same_mapping(disc,
                     dynamic_cast<const CachedMappingQ<2> &>(*copy),
                     reference),
        "the clone, refined twice globally");

  for (const auto &cell : disc.active_cell_iterators())
    if (cell->center()[0] > 1.)
      cell->set_refine_flag();
  disc.execute_coarsening_and_refinement();
  check(same_mapping(disc, mapping, reference), "refined where x > 1");

  for (const auto &cell : disc.active_cell_iterators())
    if (cell->center()[1] < 0.)
      cell->set_coarsen_flag();
  disc.execute_coarsening_and_refinement();
  check(same_mapping(disc, mapping, reference), "coarsened where y < 0");

  // A triangulation it was not attached to, then another one attached.
  Triangulation<2> other;
  GridGenerator::hyper_ball(other, Point<2>(1., 1.), 0.5);
  other.refine_global(1);
  check(same_mapping(other, mapping, reference), "another triangulation");
  Triangulation<2> square;
  GridGenerator::hyper_cube(square);
  square.refine_global(2);
  mapping.attach(square);
  check(mapping.holds(square) && !mapping.holds(disc),
        "attached to a square, the cache left the disc");
  check(same_mapping(square, mapping, reference), "the square");
  check(same_mapping(disc, mapping, reference),
        "the disc after the mapping left it");

  std::cout << (failed ? "FAILED" : "PASSED") << std::endl;
  return failed ? 1 : 0;
}

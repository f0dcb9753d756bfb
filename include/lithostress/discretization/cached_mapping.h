#ifndef lithostress_discretization_cached_mapping_h
#define lithostress_discretization_cached_mapping_h

#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

#include <boost/signals2/connection.hpp>

#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The MappingQ of a run, with the support points of every cell of one
   * triangulation computed once per mesh instead of at each
   * FEValues::reinit(). On the subduction zone's
   * TransfiniteInterpolationManifold each computation pulls the cell's
   * points back to its coarse cell's chart by Newton iterations: about 6 %
   * of a chapter-7 run, at every assembly, stress evaluation and fault
   * integration of every time step. The cached points are those MappingQ
   * computes, so results are unchanged bit for bit.
   *
   * The cache holds the triangulation given to attach() (the simulator
   * attaches only a mesh with a curved manifold: on flat ones the points are
   * cheap and the cache would only cost memory). It is filled on first use
   * after each change of the mesh (Triangulation::Signals::any_change),
   * under a lock, so that threads assembling in parallel wait for the whole
   * cache. Cells of other triangulations are mapped as by MappingQ. Copies
   * (clone()) share the cache. deal.II's MappingQCache empties its cache on
   * a change of the mesh and must then be initialised again before any use,
   * at every place that refines, coarsens or loads the mesh; filling on
   * first use needs no such hook.
   */
  template <int dim>
  class CachedMappingQ : public MappingQ<dim>
  {
  public:
    /** A mapping of polynomial degree @p degree, caching nothing yet. */
    explicit CachedMappingQ(const unsigned int degree);

    /** A copy sharing @p other's cache. */
    CachedMappingQ(const CachedMappingQ<dim> &other);

    std::unique_ptr<Mapping<dim>>
    clone() const override;

    /**
     * Caches the support points of @p triangulation's cells from now on,
     * filled again after each change of it. @p triangulation must outlive
     * the mapping's use.
     */
    void
    attach(const Triangulation<dim> &triangulation);

    /** Whether the points of @p triangulation's cells come from the cache. */
    bool
    holds(const Triangulation<dim> &triangulation) const;

    /** The cached points of @p cell, or MappingQ's for a cell of another
     * triangulation. */
    std::vector<Point<dim>>
    compute_mapping_support_points(
      const typename Triangulation<dim>::cell_iterator &cell) const override;

  private:
    /** The points of every cell on every level, by level and index. */
    struct Cache
    {
      ~Cache();

      std::mutex                                        mutex;
      std::atomic<bool>                                 valid{false};
      const Triangulation<dim>                         *triangulation = nullptr;
      boost::signals2::connection                       on_change;
      std::vector<std::vector<std::vector<Point<dim>>>> points;
    };

    /** Computes the points of every cell (with the lock held). */
    void
    fill() const;

    std::shared_ptr<Cache> cache;
  };
} // namespace lithostress

#endif

#include <lithostress/discretization/cached_mapping.h>

namespace lithostress
{
  template <int dim>
  CachedMappingQ<dim>::Cache::~Cache()
  {
    on_change.disconnect();
  }

  template <int dim>
  CachedMappingQ<dim>::CachedMappingQ(const unsigned int degree)
      : MappingQ<dim>(degree)
      , cache(std::make_shared<Cache>())
  {
  }

  template <int dim>
  CachedMappingQ<dim>::CachedMappingQ(const CachedMappingQ<dim> &other)
      : MappingQ<dim>(other)
      , cache(other.cache)
  {
  }

  template <int dim>
  std::unique_ptr<Mapping<dim>>
  CachedMappingQ<dim>::clone() const
  {
    return std::make_unique<CachedMappingQ<dim>>(*this);
  }

  template <int dim>
  void
  CachedMappingQ<dim>::attach(const Triangulation<dim> &triangulation)
  {
    std::lock_guard<std::mutex> lock(cache->mutex);
    cache->on_change.disconnect();
    cache->valid = false;
    cache->points.clear();
    cache->triangulation = &triangulation;
    Cache *const c       = cache.get();
    cache->on_change =
      triangulation.signals.any_change.connect([c]() { c->valid = false; });
  }

  template <int dim>
  bool
  CachedMappingQ<dim>::holds(const Triangulation<dim> &triangulation) const
  {
    return cache->triangulation == &triangulation;
  }

  template <int dim>
  void
  CachedMappingQ<dim>::fill() const
  {
    const Triangulation<dim> &tria = *cache->triangulation;
    auto                     &all  = cache->points;
    all.assign(tria.n_levels(), {});
    for (unsigned int level = 0; level < tria.n_levels(); ++level)
      {
        all[level].resize(tria.n_raw_cells(level));
        for (const auto &cell : tria.cell_iterators_on_level(level))
          all[level][cell->index()] =
            MappingQ<dim>::compute_mapping_support_points(cell);
      }
    cache->valid.store(true, std::memory_order_release);
  }

  template <int dim>
  std::vector<Point<dim>>
  CachedMappingQ<dim>::compute_mapping_support_points(
    const typename Triangulation<dim>::cell_iterator &cell) const
  {
    if (&cell->get_triangulation() != cache->triangulation)
      return MappingQ<dim>::compute_mapping_support_points(cell);
    if (!cache->valid.load(std::memory_order_acquire))
      {
        std::lock_guard<std::mutex> lock(cache->mutex);
        if (!cache->valid.load(std::memory_order_relaxed))
          fill();
      }
    return cache->points[cell->level()][cell->index()];
  }

  template class CachedMappingQ<2>;
} // namespace lithostress

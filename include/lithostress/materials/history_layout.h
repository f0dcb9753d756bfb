#ifndef lithostress_materials_history_layout_h
#define lithostress_materials_history_layout_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * Where each material's history lies in the records of a CellHistory:
   * a record holds every component some material's law names
   * (Rheology::history_names()), each name once, in the order the
   * materials first name them; a law reads and writes its own components,
   * in its own order. Materials whose laws name the same components share
   * them (one ParaView field per name).
   */
  class HistoryLayout
  {
  public:
    /** Give material @p id the components @p names (none: a law without
     * history). */
    void
    add(const types::material_id id, const std::vector<std::string> &names);

    /** The components of a record. */
    const std::vector<std::string> &
    names() const
    {
      return record_names;
    }

    /** The number of components of material @p id's law. */
    unsigned int
    size(const types::material_id id) const
    {
      return placement.at(id).components.size();
    }

    /**
     * Material @p id's history in @p record, in its law's order: a view of
     * @p record itself where the law's components open the record in its
     * order, else a copy in @p scratch.
     */
    ArrayView<const double>
    of(const types::material_id id,
       const Vector<double>    &record,
       std::vector<double>     &scratch) const;

    /** Put material @p id's history @p history (its law's order) into
     * @p record; the other components are left as they are. */
    void
    store(const types::material_id       id,
          const ArrayView<const double> &history,
          Vector<double>                &record) const;

  private:
    /** A material's components: their indices in a record, and whether
     * those are 0, 1, ... (the record's opening in the law's order). */
    struct Placement
    {
      std::vector<unsigned int> components;
      bool                      leading = true;
    };

    std::vector<std::string>                record_names;
    std::map<types::material_id, Placement> placement;
  };
} // namespace lithostress

#endif

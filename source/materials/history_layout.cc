#include <deal.II/base/exceptions.h>

#include <lithostress/materials/history_layout.h>

#include <algorithm>
#include <stdexcept>

namespace lithostress
{
  void
  HistoryLayout::add(const types::material_id        id,
                     const std::vector<std::string> &names)
  {
    Placement p;
    for (const std::string &name : names)
      {
        if (std::count(names.begin(), names.end(), name) > 1)
          throw std::logic_error("a rock law names its history component <" +
                                 name + "> twice");
        const auto found =
          std::find(record_names.begin(), record_names.end(), name);
        const unsigned int index = found - record_names.begin();
        if (found == record_names.end())
          record_names.push_back(name);
        p.leading = p.leading && index == p.components.size();
        p.components.push_back(index);
      }
    placement[id] = std::move(p);
  }

  ArrayView<const double>
  HistoryLayout::of(const types::material_id id,
                    const Vector<double>    &record,
                    std::vector<double>     &scratch) const
  {
    const Placement &p = placement.at(id);
    AssertDimension(record.size(), record_names.size());
    if (p.leading)
      return ArrayView<const double>(record.begin(), p.components.size());
    scratch.resize(p.components.size());
    for (unsigned int k = 0; k < p.components.size(); ++k)
      scratch[k] = record[p.components[k]];
    return make_array_view(scratch);
  }

  void
  HistoryLayout::store(const types::material_id       id,
                       const ArrayView<const double> &history,
                       Vector<double>                &record) const
  {
    const Placement &p = placement.at(id);
    AssertDimension(history.size(), p.components.size());
    AssertDimension(record.size(), record_names.size());
    for (unsigned int k = 0; k < p.components.size(); ++k)
      record[p.components[k]] = history[k];
  }
} // namespace lithostress

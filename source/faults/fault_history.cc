#include <lithostress/base/input_error.h>
#include <lithostress/faults/fault_history.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace lithostress
{
  namespace
  {
    /** A record of FaultHistory::gather(): its fault, s and components. */
    struct Record
    {
      double        fault = 0, s = 0;
      const double *components = nullptr;
      unsigned int  n          = 0;
    };

    /** The records of @p flat, sorted by fault and s. */
    std::vector<Record>
    records_of(const std::vector<double> &flat)
    {
      std::vector<Record> records;
      for (std::size_t at = 0; at < flat.size();)
        {
          Record     r;
          const bool whole = at + 3 <= flat.size() && flat[at + 2] >= 0 &&
                             flat[at + 2] == std::floor(flat[at + 2]);
          r.fault      = whole ? flat[at] : 0;
          r.s          = whole ? flat[at + 1] : 0;
          r.n          = whole ? static_cast<unsigned int>(flat[at + 2]) : 0;
          r.components = whole ? flat.data() + at + 3 : nullptr;
          if (!whole || at + 3 + r.n > flat.size())
            throw ComputationError(
              "the faults' history ends inside a record: the checkpoint "
              "is damaged (start the run anew)");
          records.push_back(r);
          at += 3 + r.n;
        }
      std::stable_sort(records.begin(),
                       records.end(),
                       [](const Record &a, const Record &b) {
                         return std::tie(a.fault, a.s) < std::tie(b.fault, b.s);
                       });
      return records;
    }
  } // namespace

  void
  FaultHistory::set_trial(const unsigned int         i,
                          const std::vector<double> &history)
  {
    AssertIndexRange(i + 1, offsets.size());
    if (history.size() != offsets[i + 1] - offsets[i])
      throw ComputationError(
        "the interface law of fault " + std::to_string(faults[i]) +
        " returned " + std::to_string(history.size()) +
        " history components at a point, and its history_names() has " +
        std::to_string(offsets[i + 1] - offsets[i]));
    std::copy(history.begin(),
              history.end(),
              trial_values.begin() + offsets[i]);
  }

  std::vector<double>
  FaultHistory::gather(const MPI_Comm communicator) const
  {
    std::vector<double> mine;
    for (unsigned int i = 0; i + 1 < offsets.size(); ++i)
      {
        const ArrayView<const double> h = committed(i);
        mine.insert(mine.end(),
                    {static_cast<double>(faults[i]),
                     distances[i],
                     static_cast<double>(h.size())});
        mine.insert(mine.end(), h.begin(), h.end());
      }
    std::vector<double> all;
    for (const auto &part : Utilities::MPI::all_gather(communicator, mine))
      all.insert(all.end(), part.begin(), part.end());
    std::vector<double> sorted;
    for (const Record &r : records_of(all))
      {
        sorted.insert(sorted.end(), {r.fault, r.s, static_cast<double>(r.n)});
        sorted.insert(sorted.end(), r.components, r.components + r.n);
      }
    return sorted;
  }

  void
  FaultHistory::restore(const std::vector<double> &records)
  {
    restored     = records;
    has_restored = true;
    mesh         = ~0ULL;
  }

  void
  FaultHistory::reinit(const std::vector<unsigned int> &new_faults,
                       const std::vector<double>       &new_distances,
                       const std::vector<std::vector<std::string>> &names,
                       const unsigned long long mesh_version,
                       const MPI_Comm           communicator)
  {
    if (mesh == mesh_version && distances.size() == new_distances.size())
      return;
    const std::vector<double> old_flat =
      has_restored ? restored : gather(communicator);
    const std::vector<Record> old = records_of(old_flat);
    restored.clear();
    has_restored         = false;
    mesh                 = mesh_version;
    faults               = new_faults;
    distances            = new_distances;
    const unsigned int n = distances.size();
    offsets.assign(1, 0);
    for (unsigned int i = 0; i < n; ++i)
      offsets.push_back(offsets.back() + names[faults[i]].size());
    values.assign(offsets.back(), 0.);
    for (unsigned int i = 0; i < n; ++i)
      {
        const unsigned int n_components = offsets[i + 1] - offsets[i];
        if (n_components == 0)
          continue;
        // The old points of this fault, then the first at or beyond s.
        const double fault = faults[i], s = distances[i];
        const auto   begin = std::lower_bound(
          old.begin(), old.end(), fault, [](const Record &r, const double f) {
            return r.fault < f;
          });
        const auto end = std::upper_bound(begin,
                                          old.end(),
                                          fault,
                                          [](const double f, const Record &r) {
                                            return f < r.fault;
                                          });
        if (begin == end)
          continue;
        if (begin->n != n_components)
          throw ComputationError(
            "the history of fault " + std::to_string(faults[i]) + " has " +
            std::to_string(begin->n) + " components, its interface law keeps " +
            std::to_string(n_components) +
            ": it was written with another law (start the run anew)");
        const auto next =
          std::lower_bound(begin, end, s, [](const Record &r, const double x) {
            return r.s < x;
          });
        double *into = values.data() + offsets[i];
        if (next == begin || next == end)
          {
            const Record &last = next == end ? *(end - 1) : *begin;
            std::copy(last.components, last.components + n_components, into);
            continue;
          }
        const Record &a = *(next - 1), &b = *next;
        const double  w = b.s > a.s ? (s - a.s) / (b.s - a.s) : 0;
        for (unsigned int c = 0; c < n_components; ++c)
          into[c] = (1 - w) * a.components[c] + w * b.components[c];
      }
    trial_values = values;
    trial_states.assign(n, SlipState::stuck);
    normal_traction.assign(n, 0.);
  }
} // namespace lithostress

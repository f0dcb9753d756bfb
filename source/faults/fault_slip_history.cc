#include <lithostress/faults/fault_slip_history.h>

#include <algorithm>

namespace lithostress
{
  std::vector<FaultSlipHistory::Record>
  FaultSlipHistory::gather(const MPI_Comm communicator) const
  {
    std::vector<Record> mine;
    for (unsigned int i = 0; i < slip.size() && i < distances.size(); ++i)
      mine.push_back({{distances[i],
                       slip[i],
                       static_cast<double>(states[i]),
                       static_cast<double>(faults[i])}});
    std::vector<Record> all;
    for (const auto &part : Utilities::MPI::all_gather(communicator, mine))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end(), [](const Record &a, const Record &b) {
      return a[3] < b[3] || (a[3] == b[3] && a[0] < b[0]);
    });
    return all;
  }

  void
  FaultSlipHistory::restore(const std::vector<Record> &records)
  {
    restored = records;
    mesh     = ~0ULL;
  }

  void
  FaultSlipHistory::reinit(const std::vector<unsigned int> &new_faults,
                           const std::vector<double>       &new_distances,
                           const unsigned long long         mesh_version,
                           const MPI_Comm                   communicator)
  {
    if (mesh == mesh_version && slip.size() == new_distances.size())
      return;
    const std::vector<Record> old =
      restored.empty() ? gather(communicator) : restored;
    restored.clear();
    mesh                 = mesh_version;
    faults               = new_faults;
    distances            = new_distances;
    const unsigned int n = distances.size();
    slip.assign(n, 0.0);
    states.assign(n, SlipState::stuck);
    for (unsigned int i = 0; i < n; ++i)
      {
        // The old points of this fault, then the first at or beyond s.
        const double fault = faults[i], s = distances[i];
        const auto   begin = std::lower_bound(
          old.begin(), old.end(), fault, [](const Record &r, const double f) {
            return r[3] < f;
          });
        const auto end = std::upper_bound(begin,
                                          old.end(),
                                          fault,
                                          [](const double f, const Record &r) {
                                            return f < r[3];
                                          });
        if (begin == end)
          continue;
        const auto next =
          std::lower_bound(begin, end, s, [](const Record &r, const double x) {
            return r[0] < x;
          });
        if (next == begin || next == end)
          {
            const Record &last = next == end ? *(end - 1) : *begin;
            slip[i]            = last[1];
            states[i]          = static_cast<SlipState>(last[2]);
            continue;
          }
        const Record &a = *(next - 1), &b = *next;
        const double  w = b[0] > a[0] ? (s - a[0]) / (b[0] - a[0]) : 0;
        slip[i]         = (1 - w) * a[1] + w * b[1];
        states[i]       = static_cast<SlipState>(w < 0.5 ? a[2] : b[2]);
      }
    trial_slip   = slip;
    trial_states = states;
    normal_traction.assign(slip.size(), 0.);
  }
} // namespace lithostress

#include <lithostress/faults/fault_slip_history.h>

#include <algorithm>

namespace lithostress
{
  std::vector<FaultSlipHistory::Record>
  FaultSlipHistory::gather(const MPI_Comm communicator) const
  {
    std::vector<Record> mine;
    for (unsigned int i = 0; i < slip.size() && i < distances.size(); ++i)
      mine.push_back({{distances[i], slip[i], static_cast<double>(states[i])}});
    std::vector<Record> all;
    for (const auto &part : Utilities::MPI::all_gather(communicator, mine))
      all.insert(all.end(), part.begin(), part.end());
    std::sort(all.begin(), all.end(), [](const Record &a, const Record &b) {
      return a[0] < b[0];
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
  FaultSlipHistory::reinit(const std::vector<double> &new_distances,
                           const unsigned long long   mesh_version,
                           const MPI_Comm             communicator)
  {
    if (mesh == mesh_version && slip.size() == new_distances.size())
      return;
    const std::vector<Record> old =
      restored.empty() ? gather(communicator) : restored;
    restored.clear();
    mesh                 = mesh_version;
    distances            = new_distances;
    const unsigned int n = distances.size();
    slip.assign(n, 0.0);
    states.assign(n, SlipState::stuck);
    for (unsigned int i = 0; i < n && !old.empty(); ++i)
      {
        const double s = distances[i];
        // The first old point at or beyond s.
        const auto next = std::lower_bound(old.begin(),
                                           old.end(),
                                           s,
                                           [](const Record &r, const double x) {
                                             return r[0] < x;
                                           });
        if (next == old.begin() || next == old.end())
          {
            const Record &end = next == old.end() ? old.back() : old.front();
            slip[i]           = end[1];
            states[i]         = static_cast<SlipState>(end[2]);
            continue;
          }
        const Record &a = *(next - 1), &b = *next;
        const double  w = b[0] > a[0] ? (s - a[0]) / (b[0] - a[0]) : 0;
        slip[i]         = (1 - w) * a[1] + w * b[1];
        states[i]       = static_cast<SlipState>(w < 0.5 ? a[2] : b[2]);
      }
    trial_slip   = slip;
    trial_states = states;
  }
} // namespace lithostress

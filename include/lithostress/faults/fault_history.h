#ifndef lithostress_faults_fault_history_h
#define lithostress_faults_fault_history_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <lithostress/faults/interface_law.h>

#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The history of the faults' interface laws: at each interface point of
   * this rank (in the order of FaultInterface::interface_quadrature()), the
   * components its fault's law names (InterfaceLaw::history_names(): the
   * frictional law's accumulated slip p, any number for another law). The
   * sliding solver writes the trial values of a solve; commit() makes them
   * the history — after each solve of an elastic run, only on an accepted
   * step in the visco-elastic loop, so that a rejected step starts again
   * from the last equilibrium.
   *
   * On a new mesh (refinement, coarsening, a checkpoint read on any number
   * of ranks) the history is carried along each fault: every component
   * interpolated linearly in the distance s from its upper end between the
   * previous mesh's points (of all ranks). This keeps a profile to the
   * interpolation error of the old points (O(h²) where it is smooth) but
   * not its integral exactly (the seismic moment) where coarsening merges
   * points.
   *
   * Besides the history it holds what the last solve found at each point
   * and the fault output shows: the state and the normal traction.
   */
  class FaultHistory
  {
  public:
    /**
     * Fit the history to this rank's interface points, on the faults
     * @p faults at the distances @p distances along them, of mesh
     * @p mesh_version, fault k's law keeping the components
     * @p names[k]: kept if it belongs to that mesh, else carried over from
     * the previous points of the same fault or a restored profile (zero if
     * there is none). Collective.
     */
    void
    reinit(const std::vector<unsigned int>             &faults,
           const std::vector<double>                   &distances,
           const std::vector<std::vector<std::string>> &names,
           const unsigned long long                     mesh_version,
           const MPI_Comm                               communicator);

    /** The number of points. */
    unsigned int
    size() const
    {
      return distances.size();
    }

    /** The committed history at point @p i (empty if the point's law keeps
     * none, or there is no point @p i). */
    ArrayView<const double>
    committed(const unsigned int i) const
    {
      return view(values, i);
    }

    /** The last solve's history at point @p i. */
    ArrayView<const double>
    trial(const unsigned int i) const
    {
      return view(trial_values, i);
    }

    /** Set the last solve's history at point @p i (as many components as
     * its law names). */
    void
    set_trial(const unsigned int i, const std::vector<double> &history);

    /** Make the trial history the history. */
    void
    commit()
    {
      values = trial_values;
    }

    /** All ranks' committed history as records (fault, s, n, the n
     * components) one after the other, sorted by fault and s: what
     * restore() reads and checkpoints keep. Collective. */
    std::vector<double>
    gather(const MPI_Comm communicator) const;

    /** Continue from @p records (gather()'s, a checkpoint's): applied by
     * the next reinit(), which refuses records whose number of components
     * differs from the law's. */
    void
    restore(const std::vector<double> &records);

    /** The last solve's state at each point, and its normal traction t_n
     * [Pa] (tension positive): the contact constraints' reaction in exact
     * contact, k_n w_n with the normal spring. Not history: computed by
     * every solve. */
    std::vector<SlipState> trial_states;
    std::vector<double>    normal_traction;

  private:
    /** The components of point @p i in @p data. */
    ArrayView<const double>
    view(const std::vector<double> &data, const unsigned int i) const
    {
      if (i + 1 >= offsets.size())
        return ArrayView<const double>();
      return ArrayView<const double>(data.data() + offsets[i],
                                     offsets[i + 1] - offsets[i]);
    }

    std::vector<unsigned int> faults;
    std::vector<double>       distances;
    /** Point i's components are [offsets[i], offsets[i + 1]). */
    std::vector<unsigned int> offsets;
    std::vector<double>       values, trial_values;
    unsigned long long        mesh = ~0ULL;
    std::vector<double>       restored;
    bool                      has_restored = false;
  };
} // namespace lithostress

#endif

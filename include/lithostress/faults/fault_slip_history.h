#ifndef lithostress_faults_fault_slip_history_h
#define lithostress_faults_fault_slip_history_h

#include <deal.II/base/mpi.h>

#include <lithostress/faults/coulomb_friction.h>

#include <array>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The history of a frictional fault: at each interface point of this
   * rank (in the order of FaultInterface::interface_quadrature()), the
   * accumulated slip p of the interface law (CoulombFriction) and the
   * state. The sliding solver writes the trial values of a solve; commit()
   * makes them the history — after each solve of an elastic run, only on an
   * accepted step in the visco-elastic loop, so that a rejected step starts
   * again from the last equilibrium.
   *
   * On a new mesh (refinement, coarsening, a checkpoint read on any number
   * of ranks) the slip is carried along the fault: interpolated linearly in
   * the distance s from its surface trace between the previous mesh's
   * points (of all ranks), the state taken from the nearest of them. This
   * keeps the slip profile to the interpolation error of the old points
   * (O(h²) where it is smooth) but not its integral exactly (the seismic
   * moment) where coarsening merges points.
   */
  class FaultSlipHistory
  {
  public:
    /** (s, p, state, fault) of one point, for transfer and checkpoints. */
    using Record = std::array<double, 4>;

    /**
     * Fit the history to this rank's interface points, on the faults
     * @p faults at the distances @p distances along them, of mesh
     * @p mesh_version: kept if it belongs to that mesh, else carried over
     * from the previous points of the same fault or a restored profile
     * (zero slip, stuck, if there is none). Collective.
     */
    void
    reinit(const std::vector<unsigned int> &faults,
           const std::vector<double>       &distances,
           const unsigned long long         mesh_version,
           const MPI_Comm                   communicator);

    /** Make the trial slip and states the history. */
    void
    commit()
    {
      slip   = trial_slip;
      states = trial_states;
    }

    /** All ranks' committed (s, p, state, fault), sorted by fault and s.
     * Collective. */
    std::vector<Record>
    gather(const MPI_Comm communicator) const;

    /** Continue from @p records (a checkpoint's): applied by the next
     * reinit(). */
    void
    restore(const std::vector<Record> &records);

    /** The committed slip p and state at each point [m]. */
    std::vector<double>    slip;
    std::vector<SlipState> states;
    /** The last solve's values (committed by commit()). */
    std::vector<double>    trial_slip;
    std::vector<SlipState> trial_states;
    /** The last solve's normal traction t_n at each point [Pa] (tension
     * positive): the contact constraints' reaction in exact contact, k_n
     * w_n with the normal spring. Not history: computed by every solve. */
    std::vector<double> normal_traction;

  private:
    std::vector<unsigned int> faults;
    std::vector<double>       distances;
    unsigned long long        mesh = ~0ULL;
    std::vector<Record>       restored;
  };
} // namespace lithostress

#endif

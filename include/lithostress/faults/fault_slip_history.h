#ifndef lithostress_faults_fault_slip_history_h
#define lithostress_faults_fault_slip_history_h

#include <lithostress/faults/coulomb_friction.h>

#include <vector>

namespace lithostress
{
  /**
   * The history of a frictional fault: at each interface point of this
   * rank (in the order of FaultInterface::interface_quadrature()), the
   * accumulated slip p of the interface law (CoulombFriction) and the
   * state the last converged solve left it in. It is committed only when a
   * solve of the sliding problem has converged, so that a load step or time
   * step starts from the last equilibrium.
   */
  class FaultSlipHistory
  {
  public:
    /** Size for @p n_points points of a new mesh, all stuck with zero slip,
     * unless the history already belongs to mesh @p mesh_version. */
    void
    reinit(const unsigned int n_points, const unsigned long long mesh_version)
    {
      if (mesh == mesh_version && slip.size() == n_points)
        return;
      mesh = mesh_version;
      slip.assign(n_points, 0.0);
      states.assign(n_points, SlipState::stuck);
    }

    /** The accumulated slip p at each point [m]. */
    std::vector<double> slip;
    /** The state at each point after the last converged solve. */
    std::vector<SlipState> states;

  private:
    unsigned long long mesh = ~0ULL;
  };
} // namespace lithostress

#endif

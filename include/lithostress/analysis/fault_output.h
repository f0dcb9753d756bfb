#ifndef lithostress_analysis_fault_output_h
#define lithostress_analysis_fault_output_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/analysis/griffith_failure.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/faults/fault_history.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/materials/stress_model.h>

#include <cmath>
#include <string>
#include <vector>

namespace lithostress
{
  /**
   * The state of a fault at one interface point, as fault.csv gives it:
   * s = distance along the fault from its upper end [m]; slip = w·d
   * (d down dip: positive = normal sense, hanging wall down) and
   * opening = w·n [m] (w = u(hanging wall) − u(footwall), n from the
   * footwall into the hanging wall); the traction σ n on the footwall's
   * face, shear_traction = its component along d and normal_traction
   * along n [Pa, tension positive] — for a frictional fault the effective
   * normal stress σ_n,eff the friction law sees (the model's traction plus
   * the lithostatic term less the pore pressure); state = stuck, sliding
   * or open (an elastic fault is always stuck).
   */
  struct FaultSample
  {
    /** The fault (index into the geometry's faults). */
    unsigned int fault = 0;
    double       s = 0, x = 0, y = 0, depth = 0;
    double       slip = 0, opening = 0, shear_traction = 0, normal_traction = 0;
    double       vertical_jump = 0;
    SlipState    state         = SlipState::stuck;

    /** For gathering samples over the ranks. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &fault &s &x &y &depth &slip &opening &shear_traction
        &normal_traction &vertical_jump &state;
    }
  };

  /** The samples at every interface point of the faults with face terms
   * (all ranks get all of them, sorted by fault and s). @p solution is
   * ghosted. */
  template <int dim>
  std::vector<FaultSample>
  sample_fault(const FaultInterface<dim>           &faults,
               const DoFHandler<dim>               &dof_handler,
               const FiniteElementSpace<dim>       &fe_space,
               const TrilinosWrappers::MPI::Vector &solution,
               const FaultHistory                  &history);

  /** Write fault.csv: `s,x,y,slip,opening,shear_traction,normal_traction,
   * state` (SI units). */
  void
  write_fault_csv(const std::string              &filename,
                  const std::vector<FaultSample> &samples);

  /** What fault_summary.json reports. */
  struct FaultSummary
  {
    /** u_y(footwall) − u_y(hanging wall) at the surface trace [m]
     * (extrapolated from the two shallowest points): positive when the
     * hanging wall is downthrown. */
    double throw_m = 0;
    /** The slip w·d of largest magnitude along the fault [m] (positive in
     * the normal sense), and the vertical offset −w_y there: a buried
     * fault's size and sense, where the throw at the surface is zero. */
    double max_slip_m = 0, max_slip_offset_m = 0;
    /** The depths of the fault's ends inside the body [m] (NaN: the end
     * is on the boundary). */
    double upper_tip_depth_m = std::nan(""), lower_tip_depth_m = std::nan("");
    /** The deepest point that slides or is open [m] (0: none). */
    double sliding_depth_m = 0;
    /** Distance from the surface trace to where the top surface of the
     * downthrown side is most likely to fail in tension [m] (thesis §6.1.7's
     * graben width): the largest σ1 there; NaN if not computed. */
    double       tensile_failure_distance_m = 0;
    unsigned int nonlinear_iterations = 0, linear_solves = 0;
  };

  /** Throw, largest slip, tips and sliding depth from @p samples of the
   * fault @p trace (a buried upper tip: no throw at the surface). */
  FaultSummary
  summarize_fault(const std::vector<FaultSample> &samples,
                  const FaultTrace               &trace);

  /** Distance from the surface trace of @p trace to the node of the top
   * surface @p top on the downthrown side (the hanging wall if
   * @p throw_m ≥ 0) where the modified Griffith criterion (@p griffith) is
   * exceeded most [m]: at a free surface it is in its tensile regime and
   * fails at σ1 = T, so this is the largest σ1 (the degree of failure C
   * ranks the same points alike below σm = T but is singular there). */
  template <int dim>
  double
  tensile_failure_distance(const FaultTrace                    &trace,
                           const double                         throw_m,
                           const DoFHandler<dim>               &dof_handler,
                           const FiniteElementSpace<dim>       &fe_space,
                           const StressModel<dim>              &stress_model,
                           const GriffithFailure               &griffith,
                           const TrilinosWrappers::MPI::Vector &solution,
                           const types::boundary_id             top);

  /** Write fault_summary.json. */
  void
  write_fault_summary(const std::string &filename, const FaultSummary &summary);
} // namespace lithostress

#endif

#ifndef lithostress_time_integration_time_stepping_h
#define lithostress_time_integration_time_stepping_h

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The `Time stepping` section of a visco-elastic run (thesis §3.9): the
   * time unit (s, years, Myr, converted to seconds once here; every output
   * is in seconds), the end time, the integrator, the step-size control and
   * the output times, which steps land on exactly.
   *
   * Step-size control: after a step the estimate of its local error
   * (CreepIntegrator::Increment: (Δt/2) max‖ċ_{n+1} − ċ_n‖ for a
   * first-order step, an O(Δt³) estimate for BDF2) relative to the largest
   * elastic deviatoric strain max‖s/(2G)‖ is compared with the tolerance:
   * above it the step is repeated with a shorter one, below a quarter (an
   * eighth for BDF2) of it the step doubles. Keeping the step otherwise
   * unchanged lets the solver reuse its set-up (the relaxed moduli depend
   * on the step).
   */
  class TimeStepping
  {
  public:
    /** The time integrator (doc/equations.md). */
    enum class Scheme
    {
      /** Variable-step BDF2 with the relaxed tangent (the default): second
       * order, L-stable, one linear solve per step. */
      bdf2,
      /** Generalised midpoint rule with the relaxed tangent: one linear
       * solve per step (θ = 1 backward Euler, θ = 1/2 trapezoidal). */
      midpoint,
      /** The thesis's initial-strain scheme (§3.9): the creep increment
       * from the average of start- and end-of-step stress, the elastic
       * operator, fixed-point iteration per step. */
      thesis
    };

    static void
    declare_parameters(ParameterHandler &prm);

    /** Read and check the section; throws InputError naming the entry. */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * The time the step from @p t ends at when the controller proposes the
     * step @p proposed: bounded by the Maximum time step, and exactly the
     * next output time (or the end time) when the step would reach it or
     * pass it by less than 1 %.
     */
    double
    next_time(const double t, const double proposed) const;

    /** The index of output time @p t (landed on exactly), or -1. */
    int
    output_index(const double t) const;

    /** @p seconds in the time unit, with the unit ("2.5 kyr" style). */
    std::string
    format(const double seconds) const;

    bool        enabled = false;
    std::string unit_name;
    /** Seconds per time unit. */
    double unit = 1;
    /** End time, first, smallest and largest step [s]. */
    double end_time = 0, first_step = 0, minimum_step = 0, maximum_step = 0;
    bool   adaptive = true;
    /** Tolerance on the relative local error estimate of a step. */
    double tolerance = 1e-3;
    /** Output times [s], ascending, each in (0, end]; 0 is kept separately. */
    std::vector<double> output_times;
    bool                output_at_zero             = true;
    Scheme              scheme                     = Scheme::bdf2;
    double              theta                      = 1;
    double              fixed_point_tolerance      = 1e-6;
    unsigned int        fixed_point_max_iterations = 50;
    /** Newton's iteration of a step with a non-linear law. */
    double       newton_tolerance      = 1e-8;
    unsigned int newton_max_iterations = 12;
    /** `Newton start`: the first iterate is the extrapolated solution
     * (true) or the step's start (false). */
    bool newton_from_extrapolation = true;
    /** Refine the mesh every this many steps (0: never in the loop). */
    unsigned int refinement_interval = 0;
    /** Write a checkpoint every this many steps (0: only at the end). */
    unsigned int checkpoint_interval = 0;
    bool         resume              = false;
  };
} // namespace lithostress

#endif

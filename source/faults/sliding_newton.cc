#include <lithostress/faults/sliding_context.h>

namespace lithostress
{
  namespace sliding
  {
    /**
     * The semi-smooth Newton method (FrictionalSlidingSolver's `newton`,
     * replacing thesis §5.5's iteration): the elastic predictor, then
     * Newton steps with the return mapping's consistent tangent and a
     * backtracking line search on the residual norm. Returns whether the
     * residual and the excess shear fell below their tolerances; @p c
     * holds the last iterate.
     */
    template <int dim>
    bool
    solve_by_newton(SlidingContext<dim> &c)
    {
      using PointValues    = typename SlidingContext<dim>::PointValues;
      const auto &settings = c.settings;
      // x: the linear solve's solution, then the step from c.u (one
      // vector fewer at the solves' peak memory).
      TrilinosWrappers::MPI::Vector x(c.u), trial(c.u);
      c.start_contact_from_iterate();
      c.r_norm = c.residual_norm(c.u);
      if (c.nested_start)
        {
          std::ostringstream line;
          line << "  sliding: Newton starts from "
               << (c.kept.predicted_start ? "the last steps' extrapolation"
                                          : "the last mesh's solution")
               << ": residual " << std::setprecision(3) << c.r_norm / c.f
               << ", " << c.count_states();
          c.progress(line.str());
        }
      // Whether the last iteration changed exact contact's open nodes (the
      // next step satisfies other constraints than the iterate, and is
      // taken whole), and whether it changed them or a point's state.
      bool set_changed = false, changed = c.states_changed_since_converged();
      const double start_norm = c.r_norm;
      for (c.iteration = 1; c.iteration <= settings.max_iterations;
           ++c.iteration)
        {
          // The elastic predictor (every point stuck), unless the last
          // solution's states are the guess.
          const bool predictor = c.iteration == 1 && !c.warm_start;
          if (predictor)
            c.set_up(c.stuck_law(c.history.slip));
          else
            c.set_up([&c](const PointValues &values,
                          Tensor<1, dim>    &t,
                          Tensor<2, dim> &D) { c.newton_law(values, t, D); });
          c.couple_friction_limits(!predictor);
          // Inexact while the states change or the friction limits follow
          // the reactions (each step then reduces the residual by the fixed
          // point's contraction only); once neither holds the step may be
          // the last one (the law is piecewise linear), and is solved to
          // the Linear solver tolerance.
          x         = c.u;
          c.forcing = changed || c.limits_follow_reactions()
                        ? settings.linear_reduction * c.r_norm
                        : 0.;
          c.linear_solve(x);
          x -= c.u;
          double alpha = 1, trial_norm = 0;
          for (unsigned int halving = 0;; ++halving)
            {
              trial = c.u;
              trial.add(alpha, x);
              trial_norm = c.residual_norm(trial);
              if (!settings.line_search ||
                  (c.iteration == 1 && !c.warm_start) || set_changed ||
                  trial_norm <= (1 - 1e-4 * alpha) * c.r_norm || halving == 6)
                break;
              alpha /= 2;
            }
          const double previous_norm = c.r_norm;
          c.u                        = trial;
          c.r_norm                   = trial_norm;
          set_changed                = c.update_active_set();
          changed                    = c.states_changed() || set_changed;
          if (!std::isfinite(c.r_norm))
            throw ComputationError(
              "the Newton iteration for the sliding on " +
              c.faults.frictional_names() +
              " produced a residual that is not finite in iteration " +
              std::to_string(c.iteration));
          std::ostringstream line;
          line << "  sliding: Newton iteration " << c.iteration << ": residual "
               << std::setprecision(3) << c.r_norm / c.f << ", excess shear "
               << c.excess << " Pa, " << c.count_states() << ", "
               << c.last_iterations << " linear iterations"
               << (alpha < 1 ? ", step " + std::to_string(alpha) : "");
          c.progress(line.str());
          if (c.r_norm <= settings.residual_tolerance * c.f &&
              c.excess <= settings.excess_shear_tolerance && !set_changed)
            return true;
          // The friction limits' coupling to the reactions can send the
          // active set astray, each whole step opening more of the fault
          // (the listric normal fault at 1.32 M DoFs: 23 open points at
          // 1.3e-4 of the load, then 41, 52, 62 ... at 3, 5, 28 times the
          // load, with the factor and the multigrid alike), where the fixed
          // point in the reactions converges. An iterate twice as far from
          // equilibrium as the start, past the first few steps, ends it.
          if (c.coupling.active() && c.iteration > 4 &&
              c.r_norm > 2 * start_norm)
            {
              c.diverged = true;
              return false;
            }
          // The states stood still and the step was solved to the Linear
          // solver tolerance, yet the step did not halve the residual: it
          // is at the round-off of the linear solves (1.65 M DoFs on 2
          // ranks with CG + AMG: 1.04e-9, 1.03e-9, 1.03e-9 of the load).
          // Within 100 times the tolerance that is the solution.
          if (!changed && c.to_tolerance &&
              c.excess <= settings.excess_shear_tolerance &&
              c.r_norm > 0.5 * previous_norm &&
              c.r_norm <= 100 * settings.residual_tolerance * c.f)
            {
              std::ostringstream note;
              note << std::setprecision(3)
                   << "  sliding: the residual stopped falling at "
                   << c.r_norm / c.f
                   << " of the load (the linear solves' round-off): "
                      "converged";
              c.progress(note.str());
              return true;
            }
          c.accelerate_tractions(changed);
        }
      return false;
    }

    /** c.u_ghost := c.u, and in exact contact the normal tractions of c.u:
     * what the thesis iteration's excess shear is read from. */

    template bool
    solve_by_newton(SlidingContext<2> &);
  } // namespace sliding
} // namespace lithostress

#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/newton_method.h>

#include <cmath>

namespace lithostress
{
  using namespace dealii;

  template <typename VectorType>
  typename NewtonMethod<VectorType>::Result
  NewtonMethod<VectorType>::solve(NewtonProblem<VectorType> &problem,
                                  VectorType                &u,
                                  const double               reference,
                                  const double start_residual) const
  {
    // step: the Newton step from u; trial: the point the line search tries.
    VectorType    step(u), trial(u);
    NewtonIterate iterate;
    iterate.residual =
      start_residual >= 0 ? start_residual : problem.residual_norm(u);
    if (!std::isfinite(iterate.residual))
      throw ComputationError("the Newton iteration for " + settings.what +
                             " starts from a residual that is not finite");
    iterate.start_residual = iterate.residual;
    Result result;
    for (iterate.iteration = 1; iterate.iteration <= settings.max_iterations;
         ++iterate.iteration)
      {
        problem.newton_step(u, iterate.iteration, step);
        double alpha = 1, trial_norm = 0;
        for (unsigned int halving = 0;; ++halving)
          {
            trial = u;
            trial.add(alpha, step);
            trial_norm = problem.residual_norm(trial);
            if (!settings.line_search ||
                problem.take_whole_step(iterate.iteration) ||
                trial_norm <= (1 - settings.sufficient_decrease * alpha) *
                                iterate.residual ||
                halving == settings.max_halvings)
              break;
            alpha /= 2;
          }
        iterate.previous_residual = iterate.residual;
        iterate.residual          = trial_norm;
        iterate.step_length       = alpha;
        u                         = trial;
        result.iterations         = iterate.iteration;
        result.residual           = trial_norm;
        if (!std::isfinite(iterate.residual))
          throw ComputationError("the Newton iteration for " + settings.what +
                                 " produced a residual that is not finite in "
                                 "iteration " +
                                 std::to_string(iterate.iteration));
        problem.step_taken(iterate);
        if (iterate.residual <= settings.residual_tolerance * reference &&
            problem.converged_otherwise(iterate))
          {
            result.verdict = NewtonVerdict::converged;
            return result;
          }
        result.verdict = problem.judge(iterate);
        if (result.verdict != NewtonVerdict::go_on)
          return result;
      }
    return result;
  }

  template <typename VectorType>
  std::string
  NewtonMethod<VectorType>::failure_message(const std::string &state) const
  {
    return settings.what + " did not converge in " +
           std::to_string(settings.max_iterations) + " newton iterations (" +
           state + "); the last iterate is written out. Raise " +
           settings.iterations_entry;
  }

  template class NewtonMethod<TrilinosWrappers::MPI::Vector>;
} // namespace lithostress

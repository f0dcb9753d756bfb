#ifndef lithostress_refinement_dual_solutions_h
#define lithostress_refinement_dual_solutions_h

#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/faults/fault_interface.h>
#include <lithostress/faults/frictional_sliding_solver.h>
#include <lithostress/refinement/stress_goals.h>
#include <lithostress/solvers/linear_solver.h>

#include <vector>

namespace lithostress
{
  /**
   * The dual solutions z_i of the goals: a(v, z_i) = J_i(v) for every v
   * with homogeneous constraints, on the operator of @p problem (the
   * elastic operator of a refinement cycle, the relaxed one of a time
   * step; the stiffness of elastic faults included). A frictional fault
   * enters with its stuck (elastic) springs: the dual only weights the
   * indicator, and the stuck tangent is the law's linearisation wherever the
   * fault does not slide. Solved with @p linear_solver, or, when a fault is
   * frictional, with the preconditioner its sliding steps take
   * (@p sliding_settings; one set-up for all goals).
   * Returns ghosted vectors. Uses `problem.system.rhs` as work space.
   */
  template <int dim>
  std::vector<TrilinosWrappers::MPI::Vector>
  solve_dual_problems(
    const StressGoals<dim>                                &goals,
    const DiscreteProblem<dim>                            &problem,
    LinearSolver<dim>                                     &linear_solver,
    const FaultInterface<dim>                             &faults,
    const typename FrictionalSlidingSolver<dim>::Settings &sliding_settings,
    SolverReport                                          &report);
} // namespace lithostress

#endif

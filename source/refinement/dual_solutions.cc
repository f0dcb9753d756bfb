#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <lithostress/refinement/dual_solutions.h>

#include <memory>

namespace lithostress
{
  template <int dim>
  std::vector<TrilinosWrappers::MPI::Vector>
  solve_dual_problems(const StressGoals<dim>     &goals,
                      const DiscreteProblem<dim> &problem,
                      LinearSolver<dim>          &linear_solver,
                      const FaultInterface<dim>  &faults,
                      SolverReport               &report)
  {
    using PointValues               = typename FaultInterface<dim>::PointValues;
    LinearSystem<dim> &system       = problem.system;
    const MPI_Comm     communicator = problem.dof_handler.get_communicator();
    report                          = SolverReport();
    report.linear_solves            = 0;

    // The constraints' inhomogeneous part g = distribute(0): the dual
    // solution is distribute(z) - g, zero where a displacement is
    // prescribed.
    TrilinosWrappers::MPI::Vector inhomogeneity(system.locally_owned,
                                                communicator);
    inhomogeneity = 0;
    system.constraints.distribute(inhomogeneity);

    // A frictional fault: the bulk matrix with the stuck springs, factorised
    // once.
    TrilinosWrappers::SparseMatrix                  stuck;
    std::unique_ptr<SolverControl>                  control;
    std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
    if (faults.frictional())
      {
        stuck.copy_from(system.matrix);
        typename FaultInterface<dim>::FaceTerms terms(problem.fe_space);
        faults.for_each_interface_point(
          problem.dof_handler,
          problem.fe_space,
          nullptr,
          [&](const PointValues &values) {
            terms.add_tangent(values, faults.stuck_tangent(values.point));
            if (!values.last_of_pair)
              return;
            system.constraints.distribute_local_to_global(terms.matrix,
                                                          values.dofs,
                                                          stuck);
            terms.clear();
          });
        stuck.compress(VectorOperation::add);
        control = std::make_unique<SolverControl>(1, 0);
        direct  = std::make_unique<TrilinosWrappers::SolverDirect>(*control);
        direct->initialize(stuck);
        report.solver = "direct (dual)";
      }

    std::vector<TrilinosWrappers::MPI::Vector> duals;
    for (unsigned int k = 0; k < goals.list().size(); ++k)
      {
        TrilinosWrappers::MPI::Vector z;
        system.rhs.reinit(system.locally_owned, communicator);
        goals.assemble_dual_rhs(k,
                                problem.dof_handler,
                                problem.fe_space,
                                problem.stress_model,
                                system.constraints,
                                system.rhs);
        if (direct)
          {
            z.reinit(system.locally_owned, communicator);
            direct->solve(z, system.rhs);
          }
        else
          {
            // One operator for all goals: its set-up is kept between them.
            DiscreteProblem<dim> dual = problem;
            dual.keep_setup = problem.keep_setup || k + 1 < goals.list().size();
            const SolverReport r = linear_solver.solve(dual, z);
            report.solver        = r.solver;
            report.iterations += r.iterations;
            report.solve_time += r.solve_time;
          }
        ++report.linear_solves;
        system.constraints.distribute(z);
        z -= inhomogeneity;
        duals.emplace_back(system.locally_owned,
                           system.locally_relevant,
                           communicator);
        duals.back() = z;
      }
    return duals;
  }

  template std::vector<TrilinosWrappers::MPI::Vector>
  solve_dual_problems<2>(const StressGoals<2> &,
                         const DiscreteProblem<2> &,
                         LinearSolver<2> &,
                         const FaultInterface<2> &,
                         SolverReport &);
} // namespace lithostress

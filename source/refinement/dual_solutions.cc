#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <lithostress/faults/normal_contact.h>
#include <lithostress/refinement/dual_solutions.h>
#include <lithostress/solvers/amg_solver.h>
#include <lithostress/solvers/rigid_body_modes.h>
#include <lithostress/solvers/sparse_cholesky.h>
#include <lithostress/solvers/two_field_multigrid.h>

#include <memory>

namespace lithostress
{
  namespace
  {
    /**
     * The dual problems' operator where the faults need the sliding
     * solver: the bulk with the stuck (elastic) face terms of every fault
     * and, in exact contact, every node closed (NormalContact's ties). In
     * exact contact it is symmetric and without stiff springs, and takes
     * the preconditioner the sliding steps take
     * (FrictionalSlidingSolver::chosen_preconditioner): the sparse
     * Cholesky factor on one rank, the two fields' multigrid or the
     * elasticity AMG for CG. With the thesis's normal spring, and with a
     * factorisation asked for on several ranks, a sparse LU
     * factorisation. Any of them is made once for all goals.
     */
    template <int dim>
    class StuckInterfaceOperator
    {
    public:
      using Preconditioner =
        typename FrictionalSlidingSolver<dim>::Preconditioner;

      StuckInterfaceOperator(
        const DiscreteProblem<dim>                            &problem,
        const FaultInterface<dim>                             &faults,
        const typename FrictionalSlidingSolver<dim>::Settings &settings)
          : faults(faults)
          , problem(problem)
      {
        if (!active())
          return;
        const LinearSystem<dim> &system = problem.system;
        stuck.locally_owned             = system.locally_owned;
        stuck.rhs.reinit(system.locally_owned,
                         problem.dof_handler.get_communicator());
        if (faults.contact())
          {
            NormalContact<dim> contact(faults,
                                       problem.dof_handler,
                                       problem.fe_space,
                                       system.locally_owned,
                                       system.locally_relevant);
            contact.assemble_bulk(problem, stuck);
          }
        else
          {
            stuck.constraints.copy_from(system.constraints);
            stuck.matrix.copy_from(system.matrix);
          }
        add_stuck_face_terms();
        const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(
          problem.dof_handler.get_communicator());
        const Preconditioner chosen =
          faults.contact()
            ? FrictionalSlidingSolver<dim>::chosen_preconditioner(
                settings, true, problem.dof_handler.n_dofs(), n_ranks)
            : Preconditioner::direct;
        if (chosen == Preconditioner::direct && n_ranks == 1 &&
            faults.contact())
          {
            cholesky = std::make_unique<SparseCholesky>();
            cholesky->factorize(stuck.matrix);
          }
        else if (chosen == Preconditioner::direct)
          {
            control = std::make_unique<SolverControl>(1, 0);
            direct = std::make_unique<TrilinosWrappers::SolverDirect>(*control);
            direct->initialize(stuck.matrix);
          }
        else if (chosen == Preconditioner::multigrid)
          {
            multigrid = std::make_unique<TwoFieldMultigrid<dim>>();
            multigrid->make_hierarchy(problem.dof_handler,
                                      problem.fe_space.fe_collection());
            multigrid->initialize(stuck.matrix,
                                  stuck.constraints,
                                  typename TwoFieldMultigrid<dim>::Settings());
          }
        else
          {
            modes =
              make_rigid_body_modes(problem.dof_handler,
                                    problem.fe_space,
                                    stuck.matrix.trilinos_matrix().DomainMap());
            initialize_elasticity_amg<dim>(amg,
                                           stuck.matrix,
                                           *modes,
                                           typename AMGSolver<dim>::Settings(),
                                           true);
          }
      }

      /** Whether the faults need it (FaultInterface::needs_sliding_solver()).
       */
      bool
      active() const
      {
        return faults.needs_sliding_solver();
      }

      /** The solver's name for the report. */
      std::string
      name() const
      {
        return cholesky    ? "Cholesky (dual, contact)"
               : direct    ? "direct (dual)"
               : multigrid ? "CG with the two fields' multigrid (dual, contact)"
                           : "CG with AMG (dual, contact)";
      }

      /** The constraints of the dual problems. */
      const AffineConstraints<double> &
      constraints() const
      {
        return stuck.constraints;
      }

      /** @p g := the constraints' inhomogeneous part. */
      void
      inhomogeneity(TrilinosWrappers::MPI::Vector &g) const
      {
        g = 0;
        stuck.constraints.distribute(g);
      }

      /** Solve for @p z with the right-hand side @p rhs; the iterations. */
      unsigned int
      solve(TrilinosWrappers::MPI::Vector       &z,
            const TrilinosWrappers::MPI::Vector &rhs) const
      {
        if (direct)
          {
            direct->solve(z, rhs);
            return 0;
          }
        if (cholesky)
          {
            cholesky->vmult(z, rhs);
            return 0;
          }
        SolverControl control(5000, 1e-10 * rhs.l2_norm(), false, false);
        try
          {
            SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
            if (multigrid)
              cg.solve(stuck.matrix, z, rhs, *multigrid);
            else
              cg.solve(stuck.matrix, z, rhs, amg);
          }
        catch (const SolverControl::NoConvergence &exc)
          {
            rethrow_solver_failure(exc,
                                   problem.dof_handler.get_communicator(),
                                   name(),
                                   rhs.l2_norm(),
                                   "use Faults/Sliding solver/Linear solver "
                                   "= direct, or Mesh refinement/Indicator = "
                                   "Kelly");
          }
        return control.last_step();
      }

    private:
      /** The stuck tangent of every fault with face terms. */
      void
      add_stuck_face_terms()
      {
        using PointValues = typename FaultInterface<dim>::PointValues;
        typename FaultInterface<dim>::FaceTerms terms(problem.fe_space);
        faults.for_each_interface_point(
          problem.dof_handler,
          problem.fe_space,
          nullptr,
          [&](const PointValues &values) {
            terms.add_tangent(values, faults.stuck_tangent(values.point));
            if (!values.last_of_pair)
              return;
            stuck.constraints.distribute_local_to_global(terms.matrix,
                                                         values.dofs,
                                                         stuck.matrix);
            terms.clear();
          });
        stuck.matrix.compress(VectorOperation::add);
      }

      const FaultInterface<dim>                      &faults;
      const DiscreteProblem<dim>                     &problem;
      LinearSystem<dim>                               stuck;
      std::unique_ptr<Epetra_MultiVector>             modes;
      TrilinosWrappers::PreconditionAMG               amg;
      std::unique_ptr<SolverControl>                  control;
      std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
      std::unique_ptr<SparseCholesky>                 cholesky;
      std::unique_ptr<TwoFieldMultigrid<dim>>         multigrid;
    };
  } // namespace

  template <int dim>
  std::vector<TrilinosWrappers::MPI::Vector>
  solve_dual_problems(
    const StressGoals<dim>                                &goals,
    const DiscreteProblem<dim>                            &problem,
    LinearSolver<dim>                                     &linear_solver,
    const FaultInterface<dim>                             &faults,
    const typename FrictionalSlidingSolver<dim>::Settings &sliding_settings,
    SolverReport                                          &report)
  {
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

    // Faults that the sliding solver handles: their stuck operator, with
    // exact contact's ties at every node.
    StuckInterfaceOperator<dim> stuck(problem, faults, sliding_settings);
    if (stuck.active())
      {
        report.solver = stuck.name();
        stuck.inhomogeneity(inhomogeneity);
      }
    const AffineConstraints<double> &constraints =
      stuck.active() ? stuck.constraints() : system.constraints;

    std::vector<TrilinosWrappers::MPI::Vector> duals;
    for (unsigned int k = 0; k < goals.list().size(); ++k)
      {
        TrilinosWrappers::MPI::Vector z;
        system.rhs.reinit(system.locally_owned, communicator);
        goals.assemble_dual_rhs(k,
                                problem.dof_handler,
                                problem.fe_space,
                                problem.stress_model,
                                constraints,
                                system.rhs);
        if (stuck.active())
          {
            z.reinit(system.locally_owned, communicator);
            report.iterations += stuck.solve(z, system.rhs);
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
        constraints.distribute(z);
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
                         const FrictionalSlidingSolver<2>::Settings &,
                         SolverReport &);
} // namespace lithostress

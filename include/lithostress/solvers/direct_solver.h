#ifndef lithostress_solvers_direct_solver_h
#define lithostress_solvers_direct_solver_h

#include <lithostress/solvers/linear_solver.h>
#include <lithostress/solvers/sparse_cholesky.h>

#include <memory>
#include <string>

namespace lithostress
{
  /**
   * A sparse direct solver. `Cholesky` (the default of `Solver/Direct
   * solver`) factorises the symmetric positive definite stiffness matrix
   * on one rank (SparseCholesky) and keeps the factor for the next solve
   * of the same operator (DiscreteProblem::keep_setup): the visco-elastic
   * loop's steps and the goal-oriented dual problems then cost two
   * triangular solves each. On several ranks, or for a matrix that is not
   * positive definite, it takes Amesos KLU, and says so in the report. The
   * Amesos packages (KLU, MUMPS, SuperLU_DIST) can be named directly.
   */
  template <int dim>
  class DirectSolver : public LinearSolver<dim>
  {
  public:
    std::string
    name() const override
    {
      return "direct solver";
    }

    /** Peak memory per DoF beyond the empty program (160 MB), measured
     * (doc/performance.md, 2026-11-27): a Cholesky solve of the thrust
     * fault locked, 1 850 B at 416 k DoFs and 1 990 B at 1.65 M (the
     * factor's fill grows like log N); the frictional models, whose
     * sliding solver keeps a second matrix and its own factor, 2.4-3.0 KB.
     * 3 000 B covers both. */
    double
    memory_per_dof(const double n_dofs) const override;

    /** @p package: `Cholesky` or an Amesos package (`Amesos_Klu`, ...). */
    explicit DirectSolver(const std::string &package);

    /** Declare this solver's entries of `Solver`. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** The solver of the `Solver` subsection (entered) for @p fe_space. */
    static std::unique_ptr<LinearSolver<dim>>
    create(ParameterHandler &prm, const FiniteElementSpace<dim> &fe_space);


    SolverReport
    solve(const DiscreteProblem<dim>    &problem,
          TrilinosWrappers::MPI::Vector &solution) override;

  private:
    std::string package;
    /** The Cholesky factor kept for the next solve and the operator
     * version it was made for. */
    std::unique_ptr<SparseCholesky> kept_cholesky;
    unsigned long long              kept_version = 0;

    /** Solve with an Amesos factorisation (@p package). */
    void
    solve_with_amesos(const LinearSystem<dim>       &system,
                      const std::string             &package,
                      TrilinosWrappers::MPI::Vector &solution) const;
  };

  /**
   * `Solver/Type = automatic` where the matrix-free multigrid does not
   * apply (faults, loads with other stiffness): the direct solver's
   * Cholesky factor on one rank up to `Direct solver limit` DoFs, the
   * iterative solver it is given (CG with AMG) above it and on several
   * ranks. Decided at each solve, since adaptive cycles change the
   * DoFs.
   */
  template <int dim>
  class FactorisationOrIterativeSolver : public LinearSolver<dim>
  {
  public:
    FactorisationOrIterativeSolver(std::unique_ptr<LinearSolver<dim>> direct,
                                   std::unique_ptr<LinearSolver<dim>> iterative,
                                   const double direct_limit);

    std::string
    name() const override
    {
      return "direct solver or " + iterative->name();
    }

    double
    memory_per_dof(const double n_dofs) const override;

    SolverReport
    solve(const DiscreteProblem<dim>    &problem,
          TrilinosWrappers::MPI::Vector &solution) override;

  private:
    std::unique_ptr<LinearSolver<dim>> direct, iterative;
    double                             direct_limit;

    /** Whether a model of @p n_dofs DoFs is factorised. */
    bool
    factorises(const double n_dofs) const;
  };
} // namespace lithostress

#endif

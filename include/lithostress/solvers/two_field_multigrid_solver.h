#ifndef lithostress_solvers_two_field_multigrid_solver_h
#define lithostress_solvers_two_field_multigrid_solver_h

#include <lithostress/solvers/linear_solver.h>
#include <lithostress/solvers/two_field_multigrid.h>

#include <memory>
#include <string>

namespace lithostress
{
  /**
   * Conjugate gradients preconditioned by the geometric multigrid on the
   * assembled matrix of a faulted model (TwoFieldMultigrid: the two
   * displacement fields of doc/faults.md, Galerkin coarse operators): the
   * elastic solves of models whose faults are locked or slip by a
   * prescribed amount, where the matrix-free multigrid (one field) does
   * not apply (an elastic fault's stiff normal spring defeats its point
   * smoother). Its levels are kept while the mesh is; a new operator on
   * the same mesh (the time loop's next step size) makes only the
   * Galerkin products again. Stops when ‖r‖ ≤ tol ‖f‖.
   */
  template <int dim>
  class TwoFieldMultigridSolver : public LinearSolver<dim>
  {
  public:
    struct Settings
    {
      double       relative_tolerance = 1e-10;
      unsigned int max_iterations     = 1000;
    };

    explicit TwoFieldMultigridSolver(const Settings &settings);

    /** Declare this solver's entries of `Solver`. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** The solver of the `Solver` subsection (entered) for @p fe_space. */
    static std::unique_ptr<LinearSolver<dim>>
    create(ParameterHandler &prm, const FiniteElementSpace<dim> &fe_space);


    std::string
    name() const override
    {
      return "CG with the two fields' multigrid";
    }

    /** The finest matrix, the coarser levels' Galerkin products and
     * prolongations, and the CG vectors: a peak of 1.43 KB per DoF on the
     * locked thrust fault at 1.65 M DoFs (doc/faults.md), with a margin. */
    double
    memory_per_dof(const double) const override
    {
      return 1600;
    }

    SolverReport
    solve(const DiscreteProblem<dim>    &problem,
          TrilinosWrappers::MPI::Vector &solution) override;

  private:
    Settings settings;
    /** The levels, kept while the mesh is (mesh_version). */
    std::unique_ptr<TwoFieldMultigrid<dim>> multigrid;
    unsigned long long                      mesh_version = ~0ULL;
    /** The operator version the level operators were made for. */
    unsigned long long operator_version = ~0ULL;
  };
} // namespace lithostress

#endif

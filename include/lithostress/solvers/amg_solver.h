#ifndef lithostress_solvers_amg_solver_h
#define lithostress_solvers_amg_solver_h

#include <deal.II/lac/trilinos_precondition.h>

#include <lithostress/solvers/linear_solver.h>

#include <Epetra_MultiVector.h>

#include <string>

namespace lithostress
{
  /**
   * Conjugate gradients preconditioned by Trilinos ML smoothed-aggregation
   * AMG with all rigid-body modes as the near-null space and settings for
   * vector-valued Q2 elasticity (Chebyshev smoothing, higher-order element
   * flag). Stops when ‖r‖ ≤ tol ‖f‖ (unpreconditioned residual).
   */
  template <int dim>
  class AMGSolver : public LinearSolver<dim>
  {
  public:
    std::string
    name() const override
    {
      return "CG with AMG";
    }

    /** Peak 887 MiB at 648 k and 3 010 MiB at 2.6 M DoFs, of which 160 MB is
     * the empty program. */
    double
    memory_per_dof(const double) const override
    {
      return 1200;
    }

    struct Settings
    {
      double       relative_tolerance    = 1e-10;
      unsigned int max_iterations        = 1000;
      unsigned int smoother_sweeps       = 2;
      double       aggregation_threshold = 1e-4;
      std::string  smoother              = "Chebyshev";
      /** Time matrix-vector products (for the benchmark). */
      bool time_matrix_vector_product = false;
    };

    explicit AMGSolver(const Settings &settings);

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
    Settings settings;
    /** The AMG kept for the next solve (DiscreteProblem::keep_setup) and
     * the operator version it was made for. */
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> kept_amg;
    unsigned long long                                 kept_version = 0;
  };

  /**
   * Set up @p amg on @p matrix as ML smoothed-aggregation AMG for
   * elasticity: the rigid-body @p modes (make_rigid_body_modes) as the
   * pre-computed near-null space, `elliptic`, `PDE equations` = dim, an
   * Amesos-KLU coarse solve, and the smoother, sweeps and aggregation
   * threshold of @p settings. Shared by AMGSolver and the multigrid's AMG
   * coarse solve (CoarseGridSolver); @p modes must outlive @p amg's set-up.
   */
  template <int dim>
  void
  initialize_elasticity_amg(TrilinosWrappers::PreconditionAMG       &amg,
                            const TrilinosWrappers::SparseMatrix    &matrix,
                            const Epetra_MultiVector                &modes,
                            const typename AMGSolver<dim>::Settings &settings,
                            const bool higher_order_elements);
} // namespace lithostress

#endif

#ifndef lithostress_solvers_multigrid_solver_h
#define lithostress_solvers_multigrid_solver_h

#include <lithostress/solvers/linear_solver.h>

#include <memory>

#include <string>

namespace lithostress
{
  /**
   * CG preconditioned by a matrix-free geometric multigrid V-cycle (deal.II
   * step-37/step-50; Kronbichler & Kormann 2012, Clevenger et al. 2021):
   * the elasticity operator is applied cell by cell (ElasticOperator) on the
   * active mesh in double precision and on every level of the p4est
   * hierarchy (local smoothing, MGTransferMatrixFree with MGConstrainedDoFs
   * for refinement edges and prescribed displacements), in single precision
   * by default; Chebyshev smoothing on the diagonal; the coarse mesh solved
   * by a sparse direct solver or by CG + AMG (CoarseGridSolver). Needs no
   * matrix, no sparsity pattern and no AMG set-up; stops when ‖r‖ ≤ tol ‖f‖
   * (unpreconditioned residual, as the AMG solver).
   *
   * Applies to one displacement field of degree 1 to 3 whose extra
   * stiffness is vertical boundary springs (isostatic restoring force).
   */
  template <int dim>
  class MatrixFreeMultigridSolver : public LinearSolver<dim>
  {
  public:
    std::string
    name() const override
    {
      return "CG with matrix-free multigrid";
    }

    /** Peak 355 MiB at 648 k DoFs, of which 160 MB is the empty program. */
    double
    memory_per_dof(const double) const override
    {
      return 400;
    }

    /**
     * With global coarsening, deal.II 9.4 finds the owners of the cells of
     * each pair of levels through a dictionary of every cell index the
     * deepest level could have (CellIDTranslator: coarse cells x
     * (4^levels - 1)/3 in 2-D), split over the ranks. Its peak is about
     * 12 bytes per index (measured on the L-shaped domain, 3 coarse cells:
     * 3.5 GB at 14 levels, 13 GB at 15), however few cells the mesh has.
     */
    double
    memory_of_levels(const double       n_coarse_cells,
                     const unsigned int n_levels) const override;

    struct Settings
    {
      double       relative_tolerance = 1e-10;
      unsigned int max_iterations     = 1000;
      /** Chebyshev polynomial degree of the smoother. */
      unsigned int smoother_degree = 5;
      /** Ratio of largest to smallest eigenvalue the smoother damps. */
      double smoothing_range = 20;
      /** Multigrid levels in single precision inside double-precision CG. */
      bool single_precision_levels = true;
      /** Coarse level solved by CG + AMG instead of a direct solver. */
      bool coarse_solver_amg = false;
      /** Levels by global coarsening instead of local smoothing. */
      bool global_coarsening = false;
      /** Time operator products (for the benchmark). */
      bool time_matrix_vector_product = false;
    };

    MatrixFreeMultigridSolver(const Settings    &settings,
                              const unsigned int fe_degree);
    ~MatrixFreeMultigridSolver() override;

    /** Declare this solver's entries of `Solver`. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** The solver of the `Solver` subsection (entered) for @p fe_space. */
    static std::unique_ptr<LinearSolver<dim>>
    create(ParameterHandler &prm, const FiniteElementSpace<dim> &fe_space);


    /** Whether the multigrid applies to a model with @p fe_space and
     * @p loads; if not, @p reason says why. */
    static bool
    applies_to(const FiniteElementSpace<dim> &fe_space,
               const LoadCollection<dim>     &loads,
               std::string                   &reason);

    SolverReport
    solve(const DiscreteProblem<dim>    &problem,
          TrilinosWrappers::MPI::Vector &solution) override;

    bool
    needs_matrix() const override
    {
      return false;
    }

    /** Number the DoFs of every level. */
    void
    prepare_dof_handler(DoFHandler<dim> &dof_handler) const override;

    /** The solver for one element degree and level precision. */
    class Implementation
    {
    public:
      virtual ~Implementation() = default;
      virtual SolverReport
      solve(const DiscreteProblem<dim>    &problem,
            TrilinosWrappers::MPI::Vector &solution,
            const Settings                &settings) = 0;
    };

  private:
    Settings                        settings;
    std::unique_ptr<Implementation> implementation;
  };
} // namespace lithostress

#endif

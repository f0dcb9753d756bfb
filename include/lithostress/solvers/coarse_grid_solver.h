#ifndef lithostress_solvers_coarse_grid_solver_h
#define lithostress_solvers_coarse_grid_solver_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/elastic_moduli.h>

#include <Epetra_MultiVector.h>

#include <functional>
#include <map>
#include <memory>

namespace lithostress
{
  /**
   * The coarsest level of the geometric multigrid: the level-0 stiffness
   * (the same bilinear form as ElasticOperator — cell moduli and vertical
   * boundary springs — on the coarse mesh) assembled into a Trilinos matrix
   * and either factorised once by a sparse direct solver (Amesos KLU; the
   * default: a generator's coarse mesh has a few thousand cells, so the
   * factorisation costs milliseconds) or, for large coarse meshes (Gmsh
   * models of tens of thousands of cells, where the factors' fill-in grows
   * faster than the mesh), solved in every V-cycle by CG with smoothed-
   * aggregation AMG (ML, all rigid-body modes of level 0 as near-null
   * space) to a relative residual of 1e-8. Boundary DoFs of prescribed
   * displacements are identity rows, as in the level operator.
   */
  template <int dim, typename number>
  class CoarseGridSolver
      : public MGCoarseGridBase<LinearAlgebra::distributed::Vector<number>>
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<number>;
    /** Moduli of a cell (level-0 or active). */
    using CellModuli = std::function<LameParameters(
      const typename Triangulation<dim>::cell_iterator &cell)>;

    /** Assemble the level-0 matrix of the local-smoothing hierarchy of
     * @p dof_handler (DoFs numbered by distribute_mg_dofs) and factorise
     * it (@p use_amg false) or set up AMG on it (@p use_amg true). */
    void
    initialize(const DoFHandler<dim>                      &dof_handler,
               const FiniteElementSpace<dim>              &fe_space,
               const MGConstrainedDoFs                    &constrained_dofs,
               const CellModuli                           &moduli,
               const std::map<types::boundary_id, double> &springs,
               const bool                                  use_amg);

    /** The same on the active cells of @p dof_handler, the coarse mesh of
     * a global-coarsening hierarchy, with the homogeneous prescribed
     * displacements in @p constraints (no hanging nodes: a coarse mesh has
     * none). */
    void
    initialize(const DoFHandler<dim>                      &dof_handler,
               const FiniteElementSpace<dim>              &fe_space,
               const AffineConstraints<double>            &constraints,
               const CellModuli                           &moduli,
               const std::map<types::boundary_id, double> &springs,
               const bool                                  use_amg);

    /** Solve the level-0 system for @p src. */
    void
    operator()(const unsigned int level,
               VectorType        &dst,
               const VectorType  &src) const override;

    /** Number of level-0 DoFs. */
    types::global_dof_index
    size() const
    {
      return matrix.m();
    }

  private:
    /** Add the stiffness of the locally owned cells in @p cells (whose DoF
     * indices @p dof_indices gives) to the matrix through @p constraints,
     * then make the rows of @p identity_rows identity rows. */
    template <typename CellRange, typename DoFIndices>
    void
    assemble(const CellRange                            &cells,
             const DoFIndices                           &dof_indices,
             const FiniteElement<dim>                   &fe,
             const Mapping<dim>                         &mapping,
             const AffineConstraints<double>            &constraints,
             const CellModuli                           &moduli,
             const std::map<types::boundary_id, double> &springs,
             const IndexSet                             &identity_rows);

    /** Factorise the matrix, or set up AMG with the rigid-body @p modes. */
    void
    set_up_solver(std::unique_ptr<Epetra_MultiVector> rigid_body_modes,
                  const bool                          higher_order,
                  const bool                          use_amg);

    TrilinosWrappers::SparseMatrix                          matrix;
    mutable SolverControl                                   control;
    mutable std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
    std::unique_ptr<Epetra_MultiVector>                     modes;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG>      amg;
    mutable TrilinosWrappers::MPI::Vector                   x, b;
    IndexSet                                                owned;
  };
} // namespace lithostress

#endif

#ifndef lithostress_solvers_coarse_grid_solver_h
#define lithostress_solvers_coarse_grid_solver_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>

#include <lithostress/materials/elastic_moduli.h>

#include <functional>
#include <map>
#include <memory>

namespace lithostress
{
  /**
   * The coarsest level of the geometric multigrid solved exactly: the
   * level-0 stiffness (the same bilinear form as ElasticOperator — cell
   * moduli and vertical boundary springs — on the coarse mesh) assembled into
   * a Trilinos matrix and factorised once by a sparse direct solver (Amesos
   * KLU). The coarse mesh of a lithostress model is the generator's or the
   * Gmsh file's mesh, a few thousand cells, so the factorisation costs
   * milliseconds. Boundary DoFs of prescribed displacements are identity
   * rows, as in the level operator.
   */
  template <int dim, typename number>
  class CoarseGridSolver
      : public MGCoarseGridBase<LinearAlgebra::distributed::Vector<number>>
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<number>;
    using CellModuli = std::function<LameParameters(
      const typename DoFHandler<dim>::level_cell_iterator &cell)>;

    /** Assemble and factorise the level-0 matrix. */
    void
    initialize(const DoFHandler<dim>                      &dof_handler,
               const Mapping<dim>                         &mapping,
               const MGConstrainedDoFs                    &constrained_dofs,
               const CellModuli                           &moduli,
               const std::map<types::boundary_id, double> &springs);

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
    TrilinosWrappers::SparseMatrix                          matrix;
    mutable SolverControl                                   control;
    mutable std::unique_ptr<TrilinosWrappers::SolverDirect> direct;
    mutable TrilinosWrappers::MPI::Vector                   x, b;
    IndexSet                                                owned;
  };
} // namespace lithostress

#endif

#ifndef lithostress_faults_fault_strip_stiffness_h
#define lithostress_faults_fault_strip_stiffness_h

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/faults/fault_interface.h>
#include <lithostress/solvers/linear_solver.h>

#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The model's stiffness matrix S (the cells' stiffness and the loads'
   * terms through the problem's constraints) as a sliding solve with exact
   * contact reads it, without assembling it (doc/faults.md, "Exact normal
   * contact"). That solve has its own linearised matrix L: the same cells
   * through the problem's constraints and the contact's ties, and the
   * interface tangent T. The two differ only on the strip G of cells whose
   * DoFs reach (through the problem's constraints) the DoFs of a cell next
   * to a fault, so that
   *
   *   S = L + S_G − (L_G + T),
   *
   * S_G and L_G the strip's cell matrices through the two sets of
   * constraints. S u is L u plus products with two matrices the size of
   * the strip, and the rows of S at the faults' DoFs are those of S_G. The
   * model's matrix, as large as L (0.38 KB/DoF on Q2 elements), is then
   * not made at all.
   */
  template <int dim>
  class FaultStripStiffness
  {
  public:
    /**
     * S_G through the problem's constraints and L_G through @p ties (the
     * problem's constraints and the contact's), made when L is made with
     * @p ties and no interface tangent yet.
     */
    void
    reinit(const DiscreteProblem<dim>      &problem,
           const FaultInterface<dim>       &faults,
           const AffineConstraints<double> &ties);

    /** Record that @p tangent (of the face pair with DoFs @p dofs) was
     * added to L through @p ties; compress() after the last one. */
    void
    add_interface_tangent(const FullMatrix<double>                   &tangent,
                          const std::vector<types::global_dof_index> &dofs,
                          const AffineConstraints<double>            &ties);

    /** Finish a round of add_interface_tangent(). */
    void
    compress();

    /** @p dst := S @p src, from @p linearised = L. */
    void
    vmult(TrilinosWrappers::MPI::Vector        &dst,
          const TrilinosWrappers::SparseMatrix &linearised,
          const TrilinosWrappers::MPI::Vector  &src) const;

    /** S_G: its rows at the DoFs of the cells next to a fault are S's. */
    const TrilinosWrappers::SparseMatrix &
    model_rows() const
    {
      return model_strip;
    }

  private:
    /** S_G, and L_G + T. */
    TrilinosWrappers::SparseMatrix model_strip, linearised_strip;
    /** (L_G + T) u, in vmult(). */
    mutable TrilinosWrappers::MPI::Vector product;
  };
} // namespace lithostress

#endif

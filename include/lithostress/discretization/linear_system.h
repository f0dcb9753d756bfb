#ifndef lithostress_discretization_linear_system_h
#define lithostress_discretization_linear_system_h

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

namespace lithostress
{
  using namespace dealii;

  /**
   * The distributed linear system K u = f of one solve: the constraints
   * (hanging nodes, prescribed displacements), the Trilinos stiffness matrix
   * and right-hand side, and the index sets of owned and relevant DoFs.
   */
  template <int dim>
  class LinearSystem
  {
  public:
    /** Build the sparsity pattern (with @p constraints already closed) and
     * size the matrix and vector. @p with_matrix = false leaves the matrix
     * empty (for matrix-free solvers). @p interface_cliques are further
     * groups of DoFs that couple with each other (a fault's face pairs). */
    void
    reinit(const DoFHandler<dim> &dof_handler,
           const MPI_Comm         communicator,
           const bool             with_matrix = true,
           const std::vector<std::vector<types::global_dof_index>>
             &interface_cliques = {});

    IndexSet                       locally_owned;
    IndexSet                       locally_relevant;
    AffineConstraints<double>      constraints;
    TrilinosWrappers::SparseMatrix matrix;
    TrilinosWrappers::MPI::Vector  rhs;
  };
} // namespace lithostress

#endif

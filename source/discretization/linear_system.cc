#include <lithostress/discretization/clique_sparsity.h>
#include <lithostress/discretization/linear_system.h>

namespace lithostress
{
  template <int dim>
  void
  LinearSystem<dim>::reinit(
    const DoFHandler<dim>                                   &dof_handler,
    const MPI_Comm                                           communicator,
    const bool                                               with_matrix,
    const std::vector<std::vector<types::global_dof_index>> &interface_cliques)
  {
    rhs.reinit(locally_owned, communicator);
    matrix.clear();
    if (!with_matrix)
      return;
    // Exact row lengths from the cells' cliques: the set-up touches little
    // more memory than the matrix keeps (doc/performance.md).
    CliqueSparsity sparsity(locally_owned, constraints);
    sparsity.add_cells(dof_handler);
    for (const auto &clique : interface_cliques)
      sparsity.add_clique(clique);
    sparsity.reinit_matrix(matrix, communicator);
  }

  template class LinearSystem<2>;
} // namespace lithostress

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <lithostress/discretization/linear_system.h>

namespace lithostress
{
  template <int dim>
  void
  LinearSystem<dim>::reinit(const DoFHandler<dim> &dof_handler,
                            const MPI_Comm         communicator,
                            const bool             with_matrix)
  {
    rhs.reinit(locally_owned, communicator);
    matrix.clear();
    if (!with_matrix)
      return;
    // Build Trilinos' pattern directly (off-rank rows are exchanged by
    // compress()): cheaper than a DynamicSparsityPattern plus a copy.
    TrilinosWrappers::SparsityPattern pattern(locally_owned,
                                              locally_owned,
                                              locally_relevant,
                                              communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    pattern,
                                    constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(
                                      communicator));
    pattern.compress();
    matrix.reinit(pattern);
  }

  template class LinearSystem<2>;
} // namespace lithostress

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

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
    DynamicSparsityPattern dsp(locally_relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned,
                                               communicator,
                                               locally_relevant);
    matrix.reinit(locally_owned, locally_owned, dsp, communicator);
  }

  template class LinearSystem<2>;
} // namespace lithostress

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgq.h>

#include <lithostress/materials/cell_history.h>

namespace lithostress
{
  template <int dim>
  CellHistory<dim>::CellHistory(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const unsigned int                               n_points_1d,
    const std::vector<std::string>                  &names)
      : component_names(names)
      , nodes(n_points_1d)
      , fe(names.empty() ? nullptr
                         : std::make_unique<FESystem<dim>>(
                             FE_DGQArbitraryNodes<dim>(QGauss<1>(n_points_1d)),
                             names.size()))
      , dofs(triangulation)
  {
  }

  template <int dim>
  void
  CellHistory<dim>::setup()
  {
    if (!fe)
      return;
    dofs.distribute_dofs(*fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    field.reinit(dofs.locally_owned_dofs(),
                 relevant,
                 dofs.get_triangulation().get_communicator());
  }

  template <int dim>
  typename DoFHandler<dim>::active_cell_iterator
  CellHistory<dim>::dof_cell(
    const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    return typename DoFHandler<dim>::active_cell_iterator(
      &dofs.get_triangulation(), cell->level(), cell->index(), &dofs);
  }

  template <int dim>
  void
  CellHistory<dim>::get(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    std::vector<Vector<double>>                             &values) const
  {
    values.resize(nodes.size(), Vector<double>(n_components()));
    if (!fe)
      return;
    std::vector<types::global_dof_index> indices(fe->n_dofs_per_cell());
    dof_cell(cell)->get_dof_indices(indices);
    for (unsigned int i = 0; i < indices.size(); ++i)
      {
        const auto c_q                = fe->system_to_component_index(i);
        values[c_q.second][c_q.first] = field(indices[i]);
      }
  }

  template <int dim>
  void
  CellHistory<dim>::value(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const Point<dim>                                        &unit,
    Vector<double>                                          &record) const
  {
    record.reinit(n_components());
    if (!fe)
      return;
    std::vector<types::global_dof_index> indices(fe->n_dofs_per_cell());
    dof_cell(cell)->get_dof_indices(indices);
    for (unsigned int i = 0; i < indices.size(); ++i)
      record[fe->system_to_component_index(i).first] +=
        field(indices[i]) * fe->shape_value(i, unit);
  }

  template <int dim>
  void
  CellHistory<dim>::set(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const std::vector<Vector<double>>                       &values)
  {
    AssertDimension(values.size(), nodes.size());
    if (!fe)
      return;
    std::vector<types::global_dof_index> indices(fe->n_dofs_per_cell());
    dof_cell(cell)->get_dof_indices(indices);
    for (unsigned int i = 0; i < indices.size(); ++i)
      {
        const auto c_q    = fe->system_to_component_index(i);
        field(indices[i]) = values[c_q.second][c_q.first];
      }
  }

  template <int dim>
  void
  CellHistory<dim>::update_ghost_values()
  {
    field.update_ghost_values();
  }

  template <int dim>
  parallel::distributed::SolutionTransfer<dim,
                                          typename CellHistory<dim>::VectorType>
    &
    CellHistory<dim>::new_transfer()
  {
    field.update_ghost_values();
    transfer = std::make_unique<
      parallel::distributed::SolutionTransfer<dim, VectorType>>(dofs);
    return *transfer;
  }

  template <int dim>
  void
  CellHistory<dim>::renumber_and_read(
    const std::function<void(VectorType &)> &read)
  {
    setup();
    VectorType owned(dofs.locally_owned_dofs(),
                     dofs.get_triangulation().get_communicator());
    read(owned);
    transfer.reset();
    field.copy_locally_owned_data_from(owned);
    field.update_ghost_values();
  }

  template <int dim>
  void
  CellHistory<dim>::prepare_for_mesh_change()
  {
    if (!fe)
      return;
    new_transfer().prepare_for_coarsening_and_refinement(field);
  }

  template <int dim>
  void
  CellHistory<dim>::finish_mesh_change()
  {
    if (!fe)
      return;
    Assert(transfer, ExcMessage("prepare_for_mesh_change() was not called"));
    renumber_and_read([&](VectorType &owned) { transfer->interpolate(owned); });
  }

  template <int dim>
  void
  CellHistory<dim>::prepare_for_checkpoint()
  {
    if (!fe)
      return;
    new_transfer().prepare_for_serialization(field);
  }

  template <int dim>
  void
  CellHistory<dim>::load_from_checkpoint()
  {
    if (!fe)
      return;
    renumber_and_read([&](VectorType &owned) {
      parallel::distributed::SolutionTransfer<dim, VectorType> reader(dofs);
      reader.deserialize(owned);
    });
  }

  template class CellHistory<2>;
} // namespace lithostress

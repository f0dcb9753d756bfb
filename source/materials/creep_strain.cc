#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgq.h>

#include <lithostress/materials/creep_strain.h>

namespace lithostress
{
  template <int dim>
  CreepStrain<dim>::CreepStrain(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const unsigned int                               n_points_1d)
      : nodes(n_points_1d)
      , fe(FE_DGQArbitraryNodes<dim>(QGauss<1>(n_points_1d)), n_components)
      , dofs(triangulation)
  {
  }

  template <int dim>
  void
  CreepStrain<dim>::setup()
  {
    dofs.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    field.reinit(dofs.locally_owned_dofs(),
                 relevant,
                 dofs.get_triangulation().get_communicator());
  }

  template <int dim>
  typename DoFHandler<dim>::active_cell_iterator
  CreepStrain<dim>::dof_cell(
    const typename Triangulation<dim>::active_cell_iterator &cell) const
  {
    return typename DoFHandler<dim>::active_cell_iterator(
      &dofs.get_triangulation(), cell->level(), cell->index(), &dofs);
  }

  template <int dim>
  void
  CreepStrain<dim>::get(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    std::vector<Vector<double>>                             &values) const
  {
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    dof_cell(cell)->get_dof_indices(indices);
    values.resize(nodes.size(), Vector<double>(n_components));
    for (unsigned int i = 0; i < indices.size(); ++i)
      {
        const auto c_q                = fe.system_to_component_index(i);
        values[c_q.second][c_q.first] = field(indices[i]);
      }
  }

  template <int dim>
  SymmetricTensor<2, 3>
  CreepStrain<dim>::value(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const Point<dim>                                        &unit) const
  {
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    dof_cell(cell)->get_dof_indices(indices);
    Vector<double> c(n_components);
    for (unsigned int i = 0; i < indices.size(); ++i)
      c[fe.system_to_component_index(i).first] +=
        field(indices[i]) * fe.shape_value(i, unit);
    return tensor(c);
  }

  template <int dim>
  SymmetricTensor<2, 3>
  CreepStrain<dim>::tensor(const Vector<double> &c)
  {
    return tensor(make_array_view(c));
  }

  template <int dim>
  SymmetricTensor<2, 3>
  CreepStrain<dim>::tensor(const ArrayView<const double> &c)
  {
    AssertDimension(c.size(), n_components);
    SymmetricTensor<2, 3> t;
    if constexpr (dim == 2)
      {
        t[0][0] = c[0];
        t[1][1] = c[1];
        t[0][1] = c[2];
        t[2][2] = c[3];
      }
    else
      {
        t[0][0] = c[0];
        t[1][1] = c[1];
        t[2][2] = c[2];
        t[0][1] = c[3];
        t[1][2] = c[4];
        t[0][2] = c[5];
      }
    return t;
  }

  template <int dim>
  void
  CreepStrain<dim>::components(const SymmetricTensor<2, 3> &t,
                               Vector<double>              &c)
  {
    c.reinit(n_components);
    components(t, make_array_view(c));
  }

  template <int dim>
  void
  CreepStrain<dim>::components(const SymmetricTensor<2, 3> &t,
                               const ArrayView<double>     &c)
  {
    AssertDimension(c.size(), n_components);
    if constexpr (dim == 2)
      {
        c[0] = t[0][0];
        c[1] = t[1][1];
        c[2] = t[0][1];
        c[3] = t[2][2];
      }
    else
      {
        c[0] = t[0][0];
        c[1] = t[1][1];
        c[2] = t[2][2];
        c[3] = t[0][1];
        c[4] = t[1][2];
        c[5] = t[0][2];
      }
  }

  template <int dim>
  void
  CreepStrain<dim>::set(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const std::vector<Vector<double>>                       &values)
  {
    AssertDimension(values.size(), nodes.size());
    std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
    dof_cell(cell)->get_dof_indices(indices);
    for (unsigned int i = 0; i < indices.size(); ++i)
      {
        const auto c_q    = fe.system_to_component_index(i);
        field(indices[i]) = values[c_q.second][c_q.first];
      }
  }

  template <int dim>
  void
  CreepStrain<dim>::update_ghost_values()
  {
    field.update_ghost_values();
  }

  template <int dim>
  parallel::distributed::SolutionTransfer<dim,
                                          typename CreepStrain<dim>::VectorType>
    &
    CreepStrain<dim>::new_transfer()
  {
    field.update_ghost_values();
    transfer = std::make_unique<
      parallel::distributed::SolutionTransfer<dim, VectorType>>(dofs);
    return *transfer;
  }

  template <int dim>
  void
  CreepStrain<dim>::renumber_and_read(
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
  CreepStrain<dim>::prepare_for_mesh_change()
  {
    new_transfer().prepare_for_coarsening_and_refinement(field);
  }

  template <int dim>
  void
  CreepStrain<dim>::finish_mesh_change()
  {
    Assert(transfer, ExcMessage("prepare_for_mesh_change() was not called"));
    renumber_and_read([&](VectorType &owned) { transfer->interpolate(owned); });
  }

  template <int dim>
  void
  CreepStrain<dim>::prepare_for_checkpoint()
  {
    new_transfer().prepare_for_serialization(field);
  }

  template <int dim>
  void
  CreepStrain<dim>::load_from_checkpoint()
  {
    renumber_and_read([&](VectorType &owned) {
      parallel::distributed::SolutionTransfer<dim, VectorType> reader(dofs);
      reader.deserialize(owned);
    });
  }

  template class CreepStrain<2>;
} // namespace lithostress

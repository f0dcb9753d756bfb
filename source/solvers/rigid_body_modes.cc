#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <lithostress/solvers/rigid_body_modes.h>

namespace lithostress
{
  namespace
  {
    /**
     * The modes of make_rigid_body_modes on the DoFs of the cells
     * @p cells (with their DoF indices from @p get_dofs and ownership from
     * @p owned): active cells, or the cells of one multigrid level.
     */
    template <int dim, typename CellRange, typename IsOwned, typename GetDoFs>
    std::unique_ptr<Epetra_MultiVector>
    make_modes(const DoFHandler<dim>         &dof_handler,
               const FiniteElementSpace<dim> &fe_space,
               const Epetra_Map              &map,
               const CellRange               &cells,
               const IsOwned                 &owned,
               const GetDoFs                 &get_dofs)
    {
      const unsigned int n_rotations = dim * (dim - 1) / 2;
      const unsigned int per_field   = dim + n_rotations;
      const unsigned int n_fields    = fe_space.n_fields();
      auto               modes =
        std::make_unique<Epetra_MultiVector>(map, per_field * n_fields, true);

      // Rotations about the centre of the bounding box keep the modes well
      // scaled relative to each other.
      const MPI_Comm comm = dof_handler.get_communicator();
      Point<dim>     lo, hi;
      for (unsigned int d = 0; d < dim; ++d)
        lo[d] = std::numeric_limits<double>::max(),
        hi[d] = -std::numeric_limits<double>::max();
      for (const auto &cell : cells)
        if (owned(cell))
          for (const unsigned int v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                lo[d] = std::min(lo[d], cell->vertex(v)[d]);
                hi[d] = std::max(hi[d], cell->vertex(v)[d]);
              }
      Point<dim> centre;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lo[d]     = Utilities::MPI::min(lo[d], comm);
          hi[d]     = Utilities::MPI::max(hi[d], comm);
          centre[d] = 0.5 * (lo[d] + hi[d]);
        }

      const Quadrature<dim> support(fe_space.unit_support_points());
      const FE_Q<dim>       scalar(fe_space.degree());
      FEValues<dim>         fe_values(fe_space.mapping(),
                              scalar,
                              support,
                              update_quadrature_points);
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : cells)
        if (owned(cell))
          {
            fe_values.reinit(
              static_cast<typename Triangulation<dim>::cell_iterator>(cell));
            const auto &fe = cell->get_fe();
            dofs.resize(fe.n_dofs_per_cell());
            get_dofs(cell, dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              {
                const int lid = map.LID(static_cast<long long>(dofs[i]));
                if (lid < 0)
                  continue;
                const auto           ci    = fe.system_to_component_index(i);
                const unsigned int   field = ci.first / dim;
                const unsigned int   d     = ci.first % dim;
                const Tensor<1, dim> x =
                  fe_values.quadrature_point(ci.second) - centre;
                const unsigned int first = field * per_field;
                (*modes)[first + d][lid] = 1.0;
                if (dim == 2)
                  (*modes)[first + 2][lid] = (d == 0) ? -x[1] : x[0];
                else
                  {
                    // Rotations about z, x and y.
                    const unsigned int a[3][2] = {{0, 1}, {1, 2}, {2, 0}};
                    for (unsigned int r = 0; r < 3; ++r)
                      {
                        if (d == a[r][0])
                          (*modes)[first + dim + r][lid] = -x[a[r][1]];
                        else if (d == a[r][1])
                          (*modes)[first + dim + r][lid] = x[a[r][0]];
                      }
                  }
              }
          }
      return modes;
    }
  } // namespace

  template <int dim>
  std::unique_ptr<Epetra_MultiVector>
  make_rigid_body_modes(const DoFHandler<dim>         &dof_handler,
                        const FiniteElementSpace<dim> &fe_space,
                        const Epetra_Map              &map)
  {
    return make_modes(
      dof_handler,
      fe_space,
      map,
      dof_handler.active_cell_iterators(),
      [](const auto &cell) { return cell->is_locally_owned(); },
      [](const auto &cell, std::vector<types::global_dof_index> &dofs) {
        cell->get_dof_indices(dofs);
      });
  }

  template <int dim>
  std::unique_ptr<Epetra_MultiVector>
  make_level_rigid_body_modes(const DoFHandler<dim>         &dof_handler,
                              const FiniteElementSpace<dim> &fe_space,
                              const unsigned int             level,
                              const Epetra_Map              &map)
  {
    return make_modes(
      dof_handler,
      fe_space,
      map,
      dof_handler.mg_cell_iterators_on_level(level),
      [](const auto &cell) { return cell->is_locally_owned_on_level(); },
      [](const auto &cell, std::vector<types::global_dof_index> &dofs) {
        cell->get_mg_dof_indices(dofs);
      });
  }

  template std::unique_ptr<Epetra_MultiVector>
  make_rigid_body_modes<2>(const DoFHandler<2> &,
                           const FiniteElementSpace<2> &,
                           const Epetra_Map &);
  template std::unique_ptr<Epetra_MultiVector>
  make_level_rigid_body_modes<2>(const DoFHandler<2> &,
                                 const FiniteElementSpace<2> &,
                                 const unsigned int,
                                 const Epetra_Map &);
} // namespace lithostress

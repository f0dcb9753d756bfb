#include <deal.II/base/mpi.h>

#include <lithostress/assembly/elastic_assembler.h>
#include <lithostress/discretization/clique_sparsity.h>
#include <lithostress/faults/fault_strip_stiffness.h>

#include <algorithm>

namespace lithostress
{
  namespace
  {
    /** The DoFs of @p cliques on every rank, sorted: a cell of this rank
     * may reach a fault cell's DoF only through another rank's cell. */
    std::vector<types::global_dof_index>
    all_ranks_dofs(
      const std::vector<std::vector<types::global_dof_index>> &cliques,
      const MPI_Comm                                           communicator)
    {
      std::vector<types::global_dof_index> mine;
      for (const auto &clique : cliques)
        mine.insert(mine.end(), clique.begin(), clique.end());
      std::vector<types::global_dof_index> all;
      for (const auto &part : Utilities::MPI::all_gather(communicator, mine))
        all.insert(all.end(), part.begin(), part.end());
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
      return all;
    }

    /** Whether each active cell (by its active_cell_index()) is a locally
     * owned cell with a DoF that is, or is constrained through
     * @p constraints to, one of @p near (sorted). */
    template <int dim>
    std::vector<bool>
    strip_cells(const DoFHandler<dim>                      &dof_handler,
                const AffineConstraints<double>            &constraints,
                const std::vector<types::global_dof_index> &near)
    {
      const auto is_near = [&](const types::global_dof_index i) {
        return std::binary_search(near.begin(), near.end(), i);
      };
      std::vector<bool> strip(dof_handler.get_triangulation().n_active_cells(),
                              false);
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned() ||
              cell->get_fe().n_dofs_per_cell() == 0)
            continue;
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          for (const auto i : dofs)
            {
              bool reaches = is_near(i);
              if (const auto *line = constraints.get_constraint_entries(i))
                for (const auto &entry : *line)
                  reaches = reaches || is_near(entry.first);
              if (reaches)
                {
                  strip[cell->active_cell_index()] = true;
                  break;
                }
            }
        }
      return strip;
    }
  } // namespace

  template <int dim>
  void
  FaultStripStiffness<dim>::reinit(const DiscreteProblem<dim>      &problem,
                                   const FaultInterface<dim>       &faults,
                                   const AffineConstraints<double> &ties)
  {
    const DoFHandler<dim>           &dof_handler = problem.dof_handler;
    const AffineConstraints<double> &constraints = problem.system.constraints;
    const MPI_Comm communicator = dof_handler.get_communicator();
    const std::vector<std::vector<types::global_dof_index>> interface =
      faults.interface_cliques(dof_handler);
    // The strip: cells with a DoF that is, or is constrained to, a DoF of
    // a cell next to a fault. Elsewhere the contact's ties do not act,
    // and L's cell terms are S's.
    const std::vector<bool> strip =
      strip_cells(dof_handler,
                  constraints,
                  all_ranks_dofs(interface, communicator));
    const auto selected =
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell) {
        return strip[cell->active_cell_index()];
      };
    const auto make_pattern = [&](const AffineConstraints<double> &c,
                                  const bool with_interface,
                                  TrilinosWrappers::SparseMatrix &matrix) {
      CliqueSparsity sparsity(problem.system.locally_owned, c);
      std::vector<types::global_dof_index> dofs;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && selected(cell))
          {
            dofs.resize(cell->get_fe().n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            sparsity.add_clique(dofs);
          }
      if (with_interface)
        for (const auto &clique : interface)
          sparsity.add_clique(clique);
      sparsity.reinit_matrix(matrix, communicator);
    };
    make_pattern(constraints, false, model_strip);
    make_pattern(ties, true, linearised_strip);

    ElasticAssembler<dim> assembler(problem.fe_space,
                                    problem.stress_model,
                                    problem.loads);
    assembler.add_cell_matrices(dof_handler,
                                selected,
                                constraints,
                                model_strip);
    assembler.add_cell_matrices(dof_handler, selected, ties, linearised_strip);
    model_strip.compress(VectorOperation::add);
    linearised_strip.compress(VectorOperation::add);
    product.reinit(problem.system.locally_owned, communicator);
  }

  template <int dim>
  void
  FaultStripStiffness<dim>::add_interface_tangent(
    const FullMatrix<double>                   &tangent,
    const std::vector<types::global_dof_index> &dofs,
    const AffineConstraints<double>            &ties)
  {
    // (Added as L gets it: the diagonal a constrained row receives is
    // not linear in the tangent.)
    ties.distribute_local_to_global(tangent, dofs, linearised_strip);
  }

  template <int dim>
  void
  FaultStripStiffness<dim>::compress()
  {
    linearised_strip.compress(VectorOperation::add);
  }

  template <int dim>
  void
  FaultStripStiffness<dim>::vmult(
    TrilinosWrappers::MPI::Vector        &dst,
    const TrilinosWrappers::SparseMatrix &linearised,
    const TrilinosWrappers::MPI::Vector  &src) const
  {
    linearised.vmult(dst, src);
    model_strip.vmult_add(dst, src);
    linearised_strip.vmult(product, src);
    dst -= product;
  }

  template class FaultStripStiffness<2>;
} // namespace lithostress

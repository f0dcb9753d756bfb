#include <deal.II/base/mpi.h>

#include <lithostress/assembly/elastic_assembler.h>
#include <lithostress/discretization/clique_sparsity.h>
#include <lithostress/faults/fault_strip_stiffness.h>

#include <algorithm>

namespace lithostress
{
  namespace
  {
    /** The DoFs of the cells next to a fault on every rank, sorted: a
     * cell of this rank may reach one only through another rank's cell. */
    template <int dim>
    std::vector<types::global_dof_index>
    fault_cell_dofs(const FaultInterface<dim> &faults,
                    const DoFHandler<dim>     &dof_handler)
    {
      std::vector<types::global_dof_index> mine;
      for (const auto &clique : faults.interface_cliques(dof_handler))
        mine.insert(mine.end(), clique.begin(), clique.end());
      std::vector<types::global_dof_index> all;
      for (const auto &part :
           Utilities::MPI::all_gather(dof_handler.get_communicator(), mine))
        all.insert(all.end(), part.begin(), part.end());
      std::sort(all.begin(), all.end());
      all.erase(std::unique(all.begin(), all.end()), all.end());
      return all;
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
    const std::vector<types::global_dof_index> near =
      fault_cell_dofs(faults, dof_handler);
    const auto is_near = [&](const types::global_dof_index i) {
      return std::binary_search(near.begin(), near.end(), i);
    };
    // The strip: cells with a DoF that is, or is constrained to, a DoF of
    // a cell next to a fault. Elsewhere the contact's ties do not act,
    // and L's cell terms are S's.
    std::vector<types::global_dof_index> dofs;
    const auto                           in_strip =
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell) {
        dofs.resize(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (const auto i : dofs)
          {
            if (is_near(i))
              return true;
            if (const auto *line = constraints.get_constraint_entries(i))
              for (const auto &entry : *line)
                if (is_near(entry.first))
                  return true;
          }
        return false;
      };
    const auto make_pattern = [&](const AffineConstraints<double> &c,
                                  const bool with_interface,
                                  TrilinosWrappers::SparseMatrix &matrix) {
      CliqueSparsity sparsity(problem.system.locally_owned, c);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0 &&
            in_strip(cell))
          sparsity.add_clique(dofs); // (in_strip() read the cell's DoFs)
      if (with_interface)
        for (const auto &clique : faults.interface_cliques(dof_handler))
          sparsity.add_clique(clique);
      sparsity.reinit_matrix(matrix, communicator);
    };
    make_pattern(constraints, false, model_strip);
    make_pattern(ties, true, linearised_strip);

    ElasticAssembler<dim> assembler(problem.fe_space,
                                    problem.stress_model,
                                    problem.loads);
    const auto            selected =
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell) {
        return cell->get_fe().n_dofs_per_cell() > 0 && in_strip(cell);
      };
    assembler.add_cell_matrices(
      dof_handler, selected, constraints, 1., model_strip);
    assembler.add_cell_matrices(
      dof_handler, selected, ties, 1., linearised_strip);
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

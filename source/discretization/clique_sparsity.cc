#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <lithostress/discretization/clique_sparsity.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <map>

namespace lithostress
{
  CliqueSparsity::CliqueSparsity(const IndexSet                  &locally_owned,
                                 const AffineConstraints<double> &constraints)
      : locally_owned(locally_owned)
      , constraints(constraints)
      , clique_start(1, 0)
  {
  }


  std::size_t
  CliqueSparsity::n_cliques() const
  {
    return clique_start.size() - 1;
  }


  template <int dim>
  void
  CliqueSparsity::add_cells(const DoFHandler<dim> &dof_handler)
  {
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
        {
          dofs.resize(cell->get_fe().n_dofs_per_cell());
          cell->get_dof_indices(dofs);
          add_clique(dofs);
        }
  }


  void
  CliqueSparsity::add_clique(const std::vector<types::global_dof_index> &dofs)
  {
    scratch.clear();
    for (const types::global_dof_index dof : dofs)
      if (const auto *entries = constraints.get_constraint_entries(dof))
        for (const auto &entry : *entries)
          scratch.push_back(entry.first);
      else
        scratch.push_back(dof);
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    clique_dofs.insert(clique_dofs.end(), scratch.begin(), scratch.end());
    clique_start.push_back(clique_dofs.size());
  }


  void
  CliqueSparsity::exchange_foreign_rows(const MPI_Comm communicator)
  {
    n_cell_cliques = n_cliques();
    received_rows.clear();
    if (Utilities::MPI::n_mpi_processes(communicator) == 1)
      return;

    // The union of our cliques in each row another rank owns.
    std::map<types::global_dof_index, std::vector<types::global_dof_index>>
      foreign;
    for (std::size_t c = 0; c < n_cell_cliques; ++c)
      {
        const auto begin = clique_dofs.begin() + clique_start[c],
                   end   = clique_dofs.begin() + clique_start[c + 1];
        for (auto row = begin; row != end; ++row)
          if (!locally_owned.is_element(*row))
            {
              auto &columns = foreign[*row];
              columns.insert(columns.end(), begin, end);
            }
      }
    IndexSet foreign_rows(locally_owned.size());
    for (auto &[row, columns] : foreign)
      {
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()),
                      columns.end());
        foreign_rows.add_index(row);
      }
    foreign_rows.compress();
    const std::vector<unsigned int> owners =
      Utilities::MPI::compute_index_owner(locally_owned,
                                          foreign_rows,
                                          communicator);

    // Each message: row, number of columns, columns; repeated.
    std::map<unsigned int, std::vector<types::global_dof_index>> messages;
    unsigned int                                                 i = 0;
    for (const auto &[row, columns] : foreign)
      {
        auto &message = messages[owners[i++]];
        message.push_back(row);
        message.push_back(columns.size());
        message.insert(message.end(), columns.begin(), columns.end());
      }
    foreign.clear();

    for (const auto &[rank, message] :
         Utilities::MPI::some_to_some(communicator, messages))
      {
        (void)rank;
        for (std::size_t p = 0; p < message.size();)
          {
            const types::global_dof_index row = message[p];
            const std::size_t             n   = message[p + 1];
            AssertThrow(locally_owned.is_element(row), ExcInternalError());
            received_rows.push_back(row);
            clique_dofs.insert(clique_dofs.end(),
                               message.begin() + p + 2,
                               message.begin() + p + 2 + n);
            clique_start.push_back(clique_dofs.size());
            p += 2 + n;
          }
      }
  }


  void
  CliqueSparsity::number_columns()
  {
    const types::global_dof_index n_owned = locally_owned.n_elements();
    column_gids.clear();
    for (const types::global_dof_index dof : locally_owned)
      column_gids.push_back(dof);
    std::vector<types::global_dof_index> remote;
    for (const types::global_dof_index dof : clique_dofs)
      if (!locally_owned.is_element(dof))
        remote.push_back(dof);
    std::sort(remote.begin(), remote.end());
    remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
    column_gids.insert(column_gids.end(), remote.begin(), remote.end());

    const auto local = [&](const types::global_dof_index dof) {
      return locally_owned.is_element(dof)
               ? locally_owned.index_within_set(dof)
               : n_owned +
                   (std::lower_bound(remote.begin(), remote.end(), dof) -
                    remote.begin());
    };
    // Owned columns come first, so a clique sorted by global number need
    // not be sorted by local number any more.
    for (std::size_t c = 0; c < n_cliques(); ++c)
      {
        const auto begin = clique_dofs.begin() + clique_start[c],
                   end   = clique_dofs.begin() + clique_start[c + 1];
        std::transform(begin, end, begin, local);
        std::sort(begin, end);
      }
    std::transform(received_rows.begin(),
                   received_rows.end(),
                   received_rows.begin(),
                   local);
  }


  void
  CliqueSparsity::index_rows_to_cliques()
  {
    const unsigned int n_rows = locally_owned.n_elements();
    row_start.assign(n_rows + 1, 0);
    const auto for_each_owned_row = [&](const auto &visit) {
      for (std::size_t c = 0; c < n_cell_cliques; ++c)
        for (std::size_t p = clique_start[c]; p < clique_start[c + 1]; ++p)
          if (clique_dofs[p] < n_rows)
            visit(clique_dofs[p], c);
      for (std::size_t k = 0; k < received_rows.size(); ++k)
        visit(received_rows[k], n_cell_cliques + k);
    };
    for_each_owned_row(
      [&](const unsigned int row, const std::size_t) { ++row_start[row + 1]; });
    for (unsigned int row = 0; row < n_rows; ++row)
      row_start[row + 1] += row_start[row];
    row_cliques.resize(row_start.back());
    std::vector<unsigned int> next(row_start.begin(), row_start.end() - 1);
    for_each_owned_row([&](const unsigned int row, const std::size_t clique) {
      row_cliques[next[row]++] = clique;
    });
  }


  void
  CliqueSparsity::row_columns(const unsigned int         row,
                              std::vector<unsigned int> &columns,
                              std::vector<unsigned int> &merged) const
  {
    columns.clear();
    // A constrained row keeps only its diagonal (the cliques hold the DoFs
    // it is constrained to instead); see add_entries_local_to_global.
    if (constraints.is_constrained(column_gids[row]))
      columns.push_back(row);
    for (unsigned int p = row_start[row]; p < row_start[row + 1]; ++p)
      {
        const auto begin = clique_dofs.begin() + clique_start[row_cliques[p]],
                   end = clique_dofs.begin() + clique_start[row_cliques[p] + 1];
        merged.resize(columns.size() + (end - begin));
        merged.erase(std::set_union(columns.begin(),
                                    columns.end(),
                                    begin,
                                    end,
                                    merged.begin()),
                     merged.end());
        columns.swap(merged);
      }
  }


  namespace
  {
    /** An Epetra graph that can be told its rows are sorted (a protected
     * flag), so that FillComplete does not sort them again. */
    class SortedEpetraGraph : public Epetra_CrsGraph
    {
    public:
      using Epetra_CrsGraph::Epetra_CrsGraph;

      void
      set_sorted()
      {
        SetSorted(true);
      }
    };
  } // namespace


  void
  CliqueSparsity::reinit_matrix(TrilinosWrappers::SparseMatrix &matrix,
                                const MPI_Comm                  communicator)
  {
    using int_type = TrilinosWrappers::types::int_type;
    matrix.clear();
    exchange_foreign_rows(communicator);
    number_columns();
    index_rows_to_cliques();

    const unsigned int        n_rows = locally_owned.n_elements();
    std::vector<unsigned int> columns, merged;
    std::vector<int>          row_lengths(n_rows);
    for (unsigned int row = 0; row < n_rows; ++row)
      {
        row_columns(row, columns, merged);
        row_lengths[row] = columns.size();
      }

    // Static profile with the exact lengths: one block of indices, filled
    // once with sorted local indices, never copied or converted. The
    // column map is Epetra's own convention: owned columns first, in order.
    const Epetra_Map row_map =
      locally_owned.make_trilinos_map(communicator, false);
    const std::vector<int_type> gids(column_gids.begin(), column_gids.end());
    const Epetra_Map            column_map(
      -1, gids.size(), gids.data(), 0, row_map.Comm());
    SortedEpetraGraph graph(
      Copy, row_map, column_map, row_lengths.data(), true);
    row_lengths = std::vector<int>();
    std::vector<int> indices;
    for (unsigned int row = 0; row < n_rows; ++row)
      {
        row_columns(row, columns, merged);
        indices.assign(columns.begin(), columns.end());
        const int ierr =
          graph.InsertMyIndices(row, indices.size(), indices.data());
        AssertThrow(ierr >= 0,
                    TrilinosWrappers::SparseMatrix::ExcTrilinosError(ierr));
      }
    clique_start.assign(1, 0);
    clique_dofs   = std::vector<types::global_dof_index>();
    received_rows = std::vector<types::global_dof_index>();
    row_start     = std::vector<unsigned int>();
    row_cliques   = std::vector<unsigned int>();
    column_gids   = std::vector<types::global_dof_index>();

    graph.set_sorted();
    int ierr = graph.FillComplete(row_map, row_map);
    AssertThrow(ierr >= 0,
                TrilinosWrappers::SparseMatrix::ExcTrilinosError(ierr));
    ierr = graph.OptimizeStorage();
    AssertThrow(ierr >= 0,
                TrilinosWrappers::SparseMatrix::ExcTrilinosError(ierr));

    // deal.II 9.4 cannot adopt an Epetra graph, but it can take the graph of
    // an Epetra matrix: a view (row pointers only, no values) shares the
    // graph's data, and the matrix deal.II makes from it holds the only copy
    // of the values.
    const Epetra_CrsMatrix view(View, graph);
    matrix.reinit(view, false);
  }


  template void
  CliqueSparsity::add_cells(const DoFHandler<2> &);
  template void
  CliqueSparsity::add_cells(const DoFHandler<3> &);
} // namespace lithostress

#ifndef lithostress_discretization_clique_sparsity_h
#define lithostress_discretization_clique_sparsity_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The sparsity of a stiffness matrix that is a sum of dense element blocks
   * ("cliques"), built with exact row lengths.
   *
   * Each locally owned cell couples all its DoFs, with every constrained DoF
   * replaced by the DoFs it is constrained to, and a constrained row keeps
   * its diagonal: exactly the entries that
   * AffineConstraints::distribute_local_to_global writes (deal.II's
   * add_entries_local_to_global without kept constrained entries). A later
   * interface element (a fault) adds its own clique with add_clique().
   *
   * Why not deal.II's patterns: they grow a list per row and copy it into
   * the final graph (Trilinos' dynamic graph, or a DynamicSparsityPattern),
   * which touches about 1.5x the memory the matrix keeps. On virtual
   * machines where fresh memory costs 2-4 s per GB, that copy was most of
   * the set-up. Here the rows are unions of sorted cliques, computed twice
   * (lengths, then entries) straight into a static-profile Epetra graph;
   * the only other memory is the cliques and a row-to-clique index (about
   * 0.1 of the graph). Rows owned by another rank are sent to it first.
   */
  class CliqueSparsity
  {
  public:
    /** Cliques for a matrix whose rows @p locally_owned are ours, with
     * constrained DoFs resolved through @p constraints (closed, and
     * defined on at least the locally relevant DoFs). Both are referenced,
     * not copied. */
    CliqueSparsity(const IndexSet                  &locally_owned,
                   const AffineConstraints<double> &constraints);

    /** One clique per locally owned cell of @p dof_handler (cells without
     * DoFs, FE_Nothing, add none). */
    template <int dim>
    void
    add_cells(const DoFHandler<dim> &dof_handler);

    /** One clique: all @p dofs couple with each other once constraints are
     * resolved. Rows owned by other ranks are allowed. */
    void
    add_clique(const std::vector<types::global_dof_index> &dofs);

    /** Send the rows other ranks own to them (collective on
     * @p communicator), then build the graph with exact row lengths and size
     * @p matrix with it (all entries zero). The cliques are released. */
    void
    reinit_matrix(TrilinosWrappers::SparseMatrix &matrix,
                  const MPI_Comm                  communicator);

    /** Number of cliques added so far on this rank. */
    std::size_t
    n_cliques() const;

  private:
    /** Exchange the contributions to rows we do not own: each becomes a
     * clique at its owner, appended after the cell cliques, that adds to
     * its row (received_rows) only. */
    void
    exchange_foreign_rows(const MPI_Comm communicator);

    /** Number the columns locally (owned ones first, in order, then the
     * others ascending: column_gids) and rewrite the cliques and the
     * received rows in these numbers; an owned row's number is its
     * column's. */
    void
    number_columns();

    /** For every owned row, the cliques that add to it: the cell cliques
     * that contain it and the received cliques of that row. */
    void
    index_rows_to_cliques();

    /** The sorted local columns of owned row @p row into @p columns. */
    void
    row_columns(const unsigned int         row,
                std::vector<unsigned int> &columns,
                std::vector<unsigned int> &merged) const;

    const IndexSet                  &locally_owned;
    const AffineConstraints<double> &constraints;

    /** Clique c is clique_dofs[clique_start[c] .. clique_start[c+1]),
     * sorted and unique; global numbers until number_columns(), local
     * ones after. */
    std::vector<std::size_t>             clique_start;
    std::vector<types::global_dof_index> clique_dofs;

    /** Cliques [0, n_cell_cliques) are this rank's cells' (and
     * add_clique()'s); received clique n_cell_cliques + k adds to row
     * received_rows[k] only. */
    std::size_t                          n_cell_cliques = 0;
    std::vector<types::global_dof_index> received_rows;

    /** Owned row l gets the cliques row_cliques[row_start[l] ..
     * row_start[l+1]). */
    std::vector<unsigned int> row_start;
    std::vector<unsigned int> row_cliques;

    /** Global number of each local column. */
    std::vector<types::global_dof_index> column_gids;

    std::vector<types::global_dof_index> scratch;
  };
} // namespace lithostress

#endif

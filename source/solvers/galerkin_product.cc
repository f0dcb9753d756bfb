#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <lithostress/solvers/galerkin_product.h>

#include <EpetraExt_MatrixMatrix.h>
#include <Epetra_CrsGraph.h>
#include <Epetra_Map.h>

#include <algorithm>
#include <vector>

namespace lithostress
{
  namespace
  {
    using Matrix = TrilinosWrappers::SparseMatrix;
    using TrilinosWrappers::global_index;

    /** A rank's rows of an Epetra matrix as plain arrays: row r's columns
     * (as given) and values at offsets[r] to offsets[r + 1]. */
    struct CompressedRows
    {
      std::vector<unsigned int> offsets, columns;
      std::vector<double>       values;
    };

    /**
     * The rows of pᵀ a p on one rank, each in turn. row(i) leaves the
     * columns of coarse row i in touched (the diagonal first) and, with
     * @p with_values, their values in sum[column]: the sum of p_ki a_kj
     * p_jl over the fine rows k of column i of p, the entries a_kj of row
     * k and the entries p_jl of row j.
     */
    class RowByRowProduct
    {
    public:
      RowByRowProduct(const Epetra_CrsMatrix &a,
                      const Epetra_CrsMatrix &p,
                      const unsigned int      n_coarse)
          : a(a)
          , marker(n_coarse, numbers::invalid_unsigned_int)
          , sum(n_coarse)
      {
        const Epetra_BlockMap &fine_rows = p.RowMap();
        // p by rows, its columns as coarse DoFs, and a's columns as p's rows.
        p_rows.offsets.assign(1, 0);
        for (int r = 0; r < p.NumMyRows(); ++r)
          {
            int     n = 0;
            double *v = nullptr;
            int    *c = nullptr;
            p.ExtractMyRowView(r, n, v, c);
            for (int e = 0; e < n; ++e)
              {
                p_rows.columns.push_back(global_index(p.ColMap(), c[e]));
                p_rows.values.push_back(v[e]);
              }
            p_rows.offsets.push_back(p_rows.columns.size());
          }
        p_row_of_a_column.resize(a.ColMap().NumMyElements());
        for (unsigned int c = 0; c < p_row_of_a_column.size(); ++c)
          p_row_of_a_column[c] =
            fine_rows.LID(static_cast<TrilinosWrappers::types::int_type>(
              global_index(a.ColMap(), c)));
        // pᵀ by rows: the fine rows (a's local rows) of each coarse DoF.
        std::vector<unsigned int> count(n_coarse + 1, 0);
        for (const unsigned int l : p_rows.columns)
          ++count[l + 1];
        for (unsigned int l = 0; l < n_coarse; ++l)
          count[l + 1] += count[l];
        transposed.offsets = count;
        transposed.columns.resize(p_rows.columns.size());
        transposed.values.resize(p_rows.columns.size());
        for (int r = 0; r < p.NumMyRows(); ++r)
          {
            const int k =
              a.RowMap().LID(static_cast<TrilinosWrappers::types::int_type>(
                global_index(fine_rows, r)));
            AssertThrow(k >= 0, ExcInternalError());
            for (unsigned int e = p_rows.offsets[r]; e < p_rows.offsets[r + 1];
                 ++e)
              {
                const unsigned int slot  = count[p_rows.columns[e]]++;
                transposed.columns[slot] = k;
                transposed.values[slot]  = p_rows.values[e];
              }
          }
      }

      template <bool with_values>
      void
      row(const unsigned int i)
      {
        touched.assign(1, i);
        marker[i] = i;
        sum[i]    = 0;
        for (unsigned int t = transposed.offsets[i];
             t < transposed.offsets[i + 1];
             ++t)
          {
            const double w = transposed.values[t];
            int          n = 0;
            double      *v = nullptr;
            int         *c = nullptr;
            a.ExtractMyRowView(transposed.columns[t], n, v, c);
            for (int e = 0; e < n; ++e)
              {
                const int j = p_row_of_a_column[c[e]];
                if (j < 0)
                  continue;
                const double wa = w * v[e];
                for (unsigned int f = p_rows.offsets[j];
                     f < p_rows.offsets[j + 1];
                     ++f)
                  {
                    const unsigned int l = p_rows.columns[f];
                    if (marker[l] != i)
                      {
                        marker[l] = i;
                        if (with_values)
                          sum[l] = 0;
                        touched.push_back(l);
                      }
                    if (with_values)
                      sum[l] += wa * p_rows.values[f];
                  }
              }
          }
      }

      /** The columns of the last row(), its diagonal first. */
      std::vector<unsigned int> touched;

      /** The last row()'s entry in column @p l (one of touched). */
      double
      value(const unsigned int l) const
      {
        return sum[l];
      }

    private:
      const Epetra_CrsMatrix   &a;
      CompressedRows            p_rows, transposed;
      std::vector<int>          p_row_of_a_column;
      std::vector<unsigned int> marker;
      std::vector<double>       sum;
    };

    /** The product on one rank, row by row (galerkin_product()). Its graph
     * is made with the exact row lengths in a static profile, as
     * CliqueSparsity makes the stiffness matrix's: Trilinos' dynamic graph
     * (TrilinosWrappers::SparsityPattern on one rank) allocated a row of
     * the full width for each row. */
    void
    product_by_rows(const Matrix   &a,
                    const Matrix   &p,
                    const IndexSet &coarse_owned,
                    Matrix         &result)
    {
      const unsigned int n_coarse = coarse_owned.size();
      RowByRowProduct    product(a.trilinos_matrix(),
                              p.trilinos_matrix(),
                              n_coarse);
      // The pattern in one pass (its columns, a third of the result's
      // memory, held until the graph has them), the values in another.
      std::vector<int>          lengths(n_coarse);
      std::vector<unsigned int> offsets(1, 0);
      std::vector<int>          columns;
      for (unsigned int i = 0; i < n_coarse; ++i)
        {
          product.row<false>(i);
          std::sort(product.touched.begin(), product.touched.end());
          columns.insert(columns.end(),
                         product.touched.begin(),
                         product.touched.end());
          lengths[i] = product.touched.size();
          offsets.push_back(columns.size());
        }
      const Epetra_Map map =
        coarse_owned.make_trilinos_map(a.get_mpi_communicator(), false);
      Epetra_CrsGraph graph(Copy, map, map, lengths.data(), true);
      for (unsigned int i = 0; i < n_coarse; ++i)
        {
          const int error =
            graph.InsertMyIndices(i, lengths[i], columns.data() + offsets[i]);
          AssertThrow(error >= 0, ExcTrilinosError(error));
        }
      columns   = std::vector<int>();
      offsets   = std::vector<unsigned int>();
      int error = graph.FillComplete(map, map);
      AssertThrow(error >= 0, ExcTrilinosError(error));
      error = graph.OptimizeStorage();
      AssertThrow(error >= 0, ExcTrilinosError(error));
      // (deal.II takes the graph of a matrix that views it.)
      result.reinit(Epetra_CrsMatrix(View, graph), false);
      std::vector<types::global_dof_index> global_columns;
      std::vector<double>                  values;
      for (unsigned int i = 0; i < n_coarse; ++i)
        {
          product.row<true>(i);
          global_columns.assign(product.touched.begin(), product.touched.end());
          values.resize(global_columns.size());
          for (unsigned int e = 0; e < global_columns.size(); ++e)
            values[e] = product.value(global_columns[e]);
          result.set(i, global_columns, values, false);
        }
      result.compress(VectorOperation::insert);
    }

    /** The product on several ranks: EpetraExt's a·p and pᵀ(a·p), copied
     * into a pattern of our own (galerkin_product()). */
    void
    product_by_epetra_ext(const Matrix   &a,
                          const Matrix   &p,
                          const IndexSet &coarse_owned,
                          Matrix         &result)
    {
      // deal.II's Tmmult (ML's) wrote past an allocation on several ranks
      // (the subduction coupling's third goal-oriented mesh on 2 ranks;
      // valgrind), and so did copying a product's graph
      // (SparseMatrix::reinit(Epetra_CrsMatrix)). ML's own triple product
      // (ML_Epetra_PtAP) numbers the columns of these products differently
      // from the coarse level's DoFs: its entries were wrong.
      const MPI_Comm          communicator = a.get_mpi_communicator();
      const Epetra_CrsMatrix &ae           = a.trilinos_matrix();
      const Epetra_CrsMatrix &pe           = p.trilinos_matrix();
      Epetra_CrsMatrix        ap(Copy, ae.RowMap(), 0);
      int error = EpetraExt::MatrixMatrix::Multiply(ae, false, pe, false, ap);
      AssertThrow(error == 0, ExcTrilinosError(error));
      Epetra_CrsMatrix ptap(Copy, pe.DomainMap(), 0);
      error = EpetraExt::MatrixMatrix::Multiply(pe, true, ap, false, ptap);
      AssertThrow(error == 0, ExcTrilinosError(error));
      const Epetra_Map &rows = ptap.RowMap();
      const Epetra_Map &cols = ptap.ColMap();
      // (The lengths indexed by the global row, as deal.II reads them.)
      std::vector<types::global_dof_index> lengths(coarse_owned.size(), 0);
      for (int i = 0; i < rows.NumMyElements(); ++i)
        lengths[rows.GID(i)] = ptap.NumMyEntries(i) + 1;
      TrilinosWrappers::SparsityPattern pattern;
      pattern.reinit(coarse_owned, coarse_owned, communicator, lengths);
      std::vector<types::global_dof_index> columns;
      std::vector<double>                  values;
      const auto                           row = [&](const int i) {
        int     n = 0;
        double *v = nullptr;
        int    *c = nullptr;
        ptap.ExtractMyRowView(i, n, v, c);
        columns.assign(1, rows.GID(i));
        values.assign(1, 0.);
        for (int e = 0; e < n; ++e)
          {
            columns.push_back(cols.GID(c[e]));
            values.push_back(v[e]);
          }
      };
      for (int i = 0; i < rows.NumMyElements(); ++i)
        {
          row(i);
          pattern.add_entries(rows.GID(i), columns.begin(), columns.end());
        }
      pattern.compress();
      result.reinit(pattern);
      for (int i = 0; i < rows.NumMyElements(); ++i)
        {
          row(i);
          result.add(rows.GID(i), columns, values, false);
        }
      result.compress(VectorOperation::add);
    }
  } // namespace

  void
  galerkin_product(const TrilinosWrappers::SparseMatrix &a,
                   const TrilinosWrappers::SparseMatrix &p,
                   const IndexSet                       &coarse_owned,
                   TrilinosWrappers::SparseMatrix       &result,
                   const bool                            without_ap)
  {
    if (Utilities::MPI::n_mpi_processes(a.get_mpi_communicator()) > 1)
      product_by_epetra_ext(a, p, coarse_owned, result);
    else if (without_ap)
      product_by_rows(a, p, coarse_owned, result);
    else
      {
        Matrix ap;
        a.mmult(ap, p);
        p.Tmmult(result, ap);
      }
  }
} // namespace lithostress

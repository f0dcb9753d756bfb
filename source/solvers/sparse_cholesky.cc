#include <lithostress/base/input_error.h>
#include <lithostress/solvers/sparse_cholesky.h>

#include <suitesparse/cholmod.h>

#include <functional>
#include <string>
#include <vector>

namespace lithostress
{
  namespace
  {
    /** The upper triangle of an n × n symmetric matrix with @p nnz entries
     * in CHOLMOD's compressed columns (row indices in each column sorted
     * if @p sorted), its first column offset zero; throws
     * ComputationError if the memory is not there. */
    cholmod_sparse *
    allocate_upper_triangle(const SuiteSparse_long n,
                            const SuiteSparse_long nnz,
                            const bool             sorted,
                            cholmod_common        &common)
    {
      cholmod_sparse *csc = cholmod_l_allocate_sparse(
        n, n, nnz, sorted, true, 1, CHOLMOD_REAL, &common);
      if (!csc)
        throw ComputationError("the sparse Cholesky factorisation could not "
                               "allocate the matrix (" +
                               std::to_string(nnz) + " entries)");
      static_cast<SuiteSparse_long *>(csc->p)[0] = 0;
      return csc;
    }
  } // namespace

  /** CHOLMOD's workspace, the matrix in its compressed-column form and the
   * factor (64-bit indices: the cholmod_l_ routines). */
  struct SparseCholesky::Data
  {
    cholmod_common   common;
    cholmod_factor  *factor = nullptr;
    SuiteSparse_long n      = 0;
    /** A hash of the sparsity the factor's ordering was made for. */
    std::size_t structure = 0;
    /** CHOLMOD's flop count of one factorisation and the non-zeros of
     * the factor (from the symbolic analysis), and those of the whole
     * symmetric matrix. */
    double flops = 0, factor_nonzeros = 0, matrix_nonzeros = 0;
  };

  SparseCholesky::SparseCholesky()
      : data(std::make_unique<Data>())
  {
    cholmod_l_start(&data->common);
  }

  SparseCholesky::~SparseCholesky()
  {
    if (data->factor)
      cholmod_l_free_factor(&data->factor, &data->common);
    cholmod_l_finish(&data->common);
  }

  void
  SparseCholesky::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    AssertThrow(A.Comm().NumProc() == 1,
                ExcMessage("SparseCholesky works on one rank"));
    const SuiteSparse_long n = A.NumMyRows();
    // CHOLMOD reads the entries on and above the diagonal of a symmetric
    // matrix (stype > 0). A row of the symmetric matrix is a column of it:
    // the rows' entries left of and on the diagonal, with global column
    // indices, are the upper triangle's compressed columns; the lower
    // triangle is not copied.
    SuiteSparse_long nnz = 0;
    for (int row = 0; row < n; ++row)
      {
        int     length;
        int    *columns;
        double *values;
        A.ExtractMyRowView(row, length, values, columns);
        AssertThrow(A.GRID64(row) == row,
                    ExcMessage("SparseCholesky expects rows 0, 1, ..."));
        for (int j = 0; j < length; ++j)
          nnz += (A.GCID64(columns[j]) <= row);
      }
    cholmod_sparse *csc = allocate_upper_triangle(n, nnz, false, data->common);
    auto           *p   = static_cast<SuiteSparse_long *>(csc->p);
    auto           *i   = static_cast<SuiteSparse_long *>(csc->i);
    auto           *x   = static_cast<double *>(csc->x);
    for (int row = 0; row < n; ++row)
      {
        int     length;
        double *values;
        int    *columns;
        A.ExtractMyRowView(row, length, values, columns);
        SuiteSparse_long k = p[row];
        for (int j = 0; j < length; ++j)
          if (A.GCID64(columns[j]) <= row)
            {
              i[k]   = A.GCID64(columns[j]);
              x[k++] = values[j];
            }
        p[row + 1] = k;
      }
    factorize_upper_triangle(csc);
  }

  void
  SparseCholesky::factorize(const SparseMatrix<double> &matrix)
  {
    const SuiteSparse_long n   = matrix.m();
    SuiteSparse_long       nnz = 0;
    for (SuiteSparse_long row = 0; row < n; ++row)
      for (auto e = matrix.begin(row); e != matrix.end(row); ++e)
        nnz += (static_cast<SuiteSparse_long>(e->column()) <= row);
    cholmod_sparse *csc = allocate_upper_triangle(n, nnz, true, data->common);
    auto           *p   = static_cast<SuiteSparse_long *>(csc->p);
    auto           *i   = static_cast<SuiteSparse_long *>(csc->i);
    auto           *x   = static_cast<double *>(csc->x);
    for (SuiteSparse_long row = 0; row < n; ++row)
      {
        // deal.II stores the diagonal first, then the columns in order:
        // the column of the upper triangle wants its row indices sorted,
        // so the diagonal goes last.
        SuiteSparse_long k = p[row];
        for (auto e = matrix.begin(row); e != matrix.end(row); ++e)
          if (static_cast<SuiteSparse_long>(e->column()) < row)
            {
              i[k]   = e->column();
              x[k++] = e->value();
            }
        i[k]       = row;
        x[k++]     = matrix.diag_element(row);
        p[row + 1] = k;
      }
    factorize_upper_triangle(csc);
  }

  void
  SparseCholesky::factorize_upper_triangle(void *upper)
  {
    auto                  *csc = static_cast<cholmod_sparse *>(upper);
    const SuiteSparse_long n   = csc->nrow;
    const SuiteSparse_long nnz = static_cast<SuiteSparse_long *>(csc->p)[n];
    const auto            *i   = static_cast<const SuiteSparse_long *>(csc->i);
    const auto            *p   = static_cast<const SuiteSparse_long *>(csc->p);
    // The ordering and symbolic factorisation once per sparsity.
    std::size_t structure = std::hash<SuiteSparse_long>()(n);
    for (SuiteSparse_long k = 0; k < nnz; ++k)
      structure = structure * 1000003 ^ std::hash<SuiteSparse_long>()(i[k]);
    for (SuiteSparse_long k = 0; k <= n; ++k)
      structure = structure * 1000003 ^ std::hash<SuiteSparse_long>()(p[k]);
    if (data->factor && structure != data->structure)
      cholmod_l_free_factor(&data->factor, &data->common);
    data->structure = structure;
    if (!data->factor)
      {
        data->factor          = cholmod_l_analyze(csc, &data->common);
        data->flops           = data->common.fl;
        data->factor_nonzeros = data->common.lnz;
      }
    data->n               = n;
    data->matrix_nonzeros = 2. * nnz - n;
    const bool done =
      data->factor && cholmod_l_factorize(csc, data->factor, &data->common);
    cholmod_l_free_sparse(&csc, &data->common);
    if (!done || data->common.status == CHOLMOD_NOT_POSDEF)
      throw ComputationError(
        data->common.status == CHOLMOD_NOT_POSDEF
          ? "the sparse Cholesky factorisation found the matrix not positive "
            "definite (a model without enough boundary conditions?)"
          : "the sparse Cholesky factorisation failed (CHOLMOD status " +
              std::to_string(data->common.status) + ", out of memory?)");
  }

  void
  SparseCholesky::vmult(TrilinosWrappers::MPI::Vector       &dst,
                        const TrilinosWrappers::MPI::Vector &src) const
  {
    solve_arrays(src.trilinos_vector()[0], dst.trilinos_vector()[0]);
  }

  void
  SparseCholesky::solve(dealii::Vector<double> &rhs_and_solution) const
  {
    AssertDimension(rhs_and_solution.size(), static_cast<std::size_t>(data->n));
    solve_arrays(rhs_and_solution.data(), rhs_and_solution.data());
  }

  void
  SparseCholesky::solve_arrays(const double *b_values, double *x_values) const
  {
    cholmod_dense b;
    b.nrow  = data->n;
    b.ncol  = 1;
    b.nzmax = data->n;
    b.d     = data->n;
    b.x     = const_cast<double *>(b_values);
    b.z     = nullptr;
    b.xtype = CHOLMOD_REAL;
    b.dtype = CHOLMOD_DOUBLE;
    cholmod_dense *solution =
      cholmod_l_solve(CHOLMOD_A, data->factor, &b, &data->common);
    AssertThrow(solution, ExcMessage("CHOLMOD's solve failed"));
    const double *values = static_cast<const double *>(solution->x);
    std::copy(values, values + data->n, x_values);
    cholmod_l_free_dense(&solution, &data->common);
  }

  double
  SparseCholesky::factorization_in_solves() const
  {
    // A solve is a forward and a backward substitution, 2 nnz(L) flops
    // each; the product by the matrix 2 nnz(A).
    const double per_solve =
      4. * data->factor_nonzeros + 2. * data->matrix_nonzeros;
    return per_solve > 0 ? data->flops / per_solve : 0;
  }

  double
  SparseCholesky::memory_consumption() const
  {
    if (!data->factor)
      return 0;
    // Values and row indices of the factor.
    return (data->factor->is_super ? data->factor->xsize
                                   : data->factor->nzmax) *
           (sizeof(double) + sizeof(SuiteSparse_long));
  }
} // namespace lithostress

#ifndef lithostress_solvers_sparse_cholesky_h
#define lithostress_solvers_sparse_cholesky_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <memory>

namespace lithostress
{
  using namespace dealii;

  /**
   * The sparse Cholesky factorisation L Lᵀ = P A Pᵀ of a symmetric
   * positive definite matrix held on one rank (SuiteSparse CHOLMOD:
   * supernodal, with its fill-reducing ordering; Chen, Davis, Hager &
   * Rajamanickam 2008), applied as a preconditioner: vmult() solves with
   * it. The ordering and the symbolic factorisation are kept for later
   * factorisations of matrices with the same sparsity (the sliding
   * solver's tangents), which only redo the numerical part.
   *
   * For the faulted models' tangents in exact contact (symmetric): on the
   * thesis's thrust fault a factorisation takes a fraction of Amesos KLU's
   * time and memory (doc/performance.md).
   */
  class SparseCholesky
  {
  public:
    SparseCholesky();
    ~SparseCholesky();
    SparseCholesky(const SparseCholesky &) = delete;
    SparseCholesky &
    operator=(const SparseCholesky &) = delete;

    /** Factorise @p matrix (one rank; only its upper triangle is read).
     * Throws ComputationError if it is not positive definite or the
     * factorisation fails (out of memory). */
    void
    factorize(const TrilinosWrappers::SparseMatrix &matrix);

    /** Factorise the serial @p matrix (its entries on and below the
     * diagonal are read; the caller knows it is symmetric): the two
     * fields' multigrid's coarsest level. Throws ComputationError as
     * above. */
    void
    factorize(const SparseMatrix<double> &matrix);

    /** @p rhs_and_solution := A⁻¹ @p rhs_and_solution (serial). */
    void
    solve(dealii::Vector<double> &rhs_and_solution) const;

    /** @p dst := A⁻¹ @p src with the last factorisation. */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** The floating-point operations of one factorisation over those of
     * one preconditioned CG iteration with it (a solve with the factor,
     * 4 nnz(L), and a product by the matrix, 2 nnz(A)): a count from the
     * matrix's structure (CHOLMOD's symbolic analysis), the same on
     * every run. 0 before the first factorisation. */
    double
    factorization_in_solves() const;

    /** Bytes of the factor. */
    double
    memory_consumption() const;

  private:
    struct Data;

    /** Factorise the upper triangle @p upper (CHOLMOD's compressed
     * columns, which it frees), the ordering kept for the same sparsity. */
    void
    factorize_upper_triangle(void *upper);

    /** x := A⁻¹ b for arrays of the matrix's size. */
    void
    solve_arrays(const double *b, double *x) const;

    std::unique_ptr<Data> data;
  };
} // namespace lithostress

#endif

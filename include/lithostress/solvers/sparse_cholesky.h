#ifndef lithostress_solvers_sparse_cholesky_h
#define lithostress_solvers_sparse_cholesky_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

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

    /** @p dst := A⁻¹ @p src with the last factorisation. */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** Bytes of the factor. */
    double
    memory_consumption() const;

  private:
    struct Data;
    std::unique_ptr<Data> data;
  };
} // namespace lithostress

#endif

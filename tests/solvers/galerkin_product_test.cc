// The Galerkin product of the two fields' multigrid (galerkin_product(),
// doc/faults.md "Preconditioners"): on random sparse matrices a (symmetric
// and not) and prolongations p with empty columns and empty rows, pᵀ a p
// equals the product formed densely here, entry by entry, to round-off
// (1e-13 of the row's largest magnitude, the sums having at most a few
// hundred terms of the same sign-mixed size); every row holds its
// diagonal, also a row no coarse function reaches; a symmetric a gives a
// symmetric product. On one rank this checks the row-by-row product, on
// several ranks EpetraExt's.

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <lithostress/solvers/galerkin_product.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>

using namespace dealii;
using namespace lithostress;

namespace
{
  using Matrix = TrilinosWrappers::SparseMatrix;

  /** A random sparse m × n matrix as a dense one (the same on every rank):
   * each row about @p per_row entries, rows listed in @p empty_rows none,
   * symmetric if asked (then m = n). */
  FullMatrix<double>
  random_matrix(const unsigned int               m,
                const unsigned int               n,
                const unsigned int               per_row,
                const bool                       symmetric,
                const std::vector<unsigned int> &empty_rows,
                std::mt19937                    &random)
  {
    FullMatrix<double>                     dense(m, n);
    std::uniform_int_distribution<>        column(0, n - 1);
    std::uniform_real_distribution<double> value(-1., 1.);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int e = 0; e < per_row; ++e)
        {
          const unsigned int j = column(random);
          const double       v = value(random);
          dense(i, j) += v;
          if (symmetric)
            dense(j, i) += v;
        }
    for (const unsigned int i : empty_rows)
      for (unsigned int j = 0; j < n; ++j)
        {
          dense(i, j) = 0;
          if (symmetric)
            dense(j, i) = 0;
        }
    return dense;
  }

  /** @p dense as a distributed Trilinos matrix, rows split evenly. */
  void
  distribute(const FullMatrix<double> &dense,
             const IndexSet           &rows,
             const IndexSet           &columns,
             Matrix                   &matrix)
  {
    TrilinosWrappers::SparsityPattern pattern(rows, columns, MPI_COMM_WORLD);
    for (const auto i : rows)
      for (unsigned int j = 0; j < dense.n(); ++j)
        if (dense(i, j) != 0)
          pattern.add(i, j);
    pattern.compress();
    matrix.reinit(pattern);
    for (const auto i : rows)
      for (unsigned int j = 0; j < dense.n(); ++j)
        if (dense(i, j) != 0)
          matrix.set(i, j, dense(i, j));
    matrix.compress(VectorOperation::insert);
  }

  IndexSet
  even_split(const unsigned int n)
  {
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const unsigned int rank  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    IndexSet           owned(n);
    owned.add_range(n * rank / ranks, n * (rank + 1) / ranks);
    return owned;
  }

  /** Number of failed checks of one case. */
  unsigned int
  check_case(const unsigned int n_fine,
             const unsigned int n_coarse,
             const bool         symmetric,
             const unsigned int seed)
  {
    std::mt19937 random(seed);
    // Fine DoFs 0 and 7 without couplings, coarse DoF 3 reaching none.
    const FullMatrix<double> a =
      random_matrix(n_fine, n_fine, 6, symmetric, {0, 7}, random);
    FullMatrix<double> p =
      random_matrix(n_fine, n_coarse, 3, false, {}, random);
    for (unsigned int k = 0; k < n_fine; ++k)
      p(k, 3) = 0;
    FullMatrix<double> ap(n_fine, n_coarse), expected(n_coarse, n_coarse);
    a.mmult(ap, p);
    p.Tmmult(expected, ap);

    const IndexSet fine = even_split(n_fine), coarse = even_split(n_coarse);
    Matrix         a_matrix, p_matrix, result;
    distribute(a, fine, fine, a_matrix);
    distribute(p, fine, coarse, p_matrix);
    galerkin_product(a_matrix, p_matrix, coarse, result);

    unsigned int failed = 0;
    for (const auto i : coarse)
      {
        double largest = 0;
        for (unsigned int j = 0; j < n_coarse; ++j)
          largest = std::max(largest, std::abs(expected(i, j)));
        for (unsigned int j = 0; j < n_coarse; ++j)
          {
            const double value = result.el(i, j);
            if (std::abs(value - expected(i, j)) > 1e-13 * largest)
              {
                std::cout << "entry (" << i << ", " << j << "): " << value
                          << " against " << expected(i, j) << std::endl;
                ++failed;
              }
            // (The other triangle where this rank owns its row.)
            if (symmetric && coarse.is_element(j) &&
                std::abs(value - result.el(j, i)) > 1e-13 * largest)
              ++failed;
          }
        bool diagonal = false;
        for (auto e = result.begin(i); e != result.end(i); ++e)
          diagonal = diagonal || e->column() == i;
        if (!diagonal)
          {
            std::cout << "row " << i << " has no diagonal" << std::endl;
            ++failed;
          }
      }
    return Utilities::MPI::sum(failed, MPI_COMM_WORLD);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  unsigned int                     failed = 0;
  failed += check_case(240, 61, true, 1);
  failed += check_case(240, 61, false, 2);
  failed += check_case(97, 40, true, 3);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::cout << (failed == 0 ? "OK" : "FAILED") << ": " << failed
              << " failed checks on "
              << Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) << " rank(s)"
              << std::endl;
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

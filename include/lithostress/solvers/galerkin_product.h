#ifndef lithostress_solvers_galerkin_product_h
#define lithostress_solvers_galerkin_product_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

namespace lithostress
{
  using namespace dealii;

  /**
   * @p result := @p pᵀ @p a @p p, the Galerkin coarse operator of a
   * geometric multigrid level (TwoFieldMultigrid), whose rows this rank
   * owns are @p coarse_owned. Formed row by row or by EpetraExt (below),
   * every row holds its diagonal, also a row no coarse function reaches
   * (then 0).
   *
   * On one rank with @p without_ap the product is formed row by row of
   * the result: for coarse DoF i it sums p_ki a_kj p_jl over the fine DoFs
   * k that coarse function i reaches, in a dense accumulator over the
   * coarse DoFs, once for the pattern and once for the values. The
   * product a·p is never held: on the finest level of the plane thrust
   * (416 k DoFs) it took 137 MB, nearly as much as a itself (158 MB), and
   * set the peak memory of every multigrid set-up. It is slower than
   * ML's two products (a set-up of that thrust 4.3 s against 3.9 s), and
   * 2.4 times slower on the coarser levels, where a·p is small: there
   * (@p without_ap false) ML's products through deal.II. On several ranks the
   * fine rows of a coarse function lie on other ranks; EpetraExt's two products
   * are used there.
   */
  void
  galerkin_product(const TrilinosWrappers::SparseMatrix &a,
                   const TrilinosWrappers::SparseMatrix &p,
                   const IndexSet                       &coarse_owned,
                   TrilinosWrappers::SparseMatrix       &result,
                   const bool                            without_ap = true);
} // namespace lithostress

#endif

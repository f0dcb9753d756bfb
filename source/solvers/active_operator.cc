#include <lithostress/base/input_error.h>
#include <lithostress/solvers/active_operator.templates.h>

namespace lithostress
{
#ifdef LITHOSTRESS_SIMD_BITS
  /** The vectorised operator (solvers/active_operator_simd.cc). */
  template <int dim, int degree>
  std::unique_ptr<ActiveOperator<dim>>
  make_vectorized_active_operator(
    const Mapping<dim>                             &mapping,
    const DoFHandler<dim>                          &dof_handler,
    const AffineConstraints<double>                &constraints,
    const typename ActiveOperator<dim>::CellModuli &moduli,
    const std::map<types::boundary_id, double>     &springs);
#endif

  bool
  vectorized_operator_built()
  {
#ifdef LITHOSTRESS_SIMD_BITS
    return true;
#else
    return false;
#endif
  }

  template <int dim, int degree>
  std::unique_ptr<ActiveOperator<dim>>
  make_active_operator(const Mapping<dim>              &mapping,
                       const DoFHandler<dim>           &dof_handler,
                       const AffineConstraints<double> &constraints,
                       const typename ActiveOperator<dim>::CellModuli &moduli,
                       const std::map<types::boundary_id, double>     &springs,
                       const bool vectorized)
  {
#ifdef LITHOSTRESS_SIMD_BITS
    if (vectorized)
      return make_vectorized_active_operator<dim, degree>(
        mapping, dof_handler, constraints, moduli, springs);
#else
    AssertThrow(!vectorized,
                ExcMessage("this build has no vectorised operator "
                           "(configure with -DLITHOSTRESS_SIMD=AVX2)"));
#endif
    return std::make_unique<
      active_operator_internal::
        Implementation<dim, degree, VectorizedArray<double>>>(
      mapping, dof_handler, constraints, moduli, springs);
  }

#define LITHOSTRESS_INSTANTIATE(DEGREE)                                        \
  template std::unique_ptr<ActiveOperator<2>> make_active_operator<2, DEGREE>( \
    const Mapping<2> &,                                                        \
    const DoFHandler<2> &,                                                     \
    const AffineConstraints<double> &,                                         \
    const typename ActiveOperator<2>::CellModuli &,                            \
    const std::map<types::boundary_id, double> &,                              \
    const bool);
  LITHOSTRESS_INSTANTIATE(1)
  LITHOSTRESS_INSTANTIATE(2)
  LITHOSTRESS_INSTANTIATE(3)
#undef LITHOSTRESS_INSTANTIATE
} // namespace lithostress

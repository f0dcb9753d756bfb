/*
 * The vectorised active-mesh operator (CMake option LITHOSTRESS_SIMD):
 * compiled only in that build, with -mavx2 -mfma (AVX2) or -mavx512f.
 *
 * Debian's deal.II 9.4.1 is configured with DEAL_II_VECTORIZATION_WIDTH_IN_BITS
 * = 0, so its VectorizedArray<double, 4> and <double, 8> do not exist. Here
 * the width is replaced before numbers.h sets the default SIMD width (as
 * bench/vectorisation_probe.cc does), and MatrixFree, its DoF, mapping and
 * shape data and the evaluation kernels are instantiated in this translation
 * unit from deal.II's *.templates.h headers. Every type with the wider batch
 * carries it in its name (MatrixFree<2, double, VectorizedArray<double, 4>>),
 * and none leaves this file: the rest of the program sees ActiveOperator.
 * deal.II 9.4.1's evaluation_template_face_factory.templates.h reuses the
 * include guard of evaluation_template_factory.templates.h, hence the
 * #undef.
 */
#define dealii_numbers_h
#include <deal.II/base/config.h>
#undef dealii_numbers_h
#undef DEAL_II_VECTORIZATION_WIDTH_IN_BITS
#define DEAL_II_VECTORIZATION_WIDTH_IN_BITS LITHOSTRESS_SIMD_BITS
#include <deal.II/base/numbers.h>

#include <deal.II/matrix_free/dof_info.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory.templates.h>
#undef dealii_matrix_free_evaluation_template_factory_templates_h
#include <deal.II/matrix_free/evaluation_template_face_factory.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#include <deal.II/matrix_free/mapping_info.templates.h>
#include <deal.II/matrix_free/mapping_info_storage.templates.h>
#include <deal.II/matrix_free/matrix_free.templates.h>
#include <deal.II/matrix_free/shape_info.templates.h>

#include <lithostress/solvers/active_operator.templates.h>

namespace lithostress
{
  /** deal.II's widest batch of doubles in this translation unit. */
  using WideBatch =
    VectorizedArray<double, LITHOSTRESS_SIMD_BITS / (8 * sizeof(double))>;
  static_assert(WideBatch::size() > 1,
                "the vectorised build needs a SIMD width of 256 or 512 bits");

  template <int dim, int degree>
  std::unique_ptr<ActiveOperator<dim>>
  make_vectorized_active_operator(
    const Mapping<dim>                             &mapping,
    const DoFHandler<dim>                          &dof_handler,
    const AffineConstraints<double>                &constraints,
    const typename ActiveOperator<dim>::CellModuli &moduli,
    const std::map<types::boundary_id, double>     &springs)
  {
    return std::make_unique<
      active_operator_internal::Implementation<dim, degree, WideBatch>>(
      mapping, dof_handler, constraints, moduli, springs);
  }

#define LITHOSTRESS_INSTANTIATE(DEGREE)             \
  template std::unique_ptr<ActiveOperator<2>>       \
  make_vectorized_active_operator<2, DEGREE>(       \
    const Mapping<2> &,                             \
    const DoFHandler<2> &,                          \
    const AffineConstraints<double> &,              \
    const typename ActiveOperator<2>::CellModuli &, \
    const std::map<types::boundary_id, double> &);
  LITHOSTRESS_INSTANTIATE(1)
  LITHOSTRESS_INSTANTIATE(2)
  LITHOSTRESS_INSTANTIATE(3)
#undef LITHOSTRESS_INSTANTIATE
} // namespace lithostress

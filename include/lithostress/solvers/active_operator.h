#ifndef lithostress_solvers_active_operator_h
#define lithostress_solvers_active_operator_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <lithostress/materials/elastic_moduli.h>

#include <functional>
#include <map>
#include <memory>

namespace lithostress
{
  using namespace dealii;

  /**
   * The elasticity operator on the active mesh, in double precision, as the
   * outer CG of the matrix-free multigrid solver sees it: a product and the
   * vector layout. Behind it is an ElasticOperator with deal.II's default
   * SIMD width or, in the vectorised build (CMake option LITHOSTRESS_SIMD),
   * one batching 4 (AVX2) or 8 (AVX-512) cells per instruction, compiled in
   * its own translation unit: deal.II 9.4.1 on Debian is built without SIMD,
   * and the types of the wider batch exist only there
   * (bench/vectorisation_probe.cc measured the product 1.8x / 2.9x faster).
   * The interface carries no SIMD type, so nothing else sees the width.
   */
  template <int dim>
  class ActiveOperator
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /** Moduli of an active cell. */
    using CellModuli = std::function<LameParameters(
      const typename DoFHandler<dim>::cell_iterator &cell)>;

    /** The tangent dσ/dε at quadrature point q of an active cell. */
    using PointTangent = std::function<SymmetricTensor<4, dim>(
      const typename DoFHandler<dim>::cell_iterator &cell,
      const unsigned int                             q)>;

    virtual ~ActiveOperator() = default;

    /** Take the tangent at each quadrature point from @p tangent instead
     * of moduli per cell (a law whose tangent varies from point to point,
     * isotropic or not; ElasticOperator::set_point_tangents()). */
    virtual void
    set_point_tangents(const PointTangent &tangent) = 0;

    /** dst = A src (constrained entries: the identity). */
    virtual void
    vmult(VectorType &dst, const VectorType &src) const = 0;

    /** Size @p v with the operator's ghosted layout. */
    virtual void
    initialize_dof_vector(VectorType &v) const = 0;

    /** Memory of the operator's data [bytes]. */
    virtual std::size_t
    memory_consumption() const = 0;

    /** Cells per SIMD batch (1 without vectorisation). */
    virtual unsigned int
    cells_per_batch() const = 0;
  };

  /** Whether this build has the vectorised operator (LITHOSTRESS_SIMD). */
  bool
  vectorized_operator_built();

  /**
   * The operator of degree @p degree for @p dof_handler with @p mapping,
   * @p constraints (hanging nodes and prescribed values, applied as
   * homogeneous), cell moduli @p moduli and vertical springs @p springs
   * [Pa/m] per boundary id; vectorised if @p vectorized (only in the
   * vectorised build).
   */
  template <int dim, int degree>
  std::unique_ptr<ActiveOperator<dim>>
  make_active_operator(const Mapping<dim>              &mapping,
                       const DoFHandler<dim>           &dof_handler,
                       const AffineConstraints<double> &constraints,
                       const typename ActiveOperator<dim>::CellModuli &moduli,
                       const std::map<types::boundary_id, double>     &springs,
                       const bool vectorized);
} // namespace lithostress

#endif

#ifndef lithostress_solvers_elastic_operator_h
#define lithostress_solvers_elastic_operator_h

#include <deal.II/base/table.h>
#include <deal.II/base/vectorization.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/matrix_free/operators.h>

#include <lithostress/materials/elastic_moduli.h>

#include <functional>
#include <map>

namespace lithostress
{
  using namespace dealii;

  /**
   * The elasticity stiffness operator without a matrix (thesis §3.6; the
   * matrix-free technique of deal.II step-37 and Kronbichler &
   * Kormann 2012): v ↦ ∫ ε(w) : C ε(v) dx + ∫_Γ k |n_y| w_y v_y ds, evaluated
   * cell by cell with sum factorisation on a degree-@p fe_degree FE_Q^dim
   * space, through the MatrixFree object's mapping (curved cells follow their
   * manifolds) and constraints (hanging nodes; prescribed displacements act
   * as homogeneous constraints: the operator is the identity on them).
   *
   * The moduli are constant per cell (from the cell's material) or, for the
   * visco-elastic loop, given at each quadrature point; the boundary term is
   * the vertical spring of the isostatic restoring force (thesis §3.10) on
   * the boundary parts that carry one. Used on the active mesh in double
   * precision and on every multigrid level (in single precision by
   * default); the diagonal, for the Chebyshev smoother, includes the
   * boundary term.
   *
   * @p VectorizedArrayType is deal.II's default SIMD batch of @p number
   * everywhere but in the vectorised build (CMake option LITHOSTRESS_SIMD,
   * solvers/active_operator_simd.cc), whose active-mesh operator batches
   * 4 (AVX2) or 8 (AVX-512) cells.
   */
  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType = VectorizedArray<number>>
  class ElasticOperator : public MatrixFreeOperators::Base<
                            dim,
                            LinearAlgebra::distributed::Vector<number>,
                            VectorizedArrayType>
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<number>;
    using Base =
      MatrixFreeOperators::Base<dim, VectorType, VectorizedArrayType>;
    using MatrixFreeType = MatrixFree<dim, number, VectorizedArrayType>;
    /** Evaluators of the vector-valued space on cells and faces, and of one
     * scalar component (for the diagonal). */
    using CellEvaluation   = FEEvaluation<dim,
                                        fe_degree,
                                        fe_degree + 1,
                                        dim,
                                        number,
                                        VectorizedArrayType>;
    using FaceEvaluation   = FEFaceEvaluation<dim,
                                            fe_degree,
                                            fe_degree + 1,
                                            dim,
                                            number,
                                            VectorizedArrayType>;
    using ScalarEvaluation = FEEvaluation<dim,
                                          fe_degree,
                                          fe_degree + 1,
                                          1,
                                          number,
                                          VectorizedArrayType>;
    using CellIterator     = typename DoFHandler<dim>::cell_iterator;

    /** Moduli of the cell @p cell (a level or active cell iterator). */
    using CellModuli = std::function<LameParameters(const CellIterator &cell)>;

    /** Moduli at quadrature point @p q of cell @p cell. */
    using PointModuli = std::function<LameParameters(const CellIterator &cell,
                                                     const unsigned int  q)>;

    /** Take moduli constant per cell from @p moduli. */
    void
    set_cell_moduli(const CellModuli &moduli);

    /** Take moduli at each quadrature point from @p moduli (stored per
     * point: costs 2 numbers per point and a little speed). */
    void
    set_point_moduli(const PointModuli &moduli);

    /** The tangent dσ/dε at quadrature point @p q of cell @p cell. */
    using PointTangent =
      std::function<SymmetricTensor<4, dim>(const CellIterator &cell,
                                            const unsigned int  q)>;

    /**
     * Take any tangent at each quadrature point from @p tangent (a law
     * whose tangent varies in space and need not be isotropic, such as the
     * consistent tangent of a non-linear law): σ = C_q : ε. Where every
     * tangent of this rank's cells is isotropic (to 1e-12 of its size)
     * they are stored as moduli, as set_point_moduli(); else as tensors
     * (dim² (dim+1)²/4 numbers per point: 9 in 2-D). Either applies the
     * same tangent, so that ranks may choose differently. CG needs the
     * tangents to have the major symmetry C_ijkl = C_klij (a law whose
     * consistent tangent lacks it, a non-associated flow rule, needs
     * another Krylov method).
     */
    void
    set_point_tangents(const PointTangent &tangent);

    /**
     * Vertical spring stiffnesses k [Pa/m] per boundary id; the term is
     * k |n_y| on every face of that boundary part (the MatrixFree object
     * must have boundary-face data with normals and JxW).
     */
    void
    set_vertical_springs(
      const std::map<types::boundary_id, double> &stiffness_by_boundary);

    /** Inverse of the operator's diagonal (springs included; 1 on
     * constrained entries), for the Chebyshev smoother. */
    void
    compute_diagonal() override;

    void
    clear() override;

    /** Memory of the moduli tables and the MatrixFree data [bytes]. */
    std::size_t
    memory_consumption() const override;

  private:
    void
    apply_add(VectorType &dst, const VectorType &src) const override;

    void
    local_apply_cell(const MatrixFreeType                        &data,
                     VectorType                                  &dst,
                     const VectorType                            &src,
                     const std::pair<unsigned int, unsigned int> &range) const;

    void
    local_apply_inner_face(const MatrixFreeType &,
                           VectorType &,
                           const VectorType &,
                           const std::pair<unsigned int, unsigned int> &) const
    {
    }

    void
    local_apply_boundary(
      const MatrixFreeType                        &data,
      VectorType                                  &dst,
      const VectorType                            &src,
      const std::pair<unsigned int, unsigned int> &range) const;

    /** The stress of the strain at every quadrature point of @p phi, with
     * a fast path for axis-parallel cells with moduli per cell. */
    template <typename Evaluator>
    void
    do_cell_integral(Evaluator &phi) const;

    /** The stress of the strain at every quadrature point of @p phi, for
     * any cell shape. */
    template <typename Evaluator>
    void
    do_general_cell_integral(Evaluator &phi) const;

    /** Whether the moduli are stored per quadrature point (else per cell
     * or as whole tangents). */
    bool
    moduli_at_points() const
    {
      return lambda_point.n_rows() > 0;
    }

    /** Whether whole tangents are stored per quadrature point. */
    bool
    tangents_at_points() const
    {
      return tangent_point.n_rows() > 0;
    }

    /** Call @p visit(batch, lane, cell, q) at every quadrature point of
     * every cell while it returns true; whether it always did. */
    template <typename Visitor>
    bool
    visit_points(const Visitor &visit) const;

    /** The spring traction of the displacement at every point of @p phi. */
    template <typename FaceEvaluator>
    void
    do_boundary_integral(FaceEvaluator &phi, const number k) const;

    /** Spring stiffness of boundary id @p id, 0 if none. */
    number
    spring_stiffness(const types::boundary_id id) const;

    AlignedVector<VectorizedArrayType> lambda_cell, mu_cell;
    Table<2, VectorizedArrayType>      lambda_point, mu_point;
    Table<2, SymmetricTensor<4, dim, VectorizedArrayType>> tangent_point;
    std::map<types::boundary_id, double>                   springs;
  };
} // namespace lithostress

#endif

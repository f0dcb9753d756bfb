#ifndef lithostress_solvers_active_operator_templates_h
#define lithostress_solvers_active_operator_templates_h

#include <deal.II/base/quadrature_lib.h>

#include <lithostress/solvers/active_operator.h>
#include <lithostress/solvers/elastic_operator.templates.h>

/*
 * The ActiveOperator behind the interface, for one SIMD type; included by
 * solvers/active_operator.cc (deal.II's default width) and
 * solvers/active_operator_simd.cc (the vectorised build).
 */
namespace lithostress
{
  namespace active_operator_internal
  {
    /** An ElasticOperator with batches of @p VectorizedArrayType. */
    template <int dim, int degree, typename VectorizedArrayType>
    class Implementation : public ActiveOperator<dim>
    {
    public:
      using VectorType = typename ActiveOperator<dim>::VectorType;

      Implementation(const Mapping<dim>              &mapping,
                     const DoFHandler<dim>           &dof_handler,
                     const AffineConstraints<double> &constraints,
                     const typename ActiveOperator<dim>::CellModuli &moduli,
                     const std::map<types::boundary_id, double>     &springs)
      {
        using MatrixFreeType = MatrixFree<dim, double, VectorizedArrayType>;
        typename MatrixFreeType::AdditionalData data;
        data.tasks_parallel_scheme = MatrixFreeType::AdditionalData::none;
        data.mapping_update_flags  = update_gradients | update_JxW_values;
        bool any_spring            = false;
        for (const auto &[id, k] : springs)
          any_spring = any_spring || k != 0;
        if (any_spring)
          data.mapping_update_flags_boundary_faces =
            update_values | update_normal_vectors | update_JxW_values;
        auto matrix_free = std::make_shared<MatrixFreeType>();
        matrix_free->reinit(
          mapping, dof_handler, constraints, QGauss<1>(degree + 1), data);
        op.initialize(matrix_free);
        op.set_cell_moduli(moduli);
        op.set_vertical_springs(springs);
      }

      void
      set_point_tangents(
        const typename ActiveOperator<dim>::PointTangent &tangent) override
      {
        op.set_point_tangents(tangent);
      }

      void
      vmult(VectorType &dst, const VectorType &src) const override
      {
        op.vmult(dst, src);
      }

      void
      initialize_dof_vector(VectorType &v) const override
      {
        op.initialize_dof_vector(v);
      }

      std::size_t
      memory_consumption() const override
      {
        return op.memory_consumption();
      }

      unsigned int
      cells_per_batch() const override
      {
        return VectorizedArrayType::size();
      }

    private:
      ElasticOperator<dim, degree, double, VectorizedArrayType> op;
    };
  } // namespace active_operator_internal
} // namespace lithostress

#endif

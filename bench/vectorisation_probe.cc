/**
 * Vectorisation probe (bench/, not part of the program): the time of one
 * product with the Q2 plane-strain elasticity operator on the 648 k-DoF
 * flexure mesh, with deal.II's MatrixFree at the SIMD width chosen at
 * compile time — 1 (Debian's deal.II is built without SIMD), 4 (AVX2) or 8
 * (AVX-512) doubles per batch — without rebuilding deal.II.
 *
 * How: VECTORIZATION_BITS (256 or 512) replaces deal.II's configured
 * DEAL_II_VECTORIZATION_WIDTH_IN_BITS = 0 before numbers.h sets the default
 * VectorizedArray width, and MatrixFree, its DoF, mapping and shape data
 * and the evaluation kernels are instantiated in this translation unit from
 * deal.II's *.templates.h headers (compile with -march=native or -mavx2).
 * deal.II 9.4.1's evaluation_template_face_factory.templates.h reuses the
 * include guard of evaluation_template_factory.templates.h, hence the
 * #undef. doc/performance.md ("Vectorisation") has the measurements.
 *
 * Build: make -C build vectorisation_probe_1 vectorisation_probe_4
 *        vectorisation_probe_8; run each (one line per run).
 */
#ifdef VECTORIZATION_BITS
#define dealii_numbers_h
#include <deal.II/base/config.h>
#undef dealii_numbers_h
#undef DEAL_II_VECTORIZATION_WIDTH_IN_BITS
#define DEAL_II_VECTORIZATION_WIDTH_IN_BITS VECTORIZATION_BITS
#include <deal.II/base/numbers.h>
#endif
#include <deal.II/base/config.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>
#ifdef VECTORIZATION_BITS
#include <deal.II/matrix_free/dof_info.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory.templates.h>
#undef dealii_matrix_free_evaluation_template_factory_templates_h
#include <deal.II/matrix_free/evaluation_template_face_factory.templates.h>
#include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#include <deal.II/matrix_free/mapping_info.templates.h>
#include <deal.II/matrix_free/mapping_info_storage.templates.h>
#include <deal.II/matrix_free/matrix_free.templates.h>
#include <deal.II/matrix_free/shape_info.templates.h>
#endif

#include <algorithm>
#include <functional>
#include <iostream>

using namespace dealii;

int
main()
{
  using VectorType = LinearAlgebra::distributed::Vector<double>;
  // The flexure benchmark's mesh: 1000 x 20 km, 250 x 5 cells, 3 global
  // refinements (80 000 cells, 648 162 Q2 DoFs).
  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_rectangle(tria,
                                            {250u, 5u},
                                            Point<2>(0, -2e4),
                                            Point<2>(1e6, 0));
  tria.refine_global(3);
  const FESystem<2> fe(FE_Q<2>(2), 2);
  DoFHandler<2>     dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  AffineConstraints<double> constraints;
  constraints.close();

  MatrixFree<2, double>                          matrix_free;
  typename MatrixFree<2, double>::AdditionalData data;
  data.tasks_parallel_scheme = MatrixFree<2, double>::AdditionalData::none;
  data.mapping_update_flags  = update_gradients | update_JxW_values;
  matrix_free.reinit(
    MappingQ1<2>(), dof_handler, constraints, QGauss<1>(3), data);

  VectorType src, dst;
  matrix_free.initialize_dof_vector(src);
  matrix_free.initialize_dof_vector(dst);
  for (unsigned int i = 0; i < src.locally_owned_size(); ++i)
    src.local_element(i) = 0.1 * (i % 7);

  // Plane strain, E = 0.85e11 Pa, nu = 0.25.
  const double lambda = 3.4e10, mu = 3.4e10;
  const std::function<void(const MatrixFree<2, double> &,
                           VectorType &,
                           const VectorType &,
                           const std::pair<unsigned int, unsigned int> &)>
    cell_operation = [&](const MatrixFree<2, double>                 &mf,
                         VectorType                                  &out,
                         const VectorType                            &in,
                         const std::pair<unsigned int, unsigned int> &cells) {
      FEEvaluation<2, 2, 3, 2, double> phi(mf);
      for (unsigned int cell = cells.first; cell < cells.second; ++cell)
        {
          phi.reinit(cell);
          phi.gather_evaluate(in, EvaluationFlags::gradients);
          for (unsigned int q = 0; q < phi.n_q_points; ++q)
            {
              const auto strain = phi.get_symmetric_gradient(q);
              auto       stress = 2. * mu * strain;
              const auto volume = trace(strain);
              for (unsigned int d = 0; d < 2; ++d)
                stress[d][d] += lambda * volume;
              phi.submit_symmetric_gradient(stress, q);
            }
          phi.integrate_scatter(EvaluationFlags::gradients, out);
        }
    };

  double fastest = 1e300;
  for (unsigned int k = 0; k < 20; ++k)
    {
      Timer timer;
      matrix_free.cell_loop(cell_operation, dst, src, true);
      fastest = std::min(fastest, timer.wall_time());
    }
  std::cout << "{\"simd_doubles\": " << VectorizedArray<double>::size()
            << ", \"dofs\": " << dof_handler.n_dofs()
            << ", \"product_ms\": " << 1e3 * fastest
            << ", \"result_norm\": " << dst.l2_norm() << "}" << std::endl;
}

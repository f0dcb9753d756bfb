// The matrix-free elasticity operator against an assembled matrix (issue 5,
// verification 1): on a curved (quarter annulus, degree-2 mapping),
// adaptively refined (hanging nodes, also on curved boundaries), two-material
// mesh with vertical springs on a curved and a straight boundary part and
// prescribed displacements (one part fixed, one a roller), the product of
// ElasticOperator with random vectors equals the product with a matrix
// assembled here, independently, with FEValues — to round-off. Checked with
// moduli per cell (by material), per quadrature point (varying in space)
// and with a tangent per quadrature point that is not isotropic
// (ElasticOperator::set_point_tangents: the isotropic moduli plus
// beta(x) A (x) A, A a fixed symmetric tensor, as a non-linear law's
// consistent tangent adds a rank-one term), on whatever number of ranks the
// test is started on. The same on an
// adaptively refined rectangle of non-square cells, where the operator takes
// its fast path for axis-parallel cells (checked to be taken), with springs
// on the base and on a vertical side (where k |n_y| vanishes). In the
// vectorised build (CMake LITHOSTRESS_SIMD) the active-mesh operator with
// the wider SIMD batch (ActiveOperator) is checked against the same matrix.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <lithostress/solvers/active_operator.h>
#include <lithostress/solvers/elastic_operator.h>

#include <cstdlib>
#include <iostream>
#include <random>

using namespace dealii;
using namespace lithostress;

namespace
{
  constexpr int dim    = 2;
  constexpr int degree = 2;

  // Two materials (inner ring 0, outer shell 1) with contrasting moduli.
  LameParameters
  material_moduli(const types::material_id id)
  {
    return id == 0 ? LameParameters{2.0e10, 3.0e10}
                   : LameParameters{7.0e10, 1.0e10};
  }

  // Moduli varying in space (for the per-point variant): smooth, positive.
  LameParameters
  point_moduli(const types::material_id id, const Point<dim> &p)
  {
    LameParameters m = material_moduli(id);
    m.lambda *= 1 + 0.5 * std::sin(3 * p[0]) * std::cos(2 * p[1]);
    m.mu *= 1.5 + 0.4 * std::cos(p[0] + 2 * p[1]);
    return m;
  }

  /** How the operator is given its stiffness. */
  enum class Moduli
  {
    per_cell,
    at_points,
    anisotropic
  };

  const char *
  name(const Moduli moduli)
  {
    return moduli == Moduli::per_cell    ? "moduli per cell "
           : moduli == Moduli::at_points ? "moduli at points"
                                         : "tangent at points";
  }

  // A tangent at points that is not isotropic: point_moduli's plus
  // beta A (x) A, beta of the order of mu and varying in space (symmetric
  // and positive definite).
  SymmetricTensor<4, dim>
  point_tangent(const types::material_id id, const Point<dim> &p)
  {
    const LameParameters    m = point_moduli(id, p);
    SymmetricTensor<4, dim> C;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        C[i][i][j][j] = m.lambda;
    C += 2 * m.mu * identity_tensor<dim>();
    SymmetricTensor<2, dim> A;
    A[0][0] = 1;
    A[1][1] = -0.5;
    A[0][1] = 0.3;
    return C + (0.8 + 0.3 * std::sin(p[0] - p[1])) * m.mu * outer_product(A, A);
  }

  // Spring stiffnesses [Pa/m] of the order of μ/h (h ≈ 0.03 the finest
  // cells), so that the boundary term is a sizeable part of the product
  // with a random vector (the check of the check below makes sure).
  const std::map<types::boundary_id, double> springs = {{1, 1.0e12},
                                                        {2, 2.0e12}};

  /**
   * The test mesh: a quarter annulus (curved cells) or a 2 x 1 rectangle of
   * 3 x 2 non-square cells (axis-parallel cells). Boundary ids: annulus 0
   * inner arc, 1 outer arc, 2 and 3 the straight sides; rectangle 0 left,
   * 1 right, 2 base, 3 top. Material 1 in the outer shell / upper half.
   * Refined twice near an interior point and near a spring boundary, so
   * that hanging nodes sit on spring boundaries.
   */
  void
  make_mesh(parallel::distributed::Triangulation<dim> &tria,
            const bool                                 rectangle)
  {
    if (rectangle)
      GridGenerator::subdivided_hyper_rectangle(
        tria, {3, 2}, Point<dim>(0, 0), Point<dim>(2, 1), true);
    else
      GridGenerator::quarter_hyper_shell(tria, Point<dim>(), 1.0, 2.0, 0, true);
    tria.refine_global(2);
    for (const auto &cell : tria.active_cell_iterators())
      cell->set_material_id(
        (rectangle ? cell->center()[1] > 0.5 : cell->center().norm() > 1.5)
          ? 1
          : 0);
    const Point<dim> focus =
      rectangle ? Point<dim>(1.3, 0.6) : Point<dim>(1.3, 1.3);
    for (unsigned int step = 0; step < 2; ++step)
      {
        for (const auto &cell : tria.active_cell_iterators())
          if (cell->is_locally_owned() &&
              (cell->center().distance(focus) < 0.45 ||
               cell->center()[1] < 0.25))
            cell->set_refine_flag();
        tria.execute_coarsening_and_refinement();
      }
  }

  using Operator = ElasticOperator<dim, degree, double>;

  /** One test mesh with its DoFs, constraints and the assembled matrix. */
  struct TestProblem
  {
    TestProblem(parallel::distributed::Triangulation<dim> &tria)
        : comm(tria.get_communicator())
        , rank(Utilities::MPI::this_mpi_process(comm))
        , fe(FE_Q<dim>(degree), dim)
        , mapping(2)
        , dof_handler(tria)
    {
      dof_handler.distribute_dofs(fe);
      owned    = dof_handler.locally_owned_dofs();
      relevant = DoFTools::extract_locally_relevant_dofs(dof_handler);
      constraints.reinit(relevant);
      DoFTools::make_hanging_node_constraints(dof_handler, constraints);
      VectorTools::interpolate_boundary_values(mapping,
                                               dof_handler,
                                               0,
                                               Functions::ZeroFunction<dim>(
                                                 dim),
                                               constraints);
      VectorTools::interpolate_boundary_values(
        mapping,
        dof_handler,
        3,
        Functions::ZeroFunction<dim>(dim),
        constraints,
        ComponentMask(std::vector<bool>{true, false}));
      constraints.close();
    }

    MPI_Comm                       comm;
    unsigned int                   rank;
    FESystem<dim>                  fe;
    MappingQ<dim>                  mapping;
    DoFHandler<dim>                dof_handler;
    IndexSet                       owned, relevant;
    AffineConstraints<double>      constraints;
    TrilinosWrappers::SparseMatrix matrix;
  };

  /** The cell matrix of elasticity and the springs, with FEValues. */
  void
  cell_matrix(const typename DoFHandler<dim>::active_cell_iterator &cell,
              FEValues<dim>                                        &fe_values,
              FEFaceValues<dim>                                    &face_values,
              const Moduli                                          moduli,
              FullMatrix<double>                                   &matrix)
  {
    const FEValuesExtractors::Vector u(0);
    const unsigned int               n = matrix.m();
    matrix                             = 0;
    fe_values.reinit(cell);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const Point<dim>             &p = fe_values.quadrature_point(q);
        const LameParameters          m = moduli == Moduli::per_cell
                                            ? material_moduli(cell->material_id())
                                            : point_moduli(cell->material_id(), p);
        const SymmetricTensor<4, dim> C =
          moduli == Moduli::anisotropic ? point_tangent(cell->material_id(), p)
                                        : SymmetricTensor<4, dim>();
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              const auto ei = fe_values[u].symmetric_gradient(i, q);
              const auto ej = fe_values[u].symmetric_gradient(j, q);
              matrix(i, j) +=
                (moduli == Moduli::anisotropic
                   ? ei * C * ej
                   : m.lambda * trace(ei) * trace(ej) + 2 * m.mu * (ei * ej)) *
                fe_values.JxW(q);
            }
      }
    for (const unsigned int f : cell->face_indices())
      if (cell->at_boundary(f) && springs.count(cell->face(f)->boundary_id()))
        {
          face_values.reinit(cell, f);
          const double k = springs.at(cell->face(f)->boundary_id());
          for (const unsigned int q : face_values.quadrature_point_indices())
            for (unsigned int i = 0; i < n; ++i)
              for (unsigned int j = 0; j < n; ++j)
                matrix(i, j) += k * std::abs(face_values.normal_vector(q)[1]) *
                                face_values[u].value(i, q)[1] *
                                face_values[u].value(j, q)[1] *
                                face_values.JxW(q);
        }
  }

  /** The matrix assembled here, independently of the operator. */
  void
  assemble_matrix(TestProblem &problem, const Moduli moduli)
  {
    TrilinosWrappers::SparsityPattern pattern(problem.owned,
                                              problem.owned,
                                              problem.relevant,
                                              problem.comm);
    DoFTools::make_sparsity_pattern(
      problem.dof_handler, pattern, problem.constraints, false, problem.rank);
    pattern.compress();
    problem.matrix.reinit(pattern);
    const QGauss<dim>                    quadrature(degree + 1);
    const QGauss<dim - 1>                face_quadrature(degree + 1);
    FEValues<dim>                        fe_values(problem.mapping,
                            problem.fe,
                            quadrature,
                            update_gradients | update_JxW_values |
                              update_quadrature_points);
    FEFaceValues<dim>                    face_values(problem.mapping,
                                  problem.fe,
                                  face_quadrature,
                                  update_values | update_normal_vectors |
                                    update_JxW_values);
    const unsigned int                   n = problem.fe.n_dofs_per_cell();
    FullMatrix<double>                   local(n, n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_matrix(cell, fe_values, face_values, moduli, local);
          cell->get_dof_indices(dofs);
          problem.constraints.distribute_local_to_global(local,
                                                         dofs,
                                                         problem.matrix);
        }
    problem.matrix.compress(VectorOperation::add);
  }

  /** Check of the check: the rectangle exercises the operator's path for
   * axis-parallel cells, the annulus the general one. */
  unsigned int
  check_cell_batches(const MatrixFree<dim, double> &matrix_free,
                     const bool                     rectangle,
                     const bool                     print)
  {
    unsigned int cartesian = 0;
    for (unsigned int b = 0; b < matrix_free.n_cell_batches(); ++b)
      cartesian += matrix_free.get_mapping_info().get_cell_type(b) ==
                       internal::MatrixFreeFunctions::cartesian
                     ? 1
                     : 0;
    const bool as_meant = rectangle ? cartesian == matrix_free.n_cell_batches()
                                    : cartesian < matrix_free.n_cell_batches();
    if (print)
      std::cout << "axis-parallel cell batches: " << cartesian << " of "
                << matrix_free.n_cell_batches()
                << (as_meant ? "  ok" : "  FAILED") << std::endl;
    return as_meant ? 0 : 1;
  }

  /** The matrix-free operator on the test problem's mesh and constraints. */
  std::shared_ptr<MatrixFree<dim, double>>
  make_matrix_free(const TestProblem &problem)
  {
    typename MatrixFree<dim, double>::AdditionalData data;
    data.tasks_parallel_scheme = MatrixFree<dim, double>::AdditionalData::none;
    data.mapping_update_flags  = update_gradients | update_JxW_values;
    data.mapping_update_flags_boundary_faces =
      update_values | update_normal_vectors | update_JxW_values;
    auto matrix_free = std::make_shared<MatrixFree<dim, double>>();
    matrix_free->reinit(problem.mapping,
                        problem.dof_handler,
                        problem.constraints,
                        QGauss<1>(degree + 1),
                        data);
    return matrix_free;
  }

  /** The largest difference on unconstrained owned DoFs, over all ranks. */
  template <typename VectorA, typename VectorB>
  double
  max_difference(const TestProblem &problem, const VectorA &a, const VectorB &b)
  {
    double difference = 0;
    for (const types::global_dof_index i : problem.owned)
      if (!problem.constraints.is_constrained(i))
        difference = std::max(difference, std::abs(a(i) - b(i)));
    return Utilities::MPI::max(difference, problem.comm);
  }

  /** Check of the check: the spring term matters in the product K x. */
  unsigned int
  check_springs_visible(
    const std::shared_ptr<MatrixFree<dim, double>>   &matrix_free,
    const LinearAlgebra::distributed::Vector<double> &x,
    const LinearAlgebra::distributed::Vector<double> &y,
    const double                                      norm,
    const bool                                        print)
  {
    Operator without_springs;
    without_springs.initialize(matrix_free);
    without_springs.set_cell_moduli(
      [](const typename Operator::CellIterator &cell) {
        return material_moduli(cell->material_id());
      });
    LinearAlgebra::distributed::Vector<double> z;
    without_springs.initialize_dof_vector(z);
    without_springs.vmult(z, x);
    z -= y;
    const double spring_part = z.linfty_norm() / norm;
    const bool   visible     = spring_part > 1e-2;
    if (print)
      std::cout << "springs change K x by " << spring_part << " of max |K x|"
                << (visible ? "  ok" : "  FAILED") << std::endl;
    return visible ? 0 : 1;
  }

  /** The vectorised operator (moduli per cell, as the solver uses it)
   * against the assembled matrix's product @p yt with @p x. */
  unsigned int
  check_vectorised(const TestProblem                                &problem,
                   const LinearAlgebra::distributed::Vector<double> &x,
                   const TrilinosWrappers::MPI::Vector              &yt,
                   const double                                      norm,
                   const unsigned int                                trial)
  {
    const auto wide = make_active_operator<dim, degree>(
      problem.mapping,
      problem.dof_handler,
      problem.constraints,
      [](const typename DoFHandler<dim>::cell_iterator &cell) {
        return material_moduli(cell->material_id());
      },
      springs,
      true);
    LinearAlgebra::distributed::Vector<double> xw, yw;
    wide->initialize_dof_vector(xw);
    wide->initialize_dof_vector(yw);
    for (const types::global_dof_index i : problem.owned)
      xw(i) = x(i);
    wide->vmult(yw, xw);
    const double difference = max_difference(problem, yw, yt);
    const bool   ok = difference <= 1e-12 * norm && wide->cells_per_batch() > 1;
    if (problem.rank == 0)
      std::cout << "vectorised (" << wide->cells_per_batch()
                << " cells per batch), trial " << trial
                << ": max |K x - A x| / max |K x| = " << difference / norm
                << (ok ? "  ok" : "  FAILED") << std::endl;
    return ok ? 0 : 1;
  }

  /** Products of the operator and of the matrix with random vectors. */
  unsigned int
  check_products(const TestProblem                              &problem,
                 const Operator                                 &op,
                 const std::shared_ptr<MatrixFree<dim, double>> &matrix_free,
                 const Moduli                                    moduli)
  {
    unsigned int                           failures = 0;
    std::mt19937                           random(17 + problem.rank);
    std::uniform_real_distribution<double> uniform(-1, 1);
    for (unsigned int trial = 0; trial < 3; ++trial)
      {
        LinearAlgebra::distributed::Vector<double> x, y;
        op.initialize_dof_vector(x);
        op.initialize_dof_vector(y);
        TrilinosWrappers::MPI::Vector xt(problem.owned, problem.comm),
          yt(problem.owned, problem.comm);
        for (const types::global_dof_index i : problem.owned)
          if (!problem.constraints.is_constrained(i))
            {
              const double value = uniform(random);
              x(i)               = value;
              xt[i]              = value;
            }
        xt.compress(VectorOperation::insert);
        op.vmult(y, x);
        problem.matrix.vmult(yt, xt);
        const double difference = max_difference(problem, y, yt);
        const double norm = Utilities::MPI::max(yt.linfty_norm(), problem.comm);
        if (moduli == Moduli::per_cell)
          {
            failures +=
              check_springs_visible(matrix_free, x, y, norm, problem.rank == 0);
            if (vectorized_operator_built())
              failures += check_vectorised(problem, x, yt, norm, trial);
          }
        // Round-off: both sum O(100) products of O(norm) terms per row in
        // a different order; 1e-12 is ~5000 ulp of the largest entry.
        const bool ok = difference <= 1e-12 * norm;
        failures += ok ? 0 : 1;
        if (problem.rank == 0)
          std::cout << name(moduli) << ", trial " << trial << ": "
                    << problem.dof_handler.n_dofs()
                    << " DoFs, max |K x - A x| / max |K x| = "
                    << difference / norm << (ok ? "  ok" : "  FAILED")
                    << std::endl;
      }
    return failures;
  }

  /** The operator's diagonal (springs included) against the matrix's, on
   * unconstrained DoFs that no hanging-node constraint refers to. */
  unsigned int
  check_diagonal(const TestProblem &problem, Operator &op, const Moduli moduli)
  {
    op.compute_diagonal();
    const auto &inverse = op.get_matrix_diagonal_inverse()->get_vector();
    IndexSet    masters(problem.dof_handler.n_dofs());
    for (const auto &line : problem.constraints.get_lines())
      for (const auto &entry : line.entries)
        masters.add_index(entry.first);
    double difference = 0, norm = 0;
    for (const types::global_dof_index i : problem.owned)
      if (!problem.constraints.is_constrained(i) && !masters.is_element(i))
        {
          difference = std::max(difference,
                                std::abs(1. / inverse(i) -
                                         problem.matrix.diag_element(i)));
          norm       = std::max(norm, std::abs(problem.matrix.diag_element(i)));
        }
    difference    = Utilities::MPI::max(difference, problem.comm);
    norm          = Utilities::MPI::max(norm, problem.comm);
    const bool ok = difference <= 1e-12 * norm;
    if (problem.rank == 0)
      std::cout << name(moduli) << ", diagonal: max difference / max entry = "
                << difference / norm << (ok ? "  ok" : "  FAILED") << std::endl;
    return ok ? 0 : 1;
  }

  /** Every check on one mesh, with moduli per cell and at points. */
  unsigned int
  check_mesh(const MPI_Comm comm, const bool rectangle)
  {
    parallel::distributed::Triangulation<dim> tria(
      comm,
      Triangulation<dim>::limit_level_difference_at_vertices,
      parallel::distributed::Triangulation<dim>::construct_multigrid_hierarchy);
    make_mesh(tria, rectangle);
    TestProblem problem(tria);
    if (problem.rank == 0)
      std::cout << (rectangle ? "rectangle (axis-parallel cells):"
                              : "quarter annulus (curved cells):")
                << std::endl;
    unsigned int failures = 0;
    for (const Moduli moduli :
         {Moduli::per_cell, Moduli::at_points, Moduli::anisotropic})
      {
        assemble_matrix(problem, moduli);
        const auto matrix_free = make_matrix_free(problem);
        failures +=
          check_cell_batches(*matrix_free,
                             rectangle,
                             problem.rank == 0 && moduli == Moduli::per_cell);
        Operator op;
        op.initialize(matrix_free);
        if (moduli == Moduli::anisotropic)
          {
            FEValues<dim> points(problem.mapping,
                                 problem.fe,
                                 QGauss<dim>(degree + 1),
                                 update_quadrature_points);
            op.set_point_tangents(
              [&](const typename Operator::CellIterator &cell,
                  const unsigned int                     q) {
                points.reinit(cell);
                return point_tangent(cell->material_id(),
                                     points.quadrature_point(q));
              });
          }
        else if (moduli == Moduli::at_points)
          {
            FEValues<dim> points(problem.mapping,
                                 problem.fe,
                                 QGauss<dim>(degree + 1),
                                 update_quadrature_points);
            op.set_point_moduli([&](const typename Operator::CellIterator &cell,
                                    const unsigned int                     q) {
              points.reinit(cell);
              return point_moduli(cell->material_id(),
                                  points.quadrature_point(q));
            });
          }
        else
          op.set_cell_moduli([](const typename Operator::CellIterator &cell) {
            return material_moduli(cell->material_id());
          });
        op.set_vertical_springs(springs);
        failures += check_products(problem, op, matrix_free, moduli);
        failures += check_diagonal(problem, op, moduli);
      }
    return failures;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm     = MPI_COMM_WORLD;
  unsigned int                     failures = 0;
  for (const bool rectangle : {false, true})
    failures += check_mesh(comm, rectangle);
  failures = Utilities::MPI::max(failures, comm);
  if (Utilities::MPI::this_mpi_process(comm) == 0)
    std::cout << (failures == 0 ? "PASSED" : "FAILED") << std::endl;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

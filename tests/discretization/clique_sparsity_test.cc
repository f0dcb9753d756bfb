// CliqueSparsity (the exact-length Trilinos graph of the stiffness matrix)
// against deal.II's own DoFTools::make_sparsity_pattern with the same
// constraints: every locally owned row has the same columns, on whatever
// number of ranks the test is started on. Two meshes:
//  - a quarter annulus (curved cells) refined adaptively twice near an
//    interior point and near the outer arc, with hanging nodes, one side
//    fixed, one a roller, and no-normal-flux constraints on the outer arc
//    (constraint lines with entries in both components);
//  - a rectangle refined adaptively, where a block of cells carries
//    FE_Nothing (no DoFs, as one side of a fault will), with a fixed side
//    and a roller base.
// Then the matrix is assembled (mass-like local matrices through the
// constraints) into both: distribute_local_to_global must find every entry
// it writes, and the two matrices must agree to round-off.

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <lithostress/discretization/clique_sparsity.h>

#include <Epetra_CrsGraph.h>

#include <algorithm>
#include <cmath>
#include <iostream>

using namespace dealii;
using namespace lithostress;

namespace
{
  constexpr int dim = 2;

  void
  refine_near(parallel::distributed::Triangulation<dim> &tria,
              const Point<dim>                          &p,
              const double                               radius)
  {
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center().distance(p) < radius)
        cell->set_refine_flag();
    tria.execute_coarsening_and_refinement();
  }

  /** The sorted global columns of @p row in @p matrix. */
  std::vector<int>
  row_columns(const TrilinosWrappers::SparseMatrix &matrix,
              const types::global_dof_index         row)
  {
    const Epetra_CrsGraph &graph = matrix.trilinos_matrix().Graph();
    std::vector<int>       columns(graph.NumGlobalIndices(row));
    int                    n = 0;
    graph.ExtractGlobalRowCopy(row, columns.size(), n, columns.data());
    columns.resize(n);
    std::sort(columns.begin(), columns.end());
    return columns;
  }

  /** Compare patterns and assembled matrices; return the number of
   * failures (this rank's). */
  unsigned int
  check(const std::string               &name,
        const DoFHandler<dim>           &dof_handler,
        const AffineConstraints<double> &constraints,
        const MPI_Comm                   communicator)
  {
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);

    TrilinosWrappers::SparsityPattern pattern(owned,
                                              owned,
                                              relevant,
                                              communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    pattern,
                                    constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(
                                      communicator));
    pattern.compress();
    TrilinosWrappers::SparseMatrix reference;
    reference.reinit(pattern);

    TrilinosWrappers::SparseMatrix matrix;
    CliqueSparsity                 sparsity(owned, constraints);
    sparsity.add_cells(dof_handler);
    const std::size_t n_cliques = sparsity.n_cliques();
    sparsity.reinit_matrix(matrix, communicator);

    unsigned int failures = 0, rows_differing = 0;
    for (const types::global_dof_index row : owned)
      if (row_columns(matrix, row) != row_columns(reference, row))
        ++rows_differing;
    rows_differing = Utilities::MPI::sum(rows_differing, communicator);
    const auto nnz = matrix.n_nonzero_elements();
    if (rows_differing > 0 || nnz != reference.n_nonzero_elements())
      ++failures;
    const unsigned int n_constraints =
      Utilities::MPI::sum(constraints.n_constraints(), communicator);
    const std::size_t all_cliques =
      Utilities::MPI::sum(n_cliques, communicator);
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      std::cout << name << ": " << dof_handler.n_dofs() << " DoFs, "
                << n_constraints << " constraint lines (with ghosts), "
                << all_cliques << " cliques, " << nnz
                << " entries (deal.II: " << reference.n_nonzero_elements()
                << "); rows differing from deal.II's pattern: "
                << rows_differing << (failures == 0 ? "  ok" : "  FAILED")
                << std::endl;

    // Assemble the same local matrices into both; entries depend on the
    // cell and the DoF pair so that a misplaced entry shows. A missing
    // entry makes Trilinos refuse the addition.
    bool assembled = true;
    try
      {
        std::vector<types::global_dof_index> dofs;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && cell->get_fe().n_dofs_per_cell() > 0)
            {
              const unsigned int n = cell->get_fe().n_dofs_per_cell();
              dofs.resize(n);
              cell->get_dof_indices(dofs);
              FullMatrix<double> local(n, n);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  local(i, j) = (i == j ? 10.0 : 0.0) +
                                std::sin(1.0 + i + 2.0 * j + cell->center()[0]);
              constraints.distribute_local_to_global(local, dofs, matrix);
              constraints.distribute_local_to_global(local, dofs, reference);
            }
        matrix.compress(VectorOperation::add);
        reference.compress(VectorOperation::add);
      }
    catch (const std::exception &)
      {
        assembled = false;
      }
    assembled = Utilities::MPI::min(assembled ? 1u : 0u, communicator) == 1;
    double difference = 0, size = 0;
    if (assembled)
      for (const types::global_dof_index row : owned)
        for (auto entry = reference.begin(row); entry != reference.end(row);
             ++entry)
          {
            difference = std::max(difference,
                                  std::abs(matrix.el(row, entry->column()) -
                                           entry->value()));
            size       = std::max(size, std::abs(entry->value()));
          }
    difference = Utilities::MPI::max(difference, communicator);
    size       = Utilities::MPI::max(size, communicator);
    // Both sum the same terms: round-off only.
    const bool agree = assembled && difference <= 1e-14 * size && size > 0;
    if (!agree)
      ++failures;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      std::cout << "  assembly through the constraints: "
                << (assembled ? "every entry found"
                              : "an entry is missing from the pattern")
                << "; largest difference from deal.II's matrix " << difference
                << " (entries up to " << size << ")"
                << (agree ? "  ok" : "  FAILED") << std::endl;
    return failures;
  }

  unsigned int
  annulus(const MPI_Comm communicator)
  {
    parallel::distributed::Triangulation<dim> tria(communicator);
    GridGenerator::quarter_hyper_shell(tria, Point<dim>(), 1.0, 2.0, 3, true);
    tria.refine_global(2);
    refine_near(tria, Point<dim>(1.2, 0.5), 0.4);
    refine_near(tria, Point<dim>(0.3, 1.95), 0.4);

    const FESystem<dim> fe(FE_Q<dim>(2), dim);
    DoFHandler<dim>     dof_handler(tria);
    dof_handler.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    const MappingQ<dim> mapping(2);
    VectorTools::interpolate_boundary_values(
      mapping, dof_handler, 2, Functions::ZeroFunction<dim>(dim), constraints);
    VectorTools::interpolate_boundary_values(mapping,
                                             dof_handler,
                                             3,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints,
                                             ComponentMask(
                                               std::vector<bool>{true, false}));
    VectorTools::compute_no_normal_flux_constraints(
      dof_handler, 0, {1}, constraints, mapping);
    constraints.close();
    return check("curved, adaptive, no-normal-flux",
                 dof_handler,
                 constraints,
                 communicator);
  }

  unsigned int
  rectangle_with_fe_nothing(const MPI_Comm communicator)
  {
    parallel::distributed::Triangulation<dim> tria(communicator);
    GridGenerator::subdivided_hyper_rectangle(
      tria, {6u, 3u}, Point<dim>(0, 0), Point<dim>(2, 1), true);
    tria.refine_global(1);
    refine_near(tria, Point<dim>(0.7, 0.4), 0.3);
    refine_near(tria, Point<dim>(0.7, 0.4), 0.15);

    hp::FECollection<dim> fe;
    fe.push_back(FESystem<dim>(FE_Q<dim>(2), dim));
    fe.push_back(FESystem<dim>(FE_Nothing<dim>(), dim));
    DoFHandler<dim> dof_handler(tria);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && cell->center()[0] > 1.5 &&
          cell->center()[1] > 0.5)
        cell->set_active_fe_index(1);
    dof_handler.distribute_dofs(fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    VectorTools::interpolate_boundary_values(dof_handler,
                                             0,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints);
    VectorTools::interpolate_boundary_values(dof_handler,
                                             2,
                                             Functions::ZeroFunction<dim>(dim),
                                             constraints,
                                             ComponentMask(
                                               std::vector<bool>{false, true}));
    constraints.close();
    return check("rectangle with FE_Nothing cells",
                 dof_handler,
                 constraints,
                 communicator);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   communicator = MPI_COMM_WORLD;
  unsigned int                     failures     = annulus(communicator);
  failures += rectangle_with_fe_nothing(communicator);
  failures = Utilities::MPI::max(failures, communicator);
  if (Utilities::MPI::this_mpi_process(communicator) == 0)
    std::cout << (failures == 0 ? "PASSED" : "FAILED") << std::endl;
  return failures == 0 ? 0 : 1;
}

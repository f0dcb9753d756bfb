#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/multigrid/mg_tools.h>

#include <lithostress/assembly/elastic_assembler.h>
#include <lithostress/base/input_error.h>
#include <lithostress/loads/load.h>
#include <lithostress/solvers/amg_solver.h>
#include <lithostress/solvers/coarse_grid_solver.h>
#include <lithostress/solvers/rigid_body_modes.h>

namespace lithostress
{
  template <int dim, typename number>
  void
  CoarseGridSolver<dim, number>::initialize(
    const DoFHandler<dim>                      &dof_handler,
    const FiniteElementSpace<dim>              &fe_space,
    const MGConstrainedDoFs                    &constrained_dofs,
    const CellModuli                           &moduli,
    const std::map<types::boundary_id, double> &springs,
    const bool                                  use_amg)
  {
    const MPI_Comm communicator = dof_handler.get_communicator();
    owned                       = dof_handler.locally_owned_mg_dofs(0);
    const IndexSet relevant =
      DoFTools::extract_locally_relevant_level_dofs(dof_handler, 0);

    AffineConstraints<double> constraints;
    constraints.reinit(relevant);
    constraints.add_lines(constrained_dofs.get_boundary_indices(0));
    constraints.close();

    DynamicSparsityPattern pattern(relevant);
    MGTools::make_sparsity_pattern(dof_handler, pattern, 0, constraints, false);
    SparsityTools::distribute_sparsity_pattern(pattern,
                                               owned,
                                               communicator,
                                               relevant);
    matrix.reinit(owned, owned, pattern, communicator);

    assemble(
      dof_handler.mg_cell_iterators_on_level(0),
      [](const auto &cell, std::vector<types::global_dof_index> &dofs) {
        if (!cell->is_locally_owned_on_level())
          return false;
        cell->get_mg_dof_indices(dofs);
        return true;
      },
      dof_handler.get_fe(),
      fe_space.mapping(),
      constraints,
      moduli,
      springs,
      constrained_dofs.get_boundary_indices(0));
    set_up_solver(
      use_amg
        ? make_level_rigid_body_modes(
            dof_handler, fe_space, 0, matrix.trilinos_matrix().DomainMap())
        : nullptr,
      fe_space.degree() > 1,
      use_amg);
  }

  template <int dim, typename number>
  void
  CoarseGridSolver<dim, number>::initialize(
    const DoFHandler<dim>                      &dof_handler,
    const FiniteElementSpace<dim>              &fe_space,
    const AffineConstraints<double>            &constraints,
    const CellModuli                           &moduli,
    const std::map<types::boundary_id, double> &springs,
    const bool                                  use_amg)
  {
    const MPI_Comm communicator = dof_handler.get_communicator();
    owned                       = dof_handler.locally_owned_dofs();
    const IndexSet relevant =
      DoFTools::extract_locally_relevant_dofs(dof_handler);

    IndexSet constrained(dof_handler.n_dofs());
    for (const auto &line : constraints.get_lines())
      {
        AssertThrow(line.entries.empty(),
                    ExcMessage("The coarse mesh of the multigrid has hanging "
                               "nodes."));
        constrained.add_index(line.index);
      }
    constrained.compress();

    DynamicSparsityPattern pattern(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, pattern, constraints, false);
    SparsityTools::distribute_sparsity_pattern(pattern,
                                               owned,
                                               communicator,
                                               relevant);
    matrix.reinit(owned, owned, pattern, communicator);

    assemble(
      dof_handler.active_cell_iterators(),
      [](const auto &cell, std::vector<types::global_dof_index> &dofs) {
        if (!cell->is_locally_owned())
          return false;
        cell->get_dof_indices(dofs);
        return true;
      },
      dof_handler.get_fe(),
      fe_space.mapping(),
      constraints,
      moduli,
      springs,
      constrained);
    set_up_solver(
      use_amg ? make_rigid_body_modes(dof_handler,
                                      fe_space,
                                      matrix.trilinos_matrix().DomainMap())
              : nullptr,
      fe_space.degree() > 1,
      use_amg);
  }

  template <int dim, typename number>
  template <typename CellRange, typename DoFIndices>
  void
  CoarseGridSolver<dim, number>::assemble(
    const CellRange                            &cells,
    const DoFIndices                           &dof_indices,
    const FiniteElement<dim>                   &fe,
    const Mapping<dim>                         &mapping,
    const AffineConstraints<double>            &constraints,
    const CellModuli                           &moduli,
    const std::map<types::boundary_id, double> &springs,
    const IndexSet                             &identity_rows)
  {
    const unsigned int                   n_points = fe.degree + 1;
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            QGauss<dim>(n_points),
                            update_gradients | update_JxW_values);
    FEFaceValues<dim>                    face_values(mapping,
                                  fe,
                                  QGauss<dim - 1>(n_points),
                                  update_values | update_normal_vectors |
                                    update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    const FEValuesExtractors::Vector     u(0);

    for (const auto &cell : cells)
      if (dof_indices(cell, dofs))
        {
          cell_matrix = 0;
          fe_values.reinit(cell);
          ElasticAssembler<dim>::add_cell_stiffness(fe_values,
                                                    moduli(cell),
                                                    cell_matrix);
          for (const unsigned int f : cell->face_indices())
            if (cell->at_boundary(f))
              {
                const auto spring = springs.find(cell->face(f)->boundary_id());
                if (spring == springs.end())
                  continue;
                face_values.reinit(cell, f);
                Load<dim>::add_vertical_spring_terms(face_values,
                                                     spring->second,
                                                     u,
                                                     cell_matrix);
              }
          constraints.distribute_local_to_global(cell_matrix, dofs, matrix);
        }
    matrix.compress(VectorOperation::add);

    // Identity on the boundary rows, as the level operator has.
    for (const types::global_dof_index i : identity_rows)
      if (owned.is_element(i))
        matrix.set(i, i, 1.);
    matrix.compress(VectorOperation::insert);
  }

  template <int dim, typename number>
  void
  CoarseGridSolver<dim, number>::set_up_solver(
    std::unique_ptr<Epetra_MultiVector> rigid_body_modes,
    const bool                          higher_order,
    const bool                          use_amg)
  {
    const MPI_Comm communicator = matrix.get_mpi_communicator();
    x.reinit(owned, communicator);
    b.reinit(owned, communicator);
    direct.reset();
    amg.reset();
    modes = std::move(rigid_body_modes);
    if (!use_amg)
      {
        direct = std::make_unique<TrilinosWrappers::SolverDirect>(control);
        direct->initialize(matrix);
        return;
      }
    // ML for elasticity with the AMG solver's default settings and all
    // rigid-body modes of the coarse mesh; the boundary rows' modes are
    // harmless (identity rows aggregate on their own).
    amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    initialize_elasticity_amg<dim>(
      *amg, matrix, *modes, typename AMGSolver<dim>::Settings(), higher_order);
  }

  template <int dim, typename number>
  void
  CoarseGridSolver<dim, number>::operator()(const unsigned int,
                                            VectorType       &dst,
                                            const VectorType &src) const
  {
    unsigned int k = 0;
    for (const types::global_dof_index i : owned)
      b[i] = src.local_element(k++);
    if (direct)
      direct->solve(x, b);
    else
      {
        // To 1e-8: far below the error the smoothers leave in a V-cycle,
        // so the multigrid stays a fixed linear preconditioner for the
        // outer CG to round-off of that size.
        x                    = 0;
        const double  b_norm = b.l2_norm();
        SolverControl iteration(1000, 1e-8 * b_norm, false, false);
        SolverCG<TrilinosWrappers::MPI::Vector> cg(iteration);
        if (b_norm > 0)
          try
            {
              cg.solve(matrix, x, b, *amg);
            }
          catch (const SolverControl::NoConvergence &exc)
            {
              throw ComputationError(
                "the multigrid's AMG coarse solve did not converge: "
                "residual " +
                std::to_string(exc.last_residual / b_norm) +
                " (relative) after " + std::to_string(exc.last_step) +
                " iterations; use Solver/Multigrid coarse solver = direct");
            }
      }
    k = 0;
    for (const types::global_dof_index i : owned)
      dst.local_element(k++) = x[i];
  }

  template class CoarseGridSolver<2, float>;
  template class CoarseGridSolver<2, double>;
} // namespace lithostress

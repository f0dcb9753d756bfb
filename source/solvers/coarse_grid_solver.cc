#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/multigrid/mg_tools.h>

#include <lithostress/discretization/elastic_assembler.h>
#include <lithostress/loads/load.h>
#include <lithostress/solvers/coarse_grid_solver.h>

namespace lithostress
{
  template <int dim, typename number>
  void
  CoarseGridSolver<dim, number>::initialize(
    const DoFHandler<dim>                      &dof_handler,
    const Mapping<dim>                         &mapping,
    const MGConstrainedDoFs                    &constrained_dofs,
    const CellModuli                           &moduli,
    const std::map<types::boundary_id, double> &springs)
  {
    const MPI_Comm            communicator = dof_handler.get_communicator();
    const FiniteElement<dim> &fe           = dof_handler.get_fe();
    owned = dof_handler.locally_owned_mg_dofs(0);
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

    for (const auto &cell : dof_handler.mg_cell_iterators_on_level(0))
      if (cell->is_locally_owned_on_level())
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
          cell->get_mg_dof_indices(dofs);
          constraints.distribute_local_to_global(cell_matrix, dofs, matrix);
        }
    matrix.compress(VectorOperation::add);

    // Identity on the boundary rows, as the level operator has.
    for (const types::global_dof_index i :
         constrained_dofs.get_boundary_indices(0))
      if (owned.is_element(i))
        matrix.set(i, i, 1.);
    matrix.compress(VectorOperation::insert);

    x.reinit(owned, communicator);
    b.reinit(owned, communicator);
    direct = std::make_unique<TrilinosWrappers::SolverDirect>(control);
    direct->initialize(matrix);
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
    direct->solve(x, b);
    k = 0;
    for (const types::global_dof_index i : owned)
      dst.local_element(k++) = x[i];
  }

  template class CoarseGridSolver<2, float>;
  template class CoarseGridSolver<2, double>;
} // namespace lithostress

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <lithostress/solvers/two_field_multigrid.h>

#include <cmath>
#include <functional>

namespace lithostress
{
  namespace
  {
    /**
     * Calls @p visit(coarse, fine, child) for each active cell @p fine of
     * @p fine_dofs with the active cell @p coarse of @p coarse_dofs that
     * contains it, @p coarse being @p fine (child = invalid) or its parent
     * (fine is its child @p child). The two meshes have the same coarse
     * cells in the same order, @p fine_dofs' refined at most once more.
     */
    template <int dim, typename Visitor>
    void
    for_each_cell_pair(const DoFHandler<dim> &coarse_dofs,
                       const DoFHandler<dim> &fine_dofs,
                       const Visitor         &visit)
    {
      using Cell = typename DoFHandler<dim>::cell_iterator;
      const std::function<void(const Cell &, const Cell &)> descend =
        [&](const Cell &coarse, const Cell &fine) {
          if (coarse->has_children())
            {
              for (unsigned int k = 0; k < coarse->n_children(); ++k)
                descend(coarse->child(k), fine->child(k));
              return;
            }
          if (!fine->has_children())
            visit(coarse, fine, numbers::invalid_unsigned_int);
          else
            for (unsigned int k = 0; k < fine->n_children(); ++k)
              {
                AssertThrow(fine->child(k)->is_active(), ExcInternalError());
                visit(coarse, fine->child(k), k);
              }
        };
      Cell fine = fine_dofs.begin(0);
      for (Cell coarse = coarse_dofs.begin(0); coarse != coarse_dofs.end(0);
           ++coarse, ++fine)
        descend(coarse, fine);
    }

    /**
     * Level @p level of the mesh hierarchy of @p fine: its coarse cells
     * (no manifolds: the transfer is topological) refined wherever @p fine
     * is, up to level @p level, so that a cell is active on it if it has
     * that level or is an active cell of @p fine of a lower one. Built
     * here rather than by deal.II's coarsening sequence, whose copy of the
     * triangulation fails on a refined TransfiniteInterpolationManifold.
     */
    template <int dim>
    std::unique_ptr<Triangulation<dim>>
    truncated_mesh(const Triangulation<dim> &fine, const unsigned int level)
    {
      std::vector<Point<dim>>    vertices = fine.get_vertices();
      std::vector<CellData<dim>> cells;
      for (const auto &cell : fine.cell_iterators_on_level(0))
        {
          CellData<dim> data(cell->n_vertices());
          for (const unsigned int v : cell->vertex_indices())
            data.vertices[v] = cell->vertex_index(v);
          data.material_id = cell->material_id();
          cells.push_back(data);
        }
      SubCellData no_boundary;
      GridTools::delete_unused_vertices(vertices, cells, no_boundary);
      auto mesh = std::make_unique<Triangulation<dim>>();
      mesh->create_triangulation(vertices, cells, no_boundary);
      using Cell = typename Triangulation<dim>::cell_iterator;
      for (unsigned int k = 0; k < level; ++k)
        {
          const std::function<void(const Cell &, const Cell &)> flag =
            [&](const Cell &mine, const Cell &theirs) {
              if (mine->has_children())
                for (unsigned int c = 0; c < mine->n_children(); ++c)
                  flag(mine->child(c), theirs->child(c));
              else if (theirs->has_children() && mine->level() == int(k))
                mine->set_refine_flag();
            };
          Cell theirs = fine.begin(0);
          for (Cell mine = mesh->begin(0); mine != mesh->end(0);
               ++mine, ++theirs)
            flag(mine, theirs);
          mesh->execute_coarsening_and_refinement();
        }
      return mesh;
    }
  } // namespace

  template <int dim>
  bool
  TwoFieldMultigrid<dim>::applies_to(const DoFHandler<dim> &dof_handler)
  {
    return Utilities::MPI::n_mpi_processes(dof_handler.get_communicator()) == 1;
  }

  template <int dim>
  void
  TwoFieldMultigrid<dim>::make_hierarchy(const DoFHandler<dim> &dof_handler,
                                         const hp::FECollection<dim> &fe)
  {
    AssertThrow(applies_to(dof_handler), ExcNotImplemented());
    const Triangulation<dim> &tria = dof_handler.get_triangulation();
    const unsigned int        n    = tria.n_global_levels();
    triangulations.clear();
    coarser_dofs.clear();
    coarser_dofs.resize(n - 1);
    level_dofs.assign(n, nullptr);
    level_dofs[n - 1] = &dof_handler;
    for (unsigned int level = n - 1; level-- > 0;)
      {
        triangulations.push_back(truncated_mesh(tria, level));
        auto dofs = std::make_unique<DoFHandler<dim>>(*triangulations.back());
        for_each_cell_pair(*dofs,
                           *level_dofs[level + 1],
                           [](const auto &coarse, const auto &fine, auto) {
                             coarse->set_active_fe_index(
                               fine->active_fe_index());
                           });
        dofs->distribute_dofs(fe);
        level_dofs[level]   = dofs.get();
        coarser_dofs[level] = std::move(dofs);
      }
    hanging_nodes.clear();
    hanging_nodes.resize(n);
    for (unsigned int level = 0; level + 1 < n; ++level)
      {
        DoFTools::make_hanging_node_constraints(*level_dofs[level],
                                                hanging_nodes[level]);
        hanging_nodes[level].close();
      }
    prolongations.clear();
    prolongations.resize(n);
    for (unsigned int level = 1; level + 1 < n; ++level)
      make_prolongation(level,
                        interpolation_rows(level),
                        &hanging_nodes[level]);
    finest_rows = n > 1 ? interpolation_rows(n - 1) : Transfers();
  }

  template <int dim>
  typename TwoFieldMultigrid<dim>::Transfers
  TwoFieldMultigrid<dim>::interpolation_rows(const unsigned int level) const
  {
    const DoFHandler<dim>           &fine           = *level_dofs[level];
    const DoFHandler<dim>           &coarse         = *level_dofs[level - 1];
    const AffineConstraints<double> &coarse_hanging = hanging_nodes[level - 1];
    Transfers                        rows(fine.n_dofs());
    std::vector<bool>                done(fine.n_dofs(), false);
    std::vector<types::global_dof_index> fine_indices, coarse_indices;
    FullMatrix<double>                   identity;
    for_each_cell_pair(
      coarse,
      fine,
      [&](const auto &coarse_cell, const auto &cell, const unsigned int child) {
        AssertThrow(coarse_cell->active_fe_index() == cell->active_fe_index(),
                    ExcInternalError());
        const FiniteElement<dim> &element = cell->get_fe();
        fine_indices.resize(element.n_dofs_per_cell());
        coarse_indices.resize(element.n_dofs_per_cell());
        cell->get_dof_indices(fine_indices);
        coarse_cell->get_dof_indices(coarse_indices);
        const bool same = child == numbers::invalid_unsigned_int;
        if (same)
          {
            identity.reinit(element.n_dofs_per_cell(),
                            element.n_dofs_per_cell());
            for (unsigned int i = 0; i < identity.m(); ++i)
              identity(i, i) = 1;
          }
        const FullMatrix<double> &weights =
          same ? identity
               : element.get_prolongation_matrix(
                   child, RefinementCase<dim>::isotropic_refinement);
        for (unsigned int i = 0; i < fine_indices.size(); ++i)
          {
            if (done[fine_indices[i]])
              continue;
            done[fine_indices[i]] = true;
            auto &row             = rows[fine_indices[i]];
            for (unsigned int j = 0; j < coarse_indices.size(); ++j)
              {
                const double w = weights(i, j);
                if (std::abs(w) < 1e-12)
                  continue;
                const auto *line =
                  coarse_hanging.get_constraint_entries(coarse_indices[j]);
                if (line == nullptr)
                  row.emplace_back(coarse_indices[j], w);
                else
                  for (const auto &[k, c] : *line)
                    row.emplace_back(k, w * c);
              }
          }
      });
    return rows;
  }

  template <int dim>
  void
  TwoFieldMultigrid<dim>::make_prolongation(
    const unsigned int               level,
    const Transfers                 &rows,
    const AffineConstraints<double> *fine_constraints)
  {
    const types::global_dof_index n_fine   = level_dofs[level]->n_dofs();
    const types::global_dof_index n_coarse = level_dofs[level - 1]->n_dofs();
    DynamicSparsityPattern        pattern(n_fine, n_coarse);
    const auto                    kept = [&](const types::global_dof_index i) {
      return fine_constraints == nullptr ||
             !fine_constraints->is_constrained(i);
    };
    for (types::global_dof_index i = 0; i < n_fine; ++i)
      if (kept(i))
        for (const auto &[j, w] : rows[i])
          pattern.add(i, j);
    auto matrix = std::make_unique<Matrix>();
    matrix->reinit(complete_index_set(n_fine),
                   complete_index_set(n_coarse),
                   pattern,
                   level_dofs[level]->get_communicator());
    for (types::global_dof_index i = 0; i < n_fine; ++i)
      if (kept(i))
        for (const auto &[j, w] : rows[i])
          matrix->add(i, j, w);
    matrix->compress(VectorOperation::add);
    prolongations[level] = std::move(matrix);
  }

  template <int dim>
  void
  TwoFieldMultigrid<dim>::initialize(
    const TrilinosWrappers::SparseMatrix &matrix,
    const AffineConstraints<double>      &constraints,
    const Settings                       &settings)
  {
    const unsigned int n      = n_levels();
    const unsigned int finest = n - 1;
    // The smoothers hold (subscribe to) the level matrices: released
    // before the matrices are made again.
    smoothers.clear();
    finest_matrix = &matrix;
    if (n > 1)
      make_prolongation(finest, finest_rows, &constraints);
    level_matrices.clear();
    level_matrices.resize(n);
    for (unsigned int level = finest; level > 0; --level)
      {
        const Matrix &fine = level == finest ? matrix : *level_matrices[level];
        Matrix        fine_times_p;
        fine.mmult(fine_times_p, *prolongations[level]);
        level_matrices[level - 1] = std::make_unique<Matrix>();
        prolongations[level]->Tmmult(*level_matrices[level - 1], fine_times_p);
      }
    const auto level_matrix = [&](const unsigned int level) -> const Matrix & {
      return level == finest ? matrix : *level_matrices[level];
    };

    smoothers.resize(n);
    residuals.resize(n);
    corrections.resize(n);
    coarse_rhs.resize(n);
    for (unsigned int level = 0; level < n; ++level)
      {
        const Matrix &a = level_matrix(level);
        residuals[level].reinit(a.locally_owned_range_indices(),
                                a.get_mpi_communicator());
        corrections[level].reinit(residuals[level]);
        coarse_rhs[level].reinit(residuals[level]);
        if (level == 0)
          continue;
        // A DoF no coarse function reaches (a hanging node of a coarser
        // level) has a zero row: the smoother leaves it at zero.
        Vector inverse_diagonal(residuals[level]);
        for (const auto i : inverse_diagonal.locally_owned_elements())
          {
            const double d      = a.diag_element(i);
            inverse_diagonal[i] = d != 0 ? 1. / d : 0.;
          }
        inverse_diagonal.compress(VectorOperation::insert);
        typename Smoother::AdditionalData data;
        data.degree                  = settings.smoother_degree;
        data.smoothing_range         = settings.smoothing_range;
        data.eig_cg_n_iterations     = 12;
        data.preconditioner          = std::make_shared<InverseDiagonal>();
        data.preconditioner->inverse = inverse_diagonal;
        smoothers[level]             = std::make_unique<Smoother>();
        smoothers[level]->initialize(a, data);
      }

    const Matrix                 &coarsest = level_matrix(0);
    const types::global_dof_index n0       = coarsest.m();
    DynamicSparsityPattern        pattern(n0, n0);
    for (types::global_dof_index i = 0; i < n0; ++i)
      {
        pattern.add(i, i);
        for (auto entry = coarsest.begin(i); entry != coarsest.end(i); ++entry)
          pattern.add(i, entry->column());
      }
    coarse_pattern.copy_from(pattern);
    coarse_matrix.reinit(coarse_pattern);
    for (types::global_dof_index i = 0; i < n0; ++i)
      {
        for (auto entry = coarsest.begin(i); entry != coarsest.end(i); ++entry)
          coarse_matrix.set(i, entry->column(), entry->value());
        if (coarse_matrix.diag_element(i) == 0)
          coarse_matrix.set(i, i, 1.);
      }
    coarse_solver.initialize(coarse_matrix);
  }

  template <int dim>
  void
  TwoFieldMultigrid<dim>::v_cycle(const unsigned int level,
                                  Vector            &x,
                                  const Vector      &b) const
  {
    if (level == 0)
      {
        dealii::Vector<double> values(b.size());
        for (types::global_dof_index i = 0; i < b.size(); ++i)
          values[i] = b[i];
        coarse_solver.solve(values);
        for (types::global_dof_index i = 0; i < b.size(); ++i)
          x[i] = values[i];
        x.compress(VectorOperation::insert);
        return;
      }
    const Matrix &a =
      level + 1 == n_levels() ? *finest_matrix : *level_matrices[level];
    smoothers[level]->vmult(x, b);
    a.vmult(residuals[level], x);
    residuals[level].sadd(-1., 1., b);
    prolongations[level]->Tvmult(coarse_rhs[level - 1], residuals[level]);
    v_cycle(level - 1, corrections[level - 1], coarse_rhs[level - 1]);
    prolongations[level]->vmult_add(x, corrections[level - 1]);
    smoothers[level]->step(x, b);
  }

  template <int dim>
  void
  TwoFieldMultigrid<dim>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                                const TrilinosWrappers::MPI::Vector &src) const
  {
    v_cycle(n_levels() - 1, dst, src);
  }

  template <int dim>
  std::size_t
  TwoFieldMultigrid<dim>::memory_consumption() const
  {
    std::size_t bytes =
      coarse_matrix.memory_consumption() + coarse_pattern.memory_consumption();
    for (const auto &m : prolongations)
      if (m)
        bytes += m->memory_consumption();
    for (const auto &m : level_matrices)
      if (m)
        bytes += m->memory_consumption();
    for (const auto &row : finest_rows)
      bytes += row.capacity() * sizeof(row[0]) + sizeof(row);
    return bytes;
  }

  template class TwoFieldMultigrid<2>;
} // namespace lithostress

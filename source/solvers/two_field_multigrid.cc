#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <lithostress/base/gather_on_all.h>
#include <lithostress/base/input_error.h>
#include <lithostress/solvers/galerkin_product.h>
#include <lithostress/solvers/two_field_multigrid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <string>

namespace lithostress
{
  namespace
  {
    /** Whether @p a equals its transpose to round-off (1e-12 of the
     * largest entry of the row): a Galerkin product of a symmetric
     * operator is symmetric up to the order of its sums. */
    bool
    is_symmetric(const SparseMatrix<double> &a)
    {
      for (unsigned int row = 0; row < a.m(); ++row)
        {
          double largest = 0;
          for (auto e = a.begin(row); e != a.end(row); ++e)
            largest = std::max(largest, std::abs(e->value()));
          for (auto e = a.begin(row); e != a.end(row); ++e)
            if (std::abs(e->value() - a.el(e->column(), row)) > 1e-12 * largest)
              return false;
        }
      return true;
    }

    /**
     * Calls @p visit(coarse, fine, child) for each locally owned active
     * cell @p fine of @p fine_dofs with the active cell @p coarse of
     * @p coarse_dofs that contains it, @p coarse being @p fine (child =
     * invalid) or its parent (fine is its child @p child). The two meshes
     * have the same coarse cells in the same order, @p fine_dofs' refined
     * at most once more; @p coarse_dofs is a whole mesh, @p fine_dofs may
     * be distributed (its artificial cells are skipped).
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
              if (fine->has_children())
                for (unsigned int k = 0; k < coarse->n_children(); ++k)
                  descend(coarse->child(k), fine->child(k));
              return;
            }
          if (!fine->has_children())
            {
              if (fine->is_locally_owned())
                visit(coarse, fine, numbers::invalid_unsigned_int);
              return;
            }
          for (unsigned int k = 0; k < fine->n_children(); ++k)
            if (fine->child(k)->is_active() &&
                fine->child(k)->is_locally_owned())
              visit(coarse, fine->child(k), k);
        };
      Cell fine = fine_dofs.begin(0);
      for (Cell coarse = coarse_dofs.begin(0); coarse != coarse_dofs.end(0);
           ++coarse, ++fine)
        descend(coarse, fine);
    }

    /** A cell's place in the hierarchy: its coarse cell's index and the
     * child indices down to it. */
    template <int dim>
    unsigned int
    coarse_index(const Triangulation<dim> &tria, const CellId &id)
    {
      return tria
        .create_cell_iterator(
          CellId(id.get_coarse_cell_id(), std::vector<std::uint8_t>()))
        ->index();
    }

    template <int dim>
    std::string
    path_of(const Triangulation<dim> &tria, const CellId &id)
    {
      std::string path = std::to_string(coarse_index(tria, id)) + ":";
      for (const std::uint8_t child : id.get_child_indices())
        path += char('0' + child);
      return path;
    }

    /** The paths of every refined cell of the (possibly distributed)
     * mesh @p fine, gathered from all ranks: the ancestors of the locally
     * owned active cells. */
    template <int dim>
    std::set<std::string>
    refined_cells(const Triangulation<dim> &fine)
    {
      std::set<std::string> mine;
      for (const auto &cell : fine.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const std::string path = path_of(fine, cell->id());
            for (std::size_t end = path.find(':') + 1; end < path.size(); ++end)
              mine.insert(path.substr(0, end));
          }
      std::set<std::string> all;
      for (const auto &part :
           Utilities::MPI::all_gather(fine.get_communicator(),
                                      std::vector<std::string>(mine.begin(),
                                                               mine.end())))
        all.insert(part.begin(), part.end());
      return all;
    }

    /**
     * The mesh of @p fine's coarse cells (no manifolds: the transfer is
     * topological) refined where @p refined says, whole on every rank
     * (deal.II adds the refinement the one-irregular rule needs). Built
     * here rather than by copying and coarsening triangulations, whose copy
     * fails on a refined TransfiniteInterpolationManifold (the subduction
     * zone's) and, of a copy without manifolds, costs a serial finest mesh
     * on every rank.
     */
    template <int dim>
    std::unique_ptr<Triangulation<dim>>
    refined_mesh(const Triangulation<dim>    &fine,
                 const std::set<std::string> &refined)
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
      for (unsigned int k = 0; k + 1 < fine.n_global_levels(); ++k)
        {
          bool flagged = false;
          for (const auto &cell : mesh->active_cell_iterators_on_level(k))
            if (refined.count(path_of(*mesh, cell->id())) != 0)
              {
                cell->set_refine_flag();
                flagged = true;
              }
          if (!flagged)
            break;
          mesh->execute_coarsening_and_refinement();
        }
      return mesh;
    }

    /**
     * The meshes of the coarser levels of @p fine's hierarchy, coarsest
     * first, whole on every rank: each is the next finer one coarsened
     * globally once, i.e. the refined cells @p refined of the finest mesh
     * less, at each step, those whose children are all active (where that
     * would break the one-irregular rule, refined_mesh() refines them
     * again), until the coarse mesh is reached. On a uniformly refined
     * mesh each step is a whole level, as a truncation at that level would
     * be; on a mesh refined towards a fault, as the chapter-7 models'
     * goal-oriented cycles make them, a truncation at level l leaves every
     * cell of level l and coarser in place: below the finest level of
     * 262 k DoFs its levels had 262, 260, 257, 245, 203, 140, 65 and 17 k,
     * so that a V-cycle cost several times the uniform one's.
     */
    template <int dim>
    std::vector<std::unique_ptr<Triangulation<dim>>>
    coarsened_meshes(const Triangulation<dim>    &fine,
                     const std::set<std::string> &refined)
    {
      std::vector<std::unique_ptr<Triangulation<dim>>> meshes;
      std::set<std::string>                            still = refined;
      while (!still.empty())
        {
          std::set<std::string> coarser;
          for (const std::string &path : still)
            for (unsigned int c = 0;
                 c < GeometryInfo<dim>::max_children_per_cell;
                 ++c)
              if (still.count(path + char('0' + c)) != 0)
                {
                  coarser.insert(path);
                  break;
                }
          still.swap(coarser);
          meshes.push_back(refined_mesh(fine, still));
        }
      std::reverse(meshes.begin(), meshes.end());
      return meshes;
    }

    /** One entry of a sparse matrix. */
    struct MatrixEntry
    {
      types::global_dof_index row, column;
      double                  value;
    };

    /** The displacement field (active FE index) of each coarse cell of
     * @p dof_handler's mesh, from every rank. */
    template <int dim>
    std::vector<unsigned int>
    coarse_cell_fields(const DoFHandler<dim> &dof_handler)
    {
      const Triangulation<dim> &tria = dof_handler.get_triangulation();
      std::vector<unsigned int> fields(tria.n_cells(0), 0);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          fields[coarse_index(tria, cell->id())] = cell->active_fe_index();
      Utilities::MPI::max(fields, dof_handler.get_communicator(), fields);
      return fields;
    }
  } // namespace

  template <int dim>
  typename TwoFieldMultigrid<dim>::Nodes
  TwoFieldMultigrid<dim>::group_nodes(const unsigned int level) const
  {
    const DoFHandler<dim> &dofs    = *level_dofs[level];
    const IndexSet        &mine    = owned[level];
    const bool             coarser = level + 1 < n_levels();
    // Support points from the cells' vertices (d-linear), on a grid far
    // finer than the mesh: the two sides' cells give a fault node's
    // point up to rounding, which the grid absorbs (a node it split
    // would be two blocks, a weaker but still symmetric smoother).
    const double grid =
      1e-6 * GridTools::minimal_cell_diameter(dofs.get_triangulation());
    using Key = std::array<long long, dim>;
    std::vector<std::pair<Key, unsigned int>> points;
    points.reserve(mine.n_elements());
    std::vector<bool>                    done(mine.n_elements(), false);
    std::vector<types::global_dof_index> indices;
    for (const auto &cell : dofs.active_cell_iterators())
      {
        if ((!coarser && !cell->is_locally_owned()) ||
            cell->get_fe().n_dofs_per_cell() == 0)
          continue;
        const FiniteElement<dim> &element = cell->get_fe();
        indices.resize(element.n_dofs_per_cell());
        cell->get_dof_indices(indices);
        for (unsigned int i = 0; i < indices.size(); ++i)
          {
            if (!mine.is_element(indices[i]))
              continue;
            const auto position = mine.index_within_set(indices[i]);
            if (done[position])
              continue;
            done[position]         = true;
            const Point<dim> &unit = element.get_unit_support_points()[i];
            Point<dim>        x;
            for (const unsigned int v : cell->vertex_indices())
              x += GeometryInfo<dim>::d_linear_shape_function(unit, v) *
                   cell->vertex(v);
            Key key;
            for (unsigned int d = 0; d < dim; ++d)
              key[d] = std::llround(x[d] / grid);
            points.emplace_back(key, position);
          }
      }
    AssertThrow(points.size() == mine.n_elements(), ExcInternalError());
    std::sort(points.begin(), points.end());
    // The nodes in the order of their first DoF, so that the smoother
    // reads and writes the vectors nearly in sequence.
    std::vector<std::pair<unsigned int, std::size_t>> starts;
    for (std::size_t k = 0; k < points.size(); ++k)
      if (k == 0 || points[k].first != points[k - 1].first)
        starts.emplace_back(points[k].second, k);
      else
        starts.back().first = std::min(starts.back().first, points[k].second);
    std::sort(starts.begin(), starts.end());
    Nodes grouped;
    for (const auto &[smallest, k] : starts)
      {
        grouped.offsets.push_back(grouped.dofs.size());
        for (std::size_t j = k;
             j < points.size() && points[j].first == points[k].first;
             ++j)
          grouped.dofs.push_back(points[j].second);
      }
    grouped.offsets.push_back(grouped.dofs.size());
    return grouped;
  }

  template <int dim>
  typename TwoFieldMultigrid<dim>::NodalBlockInverse
  TwoFieldMultigrid<dim>::block_inverse(const unsigned int level,
                                        const Matrix      &a) const
  {
    const auto             &first   = nodes[level].offsets;
    const auto             &members = nodes[level].dofs;
    const Epetra_CrsMatrix &epetra  = a.trilinos_matrix();
    NodalBlockInverse       blocks;
    blocks.nodes = &nodes[level];
    FullMatrix<double>        block, inverse;
    std::vector<int>          columns_of;
    std::vector<unsigned int> active;
    for (unsigned int k = 0; k + 1 < first.size(); ++k)
      {
        const unsigned int n = first[k + 1] - first[k];
        // The members' local column indices (each row has its own: the
        // diagonal).
        columns_of.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          columns_of[i] = epetra.LCID(epetra.GRID64(members[first[k] + i]));
        block.reinit(n, n);
        for (unsigned int i = 0; i < n; ++i)
          {
            int     length  = 0;
            double *values  = nullptr;
            int    *columns = nullptr;
            epetra.ExtractMyRowView(members[first[k] + i],
                                    length,
                                    values,
                                    columns);
            for (int e = 0; e < length; ++e)
              for (unsigned int j = 0; j < n; ++j)
                if (columns[e] == columns_of[j])
                  block(i, j) += values[e];
          }
        // A DoF no coarse function reaches (a hanging node of a coarser
        // level) has a zero row: the smoother leaves it at zero.
        active.clear();
        for (unsigned int i = 0; i < n; ++i)
          if (block(i, i) != 0)
            active.push_back(i);
        inverse.reinit(active.size(), active.size());
        for (unsigned int i = 0; i < active.size(); ++i)
          for (unsigned int j = 0; j < active.size(); ++j)
            inverse(i, j) = block(active[i], active[j]);
        if (!active.empty())
          inverse.gauss_jordan();
        block = 0;
        for (unsigned int i = 0; i < active.size(); ++i)
          for (unsigned int j = 0; j < active.size(); ++j)
            block(active[i], active[j]) = inverse(i, j);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            blocks.inverses.push_back(block(i, j));
      }
    return blocks;
  }

  template <int dim>
  void
  TwoFieldMultigrid<dim>::NodalBlockInverse::vmult(Vector       &dst,
                                                   const Vector &src) const
  {
    Assert(&dst != &src, ExcInternalError());
    const double *s       = src.begin();
    double       *d       = dst.begin();
    const auto   &offsets = nodes->offsets;
    const double *m       = inverses.data();
    for (std::size_t k = 0; k + 1 < offsets.size(); ++k)
      {
        const unsigned int  n = offsets[k + 1] - offsets[k];
        const unsigned int *i = &nodes->dofs[offsets[k]];
        if (n == 2)
          {
            // A node off the fault in 2-D.
            const double s0 = s[i[0]], s1 = s[i[1]];
            d[i[0]] = m[0] * s0 + m[1] * s1;
            d[i[1]] = m[2] * s0 + m[3] * s1;
          }
        else
          for (unsigned int r = 0; r < n; ++r)
            {
              double sum = 0;
              for (unsigned int c = 0; c < n; ++c)
                sum += m[r * n + c] * s[i[c]];
              d[i[r]] = sum;
            }
        m += n * n;
      }
  }

  template <int dim>
  void
  TwoFieldMultigrid<dim>::make_hierarchy(const DoFHandler<dim> &dof_handler,
                                         const hp::FECollection<dim> &fe)
  {
    const Triangulation<dim>       &tria   = dof_handler.get_triangulation();
    const MPI_Comm                  comm   = dof_handler.get_communicator();
    const std::vector<unsigned int> fields = coarse_cell_fields(dof_handler);
    // (The levels' DoF handlers hold their meshes: released first.)
    coarser_dofs.clear();
    triangulations             = coarsened_meshes(tria, refined_cells(tria));
    const unsigned int n       = triangulations.size() + 1;
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    coarser_dofs.resize(n - 1);
    level_dofs.assign(n, nullptr);
    level_dofs[n - 1] = &dof_handler;
    owned.assign(n, IndexSet());
    owned[n - 1] = dof_handler.locally_owned_dofs();
    hanging_nodes.clear();
    hanging_nodes.resize(n);
    for (unsigned int level = 0; level + 1 < n; ++level)
      {
        const Triangulation<dim> &mesh = *triangulations[level];
        auto dofs = std::make_unique<DoFHandler<dim>>(mesh);
        for (const auto &cell : dofs->active_cell_iterators())
          cell->set_active_fe_index(fields[coarse_index(mesh, cell->id())]);
        dofs->distribute_dofs(fe);
        // The coarser levels are whole on every rank; each rank owns a
        // contiguous range of their DoFs in the level operators.
        const types::global_dof_index size = dofs->n_dofs();
        owned[level].set_size(size);
        owned[level].add_range(size * rank / n_ranks,
                               size * (rank + 1) / n_ranks);
        DoFTools::make_hanging_node_constraints(*dofs, hanging_nodes[level]);
        hanging_nodes[level].close();
        level_dofs[level]   = dofs.get();
        coarser_dofs[level] = std::move(dofs);
      }
    // The smoothers and zones point into the nodes: made again by
    // initialize().
    smoothers.clear();
    zones.clear();
    nodes.assign(n, Nodes());
    zone_seeds.assign(n, {});
    for (unsigned int level = 1; level < n; ++level)
      {
        nodes[level]      = group_nodes(level);
        zone_seeds[level] = fault_dofs(level);
      }
    prolongations.clear();
    prolongations.resize(n);
    for (unsigned int level = 1; level + 1 < n; ++level)
      make_prolongation(level, interpolation_rows(level), hanging_nodes[level]);
    finest_rows = n > 1 ? interpolation_rows(n - 1) : Transfers();
  }

  template <int dim>
  typename TwoFieldMultigrid<dim>::Transfers
  TwoFieldMultigrid<dim>::interpolation_rows(const unsigned int level) const
  {
    const DoFHandler<dim>           &fine           = *level_dofs[level];
    const DoFHandler<dim>           &coarse         = *level_dofs[level - 1];
    const AffineConstraints<double> &coarse_hanging = hanging_nodes[level - 1];
    const IndexSet                  &mine           = owned[level];
    std::vector<std::vector<std::pair<types::global_dof_index, double>>> rows(
      mine.n_elements());
    std::vector<bool>                    done(mine.n_elements(), false);
    std::vector<types::global_dof_index> fine_indices, coarse_indices;
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
        // The same cell on both levels: the identity; a child: the
        // element's prolongation matrix.
        const bool                same = child == numbers::invalid_unsigned_int;
        const FullMatrix<double> *prolongation =
          same ? nullptr
               : &element.get_prolongation_matrix(
                   child, RefinementCase<dim>::isotropic_refinement);
        for (unsigned int i = 0; i < fine_indices.size(); ++i)
          {
            if (!mine.is_element(fine_indices[i]))
              continue;
            const auto position = mine.index_within_set(fine_indices[i]);
            if (done[position])
              continue;
            done[position] = true;
            auto &row      = rows[position];
            for (unsigned int j = 0; j < coarse_indices.size(); ++j)
              {
                const double w = same ? double(i == j) : (*prolongation)(i, j);
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
    Transfers   compact;
    std::size_t n_entries = 0;
    for (const auto &row : rows)
      n_entries += row.size();
    compact.offsets.reserve(rows.size() + 1);
    compact.coarse.reserve(n_entries);
    compact.weights.reserve(n_entries);
    for (auto &row : rows)
      {
        for (const auto &[j, w] : row)
          {
            compact.coarse.push_back(j);
            compact.weights.push_back(w);
          }
        compact.offsets.push_back(compact.coarse.size());
        row = {};
      }
    return compact;
  }

  template <int dim>
  void
  TwoFieldMultigrid<dim>::make_prolongation(
    const unsigned int               level,
    const Transfers                 &rows,
    const AffineConstraints<double> &fine_constraints)
  {
    const IndexSet                   &fine = owned[level];
    TrilinosWrappers::SparsityPattern pattern(
      fine, owned[level - 1], level_dofs.back()->get_communicator());
    const auto kept = [&](const types::global_dof_index i) {
      return !fine_constraints.is_constrained(i);
    };
    const auto entries = [&](const types::global_dof_index i) {
      const auto r = fine.index_within_set(i);
      return std::make_pair(rows.offsets[r], rows.offsets[r + 1]);
    };
    for (const auto i : fine)
      if (kept(i))
        for (auto [e, end] = entries(i); e < end; ++e)
          pattern.add(i, rows.coarse[e]);
    pattern.compress();
    auto matrix = std::make_unique<Matrix>();
    matrix->reinit(pattern);
    for (const auto i : fine)
      if (kept(i))
        for (auto [e, end] = entries(i); e < end; ++e)
          matrix->add(i, rows.coarse[e], rows.weights[e]);
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
      {
        // The finest prolongation leaves out the constrained DoFs: made
        // again only when they change (exact contact's open set).
        std::vector<types::global_dof_index> constrained;
        for (const auto i : owned[finest])
          if (constraints.is_constrained(i))
            constrained.push_back(i);
        // (Decided by all ranks together: making it is collective.)
        if (Utilities::MPI::logical_or(!prolongations[finest] ||
                                         constrained != finest_constrained,
                                       matrix.get_mpi_communicator()))
          {
            make_prolongation(finest, finest_rows, constraints);
            finest_constrained = std::move(constrained);
          }
      }
    level_matrices.clear();
    level_matrices.resize(n);
    for (unsigned int level = finest; level > 0; --level)
      {
        const Matrix &fine = level == finest ? matrix : *level_matrices[level];
        level_matrices[level - 1] = std::make_unique<Matrix>();
        galerkin_product(fine,
                         *prolongations[level],
                         owned[level - 1],
                         *level_matrices[level - 1],
                         level == finest);
      }
    const auto level_matrix = [&](const unsigned int level) -> const Matrix & {
      return level == finest ? matrix : *level_matrices[level];
    };

    smoothers.resize(n);
    zones.resize(n);
    residuals.resize(n);
    corrections.resize(n);
    coarse_rhs.resize(n);
    for (unsigned int level = 0; level < n; ++level)
      {
        const Matrix &a = level_matrix(level);
        residuals[level].reinit(a.locally_owned_range_indices(),
                                a.get_mpi_communicator());
        if (level < finest)
          {
            corrections[level].reinit(residuals[level]);
            coarse_rhs[level].reinit(residuals[level]);
          }
        if (level == 0)
          continue;
        typename Smoother::AdditionalData data;
        data.degree              = settings.smoother_degree;
        data.smoothing_range     = settings.smoothing_range;
        data.eig_cg_n_iterations = 12;
        data.preconditioner =
          std::make_shared<NodalBlockInverse>(block_inverse(level, a));
        smoothers[level] = std::make_unique<Smoother>();
        smoothers[level]->initialize(a, data);
        zones[level] = fault_zone(level, a, settings);
      }

    // The coarsest operator, gathered on every rank and factorised there.
    // (Read through Epetra's row views: deal.II's row iterators copy each
    // row into a cache, which cost more than the factorisation.)
    const Epetra_CrsMatrix  &coarsest = level_matrix(0).trilinos_matrix();
    std::vector<MatrixEntry> entries;
    for (int row = 0; row < coarsest.NumMyRows(); ++row)
      {
        int     length  = 0;
        double *values  = nullptr;
        int    *columns = nullptr;
        coarsest.ExtractMyRowView(row, length, values, columns);
        const types::global_dof_index i = coarsest.GRID64(row);
        for (int e = 0; e < length; ++e)
          entries.push_back(
            {i,
             static_cast<types::global_dof_index>(coarsest.GCID64(columns[e])),
             values[e]});
      }
    const std::vector<MatrixEntry> all_entries =
      gather_on_all(level_matrix(0).get_mpi_communicator(), entries);
    const types::global_dof_index n0 = level_matrix(0).m();
    DynamicSparsityPattern        pattern(n0, n0);
    for (types::global_dof_index i = 0; i < n0; ++i)
      pattern.add(i, i);
    for (const auto &[i, j, value] : all_entries)
      pattern.add(i, j);
    coarse_pattern.copy_from(pattern);
    coarse_matrix.reinit(coarse_pattern);
    for (const auto &[i, j, value] : all_entries)
      coarse_matrix.set(i, j, value);
    for (types::global_dof_index i = 0; i < n0; ++i)
      if (coarse_matrix.diag_element(i) == 0)
        coarse_matrix.set(i, i, 1.);
    coarse_by_cholesky = is_symmetric(coarse_matrix);
    if (coarse_by_cholesky)
      try
        {
          coarse_cholesky.factorize(coarse_matrix);
        }
      catch (const ComputationError &)
        {
          coarse_by_cholesky = false;
        }
    if (!coarse_by_cholesky)
      coarse_lu.initialize(coarse_matrix);
  }

  template <int dim>
  std::vector<unsigned int>
  TwoFieldMultigrid<dim>::fault_dofs(const unsigned int level) const
  {
    const DoFHandler<dim> &dofs    = *level_dofs[level];
    const IndexSet        &mine    = owned[level];
    const bool             coarser = level + 1 < n_levels();
    // Whether a neighbour across face f carries the other field (on a
    // refined neighbour: any of its children on that face).
    const auto other_field = [](const auto &cell, const unsigned int f) {
      if (cell->at_boundary(f))
        return false;
      const auto neighbour = cell->neighbor(f);
      if (!neighbour->has_children())
        return neighbour->active_fe_index() != cell->active_fe_index();
      for (unsigned int c = 0; c < cell->face(f)->n_children(); ++c)
        if (cell->neighbor_child_on_subface(f, c)->active_fe_index() !=
            cell->active_fe_index())
          return true;
      return false;
    };
    std::vector<char>                    seed(mine.n_elements(), 0);
    std::vector<types::global_dof_index> indices;
    for (const auto &cell : dofs.active_cell_iterators())
      {
        if ((!coarser && !cell->is_locally_owned()) ||
            cell->get_fe().n_dofs_per_cell() == 0)
          continue;
        for (const unsigned int f : cell->face_indices())
          if (other_field(cell, f))
            {
              indices.resize(cell->get_fe().n_dofs_per_face(f));
              cell->face(f)->get_dof_indices(indices, cell->active_fe_index());
              for (const auto i : indices)
                if (mine.is_element(i))
                  seed[mine.index_within_set(i)] = 1;
            }
      }
    // And the DoFs of every node that carries both fields.
    const Nodes &level_nodes = nodes[level];
    for (std::size_t k = 0; k + 1 < level_nodes.offsets.size(); ++k)
      if (level_nodes.offsets[k + 1] - level_nodes.offsets[k] > dim)
        for (auto j = level_nodes.offsets[k]; j < level_nodes.offsets[k + 1];
             ++j)
          seed[level_nodes.dofs[j]] = 1;
    std::vector<unsigned int> rows;
    for (unsigned int r = 0; r < seed.size(); ++r)
      if (seed[r])
        rows.push_back(r);
    return rows;
  }

  template <int dim>
  std::unique_ptr<FaultZoneCorrection>
  TwoFieldMultigrid<dim>::fault_zone(const unsigned int level,
                                     const Matrix      &a,
                                     const Settings    &settings) const
  {
    if (settings.fault_zone_layers == 0)
      return nullptr;
    const std::vector<unsigned int> &seeds = zone_seeds[level];
    // (Made by all ranks or none: it is collective.)
    if (!Utilities::MPI::logical_or(!seeds.empty(), a.get_mpi_communicator()))
      return nullptr;
    auto zone = std::make_unique<FaultZoneCorrection>();
    if (!zone->initialize(a,
                          seeds,
                          settings.fault_zone_layers,
                          settings.fault_zone_largest_fraction))
      return nullptr;
    return zone;
  }

  template <int dim>
  void
  TwoFieldMultigrid<dim>::v_cycle(const unsigned int level,
                                  Vector            &x,
                                  const Vector      &b) const
  {
    if (level == 0)
      {
        // Each rank's entries into the whole vector (a sum over the ranks:
        // no serialisation in the V-cycle).
        dealii::Vector<double> &values = coarse_values;
        values.reinit(b.size());
        for (const auto i : b.locally_owned_elements())
          values[i] = b[i];
        if (Utilities::MPI::n_mpi_processes(b.get_mpi_communicator()) > 1)
          Utilities::MPI::sum(values, b.get_mpi_communicator(), values);
        if (coarse_by_cholesky)
          coarse_cholesky.solve(values);
        else
          coarse_lu.solve(values);
        for (const auto i : x.locally_owned_elements())
          x[i] = values[i];
        x.compress(VectorOperation::insert);
        return;
      }
    const Matrix &a =
      level + 1 == n_levels() ? *finest_matrix : *level_matrices[level];
    smoothers[level]->vmult(x, b);
    if (zones[level])
      zones[level]->correct(x, b);
    a.vmult(residuals[level], x);
    residuals[level].sadd(-1., 1., b);
    prolongations[level]->Tvmult(coarse_rhs[level - 1], residuals[level]);
    v_cycle(level - 1, corrections[level - 1], coarse_rhs[level - 1]);
    prolongations[level]->vmult_add(x, corrections[level - 1]);
    if (zones[level])
      zones[level]->correct(x, b);
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
      coarse_matrix.memory_consumption() + coarse_pattern.memory_consumption() +
      (coarse_by_cholesky ? coarse_cholesky.memory_consumption() : 0);
    for (const auto &m : prolongations)
      if (m)
        bytes += m->memory_consumption();
    for (const auto &m : level_matrices)
      if (m)
        bytes += m->memory_consumption();
    for (const auto &zone : zones)
      if (zone)
        bytes += zone->memory_consumption();
    bytes += finest_rows.offsets.capacity() * sizeof(std::size_t) +
             finest_rows.coarse.capacity() * sizeof(types::global_dof_index) +
             finest_rows.weights.capacity() * sizeof(double);
    return bytes;
  }

  template class TwoFieldMultigrid<2>;
} // namespace lithostress

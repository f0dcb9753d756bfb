#include <lithostress/base/input_error.h>
#include <lithostress/faults/fault_interface.h>

#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <tuple>

// FaultInterface's topology (thesis chapter 5's fault with a node on each
// side, here two displacement fields): the faults' faces on the coarse
// mesh, the blocks between them and their two fields, the active FE
// indices, the face pairs across the faults and what the sparsity and the
// rigid-body support need of them.

namespace lithostress
{
  template <int dim>
  void
  FaultInterface<dim>::identify(const Triangulation<dim> &triangulation)
  {
    const unsigned int n_coarse = triangulation.n_cells(0);
    coarse_field.assign(n_coarse, 0);
    coarse_face_fault.assign(n_coarse, {});
    for (auto &faces : coarse_face_fault)
      faces.fill(-1);
    coarse_face_welded.assign(n_coarse, {});
    for (auto &faces : coarse_face_welded)
      faces.fill(false);
    if (faults.empty())
      return;
    double size = 0;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      size = std::max(size, cell->diameter());
    const double tolerance = 1e-8 * size;

    // The faces on each fault: both vertices and the midpoint (on the
    // face's manifold) on the trace.
    std::vector<unsigned int>                      faces_on(faults.size(), 0);
    std::map<unsigned int, std::set<unsigned int>> faults_at_vertex;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        {
          if (cell->at_boundary(f))
            continue;
          const auto face = cell->face(f);
          for (unsigned int k = 0; k < faults.size(); ++k)
            {
              const FaultTrace &trace = faults[k].trace;
              if (trace.distance_to(face->vertex(0)) > tolerance ||
                  trace.distance_to(face->vertex(1)) > tolerance ||
                  trace.distance_to(face->center(true)) > tolerance)
                continue;
              int &entry = coarse_face_fault[cell->index()][f];
              if (entry >= 0 && entry != static_cast<int>(k))
                throw_input_error("Faults/Names",
                                  "the faults <" + faults[entry].trace.name +
                                    "> and <" + trace.name +
                                    "> run along the same cell faces");
              entry = k;
              coarse_face_welded[cell->index()][f] =
                !trace.on_fault_part(face->center(true), tolerance);
              if (!coarse_face_welded[cell->index()][f])
                ++faces_on[k];
              for (const unsigned int v : face->vertex_indices())
                faults_at_vertex[face->vertex_index(v)].insert(k);
            }
        }
    for (unsigned int k = 0; k < faults.size(); ++k)
      if (faces_on[k] == 0)
        throw_input_error("Faults/Names",
                          "no cell faces of the mesh lie on the fault <" +
                            faults[k].trace.name +
                            "> (between its ends, if it has buried tips)");

    // Faults may share a vertex only on the boundary.
    std::set<unsigned int> boundary_vertices;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        if (cell->at_boundary(f))
          for (const unsigned int v : cell->face(f)->vertex_indices())
            boundary_vertices.insert(cell->face(f)->vertex_index(v));
    const auto &vertices = triangulation.get_vertices();
    for (const auto &[vertex, on] : faults_at_vertex)
      if (on.size() > 1 && boundary_vertices.count(vertex) == 0)
        {
          std::ostringstream where;
          where << "the faults <" << faults[*on.begin()].trace.name << "> and <"
                << faults[*std::next(on.begin())].trace.name
                << "> meet or cross inside the body, at (" << vertices[vertex]
                << ") m";
          throw_input_error("Faults/Names", where.str());
        }

    cut_into_blocks(triangulation);
  }

  template <int dim>
  void
  FaultInterface<dim>::cut_into_blocks(const Triangulation<dim> &triangulation)
  {
    const unsigned int n_coarse = triangulation.n_cells(0);
    // Blocks: the coarse cells connected across faces that are no fault's.
    std::vector<unsigned int> block(n_coarse);
    std::iota(block.begin(), block.end(), 0u);
    const std::function<unsigned int(unsigned int)> root = [&](unsigned int c) {
      while (block[c] != c)
        c = block[c] = block[block[c]];
      return c;
    };
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        if (!cell->at_boundary(f) && coarse_face_fault[cell->index()][f] < 0)
          block[root(cell->index())] = root(cell->neighbor(f)->index());
    // Each fault must separate two blocks; neighbouring blocks get
    // different fields (breadth first over the blocks).
    std::map<unsigned int, std::vector<std::pair<unsigned int, int>>> across;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      for (const unsigned int f : cell->face_indices())
        {
          const int k =
            cell->at_boundary(f) ? -1 : coarse_face_fault[cell->index()][f];
          if (k < 0)
            continue;
          const unsigned int a = root(cell->index()),
                             b = root(cell->neighbor(f)->index());
          if (a == b)
            throw_input_error(
              "Faults/Names",
              "the fault <" + faults[k].trace.name +
                "> does not split the body: its two sides are connected "
                "around an end inside the body (a fault must run from "
                "boundary to boundary)");
          across[a].emplace_back(b, k);
        }
    std::map<unsigned int, unsigned char> field_of_block;
    for (unsigned int c = 0; c < n_coarse; ++c)
      {
        const unsigned int start = root(c);
        if (field_of_block.count(start) != 0)
          continue;
        field_of_block[start]           = 0;
        std::vector<unsigned int> queue = {start};
        while (!queue.empty())
          {
            const unsigned int b = queue.back();
            queue.pop_back();
            for (const auto &[next, k] : across[b])
              {
                const unsigned char want = 1 - field_of_block[b];
                const auto          it   = field_of_block.find(next);
                if (it == field_of_block.end())
                  {
                    field_of_block[next] = want;
                    queue.push_back(next);
                  }
                else if (it->second != want)
                  throw_input_error(
                    "Faults/Names",
                    "the faults split the body into blocks that two "
                    "displacement fields cannot tell apart (an odd ring of "
                    "blocks around the fault <" +
                      faults[k].trace.name + ">)");
              }
          }
      }
    for (unsigned int c = 0; c < n_coarse; ++c)
      coarse_field[c] = field_of_block[root(c)];

    // The blocks numbered 0, 1, ..., and each fault's two.
    std::map<unsigned int, unsigned int> number;
    for (const auto &[b, field] : field_of_block)
      number.emplace(b, number.size());
    coarse_block.resize(n_coarse);
    for (unsigned int c = 0; c < n_coarse; ++c)
      coarse_block[c] = number.at(root(c));
    fault_blocks.assign(faults.size(), {0U, 0U});
    for (const auto &[a, neighbours] : across)
      for (const auto &[b, k] : neighbours)
        fault_blocks[k] = {number.at(a), number.at(b)};
  }

  template <int dim>
  RigidBodies<dim>
  FaultInterface<dim>::blocks() const
  {
    RigidBodies<dim> bodies;
    if (faults.empty())
      return bodies;
    bodies.n  = 1 + *std::max_element(coarse_block.begin(), coarse_block.end());
    bodies.of = [this](const typename Triangulation<dim>::cell_iterator &cell) {
      return coarse_block[coarse_index(cell)];
    };
    return bodies;
  }

  template <int dim>
  void
  FaultInterface<dim>::set_active_fe_indices(DoFHandler<dim> &dof_handler) const
  {
    if (faults.empty())
      return;
    Assert(coarse_field.size() == dof_handler.get_triangulation().n_cells(0),
           ExcMessage("call identify() on this mesh first"));
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        cell->set_active_fe_index(coarse_field[coarse_index(cell)]);
  }

  template <int dim>
  void
  FaultInterface<dim>::for_each_face_pair(
    const DoFHandler<dim> &dof_handler,
    const FacePairVisitor &pair_of_fault) const
  {
    const unsigned int none = numbers::invalid_unsigned_int;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (!cell->is_locally_owned() || cell->active_fe_index() != 0)
          continue;
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              continue;
            const int k = fault_of(cell, f);
            if (k < 0 || !has_face_terms(k) || welded(cell, f))
              continue;
            const auto pair = [&](const auto &...arguments) {
              pair_of_fault(k, arguments...);
            };
            const auto neighbor = cell->neighbor(f);
            if (neighbor->has_children())
              {
                // Finer hanging wall: integrate over each child's face.
                for (unsigned int sf = 0; sf < cell->face(f)->n_children();
                     ++sf)
                  {
                    const auto child = cell->neighbor_child_on_subface(f, sf);
                    if (child->active_fe_index() == 1)
                      pair(cell,
                           f,
                           sf,
                           child,
                           cell->neighbor_of_neighbor(f),
                           none);
                  }
              }
            else if (neighbor->active_fe_index() == 1)
              {
                if (cell->neighbor_is_coarser(f))
                  {
                    const auto [nf, sf] = cell->neighbor_of_coarser_neighbor(f);
                    pair(cell, f, none, neighbor, nf, sf);
                  }
                else
                  pair(cell,
                       f,
                       none,
                       neighbor,
                       cell->neighbor_of_neighbor(f),
                       none);
              }
          }
      }
  }

  template <int dim>
  std::vector<std::vector<types::global_dof_index>>
  FaultInterface<dim>::interface_cliques(
    const DoFHandler<dim> &dof_handler) const
  {
    std::vector<std::vector<types::global_dof_index>> cliques;
    for_each_face_pair(dof_handler,
                       [&](const unsigned int,
                           const auto &minus,
                           const unsigned int,
                           const unsigned int,
                           const auto &plus,
                           const unsigned int,
                           const unsigned int) {
                         std::vector<types::global_dof_index> a(
                           minus->get_fe().n_dofs_per_cell()),
                           b(plus->get_fe().n_dofs_per_cell());
                         minus->get_dof_indices(a);
                         plus->get_dof_indices(b);
                         a.insert(a.end(), b.begin(), b.end());
                         cliques.push_back(std::move(a));
                       });
    return cliques;
  }

  template <int dim>
  std::vector<BodyCoupling<dim>>
  FaultInterface<dim>::interface_points(
    const DoFHandler<dim>         &dof_handler,
    const FiniteElementSpace<dim> &fe_space) const
  {
    std::vector<BodyCoupling<dim>> points;
    if (!has_face_terms())
      return points;
    for (const InterfacePoint &p : interface_quadrature(dof_handler, fe_space))
      {
        BodyCoupling<dim> c;
        c.position                   = p.position;
        c.JxW                        = p.JxW;
        std::tie(c.body_0, c.body_1) = fault_blocks[p.fault];
        c.stiffness                  = unit_symmetric_tensor<dim>();
        points.push_back(c);
      }
    return points;
  }

  template void
  FaultInterface<2>::identify(const Triangulation<2> &);
  template void
  FaultInterface<2>::cut_into_blocks(const Triangulation<2> &);
  template void
  FaultInterface<2>::set_active_fe_indices(DoFHandler<2> &) const;
  template void
  FaultInterface<2>::for_each_face_pair(const DoFHandler<2> &,
                                        const FacePairVisitor &) const;
  template std::vector<std::vector<types::global_dof_index>>
  FaultInterface<2>::interface_cliques(const DoFHandler<2> &) const;
  template std::vector<BodyCoupling<2>>
  FaultInterface<2>::interface_points(const DoFHandler<2> &,
                                      const FiniteElementSpace<2> &) const;
  template RigidBodies<2>
  FaultInterface<2>::blocks() const;
} // namespace lithostress

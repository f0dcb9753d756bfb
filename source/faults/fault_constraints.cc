#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/full_matrix.h>

#include <lithostress/faults/fault_interface.h>

#include <array>
#include <cmath>

// FaultInterface's constraints: locked faults and prescribed slip, exact
// (thesis chapter 5's locked fault without its k = 1e15 N/m penalty).

namespace lithostress
{
  namespace
  {
    /** face_dof[d][k]: the face-local index of the DoF of displacement
     * component d at scalar face node k, for a cell whose active element
     * is @p fe (one displacement field, FE_Nothing elsewhere). */
    template <int dim>
    std::array<std::vector<unsigned int>, dim>
    face_dof_table(const FiniteElement<dim> &fe, const unsigned int n_nodes)
    {
      std::array<std::vector<unsigned int>, dim> table;
      for (auto &column : table)
        column.assign(n_nodes, numbers::invalid_unsigned_int);
      for (unsigned int i = 0; i < fe.n_dofs_per_face(); ++i)
        {
          const auto [component, node] = fe.face_system_to_component_index(i);
          table[component % dim][node] = i;
        }
      return table;
    }

    /** True if row @p j of @p m is the unit vector e_i (the subface's
     * node j is the coarse face's node i); sets @p i. */
    bool
    unit_row(const FullMatrix<double> &m, const unsigned int j, unsigned int &i)
    {
      unsigned int ones = 0;
      for (unsigned int c = 0; c < m.n(); ++c)
        {
          if (std::abs(m(j, c) - 1) < 1e-12)
            {
              i = c;
              ++ones;
            }
          else if (std::abs(m(j, c)) > 1e-12)
            return false;
        }
      return ones == 1;
    }

    /**
     * The constraints that tie the two fields' nodes on one fault face
     * together with a given jump (thesis chapter 5's locked fault, exact):
     * every constraint points from field 1, or from inside a fine field-0
     * face, towards field-0 nodes, so there are no cycles and every rank
     * makes the same ones. A DoF that is already constrained, or that
     * @p constraints cannot store, is left alone.
     */
    template <int dim>
    class FaceNodeConstraints
    {
    public:
      using cell_iterator = typename DoFHandler<dim>::active_cell_iterator;
      using face_iterator = typename DoFHandler<dim>::face_iterator;
      /** The jump u(field 1) − u(field 0) to impose: its component d at
       * the node x. */
      using Jump =
        std::function<double(const Point<dim> &x, const unsigned int d)>;

      /** For the two fields of @p fe_space, adding to @p constraints. */
      FaceNodeConstraints(const FiniteElementSpace<dim> &fe_space,
                          AffineConstraints<double>     &constraints);

      /** Face @p f of the field-0 cell @p cell, whose field-1 neighbour
       * has its level: field 1 := field 0 + jump at every node. */
      void
      equal_levels(const cell_iterator &cell,
                   const unsigned int   f,
                   const Jump          &jump);

      /** Face @p f of the field-1 cell @p cell, subface @p subface_no of
       * the field-0 side's face @p coarse_face: every field-1 node := the
       * coarse field-0 trace there + jump. */
      void
      fine_field_1(const cell_iterator &cell,
                   const unsigned int   f,
                   const face_iterator &coarse_face,
                   const unsigned int   subface_no,
                   const Jump          &jump);

      /** Face @p f of the field-0 cell @p cell, subface @p subface_no of
       * the field-1 side's face @p coarse_face: the coarse field-1 nodes :=
       * the field-0 nodes at the same points + jump, the other field-0
       * nodes := the coarse field-1 trace's interpolation − jump. */
      void
      fine_field_0(const cell_iterator &cell,
                   const unsigned int   f,
                   const face_iterator &coarse_face,
                   const unsigned int   subface_no,
                   const Jump          &jump);

    private:
      using Entries = std::vector<std::pair<types::global_dof_index, double>>;

      /** @p target := Σ entries + @p inhomogeneity, unless it is
       * constrained already or not stored here. */
      void
      constrain(const types::global_dof_index target,
                const Entries                &entries,
                const double                  inhomogeneity);

      /** The nodes of @p face in the order of the scalar element's face
       * DoFs: the vertices, then (Q2) the midpoint on the face's manifold. */
      std::vector<Point<dim>>
      node_positions(const face_iterator &face) const;

      AffineConstraints<double> &constraints;
      const unsigned int         degree;
      unsigned int               n_nodes;
      /** face_dof_table() of each field's element. */
      std::array<std::array<std::vector<unsigned int>, dim>, 2> table;
      /** (j, i): the coarse face's basis function i at subface s's node j
       * (measured: deal.II 9.4.1's FE_Q fills it by rows of the subface's
       * nodes). */
      std::array<FullMatrix<double>, GeometryInfo<dim>::max_children_per_face>
                                           subface;
      std::vector<types::global_dof_index> dofs_0, dofs_1;
    };

    template <int dim>
    FaceNodeConstraints<dim>::FaceNodeConstraints(
      const FiniteElementSpace<dim> &fe_space,
      AffineConstraints<double>     &constraints)
        : constraints(constraints)
        , degree(fe_space.degree())
    {
      const auto     &collection = fe_space.fe_collection();
      const FE_Q<dim> scalar(degree);
      n_nodes = scalar.n_dofs_per_face();
      table   = {{face_dof_table(collection[0], n_nodes),
                  face_dof_table(collection[1], n_nodes)}};
      for (unsigned int s = 0; s < subface.size(); ++s)
        {
          subface[s].reinit(n_nodes, n_nodes);
          scalar.get_subface_interpolation_matrix(scalar, s, subface[s]);
        }
      dofs_0.resize(collection[0].n_dofs_per_face());
      dofs_1.resize(collection[1].n_dofs_per_face());
    }

    template <int dim>
    void
    FaceNodeConstraints<dim>::constrain(const types::global_dof_index target,
                                        const Entries                &entries,
                                        const double inhomogeneity)
    {
      if (!constraints.can_store_line(target) ||
          constraints.is_constrained(target))
        return;
      constraints.add_line(target);
      constraints.add_entries(target, entries);
      if (inhomogeneity != 0)
        constraints.set_inhomogeneity(target, inhomogeneity);
    }

    template <int dim>
    std::vector<Point<dim>>
    FaceNodeConstraints<dim>::node_positions(const face_iterator &face) const
    {
      std::vector<Point<dim>> x;
      for (const unsigned int v : face->vertex_indices())
        x.push_back(face->vertex(v));
      if (degree == 2)
        x.push_back(face->center(true));
      return x;
    }

    template <int dim>
    void
    FaceNodeConstraints<dim>::equal_levels(const cell_iterator &cell,
                                           const unsigned int   f,
                                           const Jump          &jump)
    {
      cell->face(f)->get_dof_indices(dofs_0, 0);
      cell->face(f)->get_dof_indices(dofs_1, 1);
      const auto x = node_positions(cell->face(f));
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int j = 0; j < n_nodes; ++j)
          constrain(dofs_1[table[1][d][j]],
                    {{dofs_0[table[0][d][j]], 1.0}},
                    jump(x[j], d));
    }

    template <int dim>
    void
    FaceNodeConstraints<dim>::fine_field_1(const cell_iterator &cell,
                                           const unsigned int   f,
                                           const face_iterator &coarse_face,
                                           const unsigned int   subface_no,
                                           const Jump          &jump)
    {
      const FullMatrix<double> &m = subface[subface_no];
      const auto                x = node_positions(cell->face(f));
      coarse_face->get_dof_indices(dofs_0, 0);
      cell->face(f)->get_dof_indices(dofs_1, 1);
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int j = 0; j < n_nodes; ++j)
          {
            Entries entries;
            for (unsigned int i = 0; i < n_nodes; ++i)
              if (std::abs(m(j, i)) > 1e-14)
                entries.emplace_back(dofs_0[table[0][d][i]], m(j, i));
            constrain(dofs_1[table[1][d][j]], entries, jump(x[j], d));
          }
    }

    template <int dim>
    void
    FaceNodeConstraints<dim>::fine_field_0(const cell_iterator &cell,
                                           const unsigned int   f,
                                           const face_iterator &coarse_face,
                                           const unsigned int   subface_no,
                                           const Jump          &jump)
    {
      const FullMatrix<double> &m = subface[subface_no];
      const auto                x = node_positions(cell->face(f));
      coarse_face->get_dof_indices(dofs_1, 1);
      cell->face(f)->get_dof_indices(dofs_0, 0);
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int j = 0; j < n_nodes; ++j)
          {
            unsigned int i = 0;
            if (unit_row(m, j, i))
              constrain(dofs_1[table[1][d][i]],
                        {{dofs_0[table[0][d][j]], 1.0}},
                        jump(x[j], d));
            else
              {
                Entries entries;
                for (unsigned int c = 0; c < n_nodes; ++c)
                  if (std::abs(m(j, c)) > 1e-14)
                    entries.emplace_back(dofs_1[table[1][d][c]], m(j, c));
                constrain(dofs_0[table[0][d][j]], entries, -jump(x[j], d));
              }
          }
    }
  } // namespace

  template <int dim>
  void
  FaultInterface<dim>::add_constraints(const DoFHandler<dim> &dof_handler,
                                       const FiniteElementSpace<dim> &fe_space,
                                       AffineConstraints<double> &constraints,
                                       const double               time) const
  {
    bool with_constraints = false;
    for (const Fault &fault : faults)
      with_constraints = with_constraints || fault.law == Law::locked ||
                         fault.law == Law::prescribed_slip;
    if (!with_constraints)
      return;
    // The prescribed jump u(hanging wall) - u(footwall) of fault @p fault,
    // component d, at a node x of one of its faces whose normal into the
    // hanging wall is n (zero for a locked fault).
    const auto jump = [&](const Fault          &fault,
                          const Point<dim>     &x,
                          const Tensor<1, dim> &normal,
                          const unsigned int    d) {
      if (fault.law != Law::prescribed_slip)
        return 0.0;
      const Point<1> s(fault.trace.distance_along(x));
      fault.slip->set_time(time);
      fault.opening->set_time(time);
      return fault.slip->value(s) * fault.trace.down_dip(x)[d] +
             fault.opening->value(s) * normal[d];
    };
    // +1 if the field-1 side of face f of @p cell is the fault's hanging
    // wall, -1 if it is the footwall.
    const auto field_1_sign = [&](const auto        &cell,
                                  const unsigned int f,
                                  const FaultTrace  &trace) {
      const auto         face = cell->face(f);
      const Tensor<1, 2> t    = face->vertex(1) - face->vertex(0);
      Tensor<1, dim>     out;
      out[0] = t[1];
      out[1] = -t[0];
      if (out * (face->center() - cell->center()) < 0)
        out = -out;
      if (cell->active_fe_index() == 1)
        out = -out;
      return trace.hanging_wall_normal(face->center(true)) * out > 0 ? 1. : -1.;
    };
    FaceNodeConstraints<dim> face_constraints(fe_space, constraints);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        if (cell->is_artificial())
          continue;
        const unsigned int side = cell->active_fe_index();
        for (const unsigned int f : cell->face_indices())
          {
            if (cell->at_boundary(f))
              continue;
            const auto neighbor = cell->neighbor(f);
            if (neighbor->has_children() || neighbor->is_artificial() ||
                neighbor->active_fe_index() == side)
              continue;
            const int k = fault_of(cell, f);
            if (k < 0 || (faults[k].law != Law::locked &&
                          faults[k].law != Law::prescribed_slip))
              continue;
            const Fault &fault = faults[k];
            // The jump of the fields, u(field 1) - u(field 0).
            const double sign = field_1_sign(cell, f, fault.trace);
            const auto   n =
              fault.trace.hanging_wall_normal(cell->face(f)->center(true));
            const auto field_jump = [&](const Point<dim>  &x,
                                        const unsigned int d) {
              return sign * jump(fault, x, n, d);
            };
            if (!cell->neighbor_is_coarser(f))
              {
                // Equal levels, seen from the field-0 side.
                if (side == 0)
                  face_constraints.equal_levels(cell, f, field_jump);
                continue;
              }
            // This cell is the finer side of a hanging fault face.
            const auto [coarse_face_no, subface_no] =
              cell->neighbor_of_coarser_neighbor(f);
            const auto coarse_face = neighbor->face(coarse_face_no);
            if (side == 1)
              face_constraints.fine_field_1(
                cell, f, coarse_face, subface_no, field_jump);
            else
              face_constraints.fine_field_0(
                cell, f, coarse_face, subface_no, field_jump);
          }
      }
  }

  template void
  FaultInterface<2>::add_constraints(const DoFHandler<2> &,
                                     const FiniteElementSpace<2> &,
                                     AffineConstraints<double> &,
                                     const double) const;
} // namespace lithostress

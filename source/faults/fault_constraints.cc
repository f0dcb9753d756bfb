#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/identity_matrix.h>

#include <lithostress/faults/fault_interface.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

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

      /** A node where the normal jump only is tied (exact contact) is
       * skipped if this says it is open; its argument is the node's key,
       * the x DoF of the constrained side's node there. */
      using IsOpen = typename FaultInterface<dim>::ContactState;

      /** For the two fields of @p fe_space, adding to @p constraints. */
      FaceNodeConstraints(const FiniteElementSpace<dim> &fe_space,
                          AffineConstraints<double>     &constraints);

      /** From now on tie only the jump's component along the fault's
       * normal (given by @p trace at each node) to zero, at the nodes that
       * @p is_open does not call open (exact normal contact). */
      void
      normal_only(const FaultTrace *trace, const IsOpen &is_open)
      {
        contact_trace = trace;
        open          = is_open;
      }

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

      /** The node at @p x whose DoFs are @p targets: each component d :=
       * @p sources[d] + @p jumps[d]; with normal_only() the normal
       * component of the jump only, n·(targets − sources) = 0, as one
       * constraint on the component along which n is largest. */
      void
      tie(const Point<dim>                               &x,
          const std::array<types::global_dof_index, dim> &targets,
          const std::array<Entries, dim>                 &sources,
          const std::array<double, dim>                  &jumps);

      /** Every field-1 node j of the face (dofs_1, at @p x) := Σ_i m(j, i)
       * field-0 node i (dofs_0) + jump: the field-0 trace interpolated at
       * the field-1 nodes by @p m (the identity on faces of equal level). */
      void
      tie_field_1_nodes(const std::vector<Point<dim>> &x,
                        const FullMatrix<double>      &m,
                        const Jump                    &jump);

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
      /** The identity: the two sides' nodes coincide. */
      FullMatrix<double>                   same_nodes;
      std::vector<types::global_dof_index> dofs_0, dofs_1;
      const FaultTrace                    *contact_trace = nullptr;
      IsOpen                               open;
      /** The nodes tied by normal_only() so far (their keys). */
      std::set<types::global_dof_index> tied;
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
      same_nodes = IdentityMatrix(n_nodes);
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
    void
    FaceNodeConstraints<dim>::tie(
      const Point<dim>                               &x,
      const std::array<types::global_dof_index, dim> &targets,
      const std::array<Entries, dim>                 &sources,
      const std::array<double, dim>                  &jumps)
    {
      if (!contact_trace)
        {
          for (unsigned int d = 0; d < dim; ++d)
            constrain(targets[d], sources[d], jumps[d]);
          return;
        }
      // A node is tied once, by the first face that has it (a second face
      // would choose another component and close a cycle).
      if ((open && open(targets[0])) || !tied.insert(targets[0]).second)
        return;
      // n·(u_target − u_source) = 0 solved for the component c along which
      // n is largest (of those still free): u_c = source_c +
      // Σ_{d≠c} (n_d / n_c) (source_d − u_d).
      const Tensor<1, dim> n = contact_trace->hanging_wall_normal(x);
      unsigned int         c = numbers::invalid_unsigned_int;
      for (unsigned int d = 0; d < dim; ++d)
        if (constraints.can_store_line(targets[d]) &&
            !constraints.is_constrained(targets[d]) && std::abs(n[d]) > 0.2 &&
            (c == numbers::invalid_unsigned_int ||
             std::abs(n[d]) > std::abs(n[c])))
          c = d;
      if (c == numbers::invalid_unsigned_int)
        return;
      Entries entries = sources[c];
      for (unsigned int d = 0; d < dim; ++d)
        if (d != c)
          {
            const double ratio = n[d] / n[c];
            for (const auto &[dof, weight] : sources[d])
              entries.emplace_back(dof, ratio * weight);
            entries.emplace_back(targets[d], -ratio);
          }
      constrain(targets[c], entries, 0);
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
      tie_field_1_nodes(node_positions(cell->face(f)), same_nodes, jump);
    }

    template <int dim>
    void
    FaceNodeConstraints<dim>::fine_field_1(const cell_iterator &cell,
                                           const unsigned int   f,
                                           const face_iterator &coarse_face,
                                           const unsigned int   subface_no,
                                           const Jump          &jump)
    {
      coarse_face->get_dof_indices(dofs_0, 0);
      cell->face(f)->get_dof_indices(dofs_1, 1);
      tie_field_1_nodes(node_positions(cell->face(f)),
                        subface[subface_no],
                        jump);
    }

    template <int dim>
    void
    FaceNodeConstraints<dim>::tie_field_1_nodes(
      const std::vector<Point<dim>> &x,
      const FullMatrix<double>      &m,
      const Jump                    &jump)
    {
      for (unsigned int j = 0; j < n_nodes; ++j)
        {
          std::array<types::global_dof_index, dim> targets;
          std::array<Entries, dim>                 sources;
          std::array<double, dim>                  jumps;
          for (unsigned int d = 0; d < dim; ++d)
            {
              targets[d] = dofs_1[table[1][d][j]];
              for (unsigned int i = 0; i < n_nodes; ++i)
                if (std::abs(m(j, i)) > 1e-14)
                  sources[d].emplace_back(dofs_0[table[0][d][i]], m(j, i));
              jumps[d] = jump(x[j], d);
            }
          tie(x[j], targets, sources, jumps);
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
      for (unsigned int j = 0; j < n_nodes; ++j)
        {
          std::array<types::global_dof_index, dim> targets;
          std::array<Entries, dim>                 sources;
          std::array<double, dim>                  jumps;
          unsigned int                             i = 0;
          const bool coincides                       = unit_row(m, j, i);
          for (unsigned int d = 0; d < dim; ++d)
            if (coincides)
              {
                targets[d] = dofs_1[table[1][d][i]];
                sources[d] = {{dofs_0[table[0][d][j]], 1.0}};
                jumps[d]   = jump(x[j], d);
              }
            else
              {
                targets[d] = dofs_0[table[0][d][j]];
                for (unsigned int c = 0; c < n_nodes; ++c)
                  if (std::abs(m(j, c)) > 1e-14)
                    sources[d].emplace_back(dofs_1[table[1][d][c]], m(j, c));
                jumps[d] = -jump(x[j], d);
              }
          tie(x[j], targets, sources, jumps);
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
    tie_faces(
      dof_handler,
      fe_space,
      constraints,
      time,
      [](const Fault &fault) { return fault.law->constrains_jump(); },
      nullptr);
  }

  template <int dim>
  void
  FaultInterface<dim>::add_contact_constraints(
    const DoFHandler<dim>         &dof_handler,
    const FiniteElementSpace<dim> &fe_space,
    AffineConstraints<double>     &constraints,
    const ContactState            &is_open) const
  {
    tie_faces(
      dof_handler,
      fe_space,
      constraints,
      0,
      [](const Fault &fault) {
        return fault.law->has_face_terms() && fault.law->exact_contact();
      },
      &is_open);
  }

  template <int dim>
  void
  FaultInterface<dim>::tie_faces(
    const DoFHandler<dim>                    &dof_handler,
    const FiniteElementSpace<dim>            &fe_space,
    AffineConstraints<double>                &constraints,
    const double                              time,
    const std::function<bool(const Fault &)> &which,
    const ContactState                       *contact) const
  {
    // The welded extensions beyond buried tips are tied first (with every
    // law, and not in exact contact's call), so that a tip's node keeps
    // a zero jump; then the faces of the faults @p which selects.
    const bool welds =
      contact == nullptr &&
      std::any_of(faults.begin(), faults.end(), [](const Fault &fault) {
        return fault.trace.buried_top() || fault.trace.buried_bottom();
      });
    if (!welds && std::none_of(faults.begin(), faults.end(), which))
      return;
    // The prescribed jump u(hanging wall) - u(footwall) of fault @p fault,
    // component d, at a node x of one of its faces whose normal into the
    // hanging wall is n (zero for a locked fault and on a weld).
    const auto jump = [&](const Fault          &fault,
                          const bool            weld,
                          const Point<dim>     &x,
                          const Tensor<1, dim> &normal,
                          const unsigned int    d) {
      if (weld || !fault.law->has_prescribed_jump())
        return 0.0;
      const Tensor<1, 2> w =
        fault.law->prescribed_jump(fault.trace.distance_along(x), time);
      return w[0] * fault.trace.down_dip(x)[d] + w[1] * normal[d];
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
    const auto               tie_pass = [&](const bool weld) {
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
              if (k < 0 || welded(cell, f) != weld ||
                  (!weld && !which(faults[k])))
                continue;
              const Fault &fault = faults[k];
              face_constraints.normal_only(contact ? &fault.trace : nullptr,
                                           contact ? *contact : ContactState());
              // The jump of the fields, u(field 1) - u(field 0).
              const double sign = field_1_sign(cell, f, fault.trace);
              const auto   n =
                fault.trace.hanging_wall_normal(cell->face(f)->center(true));
              const auto field_jump = [&](const Point<dim>  &x,
                                          const unsigned int d) {
                return sign * jump(fault, weld, x, n, d);
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
    };
    if (welds)
      tie_pass(true);
    tie_pass(false);
  }

  template void
  FaultInterface<2>::add_constraints(const DoFHandler<2> &,
                                     const FiniteElementSpace<2> &,
                                     AffineConstraints<double> &,
                                     const double) const;
  template void
  FaultInterface<2>::add_contact_constraints(const DoFHandler<2> &,
                                             const FiniteElementSpace<2> &,
                                             AffineConstraints<double> &,
                                             const ContactState &) const;
} // namespace lithostress

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <lithostress/faults/fault_interface.h>

#include <cmath>

// FaultInterface's interface quadrature and face terms: the one loop over
// the faults' interface points (for_each_interface_point) and what the
// elastic law assembles with it.

namespace lithostress
{
  namespace
  {
    /** The node at an interface point among the DoFs [@p begin, @p end)
     * of one side: the DoFs whose shape functions' jumps @p jump are ±e_d
     * there (a Lobatto point is a node of the finer side). Returns the sign
     * of those jumps (0: that side has no node there, and @p node is
     * invalid). */
    template <int dim>
    double
    side_node(const std::vector<Tensor<1, dim>>          &jump,
              const std::vector<types::global_dof_index> &dofs,
              const unsigned int                          begin,
              const unsigned int                          end,
              std::array<types::global_dof_index, dim>   &node)
    {
      node.fill(numbers::invalid_dof_index);
      double       sign  = 0;
      unsigned int found = 0;
      for (unsigned int i = begin; i < end; ++i)
        for (unsigned int d = 0; d < dim; ++d)
          if (std::abs(std::abs(jump[i][d]) - 1) < 1e-10 &&
              node[d] == numbers::invalid_dof_index)
            {
              node[d] = dofs[i];
              sign    = jump[i][d] > 0 ? 1 : -1;
              ++found;
            }
      if (found == dim)
        return sign;
      node.fill(numbers::invalid_dof_index);
      return 0;
    }
  } // namespace

  template <int dim>
  FaultInterface<dim>::FaceTerms::FaceTerms(
    const FiniteElementSpace<dim> &fe_space)
  {
    const unsigned int n = fe_space.fe_collection()[0].n_dofs_per_cell() +
                           fe_space.fe_collection()[1].n_dofs_per_cell();
    matrix.reinit(n, n);
    rhs.reinit(n);
    force.reinit(n);
  }

  template <int dim>
  void
  FaultInterface<dim>::FaceTerms::add_tangent(const PointValues    &values,
                                              const Tensor<2, dim> &tangent)
  {
    const std::vector<Tensor<1, dim>> &jump = values.shape_jumps;
    for (unsigned int i = 0; i < jump.size(); ++i)
      {
        if (jump[i].norm_square() == 0)
          continue;
        const Tensor<1, dim> Dt_vi = transpose(tangent) * jump[i];
        for (unsigned int j = 0; j < jump.size(); ++j)
          matrix(i, j) += Dt_vi * jump[j] * values.point.JxW;
      }
  }

  template <int dim>
  void
  FaultInterface<dim>::FaceTerms::add_affine(const PointValues    &values,
                                             const Tensor<1, dim> &affine)
  {
    const std::vector<Tensor<1, dim>> &jump = values.shape_jumps;
    for (unsigned int i = 0; i < jump.size(); ++i)
      if (jump[i].norm_square() != 0)
        rhs[i] -= jump[i] * affine * values.point.JxW;
  }

  template <int dim>
  void
  FaultInterface<dim>::FaceTerms::add_traction(const PointValues    &values,
                                               const Tensor<1, dim> &traction)
  {
    const std::vector<Tensor<1, dim>> &jump = values.shape_jumps;
    for (unsigned int i = 0; i < jump.size(); ++i)
      if (jump[i].norm_square() != 0)
        force[i] += jump[i] * traction * values.point.JxW;
  }

  template <int dim>
  void
  FaultInterface<dim>::FaceTerms::clear()
  {
    matrix = 0;
    rhs    = 0;
    force  = 0;
  }

  template <int dim>
  typename FaultInterface<dim>::InterfacePoint
  FaultInterface<dim>::interface_point(const unsigned int fault,
                                       const Point<dim>  &position,
                                       const double       JxW) const
  {
    const FaultTrace &trace = faults[fault].trace;
    InterfacePoint    point;
    point.fault    = fault;
    point.position = position;
    point.JxW      = JxW;
    // The fault's exact normal (into the hanging wall) rather than the
    // mapped face's: faces that meet at a node of a curved fault then
    // project the same jump the same way (their mapped normals differ by
    // O(h^2) there, which the stiff normal spring would turn into spurious
    // tractions).
    point.normal           = trace.hanging_wall_normal(point.position);
    point.shear[0]         = point.normal[1];
    point.shear[1]         = -point.normal[0];
    point.depth            = trace.depth(point.position);
    point.overburden_depth = overburden_depth(fault, point.position);
    point.distance         = trace.distance_along(point.position);
    // (Interface points lie at least half a cell apart.)
    const double tolerance = 1e-3;
    point.at_tip =
      (trace.buried_top() && std::abs(point.distance) < tolerance) ||
      (trace.buried_bottom() &&
       std::abs(point.distance - (trace.end_s - trace.begin_s)) < tolerance);
    return point;
  }

  template <int dim>
  void
  FaultInterface<dim>::for_each_interface_point(
    const DoFHandler<dim>               &dof_handler,
    const FiniteElementSpace<dim>       &fe_space,
    const TrilinosWrappers::MPI::Vector *solution,
    const PointVisitor                  &visitor) const
  {
    if (!has_face_terms())
      return;
    const auto &collection = fe_space.fe_collection();
    // Gauss-Lobatto points (the face's nodes for Q2: Simpson's rule): a stiff
    // interface integrated at Gauss points gives tractions that oscillate
    // from point to point near a kink or a change of state (the known
    // defect of interface elements, cured by nodal integration; Schellekens
    // & de Borst 1993); the rule is still exact for a constant traction.
    const QGaussLobatto<dim - 1> quadrature(fe_space.degree() + 1);
    const UpdateFlags            flags = update_values | update_JxW_values |
                              update_normal_vectors | update_quadrature_points;
    const Mapping<dim>  &mapping = fe_space.mapping();
    FEFaceValues<dim>    minus_face(mapping, collection[0], quadrature, flags);
    FESubfaceValues<dim> minus_subface(mapping,
                                       collection[0],
                                       quadrature,
                                       flags);
    FEFaceValues<dim>    plus_face(mapping, collection[1], quadrature, flags);
    FESubfaceValues<dim> plus_subface(mapping,
                                      collection[1],
                                      quadrature,
                                      flags);
    const FEValuesExtractors::Vector u_minus = fe_space.displacement(0),
                                     u_plus  = fe_space.displacement(1);
    const unsigned int n_minus               = collection[0].n_dofs_per_cell(),
                       n_plus                = collection[1].n_dofs_per_cell(),
                       n                     = n_minus + n_plus;
    Vector<double>                       values(n);
    std::vector<types::global_dof_index> dofs(n), minus_dofs(n_minus),
      plus_dofs(n_plus);
    std::vector<Tensor<1, dim>>              jump(n);
    std::array<types::global_dof_index, dim> node, reaction;
    const unsigned int none  = numbers::invalid_unsigned_int;
    unsigned int       index = 0;
    // The finer side's whole face, the coarser side's subface.
    const auto reinit =
      [none](auto              &face,
             auto              &subface,
             const auto        &cell,
             const unsigned int face_no,
             const unsigned int subface_no) -> const FEFaceValuesBase<dim> * {
      if (subface_no == none)
        {
          face.reinit(cell, face_no);
          return &face;
        }
      subface.reinit(cell, face_no, subface_no);
      return &subface;
    };

    for_each_face_pair(
      dof_handler,
      [&](const unsigned int fault,
          const auto        &minus,
          const unsigned int minus_face_no,
          const unsigned int minus_subface_no,
          const auto        &plus,
          const unsigned int plus_face_no,
          const unsigned int plus_subface_no) {
        const FEFaceValuesBase<dim> *m = reinit(
          minus_face, minus_subface, minus, minus_face_no, minus_subface_no);
        const FEFaceValuesBase<dim> *p =
          reinit(plus_face, plus_subface, plus, plus_face_no, plus_subface_no);
        minus->get_dof_indices(minus_dofs);
        plus->get_dof_indices(plus_dofs);
        std::copy(minus_dofs.begin(), minus_dofs.end(), dofs.begin());
        std::copy(plus_dofs.begin(), plus_dofs.end(), dofs.begin() + n_minus);
        values = 0;
        if (solution)
          for (unsigned int i = 0; i < n; ++i)
            values[i] = (*solution)[dofs[i]];
        for (const unsigned int q : m->quadrature_point_indices())
          {
            // The two sides' points coincide (up to the mappings' O(h^3)
            // on curved hanging faces); the footwall's points lie in
            // reversed order on the hanging wall's face of a straight
            // fault if the faces' orientations differ.
            // The closer of the two orders: on curved hanging faces the
            // coarser side's mapping puts its points O(h^3) off the finer
            // side's.
            const unsigned int reversed = m->n_quadrature_points - 1 - q;
            const unsigned int qp =
              m->quadrature_point(q).distance(p->quadrature_point(q)) <=
                  m->quadrature_point(q).distance(p->quadrature_point(reversed))
                ? q
                : reversed;
            Assert(m->quadrature_point(q).distance(p->quadrature_point(qp)) <=
                     1e-2 * minus->diameter(),
                   ExcMessage("the two sides of a fault face do not match"));
            const InterfacePoint point =
              interface_point(fault, m->quadrature_point(q), m->JxW(q));
            // w = u(hanging wall) - u(footwall): the field-1 side is the
            // hanging wall where field 0's outward normal points into it.
            const double sign =
              point.normal * m->normal_vector(q) > 0 ? 1. : -1.;
            for (unsigned int i = 0; i < n_minus; ++i)
              jump[i] = -sign * (*m)[u_minus].value(i, q);
            for (unsigned int i = 0; i < n_plus; ++i)
              jump[n_minus + i] = sign * (*p)[u_plus].value(i, qp);
            Tensor<1, dim> w;
            for (unsigned int i = 0; i < n; ++i)
              w += values[i] * jump[i];
            // The node exact contact constrains: field 1's where it has
            // one here, else field 0's (the finer side of a hanging face).
            double     node_sign = side_node<dim>(jump, dofs, n_minus, n, node);
            const bool on_field_1 = node_sign != 0;
            if (!on_field_1)
              node_sign = side_node<dim>(jump, dofs, 0, n_minus, node);
            const Point<dim> &node_position =
              on_field_1 ? p->quadrature_point(qp) : m->quadrature_point(q);
            // The finer side's node (field 1's on faces of equal level):
            // its reaction is the traction times its Lobatto weight.
            const bool   minus_finer = plus_subface_no != none;
            const double reaction_sign =
              minus_finer ? side_node<dim>(jump, dofs, 0, n_minus, reaction)
                          : side_node<dim>(jump, dofs, n_minus, n, reaction);
            visitor(PointValues{index++,
                                point,
                                w,
                                dofs,
                                jump,
                                q + 1 == m->n_quadrature_points,
                                node,
                                node_sign,
                                node_position,
                                reaction,
                                reaction_sign,
                                minus,
                                plus});
          }
      });
  }

  template <int dim>
  std::vector<typename FaultInterface<dim>::InterfacePoint>
  FaultInterface<dim>::interface_quadrature(
    const DoFHandler<dim>         &dof_handler,
    const FiniteElementSpace<dim> &fe_space) const
  {
    std::vector<InterfacePoint> points;
    for_each_interface_point(dof_handler,
                             fe_space,
                             nullptr,
                             [&](const PointValues &values) {
                               points.push_back(values.point);
                             });
    return points;
  }

  template <int dim>
  void
  FaultInterface<dim>::assemble(const DoFHandler<dim>           &dof_handler,
                                const FiniteElementSpace<dim>   &fe_space,
                                const AffineConstraints<double> &constraints,
                                TrilinosWrappers::SparseMatrix  *matrix,
                                TrilinosWrappers::MPI::Vector   &rhs) const
  {
    // With a frictional fault or exact contact the sliding solver adds
    // every face term.
    if (!has_face_terms() || needs_sliding_solver())
      return;
    // The elastic law t = D w is linear: no affine part, only the tangent,
    // whose product with the constraints' inhomogeneities goes to the
    // right-hand side.
    FaceTerms terms(fe_space);
    for_each_interface_point(
      dof_handler, fe_space, nullptr, [&](const PointValues &values) {
        terms.add_tangent(values, stuck_tangent(values.point));
        if (!values.last_of_pair)
          return;
        if (matrix)
          constraints.distribute_local_to_global(
            terms.matrix, terms.rhs, values.dofs, *matrix, rhs);
        else
          constraints.distribute_local_to_global(terms.rhs,
                                                 values.dofs,
                                                 rhs,
                                                 terms.matrix);
        terms.clear();
      });
    if (matrix)
      matrix->compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
  }

  template FaultInterface<2>::FaceTerms::FaceTerms(
    const FiniteElementSpace<2> &);
  template void
  FaultInterface<2>::FaceTerms::add_tangent(const PointValues &,
                                            const Tensor<2, 2> &);
  template void
  FaultInterface<2>::FaceTerms::add_affine(const PointValues &,
                                           const Tensor<1, 2> &);
  template void
  FaultInterface<2>::FaceTerms::add_traction(const PointValues &,
                                             const Tensor<1, 2> &);
  template void
  FaultInterface<2>::FaceTerms::clear();
  template FaultInterface<2>::InterfacePoint
  FaultInterface<2>::interface_point(const unsigned int,
                                     const Point<2> &,
                                     const double) const;
  template void
  FaultInterface<2>::for_each_interface_point(
    const DoFHandler<2> &,
    const FiniteElementSpace<2> &,
    const TrilinosWrappers::MPI::Vector *,
    const PointVisitor &) const;
  template std::vector<FaultInterface<2>::InterfacePoint>
  FaultInterface<2>::interface_quadrature(const DoFHandler<2> &,
                                          const FiniteElementSpace<2> &) const;
  template void
  FaultInterface<2>::assemble(const DoFHandler<2> &,
                              const FiniteElementSpace<2> &,
                              const AffineConstraints<double> &,
                              TrilinosWrappers::SparseMatrix *,
                              TrilinosWrappers::MPI::Vector &) const;
} // namespace lithostress

#ifndef lithostress_boundary_conditions_rigid_body_support_h
#define lithostress_boundary_conditions_rigid_body_support_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/loads/load_collection.h>

#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * Well-posedness before solving: does every rigid-body motion of every
   * body (in 2-D two translations and the rotation of each displacement
   * field) meet a constraint or a spring? The test is exact and cheap. With
   * R the rigid-body modes at the DoFs (rotation about the centre of the
   * body, scaled by its size so that all modes are O(1)), each constraint
   * line u_i = sum_j a_ij u_j + b_i contributes its residual
   * r_k(i) - sum_j a_ij r_k(j) for each mode k, and each vertical spring
   * k |n_y| u_y v_y on a boundary part the form int |n_y| r_k,y r_l,y ds
   * (divided by the size of the body; the spring's magnitude does not
   * matter, only that it acts). A motion c (a combination of modes) is
   * held iff c^T G c > 0 for the sum G of these forms, so the free motions
   * are the null space of the small matrix G, whatever combination of
   * translation and rotation they are. Hanging-node constraints reproduce
   * rigid motions only to O(h^3) on curved boundaries, so the test runs on
   * the coarse mesh, where it is exact.
   */
  template <int dim>
  class RigidBodySupport
  {
  public:
    /**
     * Throw an InputError (on all ranks) naming the free motion, e.g. "the
     * body is free to translate in y: no part prescribes a y-displacement
     * and no spring holds it vertically", if @p constraints (closed, on the
     * DoFs of @p dof_handler) and the springs of @p loads leave a
     * rigid-body motion free. @p length_scale and @p length_unit give
     * points (a centre of rotation) in the input's unit. @p interface_points
     * (quadrature points x with weights w, each rank its own) are where an
     * elastic fault couples the two displacement fields: they add
     * w |r_k(field 1, x) − r_k(field 0, x)|-forms to G, so a body held
     * through the fault by the other is held.
     */
    static void
    check(
      const DoFHandler<dim>                            &dof_handler,
      const FiniteElementSpace<dim>                    &fe_space,
      const AffineConstraints<double>                  &constraints,
      const LoadCollection<dim>                        &loads,
      const double                                      length_scale,
      const std::string                                &length_unit,
      const std::vector<std::pair<Point<dim>, double>> &interface_points = {});
  };
} // namespace lithostress

#endif

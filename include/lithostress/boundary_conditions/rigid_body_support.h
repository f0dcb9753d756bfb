#ifndef lithostress_boundary_conditions_rigid_body_support_h
#define lithostress_boundary_conditions_rigid_body_support_h

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/loads/load_collection.h>

#include <functional>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The bodies whose rigid-body motions RigidBodySupport tests: one
   * without faults, else the blocks the faults cut the body into
   * (FaultInterface::block_of), which may be more than the two
   * displacement fields (a graben's three blocks share two fields).
   */
  template <int dim>
  struct RigidBodies
  {
    /** The number of bodies. */
    unsigned int n = 1;
    /** The body an active cell belongs to (all: 0). */
    std::function<unsigned int(
      const typename Triangulation<dim>::cell_iterator &)>
      of =
        [](const typename Triangulation<dim>::cell_iterator &) { return 0U; };
  };

  /**
   * Where an interface holds two bodies against each other: an interface
   * point with its weight [m], the bodies on either side and the
   * interface's stiffness there, D L / E (the tangent D of the traction
   * in the jump per unit area [Pa/m], the size L of the model and its
   * largest Young's modulus E: dimensionless). A welded or stuck fault
   * point couples with the identity; a sliding point in exact contact
   * couples nowhere (its normal is a constraint line, its shear is free);
   * an open point not at all.
   */
  template <int dim>
  struct BodyCoupling
  {
    Point<dim>     position;
    double         JxW    = 0;
    unsigned int   body_0 = 0, body_1 = 0;
    Tensor<2, dim> stiffness;
  };

  /**
   * Well-posedness: does every rigid-body motion of every body (in 2-D
   * two translations and the rotation of each body) meet a constraint, a
   * spring or an interface that holds it? The test is exact and cheap.
   * With R the rigid-body modes at the DoFs (rotation about the centre of
   * the model, scaled by its size L so that all modes are O(1)), each
   * constraint line u_i = sum_j a_ij u_j + b_i contributes its residual
   * r_k(i) - sum_j a_ij r_k(j) for each mode k; each vertical spring k
   * |n_y| u_y v_y on a boundary part the form min(1, k L / E) int |n_y|
   * r_k,y r_l,y ds / L for the largest Young's modulus E, so that a spring
   * too weak to hold anything -- a fluid density of 1e-300 -- does not
   * count, while the weakest spring of a real model, k L / E of 1e-7 for a
   * 1 m block on water, is far above the threshold; and each BodyCoupling
   * with stiffness A the form (w / L) [r_k]^T A^T A [r_l] / max(1, |A|^2)
   * of the jump [r] of the modes across it (a non-symmetric tangent holds
   * a motion unless it maps its jump to zero). A motion c (a combination
   * of modes) is held iff c^T G c > 0 for the sum G of these forms, so the
   * free motions are the null space of the small matrix G, whatever
   * combination of translations and rotations of the bodies they are.
   * Hanging-node constraints reproduce rigid motions only to O(h^3) on
   * curved boundaries, a round-off far below the threshold for the meshes
   * a model solves on; on the coarse mesh the test is exact.
   */
  template <int dim>
  class RigidBodySupport
  {
  public:
    /**
     * A sentence naming the first free motion that @p constraints (closed,
     * on the DoFs of @p dof_handler), the springs of @p loads and the
     * @p couplings between the @p bodies leave, e.g. "the block around
     * (500, -10) km is free to translate in y: no part prescribes a
     * y-displacement and no spring holds it vertically"; empty if every
     * motion is held. @p youngs_modulus is the largest Young's modulus of
     * the model [Pa]; @p length_scale and @p length_unit give points (a
     * centre of rotation) in the input's unit. Collective: @p couplings
     * are each rank's own.
     */
    static std::string
    free_motion(const DoFHandler<dim>                &dof_handler,
                const FiniteElementSpace<dim>        &fe_space,
                const AffineConstraints<double>      &constraints,
                const LoadCollection<dim>            &loads,
                const double                          youngs_modulus,
                const RigidBodies<dim>               &bodies,
                const std::vector<BodyCoupling<dim>> &couplings,
                const double                          length_scale,
                const std::string                    &length_unit);

    /**
     * Before solving: throw an InputError (on all ranks) naming the free
     * motion, if free_motion() finds one with every fault point coupling
     * its two blocks fully (the elastic predictor's view of the faults).
     */
    static void
    check(const DoFHandler<dim>                &dof_handler,
          const FiniteElementSpace<dim>        &fe_space,
          const AffineConstraints<double>      &constraints,
          const LoadCollection<dim>            &loads,
          const double                          youngs_modulus,
          const RigidBodies<dim>               &bodies,
          const std::vector<BodyCoupling<dim>> &couplings,
          const double                          length_scale,
          const std::string                    &length_unit);
  };
} // namespace lithostress

#endif

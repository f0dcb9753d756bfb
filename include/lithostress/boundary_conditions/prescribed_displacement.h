#ifndef lithostress_boundary_conditions_prescribed_displacement_h
#define lithostress_boundary_conditions_prescribed_displacement_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/lac/affine_constraints.h>

#include <lithostress/base/parsed_expression.h>
#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/loads/load.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lithostress
{
  /**
   * Prescribed displacement per component per boundary part (thesis card
   * 9): rollers (one component zero), fixed parts, or values given as
   * functions of position, or the reference solution's displacement.
   * Applied as constraints, after the hanging-node constraints.
   *
   * A component may also be `rigid`: the same unknown value at every point
   * of the part, a rigid edge or piston (Kusznir & Bott 1977, thesis
   * §7.3.2: a plate pushed by a uniform edge displacement, so that the
   * force moves from a relaxing layer to an elastic one). Every DoF of the
   * component on the part is constrained to one master DoF; a traction on
   * the part (e.g. a `Resultant force`) then acts only through its total,
   * which the constraints collect on the master.
   */
  template <int dim>
  class PrescribedDisplacement
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);
    void
    parse_parameters(ParameterHandler &prm, const ModelDescription<dim> &model);

    /** Add the constraints at time @p time to @p constraints. */
    void
    apply(const DoFHandler<dim>         &dof_handler,
          const FiniteElementSpace<dim> &fe_space,
          AffineConstraints<double>     &constraints,
          const double                   time = 0) const;

    /**
     * The degrees of freedom each part prescribes, per component, by part
     * name; a degree of freedom on two parts (a corner) belongs to the first
     * one named. Used to sum reaction forces.
     */
    std::vector<std::pair<std::string, std::array<IndexSet, dim>>>
    constrained_dofs(const DoFHandler<dim>         &dof_handler,
                     const FiniteElementSpace<dim> &fe_space) const;

    /**
     * The boundary parts with prescribed components and the component mask
     * of each, for solvers that impose the same constraints with value zero
     * on every multigrid level.
     */
    std::vector<std::pair<types::boundary_id, ComponentMask>>
    constrained_components(const FiniteElementSpace<dim> &fe_space) const;

    /** Whether any part has a `rigid` component (constraints that couple
     * DoFs along a whole edge: the matrix-free multigrid's level
     * constraints cannot express them). */
    bool
    has_rigid_components() const;

    /** Whether part @p id has a prescribed component. */
    bool
    constrains(const types::boundary_id id) const;

  private:
    struct Part
    {
      std::string                                             name;
      types::boundary_id                                      id;
      std::array<std::unique_ptr<ParsedExpression<dim>>, dim> component;
      std::array<bool, dim>                                   from_reference;
      std::array<bool, dim>                                   rigid;
    };

    /** Constrain each `rigid` component of each part to one master DoF. */
    void
                      apply_rigid_components(const DoFHandler<dim>         &dof_handler,
                                             const FiniteElementSpace<dim> &fe_space,
                                             AffineConstraints<double>     &constraints) const;
    std::vector<Part> parts;
    const ReferenceSolution<dim> *reference = nullptr;
  };
} // namespace lithostress

#endif

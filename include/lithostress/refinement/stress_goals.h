#ifndef lithostress_refinement_stress_goals_h
#define lithostress_refinement_stress_goals_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/grid/cell_id.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/reference_solutions/reference_solution.h>

#include <boost/signals2/connection.hpp>

#include <map>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * Quantities of interest for goal-oriented refinement and for stopping the
   * refinement cycles once they have converged (`Mesh refinement/Goals`):
   * regional means of a stress component,
   *
   *   J_i(u) = (1/|S_i|) ∫_{S_i} c_i : σ(u) dx,
   *
   * over the part S_i of the body inside an axis-parallel box — the
   * "regional stress" of a layer at an edge, the stress above an anomaly —
   * the numbers the thesis quotes (chapter 7) and that a convergence study
   * should converge; or of a displacement component, J_i(u) = (1/|S_i|)
   * ∫_{S_i} u·e_i dx (`Displacement averages`): over a thin box under the
   * top, the surface displacement that a buried fault's closed form and a
   * geodetic profile give. Each J_i is linear in the displacement, so its error
   * is weighted by the solution z_i of the dual problem a(v, z_i) = J_i(v)
   * (Becker & Rannacher 2001; step-14): the goal-oriented indicator
   * η_K = η_K(u) Σ_i η_K(z_i) / |J_i(u)| bounds each goal's error by
   * Cauchy–Schwarz over the cells (Prudhomme & Oden 1999).
   *
   * Cells that the box cuts are integrated on a quadtree of sub-squares
   * refined towards the box's edges (to 2^-7 of the cell), the finest
   * straddling squares clipped to the box: the region is integrated to
   * round-off for straight cells, so that the goals' change between cycles
   * is the solution's, not the quadrature's.
   */
  template <int dim>
  class StressGoals
  {
  public:
    /** The stress component a goal averages. */
    enum class Component
    {
      sigma_xx,
      sigma_yy,
      sigma_xy,
      sigma_zz,
      deviatoric_xx,
      deviatoric_yy,
      u_x,
      u_y
    };

    /** Whether @p component is one of the displacement's. */
    static bool
    is_displacement(const Component component)
    {
      return component == Component::u_x || component == Component::u_y;
    }

    /** The vector index (0 for x, 1 for y) of a displacement component. */
    static unsigned int
    displacement_index(const Component component)
    {
      return component == Component::u_x ? 0 : 1;
    }

    /** One regional mean. */
    struct Goal
    {
      std::string name;
      Component   component;
      Point<dim>  lower, upper;
    };

    static void
    declare_parameters(ParameterHandler &prm);
    /** Read the goals; @p length_scale converts the length unit to m. */
    void
    parse_parameters(ParameterHandler &prm, const double length_scale);

    /** Whether any goal is given. */
    bool
    empty() const
    {
      return goals.empty();
    }

    const std::vector<Goal> &
    list() const
    {
      return goals;
    }

    /** The relative change of every goal between two cycles below which
     * the refinement cycles stop (0: run all cycles). */
    double
    stop_tolerance() const
    {
      return tolerance;
    }

    /**
     * Check that every goal's box covers part of the body (on the coarse
     * mesh of @p dof_handler); throws InputError naming the goal otherwise.
     */
    void
    check_regions(const DoFHandler<dim>         &dof_handler,
                  const FiniteElementSpace<dim> &fe_space) const;

    /** J_i(u) of every goal for the ghosted @p solution, with the stress
     * every result reports (initial strains and creep included). */
    std::vector<double>
    values(const DoFHandler<dim>               &dof_handler,
           const FiniteElementSpace<dim>       &fe_space,
           const StressModel<dim>              &stress_model,
           const TrilinosWrappers::MPI::Vector &solution) const;

    /** J_i of the exact solution @p reference (its in-plane stress, and
     * σ_zz from the elastic law) on the same quadrature. */
    std::vector<double>
    reference_values(const DoFHandler<dim>         &dof_handler,
                     const FiniteElementSpace<dim> &fe_space,
                     const StressModel<dim>        &stress_model,
                     const ReferenceSolution<dim>  &reference) const;

    /**
     * The dual right-hand side of goal @p k: the linear part of J_k,
     * J_k(v) = (1/|S_k|) ∫ c_k : C ε(v) with the moduli of the current
     * operator (the time step's relaxed moduli in the time loop),
     * distributed through @p constraints without their inhomogeneities.
     * @p rhs is an owned vector, zeroed first.
     */
    void
    assemble_dual_rhs(const unsigned int               k,
                      const DoFHandler<dim>           &dof_handler,
                      const FiniteElementSpace<dim>   &fe_space,
                      const StressModel<dim>          &stress_model,
                      const AffineConstraints<double> &constraints,
                      TrilinosWrappers::MPI::Vector   &rhs) const;

    /** Whether every goal changed by less than the stop tolerance
     * (relative to its present value) from @p previous to @p current. */
    bool
    converged(const std::vector<double> &previous,
              const std::vector<double> &current) const;

    /** What record_cycle() found: the largest relative change of a goal
     * since the last cycle with at most half as many DoFs (that cycle's
     * DoFs; 0 if there is none yet), and whether it is below the stop
     * tolerance. */
    struct CycleChange
    {
      unsigned long long compared_with = 0;
      double             change        = 0;
      std::string        goal;
      bool               converged = false;
    };

    /**
     * Record the goals' values @p values of a cycle with @p dofs DoFs and
     * compare them with the last recorded cycle that had at most half as
     * many DoFs: between two cycles that refine a handful of cells the
     * goals hardly change whatever their error.
     */
    CycleChange
    record_cycle(const unsigned long long   dofs,
                 const std::vector<double> &values);

    /** The weights 1/|J_i| of the goal-oriented indicator (relative
     * accuracy of every goal; a goal near zero is weighted as 1e-6 of the
     * largest). */
    static std::vector<double>
    weights(const std::vector<double> &values);

    /** The largest relative change from @p previous to @p current, and the
     * goal that has it. */
    std::pair<double, std::string>
    largest_change(const std::vector<double> &previous,
                   const std::vector<double> &current) const;

    /** The name of @p component as in the `.prm` ("sigma_xx"). */
    static std::string
    component_name(const Component component);

  private:
    /** The goals of one entry (`Stress averages` or `Displacement
     * averages`, @p text as given), whose components must be among
     * @p allowed; appended to `goals`. */
    void
    parse_goals(const std::string            &entry,
                const std::string            &text,
                const std::vector<Component> &allowed,
                const double                  length_scale);

    /** The area of the part of the body in goal @p k's box (all ranks). */
    double
    area(const unsigned int             k,
         const DoFHandler<dim>         &dof_handler,
         const FiniteElementSpace<dim> &fe_space) const;

    /** Σ over the owned cells of f(cell, goal, unit point, point, JxW) for
     * the quadrature points inside goal @p k's box. */
    template <typename Integrand>
    void
    integrate(const unsigned int             k,
              const DoFHandler<dim>         &dof_handler,
              const FiniteElementSpace<dim> &fe_space,
              const Integrand               &integrand) const;

    std::vector<Goal> goals;
    double            tolerance = 0;
    /** The recorded cycles: DoFs and the goals' values. */
    std::vector<std::pair<unsigned long long, std::vector<double>>> history;
    /** Per goal, the quadrature (unit cell) of each cell its box cuts, on
     * the present mesh; cleared when the mesh changes. */
    mutable std::vector<std::map<CellId, Quadrature<dim>>> cut_cells;
    mutable boost::signals2::scoped_connection             mesh_changed;
  };
} // namespace lithostress

#endif

#ifndef lithostress_refinement_mesh_refinement_h
#define lithostress_refinement_mesh_refinement_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/stress_model.h>

#include <functional>

namespace lithostress
{
  /**
   * The `Mesh refinement` section and the refinement between cycles: global
   * refinement, or adaptive refinement driven by an error indicator —
   * Kelly's jump of the displacement gradient across faces, a
   * stress-recovery indicator (Zienkiewicz–Zhu: the L2 distance of the
   * finite element stress from its continuous nodal average), or the
   * goal-oriented product of the stress-recovery indicators of the solution
   * and of the dual solutions of the goals (StressGoals) — with
   * refine/coarsen fractions of the cells, a maximum level and p4est load
   * balancing.
   */
  template <int dim>
  class MeshRefinement
  {
  public:
    enum class Strategy
    {
      global,
      adaptive
    };
    enum class Indicator
    {
      kelly,
      stress_recovery,
      goal_oriented
    };
    /** How cells are marked: a fraction of the cells (fixed number), or the
     * cells that carry a fraction of the squared error (Dörfler marking). */
    enum class Marking
    {
      fraction_of_cells,
      fraction_of_error
    };

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Refine @p tria once, as configured; @p solution has ghost values.
     * Once the cells are marked, and before the mesh changes,
     * @p check_new_mesh is called on all ranks with the number of active
     * cells and of levels the new mesh will have (the memory check; it may
     * throw).
     */
    void
    refine(parallel::distributed::Triangulation<dim>        &tria,
           const DoFHandler<dim>                            &dof_handler,
           const FiniteElementSpace<dim>                    &fe_space,
           const StressModel<dim>                           &stress_model,
           const TrilinosWrappers::MPI::Vector              &solution,
           const std::function<void(double, unsigned int)>  &check_new_mesh,
           const std::vector<TrilinosWrappers::MPI::Vector> &duals = {},
           const std::vector<double> &weights                      = {}) const;

    /**
     * The error indicator per active cell (zero on non-owned cells). The
     * goal-oriented indicator needs the ghosted dual solutions @p duals
     * (homogeneous constraints) and their weights @p weights (1/|J_i|):
     * η_K = η_K(u) Σ_i w_i η_K(z_i), with η_K(z) the stress-recovery
     * indicator of the dual stress C ε(z) in the current operator's moduli.
     */
    Vector<float>
    indicators(const DoFHandler<dim>                            &dof_handler,
               const FiniteElementSpace<dim>                    &fe_space,
               const StressModel<dim>                           &stress_model,
               const TrilinosWrappers::MPI::Vector              &solution,
               const std::vector<TrilinosWrappers::MPI::Vector> &duals = {},
               const std::vector<double> &weights = {}) const;

    /** The stress of a strain at a point of a cell (unit and real
     * coordinates): the stress model's, or the linear law of a dual. */
    using StressOf = std::function<SymmetricTensor<2, dim>(
      const typename Triangulation<dim>::active_cell_iterator &,
      const Point<dim> &,
      const Point<dim> &,
      const SymmetricTensor<2, dim> &)>;

    /** The stress-recovery (Zienkiewicz–Zhu) indicator of @p solution with
     * stresses from @p stress_of, averaged per law (moduli and viscosity
     * of @p stress_model) and field. */
    Vector<float>
    stress_recovery(const DoFHandler<dim>               &dof_handler,
                    const FiniteElementSpace<dim>       &fe_space,
                    const StressModel<dim>              &stress_model,
                    const TrilinosWrappers::MPI::Vector &solution,
                    const StressOf                      &stress_of) const;

    /** Dörfler marking of the cells carrying the refine fraction of Σ η²
     * (and, @p with_coarsening, coarsening of those carrying the coarsen
     * fraction); adds to the flags already set. */
    void
    mark_fraction_of_error(parallel::distributed::Triangulation<dim> &tria,
                           const Vector<float>                       &eta,
                           const bool with_coarsening = true) const;

    /** The goal-oriented indicator of each goal: η_K(u) w_i η_K(z_i). */
    std::vector<Vector<float>>
    goal_indicators(const DoFHandler<dim>               &dof_handler,
                    const FiniteElementSpace<dim>       &fe_space,
                    const StressModel<dim>              &stress_model,
                    const TrilinosWrappers::MPI::Vector &solution,
                    const std::vector<TrilinosWrappers::MPI::Vector> &duals,
                    const std::vector<double> &weights) const;

    unsigned int initial_global_refinement = 0;
    unsigned int n_cycles                  = 1;
    Strategy     strategy                  = Strategy::global;
    Indicator    indicator                 = Indicator::kelly;
    Marking      marking                   = Marking::fraction_of_error;
    double       refine_fraction           = 0.3;
    double       coarsen_fraction          = 0.0;
    unsigned int max_level                 = 20;
  };
} // namespace lithostress

#endif

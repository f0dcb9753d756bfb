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
   * Kelly's jump of the displacement gradient across faces, or a
   * stress-recovery indicator (Zienkiewicz–Zhu: the L2 distance of the
   * finite element stress from its continuous nodal average) — with
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
      stress_recovery
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
    refine(
      parallel::distributed::Triangulation<dim>       &tria,
      const DoFHandler<dim>                           &dof_handler,
      const FiniteElementSpace<dim>                   &fe_space,
      const StressModel<dim>                          &stress_model,
      const TrilinosWrappers::MPI::Vector             &solution,
      const std::function<void(double, unsigned int)> &check_new_mesh) const;

    /** The error indicator per active cell (zero on non-owned cells). */
    Vector<float>
    indicators(const DoFHandler<dim>               &dof_handler,
               const FiniteElementSpace<dim>       &fe_space,
               const StressModel<dim>              &stress_model,
               const TrilinosWrappers::MPI::Vector &solution) const;

    /** Dörfler marking of the cells carrying the refine fraction of Σ η². */
    void
    mark_fraction_of_error(parallel::distributed::Triangulation<dim> &tria,
                           const Vector<float> &eta) const;

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

#ifndef lithostress_materials_cell_history_h
#define lithostress_materials_cell_history_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The history of the rock laws at the cell quadrature points (thesis
   * §3.9, doc/equations.md §10): one record per point with the components
   * the laws name (Rheology::history_names(), laid out by HistoryLayout;
   * MaxwellRheology's deviatoric creep strain xx, yy, xy, zz), stored as a
   * discontinuous finite-element field whose nodes are the Gauss points of
   * the cell quadrature (FE_DGQArbitraryNodes on QGauss(n)). So:
   * - a node's value is the history at that quadrature point: the time
   *   update at the quadrature points of assembly is exact, no projection;
   * - at any other point (output, point values, profiles) the history is
   *   the cell's polynomial through its Gauss-point values;
   * - mesh changes and checkpoints are deal.II's SolutionTransfer of a DG
   *   field: refinement evaluates the parent's polynomial at the children's
   *   nodes, coarsening projects the children's polynomials onto the parent
   *   (L2). Both are exact for a field that is a polynomial of degree n − 1
   *   in each coordinate; otherwise the error is that of the projection,
   *   O(h^n). This sidesteps 9.4.1's ContinuousQuadratureDataTransfer, which
   *   cannot coarsen (doc/dealii_facts.md);
   * - checkpoints are the same SolutionTransfer's serialization, so a run
   *   resumes on any number of ranks.
   * A model whose laws keep no history has a field of no components: every
   * operation is then empty, and nothing is transferred or written.
   */
  template <int dim>
  class CellHistory
  {
  public:
    using VectorType = LinearAlgebra::distributed::Vector<double>;

    /** A history field on @p triangulation with @p n_points_1d Gauss points
     * per direction (that of the assembly: p + 1 for Q_p) and the
     * components @p names (HistoryLayout::names(); may be none). */
    CellHistory(const parallel::distributed::Triangulation<dim> &triangulation,
                const unsigned int                               n_points_1d,
                const std::vector<std::string>                  &names);

    /** The names of the components of a record. */
    const std::vector<std::string> &
    names() const
    {
      return component_names;
    }

    /** The number of components of a record. */
    unsigned int
    n_components() const
    {
      return component_names.size();
    }

    /** Number the nodes of the current mesh and set the field to zero. */
    void
    setup();

    /** The quadrature whose points are the nodes of a cell. */
    const Quadrature<dim> &
    quadrature() const
    {
      return nodes;
    }

    /** The records at the nodes (quadrature points) of an owned @p cell:
     * @p values[q][c] for node q and component c. */
    void
    get(const typename Triangulation<dim>::active_cell_iterator &cell,
        std::vector<Vector<double>>                             &values) const;

    /** The record at the unit-cell point @p unit of an owned or ghost
     * @p cell, into @p record: the cell's polynomial through its node
     * values. */
    void
    value(const typename Triangulation<dim>::active_cell_iterator &cell,
          const Point<dim>                                        &unit,
          Vector<double> &record) const;

    /** Set the values at the nodes of an owned @p cell. */
    void
    set(const typename Triangulation<dim>::active_cell_iterator &cell,
        const std::vector<Vector<double>>                       &values);

    /** Exchange ghost values after set() (collective); needed before the
     * field is evaluated on ghost cells or transferred. */
    void
    update_ghost_values();

    /** Before the triangulation is refined or coarsened (collective). */
    void
    prepare_for_mesh_change();

    /** After it: number the new nodes and transfer the field (collective). */
    void
    finish_mesh_change();

    /**
     * Attach the field to the triangulation's next save() (collective):
     * call before `triangulation.save(file)`.
     */
    void
    prepare_for_checkpoint();

    /**
     * After `triangulation.load(file)` — on any number of ranks, the mesh
     * repartitioned — number the nodes and read the field back
     * (collective).
     */
    void
    load_from_checkpoint();

    /** The field's DoFs and values (ghosted), for evaluation at arbitrary
     * points with FEValues. */
    const DoFHandler<dim> &
    dof_handler() const
    {
      return dofs;
    }

    /** The values of the nodes (ghosted). */
    const VectorType &
    values() const
    {
      return field;
    }

    /** This field := @p a + @p factor × @p b (fields on the same mesh),
     * ghosts exchanged. */
    void
    set_to_sum(const CellHistory<dim> &a,
               const double            factor,
               const CellHistory<dim> &b)
    {
      field = a.field;
      field.add(factor, b.field);
      field.update_ghost_values();
    }

    /** This field := @p fa × @p a + @p fb × @p b (fields on the same
     * mesh), ghosts exchanged. */
    void
    set_to_combination(const double            fa,
                       const CellHistory<dim> &a,
                       const double            fb,
                       const CellHistory<dim> &b)
    {
      field.equ(fa, a.field);
      field.add(fb, b.field);
      field.update_ghost_values();
    }

    /** Exchange the values with @p other (a field on the same mesh). */
    void
    swap_values(CellHistory<dim> &other)
    {
      field.swap(other.field);
    }

    /** Set the field to @p values (a copy of values() on the same mesh)
     * and exchange ghosts: the undo of a rejected time step. */
    void
    assign(const VectorType &values)
    {
      field = values;
      field.update_ghost_values();
    }

  private:
    /** A transfer attached to the current field (ghosts updated). */
    parallel::distributed::SolutionTransfer<dim, VectorType> &
    new_transfer();

    /** Number the nodes of the current mesh (setup()) and take the owned
     * values from @p read (an interpolation or a deserialization). */
    void
    renumber_and_read(const std::function<void(VectorType &)> &read);

    typename DoFHandler<dim>::active_cell_iterator
    dof_cell(
      const typename Triangulation<dim>::active_cell_iterator &cell) const;

    const std::vector<std::string> component_names;
    const QGauss<dim>              nodes;
    /** The field's element (none without components). */
    const std::unique_ptr<const FESystem<dim>> fe;
    DoFHandler<dim>                            dofs;
    VectorType                                 field;
    std::unique_ptr<parallel::distributed::SolutionTransfer<dim, VectorType>>
      transfer;
  };
} // namespace lithostress

#endif

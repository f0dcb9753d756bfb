#ifndef lithostress_assembly_elastic_assembler_h
#define lithostress_assembly_elastic_assembler_h

#include <functional>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/fe_values.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/discretization/linear_system.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/materials/stress_model.h>

namespace lithostress
{
  /**
   * Assembles the elasticity system (thesis §3.6): the stiffness
   * ∫ ε(v) : C ε(u) dx of every cell with the moduli of its material, and
   * the contributions of every load (cell and boundary integrals), through
   * the constraints into the distributed matrix and right-hand side. Cells
   * of any active FE index are handled through the displacement field of
   * that index.
   *
   * In a step of the visco-elastic loop the stiffness is that of the step
   * moduli (StressModel::step_moduli(), the relaxed shear modulus) and the
   * laws' history h* of the step (MaxwellRheology: the history strain c*)
   * adds −∫ ε(v) : σ_h(h*) dx to the right-hand side
   * (StressModel::history_stress()). A non-linear law's step (Newton's
   * iteration) is assembled from its linearisation at the iterate instead
   * (StressModel::linearised(), LinearisedStress): the tangent C_k and
   * −∫ ε(v) : σ₀ dx.
   */
  template <int dim>
  class ElasticAssembler
  {
  public:
    ElasticAssembler(const FiniteElementSpace<dim> &fe_space,
                     const StressModel<dim>        &stress_model,
                     const LoadCollection<dim>     &loads);

    /** Assemble with the laws' history @p history of a time step
     * (nullptr: none); the field lives on the cells' quadrature points. */
    void
    set_cell_history(const CellHistory<dim> *history)
    {
      cell_history = history;
    }

    /** Assemble matrix (if @p with_matrix) and right-hand side. */
    void
    assemble(const DoFHandler<dim> &dof_handler,
             LinearSystem<dim>     &system,
             const bool             with_matrix = true) const;

    /** The locally owned cells @p selected chooses. */
    using CellSelection = std::function<bool(
      const typename DoFHandler<dim>::active_cell_iterator &)>;

    /**
     * Add the cell matrices assemble() makes (stiffness and the loads'
     * terms) of the locally owned cells @p selected chooses, through
     * @p constraints, to @p matrix (neither zeroed nor compressed):
     * the same operator on a part of the mesh with other constraints (the
     * sliding solver's strip along the faults, FaultStripStiffness).
     */
    void
    add_cell_matrices(const DoFHandler<dim>           &dof_handler,
                      const CellSelection             &selected,
                      const AffineConstraints<double> &constraints,
                      TrilinosWrappers::SparseMatrix  &matrix) const;

    /** Add the cell stiffness ∫ ε(φ_i) : C ε(φ_j) dx to @p cell_matrix. */
    static void
    add_cell_stiffness(const FEValues<dim>      &fe_values,
                       const ElasticModuli<dim> &moduli,
                       FullMatrix<double>       &cell_matrix);

    /** The same for isotropic Lamé parameters @p lame (the multigrid's
     * coarse matrix, whose moduli come per cell). */
    static void
    add_cell_stiffness(const FEValues<dim>  &fe_values,
                       const LameParameters &lame,
                       FullMatrix<double>   &cell_matrix);

    /** The same with the tangent @p tangents[q] at each quadrature point
     * of @p fe_values (a law whose tangent varies from point to point),
     * for the field @p displacement. */
    static void
    add_cell_stiffness(const FEValues<dim>                        &fe_values,
                       const FEValuesExtractors::Vector           &displacement,
                       const std::vector<SymmetricTensor<4, dim>> &tangents,
                       FullMatrix<double>                         &cell_matrix);

    /**
     * Add the stiffness of a cell of material @p id (values in
     * @p fe_values, field @p displacement) to @p cell_matrix: per cell
     * with its law's step moduli, or with @p of_state its elastic moduli
     * (the stress of a state), where the law's tangent is uniform; else
     * StressModel::tangent() at each quadrature point. The assembly's and
     * the force balance's stiffness.
     */
    static void
    add_law_stiffness(const StressModel<dim>           &stress_model,
                      const FEValues<dim>              &fe_values,
                      const FEValuesExtractors::Vector &displacement,
                      const types::material_id          id,
                      const bool                        of_state,
                      FullMatrix<double>               &cell_matrix);

    /**
     * Add the cell and boundary-face terms of @p load on @p cell (whose
     * values are in @p fe_values) to @p cell_matrix and @p cell_rhs; used by
     * the assembly and by the force balance, which needs each load alone.
     */
    static void
    add_load_terms(const Load<dim>                                      &load,
                   const typename DoFHandler<dim>::active_cell_iterator &cell,
                   const FEValues<dim>              &fe_values,
                   hp::FEFaceValues<dim>            &hp_face_values,
                   const FEValuesExtractors::Vector &displacement,
                   const Material                   &material,
                   const ElasticModuli<dim>         &moduli,
                   FullMatrix<double>               &cell_matrix,
                   Vector<double>                   &cell_rhs);

    /**
     * Add the history's term −∫ ε(φ_i) : σ_h dx to @p cell_rhs: @p records
     * are the cell history at the quadrature points of @p fe_values (a
     * cell of material @p id), σ_h their stress
     * (StressModel::history_stress(), of the current step or with
     * @p of_state of a state).
     */
    static void
    add_history_terms(const StressModel<dim>            &stress_model,
                      const FEValues<dim>               &fe_values,
                      const FEValuesExtractors::Vector  &displacement,
                      const types::material_id           id,
                      const std::vector<Vector<double>> &records,
                      const bool                         of_state,
                      Vector<double>                    &cell_rhs);

    /** The cell values the assembly needs, for @p fe_space. */
    static hp::FEValues<dim>
    cell_values(const FiniteElementSpace<dim> &fe_space);

    /** The face values the boundary loads need, for @p fe_space. */
    static hp::FEFaceValues<dim>
    face_values(const FiniteElementSpace<dim> &fe_space);

  private:
    /** The stiffness (if @p with_stiffness) and the loads' terms of
     * @p cell, whose values @p hp_fe_values holds, into @p cell_matrix and
     * @p cell_rhs (sized here). */
    void
    add_cell_terms(const typename DoFHandler<dim>::active_cell_iterator &cell,
                   const FEValues<dim>   &fe_values,
                   hp::FEFaceValues<dim> &hp_face_values,
                   const bool             with_stiffness,
                   FullMatrix<double>    &cell_matrix,
                   Vector<double>        &cell_rhs) const;


    const FiniteElementSpace<dim> &fe_space;
    const StressModel<dim>        &stress_model;
    const LoadCollection<dim>     &loads;
    const CellHistory<dim>        *cell_history = nullptr;
  };
} // namespace lithostress

#endif

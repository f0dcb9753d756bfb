#ifndef lithostress_discretization_elastic_assembler_h
#define lithostress_discretization_elastic_assembler_h

#include <deal.II/dofs/dof_handler.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/discretization/linear_system.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/material.h>

namespace lithostress
{
  /**
   * Assembles the elasticity system (SPEC §3.1, thesis §3.6): the stiffness
   * ∫ ε(v) : C ε(u) dx of every cell with the moduli of its material, and
   * the contributions of every load (cell and boundary integrals), through
   * the constraints into the distributed matrix and right-hand side. Cells
   * of any active FE index are handled through the displacement field of
   * that index.
   */
  template <int dim>
  class ElasticAssembler
  {
  public:
    ElasticAssembler(const FiniteElementSpace<dim> &fe_space,
                     const MaterialLibrary         &materials,
                     const PlaneState               plane_state,
                     const LoadCollection<dim>     &loads);

    /** Assemble matrix (if @p with_matrix) and right-hand side. */
    void
    assemble(const DoFHandler<dim> &dof_handler,
             LinearSystem<dim>     &system,
             const bool             with_matrix = true) const;

    /** Add the cell stiffness ∫ ε(φ_i) : C ε(φ_j) dx to @p cell_matrix. */
    static void
    add_cell_stiffness(const FEValues<dim>      &fe_values,
                       const ElasticModuli<dim> &moduli,
                       FullMatrix<double>       &cell_matrix);

    /** The moduli of material @p id in the model's plane state. */
    ElasticModuli<dim>
    moduli(const types::material_id id) const;

  private:
    const FiniteElementSpace<dim> &fe_space;
    const MaterialLibrary         &materials;
    const PlaneState               plane_state;
    const LoadCollection<dim>     &loads;
  };
} // namespace lithostress

#endif

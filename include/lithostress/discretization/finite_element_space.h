#ifndef lithostress_discretization_finite_element_space_h
#define lithostress_discretization_finite_element_space_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values_extractors.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/mapping_collection.h>
#include <deal.II/hp/q_collection.h>

#include <lithostress/discretization/cached_mapping.h>

#include <memory>

namespace lithostress
{
  using namespace dealii;

  /**
   * The finite element space of the displacement: an hp::FECollection with
   * one element per displacement field. An unfaulted model has one field,
   * FESystem(FE_Q(p), dim). A faulted model (next issues) has two fields on
   * the two sides of the fault, element f being FE_Q(p)^dim in field f and
   * FE_Nothing^dim in the other (the step-46 idea, see
   * doc/dealii_facts.md), so that assembly, the near-null space and
   * output all go through the field of a cell's active FE index.
   *
   * Also holds the mapping of degree `Mapping degree` (2 by default), used
   * for assembly, errors and output so that curved cells follow their
   * manifolds; it keeps each cell's support points while the mesh stands
   * (cache_mapping_of()).
   */
  template <int dim>
  class FiniteElementSpace
  {
  public:
    FiniteElementSpace(const unsigned int degree,
                       const unsigned int mapping_degree,
                       const unsigned int n_fields = 1);

    const hp::FECollection<dim> &
    fe_collection() const
    {
      return fe;
    }

    const Mapping<dim> &
    mapping() const
    {
      return *mapping_q;
    }

    /** Lets the mapping keep the support points of @p triangulation's
     * cells from one mesh change to the next (CachedMappingQ). */
    void
    cache_mapping_of(const Triangulation<dim> &triangulation)
    {
      mapping_q->attach(triangulation);
    }

    const hp::MappingCollection<dim> &
    mapping_collection() const
    {
      return mappings;
    }

    /** The displacement field of cells with active FE index @p fe_index. */
    unsigned int
    field_of(const unsigned int fe_index) const
    {
      return fe_index;
    }

    /** Extractor of the displacement of field @p field. */
    FEValuesExtractors::Vector
    displacement(const unsigned int field) const
    {
      return FEValuesExtractors::Vector(dim * field);
    }

    unsigned int
    n_fields() const
    {
      return n_displacement_fields;
    }

    unsigned int
    degree() const
    {
      return polynomial_degree;
    }

    /** Gauss quadrature with @p extra points more than degree + 1. */
    hp::QCollection<dim>
    cell_quadrature(const unsigned int extra = 0) const;

    /** Face Gauss quadrature with @p extra points more than degree + 1. */
    hp::QCollection<dim - 1>
    face_quadrature(const unsigned int extra = 0) const;

    /** Support points of the scalar FE_Q(p) in the reference cell, used by
     * the near-null space and output. */
    const std::vector<Point<dim>> &
    unit_support_points() const
    {
      return scalar_support_points;
    }

  private:
    unsigned int                         polynomial_degree;
    unsigned int                         n_displacement_fields;
    hp::FECollection<dim>                fe;
    std::unique_ptr<CachedMappingQ<dim>> mapping_q;
    hp::MappingCollection<dim>           mappings;
    std::vector<Point<dim>>              scalar_support_points;
  };
} // namespace lithostress

#endif

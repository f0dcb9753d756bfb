#ifndef lithostress_loads_density_stripping_h
#define lithostress_loads_density_stripping_h

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <lithostress/loads/load.h>

#include <memory>
#include <vector>

namespace lithostress
{
  /**
   * Density stripping (thesis §7.3; Bott & Dean 1972): the body
   * force −Δρ g ŷ of the density anomaly Δρ = ρ(material) − ρ_ref(depth)
   * relative to a reference density–depth column, given piecewise constant
   * by depth intervals. The stresses computed are then relative to those of
   * the reference (undisturbed) lithosphere. Depth is measured downward from
   * a given elevation (y = 0, sea level, by default). It replaces gravity:
   * the two cannot be combined.
   */
  template <int dim>
  class DensityStripping : public Load<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);
    /** Returns whether a reference column is given. Throws InputError for a
     * column with gaps, overlaps, unsorted or empty intervals, or negative
     * densities. */
    bool
    parse_parameters(ParameterHandler            &prm,
                     const ModelDescription<dim> &model) override;

    bool
    is_body_force() const override
    {
      return true;
    }

    bool
    strips_densities() const override
    {
      return true;
    }

    void
    add_cell_terms(const FEValues<dim>              &fe_values,
                   const FEValuesExtractors::Vector &displacement,
                   const Material                   &material,
                   const ElasticModuli<dim>         &moduli,
                   FullMatrix<double>               &cell_matrix,
                   Vector<double>                   &cell_rhs) const override;

    /** Every vertex of the coarse mesh must lie within the column. */
    void
    check_against_mesh(const Triangulation<dim> &tria,
                       const Mapping<dim>       &mapping) const override;

    std::string
    description() const override;

    /** ρ_ref at @p p (the end intervals continue beyond the column, which
     * check_against_mesh() allows only by a curved boundary's bulge). */
    double
    reference_density(const Point<dim> &p) const;

    /** The reference column's lithostatic pressure at @p p, g ∫ ρ_ref dd
     * from the column's top to the depth of @p p (0 above the top; the
     * deepest interval continued below the column): the pressure that the
     * stripped stresses leave out and that creep and yield laws add. */
    double
    reference_pressure(const Point<dim> &p) const override;

    /** g [m s⁻²]. */
    double acceleration = 9.81;

  private:
    /** Interval bottoms (depth, m, increasing) and densities; the first
     * interval starts at column_top. */
    double              column_top = 0;
    std::vector<double> bottoms, densities;
    /** y of depth zero [m]. */
    double depth_origin = 0;
    double length_scale = 1;

    /**
     * The sub-cell integration of one finite element (add_cell_terms()):
     * FEValues on 16 × 16 Gauss sub-cells, built once per element and
     * mapping degree instead of for every cell a jump of the column
     * crosses (its construction evaluates the element and the mapping at
     * the 1 024 points). It holds its own copy of the element and its own
     * MappingQ of the same degree (which places the points as a
     * CachedMappingQ does, bit for bit), so that it never outlives the
     * objects it reads; members are destroyed from the last, the values
     * first.
     */
    struct SubCellValues
    {
      std::unique_ptr<const FiniteElement<dim>> fe;
      std::unique_ptr<const MappingQ<dim>>      mapping;
      std::unique_ptr<FEValues<dim>>            values;
    };

    /** The sub-cell values for @p fe_values's element and mapping (a
     * MappingQ), made on first use. */
    FEValues<dim> &
    sub_cell_values(const FEValues<dim> &fe_values) const;

    mutable std::vector<SubCellValues> sub_cells;
  };
} // namespace lithostress

#endif

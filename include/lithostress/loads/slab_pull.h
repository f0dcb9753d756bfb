#ifndef lithostress_loads_slab_pull_h
#define lithostress_loads_slab_pull_h

#include <lithostress/base/parsed_expression.h>
#include <lithostress/loads/load.h>
#include <lithostress/loads/time_factor.h>

#include <memory>

namespace lithostress
{
  /**
   * The pull of the subducted slab where the section truncates it (thesis
   * §7.4, doc/subduction.md): a force per unit length F = P (1 / tan I, −1)
   * on a boundary part (the base beneath the slab, A–A), pulling down and
   * down-dip (towards +x) at the dip I, spread over the part by a weight
   * w(x, y) ≥ 0 as the traction t = F w / ∫ w ds.
   *
   * The vertical pull P is either given [N/m] or derived from the model's
   * own load balance: P is then the net upthrust of every other load (the
   * stripped densities, the trench and outer-rise pressures), so that the
   * applied vertical forces sum to zero, as the thesis intends ("so that it
   * balances the forces arising from the isostatically uncompensated load
   * at the trench and outer rise"). LoadCollection::balance() sets it on
   * every new mesh.
   */
  template <int dim>
  class SlabPull : public Load<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);

    /** Parse `Loads/Slab pull`; false if it is not enabled. */
    bool
    parse_parameters(ParameterHandler            &prm,
                     const ModelDescription<dim> &model) override;

    /** Whether the vertical pull is derived from the load balance. */
    bool
    balances_vertical_loads() const override
    {
      return balancing;
    }

    /**
     * Set the vertical pull to balance @p upthrust, the net vertical force
     * [N/m] of all other loads (positive = upwards). InputError if the
     * other loads pull down: a slab pull cannot balance them.
     */
    void
    balance(const double upthrust) override;

    /** The force per unit length F [N/m] on the part at the load's time
     * (the Time factor included). */
    Tensor<1, dim>
    force() const;

    bool
    acts_on_boundary(const types::boundary_id id) const override;

    void
    add_boundary_terms(const FEFaceValues<dim>          &fe_face_values,
                       const types::boundary_id          id,
                       const FEValuesExtractors::Vector &displacement,
                       FullMatrix<double>               &cell_matrix,
                       Vector<double> &cell_rhs) const override;

    /** Integrate the weight over the new mesh. */
    void
    prepare_for_mesh(const Triangulation<dim>  &tria,
                     const Mapping<dim>        &mapping,
                     const Quadrature<dim - 1> &face_quadrature) override;

    std::string
    description() const override;

  private:
    types::boundary_id                     part = 0;
    std::string                            part_name;
    std::unique_ptr<ParsedExpression<dim>> profile;
    double                                 profile_integral = 0;
    bool                                   balancing        = false;
    /** The vertical pull P [N/m] (downwards) and the dip I [rad]. */
    double vertical_pull = 0;
    double dip           = 0;
    /** f(t) on the pull. */
    TimeFactor time_factor;
  };
} // namespace lithostress

#endif

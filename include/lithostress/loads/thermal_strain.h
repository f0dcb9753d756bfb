#ifndef lithostress_loads_thermal_strain_h
#define lithostress_loads_thermal_strain_h

#include <lithostress/base/parsed_expression.h>
#include <lithostress/loads/load.h>

#include <memory>

namespace lithostress
{
  /**
   * Thermal initial strain (thesis §3.8, §7.6.2): a temperature change
   * ΔT(x, y) expands the rock isotropically by ε0 = α_lin ΔT in each of the
   * three directions, α_lin = α (a linear coefficient) or α/3 (a volumetric
   * one) — the reading is an explicit input because the thesis is ambiguous.
   * The stress is σ = C(ε − ε0): in plane strain (ε_zz = 0) the in-plane
   * initial stress is −(3λ + 2μ) ε0 I and σ_zz = λ tr ε − (3λ + 2μ) ε0 =
   * ν(σ_xx + σ_yy) − E ε0; in plane stress it is −E/(1 − ν) ε0 I and σ_zz = 0.
   * Weak form: ∫ ε(v) : C ε(u) dx = ... − ∫ σ0 : ε(v) dx.
   */
  template <int dim>
  class ThermalStrain : public Load<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);
    /** Returns whether a temperature change is given. */
    bool
    parse_parameters(ParameterHandler &prm,
                     const ModelDescription<dim> &) override;

    void
    add_cell_terms(const FEValues<dim>              &fe_values,
                   const FEValuesExtractors::Vector &displacement,
                   const Material                   &material,
                   const ElasticModuli<dim>         &moduli,
                   FullMatrix<double>               &cell_matrix,
                   Vector<double>                   &cell_rhs) const override;

    bool
    has_initial_stress() const override
    {
      return true;
    }

    void
    add_initial_stress(const Point<dim>         &p,
                       const Material           &material,
                       const ElasticModuli<dim> &moduli,
                       SymmetricTensor<2, dim>  &stress,
                       double                   &sigma_zz) const override;

    /**
     * Evaluate Delta T at the support points of Q2 on every owned cell: the
     * points where output and refinement evaluate the stress. A NaN or
     * infinity there is an input error on all ranks before anything is
     * solved or written (assembly checks the quadrature points).
     */
    void
    prepare_for_mesh(const Triangulation<dim>  &tria,
                     const Mapping<dim>        &mapping,
                     const Quadrature<dim - 1> &face_quadrature) override;

    std::string
    description() const override;

    /** The linear initial strain ε0 = α_lin ΔT at @p p. */
    double
    initial_strain(const Point<dim> &p) const;

  private:
    std::unique_ptr<ParsedExpression<dim>> temperature_change;
    /** With `Temperature change = temperature model`: ΔT = T − T_ref of
     * the section's temperature (a closed form of position), else null. */
    const PointwiseTemperature<dim> *temperature           = nullptr;
    double                           reference_temperature = 0;
    /** α as given, and whether it is volumetric (α_lin = α/3). */
    double coefficient = 0;
    bool   volumetric  = false;
  };
} // namespace lithostress

#endif

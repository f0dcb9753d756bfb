#ifndef lithostress_analysis_stress_postprocessor_h
#define lithostress_analysis_stress_postprocessor_h

#include <deal.II/numerics/data_postprocessor.h>

#include <deal.II/fe/mapping.h>
#include <lithostress/materials/material.h>

#include <lithostress/materials/stress_model.h>
#include <lithostress/analysis/griffith_failure.h>

namespace lithostress
{
  /** The in-plane principal stresses σ1 ≥ σ2 and the angle of σ1 from the
   * x axis (radians, in (−π/2, π/2]); tension positive (thesis §2.5.1). */
  struct PrincipalStresses
  {
    double sigma_1, sigma_2, angle_1;
  };

  /** Principal stresses of an in-plane stress tensor (Mohr's circle). */
  PrincipalStresses
  principal_stresses(const SymmetricTensor<2, 2> &stress);

  /**
   * What the stress analysis reports at a point (thesis §2.5.1): principal
   * stresses, the deviatoric stresses relative to the mean of the three
   * principal stresses (thesis DEVST) and the modified Griffith test.
   */
  struct StressAnalysis
  {
    PrincipalStresses principal;
    /** Deviatoric σ_xx, σ_yy, σ_zz, σ_xy. */
    double deviatoric_xx, deviatoric_yy, deviatoric_zz, deviatoric_xy;
    /** Griffith C (1 where not tested), regime (−1 not tested) and fracture
     * angle [degrees]. */
    double degree_of_failure, regime, fracture_angle;
  };

  /**
   * Analyse the stress @p stress at @p p in @p material: the Griffith test
   * is made on the principal stresses plus the lithostatic stress when
   * @p griffith says so (FAIL).
   */
  template <int dim>
  StressAnalysis
  analyse_stress(const StressState<dim> &stress,
                 const Material         &material,
                 const Point<dim>       &p,
                 const GriffithFailure  &griffith);

  /**
   * Turns the finite element solution into the fields written for
   * ParaView: the displacement (the sum of all displacement fields, since
   * FE_Nothing fields are zero), the in-plane stress tensor, σ_zz, the
   * principal stresses σ1 ≥ σ2 with the unit direction of σ1, and the
   * deviatoric stresses relative to the mean of the three principal
   * stresses (thesis DEVST), and the modified Griffith test of the
   * material's tensile strength (degree of failure C, regime 0–3 and the
   * fracture angle in degrees; where T = 0 the test is not made: regime −1, C =
   * 1; doc/griffith.md, with the lithostatic pressure FAIL adds when the model
   * has no full body force), tension positive, evaluated through the model's
   * StressModel (each cell's material, initial strains included).
   */
  template <int dim>
  class StressPostprocessor : public DataPostprocessor<dim>
  {
  public:
    /** @p mapping locates the output points in their cells, where a
     * creep strain is attached to @p stress_model. */
    StressPostprocessor(const StressModel<dim> &stress_model,
                        const Mapping<dim>     &mapping,
                        const unsigned int      n_fields,
                        const GriffithFailure  &griffith);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<dim> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const StressModel<dim> &stress_model;
    const Mapping<dim>     &mapping;
    const unsigned int      n_fields;
    const GriffithFailure  &griffith;
  };
} // namespace lithostress

#endif

#ifndef lithostress_postprocess_stress_postprocessor_h
#define lithostress_postprocess_stress_postprocessor_h

#include <deal.II/numerics/data_postprocessor.h>

#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/material.h>
#include <lithostress/postprocess/griffith_failure.h>

namespace lithostress
{
  /** The in-plane principal stresses σ1 ≥ σ2 and the angle of σ1 from the
   * x axis (radians, in (−π/2, π/2]); tension positive (SPEC §2). */
  struct PrincipalStresses
  {
    double sigma_1, sigma_2, angle_1;
  };

  /** Principal stresses of an in-plane stress tensor (Mohr's circle). */
  PrincipalStresses
  principal_stresses(const SymmetricTensor<2, 2> &stress);

  /**
   * Turns the finite element solution into the fields written for
   * ParaView: the displacement (the sum of all displacement fields, since
   * FE_Nothing fields are zero), the in-plane stress tensor, σ_zz, the
   * principal stresses σ1 ≥ σ2 with the unit direction of σ1, and the
   * deviatoric stresses relative to the mean of the three principal
   * stresses (thesis DEVST), and the modified Griffith test of the
   * material's tensile strength (degree of failure C, regime 0–3 and the
   * fracture angle in degrees; where T = 0 the test is not made: regime −1, C =
   * 1; SPEC §3.6 — the lithostatic pressure that FAIL adds without body forces
   * is not added yet), tension positive, evaluated with the moduli of each
   * cell's material.
   */
  template <int dim>
  class StressPostprocessor : public DataPostprocessor<dim>
  {
  public:
    StressPostprocessor(const MaterialLibrary &materials,
                        const PlaneState       plane_state,
                        const unsigned int     n_fields,
                        const GriffithFailure &griffith);

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
    const MaterialLibrary &materials;
    const PlaneState       plane_state;
    const unsigned int     n_fields;
    const GriffithFailure &griffith;
  };
} // namespace lithostress

#endif

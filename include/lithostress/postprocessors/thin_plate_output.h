#ifndef lithostress_postprocessors_thin_plate_output_h
#define lithostress_postprocessors_thin_plate_output_h

#include <lithostress/analysis/thin_plate_flexure.h>
#include <lithostress/postprocessors/postprocessor.h>

#include <array>
#include <vector>

namespace lithostress
{
  /** The comparison of the last cycle's surface profile with a thin
   * elastic plate on a fluid foundation (thesis §6.1.2;
   * thin_plate_comparison.csv), with `Thin plate comparison/Enabled`. */
  template <int dim>
  class ThinPlateOutput : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler           &prm,
                     const SimulatorAccess<dim> &access) override;

    void
    cycle_finished(const SimulatorAccess<dim> &access,
                   const unsigned int          cycle,
                   ConvergenceStudy           &study,
                   std::ostream               &progress) override;

    void
    finish(const SimulatorAccess<dim> &access) override;

  private:
    ThinPlateFlexure                   thin_plate;
    types::boundary_id                 boundary = numbers::invalid_boundary_id;
    std::vector<std::array<double, 5>> profile;
  };
} // namespace lithostress

#endif

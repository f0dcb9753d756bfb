#ifndef lithostress_analysis_thin_plate_flexure_h
#define lithostress_analysis_thin_plate_flexure_h

#include <deal.II/base/parameter_handler.h>

#include <lithostress/materials/material.h>
#include <lithostress/base/run_log.h>

#include <array>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * Thin elastic plate on a fluid foundation under a line load V (thesis
   * §6.1.2; Turcotte & Schubert §3.17): w(x) = w0 e^{−x/α}
   * (cos x/α + sin x/α) with D = E h³ / 12(1 − ν²) (plane strain),
   * α = (4D / ρ_f g)^{1/4}, w0 = V α³ / 8D; the forebulge crest lies at
   * x = πα with height w0 e^{−π}, the first zero at x = 3πα/4. Compares
   * the finite element surface profile with it: forebulge position and
   * height on both sides of the load, and the deflection away from it.
   */
  class ThinPlateFlexure
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler      &prm,
                     const MaterialLibrary &materials,
                     const double           length_scale,
                     const double           gravity);

    bool enabled = false;

    /** Thin-plate deflection (positive down) at distance @p x from the load. */
    double
    deflection(const double x) const;

    /** Print the comparison for a surface profile (x, y, u_x, u_y) and
     * write it to @p csv_file (empty: no file). */
    void
    report(const std::vector<std::array<double, 5>> &profile,
           RunLog                                   &log,
           const std::string                        &csv_file) const;

    double load_position, line_load, thickness, fluid_density, gravity;
    double rigidity, alpha, w0;
  };
} // namespace lithostress

#endif

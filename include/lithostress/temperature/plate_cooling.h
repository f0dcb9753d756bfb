#ifndef lithostress_temperature_plate_cooling_h
#define lithostress_temperature_plate_cooling_h

#include <lithostress/base/parsed_expression.h>
#include <lithostress/temperature/temperature_model.h>

#include <memory>

namespace lithostress
{
  /**
   * `Temperature/Model = plate cooling`: the conductive cooling of an
   * oceanic lithosphere of age t(x) (Turcotte & Schubert 2014, §4.16
   * and §4.23; Parsons & Sclater 1977). With d the depth below the plate's
   * top (`Depth origin`), T_s and T_m the surface and mantle temperatures
   * and κ the thermal diffusivity, the half-space model (`Plate thickness =
   * 0`) is
   *   T = T_s + (T_m − T_s) erf(d / (2 √(κ t))),
   * and the plate model of thickness L, whose base is held at T_m,
   *   T = T_s + (T_m − T_s) [d/L + (2/π) Σ_n (1/n) e^(−κ n² π² t / L²)
   *       sin(n π d / L)]
   * for 0 ≤ d ≤ L, T_m below it. Above the top T = T_s. Where κ t / L² <
   * 1e-3 the two differ by less than erfc(15.8) of T_m − T_s and the
   * half-space's closed form is taken (the series would need many terms).
   */
  template <int dim>
  class PlateCoolingTemperature : public PointwiseTemperature<dim>
  {
  public:
    /** Declare the subsection `Plate cooling`. */
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const double length_scale) override;

    double
    value(const Point<dim> &p) const override;

    /** The age [s] of the plate above x [m] (`Plate age` at (x, 0));
     * InputError where it is negative. */
    double
    age(const double x) const;

  private:
    std::unique_ptr<ParsedExpression<dim>> plate_age;
    double surface_temperature = 0, mantle_temperature = 0;
    double thickness = 0, diffusivity = 0, depth_origin = 0;
  };
} // namespace lithostress

#endif

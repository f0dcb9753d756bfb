// Unit test of the temperature models (Temperature/Model; doc/equations.md,
// "Temperature"). Checked against what does not repeat the implementation:
//  - every profile solves the heat equation dT/dt = kappa d2T/dd2 (central
//    differences in age, through an age that grows with x, and in depth);
//  - the half-space's thermal thickness, the depth of 90 % of the mantle
//    temperature, is 2 erfinv(0.9) sqrt(kappa t) (Turcotte & Schubert 2014,
//    eq. 4.116: 2.32 sqrt(kappa t));
//  - the plate model's series equals the half-space's erf where the plate is
//    young and is the linear conductive profile where it is old;
//  - the surface heat flow of GDH1 (Stein & Stein 1992: T_m = 1450 C, L = 95
//    km, kappa = 0.804e-6 m^2/s, k = 3.138 W/m/K): 510 t^-1/2 mW/m^2 for a
//    young plate, 48 + 96 exp(-0.0278 t) for an old one (t in Myr; their
//    coefficients are rounded to 2-3 digits, hence 0.5 %);
//  - bad input is refused naming its entry.
// Prints one "ok ..." or "FAIL ..." line per check and returns non-zero on a
// failure.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <lithostress/base/input_error.h>
#include <lithostress/temperature/plate_cooling.h>
#include <lithostress/temperature/temperature_model.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <string>

using namespace lithostress;

namespace
{
  unsigned int n_failed = 0;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok   " : "FAIL ") << what << std::endl;
    if (!ok)
      ++n_failed;
  }

  constexpr double seconds_per_myr = 1e6 * 365.25 * 24 * 3600;

  /** The model that @p text selects (lengths in km). */
  std::unique_ptr<TemperatureModel<2>>
  make(const std::string &text)
  {
    ParameterHandler prm;
    TemperatureSelector<2>::declare_parameters(prm);
    prm.parse_input_from_string(text);
    return TemperatureSelector<2>::create(prm, 1e3);
  }

  double
  at(const TemperatureModel<2> &model, const double x, const double y)
  {
    return dynamic_cast<const PointwiseTemperature<2> &>(model).value(
      Point<2>(x, y));
  }

  /** The message of the InputError that making @p text throws. */
  std::string
  refusal(const std::string &text)
  {
    try
      {
        auto model = make(text);
        at(*model, 1e4, -1e4);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  std::string
  plate(const std::string &age, const std::string &more = "")
  {
    return "subsection Temperature\n set Model = plate cooling\n"
           " subsection Plate cooling\n  set Plate age = " +
           age + "\n" + more + " end\nend\n";
  }

  /** The largest |dT/dt - kappa T_dd| relative to |kappa T_dd| at depths
   * @p depths [m] of a model whose age is x * 1e-3 Myr (x in m). */
  double
  heat_equation_residual(const TemperatureModel<2> &model,
                         const double               x,
                         const std::vector<double> &depths)
  {
    const double kappa = 1e-6, hx = 5, hd = 5;
    const double dage_dx = 1e-3 * seconds_per_myr;
    double       worst   = 0;
    for (const double d : depths)
      {
        const double dT_dt =
          (at(model, x + hx, -d) - at(model, x - hx, -d)) / (2 * hx) / dage_dx;
        const double T_dd = (at(model, x, -d + hd) - 2 * at(model, x, -d) +
                             at(model, x, -d - hd)) /
                            (hd * hd);
        worst =
          std::max(worst,
                   std::abs(dT_dt - kappa * T_dd) / std::abs(kappa * T_dd));
      }
    return worst;
  }

  /** The surface heat flow k dT/dd at the top [W/m^2] (second order). */
  double
  heat_flow(const TemperatureModel<2> &model, const double x, const double k)
  {
    const double h = 2;
    return k *
           (-3 * at(model, x, 0) + 4 * at(model, x, -h) -
            at(model, x, -2 * h)) /
           (2 * h);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  check(make("") == nullptr, "Model = none gives no temperature");

  {
    auto f = make("subsection Temperature\n set Model = function\n"
                  " subsection Function\n  set Expression = Ts + g*(-y)\n"
                  "  set Constants = Ts=273, g=0.025\n end\nend\n");
    check(std::abs(at(*f, 0, -2e4) - 773) < 1e-10,
          "function: 273 K + 25 K/km at 20 km depth is 773 K");
  }

  // Half-space cooling, the age growing with x: 1 Myr per km.
  const std::string half_space = plate("x*1e-3");
  auto              hs         = make(half_space);
  check(at(*hs, 5e4, 0) == 273 && at(*hs, 5e4, 1e3) == 273,
        "half-space: the surface temperature at and above the top");
  check(at(*hs, 0, -1e3) == 1623, "half-space: age 0 is the mantle's");
  {
    const double t = 50 * seconds_per_myr, kappa = 1e-6;
    double       lo = 0, hi = 5e5;
    for (int i = 0; i < 100; ++i)
      {
        const double mid                                  = 0.5 * (lo + hi);
        (at(*hs, 5e4, -mid) < 273 + 0.9 * 1350 ? lo : hi) = mid;
      }
    const double expected = 2 * 1.1630871536766743 * std::sqrt(kappa * t);
    std::cout << "     thermal thickness at 50 Myr " << lo / 1e3
              << " km, 2 erfinv(0.9) sqrt(kappa t) = " << expected / 1e3
              << " km" << std::endl;
    check(std::abs(lo - expected) < 1e-6 * expected,
          "half-space: thermal thickness 2.3262 sqrt(kappa t) to 1e-6");
  }
  {
    const double r =
      heat_equation_residual(*hs, 5e4, {2e3, 1e4, 3e4, 6e4, 1e5});
    std::cout << "     half-space heat-equation residual " << r << std::endl;
    check(r < 1e-4, "half-space solves the heat equation (to 1e-4)");
  }

  // The plate model, L = 125 km.
  auto pl = make(plate("x*1e-3", "  set Plate thickness = 125\n"));
  check(at(*pl, 6e4, -125e3) == 1623 && at(*pl, 6e4, -2e5) == 1623 &&
          std::abs(at(*pl, 6e4, -124.999e3) - 1623) < 0.1,
        "plate: the mantle temperature at and below its base, continuous");
  {
    const double r =
      heat_equation_residual(*pl, 6e4, {2e3, 2e4, 6e4, 1e5, 1.2e5});
    std::cout << "     plate heat-equation residual at 60 Myr " << r
              << std::endl;
    check(r < 1e-4, "plate solves the heat equation (to 1e-4)");
  }
  {
    // 2 Myr: kappa t / L^2 = 4e-3, so the series is summed; the base is
    // erfc(7.9) away.
    double worst = 0;
    for (const double d : {1e3, 5e3, 1e4, 2e4, 4e4})
      worst = std::max(worst, std::abs(at(*pl, 2e3, -d) - at(*hs, 2e3, -d)));
    std::cout << "     plate - half-space at 2 Myr: " << worst << " K"
              << std::endl;
    check(worst < 1e-9 * 1350, "plate: a young plate is the half-space");
    double linear = 0;
    for (const double d : {1e3, 3e4, 6e4, 1.2e5})
      linear =
        std::max(linear, std::abs(at(*pl, 1e7, -d) - (273 + 1350 * d / 125e3)));
    check(linear < 1e-9 * 1350, "plate: an old plate conducts linearly");
  }

  // GDH1 (Stein & Stein 1992).
  {
    auto gdh1 =
      make(plate("x*1e-3",
                 "  set Plate thickness = 95\n  set Thermal diffusivity = "
                 "0.804e-6\n  set Surface temperature = 273\n"
                 "  set Mantle temperature = 1723\n"));
    const double k     = 3.138;
    const double young = 1e3 * heat_flow(*gdh1, 25e3, k);
    const double old   = 1e3 * heat_flow(*gdh1, 100e3, k);
    std::cout << "     GDH1 heat flow at 25 Myr " << young
              << " mW/m^2 (Stein & Stein: 510/sqrt(25) = 102), at 100 Myr "
              << old << " (48 + 96 exp(-2.78) = " << 48 + 96 * std::exp(-2.78)
              << ")" << std::endl;
    check(std::abs(young - 102) < 5e-3 * 102,
          "GDH1: 510 t^-1/2 mW/m^2 at 25 Myr to 0.5 %");
    check(std::abs(old - (48 + 96 * std::exp(-2.78))) <
            5e-3 * (48 + 96 * std::exp(-2.78)),
          "GDH1: 48 + 96 exp(-0.0278 t) mW/m^2 at 100 Myr to 0.5 %");
  }

  const auto names = [](const std::string &message, const std::string &entry) {
    std::cout << "     " << message << std::endl;
    return message.find(entry) != std::string::npos;
  };
  check(names(refusal(plate("-5")), "Temperature/Plate cooling/Plate age"),
        "a negative age is refused naming Plate age");
  check(names(refusal(plate("")), "Temperature/Plate cooling/Plate age"),
        "an empty age is refused naming Plate age");
  check(names(refusal(plate("10", "  set Thermal diffusivity = 0\n")),
              "Thermal diffusivity"),
        "a zero diffusivity is refused");
  check(names(refusal(plate("10", "  set Mantle temperature = 200\n")),
              "Mantle temperature"),
        "a mantle colder than the surface is refused");
  check(names(refusal("subsection Temperature\n set Model = function\n"
                      " subsection Function\n  set Expression = 300 + y\n"
                      " end\nend\n"),
              "Temperature/Function/Expression"),
        "a temperature at or below 0 K is refused naming the expression");
  check(names(refusal("subsection Temperature\n set Model = function\nend\n"),
              "Temperature/Function/Expression"),
        "an empty expression is refused");

  std::cout << (n_failed == 0 ? "all checks passed" : "FAILED") << std::endl;
  return n_failed == 0 ? 0 : 1;
}

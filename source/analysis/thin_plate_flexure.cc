#include <deal.II/base/numbers.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>
#include <lithostress/analysis/thin_plate_flexure.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace lithostress
{
  void
  ThinPlateFlexure::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Thin plate comparison");
    prm.declare_entry("Enabled",
                      "false",
                      Patterns::Bool(),
                      "Compare the surface profile with a thin elastic plate "
                      "on a fluid foundation (needs Output/Surface profile "
                      "boundary); uses the first material's E and nu.");
    prm.declare_entry("Load position",
                      "500",
                      Patterns::Double(),
                      "x of the line load [length unit].");
    prm.declare_entry("Line load",
                      "2e12",
                      Patterns::Double(0),
                      "Magnitude V of the downward line load [N/m].");
    prm.declare_entry("Plate thickness",
                      "20",
                      Patterns::Double(0),
                      "Elastic thickness h [length unit].");
    prm.declare_entry("Fluid density",
                      "2900",
                      Patterns::Double(0),
                      "Density of the fluid foundation [kg/m^3].");
    prm.leave_subsection();
  }

  void
  ThinPlateFlexure::parse_parameters(ParameterHandler      &prm,
                                     const MaterialLibrary &materials,
                                     const double           scale,
                                     const double           g)
  {
    prm.enter_subsection("Thin plate comparison");
    enabled       = prm.get_bool("Enabled");
    load_position = prm.get_double("Load position") * scale;
    line_load     = prm.get_double("Line load");
    thickness     = prm.get_double("Plate thickness") * scale;
    fluid_density = prm.get_double("Fluid density");
    gravity       = g;
    prm.leave_subsection();
    if (!enabled)
      return;
    if (!(thickness > 0 && fluid_density > 0 && gravity > 0))
      throw_input_error("Thin plate comparison",
                        "plate thickness, fluid density and gravity must be "
                        "positive");
    const Material &m = materials.materials().front();
    rigidity          = m.youngs_modulus * std::pow(thickness, 3) /
               (12 * (1 - m.poissons_ratio * m.poissons_ratio));
    alpha = std::pow(4 * rigidity / (fluid_density * gravity), 0.25);
    w0    = line_load * std::pow(alpha, 3) / (8 * rigidity);
  }

  double
  ThinPlateFlexure::deflection(const double x) const
  {
    const double s = std::abs(x) / alpha;
    return w0 * std::exp(-s) * (std::cos(s) + std::sin(s));
  }

  void
  ThinPlateFlexure::report(const std::vector<std::array<double, 5>> &profile,
                           RunLog                                   &log,
                           const std::string &csv_file) const
  {
    std::ostringstream csv;
    csv << "quantity,finite_element,thin_plate\n" << std::setprecision(12);
    std::ostringstream out;
    out << std::fixed << std::setprecision(2);
    out << "\nThin-plate comparison (thesis §6.1.2): D = " << std::scientific
        << std::setprecision(4) << rigidity << " N m, alpha = " << std::fixed
        << std::setprecision(2) << alpha / 1e3 << " km, w0 = " << w0 << " m\n";
    out << "  forebulge       distance from load [km]   height [m]\n";
    out << "  thin plate      " << std::setw(10) << numbers::PI * alpha / 1e3
        << "           " << std::setw(10) << w0 * std::exp(-numbers::PI)
        << '\n';
    for (const int side : {-1, 1})
      {
        double best_x = 0, best_u = -1e300;
        for (const auto &row : profile)
          {
            const double d = (row[0] - load_position) * side;
            if (d > 0.25 * alpha && row[3] > best_u)
              best_u = row[3], best_x = d;
          }
        const std::string name = side < 0 ? "left" : "right";
        csv << "forebulge_distance_" << name << "_m," << best_x << ','
            << numbers::PI * alpha << '\n'
            << "forebulge_height_" << name << "_m," << best_u << ','
            << w0 * std::exp(-numbers::PI) << '\n';
        out << "  FE " << (side < 0 ? "left " : "right") << "        "
            << std::setw(10) << best_x / 1e3 << "           " << std::setw(10)
            << best_u << "  (" << std::setprecision(1)
            << 100 * (best_u / (w0 * std::exp(-numbers::PI)) - 1)
            << " % in height)\n"
            << std::setprecision(2);
      }
    out << "  deflection away from the load (positive down):\n"
        << "    distance [km]   thin plate [m]   FE [m]\n";
    for (const double d : {0.5, 1.0, 2.0, 3.0, 4.0})
      {
        const double x = load_position + d * alpha;
        // Linear interpolation in the sorted profile.
        for (unsigned int k = 0; k + 1 < profile.size(); ++k)
          if (profile[k][0] <= x && profile[k + 1][0] >= x)
            {
              const double t =
                (x - profile[k][0]) / (profile[k + 1][0] - profile[k][0]);
              const double u =
                -((1 - t) * profile[k][3] + t * profile[k + 1][3]);
              csv << "deflection_at_" << d << "_alpha_m," << u << ','
                  << deflection(d * alpha) << '\n';
              out << "    " << std::setw(12) << d * alpha / 1e3 << "   "
                  << std::setw(14) << deflection(d * alpha) << "   "
                  << std::setw(8) << u << '\n';
              break;
            }
      }
    log << out.str();
    if (!csv_file.empty())
      {
        write_file_atomically(csv_file, csv.str());
      }
  }
} // namespace lithostress

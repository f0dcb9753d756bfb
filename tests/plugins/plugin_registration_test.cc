// Unit test of the plug-in registry (base/plugin_registry.h) through the
// whole program: a rock law and a postprocessor defined and registered in
// this file only, each by its one registration line, are chosen and called
// by a .prm run through the program's own path (ParameterFile::read, the
// Simulator's constructor, run()), exactly as app/main.cc runs a model.
//
// The rock law, `scaled elasticity`, is the material's isotropic
// elasticity with its stiffness multiplied by an entry of its own,
// `Stiffness factor` (declared by the law in every material's subsection).
// The patch test: a block with the displacement u = (e1 x, e2 y) prescribed
// on all four sides. Q2 elements hold it exactly, so the strain is uniform
// and the stress at every point is f (λ tr ε I + 2 μ ε), σ_zz = f λ tr ε
// (plane strain), to round-off: checked at the report points against the
// closed form, relative 1e-9 (the CG tolerance of 1e-12 bounds the error of
// the displacement; with f = 3 an unscaled law would give a third of these
// stresses). The toy postprocessor records what it is given at the end of
// each cycle: it must be called once per cycle with the solution of the
// patch test. And the registry lists the law where the documentation reads
// it: `--print-parameters` shows it and its own entry.
//
// Prints one "ok ..." or "FAIL ..." line per check and returns non-zero on
// a failure.

#include <deal.II/base/mpi.h>

#include <lithostress/base/parameter_file.h>
#include <lithostress/materials/elastic_rheology.h>
#include <lithostress/postprocessors/postprocessor.h>
#include <lithostress/simulator/simulator.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace lithostress;

namespace
{
  unsigned int n_failed = 0;

  void
  check(const bool ok, const std::string &what)
  {
    std::cout << (ok ? "ok " : "FAIL ") << what << std::endl;
    if (!ok)
      ++n_failed;
  }

  /** Isotropic elasticity with its stiffness scaled by `Stiffness factor`:
   * ElasticRheology given the scaled Young's modulus. */
  template <int dim>
  class ScaledElasticity : public ElasticRheology<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Stiffness factor",
                        "1",
                        Patterns::Double(0),
                        "scaled elasticity: the factor on the stiffness.");
    }

    void
    parse_parameters(ParameterHandler &prm,
                     const Material   &material,
                     const PlaneState  plane_state) override
    {
      Material scaled = material;
      scaled.youngs_modulus *= prm.get_double("Stiffness factor");
      ElasticRheology<dim>::parse_parameters(prm, scaled, plane_state);
    }
  };

  /** What the toy postprocessor saw: the cycles it was called for and the
   * largest |u_x| of the solution at the last one. */
  struct Probe
  {
    std::vector<unsigned int> cycles;
    double                    largest_u_x = 0;
  } probe;

  template <int dim>
  class CycleProbe : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {
    }

    void
    cycle_finished(const SimulatorAccess<dim> &access,
                   const unsigned int          cycle,
                   ConvergenceStudy &,
                   std::ostream &) override
    {
      probe.cycles.push_back(cycle);
      probe.largest_u_x = access.solution.linfty_norm();
    }
  };
} // namespace

LITHOSTRESS_REGISTER_RHEOLOGY(ScaledElasticity,
                              "scaled elasticity",
                              "a test law: elasticity times Stiffness factor")
LITHOSTRESS_REGISTER_POSTPROCESSOR(CycleProbe,
                                   "cycle probe",
                                   "a test probe of each cycle",
                                   1000)

namespace
{
  const double e1 = 2e-4, e2 = -1e-4, factor = 3, E = 1e11, nu = 0.25;

  /** The patch test's model: a 10 × 5 km block, two refinement cycles. */
  std::string
  model(const std::string &directory)
  {
    std::ostringstream prm;
    prm << "set Output directory = " << directory << "\n"
        << "subsection Geometry\n"
           "  set Model = rectangular block\n"
           "  set Length unit = km\n"
           "  subsection Rectangular block\n"
           "    set X extent = 0, 10\n"
           "    set Y extent = 0, 5\n"
           "    set Cells = 2, 1\n"
           "  end\n"
           "end\n"
           "subsection Materials\n"
           "  set Names = rock\n"
           "  subsection rock\n"
           "    set Material id = 0\n"
           "    set Young's modulus = "
        << E << "\n    set Poisson's ratio = " << nu
        << "\n"
           "    set Rheology = scaled elasticity\n"
           "    set Stiffness factor = "
        << factor << "\n  end\nend\n"
        << "subsection Boundary conditions\n"
           "  set Prescribed displacement parts = left, right, base, top\n";
    for (const char *part : {"left", "right", "base", "top"})
      prm << "  subsection " << part
          << "\n    set x = e1 * x\n    set y = e2 * y\n"
             "    set Constants = e1="
          << e1 << ", e2=" << e2 << "\n  end\n";
    prm << "end\n"
           "subsection Solver\n"
           "  set Relative tolerance = 1e-12\n"
           "end\n"
           "subsection Mesh refinement\n"
           "  set Number of cycles = 2\n"
           "end\n"
           "subsection Output\n"
           "  set Write ParaView files = false\n"
           "  subsection Figures\n"
           "    set Enabled = false\n"
           "  end\n"
           "end\n"
           "subsection Convergence study\n"
           "  set Points = 3, 2; 7.5, 4\n"
           "end\n";
    return prm.str();
  }

  void
  declare(ParameterHandler &prm, ParameterHandler *first_pass)
  {
    Simulator<2>::declare_parameters(prm, first_pass);
  }

  /** The rows of @p file (a CSV with a header) as name → values. */
  std::vector<std::map<std::string, double>>
  read_csv(const std::string &file)
  {
    std::ifstream                              in(file);
    std::string                                line;
    std::vector<std::string>                   names;
    std::vector<std::map<std::string, double>> rows;
    if (std::getline(in, line))
      names = Utilities::split_string_list(line, ',');
    while (std::getline(in, line))
      {
        const auto values = Utilities::split_string_list(line, ',');
        std::map<std::string, double> row;
        for (unsigned int c = 0; c < names.size() && c < values.size(); ++c)
          row[names[c]] = std::atof(values[c].c_str());
        rows.push_back(row);
      }
    return rows;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  check(RheologyRegistry<2>::has("scaled elasticity") &&
          RheologyRegistry<2>::has("elastic") &&
          RheologyRegistry<2>::has("maxwell"),
        "the registry holds the built-in rock laws and the test's own");
  {
    ParameterHandler prm;
    declare(prm, nullptr);
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::PRM);
    check(text.str().find("scaled elasticity") != std::string::npos &&
            text.str().find("Stiffness factor") != std::string::npos,
          "--print-parameters shows the test law and its own entry");
  }

  const std::string directory = "output_plugin_registration";
  const std::string file      = "plugin_registration.prm";
  if (root)
    {
      std::filesystem::remove_all(directory);
      std::ofstream(file) << model(directory);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  {
    ParameterHandler prm;
    ParameterFile::read(file, {}, declare, prm);
    Simulator<2> simulator(MPI_COMM_WORLD, prm);
    simulator.run();
  }

  check(probe.cycles == std::vector<unsigned int>{0, 1},
        "the registered postprocessor is called once per cycle (" +
          std::to_string(probe.cycles.size()) + " calls)");
  // The largest |u| of the field is at a corner: |e1| · 10 km = 2 m.
  check(std::abs(probe.largest_u_x - std::abs(e1) * 1e4) < 1e-9,
        "it is given the patch test's solution (largest |u| " +
          std::to_string(probe.largest_u_x) + " m against 2 m)");

  if (root)
    {
      const double mu     = factor * E / (2 * (1 + nu));
      const double lambda = factor * E * nu / ((1 + nu) * (1 - 2 * nu));
      const double tr     = e1 + e2;
      const double sxx    = lambda * tr + 2 * mu * e1,
                   syy    = lambda * tr + 2 * mu * e2;
      const double szz    = lambda * tr;
      const auto   rows   = read_csv(directory + "/point_values.csv");
      double       worst  = rows.empty() ? 1.0 : 0.0;
      for (const auto &row : rows)
        {
          worst = std::max(worst, std::abs(row.at("sigma_xx") - sxx) / sxx);
          worst = std::max(worst, std::abs(row.at("sigma_yy") - syy) / sxx);
          worst = std::max(worst, std::abs(row.at("sigma_zz") - szz) / sxx);
          worst = std::max(worst, std::abs(row.at("sigma_xy")) / sxx);
        }
      std::ostringstream what;
      what << "the stress at the report points is the scaled law's f C eps ("
           << rows.size() << " rows, largest relative error " << std::scientific
           << worst << ")";
      check(rows.size() == 2 && worst < 1e-9, what.str());
    }
  return n_failed == 0 ? 0 : 1;
}

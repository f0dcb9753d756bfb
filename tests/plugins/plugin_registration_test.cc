// Unit test of the plug-in registry (base/plugin_registry.h) through the
// whole program: a geometry, rock laws, a fault law and a postprocessor
// defined and registered in this file only, each by its one registration
// line, are
// chosen and called by .prm runs through the program's own path
// (ParameterFile::read, the Simulator's constructor, run()), exactly as
// app/main.cc runs a model.
//
// The rock law, `scaled elasticity`, is the material's isotropic
// elasticity with its stiffness multiplied by an entry of its own,
// `Stiffness factor` (declared by the law in every material's subsection).
// The patch test: a block with the displacement u = (e1 x, e2 y) prescribed
// on all four sides, made by the test's geometry `skewed block`, a 10 x 5
// parallelogram whose top is shifted by its own entry `Skew` (1 km here).
// Its cells are parallelograms, whose mapping is affine: Q2 elements hold
// the linear displacement exactly, so the strain is uniform
// and the stress at every point is f (λ tr ε I + 2 μ ε), σ_zz = f λ tr ε
// (plane strain), to round-off: checked at the report points against the
// closed form, relative 1e-9 (the CG tolerance of 1e-12 bounds the error of
// the displacement; with f = 3 an unscaled law would give a third of these
// stresses). The toy postprocessor records what it is given at the end of
// each cycle: it must be called once per cycle with the solution of the
// patch test. And the registry lists the law where the documentation reads
// it: `--print-parameters` shows it and its own entry.
//
//
// The fault law, `stiffening spring`, is nonlinear: t_s = k_s w_s + c w_s³,
// t_n = k_n w_n, with its own entry `Cubic stiffness` c, and it keeps a
// named history of two components, the largest |w_s| and |t_s| it has
// carried. The patch test is tests/faults/elastic_fault_shear.prm's: a
// block with a vertical fault, the left side fixed and a uniform shear
// stress tau on the other sides. The fault carries tau at every point, so
// its slip is the real root of k_s w + c w³ = tau, the same at every point:
// with k_s = 1e7 Pa/m, c = 1e7 Pa/m³ and tau = 1e7 Pa, w + w³ = 1 m, w =
// 0.6823278 m (a linear spring would slip 1 m). The sliding solver's Newton
// method solves it to a residual of 1e-12 of the load, so slip and history
// agree with the root to 1e-8 relative (the error is the solver tolerances
// amplified by the block's conditioning, 4e-11 measured; a linear spring's
// slip is 47 % off). The
// postprocessor reads the committed history of the toy law at every
// interface point: its two components must be |w| and tau.
//
//
// The third law, `graded elasticity`, has a tangent that varies in space:
// E(x) = E (1 + a x) with ν = 0 (Rheology::uniform_tangent() false), so
// the matrix assembly and the matrix-free operator take its tangent at
// each quadrature point. A bar 0 < x < L = 10 km, 1 km high, fixed on the
// left and pulled by σ0 on the right, with a = 1/L: the stress is σxx =
// σ0 everywhere and u_x = σ0 ln(1 + a x) / (E a), u_y = 0 (ν = 0: no
// contraction, so the fixed left side and the free top and base are
// exact). Q2 does not hold the logarithm, so u_x at x = 7.5 km must
// converge: through the direct solver (assembled) and the matrix-free
// multigrid, three cycles of global refinement each, the error must fall
// by at least 8 per cycle (Q2's h³; the probe is a node, where it
// converges as h⁴: measured 15.5 and 15.9) and be below 1e-6 of u_x on
// the finest mesh; on an adaptive mesh (three cycles) it must not grow
// from cycle to cycle and fall at least 4 times (measured 6.2). A
// per-material tangent would give u_x = σ0 x / E, 34 % off. With the
// law's `Stiffness anisotropy` b = 1 (σxx gains b E(x) εxx: a tangent
// that is not isotropic) the direct solver and the matrix-free multigrid
// (whose operator then stores the whole tangent at each point, its levels
// each material's isotropic moduli) must give u_x/(1 + b) to the same
// tolerances.
//
// Prints one "ok ..." or "FAIL ..." line per check and returns non-zero on
// a failure.

#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>

#include <lithostress/faults/interface_law.h>
#include <lithostress/geometry/geometry_model.h>
#include <lithostress/materials/elastic_rheology.h>
#include <lithostress/postprocessors/postprocessor.h>
#include <lithostress/simulator/simulator.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
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

  /** Elasticity with E(x) = E (1 + a x), a = `Stiffness gradient`: a
   * tangent that varies from point to point. */
  template <int dim>
  class GradedElasticity : public Rheology<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Stiffness gradient",
                        "0",
                        Patterns::Double(),
                        "graded elasticity: a [1/m] of E(x) = E (1 + a x).");
      prm.declare_entry("Stiffness anisotropy",
                        "0",
                        Patterns::Double(0),
                        "graded elasticity: b of the extra stiffness "
                        "b E(x) along x (sigma_xx += b E eps_xx).");
    }

    void
    parse_parameters(ParameterHandler &prm,
                     const Material   &m,
                     const PlaneState  plane_state) override
    {
      gradient   = prm.get_double("Stiffness gradient");
      anisotropy = prm.get_double("Stiffness anisotropy");
      material   = m;
      plane      = plane_state;
      base.emplace(m, plane_state);
    }

    const ElasticModuli<dim> &
    elastic_moduli() const override
    {
      return *base;
    }

    const ElasticModuli<dim> &
    step_moduli() const override
    {
      return *base;
    }

    void
    set_time_step(const double, const double) override
    {
    }

    bool
    uniform_tangent() const override
    {
      return false;
    }

    StressState<dim>
    stress(const RheologyInputs<dim> &in) const override
    {
      const ElasticModuli<dim> moduli = at(in.position);
      StressState<dim>         s;
      s.in_plane = moduli.stress(in.strain) + in.initial_stress.in_plane;
      s.in_plane[0][0] += anisotropy * E_at(in.position) * in.strain[0][0];
      s.zz = moduli.sigma_zz(in.strain) + in.initial_stress.zz;
      return s;
    }

    void
    evaluate(const RheologyInputs<dim> &in,
             RheologyOutputs<dim>      &out) const override
    {
      out.stress  = stress(in);
      out.tangent = at(in.position).stiffness();
      out.tangent[0][0][0][0] += anisotropy * E_at(in.position);
      out.history.clear();
      out.history_rate.clear();
    }

  private:
    double
    E_at(const Point<dim> &p) const
    {
      return material.youngs_modulus * (1 + gradient * p[0]);
    }

    ElasticModuli<dim>
    at(const Point<dim> &p) const
    {
      Material m       = material;
      m.youngs_modulus = E_at(p);
      return ElasticModuli<dim>(m, plane);
    }

    double                            gradient = 0, anisotropy = 0;
    Material                          material;
    PlaneState                        plane = PlaneState::plane_strain;
    std::optional<ElasticModuli<dim>> base;
  };

  /** A nonlinear spring with its own history: t_s = k_s w_s + c w_s³,
   * t_n = k_n w_n; the history is the largest |w_s| and |t_s| so far. */
  template <int dim>
  class StiffeningSpring : public InterfaceLaw<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Cubic stiffness",
                        "0",
                        Patterns::Double(0),
                        "stiffening spring: c [Pa/m^3].");
    }

    void
    parse_parameters(ParameterHandler &prm,
                     const std::string &,
                     const GravityField &,
                     const double) override
    {
      k_s = prm.get_double("Shear stiffness");
      k_n = prm.get_double("Normal stiffness");
      c   = prm.get_double("Cubic stiffness");
    }

    std::vector<std::string>
    history_names() const override
    {
      return {"peak slip", "peak shear traction"};
    }

    bool
    has_face_terms() const override
    {
      return true;
    }

    bool
    nonlinear() const override
    {
      return true;
    }

    Tensor<2, 2>
    stuck_stiffness() const override
    {
      Tensor<2, 2> K;
      K[0][0] = k_s;
      K[1][1] = k_n;
      return K;
    }

    InterfaceResponse
    predictor(const InterfaceLawInputs &in) const override
    {
      InterfaceResponse r;
      r.tangent         = stuck_stiffness();
      r.shear_traction  = k_s * in.shear_jump;
      r.normal_traction = k_n * in.normal_jump;
      r.history.assign(in.history.begin(), in.history.end());
      return r;
    }

    InterfaceResponse
    evaluate(const InterfaceLawInputs &in) const override
    {
      const double      w = in.shear_jump;
      InterfaceResponse r;
      r.shear_traction  = k_s * w + c * w * w * w;
      r.normal_traction = k_n * in.normal_jump;
      r.tangent[0][0]   = k_s + 3 * c * w * w;
      r.tangent[1][1]   = k_n;
      r.history         = {std::max(in.history[0], std::abs(w)),
                           std::max(in.history[1], std::abs(r.shear_traction))};
      return r;
    }

  private:
    double k_s = 0, k_n = 0, c = 0;
  };

  /** A 10 × 5 (length units) block of 2 × 1 cells whose top is shifted by
   * `Skew` in x: a geometry of the test's own (the worked example of
   * doc/architecture.md, "Adding a geometry"). */
  template <int dim>
  class SkewedBlock : public GeometryModel<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Skewed block");
      prm.declare_entry("Skew",
                        "0",
                        Patterns::Double(),
                        "Shift of the top in x [length unit].");
      prm.leave_subsection();
    }

    void
    parse_parameters(ParameterHandler &prm, const double length_scale) override
    {
      prm.enter_subsection("Skewed block");
      skew = prm.get_double("Skew") * length_scale;
      prm.leave_subsection();
      length = 10 * length_scale;
      height = 5 * length_scale;
      if (!(std::abs(skew) < length))
        throw_input_error("Geometry/Skewed block/Skew",
                          "must be shorter than the block");
    }

    /** Boundary ids 0-3 for left, right, base, top (colorized), material
     * id 0. */
    void
    create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &tria) const override
    {
      GridGenerator::subdivided_hyper_rectangle(
        tria, {2, 1}, Point<dim>(), Point<dim>(length, height), true);
      const double s = skew / height;
      GridTools::transform(
        [s](const Point<dim> &p) { return Point<dim>(p[0] + s * p[1], p[1]); },
        tria);
      // Colorizing also numbers the cells: one material, id 0.
      for (const auto &cell : tria.active_cell_iterators())
        cell->set_material_id(0);
    }

    std::map<std::string, types::boundary_id>
    boundary_parts() const override
    {
      return {{"left", 0}, {"right", 1}, {"base", 2}, {"top", 3}};
    }

    std::string
    mesh_entry() const override
    {
      return "Geometry/Skewed block";
    }

  private:
    double skew = 0, length = 0, height = 0;
  };

  /** What the toy postprocessor saw: the cycles it was called for, the
   * largest |u_x| of the solution at the last one, and the faults'
   * committed history there (its names and each point's values). */
  struct Probe
  {
    std::vector<unsigned int>        cycles;
    double                           largest_u_x = 0;
    std::vector<std::string>         history_names;
    std::vector<std::vector<double>> history;
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
      probe.history.clear();
      if (access.faults.active())
        {
          probe.history_names = access.faults.law(0).history_names();
          for (unsigned int i = 0; i < access.fault_history.size(); ++i)
            {
              const auto h = access.fault_history.committed(i);
              probe.history.emplace_back(h.begin(), h.end());
            }
        }
    }
  };
} // namespace

LITHOSTRESS_REGISTER_GEOMETRY(SkewedBlock,
                              "skewed block",
                              "a test geometry: a parallelogram")
LITHOSTRESS_REGISTER_RHEOLOGY(ScaledElasticity,
                              "scaled elasticity",
                              "a test law: elasticity times Stiffness factor")
LITHOSTRESS_REGISTER_RHEOLOGY(GradedElasticity,
                              "graded elasticity",
                              "a test law: E grows linearly with x")
LITHOSTRESS_REGISTER_INTERFACE_LAW(StiffeningSpring,
                                   "stiffening spring",
                                   "a test law: a cubic spring",
                                   1000)
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
           "  set Model = skewed block\n"
           "  set Length unit = km\n"
           "  subsection Skewed block\n"
           "    set Skew = 1\n"
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

  const double k_s = 1e7, cubic = 1e7, tau = 1e7;

  /** The fault and bar models' fixed left side and output without files
   * beyond the CSVs the checks read. */
  const char *const fixed_left_side =
    "subsection Boundary conditions\n"
    "  set Prescribed displacement parts = left\n"
    "  subsection left\n"
    "    set x = 0\n"
    "    set y = 0\n"
    "  end\n"
    "end\n";
  const char *const quiet_output = "subsection Output\n"
                                   "  set Write ParaView files = false\n"
                                   "  set Force balance = false\n"
                                   "  subsection Figures\n"
                                   "    set Enabled = false\n"
                                   "  end\n"
                                   "end\n";

  /** The fault's patch test (tests/faults/elastic_fault_shear.prm with the
   * test's fault law): two cycles of global refinement. */
  std::string
  fault_model(const std::string &directory)
  {
    std::ostringstream prm;
    prm << "set Output directory = " << directory << "\n"
        << "subsection Geometry\n"
           "  set Model = layered box\n"
           "  set Length unit = km\n"
           "  subsection Layered box\n"
           "    set Width = 10\n"
           "    set Layer interfaces = 0, -10\n"
           "    set Layer names = rock\n"
           "    set Cells per layer = 4\n"
           "    set Cells across = 4\n"
           "    set Fault surface x = 5\n"
           "    set Fault dip = 90\n"
           "    set Fault dips towards = right\n"
           "  end\n"
           "end\n"
           "subsection Faults\n"
           "  set Names = fault\n"
           "  subsection fault\n"
           "    set Interface law = stiffening spring\n"
        << "    set Shear stiffness = " << k_s
        << "\n    set Normal stiffness = " << k_s
        << "\n    set Cubic stiffness = " << cubic
        << "\n  end\n"
           "  subsection Sliding solver\n"
           "    set Residual tolerance = 1e-12\n"
           "    set Excess shear tolerance = 1\n"
           "  end\n"
           "end\n"
           "subsection Materials\n"
           "  set Names = rock\n"
           "  subsection rock\n"
           "    set Young's modulus = 0.85e11\n"
           "    set Poisson's ratio = 0.25\n"
           "  end\n"
           "end\n"
        << fixed_left_side
        << "subsection Loads\n"
           "  subsection Tractions\n"
           "    set Boundary parts = top, base, right\n"
        << "    subsection top\n      set Shear traction = " << tau
        << "\n    end\n    subsection base\n      set Shear traction = " << tau
        << "\n    end\n    subsection right\n      set Shear traction = "
        << -tau
        << "\n    end\n"
           "  end\n"
           "end\n"
           "subsection Mesh refinement\n"
           "  set Number of cycles = 2\n"
           "  set Strategy = global\n"
           "end\n"
           "subsection Solver\n"
           "  set Relative tolerance = 1e-12\n"
           "end\n"
        << quiet_output;
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

  const double bar_length = 1e4, sigma_0 = 1e7, E_0 = 1e10, x_probe = 7500;

  /** The graded bar (see the head of this file) with @p solver and
   * @p strategy, three cycles. */
  std::string
  graded_model(const std::string &directory,
               const std::string &solver,
               const std::string &strategy,
               const double       anisotropy)
  {
    std::ostringstream prm;
    prm << "set Output directory = " << directory << "\n"
        << "subsection Geometry\n"
           "  set Model = rectangular block\n"
           "  subsection Rectangular block\n"
           "    set X extent = 0, "
        << bar_length
        << "\n    set Y extent = 0, 1000\n"
           "    set Cells = 4, 1\n"
           "  end\n"
           "end\n"
           "subsection Materials\n"
           "  set Names = rock\n"
           "  subsection rock\n"
           "    set Material id = 0\n"
           "    set Young's modulus = "
        << E_0
        << "\n    set Poisson's ratio = 0\n"
           "    set Rheology = graded elasticity\n"
           "    set Stiffness gradient = "
        << 1 / bar_length << "\n    set Stiffness anisotropy = " << anisotropy
        << "\n  end\nend\n"
        << fixed_left_side
        << "subsection Loads\n"
           "  subsection Tractions\n"
           "    set Boundary parts = right\n"
           "    subsection right\n"
           "      set Normal traction = "
        << sigma_0
        << "\n    end\n"
           "  end\n"
           "end\n"
           "subsection Solver\n"
           "  set Type = "
        << solver
        << "\n  set Relative tolerance = 1e-12\n"
           "end\n"
           "subsection Mesh refinement\n"
           "  set Number of cycles = 3\n"
           "  set Strategy = "
        << strategy << "\nend\n"
        << quiet_output
        << "subsection Convergence study\n"
           "  set Points = "
        << x_probe << ", 500\n"
        << "end\n";
    return prm.str();
  }
} // namespace

/** The graded bar through @p solver with @p strategy: u_x at x_probe per
 * cycle against the closed form. */
void
graded_bar_test(const bool         root,
                const std::string &solver,
                const std::string &strategy,
                const double       anisotropy = 0)
{
  const std::string directory = "output_plugin_registration_graded";
  const std::string file      = "plugin_registration_graded.prm";
  if (root)
    {
      std::filesystem::remove_all(directory);
      std::ofstream(file) << graded_model(directory,
                                          solver,
                                          strategy,
                                          anisotropy);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  std::string refusal;
  try
    {
      ParameterHandler prm;
      ParameterFile::read(file, {}, declare, prm);
      Simulator<2> simulator(MPI_COMM_WORLD, prm);
      simulator.run();
    }
  catch (const ComputationError &e)
    {
      refusal = e.what();
    }
  check(refusal.empty(),
        "the graded bar runs" + (refusal.empty() ? "" : ": " + refusal));
  if (!root)
    return;
  const double a = 1 / bar_length;
  const double exact =
    sigma_0 * std::log(1 + a * x_probe) / (E_0 * a * (1 + anisotropy));
  std::vector<double> errors;
  for (const auto &row : read_csv(directory + "/convergence.csv"))
    errors.push_back(std::abs(row.at("u_x@P1") - exact) / exact);
  std::ostringstream what;
  what << "graded elasticity" << (anisotropy != 0 ? " (anisotropic)" : "")
       << " through " << solver << " (" << strategy
       << "): u_x at x = 7.5 km against sigma_0 ln(1 + a x)/(E a (1 + b)), "
          "relative errors";
  const bool global = strategy == "global";
  bool       falls  = errors.size() == 3;
  for (unsigned int c = 0; c < errors.size(); ++c)
    {
      what << ' ' << std::scientific << std::setprecision(2) << errors[c];
      if (c > 0)
        falls = falls && errors[c] * (global ? 8 : 1) < errors[c - 1];
    }
  if (falls)
    falls = global ? errors.back() < 1e-6 : errors.back() * 4 < errors[0];
  check(falls,
        what.str() + (global ? " (each cycle 8 times smaller, the last "
                               "below 1e-6)"
                             : " (never larger, the last 4 times smaller "
                               "than the first)"));
}

/** The fault law's patch test (see the head of this file). */
void
fault_patch_test(const bool root)
{
  check(InterfaceLawRegistry<2>::has("stiffening spring") &&
          InterfaceLawRegistry<2>::has("frictional") &&
          InterfaceLawRegistry<2>::has("locked"),
        "the registry holds the built-in fault laws and the test's own");
  const std::string directory = "output_plugin_registration_fault";
  const std::string file      = "plugin_registration_fault.prm";
  if (root)
    {
      std::filesystem::remove_all(directory);
      std::ofstream(file) << fault_model(directory);
    }
  MPI_Barrier(MPI_COMM_WORLD);
  probe = Probe();
  {
    ParameterHandler prm;
    ParameterFile::read(file, {}, declare, prm);
    Simulator<2> simulator(MPI_COMM_WORLD, prm);
    simulator.run();
  }
  // The real root of k_s w + c w³ = tau by Newton's method.
  double w = tau / k_s;
  for (unsigned int i = 0; i < 50; ++i)
    w -= (k_s * w + cubic * w * w * w - tau) / (k_s + 3 * cubic * w * w);
  double worst = probe.history.empty() ? 1.0 : 0.0;
  for (const auto &h : probe.history)
    worst =
      h.size() != 2
        ? 1.0
        : std::max({worst, std::abs(h[0] - w) / w, std::abs(h[1] - tau) / tau});
  worst = Utilities::MPI::max(worst, MPI_COMM_WORLD);
  {
    std::ostringstream what;
    what << "the fault law's named history (" << probe.history_names.size()
         << " components) holds |w| = " << w << " m and tau at every point ("
         << probe.history.size() << " points, largest relative error "
         << std::scientific << worst << ")";
    check(probe.history_names ==
              std::vector<std::string>{"peak slip", "peak shear traction"} &&
            worst < 1e-8,
          what.str());
  }
  if (root)
    {
      const auto rows  = read_csv(directory + "/fault.csv");
      double     error = rows.empty() ? 1.0 : 0.0;
      for (const auto &row : rows)
        error = std::max(error, std::abs(std::abs(row.at("slip")) - w) / w);
      std::ostringstream what;
      what << "fault.csv's slip is the root of k_s w + c w^3 = tau ("
           << rows.size() << " rows, largest relative error " << std::scientific
           << error << "; a linear spring: 1 m)";
      check(rows.size() > 8 && error < 1e-8, what.str());
    }
}

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  check(RheologyRegistry<2>::has("scaled elasticity") &&
          RheologyRegistry<2>::has("elastic") &&
          RheologyRegistry<2>::has("maxwell") &&
          GeometryRegistry<2>::has("skewed block") &&
          GeometryRegistry<2>::has("rectangular block"),
        "the registries hold the built-in rock laws and geometries and the "
        "test's own");
  {
    ParameterHandler prm;
    declare(prm, nullptr);
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::PRM);
    check(text.str().find("scaled elasticity") != std::string::npos &&
            text.str().find("Stiffness factor") != std::string::npos &&
            text.str().find("skewed block") != std::string::npos &&
            text.str().find("subsection Skewed block") != std::string::npos,
          "--print-parameters shows the test law and geometry and their own "
          "entries");
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
  // The largest |u| of the field is at the top right corner: |e1| · 11 km
  // = 2.2 m.
  check(std::abs(probe.largest_u_x - std::abs(e1) * 1.1e4) < 1e-9,
        "it is given the patch test's solution on the skewed block (largest "
        "|u| " +
          std::to_string(probe.largest_u_x) + " m against 2.2 m)");

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
  fault_patch_test(root);
  graded_bar_test(root, "direct", "global");
  graded_bar_test(root, "matrix-free multigrid", "global");
  graded_bar_test(root, "matrix-free multigrid", "adaptive");
  graded_bar_test(root, "direct", "global", 1);
  graded_bar_test(root, "matrix-free multigrid", "global", 1);
  return n_failed == 0 ? 0 : 1;
}

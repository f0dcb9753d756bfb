// Unit test of the rock laws' named history at the cell quadrature points
// (materials/cell_history.h, materials/history_layout.h) through the whole
// program: a rock law defined and registered in this file only, `aging
// maxwell`, is Maxwell visco-elasticity that also keeps the age of the
// rock, a history component of its own that grows at rate 1. It names its
// history {age, creep_xx, creep_yy, creep_xy, creep_zz}; the other
// material is plain `maxwell`, {creep_xx, creep_yy, creep_xy, creep_zz}.
// The records then hold five components, the Maxwell material's first, so
// that the aging law's history is gathered from and scattered to other
// places of the record than its own order (HistoryLayout).
//
// The model is tests/viscoelastic/maxwell_block.prm's with two layers: a
// block under a constant uniform strain, u = (e1 x, e2 y) on every side,
// both layers with the same elasticity and viscosity (tau = 1000 years).
// Q2 holds the displacement exactly and the creep strain is uniform, so
// at every node of both layers, at every output time t:
// - the age is t, to 1e-12 relative: every scheme integrates a constant
//   rate exactly (BDF2 and the trapezoidal rule are exact for linear
//   functions);
// - the creep strain is the same in both layers and at every node, to
//   1e-10 of its size (the direct solver's round-off; the toy law's creep
//   is Maxwell's);
// - it is the closed form e (1 - exp(-t/tau)) of the deviatoric strain e to
//   2 % of |e|: BDF2 with steps of tau/10 from a trapezoidal start, whose
//   error is O((dt/tau)^2) = 1e-2 at most over three Maxwell times;
// and the history survives what the time loop does to it:
// - adaptive refinement every 3 steps (Refinement interval), which changes
//   the mesh (checked) and transfers the history;
// - a checkpoint written on 1 rank at t = 1500 years and resumed on 2 ranks
//   to 3000 years: its history at 2000 and 3000 years is that of an
//   uninterrupted 2-rank run to 1e-10 relative (round-off of different
//   partitions).
//
// Prints one "ok ..." or "FAIL ..." line per check and returns non-zero on
// a failure. Run on 2 ranks.

#include <deal.II/base/mpi.h>

#include <lithostress/base/parameter_file.h>
#include <lithostress/materials/creep_strain.h>
#include <lithostress/materials/maxwell_rheology.h>
#include <lithostress/postprocessors/postprocessor.h>
#include <lithostress/simulator/simulator.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
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
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      std::cout << (ok ? "ok " : "FAIL ") << what << std::endl;
    if (!ok)
      ++n_failed;
  }

  /** Maxwell visco-elasticity that also keeps the rock's age [s]: history
   * {age, creep strain}, the age's rate 1. */
  template <int dim>
  class AgingMaxwell : public Rheology<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {
    }

    void
    parse_parameters(ParameterHandler &prm,
                     const Material   &material,
                     const PlaneState  plane_state) override
    {
      maxwell.parse_parameters(prm, material, plane_state);
    }

    std::vector<std::string>
    history_names() const override
    {
      std::vector<std::string> names = {"age"};
      for (const std::string &name : CreepStrain<dim>::names())
        names.push_back(name);
      return names;
    }

    /** The step control measures the creep strain only. */
    double
    history_norm(const ArrayView<const double> &h) const override
    {
      return maxwell.history_norm(creep(h));
    }

    const ElasticModuli<dim> &
    elastic_moduli() const override
    {
      return maxwell.elastic_moduli();
    }

    bool
    creeps() const override
    {
      return true;
    }

    double
    relaxation_time() const override
    {
      return maxwell.relaxation_time();
    }

    const ElasticModuli<dim> &
    step_moduli() const override
    {
      return maxwell.step_moduli();
    }

    void
    set_time_step(const double dt, const double weight) override
    {
      maxwell.set_time_step(dt, weight);
    }

    StressState<dim>
    stress(const RheologyInputs<dim> &in) const override
    {
      return maxwell.stress(creep_inputs(in));
    }

    void
    evaluate(const RheologyInputs<dim> &in,
             RheologyOutputs<dim>      &out) const override
    {
      maxwell.evaluate(creep_inputs(in), out);
      out.history.insert(out.history.begin(),
                         in.history[0] + in.weight * in.time_step);
      out.history_rate.insert(out.history_rate.begin(), 1.0);
    }

  private:
    /** The creep strain of a history {age, creep}. */
    static ArrayView<const double>
    creep(const ArrayView<const double> &h)
    {
      return ArrayView<const double>(h.data() + 1, h.size() - 1);
    }

    static RheologyInputs<dim>
    creep_inputs(const RheologyInputs<dim> &in)
    {
      RheologyInputs<dim> maxwell_in = in;
      maxwell_in.history             = creep(in.history);
      return maxwell_in;
    }

    MaxwellRheology<dim> maxwell;
  };

  /** What the probe saw at one output time: the largest deviation of the
   * age from t (relative), the creep strain's spread over the nodes and
   * its value, the nodes with a history (and those with an age), and
   * the mesh. */
  struct Snapshot
  {
    double              age_error = 0, creep_spread = 0;
    std::vector<double> creep;
    unsigned long long  nodes = 0, aging_nodes = 0, cells = 0;
  };

  /** Snapshots by output time [years], of the run in progress. */
  std::map<long, Snapshot> snapshots;
  std::vector<std::string> record_names;

  /** Reads the cell history at every node at every output time. */
  template <int dim>
  class HistoryProbe : public Postprocessor<dim>
  {
  public:
    static void
    declare_parameters(ParameterHandler &)
    {
    }

    void
    output_time(const SimulatorAccess<dim> &access,
                const unsigned int,
                const double time) override
    {
      const StressModel<dim>     &model   = access.stress_model;
      const CellHistory<dim>     *history = model.attached_cell_history();
      const HistoryLayout        &layout  = model.history_layout();
      const MPI_Comm              comm    = access.communicator;
      std::vector<double>         low(4, 1e300), high(4, -1e300);
      double                      age_error = 0;
      unsigned long long          nodes = 0, aging_nodes = 0;
      std::vector<Vector<double>> records;
      std::vector<double>         scratch;
      record_names = layout.names();
      for (const auto &cell : access.triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && layout.size(cell->material_id()) > 0)
          {
            const types::material_id id    = cell->material_id();
            const bool               aging = layout.size(id) == 5;
            history->get(cell, records);
            for (const Vector<double> &record : records)
              {
                const ArrayView<const double> h =
                  layout.of(id, record, scratch);
                ++nodes;
                aging_nodes += aging ? 1 : 0;
                if (aging)
                  age_error =
                    std::max(age_error,
                             std::abs(h[0] - time) / std::max(time, 1.0));
                for (unsigned int c = 0; c < 4; ++c)
                  {
                    low[c]  = std::min(low[c], h[c + (aging ? 1 : 0)]);
                    high[c] = std::max(high[c], h[c + (aging ? 1 : 0)]);
                  }
              }
          }
      Snapshot s;
      s.age_error   = Utilities::MPI::max(age_error, comm);
      s.cells       = access.triangulation.n_global_active_cells();
      s.nodes       = Utilities::MPI::sum(nodes, comm);
      s.aging_nodes = Utilities::MPI::sum(aging_nodes, comm);
      double size   = 0;
      for (unsigned int c = 0; c < 4; ++c)
        {
          const double lo = -Utilities::MPI::max(-low[c], comm);
          const double hi = Utilities::MPI::max(high[c], comm);
          s.creep.push_back(hi);
          s.creep_spread = std::max(s.creep_spread, hi - lo);
          size           = std::max(size, std::abs(hi));
        }
      if (size > 0)
        s.creep_spread /= size;
      snapshots[std::lround(time / (365.25 * 86400))] = s;
    }
  };
} // namespace

LITHOSTRESS_REGISTER_RHEOLOGY(AgingMaxwell,
                              "aging maxwell",
                              "a test law: Maxwell that keeps its age")
LITHOSTRESS_REGISTER_POSTPROCESSOR(HistoryProbe,
                                   "history probe",
                                   "a test probe of the cell history",
                                   1000)

namespace
{
  const double e1 = 2e-4, e2 = -1e-4;

  /** The two-layer block to @p end_time years, written to @p file; with
   * @p elastic both layers are elastic (no law keeps a history). */
  void
  write_model(const std::string &file,
              const std::string &directory,
              const double       end_time,
              const bool         resume,
              const bool         elastic = false)
  {
    std::ostringstream side;
    side << "    set x = e1 * x\n"
         << "    set y = e2 * y\n"
         << "    set Constants = e1=" << e1 << ", e2=" << e2 << "\n";
    std::ostringstream prm;
    prm << "set Output directory = " << directory << "\n"
        << "subsection Geometry\n"
        << "  set Model = layered box\n"
        << "  set Length unit = km\n"
        << "  subsection Layered box\n"
        << "    set Width = 10\n"
        << "    set Layer interfaces = 0, -2.5, -5\n"
        << "    set Layer names = upper, lower\n"
        << "    set Cells per layer = 1, 1\n"
        << "    set Cells across = 2\n"
        << "  end\n"
        << "end\n"
        << "subsection Materials\n"
        << "  set Names = rock, aging rock\n";
    for (const std::string name : {"rock", "aging rock"})
      prm << "  subsection " << name << "\n"
          << "    set Material id = " << (name == "rock" ? 0 : 1) << "\n"
          << "    set Young's modulus = 1e11\n"
          << "    set Poisson's ratio = 0.25\n"
          << (elastic ? "" : "    set Viscosity = 1.262304e21\n")
          << (name == "rock" || elastic ? ""
                                        : "    set Rheology = aging maxwell\n")
          << "  end\n";
    prm << "end\n"
        << "subsection Boundary conditions\n"
        << "  set Prescribed displacement parts = left, right, base, top\n";
    for (const std::string part : {"left", "right", "base", "top"})
      prm << "  subsection " << part << "\n" << side.str() << "  end\n";
    prm << "end\n"
        << "subsection Solver\n"
        << "  set Type = direct\n"
        << "end\n"
        << "subsection Mesh refinement\n"
        << "  set Strategy = adaptive\n"
        << "end\n"
        << "subsection Time stepping\n"
        << "  set Enabled = true\n"
        << "  set Time unit = years\n"
        << "  set End time = " << end_time << "\n"
        << "  set Output times = "
        << (end_time > 1500 ? "0, 500, 1000, 1500, 2000, 3000"
                            : "0, 500, 1000, 1500")
        << "\n"
        << "  set Adaptive time steps = false\n"
        << "  set First time step = 100\n"
        << "  set Refinement interval = 3\n"
        << "  set Checkpoint interval = 5\n"
        << "  set Resume = " << (resume ? "true" : "false") << "\n"
        << "end\n"
        << "subsection Output\n"
        << "  set Write ParaView files = false\n"
        << "  set Force balance = false\n"
        << "  subsection Figures\n"
        << "    set Enabled = false\n"
        << "  end\n"
        << "end\n";
    std::ofstream(file) << prm.str();
  }

  void
  declare(ParameterHandler &prm, ParameterHandler *first_pass)
  {
    Simulator<2>::declare_parameters(prm, first_pass);
  }

  /** Run the model of @p file on @p comm; its snapshots. */
  std::map<long, Snapshot>
  run(const std::string &file, const MPI_Comm comm)
  {
    snapshots.clear();
    ParameterHandler prm;
    ParameterFile::read(file, {}, declare, prm);
    Simulator<2> simulator(comm, prm);
    simulator.run();
    return snapshots;
  }

  /** The closed form e (1 − exp(−t/τ)) of creep component @p c (xx, yy,
   * xy, zz) under plane strain. */
  double
  closed_form(const unsigned int c, const double years)
  {
    const double mean = (e1 + e2) / 3;
    const double e[4] = {e1 - mean, e2 - mean, 0, -mean};
    return e[c] * (1 - std::exp(-years / 1000));
  }

  /** The checks of one run's @p runs snapshots (@p what names the run);
   * with @p refines, that its mesh changed between them. */
  void
  check_run(const std::map<long, Snapshot> &runs,
            const std::string              &what,
            const bool                      refines)
  {
    double age = 0, spread = 0, closed = 0;
    bool   mesh_changed = false, both_layers = !runs.empty();
    for (const auto &[years, s] : runs)
      {
        both_layers =
          both_layers && s.aging_nodes > 0 && s.nodes > s.aging_nodes;
        age    = std::max(age, s.age_error);
        spread = std::max(spread, s.creep_spread);
        for (unsigned int c = 0; c < 4; ++c)
          closed = std::max(closed,
                            std::abs(s.creep[c] - closed_form(c, years)) /
                              std::abs(e1 - (e1 + e2) / 3));
        mesh_changed = mesh_changed || s.cells != runs.begin()->second.cells;
      }
    std::ostringstream text;
    text << std::scientific << std::setprecision(2);
    text << what << ": " << runs.size() << " output times, age = t to " << age
         << ", creep the same at every node of both layers to " << spread
         << ", the closed form to " << closed
         << (mesh_changed ? ", the mesh refined" : ", the mesh unchanged")
         << (both_layers ? "" : "; a layer had no nodes with a history");
    check(both_layers && age < 1e-12 && spread < 1e-10 && closed < 2e-2 &&
            (mesh_changed || !refines),
          text.str());
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const MPI_Comm                   comm = MPI_COMM_WORLD;
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  const bool         root = rank == 0;
  if (Utilities::MPI::n_mpi_processes(comm) != 2)
    {
      if (root)
        std::cout << "FAIL run on 2 ranks (mpirun -np 2)" << std::endl;
      return 1;
    }

  const std::string whole   = "output_cell_history_whole",
                    split   = "output_cell_history_split",
                    elastic = "output_cell_history_elastic";
  if (root)
    {
      std::filesystem::remove_all(whole);
      std::filesystem::remove_all(split);
      std::filesystem::remove_all(elastic);
      write_model("cell_history_whole.prm", whole, 3000, false);
      write_model("cell_history_first.prm", split, 1500, false);
      write_model("cell_history_resume.prm", split, 3000, true);
      write_model("cell_history_elastic_first.prm", elastic, 1500, false, true);
      write_model("cell_history_elastic_resume.prm", elastic, 3000, true, true);
    }
  MPI_Barrier(comm);

  const std::map<long, Snapshot> reference =
    run("cell_history_whole.prm", comm);
  check(record_names ==
          std::vector<std::string>{
            "creep_xx", "creep_yy", "creep_xy", "creep_zz", "age"},
        "the records hold the Maxwell material's creep strain, then the "
        "aging law's age");
  check_run(reference, "uninterrupted, 2 ranks", true);

  // The first half on rank 0 alone, then resumed on both.
  MPI_Comm first;
  MPI_Comm_split(comm, root ? 0 : MPI_UNDEFINED, 0, &first);
  if (root)
    {
      check_run(run("cell_history_first.prm", first),
                "first half, 1 rank",
                true);
      MPI_Comm_free(&first);
    }
  MPI_Barrier(comm);
  const std::map<long, Snapshot> resumed = run("cell_history_resume.prm", comm);
  double                         difference = resumed.empty() ? 1.0 : 0.0;
  for (const auto &[years, s] : resumed)
    for (unsigned int c = 0; c < 4; ++c)
      difference =
        std::max(difference,
                 std::abs(s.creep[c] - reference.at(years).creep[c]) /
                   std::abs(reference.at(years).creep[0]));
  std::ostringstream text;
  text << "resumed on 2 ranks from a 1-rank checkpoint at 1500 years: the "
          "creep strain of the uninterrupted run at "
       << resumed.size() << " output times, to " << std::scientific
       << std::setprecision(2) << difference;
  check(resumed.size() >= 2 && resumed.count(2000) && resumed.count(3000) &&
          difference < 1e-10,
        text.str());
  check_run(resumed, "resumed", false);

  // Elastic layers: a time loop whose laws keep no history (a field of no
  // components), checkpointed on 1 rank and resumed on 2.
  MPI_Comm_split(comm, root ? 0 : MPI_UNDEFINED, 0, &first);
  if (root)
    {
      run("cell_history_elastic_first.prm", first);
      MPI_Comm_free(&first);
    }
  MPI_Barrier(comm);
  const std::map<long, Snapshot> elastic_run =
    run("cell_history_elastic_resume.prm", comm);
  bool no_history = elastic_run.size() == 2;
  for (const auto &[years, s] : elastic_run)
    no_history = no_history && s.nodes == 0;
  check(no_history && record_names.empty(),
        "elastic layers (no history): checkpointed on 1 rank, resumed on 2, "
        "output at " +
          std::to_string(elastic_run.size()) +
          " times after the resume, no component and no node with a history");
  return n_failed == 0 ? 0 : 1;
}

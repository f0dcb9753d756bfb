#include <lithostress/base/huge_pages.h>
#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>
#include <lithostress/postprocessors/run_statistics.h>

#include <sys/resource.h>

#include <iomanip>
#include <sstream>

namespace lithostress
{
  namespace
  {
    /** The width in bits of the active mesh operator's cell batches: the
     * vectorised build's (LITHOSTRESS_SIMD, doc/performance.md), else one
     * double. The performance guard reads it: a matrix-free solve is
     * compared only with one of the same width. */
    constexpr unsigned int active_operator_bits =
#ifdef LITHOSTRESS_SIMD_BITS
      LITHOSTRESS_SIMD_BITS;
#else
      8 * sizeof(double);
#endif
  } // namespace

  template <int dim>
  void
  RunStatistics<dim>::finish(const SimulatorAccess<dim> &a)
  {
    const SolverReport &solver = a.statistics.solver;
    if (!solver.phases.empty())
      {
        a.log << "\nSolver (" << solver.solver
              << ", last cycle), wall time by phase:\n";
        std::ostringstream table;
        for (const auto &[phase, seconds] : solver.phases)
          table << "  " << std::left << std::setw(40) << phase << std::right
                << std::fixed << std::setprecision(3) << std::setw(9) << seconds
                << " s\n";
        a.log << table.str();
      }
    write_statistics(a);
  }

  template <int dim>
  void
  RunStatistics<dim>::interrupted(const SimulatorAccess<dim> &a)
  {
    write_statistics(a);
  }

  template <int dim>
  void
  write_statistics(const SimulatorAccess<dim> &a)
  {
    const CycleStatistics &s = a.statistics;
    rusage                 usage;
    getrusage(RUSAGE_SELF, &usage);
    const double peak_mb =
      Utilities::MPI::sum(usage.ru_maxrss / 1024.0, a.communicator);
    const double total = a.wall_clock.wall_time() - s.benchmark_time;
    on_all_ranks(a.communicator, [&]() {
      if (!a.root())
        return;
      OutputFile out(a.path("statistics.json"));
      out << "{\"solver\": \"" << s.solver.solver << "\", \"dofs\": " << s.dofs
          << ", \"cells\": " << s.cells
          << ", \"ranks\": " << Utilities::MPI::n_mpi_processes(a.communicator)
          << ", \"active_operator_bits\": " << active_operator_bits
          << ", \"huge_pages\": "
          << (huge_pages_for_large_arrays() ? "true" : "false")
          << ", \"iterations\": " << s.solver.iterations
          << ", \"nonlinear_iterations\": " << s.solver.nonlinear_iterations
          << ", \"linear_solves\": " << s.solver.linear_solves
          << ", \"setup_s\": " << s.mesh_time + s.setup_time
          << ", \"assemble_s\": " << s.assemble_time
          << ", \"solve_s\": " << s.solve_time
          << ", \"preconditioner_setup_s\": " << s.solver.setup_time
          << ", \"matvec_ms\": " << 1e3 * s.solver.matrix_vector_product_time
          << ", \"level_matvec_ms\": "
          << 1e3 * s.solver.level_matrix_vector_product_time
          << ", \"total_s\": " << total << ", \"peak_rss_mb\": " << peak_mb
          << ", \"solver_memory_mb\": " << s.solver.memory_bytes / 1048576.
          << ", \"phases\": {";
      out << "\"set-up: mesh refinement\": " << s.mesh_time;
      for (const auto &[phase, seconds] : s.setup_phases)
        out << ", \"set-up: " << phase << "\": " << seconds;
      for (const auto &[phase, seconds] : s.solver.phases)
        out << ", \"" << phase << "\": " << seconds;
      out << "}}\n";
      out.commit();
    });
  }

  template class RunStatistics<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(RunStatistics,
                                     "run statistics",
                                     "solver phases and statistics.json",
                                     110)
  template void
  write_statistics(const SimulatorAccess<2> &);
} // namespace lithostress

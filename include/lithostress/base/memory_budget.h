#ifndef lithostress_base_memory_budget_h
#define lithostress_base_memory_budget_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * The memory a run may use, and the check of every planned mesh against
   * it: before the first mesh is made and before each refinement, the
   * cells and DoFs of the next mesh are estimated and, with the measured
   * bytes per DoF of the chosen solver (doc/performance.md) and the
   * program's own size per rank when the model was read (the libraries:
   * about 150 MB in Release, 360 MB in Debug), turned into memory. A mesh that
   * would not fit stops the run with the estimate, the limit and the entry
   * to change, instead of refining into swap.
   *
   * The limit (`Resources/Memory limit`) is a size for the whole run (all
   * ranks), or `auto`: on each node, the memory available to its ranks
   * (MemAvailable of /proc/meminfo, or the cgroup's limit minus its usage
   * if that is smaller).
   */
  class MemoryBudget
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read the limit; collective over @p communicator (finds the ranks
     * that share a node). */
    void
    parse_parameters(ParameterHandler &prm, const MPI_Comm communicator);

    /**
     * Throw an InputError on all ranks if a mesh of @p cells active cells
     * and @p dofs DoFs, solved by @p solver with @p bytes_per_dof and
     * @p level_bytes for the mesh's depth (LinearSolver::memory_of_levels,
     * whole run), would exceed the limit. @p mesh says which mesh ("the
     * mesh of cycle 3"), @p entries which parameters make it smaller.
     * Needs the same arguments on all ranks.
     */
    void
    check(const std::string &mesh,
          const double       cells,
          const double       dofs,
          const std::string &solver,
          const double       bytes_per_dof,
          const double       level_bytes,
          const std::string &entries) const;

    /** Memory of a run with @p dofs DoFs on @p ranks ranks [bytes]. */
    double
    estimate(const double       dofs,
             const double       bytes_per_dof,
             const unsigned int ranks) const;

    /** A line for the log: the size per rank at start and the limit. */
    std::string
    description() const;

  private:
    MPI_Comm communicator = MPI_COMM_WORLD;
    /** Resident size of the largest rank when the model was read
     * (VmRSS) [bytes]. */
    double bytes_per_rank = 0;
    /** Limit for the whole run [bytes] if given; 0 = auto. */
    double      limit = 0;
    std::string limit_text;
  };

  /** Bytes of memory available to this process's node now: MemAvailable,
   * or the cgroup's limit minus its usage if smaller. */
  double
  available_memory_on_node();

  /** @p bytes as "354.2 MB" or "1.23 GB". */
  std::string
  memory_text(const double bytes);
} // namespace lithostress

#endif

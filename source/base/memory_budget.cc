#include <lithostress/base/input_error.h>
#include <lithostress/base/memory_budget.h>
#include <lithostress/base/parameter_file.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace lithostress
{
  namespace
  {
    /** The first number in file @p name, or a negative value. */
    double
    number_in_file(const std::string &name)
    {
      std::ifstream in(name);
      double        value = -1;
      if (in >> value)
        return value;
      return -1;
    }

    /** This process's resident size (VmRSS) [bytes], or 0. */
    double
    resident_size()
    {
      std::ifstream status("/proc/self/status");
      std::string   key, unit;
      double        value;
      std::string   line;
      while (std::getline(status, line))
        {
          std::istringstream in(line);
          if (in >> key >> value >> unit && key == "VmRSS:")
            return value * 1024;
        }
      return 0;
    }
  } // namespace

  double
  available_memory_on_node()
  {
    double        available = -1;
    std::ifstream meminfo("/proc/meminfo");
    std::string   key, unit;
    double        value;
    while (meminfo >> key >> value >> unit)
      if (key == "MemAvailable:")
        available = value * 1024;
    // cgroup v2, then v1; "max" or absurd values mean no limit.
    for (const auto &[limit_file, usage_file] :
         {std::pair<std::string, std::string>{"/sys/fs/cgroup/memory.max",
                                              "/sys/fs/cgroup/memory.current"},
          {"/sys/fs/cgroup/memory/memory.limit_in_bytes",
           "/sys/fs/cgroup/memory/memory.usage_in_bytes"}})
      {
        const double cgroup_limit = number_in_file(limit_file);
        const double usage        = number_in_file(usage_file);
        if (cgroup_limit > 0 && cgroup_limit < 1e17 && usage >= 0)
          {
            const double left = cgroup_limit - usage;
            available = available < 0 ? left : std::min(available, left);
            break;
          }
      }
    return available;
  }

  std::string
  memory_text(const double bytes)
  {
    std::ostringstream out;
    out << std::fixed << std::setprecision(bytes >= 1e9 ? 2 : 1);
    if (bytes >= 1e12)
      out << bytes / 1e12 << " TB";
    else if (bytes >= 1e9)
      out << bytes / 1e9 << " GB";
    else
      out << bytes / 1e6 << " MB";
    return out.str();
  }

  void
  MemoryBudget::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Resources");
    prm.declare_entry(
      "Memory limit",
      "auto",
      Patterns::Anything(),
      "Memory the whole run (all ranks) may use, e.g. `8 GB`, `500 MB`; "
      "`auto` = what each node has available (MemAvailable, or the cgroup "
      "limit). Each mesh is estimated before it is made (cells, DoFs, the "
      "solver's measured bytes per DoF) and a mesh that would not fit "
      "stops the run with the estimate.");
    prm.leave_subsection();
  }

  void
  MemoryBudget::parse_parameters(ParameterHandler &prm,
                                 const MPI_Comm    communicator)
  {
    this->communicator = communicator;
    bytes_per_rank     = Utilities::MPI::max(resident_size(), communicator);
    prm.enter_subsection("Resources");
    limit_text = Utilities::trim(prm.get("Memory limit"));
    prm.leave_subsection();
    limit = 0;
    if (limit_text == "auto")
      return;
    const std::string  entry = "Resources/Memory limit";
    std::istringstream in(limit_text);
    double             value = 0;
    std::string        unit;
    if (!(in >> value) || !(value > 0) || !std::isfinite(value))
      throw_input_error(entry,
                        "<" + limit_text +
                          "> is not `auto` or a positive size such as `8 GB`");
    in >> unit;
    std::string rest;
    in >> rest;
    const std::map<std::string, double> units = {{"B", 1},
                                                 {"kB", 1e3},
                                                 {"KB", 1e3},
                                                 {"MB", 1e6},
                                                 {"GB", 1e9},
                                                 {"TB", 1e12},
                                                 {"KiB", 1024.},
                                                 {"MiB", 1048576.},
                                                 {"GiB", 1073741824.},
                                                 {"TiB", 1099511627776.}};
    if (units.count(unit) == 0 || !rest.empty())
      throw_input_error(entry,
                        "<" + limit_text +
                          "> needs a unit: B, kB, MB, GB, TB, KiB, MiB, GiB "
                          "or TiB");
    limit = value * units.at(unit);
  }

  std::string
  MemoryBudget::description() const
  {
    std::ostringstream size;
    size << std::fixed << std::setprecision(1) << bytes_per_rank / 1e6;
    return "Memory: " + size.str() + " MB" +
           " per rank when the model was read; limit " +
           (limit == 0 ? "auto, " + memory_text(available_memory_on_node()) +
                           " available on this node"
                       : memory_text(limit) + " for the run") +
           " (Resources/Memory limit).";
  }

  double
  MemoryBudget::estimate(const double       dofs,
                         const double       bytes_per_dof,
                         const unsigned int ranks) const
  {
    return ranks * bytes_per_rank + dofs * bytes_per_dof;
  }

  void
  MemoryBudget::check(const std::string &mesh,
                      const double       cells,
                      const double       dofs,
                      const std::string &solver,
                      const double       bytes_per_dof,
                      const double       level_bytes,
                      const std::string &entries) const
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const double total = estimate(dofs, bytes_per_dof, n_ranks) + level_bytes;
    // The share of this node (ranks share the DoFs evenly) against what it
    // has, or the whole run against the given limit.
    double      need = total, have = limit;
    std::string source = "the limit set by Resources/Memory limit";
    if (limit == 0)
      {
        MPI_Comm node;
        MPI_Comm_split_type(
          communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
        const unsigned int on_node = Utilities::MPI::n_mpi_processes(node);
        const bool node_root = Utilities::MPI::this_mpi_process(node) == 0;
        MPI_Comm_free(&node);
        need = estimate(dofs * on_node / n_ranks, bytes_per_dof, on_node) +
               level_bytes * on_node / n_ranks;
        have = available_memory_on_node();
        // The node that is shortest of memory decides.
        const double ratio =
          Utilities::MPI::max(node_root && have > 0 ? need / have : 0.0,
                              communicator);
        const int tightest = Utilities::MPI::min(
          node_root && have > 0 && need / have == ratio
            ? static_cast<int>(Utilities::MPI::this_mpi_process(communicator))
            : static_cast<int>(n_ranks),
          communicator);
        if (tightest == static_cast<int>(n_ranks))
          return; // nothing known about the memory
        need   = Utilities::MPI::broadcast(communicator, need, tightest);
        have   = Utilities::MPI::broadcast(communicator, have, tightest);
        source = "what the node has available (MemAvailable or cgroup limit)";
      }
    if (need <= have)
      return;
    std::ostringstream what;
    what << std::setprecision(3) << mesh << " would have about " << cells
         << " cells and " << dofs << " DoFs and need about "
         << memory_text(need) << " (" << solver << ", " << bytes_per_dof / 1e3
         << " kB per DoF and " << memory_text(bytes_per_rank) << " per rank";
    if (level_bytes > 0)
      what << ", of which " << memory_text(level_bytes)
           << " for the solver's set-up on a mesh this deep";
    what << ") against " << memory_text(have) << ", " << source << "; lower "
         << entries << " or raise Resources/Memory limit";
    throw_input_error("Resources/Memory limit", what.str());
  }
} // namespace lithostress

/**
 * The `lithostress` command: a launcher that starts the program itself,
 * `lithostress-bin` next to it, with transparent huge pages for glibc's
 * large allocations (GLIBC_TUNABLES=glibc.malloc.hugetlb=1).
 *
 * Why: the solution, the multigrid levels, MatrixFree data and the Trilinos
 * matrix are arrays of tens to hundreds of MB. With 4 KiB pages the first
 * touch of each page is a page fault (expensive on a virtual machine) and
 * the sum-factorisation and sparse kernels miss the TLB; with 2 MiB pages
 * the 648 k-DoF flexure benchmark runs 20-25 % faster on both solvers
 * (doc/performance.md). glibc reads its tunables only when a process
 * starts, hence a launcher and not a call in main(); it execs the program
 * (same process, so mpirun sees no difference) and costs about 1 ms.
 *
 * LITHOSTRESS_HUGE_PAGES=off runs the program without huge pages; a
 * glibc.malloc.hugetlb setting already in GLIBC_TUNABLES is respected.
 *
 * A run started without mpirun is an MPI singleton. Open MPI's defaults
 * then fork a runtime daemon and load its network transports (libfabric,
 * PSM2, TCP) and hwloc's GPU plugins, 0.67 s before the first line of
 * lithostress against 0.29 s without them (doc/performance.md). One
 * process talks only to itself, so the launcher asks for an isolated
 * singleton with the self transport. It leaves alone runs under a
 * launcher (mpirun, srun: the environment names a rank) and every setting
 * the user made.
 *
 * Debuggers and profilers can run build/lithostress-bin directly.
 */
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{
  /** The directory of this executable (from /proc/self/exe). */
  std::string
  own_directory()
  {
    std::vector<char> buffer(4096);
    const ssize_t n = readlink("/proc/self/exe", buffer.data(), buffer.size());
    if (n <= 0 || static_cast<std::size_t>(n) >= buffer.size())
      return ".";
    const std::string path(buffer.data(), static_cast<std::size_t>(n));
    const auto        slash = path.rfind('/');
    return slash == std::string::npos ? "." : path.substr(0, slash);
  }

  bool
  huge_pages_requested()
  {
    const char *setting = std::getenv("LITHOSTRESS_HUGE_PAGES");
    if (setting == nullptr)
      return true;
    const std::string s(setting);
    return !(s == "off" || s == "0" || s == "no" || s == "false");
  }

  /** Whether an MPI launcher started this process (it names a rank). */
  bool
  started_by_mpi_launcher()
  {
    for (const char *name :
         {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
      if (std::getenv(name) != nullptr)
        return true;
    return false;
  }

  /** Open MPI's and hwloc's settings for a single process that starts
   * fast, each only where the environment has none. */
  void
  set_singleton_defaults()
  {
    setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    setenv("OMPI_MCA_pml", "ob1", 0);
    setenv("OMPI_MCA_btl", "self", 0);
    setenv("HWLOC_PLUGINS_BLACKLIST", "hwloc_gl,hwloc_opencl", 0);
    // Open MPI's shared-memory file-pointer component (MPI-IO, which the
    // checkpoints' mesh files use) keeps a file in the session directory,
    // which isolated singletons of one user share: one that finishes
    // removes it while another writes its checkpoint, whose MPI_File_open
    // then fails ("mca_sharedfp_sm_file_open: Error, unable to open file
    // for mmap", the test maxwell_block under ctest -j2 on 2026-12-02).
    setenv("OMPI_MCA_sharedfp", "^sm", 0);
  }
} // namespace

int
main(int, char *argv[])
{
  if (huge_pages_requested())
    {
      const char       *existing = std::getenv("GLIBC_TUNABLES");
      const std::string tunables = existing == nullptr ? "" : existing;
      if (tunables.find("glibc.malloc.hugetlb") == std::string::npos)
        {
          const std::string value = tunables.empty()
                                      ? "glibc.malloc.hugetlb=1"
                                      : tunables + ":glibc.malloc.hugetlb=1";
          setenv("GLIBC_TUNABLES", value.c_str(), 1);
        }
    }
  if (!started_by_mpi_launcher())
    set_singleton_defaults();
  const std::string program = own_directory() + "/lithostress-bin";
  execv(program.c_str(), argv);
  std::cerr << "lithostress: cannot start " << program << ": "
            << std::strerror(errno) << std::endl;
  return 127;
}

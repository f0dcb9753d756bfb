#include <lithostress/base/huge_pages.h>

#include <cstdlib>
#include <fstream>

namespace lithostress
{
  namespace
  {
    bool
    requested_from_glibc()
    {
      const char *tunables = std::getenv("GLIBC_TUNABLES");
      return tunables != nullptr &&
             std::string(tunables).find("glibc.malloc.hugetlb=1") !=
               std::string::npos;
    }

    /** The kernel's transparent huge page mode, e.g. "madvise". */
    std::string
    kernel_mode()
    {
      std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
      std::string   line;
      std::getline(in, line);
      const auto open = line.find('['), close = line.find(']');
      if (open == std::string::npos || close == std::string::npos)
        return "unknown";
      return line.substr(open + 1, close - open - 1);
    }
  } // namespace

  bool
  huge_pages_for_large_arrays()
  {
    const std::string mode = kernel_mode();
    return mode == "always" || (requested_from_glibc() && mode == "madvise");
  }

  std::string
  huge_pages_description()
  {
    const std::string mode = kernel_mode();
    if (mode == "always")
      return "Memory: transparent huge pages (the kernel's mode is "
             "'always').";
    if (!requested_from_glibc())
      return "Memory: 4 KiB pages (started without the lithostress "
             "launcher, or with LITHOSTRESS_HUGE_PAGES=off).";
    if (mode != "madvise")
      return "Memory: 4 KiB pages (the kernel's transparent huge pages are "
             "'" +
             mode + "').";
    return std::string("Memory: transparent huge pages for large arrays "
                       "(GLIBC_TUNABLES=") +
           std::getenv("GLIBC_TUNABLES") + ").";
  }
} // namespace lithostress

#ifndef lithostress_base_huge_pages_h
#define lithostress_base_huge_pages_h

#include <string>

namespace lithostress
{
  /**
   * Whether glibc places this process's large allocations on transparent
   * huge pages: the `lithostress` launcher (app/launcher.cc) starts the
   * program with GLIBC_TUNABLES=glibc.malloc.hugetlb=1, which takes effect
   * where the kernel's transparent_hugepage mode is `madvise`; in mode
   * `always` every run has them. Reported in the log and in
   * statistics.json.
   */
  bool
  huge_pages_for_large_arrays();

  /** One line for the log: whether huge pages are used, and if not, why. */
  std::string
  huge_pages_description();
} // namespace lithostress

#endif

#ifndef lithostress_base_gather_on_all_h
#define lithostress_base_gather_on_all_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <limits>
#include <type_traits>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * Every rank's @p mine, concatenated in rank order, on every rank: one
   * MPI_Allgatherv of the bytes. For plain records (matrix entries,
   * indices), where Utilities::MPI::all_gather()'s serialisation through
   * Boost cost more than the rest of the set-up it served (1.9 s of the
   * fault zones' 2.5 s on the million-DoF subduction coupling on 2 ranks).
   */
  template <typename T>
  std::vector<T>
  gather_on_all(const MPI_Comm communicator, const std::vector<T> &mine)
  {
    static_assert(std::is_trivially_copyable_v<T>,
                  "gather_on_all() sends the records' bytes");
    if (Utilities::MPI::n_mpi_processes(communicator) == 1)
      return mine;
    AssertThrow(mine.size() * sizeof(T) <
                  static_cast<std::size_t>(std::numeric_limits<int>::max()),
                ExcMessage("gather_on_all(): more than 2 GB on one rank"));
    const int              bytes = mine.size() * sizeof(T);
    const std::vector<int> counts =
      Utilities::MPI::all_gather(communicator, bytes);
    std::vector<int> offsets(counts.size(), 0);
    for (unsigned int r = 1; r < counts.size(); ++r)
      {
        AssertThrow(static_cast<long long>(offsets[r - 1]) + counts[r - 1] <
                      std::numeric_limits<int>::max(),
                    ExcMessage("gather_on_all(): more than 2 GB in all"));
        offsets[r] = offsets[r - 1] + counts[r - 1];
      }
    std::vector<T> all(
      (static_cast<std::size_t>(offsets.back()) + counts.back()) / sizeof(T));
    const int error = MPI_Allgatherv(mine.data(),
                                     bytes,
                                     MPI_BYTE,
                                     all.data(),
                                     counts.data(),
                                     offsets.data(),
                                     MPI_BYTE,
                                     communicator);
    AssertThrowMPI(error);
    return all;
  }
} // namespace lithostress

#endif

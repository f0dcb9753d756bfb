#ifndef lithostress_base_output_file_h
#define lithostress_base_output_file_h

#include <mpi.h>

#include <sstream>
#include <string>

namespace lithostress
{
  /**
   * A result file written completely or not at all. The text is collected
   * in memory; commit() checks that every number in it is finite, writes it
   * under a temporary name in the same directory and renames it to its
   * name, so that a reader, a later failure or a run stopped by a signal
   * never sees half a file, and an earlier run's file stays as it was until
   * the new one is complete. Without commit() nothing is written.
   */
  class OutputFile : public std::ostringstream
  {
  public:
    /** What commit() checks: the numbers of a text file, or nothing in a
     * file of encoded binary data (a compressed .vtu piece, made from a
     * solution that was checked finite). */
    enum Content
    {
      text,
      binary
    };

    explicit OutputFile(const std::string &file_name,
                        const Content      content = text);

    /**
     * Write the file. Throws ComputationError naming the file and the line
     * if the text has a NaN or infinity in it, or if the file cannot be
     * written; the old file (if any) is then unchanged. Called on the one
     * rank that writes: wrap the call in on_all_ranks() so that an error
     * reaches every rank.
     */
    void
    commit();

  private:
    std::string file_name;
    Content     content;
  };

  /** Write @p text to @p file_name atomically, as OutputFile::commit();
   * @p check_numbers: fail on a NaN or infinity in it. */
  void
  write_file_atomically(const std::string &file_name,
                        const std::string &text,
                        const bool         check_numbers = true);
  /**
   * Create the output directory @p directory (rank 0 of @p communicator)
   * and probe it with a test file, before anything of a run is written;
   * an InputError naming `Output directory` on every rank if it cannot be
   * made or written into.
   */
  void
  check_output_directory(const std::string &directory,
                         const MPI_Comm     communicator);
} // namespace lithostress

#endif

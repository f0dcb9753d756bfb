#ifndef lithostress_base_run_log_h
#define lithostress_base_run_log_h

#include <deal.II/base/mpi.h>

#include <fstream>
#include <sstream>
#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * The run's log: what rank 0 prints goes both to the screen and to
   * `log.txt` in the output directory. What is printed before the file is
   * opened — once the model has been accepted, so that a rejected model
   * leaves the output directory untouched — is kept and written first.
   * Each line is flushed: the log of a stopped run is complete up to its
   * last line.
   */
  class RunLog
  {
  public:
    explicit RunLog(const MPI_Comm communicator);

    /** Start writing to @p filename (what was printed so far first). */
    void
    open(const std::string &filename);

    template <typename T>
    RunLog &
    operator<<(const T &value)
    {
      if (is_root)
        {
          std::ostringstream text;
          text << value;
          write(text.str());
        }
      return *this;
    }

    RunLog &
    operator<<(std::ostream &(*manipulator)(std::ostream &));

    /** Whether this is the rank that writes. */
    bool
    on_root() const
    {
      return is_root;
    }

  private:
    void
    write(const std::string &text);

    bool          is_root;
    std::ofstream file;
    /** What was printed before open(). */
    std::string before_open;
  };
} // namespace lithostress

#endif

#ifndef lithostress_base_interruption_h
#define lithostress_base_interruption_h

#include <mpi.h>

#include <stdexcept>
#include <string>

namespace lithostress
{
  /**
   * A run stopped by SIGINT or SIGTERM. Thrown on all ranks together at a
   * safe point (between the phases of a cycle, or between two CG
   * iterations), so that every file written so far is complete; `main`
   * reports where the run stopped and exits with 128 + the signal number,
   * as a shell does.
   */
  class RunInterrupted : public std::runtime_error
  {
  public:
    RunInterrupted(const int signal, const std::string &where);

    /** Where the run stopped (without "stopped by ..."). */
    const std::string &
    where() const
    {
      return stopped_in;
    }

    /** The signal that stopped the run (SIGINT or SIGTERM). */
    int
    signal() const
    {
      return signal_number;
    }

  private:
    int         signal_number;
    std::string stopped_in;
  };

  /**
   * Graceful stop on SIGINT and SIGTERM: the signal handler only records the
   * signal; the run asks at safe points whether any rank has received one.
   * A second signal before the run has stopped ends it at once.
   * Ranks receive a signal at slightly different moments, so the question
   * is collective, and all ranks stop at the same point.
   */
  namespace interruption
  {
    /** Install the handlers for SIGINT and SIGTERM (once, in main). */
    void
    install_handlers();

    /** Collective: the signal received by any rank of @p communicator, or
     * 0. */
    int
    signal_on_any_rank(const MPI_Comm communicator);

    /** Collective: throw RunInterrupted on every rank if any rank has
     * received a signal; @p where (e.g. "cycle 2, solve") goes into the
     * message. */
    void
    stop_if_requested(const MPI_Comm communicator, const std::string &where);
  } // namespace interruption
} // namespace lithostress

#endif

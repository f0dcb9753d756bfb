#include <deal.II/base/mpi.h>

#include <lithostress/base/interruption.h>

#include <csignal>

namespace lithostress
{
  namespace
  {
    volatile std::sig_atomic_t pending_signal = 0;

    /** Record the signal; a second one while the first is pending ends the
     * program at once (the default action), for a phase that would take
     * too long to reach its next safe point. */
    extern "C" void
    record_signal(int signal)
    {
      if (pending_signal != 0)
        {
          std::signal(signal, SIG_DFL);
          std::raise(signal);
        }
      pending_signal = signal;
    }

    std::string
    signal_name(const int signal)
    {
      return signal == SIGINT    ? "SIGINT"
             : signal == SIGTERM ? "SIGTERM"
                                 : "signal " + std::to_string(signal);
    }
  } // namespace

  RunInterrupted::RunInterrupted(const int signal, const std::string &where)
      : std::runtime_error("stopped by " + signal_name(signal) + " in " + where)
      , signal_number(signal)
      , stopped_in(where)
  {
  }

  namespace interruption
  {
    void
    install_handlers()
    {
      struct sigaction action = {};
      action.sa_handler       = record_signal;
      sigemptyset(&action.sa_mask);
      // Restart interrupted system calls: a signal must not make a write
      // or an MPI call fail half-way.
      action.sa_flags = SA_RESTART;
      sigaction(SIGINT, &action, nullptr);
      sigaction(SIGTERM, &action, nullptr);
    }

    int
    signal_on_any_rank(const MPI_Comm communicator)
    {
      return dealii::Utilities::MPI::max(static_cast<int>(pending_signal),
                                         communicator);
    }

    void
    stop_if_requested(const MPI_Comm communicator, const std::string &where)
    {
      const int signal = signal_on_any_rank(communicator);
      if (signal != 0)
        throw RunInterrupted(signal, where);
    }
  } // namespace interruption
} // namespace lithostress

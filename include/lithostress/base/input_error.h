#ifndef lithostress_base_input_error_h
#define lithostress_base_input_error_h

#include <mpi.h>

#include <exception>
#include <stdexcept>
#include <string>

namespace lithostress
{
  /**
   * An error in what the user gave the program: a `.prm` entry, a mesh file,
   * an output directory. The message names the entry or the file and says what
   * is wrong; `main` prints it as one line and exits with a non-zero status,
   * before anything has been written to the output directory.
   */
  class InputError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * Throw an InputError for the parameter @p entry (a path such as
   * "Materials/crust/Poisson's ratio") with the explanation @p what.
   */
  [[noreturn]] void
  throw_input_error(const std::string &entry, const std::string &what);

  /**
   * An error in the state of a computation (a solver that did not converge, a
   * Newton iteration that stalled). Reported like an InputError.
   */
  class ComputationError : public std::runtime_error
  {
  public:
    using std::runtime_error::runtime_error;
  };

  /**
   * The collective part of on_all_ranks(): @p error is this rank's error
   * (null if none; only InputError or
   * ComputationError); throws on every rank if any rank has one.
   */
  void
  rethrow_on_all_ranks(const MPI_Comm communicator, std::exception_ptr error);

  /**
   * Make the outcome of rank-local work collective. @p local_work must not
   * communicate (a loop over owned cells that evaluates user functions, a
   * file written by rank 0); if it throws an InputError or ComputationError
   * on some ranks, every rank throws the error of the lowest such rank, so
   * that no rank waits in a collective call another rank has left and all
   * ranks end with the same message (doc/architecture.md, error policy).
   * Other exceptions are internal errors and pass through unchanged.
   */
  template <typename LocalWork>
  void
  on_all_ranks(const MPI_Comm communicator, const LocalWork &local_work)
  {
    std::exception_ptr error;
    try
      {
        local_work();
      }
    catch (const InputError &)
      {
        error = std::current_exception();
      }
    catch (const ComputationError &)
      {
        error = std::current_exception();
      }
    rethrow_on_all_ranks(communicator, error);
  }

} // namespace lithostress

#endif

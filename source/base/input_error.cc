#include <deal.II/base/mpi.h>

#include <lithostress/base/input_error.h>

namespace lithostress
{
  void
  throw_input_error(const std::string &entry, const std::string &what)
  {
    throw InputError("parameter <" + entry + ">: " + what);
  }

  void
  rethrow_on_all_ranks(const MPI_Comm communicator, std::exception_ptr error)
  {
    using namespace dealii;
    const unsigned int rank    = Utilities::MPI::this_mpi_process(communicator);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(communicator);
    const unsigned int first =
      Utilities::MPI::min(error ? rank : n_ranks, communicator);
    if (first == n_ranks)
      return;
    // The kind ('I' input error, 'C' computation error) and the message.
    std::string what;
    if (rank == first)
      {
        try
          {
            std::rethrow_exception(error);
          }
        catch (const InputError &e)
          {
            what = std::string("I") + e.what();
          }
        catch (const ComputationError &e)
          {
            what = std::string("C") + e.what();
          }
      }
    what = Utilities::MPI::broadcast(communicator, what, first);
    if (what[0] == 'I')
      throw InputError(what.substr(1));
    throw ComputationError(what.substr(1));
  }
} // namespace lithostress

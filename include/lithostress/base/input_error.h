#ifndef lithostress_base_input_error_h
#define lithostress_base_input_error_h

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
} // namespace lithostress

#endif

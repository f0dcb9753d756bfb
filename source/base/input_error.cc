#include <lithostress/base/input_error.h>

namespace lithostress
{
  void
  throw_input_error(const std::string &entry, const std::string &what)
  {
    throw InputError("parameter <" + entry + ">: " + what);
  }
} // namespace lithostress

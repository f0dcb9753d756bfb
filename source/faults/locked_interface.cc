#include <lithostress/faults/locked_interface.h>

namespace lithostress
{
  template class LockedInterface<2>;
  LITHOSTRESS_REGISTER_INTERFACE_LAW(
    LockedInterface,
    "locked",
    "the displacement is continuous across the fault (exact constraints, "
    "thesis §5's k = 1e15 N/m without its penalty)",
    0)
} // namespace lithostress

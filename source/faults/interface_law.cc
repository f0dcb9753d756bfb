#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/faults/interface_law.h>

namespace lithostress
{
  std::string
  to_string(const SlipState state)
  {
    switch (state)
      {
      case SlipState::stuck:
        return "stuck";
      case SlipState::sliding:
        return "sliding";
      case SlipState::open:
        return "open";
      }
    return "";
  }

  double
  fault_law_number(const ParameterHandler &prm,
                   const std::string      &fault,
                   const std::string      &name,
                   const std::string      &law,
                   const double            lowest,
                   const bool              inclusive)
  {
    const std::string entry = "Faults/" + fault + "/" + name;
    const std::string text  = Utilities::trim(prm.get(name));
    if (text.empty())
      throw_input_error(entry, "is needed by the " + law + " law");
    const double value = parse_number(text, entry);
    if (inclusive ? !(value >= lowest) : !(value > lowest))
      throw_input_error(entry,
                        std::string("must be ") +
                          (inclusive ? "at least " : "greater than ") +
                          (lowest == 0 ? "0" : std::to_string(lowest)) +
                          ", got " + text);
    return value;
  }
} // namespace lithostress

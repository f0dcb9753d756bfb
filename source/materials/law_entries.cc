#include <lithostress/base/input_error.h>
#include <lithostress/materials/law_entries.h>
#include <lithostress/materials/rheology.h>

#include <map>
#include <set>
#include <sstream>

namespace lithostress
{
  namespace
  {
    /** The top-level entries and defaults a law declares: its declaration
     * run on an empty handler, printed as ShortPRM and read back. */
    std::map<std::string, std::string>
    declared_entries(const RheologyRegistry<2>::Plugin &plugin)
    {
      ParameterHandler scratch;
      plugin.declare(scratch, nullptr);
      std::ostringstream out;
      scratch.print_parameters(out, ParameterHandler::ShortPRM);
      std::map<std::string, std::string> entries;
      std::istringstream                 in(out.str());
      std::string                        line;
      unsigned int                       depth = 0;
      while (std::getline(in, line))
        {
          const std::string text = Utilities::trim(line);
          if (text.rfind("subsection ", 0) == 0)
            ++depth;
          else if (text == "end" && depth > 0)
            --depth;
          else if (depth == 0 && text.rfind("set ", 0) == 0)
            {
              const auto equal = text.find('=');
              if (equal != std::string::npos)
                entries[Utilities::trim(text.substr(4, equal - 4))] =
                  Utilities::trim(text.substr(equal + 1));
            }
        }
      return entries;
    }

    /** Whether @p a and @p b are the same value: equal text or equal
     * numbers. */
    bool
    same_value(const std::string &a, const std::string &b)
    {
      if (a == b)
        return true;
      std::istringstream in_a(a), in_b(b);
      double             x = 0, y = 0;
      std::string        rest_a, rest_b;
      return (in_a >> x) && !(in_a >> rest_a) && (in_b >> y) &&
             !(in_b >> rest_b) && x == y;
    }
  } // namespace

  void
  refuse_entries_of_other_laws(ParameterHandler  &prm,
                               const std::string &law,
                               const std::string &where)
  {
    std::set<std::string> own;
    for (const auto &plugin : RheologyRegistry<2>::plugins())
      if (plugin.name == law)
        for (const auto &entry : declared_entries(plugin))
          own.insert(entry.first);
    for (const auto &plugin : RheologyRegistry<2>::plugins())
      {
        if (plugin.name == law)
          continue;
        for (const auto &[name, default_value] : declared_entries(plugin))
          if (own.count(name) == 0 &&
              !same_value(Utilities::trim(prm.get(name)), default_value))
            throw_input_error(where + name,
                              "is given, but Rheology = " + law +
                                " does not read it (Rheology = " + plugin.name +
                                " does): remove it or choose that law");
      }
  }
} // namespace lithostress

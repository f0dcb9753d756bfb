#ifndef lithostress_base_plugin_registry_h
#define lithostress_base_plugin_registry_h

#include <deal.II/base/parameter_handler.h>

#include <lithostress/base/input_error.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The plug-ins of one kind (geometries, loads, rheologies, linear solvers,
   * postprocessors), each added by one registration line
   * in its own source file (in the way of ASPECT's plug-in macros). A kind
   * is the interface @p Interface and the arguments @p Arguments its
   * plug-ins are made from. The registry is what the program knows of its
   * plug-ins: the allowed values of the selecting entry
   * (`--print-parameters`, doc/parameters.md), the declarations of their
   * parameters and their construction all come from it, so that adding a
   * plug-in is a header, a source file and that line.
   *
   * The list is built while static objects are initialised (the plug-ins'
   * translation units are linked whole, CMakeLists.txt), so it is complete
   * before main() begins and is only read afterwards.
   */
  template <class Interface, class... Arguments>
  class PluginRegistry
  {
  public:
    /** One registered plug-in. */
    struct Plugin
    {
      /** The value that selects it in the input (`Model = layered box`). */
      std::string name;
      /** One sentence for the documentation of the selecting entry. */
      std::string description;
      /** Declares its parameters (in the subsection the kind's owner has
       * entered; @p first_pass as in ParameterFile::read, may be null). */
      std::function<void(ParameterHandler &prm, ParameterHandler *first_pass)>
        declare;
      /** Makes one. */
      std::function<std::unique_ptr<Interface>(Arguments...)> create;
      /** Where it comes in plugins() (the calling order of loads and
       * postprocessors); equal positions are in name order. */
      int position = 0;
    };

    /** Add @p plugin; returns true (for the registration's static
     * initialiser). Two plug-ins of a kind may not share a name. */
    static bool
    add(Plugin plugin)
    {
      std::vector<Plugin> &all = storage();
      for (const Plugin &p : all)
        if (p.name == plugin.name)
          throw std::logic_error("two plug-ins are registered as <" +
                                 plugin.name + ">");
      all.push_back(std::move(plugin));
      std::sort(all.begin(), all.end(), [](const Plugin &a, const Plugin &b) {
        return std::tie(a.position, a.name) < std::tie(b.position, b.name);
      });
      return true;
    }

    /** Every registered plug-in, by position and name. */
    static const std::vector<Plugin> &
    plugins()
    {
      return storage();
    }

    /** The names, joined by @p separator: `a|b|c` for a
     * Patterns::Selection, `a, b, c` for a message. */
    static std::string
    names(const std::string &separator = "|")
    {
      std::string joined;
      for (const Plugin &p : storage())
        joined += (joined.empty() ? "" : separator) + p.name;
      return joined;
    }

    /** The names with their descriptions, for the documentation of the
     * selecting entry: "a: what a is; b: ...". */
    static std::string
    documentation()
    {
      std::string text;
      for (const Plugin &p : storage())
        text += (text.empty() ? "" : "; ") + p.name + ": " + p.description;
      return text;
    }

    /** Declare the parameters of every plug-in. */
    static void
    declare_parameters(ParameterHandler &prm,
                       ParameterHandler *first_pass = nullptr)
    {
      for (const Plugin &p : storage())
        if (p.declare)
          p.declare(prm, first_pass);
    }

    /** Whether a plug-in is called @p name. */
    static bool
    has(const std::string &name)
    {
      for (const Plugin &p : storage())
        if (p.name == name)
          return true;
      return false;
    }

    /** The plug-in called @p name; an InputError naming @p entry (the
     * selecting entry) and the registered names if there is none. */
    static const Plugin &
    find(const std::string &name, const std::string &entry)
    {
      for (const Plugin &p : storage())
        if (p.name == name)
          return p;
      throw_input_error(entry, "<" + name + "> is not one of " + names(", "));
    }

  private:
    static std::vector<Plugin> &
    storage()
    {
      static std::vector<Plugin> all;
      return all;
    }
  };

  /** Joins two tokens after expanding them (for unique registration
   * names). */
#define LITHOSTRESS_JOIN_TOKENS_(a, b) a##b
#define LITHOSTRESS_JOIN_TOKENS(a, b) LITHOSTRESS_JOIN_TOKENS_(a, b)

  /**
   * Register a plug-in of kind @p registry (a PluginRegistry) with the
   * fields of PluginRegistry::Plugin in braces; used by the kinds' own
   * macros (LITHOSTRESS_REGISTER_GEOMETRY, ...), one line per plug-in.
   */
#define LITHOSTRESS_REGISTER_PLUGIN(registry, ...)                    \
  namespace                                                           \
  {                                                                   \
    [[maybe_unused]] const bool                                       \
      LITHOSTRESS_JOIN_TOKENS(lithostress_registered_,                \
                              __LINE__) = registry::add(__VA_ARGS__); \
  }
} // namespace lithostress

#endif

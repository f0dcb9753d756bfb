#include <deal.II/base/utilities.h>

#include <lithostress/base/renamed_entries.h>

#include <sstream>

namespace lithostress
{
  const std::vector<RenamedEntry> &
  renamed_entries()
  {
    // One gravity for the whole model (2c42bf2): every gravity term takes
    // g and the depth origin from `Gravity field`.
    static const std::string               one_gravity = "2026-11-26, 2c42bf2";
    static const std::vector<RenamedEntry> table       = {
            {"Loads/Gravity/Acceleration", "Gravity field/Acceleration", one_gravity},
            {"Convergence study/Lithostatic column/Gravity",
             "Gravity field/Acceleration",
             one_gravity},
            {"Loads/Isostatic restoring force/Gravity",
             "Gravity field/Acceleration",
             one_gravity},
            {"Loads/Density stripping/Gravity",
             "Gravity field/Acceleration",
             one_gravity},
            {"Loads/Density stripping/Depth origin",
             "Gravity field/Depth origin",
             one_gravity},
            {"Griffith failure/Gravity", "Gravity field/Acceleration", one_gravity},
            {"Griffith failure/Depth origin",
             "Gravity field/Depth origin",
             one_gravity},
            {"Thin plate comparison/Gravity",
             "Gravity field/Acceleration",
             one_gravity},
            {"Faults/<name>/Gravity", "Gravity field/Acceleration", one_gravity}};
    return table;
  }

  const std::vector<RenamedValue> &
  renamed_values()
  {
    static const std::vector<RenamedValue> table = {
      {"Time stepping/Scheme",
       "implicit",
       "generalized midpoint",
       "2026-11-25, dc58760"},
      {"Faults/Sliding solver/Linear solver",
       "GMRES with AMG",
       "AMG",
       "2026-11-26, db2b233"}};
    return table;
  }

  namespace
  {
    /** Whether @p path matches @p pattern, component by component, with
     * `<name>` matching any one component. */
    bool
    path_matches(const std::vector<std::string> &path,
                 const std::string              &pattern)
    {
      const std::vector<std::string> parts =
        dealii::Utilities::split_string_list(pattern, '/');
      if (parts.size() != path.size())
        return false;
      for (unsigned int i = 0; i < parts.size(); ++i)
        if (parts[i] != "<name>" && parts[i] != path[i])
          return false;
      return true;
    }

    /** The message for setting @p path to @p value; empty if neither the
     * entry nor the value was renamed, or if @p parser_message (when not
     * null) does not name the entry or the value: deal.II writes "No entry
     * with name <Acceleration>", "The string <implicit> does not match"
     * (a set()) and "The entry value implicit for the entry named Scheme"
     * (a file). */
    std::string
    message_for(const std::vector<std::string> &path,
                const std::string              &value,
                const std::string              *parser_message = nullptr)
    {
      const auto named = [&](const std::string &token) {
        return parser_message == nullptr ||
               parser_message->find("<" + token + ">") != std::string::npos;
      };
      std::string where;
      for (const std::string &p : path)
        where += (where.empty() ? "" : "/") + p;
      for (const RenamedEntry &r : renamed_entries())
        if (path_matches(path, r.old_path) && named(path.back()))
          return "the entry <" + where + "> has moved to <" + r.new_path +
                 "> (since " + r.since + "); set it there";
      for (const RenamedValue &r : renamed_values())
        if (path_matches(path, r.entry) && value == r.old_value &&
            (named(r.old_value) ||
             parser_message->find("value " + r.old_value +
                                  " for the entry named " + path.back()) !=
               std::string::npos))
          return where + " = <" + r.old_value + "> is now called <" +
                 r.new_value + "> (since " + r.since + "); set that";
      return "";
    }
  } // namespace

  std::string
  renamed_entry_message(const std::string &contents,
                        const std::string &filename,
                        const std::string &parser_message)
  {
    std::istringstream       in(contents);
    std::string              line;
    std::vector<std::string> sections;
    for (unsigned int number = 1; std::getline(in, line); ++number)
      {
        line = dealii::Utilities::trim(line.substr(0, line.find('#')));
        if (line.rfind("subsection ", 0) == 0)
          sections.push_back(dealii::Utilities::trim(line.substr(11)));
        else if (line == "end" && !sections.empty())
          sections.pop_back();
        else if (line.rfind("set ", 0) == 0 &&
                 line.find('=') != std::string::npos)
          {
            const auto               equal = line.find('=');
            std::vector<std::string> path  = sections;
            path.push_back(dealii::Utilities::trim(line.substr(4, equal - 4)));
            const std::string message =
              message_for(path,
                          dealii::Utilities::trim(line.substr(equal + 1)),
                          &parser_message);
            if (!message.empty())
              return filename + ":" + std::to_string(number) + ": " + message;
          }
      }
    return "";
  }

  std::string
  renamed_override_message(const std::string &assignment)
  {
    const auto equal = assignment.find('=');
    if (equal == std::string::npos)
      return "";
    std::vector<std::string> path =
      dealii::Utilities::split_string_list(assignment.substr(0, equal), '/');
    const std::string message =
      message_for(path, dealii::Utilities::trim(assignment.substr(equal + 1)));
    return message.empty() ? "" : "override <" + assignment + ">: " + message;
  }
} // namespace lithostress

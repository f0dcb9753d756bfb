#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/base/renamed_entries.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

namespace lithostress
{
  std::string
  one_line(const std::string &text)
  {
    std::string result;
    for (const char c : text)
      {
        const char d = (c == '\n' || c == '\t') ? ' ' : c;
        if (d == ' ' && (result.empty() || result.back() == ' '))
          continue;
        result += d;
      }
    while (!result.empty() && result.back() == ' ')
      result.pop_back();
    return result;
  }

  std::string
  one_line_message(const ExceptionBase &exc)
  {
    std::ostringstream text;
    exc.print_info(text);
    return one_line(text.str());
  }

  double
  parse_number(const std::string &text, const std::string &entry)
  {
    const std::string trimmed = Utilities::trim(text);
    try
      {
        std::size_t  used  = 0;
        const double value = std::stod(trimmed, &used);
        if (used == trimmed.size() && std::isfinite(value))
          return value;
      }
    catch (const std::exception &)
      {
      }
    throw_input_error(entry, "<" + text + "> is not a finite number");
  }

  std::vector<std::string>
  split_list(const std::string &text, const char separator)
  {
    std::vector<std::string> items;
    std::string              item;
    std::istringstream       stream(text);
    while (std::getline(stream, item, separator))
      {
        item = Utilities::trim(item);
        if (!item.empty())
          items.push_back(item);
      }
    return items;
  }

  template <int dim>
  std::vector<Point<dim>>
  parse_point_list(const std::string &text,
                   const std::string &entry,
                   const double       scale)
  {
    std::vector<Point<dim>> points;
    for (const std::string &item : split_list(text, ';'))
      {
        const std::vector<std::string> coordinates = split_list(item, ',');
        if (coordinates.size() != dim)
          throw_input_error(entry,
                            "the point <" + item + "> does not have " +
                              std::to_string(dim) + " coordinates");
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = parse_number(coordinates[d], entry) * scale;
        points.push_back(p);
      }
    return points;
  }

  namespace
  {
    /** An entry or section name as ParameterHandler stores it (every
     * character but letters and digits as _ and two hex digits) in words. */
    std::string
    demangle(const std::string &name)
    {
      std::string out;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size() &&
            std::isxdigit(static_cast<unsigned char>(name[i + 1])) &&
            std::isxdigit(static_cast<unsigned char>(name[i + 2])))
          {
            out +=
              static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          out += name[i];
      return out;
    }

    /** Check the numbers of the entries below @p tree, whose path is
     * @p path (ParameterFile::check_numbers). */
    void
    check_numbers_below(const boost::property_tree::ptree &tree,
                        const std::string                 &path)
    {
      for (const auto &[key, child] : tree)
        {
          const std::string name = path + demangle(key);
          const auto        pattern =
            child.get_optional<std::string>("pattern_description");
          const auto value = child.get_optional<std::string>("value");
          if (!pattern || !value)
            {
              check_numbers_below(child, name + "/");
              continue;
            }
          const bool is_double  = pattern->rfind("[Double", 0) == 0;
          const bool is_integer = pattern->rfind("[Integer", 0) == 0;
          if (!is_double && !is_integer)
            continue;
          bool fits = true;
          try
            {
              if (is_double)
                fits = std::isfinite(Utilities::string_to_double(*value));
              else
                Utilities::string_to_int(*value);
            }
          catch (...)
            {
              fits = false;
            }
          if (!fits)
            throw_input_error(name,
                              "<" + *value + "> does not fit " +
                                (is_double
                                   ? std::string("a double (magnitudes from "
                                                 "2.3e-308 to 1.8e308, or 0)")
                                   : std::string("an int")));
        }
    }

    /** The InputError for the parser's error @p exc in the file @p filename
     * with text @p contents: where the file sets an entry that was renamed
     * or moved, the line that says where it went (the parser only knows
     * that the old name is not declared); otherwise the parser's message. */
    [[noreturn]] void
    throw_input_error_of_file(const std::string   &contents,
                              const std::string   &filename,
                              const ExceptionBase &exc)
    {
      const std::string parser = one_line_message(exc);
      const std::string renamed =
        renamed_entry_message(contents, filename, parser);
      throw InputError(renamed.empty() ? parser : renamed);
    }
  } // namespace

  std::vector<std::string>
  ParameterFile::names_from(ParameterHandler               *first_pass,
                            const std::vector<std::string> &path,
                            const std::string              &entry,
                            const std::vector<std::string> &example)
  {
    if (first_pass == nullptr)
      return example;
    for (const std::string &section : path)
      first_pass->enter_subsection(section);
    const std::vector<std::string> names = split_list(first_pass->get(entry));
    for (unsigned int i = 0; i < path.size(); ++i)
      first_pass->leave_subsection();
    return names;
  }

  void
  ParameterFile::apply_override(ParameterHandler  &prm,
                                const std::string &assignment)
  {
    const auto equal = assignment.find('=');
    if (equal == std::string::npos)
      throw InputError("override <" + assignment +
                       "> is not of the form Section/Entry=value");
    const std::vector<std::string> path =
      split_list(assignment.substr(0, equal), '/');
    const std::string value = Utilities::trim(assignment.substr(equal + 1));
    if (path.empty())
      throw InputError("override <" + assignment + "> names no entry");
    unsigned int entered = 0;
    try
      {
        for (unsigned int i = 0; i + 1 < path.size(); ++i, ++entered)
          prm.enter_subsection(path[i]);
        prm.set(path.back(), value);
      }
    catch (const ExceptionBase &exc)
      {
        for (unsigned int i = 0; i < entered; ++i)
          prm.leave_subsection();
        const std::string renamed = renamed_override_message(assignment);
        if (!renamed.empty())
          throw InputError(renamed);
        throw InputError("override <" + assignment +
                         ">: " + one_line_message(exc));
      }
    for (unsigned int i = 0; i < entered; ++i)
      prm.leave_subsection();
  }

  void
  ParameterFile::read(const std::string              &filename,
                      const std::vector<std::string> &overrides,
                      const Declaration              &declare,
                      ParameterHandler               &prm)
  {
    std::ifstream file(filename);
    if (!file)
      throw InputError("cannot open the parameter file <" + filename + ">");
    std::ostringstream contents;
    contents << file.rdbuf();

    ParameterHandler first_pass;
    declare(first_pass, nullptr);
    try
      {
        std::istringstream in(contents.str());
        first_pass.parse_input(in, filename, "", true);
      }
    catch (const ExceptionBase &exc)
      {
        throw_input_error_of_file(contents.str(), filename, exc);
      }
    for (const std::string &o : overrides)
      {
        // Overrides of user-named subsections cannot be applied yet.
        try
          {
            apply_override(first_pass, o);
          }
        catch (const InputError &)
          {
          }
      }

    declare(prm, &first_pass);
    try
      {
        std::istringstream in(contents.str());
        prm.parse_input(in, filename, "", false);
      }
    catch (const ExceptionBase &exc)
      {
        throw_input_error_of_file(contents.str(), filename, exc);
      }
    for (const std::string &o : overrides)
      apply_override(prm, o);
    check_numbers(prm);
  }

  void
  ParameterFile::check_numbers(const ParameterHandler &prm)
  {
    std::stringstream json;
    prm.print_parameters(json, ParameterHandler::JSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);
    check_numbers_below(tree, "");
  }

  template std::vector<Point<2>>
  parse_point_list<2>(const std::string &, const std::string &, const double);
  template std::vector<Point<3>>
  parse_point_list<3>(const std::string &, const std::string &, const double);
} // namespace lithostress

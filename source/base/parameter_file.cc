#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/base/renamed_entries.h>

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
  }

  template std::vector<Point<2>>
  parse_point_list<2>(const std::string &, const std::string &, const double);
  template std::vector<Point<3>>
  parse_point_list<3>(const std::string &, const std::string &, const double);
} // namespace lithostress

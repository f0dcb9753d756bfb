#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <fstream>

namespace lithostress
{
  namespace
  {
    /** The 1-based line of @p text with a non-finite number ("nan", "inf",
     * "-nan", "infinity" as a whole token), or 0. */
    unsigned int
    line_with_non_finite_number(const std::string &text)
    {
      unsigned int line = 1;
      std::string  token;
      const auto   non_finite = [&]() {
        std::string t = token;
        std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) {
          return std::tolower(c);
        });
        if (!t.empty() && (t[0] == '-' || t[0] == '+'))
          t.erase(0, 1);
        return t == "nan" || t == "inf" || t == "infinity";
      };
      for (const char c : text)
        {
          const bool separator = std::isspace(static_cast<unsigned char>(c)) ||
                                 c == ',' || c == ';' || c == ':' || c == '"' ||
                                 c == '[' || c == ']' || c == '{' || c == '}' ||
                                 c == '(' || c == ')' || c == '=';
          if (!separator)
            {
              token += c;
              continue;
            }
          if (non_finite())
            return line;
          token.clear();
          if (c == '\n')
            ++line;
        }
      return non_finite() ? line : 0;
    }
  } // namespace

  OutputFile::OutputFile(const std::string &file_name, const Content content)
      : file_name(file_name)
      , content(content)
  {
  }

  void
  OutputFile::commit()
  {
    write_file_atomically(file_name, str(), content == text);
  }

  void
  write_file_atomically(const std::string &file_name,
                        const std::string &text,
                        const bool         check_numbers)
  {
    if (const unsigned int line =
          check_numbers ? line_with_non_finite_number(text) : 0)
      throw ComputationError("a non-finite number (NaN or infinity) would "
                             "be written to <" +
                             file_name + "> in line " + std::to_string(line) +
                             "; the file is left as it was");
    const std::string temporary =
      file_name + ".part-" + std::to_string(getpid());
    {
      std::ofstream out(temporary, std::ios::binary);
      out << text;
      out.flush();
      if (!out)
        {
          std::remove(temporary.c_str());
          throw ComputationError("cannot write <" + file_name + ">");
        }
    }
    if (std::rename(temporary.c_str(), file_name.c_str()) != 0)
      {
        std::remove(temporary.c_str());
        throw ComputationError("cannot rename the complete <" + temporary +
                               "> to <" + file_name + ">");
      }
  }
} // namespace lithostress

#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>

#include <deal.II/base/mpi.h>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
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
  void
  check_output_directory(const std::string &directory,
                         const MPI_Comm     communicator)
  {
    std::string problem;
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(directory, error);
        if (error)
          problem = "cannot create it: " + error.message();
        else
          {
            const std::string probe = directory + "/.write-test";
            std::ofstream     out(probe);
            if (!out)
              problem = "cannot write into it";
            out.close();
            std::filesystem::remove(probe, error);
          }
      }
    problem = dealii::Utilities::MPI::broadcast(communicator, problem, 0);
    if (!problem.empty())
      throw_input_error("Output directory", "<" + directory + ">: " + problem);
  }
} // namespace lithostress

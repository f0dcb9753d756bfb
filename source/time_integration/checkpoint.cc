#include <deal.II/base/mpi.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>
#include <lithostress/time_integration/checkpoint.h>

#include <boost/archive/archive_exception.hpp>
#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace lithostress
{
  std::string
  Checkpoint::model_text(ParameterHandler &prm)
  {
    std::ostringstream all;
    prm.print_parameters(all, ParameterHandler::ShortPRM);
    std::istringstream lines(all.str());
    std::ostringstream model;
    std::string        line;
    unsigned int       depth = 0, skipped_from = 0;
    bool               skipping = false;
    while (std::getline(lines, line))
      {
        const std::string trimmed = Utilities::trim(line);
        if (trimmed.rfind("subsection ", 0) == 0)
          {
            ++depth;
            const std::string name = Utilities::trim(trimmed.substr(11));
            if (!skipping && depth == 1 &&
                (name == "Time stepping" || name == "Output" ||
                 name == "Solver" || name == "Resources"))
              {
                skipping     = true;
                skipped_from = depth;
              }
          }
        else if (trimmed == "end")
          {
            if (skipping && depth == skipped_from)
              {
                skipping = false;
                --depth;
                continue;
              }
            --depth;
          }
        else if (depth == 0 && trimmed.rfind("set Output directory", 0) == 0)
          continue;
        if (!skipping && !trimmed.empty())
          model << trimmed << '\n';
      }
    return model.str();
  }

  namespace
  {
    /** The first line of state.txt: the format of what follows. */
    // 4: the model text holds each material's Rheology (2026-12-01);
    // 5: the faults' named history; 6: the names of the cell history's
    // components (2026-12-02).
    const std::string state_format = "lithostress-checkpoint 6";
  } // namespace

  void
  Checkpoint::write_state(const std::string &directory,
                          const LoopState   &state,
                          const std::string &model_text)
  {
    std::ostringstream text;
    text << state_format << '\n';
    {
      // Doubles are written with all digits: they are read back exactly.
      boost::archive::text_oarchive archive(text);
      archive << state;
    }
    write_file_atomically(directory + "/state.txt", text.str(), false);
    write_file_atomically(directory + "/model.prm", model_text, false);
  }

  LoopState
  Checkpoint::read_state(const std::string &directory)
  {
    const std::string file = directory + "/state.txt";
    std::ifstream     in(file);
    std::string       first;
    std::getline(in, first);
    if (first != state_format)
      throw ComputationError("the checkpoint " + file + " has format <" +
                             first + ">; this lithostress reads <" +
                             state_format + "> (start the run anew)");
    LoopState state;
    try
      {
        boost::archive::text_iarchive archive(in);
        archive >> state;
      }
    catch (const boost::archive::archive_exception &e)
      {
        throw ComputationError("the checkpoint " + file + " is damaged (" +
                               e.what() + ")");
      }
    return state;
  }

  std::string
  Checkpoint::current(const std::string &output_directory)
  {
    std::ifstream pointer(output_directory + "/checkpoint.current");
    std::string   name;
    if (!(pointer >> name))
      return "";
    return output_directory + "/" + name;
  }

  void
  Checkpoint::check_resumable(const std::string &output_directory,
                              ParameterHandler  &prm,
                              const MPI_Comm     communicator)
  {
    std::string problem;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        const std::string directory = current(output_directory);
        std::string       format;
        std::ifstream     saved(directory + "/model.prm");
        if (directory.empty())
          problem = "there is no checkpoint in " + output_directory +
                    " (no checkpoint.current)";
        else if (!saved)
          problem = "the checkpoint " + directory + " has no model.prm";
        else if (std::ifstream state(directory + "/state.txt");
                 state && std::getline(state, format) && format != state_format)
          problem = "the checkpoint " + directory +
                    " was written by another version of lithostress (format <" +
                    format + ">; this one reads <" + state_format +
                    ">): it cannot be resumed, start the run anew";
        else
          {
            std::stringstream text;
            text << saved.rdbuf();
            std::istringstream a(text.str()), b(model_text(prm));
            std::string        line_a, line_b;
            while (problem.empty())
              {
                const bool more_a = static_cast<bool>(std::getline(a, line_a));
                const bool more_b = static_cast<bool>(std::getline(b, line_b));
                if (!more_a && !more_b)
                  break;
                if (line_a != line_b || more_a != more_b)
                  problem = "the checkpoint " + directory +
                            " belongs to another model: it has <" +
                            (more_a ? line_a : std::string("(end)")) +
                            "> where this model has <" +
                            (more_b ? line_b : std::string("(end)")) + ">";
              }
          }
        if (problem.empty() && !directory.empty() &&
            !std::ifstream(directory + "/state.txt"))
          problem = "the checkpoint " + directory + " has no state.txt";
      }
    problem = Utilities::MPI::broadcast(communicator, problem, 0);
    if (!problem.empty())
      throw_input_error("Time stepping/Resume", problem);
  }

  void
  Checkpoint::make_current(const std::string &output_directory,
                           const std::string &directory)
  {
    const std::string name =
      std::filesystem::path(directory).filename().string();
    write_file_atomically(output_directory + "/checkpoint.current",
                          name + "\n");
    for (const auto &entry :
         std::filesystem::directory_iterator(output_directory))
      {
        const std::string other = entry.path().filename().string();
        if (entry.is_directory() && other.rfind("checkpoint-", 0) == 0 &&
            other != name)
          std::filesystem::remove_all(entry.path());
      }
  }
} // namespace lithostress

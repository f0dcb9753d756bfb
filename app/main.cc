/**
 * lithostress: stress and deformation in 2-D lithospheric cross sections.
 * The program entry point: command line, MPI, and the translation of input
 * errors into one clear message and a non-zero exit status.
 */
#include <deal.II/base/mpi.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/interruption.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/base/renamed_entries.h>
#include <lithostress/simulator/simulator.h>

#include <iostream>
#include <string>
#include <vector>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out
      << "lithostress — finite-element stress and deformation of 2-D\n"
         "lithospheric cross sections (deal.II, Q2 elements, p4est, "
         "Trilinos).\n"
         "\n"
         "Usage:\n"
         "  lithostress model.prm [--set 'Section/Entry=value' ...] "
         "[--resume]\n"
         "  mpirun -np N lithostress model.prm\n"
         "  lithostress --print-parameters        every parameter, with its\n"
         "                                        documentation, default and\n"
         "                                        allowed values (.prm "
         "format)\n"
         "  lithostress --print-parameters=json   the same as JSON (used to\n"
         "                                        generate doc/parameters.md)\n"
         "  lithostress --print-renamed-entries   the entries and values that\n"
         "                                        were renamed or moved (tab-\n"
         "                                        separated: old, new, since)\n"
         "  lithostress --help                    this text\n"
         "\n"
         "Results go to the `Output directory` of the .prm: ParaView files\n"
         "(solution.pvd), parameters.prm as run, log.txt, convergence.csv\n"
         "(one row per cycle) and statistics.json. See README.md and doc/.\n";
  }

  void
  declare(dealii::ParameterHandler &prm, dealii::ParameterHandler *first_pass)
  {
    lithostress::Simulator<2>::declare_parameters(prm, first_pass);
  }
} // namespace

int
main(int argc, char *argv[])
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  std::vector<std::string> args(argv + 1, argv + argc);
  std::string              prm_file;
  std::vector<std::string> overrides;
  for (unsigned int i = 0; i < args.size(); ++i)
    {
      const std::string &a = args[i];
      if (a == "--help" || a == "-h")
        {
          if (root)
            print_usage(std::cout);
          return 0;
        }
      if (a == "--print-parameters" || a == "--print-parameters=json")
        {
          ParameterHandler prm;
          declare(prm, nullptr);
          if (root)
            prm.print_parameters(std::cout,
                                 a == "--print-parameters"
                                   ? ParameterHandler::PRM
                                   : ParameterHandler::JSON);
          return 0;
        }
      if (a == "--print-renamed-entries")
        {
          if (root)
            {
              for (const auto &r : lithostress::renamed_entries())
                std::cout << r.old_path << '\t' << r.new_path << '\t' << r.since
                          << '\n';
              for (const auto &r : lithostress::renamed_values())
                std::cout << r.entry << " = " << r.old_value << '\t' << r.entry
                          << " = " << r.new_value << '\t' << r.since << '\n';
            }
          return 0;
        }
      if (a == "--resume")
        {
          overrides.push_back("Time stepping/Resume=true");
          continue;
        }
      if (a == "--set")
        {
          if (i + 1 >= args.size())
            {
              if (root)
                std::cerr << "lithostress: --set needs 'Section/Entry=value'\n";
              return 1;
            }
          overrides.push_back(args[++i]);
          continue;
        }
      if (!a.empty() && a[0] == '-')
        {
          if (root)
            std::cerr << "lithostress: unknown option <" << a
                      << ">; see lithostress --help\n";
          return 1;
        }
      if (!prm_file.empty())
        {
          if (root)
            std::cerr << "lithostress: more than one parameter file given\n";
          return 1;
        }
      prm_file = a;
    }
  if (prm_file.empty())
    {
      if (root)
        {
          std::cerr << "lithostress: no parameter file given\n\n";
          print_usage(std::cerr);
        }
      return 1;
    }

  lithostress::interruption::install_handlers();
  try
    {
      ParameterHandler prm;
      lithostress::ParameterFile::read(prm_file, overrides, declare, prm);
      lithostress::Simulator<2> simulator(MPI_COMM_WORLD, prm);
      simulator.run();
    }
  catch (const lithostress::InputError &error)
    {
      if (root)
        std::cerr << "lithostress: error in the input: " << error.what()
                  << std::endl;
      return 1;
    }
  catch (const lithostress::ComputationError &error)
    {
      if (root)
        std::cerr << "lithostress: the computation failed: " << error.what()
                  << std::endl;
      return 3;
    }
  catch (const lithostress::RunInterrupted &stop)
    {
      if (root)
        std::cerr << "lithostress: " << stop.what() << std::endl;
      return 128 + stop.signal();
    }
  catch (const std::exception &error)
    {
      // Not known to be collective: the other ranks may be waiting in a
      // communication this rank has left, so end them all. deal.II's
      // what() carries the file, the condition and a stack trace: the one
      // line is its message.
      const auto *dealii_error =
        dynamic_cast<const dealii::ExceptionBase *>(&error);
      std::cerr << "lithostress: internal error: "
                << (dealii_error ? lithostress::one_line_message(*dealii_error)
                                 : lithostress::one_line(error.what()))
                << std::endl;
      if (Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        MPI_Abort(MPI_COMM_WORLD, 2);
      return 2;
    }
  return 0;
}

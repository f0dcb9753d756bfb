#include <lithostress/base/run_log.h>

#include <iostream>

namespace lithostress
{
  RunLog::RunLog(const MPI_Comm communicator)
      : is_root(Utilities::MPI::this_mpi_process(communicator) == 0)
  {
  }

  void
  RunLog::open(const std::string &filename)
  {
    if (!is_root)
      return;
    file.open(filename);
    file << before_open << std::flush;
    before_open.clear();
  }

  void
  RunLog::write(const std::string &text)
  {
    std::cout << text;
    if (file.is_open())
      file << text << std::flush;
    else
      before_open += text;
  }

  RunLog &
  RunLog::operator<<(std::ostream &(*manipulator)(std::ostream &))
  {
    if (is_root)
      {
        manipulator(std::cout);
        if (file.is_open())
          manipulator(file);
        else
          {
            std::ostringstream text;
            manipulator(text);
            before_open += text.str();
          }
      }
    return *this;
  }
} // namespace lithostress

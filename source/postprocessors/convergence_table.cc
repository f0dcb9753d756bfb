#include <lithostress/postprocessors/convergence_table.h>

#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  ConvergenceTableReport<dim>::finish(const SimulatorAccess<dim> &access)
  {
    if (access.convergence_study.empty())
      return;
    std::ostringstream table;
    access.convergence_study.print(table);
    access.log << "\nConvergence table (rates in DoFs; for errors "
                  "rate = -dlog(e)/dlog(N)):\n"
               << table.str();
  }

  template class ConvergenceTableReport<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(
    ConvergenceTableReport,
    "convergence table",
    "the convergence table with rates (convergence.csv)",
    10)
} // namespace lithostress

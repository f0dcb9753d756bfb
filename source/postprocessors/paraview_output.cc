#include <lithostress/postprocessors/paraview_output.h>

#include <iomanip>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  ParaviewOutput<dim>::declare_parameters(ParameterHandler &prm)
  {
    SolutionOutput<dim>::declare_parameters(prm);
  }

  template <int dim>
  void
  ParaviewOutput<dim>::parse_parameters(ParameterHandler &prm,
                                        const SimulatorAccess<dim> &)
  {
    output.parse_parameters(prm);
  }

  template <int dim>
  void
  ParaviewOutput<dim>::cycle_output(const SimulatorAccess<dim> &a,
                                    const unsigned int          cycle,
                                    const bool                  last)
  {
    TimerOutput::Scope t(a.timer, "output");
    if (!output.last_only || last)
      output.write(a.output_directory,
                   cycle,
                   cycle,
                   a.dof_handler,
                   a.fe_space,
                   a.stress_model,
                   a.griffith,
                   a.solution);
  }

  template <int dim>
  void
  ParaviewOutput<dim>::output_time(const SimulatorAccess<dim> &a,
                                   const unsigned int          index,
                                   const double                time)
  {
    output.write(a.output_directory,
                 index,
                 time,
                 a.dof_handler,
                 a.fe_space,
                 a.stress_model,
                 a.griffith,
                 a.solution);
  }

  template <int dim>
  void
  ParaviewOutput<dim>::save(std::map<std::string, std::string> &state) const
  {
    std::ostringstream records;
    for (const auto &[time, file] : output.records)
      records << std::hexfloat << time << ' ' << file << '\n';
    state["paraview_records"] = records.str();
  }

  template <int dim>
  void
  ParaviewOutput<dim>::load(const SimulatorAccess<dim> &,
                            const std::map<std::string, std::string> &state)
  {
    output.records.clear();
    const auto found = state.find("paraview_records");
    if (found == state.end())
      return;
    std::istringstream records(found->second);
    std::string        time, file;
    while (records >> time >> file)
      output.records.emplace_back(std::stod(time), file);
  }

  template class ParaviewOutput<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(
    ParaviewOutput,
    "paraview",
    "ParaView files of the solution and stress",
    50)
} // namespace lithostress

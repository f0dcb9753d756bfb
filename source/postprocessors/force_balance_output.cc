#include <lithostress/base/input_error.h>
#include <lithostress/analysis/force_balance.h>
#include <lithostress/postprocessors/force_balance_output.h>

namespace lithostress
{
  template <int dim>
  void
  ForceBalanceOutput<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Force balance",
                      "true",
                      Patterns::Bool(),
                      "After the last cycle, print the resultant of every "
                      "load and the reaction of every part with prescribed "
                      "displacement, and write force_balance.csv [N/m]; "
                      "costs one more assembly.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ForceBalanceOutput<dim>::parse_parameters(ParameterHandler &prm,
                                            const SimulatorAccess<dim> &)
  {
    prm.enter_subsection("Output");
    enabled = prm.get_bool("Force balance");
    prm.leave_subsection();
  }

  template <int dim>
  void
  ForceBalanceOutput<dim>::finish(const SimulatorAccess<dim> &a)
  {
    if (!enabled)
      return;
    TimerOutput::Scope      t(a.timer, "force balance");
    const ForceBalance<dim> balance =
      compute_force_balance(a.dof_handler,
                            a.fe_space,
                            a.stress_model,
                            a.loads,
                            a.prescribed_displacement,
                            a.solution);
    a.log << '\n' << balance.table();
    on_all_ranks(a.communicator, [&]() {
      if (a.root())
        balance.write_csv(a.path("force_balance.csv"));
    });
  }

  template class ForceBalanceOutput<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(
    ForceBalanceOutput,
    "force balance",
    "reactions against loads (force_balance.csv)",
    60)
} // namespace lithostress

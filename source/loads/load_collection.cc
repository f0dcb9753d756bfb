#include <lithostress/base/input_error.h>
#include <lithostress/loads/load_collection.h>

namespace lithostress
{
  template <int dim>
  void
  LoadCollection<dim>::declare_parameters(ParameterHandler &prm,
                                          ParameterHandler *first_pass)
  {
    prm.enter_subsection("Loads");
    LoadRegistry<dim>::declare_parameters(prm, first_pass);
    prm.leave_subsection();
  }

  template <int dim>
  void
  LoadCollection<dim>::parse_parameters(ParameterHandler            &prm,
                                        const ModelDescription<dim> &model)
  {
    active.clear();
    prm.enter_subsection("Loads");
    for (const auto &plugin : LoadRegistry<dim>::plugins())
      {
        std::unique_ptr<Load<dim>> load = plugin.create();
        if (load->parse_parameters(prm, model))
          active.push_back(std::move(load));
      }
    prm.leave_subsection();
    unsigned int body_forces = 0;
    stripped                 = false;
    for (const auto &load : active)
      {
        body_forces += load->is_body_force() ? 1 : 0;
        stripped = stripped || load->strips_densities();
      }
    if (body_forces > 1 && stripped)
      throw_input_error("Loads/Density stripping/Reference column",
                        "cannot be combined with Loads/Gravity/Enabled = "
                        "true: the stripped body force replaces gravity");
    body_force_absent = body_forces == 0;
  }

  template <int dim>
  bool
  LoadCollection<dim>::balances_vertical_loads() const
  {
    for (const auto &load : active)
      if (load->balances_vertical_loads())
        return true;
    return false;
  }

  template <int dim>
  void
  LoadCollection<dim>::balance(const std::vector<Tensor<1, dim>> &resultants)
  {
    AssertDimension(resultants.size(), active.size());
    double upthrust = 0;
    for (unsigned int l = 0; l < active.size(); ++l)
      if (!active[l]->balances_vertical_loads())
        upthrust += resultants[l][dim - 1];
    for (const auto &load : active)
      if (load->balances_vertical_loads())
        load->balance(upthrust);
  }

  template <int dim>
  std::map<types::boundary_id, double>
  LoadCollection<dim>::vertical_springs(
    const std::vector<types::boundary_id> &boundary_ids) const
  {
    std::map<types::boundary_id, double> springs;
    for (const types::boundary_id id : boundary_ids)
      for (const auto &load : active)
        if (load->vertical_spring_stiffness(id) != 0)
          springs[id] += load->vertical_spring_stiffness(id);
    return springs;
  }

  template <int dim>
  bool
  LoadCollection<dim>::stiffness_is_vertical_springs() const
  {
    for (const auto &load : active)
      if (!load->stiffness_is_vertical_spring())
        return false;
    return true;
  }

  template class LoadCollection<2>;
} // namespace lithostress

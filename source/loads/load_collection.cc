#include <lithostress/base/input_error.h>
#include <lithostress/loads/boundary_traction.h>
#include <lithostress/loads/density_stripping.h>
#include <lithostress/loads/gravity.h>
#include <lithostress/loads/isostatic_restoring_force.h>
#include <lithostress/loads/line_force.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/loads/slab_pull.h>
#include <lithostress/loads/thermal_strain.h>

namespace lithostress
{
  template <int dim>
  void
  LoadCollection<dim>::declare_parameters(ParameterHandler &prm,
                                          ParameterHandler *first_pass)
  {
    prm.enter_subsection("Loads");
    Gravity<dim>::declare_parameters(prm);
    DensityStripping<dim>::declare_parameters(prm);
    ThermalStrain<dim>::declare_parameters(prm);
    BoundaryTraction<dim>::declare_parameters(prm, first_pass);
    IsostaticRestoringForce<dim>::declare_parameters(prm);
    LineForce<dim>::declare_parameters(prm);
    SlabPull<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  void
  LoadCollection<dim>::parse_parameters(ParameterHandler            &prm,
                                        const ModelDescription<dim> &model)
  {
    active.clear();
    prm.enter_subsection("Loads");
    auto       gravity      = std::make_unique<Gravity<dim>>();
    const bool with_gravity = gravity->parse_parameters(prm, model);
    if (with_gravity)
      active.push_back(std::move(gravity));
    auto stripping = std::make_unique<DensityStripping<dim>>();
    stripped       = stripping->parse_parameters(prm, model);
    if (stripped && with_gravity)
      throw_input_error("Loads/Density stripping/Reference column",
                        "cannot be combined with Loads/Gravity/Enabled = "
                        "true: the stripped body force replaces gravity");
    if (stripped)
      active.push_back(std::move(stripping));
    body_force_absent = !with_gravity && !stripped;
    auto thermal      = std::make_unique<ThermalStrain<dim>>();
    if (thermal->parse_parameters(prm))
      active.push_back(std::move(thermal));
    auto traction = std::make_unique<BoundaryTraction<dim>>();
    traction->parse_parameters(prm, model);
    if (!traction->empty())
      active.push_back(std::move(traction));
    auto restoring = std::make_unique<IsostaticRestoringForce<dim>>();
    restoring->parse_parameters(prm, model);
    if (!restoring->empty())
      active.push_back(std::move(restoring));
    auto line_force = std::make_unique<LineForce<dim>>();
    line_force->parse_parameters(prm, model);
    if (!line_force->empty())
      active.push_back(std::move(line_force));
    auto slab_pull = std::make_unique<SlabPull<dim>>();
    if (slab_pull->parse_parameters(prm, model))
      active.push_back(std::move(slab_pull));
    prm.leave_subsection();
  }

  template <int dim>
  bool
  LoadCollection<dim>::balances_vertical_loads() const
  {
    for (const auto &load : active)
      if (const auto *pull = dynamic_cast<const SlabPull<dim> *>(load.get()))
        if (pull->balances_vertical_loads())
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
      if (dynamic_cast<const SlabPull<dim> *>(active[l].get()) == nullptr)
        upthrust += resultants[l][dim - 1];
    for (const auto &load : active)
      if (auto *pull = dynamic_cast<SlabPull<dim> *>(load.get()))
        if (pull->balances_vertical_loads())
          pull->balance(upthrust);
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

#include <lithostress/loads/boundary_traction.h>
#include <lithostress/loads/gravity.h>
#include <lithostress/loads/load_collection.h>

namespace lithostress
{
  template <int dim>
  void
  LoadCollection<dim>::declare_parameters(ParameterHandler &prm,
                                          ParameterHandler *first_pass)
  {
    prm.enter_subsection("Loads");
    Gravity<dim>::declare_parameters(prm);
    BoundaryTraction<dim>::declare_parameters(prm, first_pass);
    prm.leave_subsection();
  }

  template <int dim>
  void
  LoadCollection<dim>::parse_parameters(ParameterHandler &           prm,
                                        const ModelDescription<dim> &model)
  {
    active.clear();
    prm.enter_subsection("Loads");
    auto gravity = std::make_unique<Gravity<dim>>();
    if (gravity->parse_parameters(prm))
      active.push_back(std::move(gravity));
    auto traction = std::make_unique<BoundaryTraction<dim>>();
    traction->parse_parameters(prm, model);
    if (!traction->empty())
      active.push_back(std::move(traction));
    prm.leave_subsection();
  }

  template <int dim>
  bool
  LoadCollection<dim>::acts_on_boundary(const types::boundary_id id) const
  {
    for (const auto &load : active)
      if (load->acts_on_boundary(id))
        return true;
    return false;
  }

  template class LoadCollection<2>;
} // namespace lithostress

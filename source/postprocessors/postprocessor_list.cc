#include <lithostress/postprocessors/postprocessor.h>

namespace lithostress
{
  template <int dim>
  void
  PostprocessorList<dim>::declare_parameters(ParameterHandler &prm)
  {
    PostprocessorRegistry<dim>::declare_parameters(prm);
  }

  template <int dim>
  void
  PostprocessorList<dim>::parse_parameters(ParameterHandler           &prm,
                                           const SimulatorAccess<dim> &access)
  {
    postprocessors.clear();
    for (const auto &plugin : PostprocessorRegistry<dim>::plugins())
      {
        postprocessors.push_back(plugin.create());
        postprocessors.back()->parse_parameters(prm, access);
      }
  }

  template <int dim>
  void
  PostprocessorList<dim>::cycle_finished(const SimulatorAccess<dim> &access,
                                         const unsigned int          cycle,
                                         ConvergenceStudy           &study,
                                         std::ostream               &progress)
  {
    for (const auto &p : postprocessors)
      p->cycle_finished(access, cycle, study, progress);
  }

  template <int dim>
  void
  PostprocessorList<dim>::cycle_output(const SimulatorAccess<dim> &access,
                                       const unsigned int          cycle,
                                       const bool                  last)
  {
    for (const auto &p : postprocessors)
      p->cycle_output(access, cycle, last);
  }

  template <int dim>
  void
  PostprocessorList<dim>::output_time(const SimulatorAccess<dim> &access,
                                      const unsigned int          index,
                                      const double                time)
  {
    for (const auto &p : postprocessors)
      p->output_time(access, index, time);
  }

  template <int dim>
  void
  PostprocessorList<dim>::solve_failed(const SimulatorAccess<dim> &access)
  {
    for (const auto &p : postprocessors)
      p->solve_failed(access);
  }

  template <int dim>
  void
  PostprocessorList<dim>::finish(const SimulatorAccess<dim> &access)
  {
    for (const auto &p : postprocessors)
      p->finish(access);
  }

  template <int dim>
  void
  PostprocessorList<dim>::interrupted(const SimulatorAccess<dim> &access)
  {
    for (const auto &p : postprocessors)
      p->interrupted(access);
  }

  template <int dim>
  void
  PostprocessorList<dim>::save(std::map<std::string, std::string> &state) const
  {
    for (const auto &p : postprocessors)
      p->save(state);
  }

  template <int dim>
  void
  PostprocessorList<dim>::load(const SimulatorAccess<dim>               &access,
                               const std::map<std::string, std::string> &state)
  {
    for (const auto &p : postprocessors)
      p->load(access, state);
  }

  template class PostprocessorList<2>;
} // namespace lithostress

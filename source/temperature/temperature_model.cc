#include <lithostress/base/input_error.h>
#include <lithostress/temperature/temperature_model.h>

namespace lithostress
{
  template <int dim>
  void
  PointwiseTemperature<dim>::values(
    const typename Triangulation<dim>::active_cell_iterator &,
    const std::vector<Point<dim>> &points,
    std::vector<double>           &temperatures) const
  {
    temperatures.resize(points.size());
    for (unsigned int q = 0; q < points.size(); ++q)
      temperatures[q] = value(points[q]);
  }

  template <int dim>
  void
  TemperatureModel<dim>::check_against_mesh(const Triangulation<dim> &) const
  {
  }

  template <int dim>
  void
  TemperatureModel<dim>::attach_mesh(const TemperatureMesh<dim> &)
  {
  }

  template <int dim>
  void
  PointwiseTemperature<dim>::check_against_mesh(
    const Triangulation<dim> &tria) const
  {
    for (const auto &cell : tria.cell_iterators_on_level(0))
      {
        value(cell->center());
        for (const unsigned int v : cell->vertex_indices())
          value(cell->vertex(v));
      }
  }

  template <int dim>
  void
  TemperatureSelector<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Temperature");
    prm.declare_entry("Model",
                      "none",
                      Patterns::Selection("none|" +
                                          TemperatureRegistry<dim>::names()),
                      "The temperature of the section [K], read by "
                      "temperature-dependent laws and written with the "
                      "results. none: the model has no temperature; " +
                        TemperatureRegistry<dim>::documentation() + ".");
    TemperatureRegistry<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  std::unique_ptr<TemperatureModel<dim>>
  TemperatureSelector<dim>::create(ParameterHandler &prm,
                                   const double      length_scale)
  {
    prm.enter_subsection("Temperature");
    const std::string                      name = prm.get("Model");
    std::unique_ptr<TemperatureModel<dim>> model;
    if (name != "none")
      {
        model =
          TemperatureRegistry<dim>::find(name, "Temperature/Model").create();
        model->parse_parameters(prm, length_scale);
      }
    prm.leave_subsection();
    return model;
  }

  template class TemperatureModel<2>;
  template class PointwiseTemperature<2>;
  template class TemperatureSelector<2>;
} // namespace lithostress

#include <lithostress/base/input_error.h>
#include <lithostress/geometry/geometry_model.h>

namespace lithostress
{
  template <int dim>
  void
  GeometrySelector<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry("Model",
                      "rectangular block",
                      Patterns::Selection(GeometryRegistry<dim>::names()),
                      "The geometry: a built-in generator or a Gmsh mesh. " +
                        GeometryRegistry<dim>::documentation() + ".");
    prm.declare_entry("Length unit",
                      "m",
                      Patterns::Selection("m|km"),
                      "Unit of lengths and coordinates given in the input "
                      "(geometry, points). Functions of position always "
                      "receive x, y in metres.");
    prm.declare_entry("Write coarse mesh",
                      "",
                      Patterns::Anything(),
                      "Write the coarse mesh, its boundary parts, regions and "
                      "faults to this Gmsh MSH 2.2 file (relative to the "
                      "working directory, coordinates in the Length unit) "
                      "for Geometry/Model = gmsh to read back, e.g. to edit a "
                      "generated section in Gmsh; empty = no file.");
    GeometryRegistry<dim>::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  double
  GeometrySelector<dim>::length_scale(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    const double scale = (prm.get("Length unit") == "km") ? 1e3 : 1.0;
    prm.leave_subsection();
    return scale;
  }

  template <int dim>
  std::string
  GeometrySelector<dim>::coarse_mesh_file(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    const std::string file = Utilities::trim(prm.get("Write coarse mesh"));
    prm.leave_subsection();
    return file;
  }

  template <int dim>
  std::unique_ptr<GeometryModel<dim>>
  GeometrySelector<dim>::create(ParameterHandler &prm)
  {
    const double scale = length_scale(prm);
    prm.enter_subsection("Geometry");
    const std::string                   name = prm.get("Model");
    std::unique_ptr<GeometryModel<dim>> model =
      GeometryRegistry<dim>::find(name, "Geometry/Model").create();
    model->parse_parameters(prm, scale);
    prm.leave_subsection();
    return model;
  }

  template class GeometrySelector<2>;
} // namespace lithostress

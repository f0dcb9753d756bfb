#include <lithostress/base/input_error.h>
#include <lithostress/geometry/geometry_model.h>
#include <lithostress/geometry/gmsh_mesh.h>
#include <lithostress/geometry/l_shaped_domain.h>
#include <lithostress/geometry/quarter_annulus.h>
#include <lithostress/geometry/rectangular_geometries.h>
#include <lithostress/geometry/subduction_zone.h>

namespace lithostress
{
  template <int dim>
  void
  GeometrySelector<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry("Model",
                      "rectangular block",
                      Patterns::Selection(
                        "rectangular block|cantilever beam|"
                        "thin plate|layered box|quarter "
                        "annulus|L-shaped domain|subduction zone|gmsh"),
                      "The geometry: a built-in generator or a Gmsh mesh.");
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
    RectangularBlock<dim>::declare_parameters(prm);
    CantileverBeam<dim>::declare_parameters(prm);
    ThinPlate<dim>::declare_parameters(prm);
    LayeredBox<dim>::declare_parameters(prm);
    QuarterAnnulus<dim>::declare_parameters(prm);
    LShapedDomain<dim>::declare_parameters(prm);
    SubductionZone<dim>::declare_parameters(prm);
    GmshMesh<dim>::declare_parameters(prm);
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
    std::unique_ptr<GeometryModel<dim>> model;
    if (name == "rectangular block")
      model = std::make_unique<RectangularBlock<dim>>();
    else if (name == "cantilever beam")
      model = std::make_unique<CantileverBeam<dim>>();
    else if (name == "thin plate")
      model = std::make_unique<ThinPlate<dim>>();
    else if (name == "layered box")
      model = std::make_unique<LayeredBox<dim>>();
    else if (name == "quarter annulus")
      model = std::make_unique<QuarterAnnulus<dim>>();
    else if (name == "L-shaped domain")
      model = std::make_unique<LShapedDomain<dim>>();
    else if (name == "subduction zone")
      model = std::make_unique<SubductionZone<dim>>();
    else if (name == "gmsh")
      model = std::make_unique<GmshMesh<dim>>();
    else
      throw_input_error("Geometry/Model", "<" + name + "> is not implemented");
    model->parse_parameters(prm, scale);
    prm.leave_subsection();
    return model;
  }

  template class GeometrySelector<2>;
} // namespace lithostress

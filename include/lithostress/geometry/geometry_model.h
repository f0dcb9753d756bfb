#ifndef lithostress_geometry_geometry_model_h
#define lithostress_geometry_geometry_model_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/distributed/tria.h>

#include <lithostress/base/plugin_registry.h>
#include <lithostress/geometry/fault_trace.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * A model geometry: builds the coarse mesh of a cross section with its
   * material ids, named boundary parts and manifolds for curved parts, so
   * that every later refinement places new vertices on the true geometry.
   * Each concrete geometry declares and parses its own parameters in a
   * subsection of `Geometry` named after it.
   */
  template <int dim>
  class GeometryModel
  {
  public:
    virtual ~GeometryModel() = default;

    /** Parse this geometry's subsection; lengths are multiplied by
     * @p length_scale (the `Length unit`). */
    virtual void
    parse_parameters(ParameterHandler &prm, const double length_scale) = 0;

    /** Create the coarse mesh in the empty @p triangulation, with material,
     * boundary and manifold ids set and manifolds attached. */
    virtual void
    create_coarse_mesh(
      parallel::distributed::Triangulation<dim> &triangulation) const = 0;

    /** The named boundary parts and their boundary ids. */
    virtual std::map<std::string, types::boundary_id>
    boundary_parts() const = 0;

    /** Named regions (material ids) of the mesh, if the geometry names them
     * (Gmsh physical groups, layers). */
    virtual std::map<std::string, types::material_id>
    named_regions() const
    {
      return {};
    }

    /** The faults the coarse mesh is built to follow (each a curve of
     * cell faces through the whole model); none by default. */
    virtual std::vector<FaultTrace>
    fault_traces() const
    {
      return {};
    }

    /** The entry that messages about the coarse mesh's cells name (see
     * check_coarse_cells()): the geometry's subsection, e.g.
     * `Geometry/Subduction zone`, or its mesh file. */
    virtual std::string
    mesh_entry() const = 0;

    /** How messages name coarse cell @p index: "coarse cell <index>" (in
     * the order the geometry creates the cells), or the cell's number in a
     * mesh file. */
    virtual std::string
    cell_name(const unsigned int index) const
    {
      return "coarse cell " + std::to_string(index);
    }
  };

  /** The geometries: `Geometry/Model` selects one by name. */
  template <int dim>
  using GeometryRegistry = PluginRegistry<GeometryModel<dim>>;

  /**
   * The `Geometry` section: selects one of the registered geometries (the
   * built-in generators and the Gmsh reader), and the unit of the lengths
   * given in the input.
   */
  template <int dim>
  class GeometrySelector
  {
  public:
    /** Declare `Geometry` with the subsections of every geometry. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Create and configure the selected geometry. */
    static std::unique_ptr<GeometryModel<dim>>
    create(ParameterHandler &prm);

    /** The factor that converts input lengths to metres. */
    static double
    length_scale(ParameterHandler &prm);

    /** `Geometry/Write coarse mesh`: the Gmsh file to export the coarse
     * mesh to, or empty. */
    static std::string
    coarse_mesh_file(ParameterHandler &prm);
  };
} // namespace lithostress

/**
 * Register the geometry class template @p classname (a GeometryModel with a
 * static `declare_parameters(ParameterHandler &)` that declares its
 * subsection of `Geometry`) as `Geometry/Model = name`; one line in its
 * source file.
 */
#define LITHOSTRESS_REGISTER_GEOMETRY(classname, name, description) \
  LITHOSTRESS_REGISTER_PLUGIN(                                      \
    ::lithostress::GeometryRegistry<2>,                             \
    {name,                                                          \
     description,                                                   \
     [](ParameterHandler &prm, ParameterHandler *) {                \
       classname<2>::declare_parameters(prm);                       \
     },                                                             \
     []() -> std::unique_ptr<::lithostress::GeometryModel<2>> {     \
       return std::make_unique<classname<2>>();                     \
     }})

#endif

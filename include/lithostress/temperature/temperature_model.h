#ifndef lithostress_temperature_temperature_model_h
#define lithostress_temperature_temperature_model_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <lithostress/base/plugin_registry.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The mesh of a run as a temperature model whose field is solved on it
   * sees it: the triangulation (refined, coarsened and loaded during the
   * run), its mapping, and the names the input gives its materials and
   * boundary parts.
   */
  template <int dim>
  struct TemperatureMesh
  {
    /** The run's triangulation; it outlives the model's use. */
    const Triangulation<dim> *triangulation = nullptr;
    /** The mapping of the run's finite elements (exact curved geometry). */
    const Mapping<dim> *mapping = nullptr;
    /** Every material (`Materials/Names`) and its material id. */
    std::map<std::string, types::material_id> materials;
    /** The named boundary parts of the mesh and their boundary ids. */
    std::map<std::string, types::boundary_id> boundary_parts;
  };

  /**
   * The temperature of the cross section [K]: what the temperature-
   * activated creep laws (Goetze & Evans 1979; ASPECT's `visco_plastic`)
   * and the output read at their points. A model is one plug-in of
   * `Temperature/Model`; it declares and parses its own subsection of
   * `Temperature`, named after it. Coordinates are in metres, y up, depths
   * below sea level negative (doc/equations.md, conventions).
   */
  template <int dim>
  class TemperatureModel
  {
  public:
    virtual ~TemperatureModel() = default;

    /** Read the model's subsection (the `Temperature` section entered);
     * lengths given in the input are multiplied by @p length_scale (the
     * `Geometry/Length unit`). Throws InputError naming the entry. */
    virtual void
    parse_parameters(ParameterHandler &prm, const double length_scale) = 0;

    /** The temperatures at @p points [m], points of @p cell (inside it or
     * on its boundary), in @p temperatures (resized). A model whose field
     * lives on the mesh uses @p cell; a closed form ignores it. Throws
     * InputError where the model's input gives no valid temperature. */
    virtual void
    values(const typename Triangulation<dim>::active_cell_iterator &cell,
           const std::vector<Point<dim>>                           &points,
           std::vector<double> &temperatures) const = 0;

    /** Throw the InputError that values() would throw somewhere on the
     * coarse mesh @p tria (its cells still active), before anything is
     * computed or written; a model that can only be evaluated later (a
     * field solved on the mesh) checks nothing here. */
    virtual void
    check_against_mesh(const Triangulation<dim> &tria) const;

    /** Give the model the run's mesh (collective, once, after
     * parse_parameters()): a model whose field lives on the mesh resolves
     * its names of materials and boundaries (InputError naming the entry)
     * and computes its field, again after every change of the mesh. A
     * closed form does nothing. */
    virtual void
    attach_mesh(const TemperatureMesh<dim> &mesh);
  };

  /**
   * A temperature that is a closed form of position: value() at each point,
   * whatever the cell.
   */
  template <int dim>
  class PointwiseTemperature : public TemperatureModel<dim>
  {
  public:
    /** The temperature [K] at @p p [m]. */
    virtual double
    value(const Point<dim> &p) const = 0;

    void
    values(const typename Triangulation<dim>::active_cell_iterator &cell,
           const std::vector<Point<dim>>                           &points,
           std::vector<double> &temperatures) const override;

    /** value() at every vertex and centre of the coarse cells. */
    void
    check_against_mesh(const Triangulation<dim> &tria) const override;
  };

  /** The temperature models: `Temperature/Model` selects one by name. */
  template <int dim>
  using TemperatureRegistry = PluginRegistry<TemperatureModel<dim>>;

  /**
   * The `Temperature` section: `Model = none` (the default: the model has
   * no temperature, and nothing may ask for one) or one of the registered
   * models, each with its subsection.
   */
  template <int dim>
  class TemperatureSelector
  {
  public:
    /** Declare `Temperature` with the subsections of every model. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** The selected model, configured; null for `Model = none`. */
    static std::unique_ptr<TemperatureModel<dim>>
    create(ParameterHandler &prm, const double length_scale);
  };
} // namespace lithostress

/**
 * Register the temperature model class template @p classname (a
 * TemperatureModel with a static `declare_parameters(ParameterHandler &)`
 * that declares its subsection of `Temperature`) as `Temperature/Model =
 * name`; one line in its source file.
 */
#define LITHOSTRESS_REGISTER_TEMPERATURE_MODEL(classname, name, description) \
  LITHOSTRESS_REGISTER_PLUGIN(                                               \
    ::lithostress::TemperatureRegistry<2>,                                   \
    {name,                                                                   \
     description,                                                            \
     [](ParameterHandler &prm, ParameterHandler *) {                         \
       classname<2>::declare_parameters(prm);                                \
     },                                                                      \
     []() -> std::unique_ptr<::lithostress::TemperatureModel<2>> {           \
       return std::make_unique<classname<2>>();                              \
     }})

#endif

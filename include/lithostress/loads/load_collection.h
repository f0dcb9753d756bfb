#ifndef lithostress_loads_load_collection_h
#define lithostress_loads_load_collection_h

#include <lithostress/base/plugin_registry.h>
#include <lithostress/loads/load.h>

#include <map>
#include <memory>
#include <vector>

namespace lithostress
{
  /** The loads, in the order they are assembled and reported. */
  template <int dim>
  using LoadRegistry = PluginRegistry<Load<dim>>;

  /**
   * The `Loads` section: every load of the model. A new load is one class
   * derived from Load with its own parameters and one line,
   * LITHOSTRESS_REGISTER_LOAD, in its source file.
   */
  template <int dim>
  class LoadCollection
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm, ParameterHandler *first_pass);

    void
    parse_parameters(ParameterHandler &prm, const ModelDescription<dim> &model);

    /** The active loads. */
    const std::vector<std::unique_ptr<Load<dim>>> &
    loads() const
    {
      return active;
    }

    /** Whether densities are stripped (stresses relative to a reference
     * column). */
    bool
    densities_stripped() const
    {
      return stripped;
    }

    /** Whether the model has no body force (neither gravity nor stripped
     * densities). */
    bool
    without_body_force() const
    {
      return body_force_absent;
    }

    /** The vertical spring stiffness of all loads on each of
     * @p boundary_ids that has one [Pa/m]. */
    std::map<types::boundary_id, double>
    vertical_springs(const std::vector<types::boundary_id> &boundary_ids) const;

    /** Whether every load's stiffness is a vertical boundary spring (what
     * the matrix-free operator represents). */
    bool
    stiffness_is_vertical_springs() const;

    /** Whether a load (the slab pull) is set by the balance of the others'
     * vertical forces, so that balance() must be called on every mesh. */
    bool
    balances_vertical_loads() const;

    /**
     * Give the loads that balance the others (SlabPull with `Vertical force
     * = balance`) the net vertical force of the rest: @p resultants are the
     * loads' resultants [N/m] in the order of loads(), measured at zero
     * displacement (so that springs contribute nothing).
     */
    void
    balance(const std::vector<Tensor<1, dim>> &resultants);

  private:
    std::vector<std::unique_ptr<Load<dim>>> active;
    bool                                    stripped          = false;
    bool                                    body_force_absent = true;
  };
} // namespace lithostress

/**
 * Register the load class template @p classname (with a static
 * `declare_parameters(ParameterHandler &, ParameterHandler *first_pass)`
 * for its subsection of `Loads`) under @p name, at @p position among the
 * loads (the order of their terms and of the force balance's rows); one
 * line in its source file.
 */
#define LITHOSTRESS_REGISTER_LOAD(classname, name, description, position) \
  LITHOSTRESS_REGISTER_PLUGIN(                                            \
    ::lithostress::LoadRegistry<2>,                                       \
    {name,                                                                \
     description,                                                         \
     [](ParameterHandler &prm, ParameterHandler *first_pass) {            \
       classname<2>::declare_parameters(prm, first_pass);                 \
     },                                                                   \
     []() -> std::unique_ptr<::lithostress::Load<2>> {                    \
       return std::make_unique<classname<2>>();                           \
     },                                                                   \
     position})

#endif

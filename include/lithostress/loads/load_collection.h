#ifndef lithostress_loads_load_collection_h
#define lithostress_loads_load_collection_h

#include <lithostress/loads/load.h>

#include <map>
#include <memory>
#include <vector>

namespace lithostress
{
  /**
   * The `Loads` section: every load of the model. A new load is one class
   * derived from Load with its own parameters, declared and created here.
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

#endif

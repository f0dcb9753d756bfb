#ifndef lithostress_materials_initial_stress_source_h
#define lithostress_materials_initial_stress_source_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/material.h>

namespace lithostress
{
  using namespace dealii;

  /**
   * A source of initial strain ε0 in σ = C(ε − ε0) (thesis §3.6, §3.8:
   * the thermal strain of a temperature change): the stress −C ε0 it adds
   * at a point. Loads that carry one implement it (ThermalStrain), and
   * StressModel adds every source's stress to every reported stress; the
   * interface lives here so that the stress model does not depend on the
   * loads.
   */
  template <int dim>
  class InitialStressSource
  {
  public:
    virtual ~InitialStressSource() = default;

    /** Whether this source carries an initial strain, so that the stress
     * at a given strain depends on it. */
    virtual bool
    has_initial_stress() const
    {
      return false;
    }

    /**
     * Add the stress −C ε0 of the initial strain at @p p in a cell of
     * @p material with moduli @p moduli to the in-plane @p stress and to
     * @p sigma_zz.
     */
    virtual void
    add_initial_stress(const Point<dim>         &p,
                       const Material           &material,
                       const ElasticModuli<dim> &moduli,
                       SymmetricTensor<2, dim>  &stress,
                       double                   &sigma_zz) const = 0;

    /**
     * The pressure [Pa, compression positive] at @p p of a reference state
     * that the computed stresses are relative to and that laws reading the
     * pressure must add (density stripping: the reference column's
     * lithostatic pressure, doc/equations.md §12); 0 by default.
     */
    virtual double
    reference_pressure(const Point<dim> &p) const
    {
      (void)p;
      return 0;
    }
  };
} // namespace lithostress

#endif

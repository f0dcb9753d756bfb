#ifndef lithostress_faults_fault_element_stresses_h
#define lithostress_faults_fault_element_stresses_h

#include <deal.II/base/point.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/materials/stress_model.h>

#include <memory>

namespace lithostress
{
  using namespace dealii;

  /**
   * FSHEAR's reading of the stresses on a fault element (thesis appendix,
   * FSHEAR and the routine that fills BFAULT and DEPTH): the stress of
   * each of the two elements beside the fault at its centroid, turned into
   * the fault's frame; the lithostatic normal stress ρ_l g d at each
   * centroid's depth; the two sides averaged; the pore pressure ρ_w g d at
   * the depth of the fault element's midpoint subtracted. One shear and one
   * effective normal stress per fault element, where lithostress's own law
   * reads the interface traction at every interface point. Here a fault
   * element is a face pair (the finer side's face), its elements the two
   * cells that share it. `Faults/Sliding solver/Thesis stress reading =
   * element centroids` uses it in the thesis iteration.
   */
  template <int dim>
  class FaultElementStresses
  {
  public:
    /** The reading of @p faults' elements in @p fe_space, with the
     * stresses of @p stress_model. */
    FaultElementStresses(const FiniteElementSpace<dim> &fe_space,
                         const StressModel<dim>        &stress_model,
                         const FaultInterface<dim>     &faults);

    /** FSHEAR's SHAV and SNAV − POREP [Pa] on one fault element. */
    struct Reading
    {
      /** The mean shear stress s·σ·n of the two centroids. */
      double shear = 0;
      /** σ_n,eff: the mean of n·σ·n − ρ_l g d_centroid, plus ρ_w g
       * d_midpoint (compression negative). */
      double effective_normal = 0;
    };

    /**
     * The reading of the face pair of the interface point @p values (its
     * cells and fault frame), whose midpoint is @p midpoint, for the
     * displacement @p u (with ghosts).
     */
    Reading
    read(const typename FaultInterface<dim>::PointValues &values,
         const Point<dim>                                &midpoint,
         const TrilinosWrappers::MPI::Vector             &u);

  private:
    /** n·σ·n − ρ_l g d and s·σ·n at the centroid of @p cell (field
     * @p field), for point @p values's fault. */
    std::pair<double, double>
    centroid_stress(const typename DoFHandler<dim>::active_cell_iterator &cell,
                    const unsigned int                                    field,
                    const typename FaultInterface<dim>::PointValues &values,
                    const TrilinosWrappers::MPI::Vector             &u);

    const FiniteElementSpace<dim>                &fe_space;
    const StressModel<dim>                       &stress_model;
    const FaultInterface<dim>                    &faults;
    std::array<std::unique_ptr<FEValues<dim>>, 2> centroid_values;
  };
} // namespace lithostress

#endif

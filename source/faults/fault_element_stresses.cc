#include <deal.II/base/quadrature.h>

#include <lithostress/faults/fault_element_stresses.h>

namespace lithostress
{
  template <int dim>
  FaultElementStresses<dim>::FaultElementStresses(
    const FiniteElementSpace<dim> &fe_space,
    const StressModel<dim>        &stress_model,
    const FaultInterface<dim>     &faults)
      : fe_space(fe_space)
      , stress_model(stress_model)
      , faults(faults)
  {
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5;
    const Quadrature<dim> at_centre(centre);
    for (unsigned int field = 0; field < 2; ++field)
      centroid_values[field] =
        std::make_unique<FEValues<dim>>(fe_space.mapping(),
                                        fe_space.fe_collection()[field],
                                        at_centre,
                                        update_gradients |
                                          update_quadrature_points);
  }

  template <int dim>
  std::pair<double, double>
  FaultElementStresses<dim>::centroid_stress(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                    field,
    const typename FaultInterface<dim>::PointValues      &values,
    const TrilinosWrappers::MPI::Vector                  &u)
  {
    FEValues<dim> &fe_values = *centroid_values[field];
    fe_values.reinit(cell);
    std::vector<SymmetricTensor<2, dim>> strain(1);
    fe_values[fe_space.displacement(field)].get_function_symmetric_gradients(
      u, strain);
    const Point<dim>             &centroid = fe_values.quadrature_point(0);
    const SymmetricTensor<2, dim> sigma =
      stress_model
        .stress(cell, fe_values.get_quadrature().point(0), centroid, strain[0])
        .in_plane;
    const auto            &p           = values.point;
    const Tensor<1, dim>   t           = sigma * p.normal;
    const CoulombFriction &law         = faults.coulomb_friction(p.fault);
    const double           lithostatic = law.lithostatic_density * law.gravity *
                               faults.overburden_depth(p.fault, centroid);
    return {t * p.normal - lithostatic, t * p.shear};
  }

  template <int dim>
  typename FaultElementStresses<dim>::Reading
  FaultElementStresses<dim>::read(
    const typename FaultInterface<dim>::PointValues &values,
    const Point<dim>                                &midpoint,
    const TrilinosWrappers::MPI::Vector             &u)
  {
    const auto  minus = centroid_stress(values.minus_cell, 0, values, u);
    const auto  plus  = centroid_stress(values.plus_cell, 1, values, u);
    const auto &p     = values.point;
    const CoulombFriction &law = faults.coulomb_friction(p.fault);
    Reading                r;
    r.shear            = 0.5 * (minus.second + plus.second);
    r.effective_normal = 0.5 * (minus.first + plus.first) +
                         law.pore_fluid_density * law.gravity *
                           faults.overburden_depth(p.fault, midpoint);
    return r;
  }

  template class FaultElementStresses<2>;
} // namespace lithostress

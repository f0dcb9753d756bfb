#ifndef lithostress_analysis_point_values_h
#define lithostress_analysis_point_values_h

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/stress_model.h>

#include <limits>
#include <vector>

namespace lithostress
{
  /** Displacement and stress of the solution at one point. */
  template <int dim>
  struct PointValue
  {
    Point<dim>              point;
    Tensor<1, dim>          displacement;
    SymmetricTensor<2, dim> stress;
    double                  sigma_zz = 0;
    /** The material of the evaluating cell. */
    types::material_id material_id = 0;
    /** The temperature [K] (`Temperature/Model`); NaN where the model has
     * none. */
    double temperature = std::numeric_limits<double>::quiet_NaN();
    /** The accumulated plastic strain (interpolated from its quadrature
     * points) and the yielding indicator (1 where the last step's return
     * mapping reached the yield surface at the nearest quadrature point, 0
     * where not) of the non-linear rock laws (Rheology =
     * visco-elasto-plastic); NaN where the model keeps neither. */
    double plastic_strain = std::numeric_limits<double>::quiet_NaN();
    double yielding       = std::numeric_limits<double>::quiet_NaN();
    /** The effective viscosity tau_II/(2 strain_rate_II) [Pa s] and the
     * second invariant of the inelastic strain rate [1/s] of the last
     * step at the nearest quadrature point, where yielding is given (the
     * viscosity 0 where nothing flows, as in the ParaView field). */
    double effective_viscosity = std::numeric_limits<double>::quiet_NaN();
    double strain_rate_ii      = std::numeric_limits<double>::quiet_NaN();
    /** Whether the point lies in the mesh (only false when outside points
     * are allowed). */
    bool inside = true;
  };

  /**
   * Evaluates the solution at given points on a distributed mesh: the rank
   * that owns a cell containing the point evaluates it (through the
   * degree-p mapping), and the values are shared with all ranks. A point
   * outside the mesh is an error naming it, unless @p allow_outside (then it
   * is returned with `inside = false`, e.g. for sampling grids).
   */
  template <int dim>
  std::vector<PointValue<dim>>
  evaluate_at_points(const DoFHandler<dim>               &dof_handler,
                     const FiniteElementSpace<dim>       &fe_space,
                     const StressModel<dim>              &stress_model,
                     const TrilinosWrappers::MPI::Vector &solution,
                     const std::vector<Point<dim>>       &points,
                     const bool allow_outside = false);
} // namespace lithostress

#endif

#ifndef lithostress_postprocess_point_values_h
#define lithostress_postprocess_point_values_h

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/elastic_moduli.h>

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
  };

  /**
   * Evaluates the solution at given points on a distributed mesh: the rank
   * that owns a cell containing the point evaluates it (through the
   * degree-p mapping), and the values are shared with all ranks. A point
   * outside the mesh is an error naming it.
   */
  template <int dim>
  std::vector<PointValue<dim>>
  evaluate_at_points(const DoFHandler<dim>               &dof_handler,
                     const FiniteElementSpace<dim>       &fe_space,
                     const MaterialLibrary               &materials,
                     const PlaneState                     plane_state,
                     const TrilinosWrappers::MPI::Vector &solution,
                     const std::vector<Point<dim>>       &points);
} // namespace lithostress

#endif

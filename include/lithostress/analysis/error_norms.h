#ifndef lithostress_analysis_error_norms_h
#define lithostress_analysis_error_norms_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/reference_solutions/reference_solution.h>

namespace lithostress
{
  /** Errors of a solution against a reference, with the reference's norms. */
  struct ErrorNorms
  {
    /** ‖u_h − u‖_L2 [m·m]. */
    double displacement_l2 = 0;
    /** Energy norm (∫ (σ_h − σ) : (ε_h − ε))^½. */
    double energy = 0;
    /** ‖σ_h − σ‖_L2 over the in-plane components. */
    double stress_l2 = 0;
    /** ‖u‖_L2, ‖u‖_E, ‖σ‖_L2 of the reference, for relative errors. */
    double displacement_l2_norm = 0, energy_norm = 0, stress_l2_norm = 0;
  };

  /**
   * Integrates the errors over the owned cells with a Gauss rule of
   * degree + 4 points per direction on the model's mapping (so that the
   * geometry error of curved cells is measured, not hidden) and sums them over
   * all ranks.
   */
  template <int dim>
  ErrorNorms
  compute_error_norms(const DoFHandler<dim>               &dof_handler,
                      const FiniteElementSpace<dim>       &fe_space,
                      const StressModel<dim>              &stress_model,
                      const TrilinosWrappers::MPI::Vector &solution,
                      const ReferenceSolution<dim>        &reference);
} // namespace lithostress

#endif

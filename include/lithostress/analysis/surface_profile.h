#ifndef lithostress_analysis_surface_profile_h
#define lithostress_analysis_surface_profile_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>

#include <array>
#include <string>
#include <vector>

namespace lithostress
{
  /**
   * The displacement along a boundary part, typically the top surface
   * (thesis surface-uplift profiles): x, u_x, u_y in metres at every
   * distinct support point of the part, sorted by x. Written by rank 0 as
   * `surface_profile.csv`.
   */
  template <int dim>
  std::vector<std::array<double, 1 + 2 * dim>>
  surface_profile(const DoFHandler<dim>               &dof_handler,
                  const FiniteElementSpace<dim>       &fe_space,
                  const TrilinosWrappers::MPI::Vector &solution,
                  const types::boundary_id             boundary);

  /** Write a profile as CSV with columns x, y, u_x, u_y [m]. */
  template <int dim>
  void
  write_surface_profile(
    const std::string                                  &filename,
    const std::vector<std::array<double, 1 + 2 * dim>> &profile);
} // namespace lithostress

#endif

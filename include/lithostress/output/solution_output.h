#ifndef lithostress_output_solution_output_h
#define lithostress_output_solution_output_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/postprocess/griffith_failure.h>

#include <string>
#include <utility>
#include <vector>

namespace lithostress
{
  /**
   * ParaView output: one `.pvtu` (with a `.vtu` per rank) per cycle and a
   * `.pvd` collection of all cycles. Cells are written as higher-order
   * Lagrange cells through the degree-p mapping, so curved boundaries and
   * interfaces appear curved. Fields: displacement, stress tensor, σ_zz,
   * principal and deviatoric stresses, the Griffith test, material id and
   * MPI rank.
   */
  template <int dim>
  class SolutionOutput
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** Write the solution (with ghost values) of cycle @p cycle into
     * @p directory and update the `.pvd` record. */
    void
    write(const std::string                   &directory,
          const unsigned int                   cycle,
          const DoFHandler<dim>               &dof_handler,
          const FiniteElementSpace<dim>       &fe_space,
          const StressModel<dim>              &stress_model,
          const GriffithFailure               &griffith,
          const TrilinosWrappers::MPI::Vector &solution);

    bool enabled = true;
    /** Write only the last cycle. */
    bool last_only = false;

  private:
    unsigned int                                subdivisions = 0;
    std::vector<std::pair<double, std::string>> records;
  };
} // namespace lithostress

#endif

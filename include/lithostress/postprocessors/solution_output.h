#ifndef lithostress_postprocessors_solution_output_h
#define lithostress_postprocessors_solution_output_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/analysis/griffith_failure.h>

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
   * MPI rank; in the visco-elastic loop also the creep strain (xx, yy, xy,
   * zz) and each cell's Maxwell time η/G (0 = elastic), and the `.pvd`
   * records the model time in seconds.
   */
  template <int dim>
  class SolutionOutput
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /** Write the solution (with ghost values) as output number @p index
     * (a cycle or an output time) into @p directory and add it to the
     * `.pvd` record at time @p time (the cycle, or seconds). */
    void
    write(const std::string                   &directory,
          const unsigned int                   index,
          const double                         time,
          const DoFHandler<dim>               &dof_handler,
          const FiniteElementSpace<dim>       &fe_space,
          const StressModel<dim>              &stress_model,
          const GriffithFailure               &griffith,
          const TrilinosWrappers::MPI::Vector &solution);

    bool enabled = true;
    /** Write only the last cycle. */
    bool last_only = false;

    /** The `.pvd` records (time, file) written so far: part of a
     * checkpoint, so that a resumed run continues the same series. */
    std::vector<std::pair<double, std::string>> records;

  private:
    unsigned int subdivisions = 0;
  };
} // namespace lithostress

#endif

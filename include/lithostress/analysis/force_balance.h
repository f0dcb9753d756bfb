#ifndef lithostress_analysis_force_balance_h
#define lithostress_analysis_force_balance_h

#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/boundary_conditions/prescribed_displacement.h>
#include <lithostress/loads/load_collection.h>
#include <lithostress/materials/stress_model.h>

#include <string>
#include <utility>
#include <vector>

namespace lithostress
{
  /**
   * The forces on the body [N per m out of plane]: the resultant of each load
   * (body forces, tractions, line forces, the isostatic restoring force
   * −∫ρ_f g u_y |n_y| ds) and the reaction of each part with prescribed
   * displacement, r = K u − f summed over the degrees of freedom that part
   * prescribes. In equilibrium they sum to zero up to the solver tolerance:
   * a check that every load applies the force it should.
   */
  template <int dim>
  struct ForceBalance
  {
    std::vector<std::pair<std::string, Tensor<1, dim>>> loads, reactions;

    /** The sum of all forces (zero in equilibrium). */
    Tensor<1, dim>
    imbalance() const;

    /** The largest force magnitude, to judge the imbalance by. */
    double
    scale() const;

    /** Write `force_balance.csv`: `kind, name, F_x, F_y` [N/m]. */
    void
    write_csv(const std::string &file_name) const;

    /** A table for the log. */
    std::string
    table() const;
  };

  /** Compute the force balance of @p solution (with ghost values). */
  template <int dim>
  ForceBalance<dim>
  compute_force_balance(const DoFHandler<dim>               &dof_handler,
                        const FiniteElementSpace<dim>       &fe_space,
                        const StressModel<dim>              &stress_model,
                        const LoadCollection<dim>           &loads,
                        const PrescribedDisplacement<dim>   &prescribed,
                        const TrilinosWrappers::MPI::Vector &solution);
} // namespace lithostress

#endif

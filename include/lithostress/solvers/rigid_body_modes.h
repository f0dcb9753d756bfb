#ifndef lithostress_solvers_rigid_body_modes_h
#define lithostress_solvers_rigid_body_modes_h

#include <deal.II/dofs/dof_handler.h>

#include <lithostress/discretization/finite_element_space.h>

#include <Epetra_Map.h>
#include <Epetra_MultiVector.h>

#include <memory>

namespace lithostress
{
  /**
   * The rigid-body modes of each displacement field (in 2-D: two
   * translations and the rotation) on the owned DoFs, in the layout of
   * @p map: the near-null space that smoothed-aggregation AMG needs for
   * elasticity. deal.II 9.4.1 can pass only translations to ML, which
   * doubles the iteration count (doc/dealii_facts.md), so the modes are
   * built here from the support point of each DoF; each field's modes are
   * zero on the other fields' DoFs, so faulted models get six modes.
   */
  template <int dim>
  std::unique_ptr<Epetra_MultiVector>
  make_rigid_body_modes(const DoFHandler<dim>         &dof_handler,
                        const FiniteElementSpace<dim> &fe_space,
                        const Epetra_Map              &map);

  /** The same on the DoFs of multigrid level @p level (numbered by
   * DoFHandler::distribute_mg_dofs), for an AMG coarse solve. */
  template <int dim>
  std::unique_ptr<Epetra_MultiVector>
  make_level_rigid_body_modes(const DoFHandler<dim>         &dof_handler,
                              const FiniteElementSpace<dim> &fe_space,
                              const unsigned int             level,
                              const Epetra_Map              &map);
} // namespace lithostress

#endif

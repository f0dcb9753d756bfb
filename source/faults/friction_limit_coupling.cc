#include <deal.II/base/mpi.h>

#include <lithostress/faults/friction_limit_coupling.h>

#include <Epetra_CrsMatrix.h>

#include <map>
#include <set>

namespace lithostress
{
  template <int dim>
  void
  FrictionLimitCoupling<dim>::reinit(
    const FaultInterface<dim>            &faults,
    const DoFHandler<dim>                &dof_handler,
    const FiniteElementSpace<dim>        &fe_space,
    const NormalContact<dim>             &contact,
    const std::vector<InterfaceResponse> &responses,
    const TrilinosWrappers::SparseMatrix &bulk,
    const AffineConstraints<double>      &ties,
    const IndexSet                       &locally_owned,
    const IndexSet                       &locally_relevant)
  {
    clear();
    this->contact     = &contact;
    this->ties        = &ties;
    using PointValues = typename FaultInterface<dim>::PointValues;
    typename FaultInterface<dim>::FaceTerms terms(fe_space);
    slopes.assign(responses.size(), 0.);
    linearised_reactions.assign(responses.size(), 0.);
    faults.for_each_interface_point(
      dof_handler, fe_space, nullptr, [&](const PointValues &values) {
        const unsigned int       i = values.index;
        const InterfaceResponse &r = responses[i];
        if (!contact.exact(i) || !contact.closed(i) ||
            r.state != SlipState::sliding || r.effective_normal_stress >= 0)
          return;
        // t_s = sign μ (−σ_n,eff): ∂t_s/∂λ = −sign μ.
        const double slope =
          -(r.shear_traction > 0 ? 1. : -1.) * r.friction_coefficient;
        slopes[i]               = slope;
        linearised_reactions[i] = contact.normal_traction(i);
        terms.clear();
        terms.add_traction(values, slope * values.point.shear);
        columns.push_back({i, values.dofs, terms.force});
      });
    const MPI_Comm communicator = dof_handler.get_communicator();
    any = Utilities::MPI::logical_or(!columns.empty(), communicator);
    if (!any)
      return;
    // C: the ties and the problem's constraints without inhomogeneities
    // (M acts on directions).
    AffineConstraints<double> homogeneous;
    homogeneous.copy_from(ties);
    for (const auto &line : ties.get_lines())
      if (line.inhomogeneity != 0)
        homogeneous.set_inhomogeneity(line.index, 0.);
    make_reaction_rows(bulk, homogeneous, locally_owned);
    product.reinit(locally_owned, communicator);
    product = 0;
    ghosted.reinit(locally_owned, locally_relevant, communicator);
  }

  template <int dim>
  void
  FrictionLimitCoupling<dim>::make_reaction_rows(
    const TrilinosWrappers::SparseMatrix &bulk,
    const AffineConstraints<double>      &homogeneous,
    const IndexSet                       &locally_owned)
  {
    // The rows the columns read, from every rank: a point's node may be
    // owned by a rank that does not have the point.
    std::vector<types::global_dof_index> needed;
    for (const Column &column : columns)
      for (const auto dof : contact->reaction_dofs(column.point))
        needed.push_back(dof);
    const MPI_Comm communicator = bulk.get_mpi_communicator();
    std::set<types::global_dof_index> rows;
    for (const auto &part : Utilities::MPI::all_gather(communicator, needed))
      for (const auto dof : part)
        if (locally_owned.is_element(dof))
          rows.insert(dof);
    // Row r of K C: K's entries, a constrained column's onto its masters.
    std::map<std::pair<types::global_dof_index, types::global_dof_index>,
             double>
                            entries;
    const Epetra_CrsMatrix &k = bulk.trilinos_matrix();
    for (const auto r : rows)
      {
        int     n       = 0;
        double *values  = nullptr;
        int    *columns = nullptr;
        k.ExtractMyRowView(k.LRID(
                             static_cast<TrilinosWrappers::types::int_type>(r)),
                           n,
                           values,
                           columns);
        for (int e = 0; e < n; ++e)
          {
            const types::global_dof_index j = k.GCID(columns[e]);
            if (!homogeneous.is_constrained(j))
              entries[{r, j}] += values[e];
            else
              for (const auto &[m, w] : *homogeneous.get_constraint_entries(j))
                entries[{r, m}] += w * values[e];
          }
      }
    reaction_rows.clear();
    for (const auto &[key, value] : entries)
      {
        if (reaction_rows.empty() || reaction_rows.back().row != key.first)
          reaction_rows.push_back({key.first, {}});
        reaction_rows.back().entries.emplace_back(key.second, value);
      }
  }

  template <int dim>
  void
  FrictionLimitCoupling<dim>::vmult_add(
    TrilinosWrappers::MPI::Vector       &dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    if (!any)
      return;
    // The change of the reactions for the direction src: Λ C src (the
    // rows' columns are locally relevant).
    ghosted = src;
    product = 0;
    for (const Row &row : reaction_rows)
      {
        double value = 0;
        for (const auto &[column, weight] : row.entries)
          value += weight * ghosted[column];
        product[row.row] = value;
      }
    product.compress(VectorOperation::insert);
    ghosted = product;
    // The sliding points' shear forces for it, onto the ties' masters
    // (Cᵀ, with the problem's constraints), summed in `product`, whose
    // reactions `ghosted` now holds.
    product = 0;
    Vector<double> local;
    for (const Column &column : columns)
      {
        local = column.force;
        local *= contact->reaction(ghosted, column.point);
        ties->distribute_local_to_global(local, column.dofs, product);
      }
    product.compress(VectorOperation::add);
    dst += product;
  }

  template class FrictionLimitCoupling<2>;
} // namespace lithostress

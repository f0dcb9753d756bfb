#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <lithostress/assembly/elastic_assembler.h>
#include <lithostress/faults/normal_contact.h>

namespace lithostress
{
  void
  condense_ties(const AffineConstraints<double> &ties,
                const AffineConstraints<double> &constraints,
                const IndexSet                  &locally_owned,
                const IndexSet                  &locally_relevant,
                TrilinosWrappers::MPI::Vector   &r)
  {
    const MPI_Comm                communicator = r.get_mpi_communicator();
    TrilinosWrappers::MPI::Vector moved;
    moved.reinit(locally_owned, locally_relevant, communicator, true);
    std::vector<types::global_dof_index> sources;
    std::vector<double>                  values;
    const auto tied = [&](const types::global_dof_index i) {
      return ties.is_constrained(i) && !constraints.is_constrained(i);
    };
    for (const auto i : locally_owned)
      if (tied(i))
        {
          sources.clear();
          values.clear();
          for (const auto &[j, w] : *ties.get_constraint_entries(i))
            {
              sources.push_back(j);
              values.push_back(w * r[i]);
            }
          moved.add(sources, values);
        }
    moved.compress(VectorOperation::add);
    // r += moved - (the tied rows of r), written once per owned row (the
    // same operation on every rank).
    TrilinosWrappers::MPI::Vector change(locally_owned, communicator);
    for (const auto i : locally_owned)
      change[i] = moved[i] - (tied(i) ? r[i] : 0.);
    change.compress(VectorOperation::insert);
    r += change;
  }

  namespace
  {
    /** The bulk of @p problem (cells and loads, with its history)
     * into @p system's right-hand side, and its matrix if @p with_matrix,
     * with @p system's constraints. */
    template <int dim>
    void
    assemble_cells(const DiscreteProblem<dim> &problem,
                   const DoFHandler<dim>      &dof_handler,
                   LinearSystem<dim>          &system,
                   const bool                  with_matrix)
    {
      ElasticAssembler<dim> assembler(problem.fe_space,
                                      problem.stress_model,
                                      problem.loads);
      assembler.set_cell_history(problem.cell_history);
      assembler.assemble(dof_handler, system, with_matrix);
    }
  } // namespace

  template <int dim>
  NormalContact<dim>::NormalContact(const FaultInterface<dim>     &faults,
                                    const DoFHandler<dim>         &dof_handler,
                                    const FiniteElementSpace<dim> &fe_space,
                                    const IndexSet &locally_owned,
                                    const IndexSet &locally_relevant)
      : faults(faults)
      , dof_handler(dof_handler)
      , fe_space(fe_space)
      , locally_owned(locally_owned)
      , locally_relevant(locally_relevant)
      , communicator(dof_handler.get_communicator())
  {
    // Each node's share of the fault's area: the integral of its basis
    // function over the fault, ∫ |[φ]| ds at the interface points (the
    // finer side's Lobatto rule, exact for it), summed on every rank; the
    // reaction is read at the finer side's node, whose basis function is
    // 1 at its point and 0 at the pair's other points, so that its
    // reaction is the traction times that integral. (Where the finer side
    // changes from one face pair to the next, a node at their common
    // vertex is the coarser side's on one of them: there the quotient is
    // a weighted mean of the tractions nearby.)
    TrilinosWrappers::MPI::Vector area;
    area.reinit(locally_owned, locally_relevant, communicator, true);
    using PointValues = typename FaultInterface<dim>::PointValues;
    std::vector<double> integrals;
    faults.for_each_interface_point(
      dof_handler, fe_space, nullptr, [&](const PointValues &values) {
        const unsigned int k = values.point.fault;
        const bool exact = faults.exact_contact(k) && values.node_sign != 0 &&
                           values.reaction_sign != 0 &&
                           faults.has_face_terms(k) && !values.point.at_tip;
        in_contact.push_back(exact);
        slides.push_back(faults.law(k).nonlinear());
        keys.push_back(values.node[0]);
        // The reaction is read at the finer side's node (on a hanging
        // face whose finer side is the footwall the tied node is the
        // coarser hanging wall's, whose basis function spans both
        // subfaces).
        nodes.push_back(values.reaction_node);
        signs.push_back(values.reaction_sign);
        // The normal at the node, as its tie takes it.
        normals.push_back(
          faults.trace(k).hanging_wall_normal(values.node_position));
        if (!faults.exact_contact(k) || !faults.has_face_terms(k))
          return;
        integrals.resize(values.dofs.size());
        for (unsigned int i = 0; i < values.dofs.size(); ++i)
          integrals[i] = values.point.JxW * values.shape_jumps[i].norm();
        area.add(values.dofs, integrals);
      });
    area.compress(VectorOperation::add);
    weight.reinit(locally_owned, locally_relevant, communicator);
    weight = area;
    tractions.assign(keys.size(), 0.);
  }

  template <int dim>
  void
  NormalContact<dim>::make_constraints(
    const AffineConstraints<double> &base,
    AffineConstraints<double>       &constraints) const
  {
    constraints.clear();
    constraints.reinit(locally_relevant);
    constraints.merge(base);
    faults.add_contact_constraints(dof_handler,
                                   fe_space,
                                   constraints,
                                   [this](const types::global_dof_index node) {
                                     return open.count(node) > 0;
                                   });
    constraints.close();
  }

  template <int dim>
  void
  NormalContact<dim>::assemble_bulk(const DiscreteProblem<dim> &problem,
                                    LinearSystem<dim>          &system)
  {
    // The constraints change only with the open nodes; the matrix gets
    // their sparsity (constrained rows keep only their diagonal), from
    // the cells and the faults' face pairs.
    if (constraints_made_for != version)
      {
        make_constraints(problem.system.constraints, system.constraints);
        system.locally_owned = locally_owned;
        system.reinit(dof_handler,
                      communicator,
                      true,
                      faults.interface_cliques(dof_handler));
      }
    constraints_made_for = version;
    assemble_cells(problem, dof_handler, system, true);
  }


  template <int dim>
  void
  NormalContact<dim>::assemble_bulk_rhs(const DiscreteProblem<dim> &problem,
                                        LinearSystem<dim> &system) const
  {
    Assert(constraints_made_for == version,
           ExcMessage("assemble_bulk() first, for this open set"));
    assemble_cells(problem, dof_handler, system, false);
  }

  template <int dim>
  void
  NormalContact<dim>::compute_tractions(
    const TrilinosWrappers::MPI::Vector &residual)
  {
    // At a closed node on the side `signs` names, K u − f + (the other
    // forces) + s W t_n n = 0 in the normal direction, s = ±1 the sign of
    // that side's jump, W the node's area.
    for (unsigned int i = 0; i < keys.size(); ++i)
      if (in_contact[i])
        tractions[i] = reaction(residual, i);
  }

  template <int dim>
  bool
  NormalContact<dim>::update(const std::vector<InterfaceResponse> &responses,
                             const std::vector<double>            &normal_jumps)
  {
    std::vector<types::global_dof_index> opening, closing;
    for (unsigned int i = 0; i < keys.size(); ++i)
      {
        if (!in_contact[i])
          continue;
        if (closed(i) && slides[i] && responses[i].effective_normal_stress > 0)
          opening.push_back(keys[i]);
        else if (!closed(i) && normal_jumps[i] < 0)
          closing.push_back(keys[i]);
      }
    bool changed = false;
    for (const auto &part : Utilities::MPI::all_gather(communicator, opening))
      for (const types::global_dof_index key : part)
        changed = open.insert(key).second || changed;
    for (const auto &part : Utilities::MPI::all_gather(communicator, closing))
      for (const types::global_dof_index key : part)
        changed = open.erase(key) > 0 || changed;
    if (changed)
      ++version;
    return changed;
  }

  template <int dim>
  void
  NormalContact<dim>::start_from(const std::vector<double>       &normal_jumps,
                                 const double                     gap,
                                 const AffineConstraints<double> &base,
                                 AffineConstraints<double>       &constraints)
  {
    std::vector<types::global_dof_index> apart;
    for (unsigned int i = 0; i < keys.size(); ++i)
      if (in_contact[i] && normal_jumps[i] > gap)
        apart.push_back(keys[i]);
    open.clear();
    for (const auto &part : Utilities::MPI::all_gather(communicator, apart))
      open.insert(part.begin(), part.end());
    ++version;
    make_constraints(base, constraints);
  }

  template <int dim>
  void
  NormalContact<dim>::accelerate(const bool restart)
  {
    const unsigned int  depth = 4;
    std::vector<double> g(tractions.size(), 0.);
    for (unsigned int i = 0; i < tractions.size(); ++i)
      if (in_contact[i] && closed(i))
        g[i] = tractions[i];
    if (accelerated < 0 || restart)
      {
        accelerated = 0;
        dG.clear();
        dF.clear();
        last_f.clear();
        last_g = g;
        input  = g;
        return;
      }
    std::vector<double> f(g.size());
    for (unsigned int i = 0; i < g.size(); ++i)
      f[i] = g[i] - input[i];
    if (accelerated++ > 0)
      {
        std::vector<double> df(g.size()), dg(g.size());
        for (unsigned int i = 0; i < g.size(); ++i)
          {
            df[i] = f[i] - last_f[i];
            dg[i] = g[i] - last_g[i];
          }
        dF.push_back(df);
        dG.push_back(dg);
        if (dF.size() > depth)
          {
            dF.pop_front();
            dG.pop_front();
          }
      }
    last_f = f;
    last_g = g;
    // γ = argmin |f − ΔF γ|: the normal equations, summed over the ranks.
    const unsigned int  m = dF.size();
    std::vector<double> products(m * m + m, 0.);
    for (unsigned int a = 0; a < m; ++a)
      {
        for (unsigned int b = 0; b < m; ++b)
          for (unsigned int i = 0; i < g.size(); ++i)
            products[a * m + b] += dF[a][i] * dF[b][i];
        for (unsigned int i = 0; i < g.size(); ++i)
          products[m * m + a] += dF[a][i] * f[i];
      }
    Utilities::MPI::sum(products, communicator, products);
    FullMatrix<double> normal(m, m);
    Vector<double>     rhs(m), gamma(m);
    double             scale = 0;
    for (unsigned int a = 0; a < m; ++a)
      {
        for (unsigned int b = 0; b < m; ++b)
          normal(a, b) = products[a * m + b];
        rhs(a) = products[m * m + a];
        scale  = std::max(scale, normal(a, a));
      }
    input = g;
    if (m == 0 || !(scale > 0))
      return;
    // A little Tikhonov regularisation: nearly parallel differences.
    for (unsigned int a = 0; a < m; ++a)
      normal(a, a) += 1e-10 * scale;
    normal.gauss_jordan();
    normal.vmult(gamma, rhs);
    for (unsigned int a = 0; a < m; ++a)
      for (unsigned int i = 0; i < g.size(); ++i)
        input[i] -= gamma(a) * dG[a][i];
    for (unsigned int i = 0; i < g.size(); ++i)
      if (in_contact[i] && closed(i))
        tractions[i] = input[i];
  }

  template class NormalContact<2>;
} // namespace lithostress

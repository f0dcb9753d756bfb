#include <deal.II/dofs/dof_tools.h>
#include <deal.II/hp/fe_values.h>

#include <lithostress/analysis/force_balance.h>
#include <lithostress/assembly/elastic_assembler.h>
#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>

#include <fstream>
#include <iomanip>
#include <sstream>

namespace lithostress
{
  namespace
  {
    /** A short name of a load: its description up to the first ':',
     * without parenthesised details, the pieces between them joined by
     * commas ("tractions on top (normal ...) base (...)" gives "tractions
     * on top, base"). */
    std::string
    short_name(const std::string &description)
    {
      const std::string text = description.substr(0, description.find(':'));
      std::vector<std::string> pieces(1);
      int                      depth = 0;
      for (const char c : text)
        if (c == '(' && depth++ == 0)
          pieces.emplace_back();
        else if (c == ')' && depth > 0)
          --depth;
        else if (depth == 0)
          pieces.back() += c;
      std::string name;
      for (const std::string &piece : pieces)
        {
          const std::string trimmed = Utilities::trim(piece);
          if (!trimmed.empty())
            name += (name.empty() ? "" : ", ") + trimmed;
        }
      return name;
    }
  } // namespace

  template <int dim>
  Tensor<1, dim>
  ForceBalance<dim>::imbalance() const
  {
    Tensor<1, dim> sum;
    for (const auto &f : loads)
      sum += f.second;
    for (const auto &f : reactions)
      sum += f.second;
    return sum;
  }

  template <int dim>
  double
  ForceBalance<dim>::scale() const
  {
    double s = 0;
    for (const auto &f : loads)
      s = std::max(s, f.second.norm());
    for (const auto &f : reactions)
      s = std::max(s, f.second.norm());
    return s;
  }

  template <int dim>
  void
  ForceBalance<dim>::write_csv(const std::string &file_name) const
  {
    OutputFile out(file_name);
    out << "kind,name,F_x,F_y\n" << std::setprecision(12);
    for (const auto &f : loads)
      out << "load,\"" << f.first << "\"," << f.second[0] << ',' << f.second[1]
          << '\n';
    for (const auto &f : reactions)
      out << "reaction,\"" << f.first << "\"," << f.second[0] << ','
          << f.second[1] << '\n';
    const Tensor<1, dim> sum = imbalance();
    out << "sum,all," << sum[0] << ',' << sum[1] << '\n';
    out.commit();
  }

  template <int dim>
  std::string
  ForceBalance<dim>::table() const
  {
    std::ostringstream out;
    out << "Force balance [N/m]:\n" << std::setprecision(6);
    auto row = [&](const std::string    &kind,
                   const std::string    &name,
                   const Tensor<1, dim> &f) {
      out << "  " << std::left << std::setw(9) << kind << std::setw(34)
          << name.substr(0, 33) << std::right << std::setw(14) << f[0]
          << std::setw(14) << f[1] << '\n';
    };
    for (const auto &f : loads)
      row("load", f.first, f.second);
    for (const auto &f : reactions)
      row("reaction", f.first, f.second);
    row("sum", "(zero in equilibrium)", imbalance());
    out << "  relative imbalance " << std::setprecision(2)
        << imbalance().norm() / std::max(scale(), 1e-300) << '\n';
    return out.str();
  }

  template <int dim>
  ForceBalance<dim>
  compute_force_balance(const DoFHandler<dim>               &dof_handler,
                        const FiniteElementSpace<dim>       &fe_space,
                        const StressModel<dim>              &stress_model,
                        const LoadCollection<dim>           &loads,
                        const PrescribedDisplacement<dim>   &prescribed,
                        const TrilinosWrappers::MPI::Vector &solution)
  {
    const MPI_Comm    comm = dof_handler.get_communicator();
    const auto       &all  = loads.loads();
    hp::FEValues<dim> hp_fe_values =
      ElasticAssembler<dim>::cell_values(fe_space);
    hp::FEFaceValues<dim> hp_face_values =
      ElasticAssembler<dim>::face_values(fe_space);
    const IndexSet owned = dof_handler.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    // The residual K u − f of every degree of freedom, without constraints.
    TrilinosWrappers::MPI::Vector residual;
    residual.reinit(owned, relevant, comm, true);
    std::vector<Tensor<1, dim>> resultant(all.size());

    FullMatrix<double>                   cell_matrix, load_matrix;
    Vector<double>                       u_cell, cell_residual, load_rhs;
    Vector<double>                       load_force;
    std::vector<Vector<double>>          history_values;
    std::vector<types::global_dof_index> dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          hp_fe_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_fe_values.get_present_fe_values();
          const unsigned int   n         = fe_values.dofs_per_cell;
          const auto           u =
            fe_space.displacement(fe_space.field_of(cell->active_fe_index()));
          const Material &material =
            stress_model.materials(cell->material_id());
          const ElasticModuli<dim> &moduli =
            stress_model.moduli(cell->material_id());
          dofs.resize(n);
          cell->get_dof_indices(dofs);
          u_cell.reinit(n);
          for (unsigned int i = 0; i < n; ++i)
            u_cell(i) = solution(dofs[i]);
          cell_matrix.reinit(n, n);
          ElasticAssembler<dim>::add_law_stiffness(
            stress_model, fe_values, u, material.id, true, cell_matrix);
          cell_residual.reinit(n);
          cell_matrix.vmult(cell_residual, u_cell);
          load_force.reinit(n);
          const auto &fe = cell->get_fe();
          for (unsigned int l = 0; l < all.size(); ++l)
            {
              load_matrix.reinit(n, n);
              load_rhs.reinit(n);
              ElasticAssembler<dim>::add_load_terms(*all[l],
                                                    cell,
                                                    fe_values,
                                                    hp_face_values,
                                                    u,
                                                    material,
                                                    moduli,
                                                    load_matrix,
                                                    load_rhs);
              // The force of the load on the body: f − K_load u; its
              // resultant is the sum over each component's shape functions
              // (a partition of unity).
              load_matrix.vmult(load_force, u_cell);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const double force = load_rhs(i) - load_force(i);
                  resultant[l][fe.system_to_component_index(i).first % dim] +=
                    force;
                  cell_residual(i) -= force;
                }
            }
          // The history's share of the internal force ∫ ε(v) : σ.
          const CellHistory<dim> *history =
            stress_model.attached_cell_history();
          if (history != nullptr && stress_model.has_history(material.id))
            {
              history->get(cell, history_values);
              load_rhs.reinit(n);
              ElasticAssembler<dim>::add_history_terms(stress_model,
                                                       fe_values,
                                                       u,
                                                       material.id,
                                                       history_values,
                                                       true,
                                                       load_rhs);
              cell_residual -= load_rhs;
            }
          for (unsigned int i = 0; i < n; ++i)
            residual(dofs[i]) += cell_residual(i);
        }

    // Point forces, without constraints so that none is dropped.
    AffineConstraints<double> none;
    none.close();
    TrilinosWrappers::MPI::Vector point_forces(owned, comm);
    std::array<IndexSet, dim>     component_dofs;
    for (unsigned int d = 0; d < dim; ++d)
      {
        std::vector<bool> mask(fe_space.fe_collection().n_components(), false);
        for (unsigned int c = d; c < mask.size(); c += dim)
          mask[c] = true;
        component_dofs[d] =
          DoFTools::extract_dofs(dof_handler, ComponentMask(mask));
      }
    for (unsigned int l = 0; l < all.size(); ++l)
      {
        point_forces = 0;
        all[l]->add_point_terms(dof_handler, fe_space, none, point_forces);
        point_forces.compress(VectorOperation::add);
        for (unsigned int d = 0; d < dim; ++d)
          for (const auto i : component_dofs[d])
            if (owned.is_element(i))
              {
                resultant[l][d] += point_forces(i);
                residual(i) -= point_forces(i);
              }
      }
    residual.compress(VectorOperation::add);

    ForceBalance<dim> balance;
    for (unsigned int l = 0; l < all.size(); ++l)
      {
        Tensor<1, dim> f;
        for (unsigned int d = 0; d < dim; ++d)
          f[d] = Utilities::MPI::sum(resultant[l][d], comm);
        balance.loads.emplace_back(short_name(all[l]->description()), f);
      }
    for (const auto &part : prescribed.constrained_dofs(dof_handler, fe_space))
      {
        Tensor<1, dim> r;
        for (unsigned int d = 0; d < dim; ++d)
          {
            double sum = 0;
            for (const auto i : part.second[d])
              if (owned.is_element(i))
                sum += residual(i);
            r[d] = Utilities::MPI::sum(sum, comm);
          }
        balance.reactions.emplace_back(part.first, r);
      }
    return balance;
  }

  template struct ForceBalance<2>;
  template ForceBalance<2>
  compute_force_balance<2>(const DoFHandler<2> &,
                           const FiniteElementSpace<2> &,
                           const StressModel<2> &,
                           const LoadCollection<2> &,
                           const PrescribedDisplacement<2> &,
                           const TrilinosWrappers::MPI::Vector &);
} // namespace lithostress

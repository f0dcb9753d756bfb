#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/trilinos_index_access.h>

#include <lithostress/assembly/elastic_assembler.h>
#include <lithostress/base/input_error.h>

#include <Epetra_CrsMatrix.h>

#include <algorithm>

namespace lithostress
{
  namespace
  {
    /**
     * Adds cell matrices whose degrees of freedom are all locally owned and
     * unconstrained (all but a thin layer of cells) straight into the Epetra
     * rows by local index: the constraints' general path converts every
     * global index of every entry, which costs more than computing the
     * cell matrix. Applies when the owned indices are one contiguous range
     * and the matrix's column map starts with them in order (Epetra's
     * convention, checked here).
     */
    template <int dim>
    class OwnedCellInsertion
    {
    public:
      explicit OwnedCellInsertion(LinearSystem<dim> &system)
          : system(system)
          , n_owned(system.locally_owned.n_elements())
      {
        if (n_owned == 0 || !system.locally_owned.is_contiguous())
          return;
        first                     = system.locally_owned.nth_index_in_set(0);
        const Epetra_Map &columns = system.matrix.trilinos_matrix().ColMap();
        if (static_cast<types::global_dof_index>(columns.NumMyElements()) <
            n_owned)
          return;
        for (types::global_dof_index i = 0; i < n_owned; ++i)
          if (static_cast<types::global_dof_index>(
                TrilinosWrappers::global_index(columns, i)) != first + i)
            return;
        matrix =
          &const_cast<Epetra_CrsMatrix &>(system.matrix.trilinos_matrix());
      }

      /** Whether the cell with @p dofs can be added directly. */
      bool
      applies(const std::vector<types::global_dof_index> &dofs) const
      {
        if (matrix == nullptr)
          return false;
        for (const types::global_dof_index i : dofs)
          if (i - first >= n_owned || system.constraints.is_constrained(i))
            return false;
        return true;
      }

      /** Add @p cell_matrix and @p cell_rhs of the cell with @p dofs. */
      void
      add(const std::vector<types::global_dof_index> &dofs,
          const FullMatrix<double>                   &cell_matrix,
          const Vector<double>                       &cell_rhs)
      {
        // Walk each Epetra row (sorted by FillComplete) and the cell's
        // columns in ascending order together instead of searching for
        // every entry; an entry not found that way is searched for.
        const unsigned int n = dofs.size();
        local.resize(n);
        order.resize(n);
        for (unsigned int i = 0; i < n; ++i)
          {
            local[i] = static_cast<int>(dofs[i] - first);
            order[i] = i;
          }
        std::sort(order.begin(),
                  order.end(),
                  [&](const unsigned int x, const unsigned int y) {
                    return local[x] < local[y];
                  });
        for (unsigned int i = 0; i < n; ++i)
          {
            int     length;
            double *values;
            int    *columns;
            matrix->ExtractMyRowView(local[i], length, values, columns);
            int p = 0;
            for (const unsigned int j : order)
              {
                while (p < length && columns[p] < local[j])
                  ++p;
                if (p < length && columns[p] == local[j])
                  values[p] += cell_matrix(i, j);
                else
                  {
                    const int ierr = matrix->SumIntoMyValues(local[i],
                                                             1,
                                                             &cell_matrix(i, j),
                                                             &local[j]);
                    AssertThrow(ierr == 0, ExcTrilinosError(ierr));
                  }
              }
          }
        system.rhs.add(dofs, cell_rhs);
      }

    private:
      LinearSystem<dim>        &system;
      types::global_dof_index   n_owned;
      types::global_dof_index   first  = 0;
      Epetra_CrsMatrix         *matrix = nullptr;
      std::vector<int>          local;
      std::vector<unsigned int> order;
    };
  } // namespace

  template <int dim>
  ElasticAssembler<dim>::ElasticAssembler(
    const FiniteElementSpace<dim> &fe_space,
    const StressModel<dim>        &stress_model,
    const LoadCollection<dim>     &loads)
      : fe_space(fe_space)
      , stress_model(stress_model)
      , loads(loads)
  {
  }

  template <int dim>
  hp::FEValues<dim>
  ElasticAssembler<dim>::cell_values(const FiniteElementSpace<dim> &fe_space)
  {
    return hp::FEValues<dim>(fe_space.mapping_collection(),
                             fe_space.fe_collection(),
                             fe_space.cell_quadrature(),
                             update_values | update_gradients |
                               update_quadrature_points | update_JxW_values);
  }

  template <int dim>
  hp::FEFaceValues<dim>
  ElasticAssembler<dim>::face_values(const FiniteElementSpace<dim> &fe_space)
  {
    return hp::FEFaceValues<dim>(fe_space.mapping_collection(),
                                 fe_space.fe_collection(),
                                 fe_space.face_quadrature(),
                                 update_values | update_quadrature_points |
                                   update_normal_vectors | update_JxW_values);
  }

  template <int dim>
  void
  ElasticAssembler<dim>::add_load_terms(
    const Load<dim>                                      &load,
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const FEValues<dim>                                  &fe_values,
    hp::FEFaceValues<dim>                                &hp_face_values,
    const FEValuesExtractors::Vector                     &displacement,
    const Material                                       &material,
    const ElasticModuli<dim>                             &moduli,
    FullMatrix<double>                                   &cell_matrix,
    Vector<double>                                       &cell_rhs)
  {
    load.add_cell_terms(
      fe_values, displacement, material, moduli, cell_matrix, cell_rhs);
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() &&
          load.acts_on_boundary(cell->face(f)->boundary_id()))
        {
          hp_face_values.reinit(cell, f);
          load.add_boundary_terms(hp_face_values.get_present_fe_values(),
                                  cell->face(f)->boundary_id(),
                                  displacement,
                                  cell_matrix,
                                  cell_rhs);
        }
  }

  template <int dim>
  void
  ElasticAssembler<dim>::add_cell_terms(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    const FEValues<dim>                                  &fe_values,
    hp::FEFaceValues<dim>                                &hp_face_values,
    const bool                                            with_stiffness,
    FullMatrix<double>                                   &cell_matrix,
    Vector<double>                                       &cell_rhs) const
  {
    const unsigned int               n = fe_values.dofs_per_cell;
    const FEValuesExtractors::Vector u =
      fe_space.displacement(fe_space.field_of(cell->active_fe_index()));
    const Material &material = stress_model.materials(cell->material_id());
    const ElasticModuli<dim> &moduli = stress_model.step_moduli(material.id);
    cell_matrix.reinit(n, n);
    cell_rhs.reinit(n);
    if (stress_model.linearised(material.id))
      {
        // Newton's linearisation of a non-linear law (LinearisedStress):
        // the tangent C_k, and σ₀ on the right-hand side, −∫ ε(v) : σ₀.
        std::vector<LinearisedStress<dim>> linearisation;
        stress_model.linearisation_at(cell, linearisation);
        AssertDimension(linearisation.size(), fe_values.n_quadrature_points);
        if (with_stiffness)
          {
            std::vector<SymmetricTensor<4, dim>> tangents;
            for (const LinearisedStress<dim> &l : linearisation)
              tangents.push_back(l.tangent);
            add_cell_stiffness(fe_values, u, tangents, cell_matrix);
          }
        for (const unsigned int q : fe_values.quadrature_point_indices())
          for (unsigned int i = 0; i < n; ++i)
            cell_rhs(i) -= (fe_values[u].symmetric_gradient(i, q) *
                            linearisation[q].stress) *
                           fe_values.JxW(q);
      }
    else if (with_stiffness)
      add_law_stiffness(
        stress_model, fe_values, u, material.id, false, cell_matrix);
    for (const auto &load : loads.loads())
      add_load_terms(*load,
                     cell,
                     fe_values,
                     hp_face_values,
                     u,
                     material,
                     moduli,
                     cell_matrix,
                     cell_rhs);
  }

  template <int dim>
  void
  ElasticAssembler<dim>::add_cell_matrices(
    const DoFHandler<dim>           &dof_handler,
    const CellSelection             &selected,
    const AffineConstraints<double> &constraints,
    TrilinosWrappers::SparseMatrix  &matrix) const
  {
    hp::FEValues<dim>                    hp_fe_values   = cell_values(fe_space);
    hp::FEFaceValues<dim>                hp_face_values = face_values(fe_space);
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> dofs;
    on_all_ranks(dof_handler.get_communicator(), [&]() {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && selected(cell))
          {
            hp_fe_values.reinit(cell);
            add_cell_terms(cell,
                           hp_fe_values.get_present_fe_values(),
                           hp_face_values,
                           true,
                           cell_matrix,
                           cell_rhs);
            dofs.resize(cell_matrix.m());
            cell->get_dof_indices(dofs);
            constraints.distribute_local_to_global(cell_matrix, dofs, matrix);
          }
    });
  }

  template <int dim>
  void
  ElasticAssembler<dim>::assemble(const DoFHandler<dim> &dof_handler,
                                  LinearSystem<dim>     &system,
                                  const bool             with_matrix) const
  {
    hp::FEValues<dim>                    hp_fe_values   = cell_values(fe_space);
    hp::FEFaceValues<dim>                hp_face_values = face_values(fe_space);
    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> dofs;
    std::vector<Vector<double>>          history_values;

    if (with_matrix)
      system.matrix = 0;
    system.rhs = 0;
    std::unique_ptr<OwnedCellInsertion<dim>> direct;
    if (with_matrix)
      direct = std::make_unique<OwnedCellInsertion<dim>>(system);

    // User functions (tractions, temperature changes) are evaluated in the
    // cell loop; an error there on one rank reaches all before compress().
    on_all_ranks(dof_handler.get_communicator(), [&]() {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            hp_fe_values.reinit(cell);
            const FEValues<dim> &fe_values =
              hp_fe_values.get_present_fe_values();
            const unsigned int n = fe_values.dofs_per_cell;
            const Material    &material =
              stress_model.materials(cell->material_id());
            dofs.resize(n);
            cell->get_dof_indices(dofs);

            // Without a global matrix, the right-hand side still needs
            // −K_ij g_j for prescribed values g_j ≠ 0: compute the cell
            // matrix on the cells that have them.
            bool inhomogeneous = false;
            if (!with_matrix)
              for (const types::global_dof_index i : dofs)
                if (system.constraints.is_inhomogeneously_constrained(i))
                  {
                    inhomogeneous = true;
                    break;
                  }
            add_cell_terms(cell,
                           fe_values,
                           hp_face_values,
                           with_matrix || inhomogeneous,
                           cell_matrix,
                           cell_rhs);

            if (cell_history != nullptr &&
                stress_model.has_history(material.id) &&
                !stress_model.linearised(material.id))
              {
                cell_history->get(cell, history_values);
                add_history_terms(stress_model,
                                  fe_values,
                                  fe_space.displacement(
                                    fe_space.field_of(cell->active_fe_index())),
                                  material.id,
                                  history_values,
                                  false,
                                  cell_rhs);
              }

            if (with_matrix && direct->applies(dofs))
              direct->add(dofs, cell_matrix, cell_rhs);
            else if (with_matrix)
              system.constraints.distribute_local_to_global(
                cell_matrix, cell_rhs, dofs, system.matrix, system.rhs);
            else if (inhomogeneous)
              system.constraints.distribute_local_to_global(cell_rhs,
                                                            dofs,
                                                            system.rhs,
                                                            cell_matrix);
            else
              system.constraints.distribute_local_to_global(cell_rhs,
                                                            dofs,
                                                            system.rhs);
          }
    });
    for (const auto &load : loads.loads())
      load->add_point_terms(dof_handler,
                            fe_space,
                            system.constraints,
                            system.rhs);
    if (with_matrix)
      system.matrix.compress(VectorOperation::add);
    system.rhs.compress(VectorOperation::add);
  }

  template <int dim>
  void
  ElasticAssembler<dim>::add_law_stiffness(
    const StressModel<dim>           &stress_model,
    const FEValues<dim>              &fe_values,
    const FEValuesExtractors::Vector &displacement,
    const types::material_id          id,
    const bool                        of_state,
    FullMatrix<double>               &cell_matrix)
  {
    if (stress_model.uniform_tangent(id))
      {
        add_cell_stiffness(fe_values,
                           of_state ? stress_model.moduli(id)
                                    : stress_model.step_moduli(id),
                           cell_matrix);
        return;
      }
    std::vector<SymmetricTensor<4, dim>> tangents(
      fe_values.n_quadrature_points);
    for (unsigned int q = 0; q < tangents.size(); ++q)
      tangents[q] =
        stress_model.tangent(id, fe_values.quadrature_point(q), of_state);
    add_cell_stiffness(fe_values, displacement, tangents, cell_matrix);
  }

  template <int dim>
  void
  ElasticAssembler<dim>::add_cell_stiffness(
    const FEValues<dim>                        &fe_values,
    const FEValuesExtractors::Vector           &displacement,
    const std::vector<SymmetricTensor<4, dim>> &tangents,
    FullMatrix<double>                         &cell_matrix)
  {
    const unsigned int n = fe_values.dofs_per_cell;
    // ε(φ_i) : (C_q ε(φ_j)), with C_q ε(φ_j) JxW formed once per j.
    std::vector<SymmetricTensor<2, dim>> strains(n), stresses(n);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        for (unsigned int j = 0; j < n; ++j)
          {
            strains[j]  = fe_values[displacement].symmetric_gradient(j, q);
            stresses[j] = tangents[q] * strains[j] * fe_values.JxW(q);
          }
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            cell_matrix(i, j) += strains[i] * stresses[j];
      }
  }

  template <int dim>
  void
  ElasticAssembler<dim>::add_cell_stiffness(const FEValues<dim>      &fe_values,
                                            const ElasticModuli<dim> &moduli,
                                            FullMatrix<double> &cell_matrix)
  {
    add_cell_stiffness(fe_values, moduli.lame_parameters(), cell_matrix);
  }

  template <int dim>
  void
  ElasticAssembler<dim>::add_cell_stiffness(const FEValues<dim>  &fe_values,
                                            const LameParameters &lame,
                                            FullMatrix<double>   &cell_matrix)
  {
    // Isotropic stiffness through the scalar shape gradients: each shape
    // function φ_i = N_i e_{c_i} of the primitive element has one nonzero
    // component, so
    //   ε(φ_i) : C ε(φ_j) = λ ∂_{c_i}N_i ∂_{c_j}N_j
    //                      + μ (∂_{c_j}N_i ∂_{c_i}N_j + δ_{c_i c_j} ∇N_i·∇N_j).
    const FiniteElement<dim> &fe = fe_values.get_fe();
    const unsigned int        n  = fe_values.dofs_per_cell;
    std::vector<unsigned int> component(n);
    for (unsigned int i = 0; i < n; ++i)
      component[i] = fe.system_to_component_index(i).first % dim;
    const double                lambda = lame.lambda;
    const double                mu     = lame.mu;
    std::vector<Tensor<1, dim>> grad(n);
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          grad[i] = fe_values.shape_grad(i, q);
        for (unsigned int i = 0; i < n; ++i)
          {
            const unsigned int   ci = component[i];
            const Tensor<1, dim> gi = grad[i] * JxW;
            for (unsigned int j = 0; j <= i; ++j)
              {
                const unsigned int cj = component[j];
                double             value =
                  lambda * gi[ci] * grad[j][cj] + mu * gi[cj] * grad[j][ci];
                if (ci == cj)
                  value += mu * (gi * grad[j]);
                cell_matrix(i, j) += value;
              }
          }
      }
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = i + 1; j < n; ++j)
        cell_matrix(i, j) = cell_matrix(j, i);
  }

  template <int dim>
  void
  ElasticAssembler<dim>::add_history_terms(
    const StressModel<dim>            &stress_model,
    const FEValues<dim>               &fe_values,
    const FEValuesExtractors::Vector  &displacement,
    const types::material_id           id,
    const std::vector<Vector<double>> &records,
    const bool                         of_state,
    Vector<double>                    &cell_rhs)
  {
    AssertDimension(records.size(), fe_values.n_quadrature_points);
    const HistoryLayout &layout = stress_model.history_layout();
    std::vector<double>  scratch;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        const SymmetricTensor<2, dim> sigma_h =
          stress_model
            .history_stress(id,
                            fe_values.quadrature_point(q),
                            layout.of(id, records[q], scratch),
                            of_state)
            .in_plane;
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < fe_values.dofs_per_cell; ++i)
          cell_rhs(i) -=
            (fe_values[displacement].symmetric_gradient(i, q) * sigma_h) * JxW;
      }
  }

  template class ElasticAssembler<2>;
} // namespace lithostress

#ifndef lithostress_solvers_elastic_operator_templates_h
#define lithostress_solvers_elastic_operator_templates_h

#include <deal.II/matrix_free/fe_evaluation.h>

#include <lithostress/solvers/elastic_operator.h>

/*
 * The definitions of ElasticOperator, included where it is instantiated:
 * solvers/elastic_operator.cc for deal.II's default SIMD width, and
 * solvers/active_operator_simd.cc for the vectorised build.
 */
namespace lithostress
{
  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::clear()
  {
    lambda_cell.clear();
    mu_cell.clear();
    lambda_point.reinit(0, 0);
    mu_point.reinit(0, 0);
    tangent_point.reinit(0, 0);
    springs.clear();
    Base::clear();
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::set_cell_moduli(
    const CellModuli &moduli)
  {
    const MatrixFreeType &data    = *this->data;
    const unsigned int    batches = data.n_cell_batches();
    lambda_cell.resize(batches);
    mu_cell.resize(batches);
    for (unsigned int b = 0; b < batches; ++b)
      {
        lambda_cell[b] = 0;
        mu_cell[b]     = 0;
        for (unsigned int v = 0; v < data.n_active_entries_per_cell_batch(b);
             ++v)
          {
            const LameParameters p = moduli(data.get_cell_iterator(b, v));
            lambda_cell[b][v]      = p.lambda;
            mu_cell[b][v]          = p.mu;
          }
      }
    lambda_point.reinit(0, 0);
    mu_point.reinit(0, 0);
    tangent_point.reinit(0, 0);
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  template <typename Visitor>
  bool
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::visit_points(
    const Visitor &visit) const
  {
    const MatrixFreeType &data     = *this->data;
    const unsigned int    n_points = Utilities::pow(fe_degree + 1, dim);
    for (unsigned int b = 0; b < data.n_cell_batches(); ++b)
      for (unsigned int v = 0; v < data.n_active_entries_per_cell_batch(b); ++v)
        {
          const CellIterator cell = data.get_cell_iterator(b, v);
          for (unsigned int q = 0; q < n_points; ++q)
            if (!visit(b, v, cell, q))
              return false;
        }
    return true;
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    set_point_moduli(const PointModuli &moduli)
  {
    const unsigned int batches  = this->data->n_cell_batches();
    const unsigned int n_points = Utilities::pow(fe_degree + 1, dim);
    lambda_point.reinit(batches, n_points);
    mu_point.reinit(batches, n_points);
    visit_points([&](const unsigned int  b,
                     const unsigned int  v,
                     const CellIterator &cell,
                     const unsigned int  q) {
      const LameParameters p = moduli(cell, q);
      lambda_point(b, q)[v]  = p.lambda;
      mu_point(b, q)[v]      = p.mu;
      return true;
    });
    lambda_cell.clear();
    mu_cell.clear();
    tangent_point.reinit(0, 0);
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    set_point_tangents(const PointTangent &tangent)
  {
    const unsigned int batches  = this->data->n_cell_batches();
    const unsigned int n_points = Utilities::pow(fe_degree + 1, dim);
    // λ, μ at every point while the tangents are isotropic; the whole
    // tensors, in a second pass, once one is not.
    Table<2, VectorizedArrayType> lambda(batches, n_points),
      mu(batches, n_points);
    const bool isotropic = visit_points([&](const unsigned int  b,
                                            const unsigned int  v,
                                            const CellIterator &cell,
                                            const unsigned int  q) {
      const SymmetricTensor<4, dim> C = tangent(cell, q);
      lambda(b, q)[v]                 = C[0][0][1][1];
      mu(b, q)[v]                     = C[0][1][0][1];
      SymmetricTensor<4, dim> iso;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          iso[i][i][j][j] = C[0][0][1][1];
      iso += 2 * C[0][1][0][1] * identity_tensor<dim>();
      return (C - iso).norm() <= 1e-12 * C.norm();
    });
    lambda_cell.clear();
    mu_cell.clear();
    if (isotropic)
      {
        lambda_point.swap(lambda);
        mu_point.swap(mu);
        tangent_point.reinit(0, 0);
        return;
      }
    lambda.reinit(0, 0);
    mu.reinit(0, 0);
    Table<2, SymmetricTensor<4, dim, VectorizedArrayType>> tangents(batches,
                                                                    n_points);
    visit_points([&](const unsigned int  b,
                     const unsigned int  v,
                     const CellIterator &cell,
                     const unsigned int  q) {
      const SymmetricTensor<4, dim> C = tangent(cell, q);
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          for (unsigned int k = 0; k < dim; ++k)
            for (unsigned int l = k; l < dim; ++l)
              tangents(b, q)[i][j][k][l][v] = C[i][j][k][l];
      return true;
    });
    tangent_point.swap(tangents);
    lambda_point.reinit(0, 0);
    mu_point.reinit(0, 0);
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    set_vertical_springs(
      const std::map<types::boundary_id, double> &stiffness_by_boundary)
  {
    springs.clear();
    for (const auto &[id, k] : stiffness_by_boundary)
      if (k != 0)
        springs[id] = k;
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  number
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    spring_stiffness(const types::boundary_id id) const
  {
    const auto it = springs.find(id);
    return it == springs.end() ? number(0) : number(it->second);
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  template <typename Evaluator>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    do_cell_integral(Evaluator &phi) const
  {
    if (moduli_at_points() || tangents_at_points() ||
        phi.get_cell_type() != internal::MatrixFreeFunctions::cartesian)
      {
        do_general_cell_integral(phi);
        return;
      }
    // Axis-parallel cell (the flexure plate, the column, every layered box)
    // with moduli per cell: the physical gradient is G_cd s_d with the
    // reference gradient G and s_d = 1/h_d, and the submitted value
    // σ_cd s_d JxW folds into cell constants, so a point costs 4 loads,
    // 12 multiplications and 4 stores instead of the general Jacobian
    // products of get_gradient/submit_gradient.
    const unsigned int        cell   = phi.get_current_cell_index();
    const VectorizedArrayType lambda = lambda_cell[cell];
    const VectorizedArrayType mu     = mu_cell[cell];
    const Tensor<2, dim, VectorizedArrayType> inverse_jacobian =
      phi.inverse_jacobian(0);
    VectorizedArrayType s[dim];
    for (unsigned int d = 0; d < dim; ++d)
      s[d] = inverse_jacobian[d][d];
    // normal[c][d]: coefficient of G_dd in the submitted entry (c, c);
    // shear[c][d]: coefficient of G_cd in the submitted entries (c, d) and
    // (d, c).
    VectorizedArrayType normal[dim][dim], shear[dim][dim];
    for (unsigned int c = 0; c < dim; ++c)
      for (unsigned int d = 0; d < dim; ++d)
        {
          normal[c][d] = (c == d ? lambda + 2. * mu : lambda) * s[c] * s[d];
          shear[c][d]  = mu * s[c] * s[d];
        }
    constexpr unsigned int n_points  = Utilities::pow(fe_degree + 1, dim);
    VectorizedArrayType   *gradients = phi.begin_gradients();
#ifdef DEBUG
    {
      // deal.II's debug checks want submit_gradient called before
      // integrate(); call it once and restore the values it overwrites.
      VectorizedArrayType saved[dim * dim];
      for (unsigned int k = 0; k < dim * dim; ++k)
        saved[k] = gradients[k * n_points];
      phi.submit_gradient(Tensor<2, dim, VectorizedArrayType>(), 0);
      for (unsigned int k = 0; k < dim * dim; ++k)
        gradients[k * n_points] = saved[k];
    }
#endif
    for (unsigned int q = 0; q < n_points; ++q)
      {
        const VectorizedArrayType JxW = phi.JxW(q);
        VectorizedArrayType       G[dim][dim];
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int d = 0; d < dim; ++d)
            G[c][d] = gradients[(c * dim + d) * n_points + q];
        for (unsigned int c = 0; c < dim; ++c)
          {
            VectorizedArrayType value = normal[c][0] * G[0][0];
            for (unsigned int d = 1; d < dim; ++d)
              value += normal[c][d] * G[d][d];
            gradients[(c * dim + c) * n_points + q] = value * JxW;
            for (unsigned int d = 0; d < dim; ++d)
              if (d != c)
                gradients[(c * dim + d) * n_points + q] =
                  (shear[d][d] * G[c][d] + shear[c][d] * G[d][c]) * JxW;
          }
      }
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  template <typename Evaluator>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    do_general_cell_integral(Evaluator &phi) const
  {
    const unsigned int cell = phi.get_current_cell_index();
    if (tangents_at_points())
      {
        // σ = C_q : ε, submitted as a full tensor.
        for (const unsigned int q : phi.quadrature_point_indices())
          {
            const SymmetricTensor<2, dim, VectorizedArrayType> stress =
              tangent_point(cell, q) * symmetrize(phi.get_gradient(q));
            Tensor<2, dim, VectorizedArrayType> submitted;
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int e = 0; e < dim; ++e)
                submitted[d][e] = stress[d][e];
            phi.submit_gradient(submitted, q);
          }
        return;
      }
    VectorizedArrayType lambda = 0, mu = 0;
    if (!moduli_at_points())
      {
        lambda = lambda_cell[cell];
        mu     = mu_cell[cell];
      }
    for (const unsigned int q : phi.quadrature_point_indices())
      {
        if (moduli_at_points())
          {
            lambda = lambda_point(cell, q);
            mu     = mu_point(cell, q);
          }
        // σ = λ tr(ε) I + 2 μ ε with ε = (∇u + ∇uᵀ)/2, submitted as a full
        // tensor (cheaper than the symmetric-tensor interface).
        Tensor<2, dim, VectorizedArrayType> gradient   = phi.get_gradient(q);
        VectorizedArrayType                 volumetric = gradient[0][0];
        for (unsigned int d = 1; d < dim; ++d)
          volumetric += gradient[d][d];
        volumetric *= lambda;
        Tensor<2, dim, VectorizedArrayType> stress;
        for (unsigned int d = 0; d < dim; ++d)
          {
            stress[d][d] = 2. * mu * gradient[d][d] + volumetric;
            for (unsigned int e = d + 1; e < dim; ++e)
              {
                stress[d][e] = mu * (gradient[d][e] + gradient[e][d]);
                stress[e][d] = stress[d][e];
              }
          }
        phi.submit_gradient(stress, q);
      }
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  template <typename FaceEvaluator>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    do_boundary_integral(FaceEvaluator &phi, const number k) const
  {
    for (const unsigned int q : phi.quadrature_point_indices())
      {
        Tensor<1, dim, VectorizedArrayType> traction;
        traction[dim - 1] = k * std::abs(phi.get_normal_vector(q)[dim - 1]) *
                            phi.get_value(q)[dim - 1];
        phi.submit_value(traction, q);
      }
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    local_apply_cell(const MatrixFreeType                        &data,
                     VectorType                                  &dst,
                     const VectorType                            &src,
                     const std::pair<unsigned int, unsigned int> &range) const
  {
    CellEvaluation phi(data);
    for (unsigned int cell = range.first; cell < range.second; ++cell)
      {
        phi.reinit(cell);
        phi.gather_evaluate(src, EvaluationFlags::gradients);
        do_cell_integral(phi);
        phi.integrate_scatter(EvaluationFlags::gradients, dst);
      }
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    local_apply_boundary(
      const MatrixFreeType                        &data,
      VectorType                                  &dst,
      const VectorType                            &src,
      const std::pair<unsigned int, unsigned int> &range) const
  {
    FaceEvaluation phi(data, true);
    for (unsigned int face = range.first; face < range.second; ++face)
      {
        const number k = spring_stiffness(data.get_boundary_id(face));
        if (k == number(0))
          continue;
        phi.reinit(face);
        phi.gather_evaluate(src, EvaluationFlags::values);
        do_boundary_integral(phi, k);
        phi.integrate_scatter(EvaluationFlags::values, dst);
      }
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::apply_add(
    VectorType       &dst,
    const VectorType &src) const
  {
    if (springs.empty())
      this->data->cell_loop(&ElasticOperator::local_apply_cell, this, dst, src);
    else
      this->data->loop(&ElasticOperator::local_apply_cell,
                       &ElasticOperator::local_apply_inner_face,
                       &ElasticOperator::local_apply_boundary,
                       this,
                       dst,
                       src,
                       false,
                       MatrixFreeType::DataAccessOnFaces::none,
                       MatrixFreeType::DataAccessOnFaces::none);
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  void
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    compute_diagonal()
  {
    // Only the inverse is kept (the Chebyshev smoother's preconditioner):
    // the diagonal itself is a temporary.
    this->inverse_diagonal_entries =
      std::make_shared<DiagonalMatrix<VectorType>>();
    this->diagonal_entries.reset();
    VectorType diagonal;
    this->data->initialize_dof_vector(diagonal);

    // The cell part: for φ = N_a e_c, ε(φ) : ε(φ) = (|∇N_a|² + (∂_c N_a)²)/2
    // and div φ = ∂_c N_a, so the diagonal entry (a, c) is
    // Σ_q [λ (∂_c N_a)² + μ (|∇N_a|² + (∂_c N_a)²)] JxW: one scalar
    // gradient evaluation per scalar shape function instead of one vector
    // operator application per vector shape function (9x cheaper for Q2).
    // Exact where cells carry no hanging-node constraints (every multigrid
    // level, the only place the diagonal is used).
    {
      ScalarEvaluation   scalar(*this->data);
      CellEvaluation     phi(*this->data);
      const unsigned int n = scalar.dofs_per_cell;
      for (unsigned int cell = 0; cell < this->data->n_cell_batches(); ++cell)
        {
          scalar.reinit(cell);
          phi.reinit(cell);
          for (unsigned int a = 0; a < n; ++a)
            {
              for (unsigned int b = 0; b < n; ++b)
                scalar.begin_dof_values()[b] = VectorizedArrayType();
              scalar.begin_dof_values()[a] = VectorizedArrayType(number(1.));
              scalar.evaluate(EvaluationFlags::gradients);
              std::array<VectorizedArrayType, dim> entry{};
              for (const unsigned int q : scalar.quadrature_point_indices())
                if (tangents_at_points())
                  {
                    // ε(N_a e_c) : C_q : ε(N_a e_c) for any tangent.
                    const Tensor<1, dim, VectorizedArrayType> gradient =
                      scalar.get_gradient(q);
                    for (unsigned int c = 0; c < dim; ++c)
                      {
                        Tensor<2, dim, VectorizedArrayType> G;
                        G[c] = gradient;
                        const SymmetricTensor<2, dim, VectorizedArrayType> eps =
                          symmetrize(G);
                        entry[c] += (eps * (tangent_point(cell, q) * eps)) *
                                    scalar.JxW(q);
                      }
                  }
                else
                  {
                    const VectorizedArrayType lambda = moduli_at_points()
                                                         ? lambda_point(cell, q)
                                                         : lambda_cell[cell];
                    const VectorizedArrayType mu =
                      moduli_at_points() ? mu_point(cell, q) : mu_cell[cell];
                    const Tensor<1, dim, VectorizedArrayType> gradient =
                      scalar.get_gradient(q);
                    const VectorizedArrayType JxW   = scalar.JxW(q);
                    const VectorizedArrayType norm2 = gradient.norm_square();
                    for (unsigned int c = 0; c < dim; ++c)
                      entry[c] += ((lambda + mu) * gradient[c] * gradient[c] +
                                   mu * norm2) *
                                  JxW;
                  }
              for (unsigned int c = 0; c < dim; ++c)
                phi.begin_dof_values()[c * n + a] = entry[c];
            }
          phi.distribute_local_to_global(diagonal);
        }
    }

    // The spring term's diagonal, face by face. Exact where faces carry no
    // hanging-node constraints, i.e. on every multigrid level (the only
    // place the diagonal is used).
    if (!springs.empty())
      {
        FaceEvaluation                     phi(*this->data, true);
        AlignedVector<VectorizedArrayType> local(phi.dofs_per_cell);
        const unsigned int first = this->data->n_inner_face_batches();
        const unsigned int last = first + this->data->n_boundary_face_batches();
        for (unsigned int face = first; face < last; ++face)
          {
            const number k =
              spring_stiffness(this->data->get_boundary_id(face));
            if (k == number(0))
              continue;
            phi.reinit(face);
            for (unsigned int i = 0; i < phi.dofs_per_cell; ++i)
              {
                for (unsigned int j = 0; j < phi.dofs_per_cell; ++j)
                  phi.begin_dof_values()[j] = VectorizedArrayType();
                phi.begin_dof_values()[i] = VectorizedArrayType(number(1.));
                phi.evaluate(EvaluationFlags::values);
                do_boundary_integral(phi, k);
                phi.integrate(EvaluationFlags::values);
                local[i] = phi.begin_dof_values()[i];
              }
            for (unsigned int i = 0; i < phi.dofs_per_cell; ++i)
              phi.begin_dof_values()[i] = local[i];
            phi.distribute_local_to_global(diagonal);
          }
      }
    diagonal.compress(VectorOperation::add);
    this->set_constrained_entries_to_one(diagonal);

    VectorType &inverse = this->inverse_diagonal_entries->get_vector();
    inverse.reinit(diagonal);
    for (unsigned int i = 0; i < diagonal.locally_owned_size(); ++i)
      inverse.local_element(i) = diagonal.local_element(i) > number(0)
                                   ? number(1) / diagonal.local_element(i)
                                   : number(1);
  }

  template <int dim,
            int fe_degree,
            typename number,
            typename VectorizedArrayType>
  std::size_t
  ElasticOperator<dim, fe_degree, number, VectorizedArrayType>::
    memory_consumption() const
  {
    return Base::memory_consumption() + this->data->memory_consumption() +
           lambda_cell.memory_consumption() + mu_cell.memory_consumption() +
           lambda_point.memory_consumption() + mu_point.memory_consumption() +
           tangent_point.memory_consumption();
  }

} // namespace lithostress

#endif

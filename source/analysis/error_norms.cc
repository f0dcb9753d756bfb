#include <deal.II/base/mpi.h>
#include <deal.II/hp/fe_values.h>

#include <lithostress/analysis/error_norms.h>

namespace lithostress
{
  template <int dim>
  ErrorNorms
  compute_error_norms(const DoFHandler<dim>               &dof_handler,
                      const FiniteElementSpace<dim>       &fe_space,
                      const StressModel<dim>              &stress_model,
                      const TrilinosWrappers::MPI::Vector &solution,
                      const ReferenceSolution<dim>        &reference)
  {
    hp::FEValues<dim>           hp_fe_values(fe_space.mapping_collection(),
                                   fe_space.fe_collection(),
                                   fe_space.cell_quadrature(3),
                                   update_values | update_gradients |
                                     update_quadrature_points |
                                     update_JxW_values);
    std::vector<Tensor<1, dim>> u_h;
    std::vector<Tensor<2, dim>> grad_h;
    double                      e[6] = {0, 0, 0, 0, 0, 0};
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          hp_fe_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_fe_values.get_present_fe_values();
          const auto           u =
            fe_space.displacement(fe_space.field_of(cell->active_fe_index()));
          const unsigned int n_q = fe_values.n_quadrature_points;
          u_h.resize(n_q);
          grad_h.resize(n_q);
          fe_values[u].get_function_values(solution, u_h);
          fe_values[u].get_function_gradients(solution, grad_h);
          const SymmetricTensor<4, dim> S =
            stress_model.moduli(cell->material_id()).compliance();
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const Point<dim>             &p   = fe_values.quadrature_point(q);
              const double                  JxW = fe_values.JxW(q);
              const Tensor<1, dim>          u_exact = reference.displacement(p);
              const SymmetricTensor<2, dim> s_exact = reference.stress(p);
              const SymmetricTensor<2, dim> strain_h = symmetrize(grad_h[q]);
              const SymmetricTensor<2, dim> s_h =
                stress_model
                  .stress(cell,
                          fe_values.get_quadrature().point(q),
                          p,
                          strain_h)
                  .in_plane;
              const SymmetricTensor<2, dim> ds = s_h - s_exact;
              e[0] += (u_h[q] - u_exact).norm_square() * JxW;
              e[1] += (ds * (S * ds)) * JxW;
              e[2] += ds.norm() * ds.norm() * JxW;
              e[3] += u_exact.norm_square() * JxW;
              e[4] += (s_exact * (S * s_exact)) * JxW;
              e[5] += s_exact.norm() * s_exact.norm() * JxW;
            }
        }
    double local[6];
    std::copy(e, e + 6, local);
    Utilities::MPI::sum(ArrayView<const double>(local, 6),
                        dof_handler.get_communicator(),
                        ArrayView<double>(e, 6));
    ErrorNorms norms;
    norms.displacement_l2      = std::sqrt(e[0]);
    norms.energy               = std::sqrt(e[1]);
    norms.stress_l2            = std::sqrt(e[2]);
    norms.displacement_l2_norm = std::sqrt(e[3]);
    norms.energy_norm          = std::sqrt(e[4]);
    norms.stress_l2_norm       = std::sqrt(e[5]);
    return norms;
  }

  template ErrorNorms
  compute_error_norms<2>(const DoFHandler<2> &,
                         const FiniteElementSpace<2> &,
                         const StressModel<2> &,
                         const TrilinosWrappers::MPI::Vector &,
                         const ReferenceSolution<2> &);
} // namespace lithostress

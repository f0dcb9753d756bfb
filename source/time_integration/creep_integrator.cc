#include <deal.II/base/mpi.h>

#include <lithostress/assembly/elastic_assembler.h>
#include <lithostress/base/input_error.h>
#include <lithostress/time_integration/creep_integrator.h>

namespace lithostress
{
  template <int dim>
  CreepIntegrator<dim>::CreepIntegrator(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const unsigned int                               n_points_1d)
      : creep(triangulation, n_points_1d)
      , history(triangulation, n_points_1d)
      , start_rate(triangulation, n_points_1d)
      , end_rate(triangulation, n_points_1d)
      , previous(triangulation, n_points_1d)
  {
  }

  template <int dim>
  void
  CreepIntegrator<dim>::start_history()
  {
    creep.setup();
    previous.setup();
    previous_step = 0;
    setup_step_fields();
  }

  template <int dim>
  void
  CreepIntegrator<dim>::setup_step_fields()
  {
    history.setup();
    start_rate.setup();
    end_rate.setup();
    start_rate_current = false;
  }

  template <int dim>
  SymmetricTensor<2, 3>
  CreepIntegrator<dim>::tensor_3d(const StressState<dim> &s)
  {
    SymmetricTensor<2, 3> t;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        t[i][j] = s.in_plane[i][j];
    if (dim == 2)
      t[2][2] = s.zz;
    return t;
  }

  template <int dim>
  void
  CreepIntegrator<dim>::for_each_viscous_cell(
    const DoFHandler<dim>               &dof_handler,
    const FiniteElementSpace<dim>       &fe_space,
    const StressModel<dim>              &stress_model,
    const TrilinosWrappers::MPI::Vector &solution,
    const std::function<
      void(const typename Triangulation<dim>::active_cell_iterator &,
           const std::vector<Point<dim>> &,
           const std::vector<SymmetricTensor<2, dim>> &)> &visit) const
  {
    hp::FEValues<dim> hp_fe_values =
      ElasticAssembler<dim>::cell_values(fe_space);
    std::vector<Tensor<2, dim>>          gradients;
    std::vector<SymmetricTensor<2, dim>> strains;
    // User functions (a temperature change) are evaluated in the stress:
    // an error on one rank reaches all.
    on_all_ranks(dof_handler.get_communicator(), [&]() {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() &&
            stress_model.rheology(cell->material_id()).creeps())
          {
            hp_fe_values.reinit(cell);
            const FEValues<dim> &fe_values =
              hp_fe_values.get_present_fe_values();
            AssertDimension(fe_values.n_quadrature_points,
                            creep.quadrature().size());
            const auto u =
              fe_space.displacement(fe_space.field_of(cell->active_fe_index()));
            gradients.resize(fe_values.n_quadrature_points);
            fe_values[u].get_function_gradients(solution, gradients);
            strains.resize(gradients.size());
            for (unsigned int q = 0; q < gradients.size(); ++q)
              strains[q] = symmetrize(gradients[q]);
            visit(cell, fe_values.get_quadrature_points(), strains);
          }
    });
  }

  template <int dim>
  double
  CreepIntegrator<dim>::begin_step(
    const DoFHandler<dim>               &dof_handler,
    const FiniteElementSpace<dim>       &fe_space,
    const StressModel<dim>              &stress_model,
    const TrilinosWrappers::MPI::Vector &solution,
    const double                         dt,
    const TimeStepping::Scheme           scheme,
    const double                         theta)
  {
    step = dt;
    // The rate s_n/(2η) of the start of the step: the end rate of the last
    // step, unless the mesh or the solution changed since.
    if (!start_rate_current)
      {
        std::vector<Vector<double>> c, rate;
        RheologyInputs<dim>         in;
        RheologyOutputs<dim>        out;
        for_each_viscous_cell(
          dof_handler,
          fe_space,
          stress_model,
          solution,
          [&](const auto &cell, const auto &points, const auto &strains) {
            creep.get(cell, c);
            rate.resize(c.size());
            for (unsigned int q = 0; q < c.size(); ++q)
              {
                in.position = points[q];
                in.strain   = strains[q];
                in.history  = make_array_view(c[q]);
                stress_model.evaluate(cell->material_id(), in, out);
                rate[q].reinit(out.history_rate.size());
                std::copy(out.history_rate.begin(),
                          out.history_rate.end(),
                          rate[q].begin());
              }
            start_rate.set(cell, rate);
          });
        start_rate.update_ghost_values();
        start_rate_current = true;
      }
    bdf2_step = scheme == TimeStepping::Scheme::bdf2 && previous_step > 0;
    if (bdf2_step)
      {
        // c* = ((1+ω)² c_n − ω² c_{n−1})/(1+2ω), weight (1+ω)/(1+2ω).
        const double w = dt / previous_step;
        history.set_to_combination((1 + w) * (1 + w) / (1 + 2 * w),
                                   creep,
                                   -w * w / (1 + 2 * w),
                                   previous);
        step_weight = (1 + w) / (1 + 2 * w);
        return step_weight;
      }
    if (scheme == TimeStepping::Scheme::thesis)
      {
        // The thesis's predictor c_n + Δt ċ_n.
        history.set_to_sum(creep, dt, start_rate);
        step_weight = 0;
        return step_weight;
      }
    // c* = c_n + (1 − θ) Δt ċ_n; BDF2 starts with a trapezoidal step.
    step_weight = scheme == TimeStepping::Scheme::bdf2 ? 0.5 : theta;
    history.set_to_sum(creep, (1 - step_weight) * dt, start_rate);
    return step_weight;
  }

  template <int dim>
  typename CreepIntegrator<dim>::Increment
  CreepIntegrator<dim>::finish_implicit_step(
    const DoFHandler<dim>               &dof_handler,
    const FiniteElementSpace<dim>       &fe_space,
    const StressModel<dim>              &stress_model,
    const TrilinosWrappers::MPI::Vector &solution)
  {
    Increment                   increment;
    std::vector<Vector<double>> c, h, rate;
    RheologyInputs<dim>         in;
    RheologyOutputs<dim>        out;
    in.time_step = step;
    in.weight    = step_weight;
    for_each_viscous_cell(
      dof_handler,
      fe_space,
      stress_model,
      solution,
      [&](const auto &cell, const auto &points, const auto &strains) {
        const types::material_id id = cell->material_id();
        creep.get(cell, c);
        history.get(cell, h);
        start_rate.get(cell, rate);
        for (unsigned int q = 0; q < c.size(); ++q)
          {
            // The step's stress with the history strain c*, its creep rate
            // and c_{n+1} = c* + w Δt ċ_{n+1}.
            in.position = points[q];
            in.strain   = strains[q];
            in.history  = make_array_view(h[q]);
            stress_model.evaluate(id, in, out);
            const SymmetricTensor<2, 3> rate_end =
              CreepStrain<dim>::tensor(make_array_view(out.history_rate));
            const SymmetricTensor<2, 3> c_new =
              CreepStrain<dim>::tensor(make_array_view(out.history));
            increment.add(CreepStrain<dim>::tensor(c[q]),
                          c_new,
                          CreepStrain<dim>::tensor(rate[q]),
                          rate_end,
                          stress_model.rheology(id).relaxation_time(),
                          step,
                          bdf2_step);
            CreepStrain<dim>::components(c_new, c[q]);
            CreepStrain<dim>::components(rate_end, rate[q]);
          }
        creep.set(cell, c);
        end_rate.set(cell, rate);
      });
    creep.update_ghost_values();
    end_rate.update_ghost_values();
    return all_ranks(increment);
  }

  template <int dim>
  double
  CreepIntegrator<dim>::update_thesis_history(
    const DoFHandler<dim>               &dof_handler,
    const FiniteElementSpace<dim>       &fe_space,
    const StressModel<dim>              &stress_model,
    const TrilinosWrappers::MPI::Vector &solution,
    double                              &stress_scale)
  {
    double                      change = 0, largest = 0;
    std::vector<Vector<double>> c, h, rate;
    RheologyInputs<dim>         in;
    RheologyOutputs<dim>        out;
    for_each_viscous_cell(
      dof_handler,
      fe_space,
      stress_model,
      solution,
      [&](const auto &cell, const auto &points, const auto &strains) {
        const types::material_id id = cell->material_id();
        creep.get(cell, c);
        history.get(cell, h);
        start_rate.get(cell, rate);
        for (unsigned int q = 0; q < c.size(); ++q)
          {
            // The stress of the state with history h (elastic moduli) and
            // its creep rate.
            const SymmetricTensor<2, 3> h_old = CreepStrain<dim>::tensor(h[q]);
            in.position                       = points[q];
            in.strain                         = strains[q];
            in.history                        = make_array_view(h[q]);
            stress_model.evaluate(id, in, out);
            const SymmetricTensor<2, 3> sigma = tensor_3d(out.stress);
            const SymmetricTensor<2, 3> h_new =
              CreepStrain<dim>::tensor(c[q]) +
              0.5 * step *
                (CreepStrain<dim>::tensor(rate[q]) +
                 CreepStrain<dim>::tensor(make_array_view(out.history_rate)));
            // Δs = 4η ΔΔc / Δt: the stress change behind the history's.
            change  = std::max(change,
                              (h_new - h_old).norm() * 4.0 *
                                stress_model.rheology(id).relaxation_time() *
                                stress_model.moduli(id).mu / step);
            largest = std::max(largest, deviator(sigma).norm());
            CreepStrain<dim>::components(h_new, h[q]);
          }
        history.set(cell, h);
      });
    history.update_ghost_values();
    const MPI_Comm comm = dof_handler.get_communicator();
    change              = Utilities::MPI::max(change, comm);
    largest             = Utilities::MPI::max(largest, comm);
    stress_scale        = std::max(stress_scale, largest);
    return stress_scale > 0 ? change / stress_scale : 0.0;
  }

  template <int dim>
  typename CreepIntegrator<dim>::Increment
  CreepIntegrator<dim>::finish_thesis_step(const StressModel<dim> &stress_model)
  {
    Increment                   increment;
    std::vector<Vector<double>> c, h, rate;
    const auto                 &tria = creep.dof_handler().get_triangulation();
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() &&
          stress_model.rheology(cell->material_id()).creeps())
        {
          creep.get(cell, c);
          history.get(cell, h);
          start_rate.get(cell, rate);
          const double tau =
            stress_model.rheology(cell->material_id()).relaxation_time();
          for (unsigned int q = 0; q < c.size(); ++q)
            {
              const SymmetricTensor<2, 3> c_new =
                CreepStrain<dim>::tensor(h[q]);
              // The trapezoidal rule's end rate: 2 Δc/Δt − ċ_n.
              const SymmetricTensor<2, 3> rate_end =
                2.0 / step * (c_new - CreepStrain<dim>::tensor(c[q])) -
                CreepStrain<dim>::tensor(rate[q]);
              increment.add(CreepStrain<dim>::tensor(c[q]),
                            c_new,
                            CreepStrain<dim>::tensor(rate[q]),
                            rate_end,
                            tau,
                            step);
              CreepStrain<dim>::components(rate_end, rate[q]);
            }
          creep.set(cell, h);
          end_rate.set(cell, rate);
        }
    creep.update_ghost_values();
    end_rate.update_ghost_values();
    return all_ranks(increment);
  }

  template <int dim>
  typename CreepIntegrator<dim>::Increment
  CreepIntegrator<dim>::all_ranks(const Increment &increment) const
  {
    const MPI_Comm comm = creep.dof_handler().get_communicator();
    Increment      result;
    result.creep_change   = Utilities::MPI::max(increment.creep_change, comm);
    result.elastic_strain = Utilities::MPI::max(increment.elastic_strain, comm);
    result.local_error    = Utilities::MPI::max(increment.local_error, comm);
    return result;
  }

  template class CreepIntegrator<2>;
} // namespace lithostress

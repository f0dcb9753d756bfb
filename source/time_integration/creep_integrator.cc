#include <deal.II/base/mpi.h>

#include <lithostress/assembly/elastic_assembler.h>
#include <lithostress/base/input_error.h>
#include <lithostress/time_integration/creep_integrator.h>

#include <cmath>
#include <limits>

namespace lithostress
{
  template <int dim>
  CreepIntegrator<dim>::CreepIntegrator(
    const parallel::distributed::Triangulation<dim> &triangulation,
    const unsigned int                               n_points_1d,
    const HistoryLayout                             &layout,
    const bool                                       nonlinear)
      : layout(layout)
      , creep(triangulation, n_points_1d, layout.names())
      , history(triangulation, n_points_1d, layout.names())
      , start_rate(triangulation, n_points_1d, layout.names())
      , end_rate(triangulation, n_points_1d, layout.names())
      , previous(triangulation, n_points_1d, layout.names())
      , linearised(triangulation,
                   n_points_1d,
                   nonlinear ? LinearisedStress<dim>::names()
                             : std::vector<std::string>())
      , flow(triangulation,
             n_points_1d,
             nonlinear ? std::vector<std::string>{"effective_viscosity",
                                                  "strain_rate_II",
                                                  "yielding"}
                       : std::vector<std::string>())
  {
  }

  template <int dim>
  void
  CreepIntegrator<dim>::Increment::add(
    const Rheology<dim>           &law,
    const ArrayView<const double> &c_old,
    const ArrayView<const double> &c_new,
    const ArrayView<const double> &rate_start,
    const ArrayView<const double> &rate_end,
    const double                   dt,
    const double                   elastic_strain,
    const bool                     second_order)
  {
    const unsigned int n = c_old.size();
    work.resize(n);
    const ArrayView<const double> combination(work.data(), n);
    for (unsigned int k = 0; k < n; ++k)
      work[k] = c_new[k] - c_old[k];
    creep_change = std::max(creep_change, law.history_norm(combination));
    if (second_order)
      {
        for (unsigned int k = 0; k < n; ++k)
          work[k] =
            c_new[k] - c_old[k] - 0.5 * dt * (rate_start[k] + rate_end[k]);
        local_error =
          std::max(local_error, 1.6 * law.history_norm(combination));
      }
    else
      {
        for (unsigned int k = 0; k < n; ++k)
          work[k] = rate_end[k] - rate_start[k];
        local_error =
          std::max(local_error, 0.5 * dt * law.history_norm(combination));
      }
    this->elastic_strain = std::max(this->elastic_strain, elastic_strain);
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
    linearised.setup();
    flow.setup();
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
  CreepIntegrator<dim>::store(const types::material_id   id,
                              const std::vector<double> &values,
                              Vector<double>            &record) const
  {
    layout.store(id, make_array_view(values), record);
  }

  template <int dim>
  void
  CreepIntegrator<dim>::for_each_cell_with_history(
    const DoFHandler<dim>               &dof_handler,
    const FiniteElementSpace<dim>       &fe_space,
    const StressModel<dim>              &stress_model,
    const TrilinosWrappers::MPI::Vector &solution,
    const std::function<
      void(const typename Triangulation<dim>::active_cell_iterator &,
           std::vector<RheologyInputs<dim>> &)> &visit) const
  {
    hp::FEValues<dim> hp_fe_values =
      ElasticAssembler<dim>::cell_values(fe_space);
    std::vector<Tensor<2, dim>>      gradients;
    std::vector<double>              temperatures;
    std::vector<RheologyInputs<dim>> nodes;
    const TemperatureModel<dim> *temperature = stress_model.temperature_model();
    // User functions (a temperature change) are evaluated in the stress:
    // an error on one rank reaches all.
    on_all_ranks(dof_handler.get_communicator(), [&]() {
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() &&
            stress_model.has_history(cell->material_id()))
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
            if (temperature != nullptr)
              temperature->values(cell,
                                  fe_values.get_quadrature_points(),
                                  temperatures);
            nodes.assign(gradients.size(), RheologyInputs<dim>());
            for (unsigned int q = 0; q < gradients.size(); ++q)
              {
                nodes[q].position = fe_values.quadrature_point(q);
                nodes[q].strain   = symmetrize(gradients[q]);
                if (temperature != nullptr)
                  nodes[q].temperature = temperatures[q];
              }
            visit(cell, nodes);
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
        std::vector<double>         scratch;
        RheologyOutputs<dim>        out;
        for_each_cell_with_history(dof_handler,
                                   fe_space,
                                   stress_model,
                                   solution,
                                   [&](const auto &cell, auto &nodes) {
                                     const types::material_id id =
                                       cell->material_id();
                                     creep.get(cell, c);
                                     start_rate.get(cell, rate);
                                     for (unsigned int q = 0; q < c.size(); ++q)
                                       {
                                         RheologyInputs<dim> &in = nodes[q];
                                         in.history =
                                           layout.of(id, c[q], scratch);
                                         stress_model.evaluate(id, in, out);
                                         store(id, out.history_rate, rate[q]);
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
  double
  CreepIntegrator<dim>::linearise(const DoFHandler<dim>         &dof_handler,
                                  const FiniteElementSpace<dim> &fe_space,
                                  const StressModel<dim>        &stress_model,
                                  const TrilinosWrappers::MPI::Vector &solution,
                                  const bool                           first)
  {
    AssertThrow(linearised.n_components() > 0, ExcInternalError());
    double                      missed = 0, largest = 0;
    std::vector<Vector<double>> h, records;
    std::vector<double>         h_scratch;
    RheologyOutputs<dim>        out;
    for_each_cell_with_history(
      dof_handler,
      fe_space,
      stress_model,
      solution,
      [&](const auto &cell, auto &nodes) {
        const types::material_id id = cell->material_id();
        if (!stress_model.rheology(id).nonlinear())
          return;
        history.get(cell, h);
        linearised.get(cell, records);
        for (unsigned int q = 0; q < h.size(); ++q)
          {
            RheologyInputs<dim> &in = nodes[q];
            in.time_step            = step;
            in.weight               = step_weight;
            in.history              = layout.of(id, h[q], h_scratch);
            stress_model.evaluate(id, in, out);
            // σ_lin(ε) = C ε + σ₀ + σ_init: what the last solve balanced.
            const SymmetricTensor<2, dim> sigma =
              out.stress.in_plane - in.initial_stress.in_plane;
            if (!first)
              {
                const LinearisedStress<dim> old =
                  LinearisedStress<dim>::from(records[q]);
                missed = std::max(
                  missed,
                  (sigma - old.tangent * in.strain - old.stress).norm());
              }
            largest = std::max(largest, deviator(tensor_3d(out.stress)).norm());
            LinearisedStress<dim> now;
            now.tangent = out.tangent;
            now.stress  = sigma - out.tangent * in.strain;
            now.to(records[q]);
          }
        linearised.set(cell, records);
      });
    linearised.update_ghost_values();
    const MPI_Comm comm = dof_handler.get_communicator();
    missed              = Utilities::MPI::max(missed, comm);
    largest             = Utilities::MPI::max(largest, comm);
    if (missed == 0)
      return 0;
    return largest > 0 ? missed / largest
                       : std::numeric_limits<double>::infinity();
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
    std::vector<double>         c_scratch, h_scratch, rate_scratch;
    std::vector<Vector<double>> flow_values;
    RheologyOutputs<dim>        out;
    for_each_cell_with_history(
      dof_handler,
      fe_space,
      stress_model,
      solution,
      [&](const auto &cell, auto &nodes) {
        const types::material_id id = cell->material_id();
        creep.get(cell, c);
        history.get(cell, h);
        start_rate.get(cell, rate);
        for (unsigned int q = 0; q < c.size(); ++q)
          {
            // The step's stress with the history h* (the history strain
            // c*), the history's rate and h_{n+1} = h* + w Δt ḣ_{n+1}.
            RheologyInputs<dim> &in = nodes[q];
            in.time_step            = step;
            in.weight               = step_weight;
            in.history              = layout.of(id, h[q], h_scratch);
            stress_model.evaluate(id, in, out);
            increment.add(stress_model.rheology(id),
                          layout.of(id, c[q], c_scratch),
                          make_array_view(out.history),
                          layout.of(id, rate[q], rate_scratch),
                          make_array_view(out.history_rate),
                          step,
                          out.elastic_strain,
                          bdf2_step);
            store(id, out.history, c[q]);
            store(id, out.history_rate, rate[q]);
            if (flow.n_components() > 0)
              {
                // An infinite viscosity (no flow) is written as 0.
                flow_values.resize(c.size(), Vector<double>(3));
                flow_values[q][0] = std::isfinite(out.effective_viscosity)
                                      ? out.effective_viscosity
                                      : 0.0;
                flow_values[q][1] = out.inelastic_strain_rate;
                flow_values[q][2] = out.yielding ? 1.0 : 0.0;
              }
          }
        creep.set(cell, c);
        end_rate.set(cell, rate);
        if (flow.n_components() > 0 && stress_model.rheology(id).nonlinear())
          flow.set(cell, flow_values);
      });
    creep.update_ghost_values();
    end_rate.update_ghost_values();
    flow.update_ghost_values();
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
    std::vector<double>  c_scratch, h_scratch, rate_scratch, h_new, difference;
    RheologyOutputs<dim> out;
    for_each_cell_with_history(
      dof_handler,
      fe_space,
      stress_model,
      solution,
      [&](const auto &cell, auto &nodes) {
        const types::material_id id  = cell->material_id();
        const Rheology<dim>     &law = stress_model.rheology(id);
        creep.get(cell, c);
        history.get(cell, h);
        start_rate.get(cell, rate);
        for (unsigned int q = 0; q < c.size(); ++q)
          {
            // The stress of the state with history h (elastic moduli) and
            // its rate; the new history c_n + (Δt/2)(ḣ_n + ḣ).
            const ArrayView<const double> h_old =
              layout.of(id, h[q], h_scratch);
            RheologyInputs<dim> &in = nodes[q];
            in.history              = h_old;
            stress_model.evaluate(id, in, out);
            const ArrayView<const double> c_old =
              layout.of(id, c[q], c_scratch);
            const ArrayView<const double> r_old =
              layout.of(id, rate[q], rate_scratch);
            h_new.resize(h_old.size());
            difference.resize(h_old.size());
            for (unsigned int k = 0; k < h_new.size(); ++k)
              {
                h_new[k] =
                  c_old[k] + 0.5 * step * (r_old[k] + out.history_rate[k]);
                difference[k] = h_new[k] - h_old[k];
              }
            // Δs = 4η ΔΔc / Δt: the stress change behind the history's.
            change  = std::max(change,
                              law.history_norm(make_array_view(difference)) *
                                4.0 * law.relaxation_time() *
                                stress_model.moduli(id).mu / step);
            largest = std::max(largest, deviator(tensor_3d(out.stress)).norm());
            store(id, h_new, h[q]);
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
    std::vector<double>         c_scratch, h_scratch, rate_scratch, rate_end;
    const auto                 &tria = creep.dof_handler().get_triangulation();
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned() &&
          stress_model.has_history(cell->material_id()))
        {
          const types::material_id id = cell->material_id();
          creep.get(cell, c);
          history.get(cell, h);
          start_rate.get(cell, rate);
          for (unsigned int q = 0; q < c.size(); ++q)
            {
              const ArrayView<const double> c_old =
                layout.of(id, c[q], c_scratch);
              const ArrayView<const double> c_new =
                layout.of(id, h[q], h_scratch);
              const ArrayView<const double> r_old =
                layout.of(id, rate[q], rate_scratch);
              // The trapezoidal rule's end rate: 2 Δc/Δt − ċ_n.
              rate_end.resize(c_old.size());
              for (unsigned int k = 0; k < rate_end.size(); ++k)
                rate_end[k] = 2.0 / step * (c_new[k] - c_old[k]) - r_old[k];
              const Rheology<dim> &law = stress_model.rheology(id);
              increment.add(law,
                            c_old,
                            c_new,
                            r_old,
                            make_array_view(rate_end),
                            step,
                            law.relaxation_time() *
                              law.history_norm(make_array_view(rate_end)));
              store(id, rate_end, rate[q]);
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

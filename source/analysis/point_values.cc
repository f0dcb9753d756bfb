#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/cell_id.h>

#include <lithostress/analysis/point_values.h>
#include <lithostress/base/input_error.h>

#include <cmath>

namespace lithostress
{
  template <int dim>
  std::vector<PointValue<dim>>
  evaluate_at_points(const DoFHandler<dim>               &dof_handler,
                     const FiniteElementSpace<dim>       &fe_space,
                     const StressModel<dim>              &stress_model,
                     const TrilinosWrappers::MPI::Vector &solution,
                     const std::vector<Point<dim>>       &points,
                     const bool                           allow_outside)
  {
    std::vector<bool> inside(points.size(), true);
    // u, σ (dim × dim), σzz, the material and the temperature per point;
    // only the winning rank fills them.
    const unsigned int           n_values    = dim + dim * dim + 3;
    const TemperatureModel<dim> *temperature = stress_model.temperature_model();
    std::vector<double>          local(points.size() * n_values, 0.0);
    const MPI_Comm               comm = dof_handler.get_communicator();
    // The owned cells with their bounding boxes, widened by a tenth of the
    // diameter for curved cells, in iteration order.
    std::vector<std::pair<typename DoFHandler<dim>::active_cell_iterator,
                          BoundingBox<dim>>>
      owned_cells;
    for (const auto &c : dof_handler.active_cell_iterators())
      if (c->is_locally_owned())
        {
          auto box = c->bounding_box();
          box.extend(0.1 * c->diameter());
          owned_cells.emplace_back(c, box);
        }
    std::exception_ptr error;
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        // The first owned cell (in CellId order) that contains the point;
        // of all ranks' candidates the smallest CellId evaluates, so that
        // the result does not depend on the partition.
        typename DoFHandler<dim>::active_cell_iterator cell;
        Point<dim>                                     unit;
        bool                                           found = false;
        for (const auto &[c, box] : owned_cells)
          {
            if (!box.point_inside(points[k]))
              continue;
            try
              {
                unit =
                  fe_space.mapping().transform_real_to_unit_cell(c, points[k]);
              }
            catch (const typename Mapping<dim>::ExcTransformationFailed &)
              {
                continue;
              }
            if (GeometryInfo<dim>::is_inside_unit_cell(unit, 1e-10))
              {
                cell  = c;
                found = true;
                break;
              }
          }
        const std::vector<std::string> candidates = Utilities::MPI::all_gather(
          comm, found ? cell->id().to_string() : std::string());
        int winner = -1;
        for (unsigned int r = 0; r < candidates.size(); ++r)
          if (!candidates[r].empty() &&
              (winner < 0 ||
               CellId(candidates[r]) < CellId(candidates[winner])))
            winner = r;
        if (winner < 0 && allow_outside)
          {
            inside[k] = false;
            continue;
          }
        if (winner < 0)
          throw InputError("the point (" + std::to_string(points[k][0]) + ", " +
                           std::to_string(points[k][1]) +
                           ") [m] is outside the mesh");
        if (static_cast<unsigned int>(winner) !=
            Utilities::MPI::this_mpi_process(comm))
          continue;
        // The stress evaluates user functions (a temperature change): an
        // error here is made collective after the loop.
        try
          {
            const auto           &fe = cell->get_fe();
            const Quadrature<dim> q(
              GeometryInfo<dim>::project_to_unit_cell(unit));
            FEValues<dim> fe_values(fe_space.mapping(),
                                    fe,
                                    q,
                                    update_values | update_gradients |
                                      update_quadrature_points);
            fe_values.reinit(cell);
            const auto u =
              fe_space.displacement(fe_space.field_of(cell->active_fe_index()));
            std::vector<Tensor<1, dim>> value(1);
            std::vector<Tensor<2, dim>> gradient(1);
            fe_values[u].get_function_values(solution, value);
            fe_values[u].get_function_gradients(solution, gradient);
            const StressState<dim> stress =
              stress_model.stress(cell,
                                  q.point(0),
                                  fe_values.quadrature_point(0),
                                  symmetrize(gradient[0]));
            double *v = &local[k * n_values];
            for (unsigned int d = 0; d < dim; ++d)
              v[d] = value[0][d];
            for (unsigned int a = 0; a < dim; ++a)
              for (unsigned int b = 0; b < dim; ++b)
                v[dim + a * dim + b] = stress.in_plane[a][b];
            v[dim + dim * dim]     = stress.zz;
            v[dim + dim * dim + 1] = cell->material_id();
            if (temperature != nullptr)
              {
                std::vector<double> t;
                temperature->values(cell, {fe_values.quadrature_point(0)}, t);
                v[dim + dim * dim + 2] = t[0];
              }
          }
        catch (const InputError &)
          {
            error = std::current_exception();
          }
      }
    rethrow_on_all_ranks(comm, error);
    std::vector<double> global(local.size());
    Utilities::MPI::sum(local, comm, global);

    std::vector<PointValue<dim>> result(points.size());
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        const double *v  = &global[k * n_values];
        result[k].point  = points[k];
        result[k].inside = inside[k];
        for (unsigned int d = 0; d < dim; ++d)
          result[k].displacement[d] = v[d];
        for (unsigned int a = 0; a < dim; ++a)
          for (unsigned int b = a; b < dim; ++b)
            result[k].stress[a][b] = v[dim + a * dim + b];
        result[k].sigma_zz = v[dim + dim * dim];
        result[k].material_id =
          static_cast<types::material_id>(std::lround(v[dim + dim * dim + 1]));
        if (temperature != nullptr)
          result[k].temperature = v[dim + dim * dim + 2];
      }
    return result;
  }

  template std::vector<PointValue<2>>
  evaluate_at_points<2>(const DoFHandler<2> &,
                        const FiniteElementSpace<2> &,
                        const StressModel<2> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const std::vector<Point<2>> &,
                        const bool);
} // namespace lithostress

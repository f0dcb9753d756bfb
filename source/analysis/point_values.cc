#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/cell_id.h>

#include <lithostress/analysis/point_values.h>
#include <lithostress/base/input_error.h>

#include <algorithm>
#include <cmath>

namespace lithostress
{
  namespace
  {
    /** One named component of a field of quadrature-point records
     * (CellHistory), evaluated in a cell: the cell's polynomial through its
     * nodes, or (@p nearest) the value of the node nearest to the point,
     * for fields that are not smooth between the nodes (a yielding flag,
     * a viscosity that varies over orders of magnitude, whose polynomial
     * overshoots). Absent if the field is missing or has no such
     * component. */
    template <int dim>
    class QuadratureField
    {
    public:
      QuadratureField(const CellHistory<dim> *field,
                      const std::string      &name,
                      const bool              nearest = false)
          : field(field)
          , nearest(nearest)
      {
        if (field == nullptr)
          return;
        const std::vector<std::string> &names = field->names();
        const auto where = std::find(names.begin(), names.end(), name);
        if (where != names.end())
          component = where - names.begin();
        else
          this->field = nullptr;
      }

      bool
      exists() const
      {
        return field != nullptr;
      }

      /** The component at @p unit in @p cell (0 if absent). */
      double
      value(const typename Triangulation<dim>::active_cell_iterator &cell,
            const Point<dim>                                        &unit)
      {
        if (field == nullptr)
          return 0;
        if (!nearest)
          {
            field->value(cell, unit, record);
            return record[component];
          }
        field->get(cell, records);
        const Quadrature<dim> &nodes = field->quadrature();
        unsigned int           best  = 0;
        for (unsigned int q = 1; q < nodes.size(); ++q)
          if (nodes.point(q).distance(unit) < nodes.point(best).distance(unit))
            best = q;
        return records[best][component];
      }

    private:
      const CellHistory<dim>     *field;
      const bool                  nearest;
      unsigned int                component = 0;
      Vector<double>              record;
      std::vector<Vector<double>> records;
    };

    /** The state at a point besides the displacement and the stress: the
     * temperature, the plastic strain (interpolated) and the last step's
     * yielding, effective viscosity and strain rate (at the nearest
     * quadrature point), each where the model has it. */
    template <int dim>
    class PointState
    {
    public:
      static constexpr unsigned int n_values = 5;

      explicit PointState(const StressModel<dim> &stress_model)
          : temperature(stress_model.temperature_model())
          , plastic_strain(stress_model.attached_cell_history(),
                           "plastic_strain")
          , yielding(stress_model.attached_flow_state(), "yielding", true)
          , viscosity(stress_model.attached_flow_state(),
                      "effective_viscosity",
                      true)
          , rate(stress_model.attached_flow_state(), "strain_rate_II", true)
      {
      }

      /** Write the values at @p unit (real point @p p) of @p cell. */
      void
      evaluate(const typename DoFHandler<dim>::active_cell_iterator &cell,
               const Point<dim>                                     &unit,
               const Point<dim>                                     &p,
               double                                               *v)
      {
        if (temperature != nullptr)
          {
            std::vector<double> t;
            temperature->values(cell, {p}, t);
            v[0] = t[0];
          }
        v[1] = plastic_strain.value(cell, unit);
        v[2] = yielding.value(cell, unit);
        v[3] = viscosity.value(cell, unit);
        v[4] = rate.value(cell, unit);
      }

      /** Read them back into @p result (those the model has). */
      void
      store(const double *v, PointValue<dim> &result) const
      {
        if (temperature != nullptr)
          result.temperature = v[0];
        if (plastic_strain.exists())
          result.plastic_strain = v[1];
        if (yielding.exists())
          result.yielding = v[2];
        if (viscosity.exists())
          result.effective_viscosity = v[3];
        if (rate.exists())
          result.strain_rate_ii = v[4];
      }

    private:
      const TemperatureModel<dim> *temperature;
      QuadratureField<dim>         plastic_strain, yielding, viscosity, rate;
    };

    /** u, σ (dim × dim), σzz and the material at @p unit of @p cell into
     * @p v (dim + dim² + 2 values); the real point is returned. */
    template <int dim>
    Point<dim>
    evaluate_in_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
                     const Point<dim>                                     &unit,
                     const FiniteElementSpace<dim>       &fe_space,
                     const StressModel<dim>              &stress_model,
                     const TrilinosWrappers::MPI::Vector &solution,
                     double                              *v)
    {
      const Quadrature<dim> q(GeometryInfo<dim>::project_to_unit_cell(unit));
      FEValues<dim>         fe_values(fe_space.mapping(),
                              cell->get_fe(),
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
      for (unsigned int d = 0; d < dim; ++d)
        v[d] = value[0][d];
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          v[dim + a * dim + b] = stress.in_plane[a][b];
      v[dim + dim * dim]     = stress.zz;
      v[dim + dim * dim + 1] = cell->material_id();
      return fe_values.quadrature_point(0);
    }
  } // namespace

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
    // u, σ (dim × dim), σzz and the material, then the point's state,
    // per point; only the winning rank fills them.
    const unsigned int  n_mechanics = dim + dim * dim + 2;
    const unsigned int  n_values    = n_mechanics + PointState<dim>::n_values;
    PointState<dim>     state(stress_model);
    std::vector<double> local(points.size() * n_values, 0.0);
    const MPI_Comm      comm = dof_handler.get_communicator();
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
            double          *v = &local[k * n_values];
            const Point<dim> p =
              evaluate_in_cell(cell, unit, fe_space, stress_model, solution, v);
            state.evaluate(cell, unit, p, v + n_mechanics);
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
        state.store(v + n_mechanics, result[k]);
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

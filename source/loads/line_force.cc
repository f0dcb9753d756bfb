#include <deal.II/base/mpi.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/loads/line_force.h>
#include <lithostress/loads/load_collection.h>

#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  LineForce<dim>::declare_parameters(ParameterHandler &prm, ParameterHandler *)
  {
    prm.enter_subsection("Line forces");
    prm.declare_entry("Points",
                      "",
                      Patterns::Anything(),
                      "Where the line forces act: `x1, y1; x2, y2` [length "
                      "unit]; each is applied at the nearest mesh vertex.");
    prm.declare_entry("Forces",
                      "",
                      Patterns::Anything(),
                      "The force vector at each point: `fx1, fy1; fx2, fy2` "
                      "[N/m], y up (a downward load has negative fy).");
    TimeFactor::declare_parameters(prm);
    prm.leave_subsection();
  }

  template <int dim>
  void
  LineForce<dim>::read_parameters(ParameterHandler            &prm,
                                  const ModelDescription<dim> &model)
  {
    const std::string where = "Loads/Line forces/";
    prm.enter_subsection("Line forces");
    points = parse_point_list<dim>(prm.get("Points"),
                                   where + "Points",
                                   model.length_scale);
    const auto f =
      parse_point_list<dim>(prm.get("Forces"), where + "Forces", 1.0);
    time_factor.parse_parameters(prm, where + "Time factor");
    prm.leave_subsection();
    if (f.size() != points.size())
      throw_input_error(where + "Forces",
                        "needs one force per point (" +
                          std::to_string(points.size()) + ")");
    forces.clear();
    for (const auto &v : f)
      forces.emplace_back(v);
  }

  template <int dim>
  void
  LineForce<dim>::check_against_mesh(const Triangulation<dim> &tria,
                                     const Mapping<dim>       &mapping) const
  {
    for (const Point<dim> &p : points)
      if (!point_in_mesh(tria, mapping, p))
        throw_input_error("Loads/Line forces/Points",
                          "the point (" + std::to_string(p[0]) + ", " +
                            std::to_string(p[1]) + ") [m] is outside the body");
  }

  template <int dim>
  void
  LineForce<dim>::add_point_terms(const DoFHandler<dim> &dof_handler,
                                  const FiniteElementSpace<dim> &,
                                  const AffineConstraints<double> &constraints,
                                  TrilinosWrappers::MPI::Vector   &rhs) const
  {
    const MPI_Comm     comm = dof_handler.get_communicator();
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    // On every rank: a factor that is not finite is an error on all.
    const double factor = time_factor.value(this->time());
    for (unsigned int k = 0; k < points.size(); ++k)
      {
        // The nearest vertex of an owned cell; the rank with the smallest
        // distance (lowest rank on ties) applies the force.
        double distance = std::numeric_limits<double>::max();
        typename DoFHandler<dim>::active_cell_iterator best;
        unsigned int                                   best_vertex = 0;
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            for (const unsigned int v : cell->vertex_indices())
              {
                const double d = cell->vertex(v).distance(points[k]);
                if (d < distance)
                  {
                    distance    = d;
                    best        = cell;
                    best_vertex = v;
                  }
              }
        const double       smallest = Utilities::MPI::min(distance, comm);
        const unsigned int owner =
          Utilities::MPI::min(distance == smallest
                                ? rank
                                : std::numeric_limits<unsigned int>::max(),
                              comm);
        if (owner != rank)
          continue;
        const unsigned int                   fe_index = best->active_fe_index();
        std::vector<types::global_dof_index> dofs(dim);
        Vector<double>                       values(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            dofs[d]   = best->vertex_dof_index(best_vertex, d, fe_index);
            values[d] = factor * forces[k][d];
          }
        constraints.distribute_local_to_global(values, dofs, rhs);
      }
  }

  template <int dim>
  std::string
  LineForce<dim>::description() const
  {
    std::ostringstream out;
    out << "line forces [N/m] at the nearest vertex:";
    for (unsigned int k = 0; k < points.size(); ++k)
      out << (k == 0 ? " " : "; ") << forces[k] << " at (" << points[k]
          << ") m";
    if (!time_factor.is_one())
      out << ", times " << time_factor.text();
    return out.str();
  }

  template class LineForce<2>;
  LITHOSTRESS_REGISTER_LOAD(LineForce, "line force", "forces at points", 60)
} // namespace lithostress

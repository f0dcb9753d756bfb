#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>

#include <lithostress/base/output_file.h>
#include <lithostress/analysis/surface_profile.h>

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <limits>

namespace lithostress
{
  template <int dim>
  std::vector<std::array<double, 1 + 2 * dim>>
  surface_profile(const DoFHandler<dim>               &dof_handler,
                  const FiniteElementSpace<dim>       &fe_space,
                  const TrilinosWrappers::MPI::Vector &solution,
                  const types::boundary_id             boundary)
  {
    // Points (x, y) with their displacement, from every owned face on the
    // part; the displacement is continuous, so duplicates agree.
    const FE_Q<dim>           scalar(fe_space.degree());
    const Quadrature<dim - 1> points(scalar.get_unit_face_support_points());
    std::vector<double>       local;
    hp::QCollection<dim - 1>  face_points;
    for (unsigned int i = 0; i < fe_space.fe_collection().size(); ++i)
      face_points.push_back(points);
    hp::FEFaceValues<dim>       hp_face_values(fe_space.mapping_collection(),
                                         fe_space.fe_collection(),
                                         face_points,
                                         update_values |
                                           update_quadrature_points);
    std::vector<Tensor<1, dim>> values(points.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == boundary)
            {
              hp_face_values.reinit(cell, f);
              const FEFaceValues<dim> &fe_face_values =
                hp_face_values.get_present_fe_values();
              const auto u = fe_space.displacement(
                fe_space.field_of(cell->active_fe_index()));
              fe_face_values[u].get_function_values(solution, values);
              for (unsigned int q = 0; q < points.size(); ++q)
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    local.push_back(fe_face_values.quadrature_point(q)[d]);
                  for (unsigned int d = 0; d < dim; ++d)
                    local.push_back(values[q][d]);
                }
            }
    const auto gathered =
      Utilities::MPI::all_gather(dof_handler.get_communicator(), local);
    std::vector<std::array<double, 1 + 2 * dim>> rows;
    for (const auto &part : gathered)
      for (unsigned int k = 0; k + 2 * dim <= part.size(); k += 2 * dim)
        {
          std::array<double, 1 + 2 * dim> row;
          for (unsigned int c = 0; c < 2 * dim; ++c)
            row[c] = part[k + c];
          rows.push_back(row);
        }
    std::sort(rows.begin(), rows.end(), [](const auto &a, const auto &b) {
      return a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]);
    });
    // One row per distinct support point.
    std::vector<std::array<double, 1 + 2 * dim>> unique;
    for (const auto &row : rows)
      {
        const double scale = std::max(1.0, std::abs(row[0]));
        if (unique.empty() ||
            std::abs(unique.back()[0] - row[0]) > 1e-9 * scale ||
            std::abs(unique.back()[1] - row[1]) > 1e-9 * scale)
          unique.push_back(row);
      }
    return unique;
  }

  template <int dim>
  void
  write_surface_profile(
    const std::string                                  &filename,
    const std::vector<std::array<double, 1 + 2 * dim>> &profile)
  {
    OutputFile out(filename);
    out << "x,u_x,u_y,y\n"
        << std::setprecision(std::numeric_limits<double>::max_digits10);
    for (const auto &row : profile)
      out << row[0] << ',' << row[2] << ',' << row[3] << ',' << row[1] << '\n';
    out.commit();
  }

  template std::vector<std::array<double, 5>>
  surface_profile<2>(const DoFHandler<2> &,
                     const FiniteElementSpace<2> &,
                     const TrilinosWrappers::MPI::Vector &,
                     const types::boundary_id);
  template void
  write_surface_profile<2>(const std::string &,
                           const std::vector<std::array<double, 5>> &);
} // namespace lithostress

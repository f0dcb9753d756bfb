#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>
#include <lithostress/postprocessors/figures.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>

namespace lithostress
{
  template <int dim>
  void
  Figures<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.enter_subsection("Figures");
    prm.declare_entry("Enabled",
                      "true",
                      Patterns::Bool(),
                      "After the last cycle, write mesh_outline.csv and "
                      "principal_stresses.csv and draw PNG figures "
                      "(principal-stress crosses, surface profile, "
                      "stress-depth profiles) with scripts/plot_figures.py; "
                      "needs python3-matplotlib, else a warning.");
    prm.declare_entry("Stress cross spacing",
                      "0",
                      Patterns::Double(0),
                      "Spacing [length unit] of the grid of principal-stress "
                      "crosses; 0 = automatic (the smaller of 1/40 of the "
                      "width and 1/4 of the height).");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  void
  Figures<dim>::parse_parameters(ParameterHandler  &prm,
                                 const double       length_scale,
                                 const std::string &length_unit)
  {
    this->length_scale = length_scale;
    this->length_unit  = length_unit;
    prm.enter_subsection("Output");
    prm.enter_subsection("Figures");
    enabled       = prm.get_bool("Enabled");
    cross_spacing = prm.get_double("Stress cross spacing") * length_scale;
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  void
  Figures<dim>::write_data(const std::string                   &directory,
                           const std::string                   &title,
                           const DoFHandler<dim>               &dof_handler,
                           const FiniteElementSpace<dim>       &fe_space,
                           const StressModel<dim>              &stress_model,
                           const GriffithFailure               &griffith,
                           const TrilinosWrappers::MPI::Vector &solution,
                           const double envelope_strain_rate) const
  {
    if (!enabled)
      return;
    const MPI_Comm comm = dof_handler.get_communicator();
    const bool     root = Utilities::MPI::this_mpi_process(comm) == 0;
    const auto    &tria = dof_handler.get_triangulation();

    // The outline: every boundary face, through the mapping, as four
    // straight segments.
    const FE_Q<dim>                    fe(1);
    const QIterated<dim - 1>           along(QTrapezoid<1>(), 4);
    FEFaceValues<dim>                  face_values(fe_space.mapping(),
                                  fe,
                                  along,
                                  update_quadrature_points);
    std::vector<std::array<double, 4>> segments;
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              face_values.reinit(cell, f);
              for (unsigned int q = 0; q + 1 < along.size(); ++q)
                {
                  const Point<dim> &a = face_values.quadrature_point(q);
                  const Point<dim> &b = face_values.quadrature_point(q + 1);
                  segments.push_back({{a[0], a[1], b[0], b[1]}});
                }
            }
    const auto all_segments = Utilities::MPI::gather(comm, segments, 0);
    on_all_ranks(comm, [&]() {
      if (root)
        {
          OutputFile out(directory + "/mesh_outline.csv");
          out << "x0,y0,x1,y1\n" << std::setprecision(10);
          for (const auto &rank_segments : all_segments)
            for (const auto &s : rank_segments)
              out << s[0] << ',' << s[1] << ',' << s[2] << ',' << s[3] << '\n';
          out.commit();
        }
    });

    // The stress crosses on a regular grid over the body.
    const BoundingBox<dim> box(tria.get_vertices());
    const double           width  = box.side_length(0);
    const double           height = box.side_length(dim - 1);
    const double           h =
      cross_spacing > 0 ? cross_spacing : std::min(width / 40, height / 4);
    const unsigned int nx =
      std::max(1u, static_cast<unsigned int>(std::floor(width / h)));
    const unsigned int ny =
      std::max(1u, static_cast<unsigned int>(std::floor(height / h)));
    if (static_cast<double>(nx) * ny > 20000)
      throw_input_error("Output/Figures/Stress cross spacing",
                        "gives " + std::to_string(nx) + " x " +
                          std::to_string(ny) +
                          " crosses; use a larger spacing");
    std::vector<Point<dim>> grid;
    for (unsigned int j = 0; j < ny; ++j)
      for (unsigned int i = 0; i < nx; ++i)
        {
          Point<dim> p;
          p[0]       = box.lower_bound(0) + (i + 0.5) * width / nx;
          p[dim - 1] = box.lower_bound(dim - 1) + (j + 0.5) * height / ny;
          grid.push_back(p);
        }
    auto samples = sample_stresses(
      dof_handler, fe_space, stress_model, griffith, solution, grid, true);
    if (envelope_strain_rate > 0)
      add_strength_envelope(samples, stress_model, envelope_strain_rate);
    on_all_ranks(comm, [&]() {
      if (root)
        {
          write_stress_samples(directory + "/principal_stresses.csv", samples);
          OutputFile json(directory + "/figures.json");
          json << "{\"title\": \"" << title << "\", \"length_unit\": \""
               << length_unit << "\", \"length_scale\": " << length_scale
               << ", \"stress_unit_scale\": 1e6}\n";
          json.commit();
        }
    });
  }

  template <int dim>
  void
  Figures<dim>::plot(const std::string &directory, RunLog &log) const
  {
    if (!enabled)
      return;
    std::string messages;
    int         status = 0;
    // Rank 0 runs the script; the others wait for its messages.
    if (log.on_root())
      {
        const std::string command =
          std::string("/usr/bin/python3 ") + LITHOSTRESS_SOURCE_DIR +
          "/scripts/plot_figures.py '" + directory + "' 2>&1";
        FILE *pipe = popen(command.c_str(), "r");
        if (pipe == nullptr)
          status = -1;
        else
          {
            char buffer[512];
            while (fgets(buffer, sizeof(buffer), pipe) != nullptr)
              messages += buffer;
            status = pclose(pipe);
          }
      }
    if (status != 0)
      log << "warning: the figures could not be made (scripts/"
             "plot_figures.py exited with status "
          << status << "); the results are complete without them\n";
    log << messages;
  }

  template class Figures<2>;
} // namespace lithostress

#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/analysis/point_values.h>
#include <lithostress/analysis/stress_sampling.h>
#include <lithostress/postprocessors/point_values_output.h>

#include <iomanip>
#include <sstream>

namespace lithostress
{
  template <int dim>
  void
  PointValuesOutput<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Convergence study");
    prm.declare_entry("Points",
                      "",
                      Patterns::Anything(),
                      "Points at which displacement and stress are reported "
                      "each cycle (point_values.csv) and, in the visco-"
                      "elastic loop, at each output time (point_history.csv): "
                      "`x1, y1; x2, y2` [length unit].");
    prm.leave_subsection();
  }

  template <int dim>
  void
  PointValuesOutput<dim>::parse_parameters(ParameterHandler           &prm,
                                           const SimulatorAccess<dim> &a)
  {
    prm.enter_subsection("Convergence study");
    points = parse_point_list<dim>(prm.get("Points"),
                                   "Convergence study/Points",
                                   a.length_scale);
    prm.leave_subsection();
    for (const Point<dim> &p : points)
      if (!point_in_mesh<dim>(a.triangulation, a.fe_space.mapping(), p))
        throw_input_error("Convergence study/Points",
                          "the point (" + std::to_string(p[0]) + ", " +
                            std::to_string(p[1]) + ") [m] is outside the mesh");
  }

  template <int dim>
  void
  PointValuesOutput<dim>::cycle_finished(const SimulatorAccess<dim> &a,
                                         const unsigned int,
                                         ConvergenceStudy &study,
                                         std::ostream &)
  {
    const auto samples = sample_stresses(a.dof_handler,
                                         a.fe_space,
                                         a.stress_model,
                                         a.griffith,
                                         a.solution,
                                         points);
    on_all_ranks(a.communicator, [&]() {
      if (!points.empty() && a.root())
        write_stress_samples(a.path("point_values.csv"), samples);
    });
    using Kind = ConvergenceStudy::Kind;
    for (unsigned int k = 0; k < samples.size(); ++k)
      {
        const std::string      at = "@P" + std::to_string(k + 1);
        const PointValue<dim> &v  = samples[k].value;
        study.add("u_x" + at, v.displacement[0], Kind::functional);
        study.add("u_y" + at, v.displacement[1], Kind::functional);
        study.add("s_xx" + at, v.stress[0][0], Kind::functional);
        study.add("s_yy" + at, v.stress[1][1], Kind::functional);
        study.add("s_xy" + at, v.stress[0][1], Kind::functional);
        if (a.reference)
          study.add(
            "err_u" + at,
            (v.displacement - a.reference->displacement(v.point)).norm(),
            Kind::error);
      }
  }

  template <int dim>
  void
  PointValuesOutput<dim>::output_time(const SimulatorAccess<dim> &a,
                                      const unsigned int,
                                      const double time)
  {
    if (points.empty())
      return;
    const auto values = evaluate_at_points(
      a.dof_handler, a.fe_space, a.stress_model, a.solution, points);
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        std::ostringstream row;
        row << std::setprecision(10) << time << ',' << k + 1 << ','
            << values[k].point[0] << ',' << values[k].point[1] << ','
            << values[k].displacement[0] << ',' << values[k].displacement[1]
            << ',' << values[k].stress[0][0] << ',' << values[k].stress[1][1]
            << ',' << values[k].stress[0][1] << ',' << values[k].sigma_zz;
        history.push_back(row.str());
      }
    write_history(a);
  }

  template <int dim>
  void
  PointValuesOutput<dim>::write_history(const SimulatorAccess<dim> &a) const
  {
    on_all_ranks(a.communicator, [&]() {
      if (!a.root() || points.empty())
        return;
      OutputFile csv(a.path("point_history.csv"));
      csv << "time,point,x,y,u_x,u_y,s_xx,s_yy,s_xy,s_zz\n";
      for (const std::string &row : history)
        csv << row << '\n';
      csv.commit();
    });
  }

  template <int dim>
  void
  PointValuesOutput<dim>::save(std::map<std::string, std::string> &state) const
  {
    std::ostringstream rows;
    for (const std::string &row : history)
      rows << row << '\n';
    state["point_history"] = rows.str();
  }

  template <int dim>
  void
  PointValuesOutput<dim>::load(const SimulatorAccess<dim>               &a,
                               const std::map<std::string, std::string> &state)
  {
    history.clear();
    const auto found = state.find("point_history");
    if (found != state.end())
      {
        std::istringstream rows(found->second);
        for (std::string row; std::getline(rows, row);)
          history.push_back(row);
      }
    write_history(a);
  }

  template class PointValuesOutput<2>;
  LITHOSTRESS_REGISTER_POSTPROCESSOR(
    PointValuesOutput,
    "point values",
    "values at report points (point_values.csv)",
    30)
} // namespace lithostress

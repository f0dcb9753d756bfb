#include <deal.II/base/mpi.h>

#include <lithostress/analysis/fault_output.h>
#include <lithostress/analysis/stress_sampling.h>
#include <lithostress/analysis/surface_profile.h>
#include <lithostress/base/output_file.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

namespace lithostress
{
  template <int dim>
  std::vector<FaultSample>
  sample_fault(const FaultInterface<dim>           &faults,
               const DoFHandler<dim>               &dof_handler,
               const FiniteElementSpace<dim>       &fe_space,
               const TrilinosWrappers::MPI::Vector &solution,
               const FaultHistory                  &history)
  {
    using PointValues = typename FaultInterface<dim>::PointValues;
    std::vector<FaultSample> samples;
    faults.for_each_interface_point(
      dof_handler, fe_space, &solution, [&](const PointValues &values) {
        const unsigned int       i         = values.index;
        const auto              &p         = values.point;
        const Tensor<1, dim>    &w         = values.jump;
        const InterfaceLaw<dim> &law       = faults.law(p.fault);
        const bool               nonlinear = law.nonlinear();
        const Tensor<1, 2> down = faults.trace(p.fault).down_dip(p.position);
        FaultSample        sample;
        sample.fault         = p.fault;
        sample.s             = p.distance;
        sample.x             = p.position[0];
        sample.y             = p.position[1];
        sample.depth         = p.depth;
        sample.slip          = w[0] * down[0] + w[1] * down[1];
        sample.opening       = w * p.normal;
        sample.vertical_jump = w[1];
        // The traction of the last solve's state: the law's stuck response
        // with that history (the tractions of a frictional law's state).
        const InterfaceResponse r = law.predictor(
          FaultInterface<dim>::law_inputs(p, w, history.trial(i)));
        sample.shear_traction =
          r.shear_traction * (p.shear[0] * down[0] + p.shear[1] * down[1]);
        sample.normal_traction =
          law.exact_contact() && i < history.normal_traction.size()
            ? history.normal_traction[i]
            : r.normal_traction;
        if (nonlinear)
          {
            sample.normal_traction -= law.overburden(p.overburden_depth);
            sample.state = i < history.trial_states.size()
                             ? history.trial_states[i]
                             : SlipState::stuck;
            if (sample.state == SlipState::open)
              sample.shear_traction = 0;
          }
        samples.push_back(sample);
      });
    // All ranks' samples, sorted along the fault.
    const auto all =
      Utilities::MPI::all_gather(dof_handler.get_communicator(), samples);
    samples.clear();
    for (const auto &part : all)
      samples.insert(samples.end(), part.begin(), part.end());
    std::sort(samples.begin(),
              samples.end(),
              [](const FaultSample &a, const FaultSample &b) {
                return a.fault < b.fault ||
                       (a.fault == b.fault &&
                        (a.s < b.s || (a.s == b.s && a.x < b.x)));
              });
    return samples;
  }

  void
  write_fault_csv(const std::string              &filename,
                  const std::vector<FaultSample> &samples)
  {
    OutputFile out(filename);
    out << "s,x,y,slip,opening,shear_traction,normal_traction,state\n"
        << std::setprecision(10);
    for (const FaultSample &p : samples)
      out << p.s << ',' << p.x << ',' << p.y << ',' << p.slip << ','
          << p.opening << ',' << p.shear_traction << ',' << p.normal_traction
          << ',' << to_string(p.state) << '\n';
    out.commit();
  }

  FaultSummary
  summarize_fault(const std::vector<FaultSample> &samples,
                  const FaultTrace               &trace)
  {
    FaultSummary summary;
    for (const FaultSample &p : samples)
      {
        if (p.state != SlipState::stuck)
          summary.sliding_depth_m = std::max(summary.sliding_depth_m, p.depth);
        if (std::abs(p.slip) > std::abs(summary.max_slip_m))
          {
            summary.max_slip_m        = p.slip;
            summary.max_slip_offset_m = -p.vertical_jump;
          }
      }
    // The interface points are Gauss-Lobatto points: the first and the
    // last lie on the fault's ends.
    if (trace.buried_top() && !samples.empty())
      summary.upper_tip_depth_m = samples.front().depth;
    if (trace.buried_bottom() && !samples.empty())
      summary.lower_tip_depth_m = samples.back().depth;
    // The vertical jump at s = 0, linear through the two shallowest points
    // at different s; a buried fault does not reach the surface.
    if (!samples.empty() && !trace.buried_top())
      {
        const FaultSample &a = samples.front();
        summary.throw_m      = -a.vertical_jump;
        for (const FaultSample &b : samples)
          if (b.s > a.s * (1 + 1e-9) + 1e-9)
            {
              const double jump =
                a.vertical_jump -
                a.s * (b.vertical_jump - a.vertical_jump) / (b.s - a.s);
              summary.throw_m = -jump;
              break;
            }
      }
    return summary;
  }

  template <int dim>
  double
  tensile_failure_distance(const FaultTrace                    &trace,
                           const double                         throw_m,
                           const DoFHandler<dim>               &dof_handler,
                           const FiniteElementSpace<dim>       &fe_space,
                           const StressModel<dim>              &stress_model,
                           const GriffithFailure               &griffith,
                           const TrilinosWrappers::MPI::Vector &solution,
                           const types::boundary_id             top)
  {
    const double            side = (throw_m >= 0 ? 1. : -1.) * trace.direction;
    std::vector<Point<dim>> points;
    for (const auto &row :
         surface_profile(dof_handler, fe_space, solution, top))
      if (side * (row[0] - trace.surface_x) > 1e-6 * std::abs(row[0]) + 1e-3)
        points.emplace_back(row[0], row[1]);
    // Ranked by sigma_1, the Griffith criterion's excess sigma_1 - T at a
    // free surface (its tensile regime): C = 1 - tau_m/(T - sigma_m)
    // orders points the same way below sigma_m = T but is singular there,
    // which would pick the edge of the failed region instead of its most
    // failed point (doc/faults.md).
    std::vector<std::pair<double, double>> x_sigma;
    for (const auto &sample : sample_stresses(
           dof_handler, fe_space, stress_model, griffith, solution, points))
      x_sigma.emplace_back(sample.value.point[0],
                           sample.analysis.principal.sigma_1);
    if (x_sigma.empty())
      return std::nan("");
    std::sort(x_sigma.begin(), x_sigma.end());
    const auto highest = std::max_element(x_sigma.begin(),
                                          x_sigma.end(),
                                          [](const auto &a, const auto &b) {
                                            return a.second < b.second;
                                          });
    double     x       = highest->first;
    // Between the surface's nodes: the vertex of the parabola through the
    // largest sigma_1 and its two neighbours (the nodes are a cell's
    // length apart, too coarse for the graben widths of thesis table 6.3).
    if (highest != x_sigma.begin() && highest + 1 != x_sigma.end())
      {
        const auto  &a = *(highest - 1), &b = *highest, &c = *(highest + 1);
        const double ab        = (b.second - a.second) / (b.first - a.first),
                     bc        = (c.second - b.second) / (c.first - b.first),
                     curvature = (bc - ab) / (c.first - a.first);
        if (curvature < 0)
          x = 0.5 * (a.first + b.first) - ab / (2 * curvature);
      }
    return std::abs(x - trace.surface_x);
  }

  void
  write_fault_summary(const std::string &filename, const FaultSummary &summary)
  {
    OutputFile out(filename);
    const auto number = [](const double x) {
      std::ostringstream s;
      if (std::isfinite(x))
        s << std::setprecision(10) << x;
      else
        s << "null";
      return s.str();
    };
    out << "{\"throw_m\": " << number(summary.throw_m)
        << ", \"max_slip_m\": " << number(summary.max_slip_m)
        << ", \"upper_tip_depth_m\": " << number(summary.upper_tip_depth_m)
        << ", \"lower_tip_depth_m\": " << number(summary.lower_tip_depth_m)
        << ", \"sliding_depth_m\": " << number(summary.sliding_depth_m)
        << ", \"nonlinear_iterations\": " << summary.nonlinear_iterations
        << ", \"linear_solves\": " << summary.linear_solves
        << ", \"tensile_failure_distance_m\": "
        << number(summary.tensile_failure_distance_m) << "}\n";
    out.commit();
  }

  template double
  tensile_failure_distance(const FaultTrace &,
                           const double,
                           const DoFHandler<2> &,
                           const FiniteElementSpace<2> &,
                           const StressModel<2> &,
                           const GriffithFailure &,
                           const TrilinosWrappers::MPI::Vector &,
                           const types::boundary_id);
  template std::vector<FaultSample>
  sample_fault(const FaultInterface<2> &,
               const DoFHandler<2> &,
               const FiniteElementSpace<2> &,
               const TrilinosWrappers::MPI::Vector &,
               const FaultHistory &);
} // namespace lithostress

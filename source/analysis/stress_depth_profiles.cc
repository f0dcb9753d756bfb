#include <lithostress/analysis/stress_depth_profiles.h>
#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>

#include <deal.II/grid/grid_tools.h>

#include <array>

namespace lithostress
{
  template <int dim>
  void
  StressDepthProfiles<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Stress-depth profiles",
                      "",
                      Patterns::Anything(),
                      "x positions [length unit] of vertical lines along "
                      "which stresses are written after the last cycle, "
                      "`x1, x2, ...`: stress_depth_x<x>.csv with depth, "
                      "displacement, stresses, principal and deviatoric "
                      "stresses and the Griffith test (m, Pa), and the "
                      "temperature [K] where Temperature/Model gives one.");
    prm.declare_entry("Strength envelope strain rate",
                      "1e-15",
                      Patterns::Double(0),
                      "The strain rate [1/s] of the strength envelope in "
                      "the stress-depth profiles and in the figures' "
                      "principal_stresses.csv, where rocks yield or "
                      "creep (Rheology = visco-elasto-plastic): columns "
                      "tau_II, strength_brittle, strength_ductile and their "
                      "minimum, strength (Pa; empty where a rock has no "
                      "such branch); 0: none.");
    prm.declare_entry("Points per profile",
                      "101",
                      Patterns::Integer(2),
                      "Number of equally spaced points from the top to the "
                      "base of the body on each profile line.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  StressDepthProfiles<dim>::parse_parameters(ParameterHandler &prm,
                                             const double      length_scale)
  {
    this->length_scale = length_scale;
    positions.clear();
    labels.clear();
    prm.enter_subsection("Output");
    for (const std::string &x : split_list(prm.get("Stress-depth profiles")))
      {
        positions.push_back(parse_number(x, "Output/Stress-depth profiles") *
                            length_scale);
        labels.push_back("x" + x);
      }
    n_points             = prm.get_integer("Points per profile");
    envelope_strain_rate = prm.get_double("Strength envelope strain rate");
    prm.leave_subsection();
  }

  template <int dim>
  void
  StressDepthProfiles<dim>::write(
    const std::string                   &directory,
    const DoFHandler<dim>               &dof_handler,
    const FiniteElementSpace<dim>       &fe_space,
    const StressModel<dim>              &stress_model,
    const GriffithFailure               &griffith,
    const TrilinosWrappers::MPI::Vector &solution) const
  {
    const auto &tria = dof_handler.get_triangulation();
    // The vertical extent of the body, from its vertices (a curved boundary
    // may bulge slightly beyond them: widen by a little).
    const BoundingBox<dim> box(tria.get_vertices());
    const double           height = box.side_length(dim - 1);
    const double           bottom = box.lower_bound(dim - 1) - 1e-3 * height;
    const double           top    = box.upper_bound(dim - 1) + 1e-3 * height;
    const MPI_Comm         comm   = dof_handler.get_communicator();
    for (unsigned int l = 0; l < positions.size(); ++l)
      {
        // Find the body's top and base on this line with a fine search,
        // then sample equally between them.
        const unsigned int      n_search = 8 * n_points;
        std::vector<Point<dim>> search(n_search);
        for (unsigned int k = 0; k < n_search; ++k)
          {
            search[k][0]       = positions[l];
            search[k][dim - 1] = top - (top - bottom) * k / (n_search - 1);
          }
        const auto probe = evaluate_at_points(
          dof_handler, fe_space, stress_model, solution, search, true);
        int first = -1, last = -1;
        for (unsigned int k = 0; k < n_search; ++k)
          if (probe[k].inside)
            {
              if (first < 0)
                first = k;
              last = k;
            }
        if (first < 0 || first == last)
          throw_input_error("Output/Stress-depth profiles",
                            "the vertical line at x = " +
                              std::to_string(positions[l] / length_scale) +
                              " [length unit] does not cross the body");
        // Refine the top and the base to the boundary: each round samples
        // both bracketing intervals at once (one collective evaluation),
        // shrinking them 33-fold; 6 rounds reach 1e-9 of the search step.
        // The brackets are [outside, inside] pairs of heights.
        const bool top_inside_search  = first == 0;
        const bool base_inside_search = last + 1 == static_cast<int>(n_search);
        std::array<std::pair<double, double>, 2> bracket = {
          {{top_inside_search ? search[0][dim - 1] : search[first - 1][dim - 1],
            search[first][dim - 1]},
           {base_inside_search ? search[last][dim - 1]
                               : search[last + 1][dim - 1],
            search[last][dim - 1]}}};
        constexpr unsigned int n_split = 32;
        for (unsigned int round = 0; round < 6; ++round)
          {
            std::vector<Point<dim>> trial;
            for (unsigned int b = 0; b < 2; ++b)
              for (unsigned int k = 1; k <= n_split; ++k)
                {
                  Point<dim> p;
                  p[0] = positions[l];
                  p[dim - 1] =
                    bracket[b].first +
                    (bracket[b].second - bracket[b].first) * k / (n_split + 1);
                  trial.push_back(p);
                }
            const auto values = evaluate_at_points(
              dof_handler, fe_space, stress_model, solution, trial, true);
            for (unsigned int b = 0; b < 2; ++b)
              {
                // Walk from the outside end to the first point inside.
                double outside = bracket[b].first;
                for (unsigned int k = 0; k < n_split; ++k)
                  {
                    if (values[b * n_split + k].inside)
                      {
                        bracket[b].second = trial[b * n_split + k][dim - 1];
                        break;
                      }
                    outside = trial[b * n_split + k][dim - 1];
                  }
                bracket[b].first = outside;
              }
          }
        const double y_top =
          top_inside_search ? search[0][dim - 1] : bracket[0].second;
        const double y_base =
          base_inside_search ? search[last][dim - 1] : bracket[1].second;
        std::vector<Point<dim>> points(n_points);
        for (unsigned int k = 0; k < n_points; ++k)
          {
            points[k][0]       = positions[l];
            points[k][dim - 1] = y_top - (y_top - y_base) * k / (n_points - 1);
          }
        auto samples = sample_stresses(dof_handler,
                                       fe_space,
                                       stress_model,
                                       griffith,
                                       solution,
                                       points,
                                       true);
        if (envelope_strain_rate > 0)
          add_strength_envelope(samples, stress_model, envelope_strain_rate);
        on_all_ranks(comm, [&]() {
          if (Utilities::MPI::this_mpi_process(comm) == 0)
            write_stress_samples(directory + "/stress_depth_" + labels[l] +
                                   ".csv",
                                 samples,
                                 y_top);
        });
      }
  }

  template <int dim>
  void
  StressDepthProfiles<dim>::check_against_mesh(
    const Triangulation<dim> &tria) const
  {
    const BoundingBox<dim> box(tria.get_vertices());
    for (const double x : positions)
      if (x < box.lower_bound(0) || x > box.upper_bound(0))
        throw_input_error(
          "Output/Stress-depth profiles",
          "the vertical line at x = " + std::to_string(x / length_scale) +
            " [length unit] misses the body (x from " +
            std::to_string(box.lower_bound(0) / length_scale) + " to " +
            std::to_string(box.upper_bound(0) / length_scale) + ")");
  }

  template class StressDepthProfiles<2>;
} // namespace lithostress

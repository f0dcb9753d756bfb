#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/manifold.h>

#include <lithostress/base/huge_pages.h>
#include <lithostress/base/input_error.h>
#include <lithostress/base/interruption.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/boundary_conditions/rigid_body_support.h>
#include <lithostress/discretization/elastic_assembler.h>
#include <lithostress/faults/fault_output.h>
#include <lithostress/geometry/coarse_mesh_writer.h>
#include <lithostress/output/output_file.h>
#include <lithostress/postprocess/error_norms.h>
#include <lithostress/postprocess/force_balance.h>
#include <lithostress/postprocess/point_values.h>
#include <lithostress/postprocess/stress_sampling.h>
#include <lithostress/postprocess/surface_profile.h>
#include <lithostress/postprocess/thin_plate_flexure.h>
#include <lithostress/simulator.h>
#include <lithostress/time_integration/checkpoint.h>
#include <lithostress/time_integration/viscoelastic_time_loop.h>

#include <sys/resource.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>

namespace lithostress
{
  template <int dim>
  void
  Simulator<dim>::declare_parameters(ParameterHandler &prm,
                                     ParameterHandler *first_pass)
  {
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::Anything(),
                      "Directory for all results; created if missing.");
    prm.declare_entry("Plane state",
                      "plane strain",
                      Patterns::Selection("plane strain|plane stress"),
                      "Plane strain (sigma_zz reported) or plane stress.");
    prm.enter_subsection("Discretization");
    prm.declare_entry("Polynomial degree",
                      "2",
                      Patterns::Integer(1, 4),
                      "Degree p of the Lagrange elements (Q2 by default).");
    prm.declare_entry("Mapping degree",
                      "2",
                      Patterns::Integer(1, 4),
                      "Degree of the mapping used in assembly, errors and "
                      "output on meshes with curved manifolds; 1 = "
                      "straight-sided cells. Meshes without curved parts "
                      "always use degree 1, which is the same geometry.");
    prm.declare_entry("Use manifolds",
                      "true",
                      Patterns::Bool(),
                      "Attach the geometry's manifolds (curved boundaries); "
                      "false = new vertices on straight lines (for tests).");
    prm.leave_subsection();
    GeometrySelector<dim>::declare_parameters(prm);
    MaterialLibrary::declare_parameters(prm, first_pass);
    PrescribedDisplacement<dim>::declare_parameters(prm, first_pass);
    FaultInterface<dim>::declare_parameters(prm, first_pass);
    FrictionalSlidingSolver<dim>::declare_parameters(prm);
    LoadCollection<dim>::declare_parameters(prm, first_pass);
    MeshRefinement<dim>::declare_parameters(prm);
    StressGoals<dim>::declare_parameters(prm);
    LinearSolverSelector<dim>::declare_parameters(prm);
    MemoryBudget::declare_parameters(prm);
    SolutionOutput<dim>::declare_parameters(prm);
    prm.enter_subsection("Output");
    prm.declare_entry("Surface profile boundary",
                      "",
                      Patterns::Anything(),
                      "Boundary part whose displacement is written to "
                      "surface_profile.csv (x, u_x, u_y, y in m, sorted by "
                      "x) each cycle; empty = none.");
    prm.declare_entry("Force balance",
                      "true",
                      Patterns::Bool(),
                      "After the last cycle, print the resultant of every "
                      "load and the reaction of every part with prescribed "
                      "displacement, and write force_balance.csv [N/m]; "
                      "costs one more assembly.");
    prm.leave_subsection();
    StressDepthProfiles<dim>::declare_parameters(prm);
    Figures<dim>::declare_parameters(prm);
    ThinPlateFlexure::declare_parameters(prm);
    GriffithFailure::declare_parameters(prm);
    TimeStepping::declare_parameters(prm);
    prm.enter_subsection("Convergence study");
    ReferenceSolutionSelector<dim>::declare_parameters(prm);
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
  Simulator<dim>::Simulator(const MPI_Comm communicator, ParameterHandler &prm)
      : communicator(communicator)
      , prm(prm)
      , log(communicator)
      , timer_stream(timer_text,
                     Utilities::MPI::this_mpi_process(communicator) == 0)
      , timer(std::make_unique<TimerOutput>(communicator,
                                            timer_stream,
                                            TimerOutput::never,
                                            TimerOutput::wall_times))
      , triangulation(
          communicator,
          // No island elimination: adaptive refinement at a
          // singularity must be able to refine a single cell, and
          // the mesh must not depend on the partition.
          Triangulation<dim>::limit_level_difference_at_vertices,
          // The geometric multigrid needs the level hierarchy.
          LinearSolverSelector<dim>::may_use_multigrid(prm)
            ? parallel::distributed::Triangulation<
                dim>::construct_multigrid_hierarchy
            : parallel::distributed::Triangulation<dim>::default_setting)
      , dof_handler(triangulation)
      , wall_clock(communicator, true)
  {
    try
      {
        TimerOutput::Scope t(*timer, "read and check model");
        read_model();
      }
    catch (...)
      {
        // Destroy the timer outside of stack unwinding so that it does not
        // warn about skipping its MPI summary.
        timer.reset();
        throw;
      }
  }

  template <int dim>
  void
  Simulator<dim>::read_model()
  {
    output_directory = prm.get("Output directory");
    plane_state      = parse_plane_state(prm.get("Plane state"));
    length_scale     = GeometrySelector<dim>::length_scale(prm);

    prm.enter_subsection("Discretization");
    const unsigned int degree         = prm.get_integer("Polynomial degree");
    const unsigned int mapping_degree = prm.get_integer("Mapping degree");
    const bool         use_manifolds  = prm.get_bool("Use manifolds");
    prm.leave_subsection();
    geometry = GeometrySelector<dim>::create(prm);
    geometry->create_coarse_mesh(triangulation);
    const std::string export_file =
      GeometrySelector<dim>::coarse_mesh_file(prm);
    on_all_ranks(communicator, [&]() {
      if (!export_file.empty() &&
          Utilities::MPI::this_mpi_process(communicator) == 0)
        write_coarse_mesh_msh(triangulation,
                              geometry->boundary_parts(),
                              geometry->named_regions(),
                              geometry->fault_traces(),
                              length_scale,
                              export_file);
    });
    if (!use_manifolds)
      {
        triangulation.reset_all_manifolds();
        triangulation.set_all_manifold_ids(numbers::flat_manifold_id);
      }
    // Without a curved manifold every cell stays straight-sided under
    // refinement, and a mapping of any degree reproduces the same bilinear
    // geometry; the degree-1 mapping gives it at a fraction of the cost.
    bool curved = false;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      {
        curved = curved || cell->manifold_id() != numbers::flat_manifold_id;
        for (const auto &face : cell->face_iterators())
          curved = curved || face->manifold_id() != numbers::flat_manifold_id;
      }
    faults.parse_parameters(prm, geometry->fault_traces(), length_scale);
    faults.identify(triangulation);
    sliding_solver.parse_parameters(prm);
    if (faults.active() && degree > 2)
      throw_input_error("Discretization/Polynomial degree",
                        "faults are implemented for degrees 1 and 2");
    // One displacement field per side of a fault.
    fe_space =
      std::make_unique<FiniteElementSpace<dim>>(degree,
                                                curved ? mapping_degree : 1,
                                                faults.active() ? 2 : 1);

    // Every material id and boundary part of the coarse mesh (the same on
    // all ranks).
    std::set<types::material_id> ids_in_mesh;
    std::set<types::boundary_id> boundary_ids;
    for (const auto &cell : triangulation.cell_iterators_on_level(0))
      {
        ids_in_mesh.insert(cell->material_id());
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary())
            boundary_ids.insert(face->boundary_id());
      }
    materials.parse_parameters(prm);
    materials.resolve(geometry->named_regions(), ids_in_mesh);

    prm.enter_subsection("Convergence study");
    reference = ReferenceSolutionSelector<dim>::create(prm,
                                                       materials,
                                                       plane_state,
                                                       length_scale);
    points    = parse_point_list<dim>(prm.get("Points"),
                                   "Convergence study/Points",
                                   length_scale);
    prm.leave_subsection();

    ModelDescription<dim> model;
    for (const auto &part : geometry->boundary_parts())
      if (boundary_ids.count(part.second) != 0)
        model.boundary_parts.insert(part);
    model.length_scale = length_scale;
    model.reference    = reference.get();
    loads.parse_parameters(prm, model);
    for (const auto &load : loads.loads())
      load->check_against_mesh(triangulation, fe_space->mapping());
    stress_model =
      std::make_unique<StressModel<dim>>(materials, plane_state, loads);
    prescribed_displacement.parse_parameters(prm, model);

    prm.enter_subsection("Output");
    const std::string surface =
      Utilities::trim(prm.get("Surface profile boundary"));
    with_force_balance = prm.get_bool("Force balance");
    prm.leave_subsection();
    if (!surface.empty())
      surface_boundary =
        model.boundary_id(surface, "Output/Surface profile boundary");
    thin_plate.parse_parameters(prm, materials, length_scale);
    griffith.parse_parameters(prm, length_scale);
    griffith.resolve_lithostatic_pressure(loads.without_body_force() ||
                                          loads.densities_stripped());
    profiles.parse_parameters(prm, length_scale);
    profiles.check_against_mesh(triangulation);
    prm.enter_subsection("Geometry");
    const std::string length_unit = prm.get("Length unit");
    prm.leave_subsection();
    figures.parse_parameters(prm, length_scale, length_unit);
    if (thin_plate.enabled && surface.empty())
      throw_input_error("Thin plate comparison/Enabled",
                        "needs Output/Surface profile boundary");

    refinement.parse_parameters(prm);
    goals.parse_parameters(prm, length_scale);
    if (refinement.strategy == MeshRefinement<dim>::Strategy::adaptive &&
        refinement.indicator == MeshRefinement<dim>::Indicator::goal_oriented &&
        goals.empty())
      throw_input_error("Mesh refinement/Indicator",
                        "`goal oriented` needs the goals in Mesh "
                        "refinement/Goals/Stress averages");
    if (goals.stop_tolerance() > 0 && goals.empty())
      throw_input_error("Mesh refinement/Goals/Stop at relative change",
                        "needs the goals in Mesh refinement/Goals/Stress "
                        "averages");
    time_stepping.parse_parameters(prm);
    if (time_stepping.enabled && time_stepping.resume)
      Checkpoint::check_resumable(output_directory, prm, communicator);
    if (time_stepping.enabled)
      creep = std::make_unique<CreepIntegrator<dim>>(triangulation,
                                                     fe_space->degree() + 1);
    linear_solver = LinearSolverSelector<dim>::create(
      prm,
      *fe_space,
      loads,
      prescribed_displacement.has_rigid_components()
        ? "a `rigid` boundary component ties DoFs along a whole edge"
        : "");
    solution_output.parse_parameters(prm);
    memory_budget.parse_parameters(prm, communicator);

    for (const Point<dim> &p : points)
      {
        const bool inside =
          point_in_mesh<dim>(triangulation, fe_space->mapping(), p);
        if (!inside)
          throw_input_error("Convergence study/Points",
                            "the point (" + std::to_string(p[0]) + ", " +
                              std::to_string(p[1]) +
                              ") [m] is outside the mesh");
      }
    check_well_posed(length_unit);
    check_output_directory();
  }

  template <int dim>
  void
  Simulator<dim>::check_well_posed(const std::string &length_unit)
  {
    // Rigid-body motions on the coarse mesh, where the test is exact.
    faults.set_active_fe_indices(dof_handler);
    dof_handler.distribute_dofs(fe_space->fe_collection());
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    on_all_ranks(communicator, [&]() {
      prescribed_displacement.apply(dof_handler, *fe_space, constraints);
      faults.add_constraints(dof_handler, *fe_space, constraints);
    });
    constraints.close();
    RigidBodySupport<dim>::check(dof_handler,
                                 *fe_space,
                                 constraints,
                                 loads,
                                 length_scale,
                                 length_unit,
                                 faults.interface_points(dof_handler,
                                                         *fe_space));

    // The first mesh, and with global refinement the last one, must fit
    // in memory. DoFs grow with the cells in the interior (dim p^dim per
    // cell) and with their square root on the boundary.
    const unsigned int degree        = fe_space->degree();
    const double       interior_dofs = dim * std::pow(degree, dim);
    const double       coarse_cells  = triangulation.n_global_active_cells();
    const double       boundary_dofs =
      std::max(0.0, dof_handler.n_dofs() - interior_dofs * coarse_cells);
    const auto check_mesh = [&](const std::string &mesh,
                                const unsigned int refinements) {
      const double growth = std::pow(2.0, refinements);
      const double cells  = coarse_cells * std::pow(growth, dim);
      memory_budget.check(
        mesh,
        cells,
        interior_dofs * cells + boundary_dofs * growth,
        linear_solver->name(),
        linear_solver->memory_per_dof(),
        linear_solver->memory_of_levels(coarse_cells,
                                        triangulation.n_global_levels() +
                                          refinements),
        "Mesh refinement/Initial global refinement" +
          std::string(refinement.strategy ==
                          MeshRefinement<dim>::Strategy::global
                        ? " or Number of cycles"
                        : ""));
    };
    const unsigned int first = refinement.initial_global_refinement;
    check_mesh("the first mesh (cycle 0)", first);
    if (refinement.strategy == MeshRefinement<dim>::Strategy::global &&
        refinement.n_cycles > 1)
      check_mesh("the mesh of the last cycle (" +
                   std::to_string(refinement.n_cycles - 1) + ")",
                 std::min(first + refinement.n_cycles - 1,
                          std::max(first, refinement.max_level)));
  }

  template <int dim>
  void
  Simulator<dim>::check_output_directory() const
  {
    std::string problem;
    if (Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(output_directory, error);
        if (error)
          problem = "cannot create it: " + error.message();
        else
          {
            const std::string probe = output_directory + "/.write-test";
            std::ofstream     out(probe);
            if (!out)
              problem = "cannot write into it";
            out.close();
            std::filesystem::remove(probe, error);
          }
      }
    problem = Utilities::MPI::broadcast(communicator, problem, 0);
    if (!problem.empty())
      throw_input_error("Output directory",
                        "<" + output_directory + ">: " + problem);
  }

  template <int dim>
  void
  Simulator<dim>::setup_dofs()
  {
    TimerOutput::Scope t(*timer, "setup");
    Timer              clock(communicator, true), part(communicator, true);
    statistics.setup_phases.clear();
    const auto phase_done = [&](const std::string &name) {
      statistics.setup_phases.emplace_back(name, part.wall_time());
      // The set-up is the longest phase without CG iterations: a safe
      // point after each of its parts.
      stop_if_requested("set-up (" + name + ")");
      part.restart();
    };
    faults.set_active_fe_indices(dof_handler);
    dof_handler.distribute_dofs(fe_space->fe_collection());
    phase_done("DoFs");
    linear_solver->prepare_dof_handler(dof_handler);
    phase_done("level DoFs");
    system.locally_owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler,
                                            system.locally_relevant);
    make_constraints();
    phase_done("constraints");
    system.reinit(dof_handler,
                  communicator,
                  linear_solver->needs_matrix(),
                  faults.has_face_terms() && linear_solver->needs_matrix()
                    ? faults.interface_cliques(dof_handler)
                    : std::vector<std::vector<types::global_dof_index>>());
    ++mesh_version;
    phase_done("sparsity pattern and matrix");
    // The previous mesh's solution; solve() sizes it anew.
    solution.clear();
    statistics.dofs       = dof_handler.n_dofs();
    statistics.cells      = triangulation.n_global_active_cells();
    statistics.setup_time = clock.wall_time();
  }

  template <int dim>
  void
  Simulator<dim>::make_constraints()
  {
    system.constraints.clear();
    system.constraints.reinit(system.locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, system.constraints);
    on_all_ranks(communicator, [&]() {
      prescribed_displacement.apply(dof_handler,
                                    *fe_space,
                                    system.constraints,
                                    time);
      faults.add_constraints(dof_handler, *fe_space, system.constraints, time);
    });
    system.constraints.close();
  }

  template <int dim>
  void
  Simulator<dim>::assemble_system()
  {
    TimerOutput::Scope t(*timer, "assemble");
    Timer              clock(communicator, true);
    // Mesh integrals of the loads once per mesh, not once per time step;
    // a slab pull that balances the other loads measures them there.
    const bool new_mesh = loads_prepared_for != mesh_version;
    if (new_mesh)
      for (const auto &load : loads.loads())
        load->prepare_for_mesh(triangulation,
                               fe_space->mapping(),
                               fe_space->face_quadrature()[0]);
    loads_prepared_for = mesh_version;
    for (const auto &load : loads.loads())
      load->set_time(time);
    if (new_mesh && loads.balances_vertical_loads())
      {
        TrilinosWrappers::MPI::Vector at_rest(dof_handler.locally_owned_dofs(),
                                              system.locally_relevant,
                                              communicator);
        std::vector<Tensor<1, dim>>   resultants;
        for (const auto &load : compute_force_balance(dof_handler,
                                                      *fe_space,
                                                      *stress_model,
                                                      loads,
                                                      prescribed_displacement,
                                                      at_rest)
                                  .loads)
          resultants.push_back(load.second);
        loads.balance(resultants);
      }
    ElasticAssembler<dim> assembler(*fe_space, *stress_model, loads);
    assembler.set_history_strain(history_strain);
    // The matrix only where the operator changed (the time loop assembles
    // many right-hand sides for one operator).
    const bool with_matrix =
      linear_solver->needs_matrix() && matrix_version != operator_version();
    assembler.assemble(dof_handler, system, with_matrix);
    faults.assemble(dof_handler,
                    *fe_space,
                    system.constraints,
                    with_matrix ? &system.matrix : nullptr,
                    system.rhs);
    if (with_matrix)
      matrix_version = operator_version();
    statistics.assemble_time = clock.wall_time();
  }

  template <int dim>
  void
  Simulator<dim>::solve()
  {
    TimerOutput::Scope t(*timer, "solve");
    Timer              clock(communicator, true);
    // The solver sizes owned_solution when its own vectors are gone, and
    // the ghosted solution is made after it: the peak memory of the solve
    // holds neither.
    TrilinosWrappers::MPI::Vector owned_solution;
    const DiscreteProblem<dim>    problem = discrete_problem();
    if (faults.frictional())
      {
        try
          {
            sliding_solver.solve(problem,
                                 faults,
                                 slip_history,
                                 owned_solution,
                                 statistics.solver,
                                 [&](const std::string &line) {
                                   log << line << std::endl;
                                 });
            if (!defer_slip_commit)
              slip_history.commit();
          }
        catch (const ComputationError &)
          {
            // The last iterate, for the user to look at, if it is one (a
            // diverged iteration has none).
            if (owned_solution.size() == dof_handler.n_dofs() &&
                std::isfinite(owned_solution.l2_norm()))
              {
                solution.reinit(system.locally_owned,
                                system.locally_relevant,
                                communicator);
                solution = owned_solution;
                write_fault_results();
              }
            throw;
          }
      }
    else
      statistics.solver = linear_solver->solve(problem, owned_solution);
    system.constraints.distribute(owned_solution);
    const double norm = owned_solution.l2_norm();
    if (!std::isfinite(norm))
      throw ComputationError("the solution of the linear system is not "
                             "finite (norm " +
                             std::to_string(norm) + ", " +
                             statistics.solver.solver + ")");
    solution.reinit(system.locally_owned,
                    system.locally_relevant,
                    communicator);
    solution = owned_solution;
    statistics.solve_time =
      clock.wall_time() - statistics.solver.benchmark_time;
    statistics.benchmark_time += statistics.solver.benchmark_time;
  }

  template <int dim>
  DiscreteProblem<dim>
  Simulator<dim>::discrete_problem()
  {
    return {dof_handler,
            *fe_space,
            system,
            *stress_model,
            loads,
            prescribed_displacement,
            keep_solver_setup,
            operator_version()};
  }

  template <int dim>
  void
  Simulator<dim>::postprocess(const unsigned int cycle)
  {
    TimerOutput::Scope t(*timer, "postprocess");
    study.start_row(cycle, statistics.cells, statistics.dofs);
    std::ostringstream progress;
    progress << "cycle " << cycle << ": " << statistics.cells << " cells, "
             << statistics.dofs << " DoFs, " << statistics.solver.solver << ' '
             << statistics.solver.iterations << " it";
    if (reference)
      {
        const ErrorNorms e = compute_error_norms(
          dof_handler, *fe_space, *stress_model, solution, *reference);
        study.add("L2(u)", e.displacement_l2, ConvergenceStudy::Kind::error);
        study.add("energy", e.energy, ConvergenceStudy::Kind::error);
        study.add("L2(stress)", e.stress_l2, ConvergenceStudy::Kind::error);
        study.add("rel_L2(u)",
                  e.displacement_l2 / std::max(e.displacement_l2_norm, 1e-300),
                  ConvergenceStudy::Kind::error);
        study.add("rel_energy",
                  e.energy / std::max(e.energy_norm, 1e-300),
                  ConvergenceStudy::Kind::error);
        study.add("rel_L2(stress)",
                  e.stress_l2 / std::max(e.stress_l2_norm, 1e-300),
                  ConvergenceStudy::Kind::error);
        progress << ", relative errors: L2(u) " << std::setprecision(3)
                 << e.displacement_l2 / e.displacement_l2_norm << ", energy "
                 << e.energy / e.energy_norm;
      }
    const auto samples = sample_stresses(
      dof_handler, *fe_space, *stress_model, griffith, solution, points);
    on_all_ranks(communicator, [&]() {
      if (!points.empty() &&
          Utilities::MPI::this_mpi_process(communicator) == 0)
        write_stress_samples(output_directory + "/point_values.csv", samples);
    });
    for (unsigned int k = 0; k < samples.size(); ++k)
      {
        const std::string at = "@P" + std::to_string(k + 1);
        study.add("u_x" + at,
                  samples[k].value.displacement[0],
                  ConvergenceStudy::Kind::functional);
        study.add("u_y" + at,
                  samples[k].value.displacement[1],
                  ConvergenceStudy::Kind::functional);
        study.add("s_xx" + at,
                  samples[k].value.stress[0][0],
                  ConvergenceStudy::Kind::functional);
        study.add("s_yy" + at,
                  samples[k].value.stress[1][1],
                  ConvergenceStudy::Kind::functional);
        study.add("s_xy" + at,
                  samples[k].value.stress[0][1],
                  ConvergenceStudy::Kind::functional);
        if (reference)
          study.add("err_u" + at,
                    (samples[k].value.displacement -
                     reference->displacement(samples[k].value.point))
                      .norm(),
                    ConvergenceStudy::Kind::error);
      }
    if (surface_boundary != numbers::invalid_boundary_id)
      {
        const auto profile =
          surface_profile(dof_handler, *fe_space, solution, surface_boundary);
        on_all_ranks(communicator, [&]() {
          if (Utilities::MPI::this_mpi_process(communicator) == 0)
            write_surface_profile<dim>(output_directory +
                                         "/surface_profile.csv",
                                       profile);
        });
        if (thin_plate.enabled)
          thin_plate_profile = profile;
      }
    if (faults.has_face_terms())
      write_fault_results();
    log << progress.str() << std::endl;
    if (!goals.empty())
      record_goals();
  }

  template <int dim>
  void
  Simulator<dim>::record_goals()
  {
    const std::vector<double> values =
      goals.values(dof_handler, *fe_space, *stress_model, solution);
    std::vector<double> exact;
    if (reference)
      exact = goals.reference_values(dof_handler,
                                     *fe_space,
                                     *stress_model,
                                     *reference);
    std::ostringstream line;
    line << "  goals:" << std::setprecision(6);
    for (unsigned int k = 0; k < values.size(); ++k)
      {
        const std::string &name = goals.list()[k].name;
        study.add(name, values[k], ConvergenceStudy::Kind::functional);
        line << (k > 0 ? "," : "") << ' ' << name << ' ' << values[k];
        if (reference)
          study.add("rel_err_" + name,
                    std::abs(values[k] - exact[k]) /
                      std::max(std::abs(exact[k]), 1e-300),
                    ConvergenceStudy::Kind::error);
      }
    const auto change = goals.record_cycle(statistics.dofs, values);
    if (change.compared_with > 0)
      line << "; largest change since " << change.compared_with << " DoFs "
           << std::setprecision(3) << 100 * change.change << " % ("
           << change.goal << ")";
    goals_converged = change.converged;
    log << line.str() << std::endl;
  }

  template <int dim>
  bool
  Simulator<dim>::last_cycle()
  {
    if (goals_converged)
      {
        log << "  the goals changed by less than "
            << 100 * goals.stop_tolerance()
            << " % while the DoFs at least doubled: refinement cycles done"
            << std::endl;
        return true;
      }
    if (cycle + 1 < refinement.n_cycles)
      return false;
    // A single cycle has nothing to compare with (said in the log's
    // header); more cycles that did not converge are an error.
    if (goals.stop_tolerance() > 0 && refinement.n_cycles > 1)
      {
        std::ostringstream message;
        message << "the goals (Mesh refinement/Goals) did not converge to "
                << 100 * goals.stop_tolerance() << " % within "
                << refinement.n_cycles
                << " cycles; the results of every cycle are in "
                << output_directory
                << " (convergence.csv); raise Mesh refinement/Number of "
                   "cycles";
        throw ComputationError(message.str());
      }
    return true;
  }

  template <int dim>
  void
  Simulator<dim>::write_fault_results(const int output_index)
  {
    const std::vector<FaultSample> all =
      sample_fault(faults, dof_handler, *fe_space, solution, slip_history);
    for (unsigned int k = 0; k < faults.n_faults(); ++k)
      {
        if (!faults.has_face_terms(k))
          continue;
        std::vector<FaultSample> samples;
        for (const FaultSample &sample : all)
          if (sample.fault == k)
            samples.push_back(sample);
        FaultSummary summary         = summarize_fault(samples);
        summary.nonlinear_iterations = statistics.solver.nonlinear_iterations;
        summary.linear_solves        = statistics.solver.linear_solves;
        summary.tensile_failure_distance_m =
          surface_boundary == numbers::invalid_boundary_id
            ? std::nan("")
            : tensile_failure_distance(faults.trace(k),
                                       summary.throw_m,
                                       dof_handler,
                                       *fe_space,
                                       *stress_model,
                                       griffith,
                                       solution,
                                       surface_boundary);
        // fault.csv for the model's one fault, fault_<name>.csv for each of
        // several.
        const std::string suffix =
          faults.n_faults() == 1 ? "" : "_" + faults.trace(k).name;
        on_all_ranks(communicator, [&]() {
          if (Utilities::MPI::this_mpi_process(communicator) == 0)
            {
              write_fault_csv(output_directory + "/fault" + suffix + ".csv",
                              samples);
              if (output_index >= 0)
                write_fault_csv(output_directory + "/fault" + suffix + "-" +
                                  Utilities::int_to_string(output_index, 5) +
                                  ".csv",
                                samples);
              write_fault_summary(output_directory + "/fault_summary" + suffix +
                                    ".json",
                                  summary);
            }
        });
      }
  }

  template <int dim>
  void
  Simulator<dim>::run()
  {
    try
      {
        if (time_stepping.enabled)
          ViscoelasticTimeLoop<dim>(*this).run();
        else
          run_cycles();
      }
    catch (const RunInterrupted &stop)
      {
        // Stopped at a safe point: what is written is complete; add the
        // statistics and the timing table so far, and say where it stopped.
        std::string message =
          stop.where() + " of cycle " + std::to_string(cycle) + "; ";
        const std::string checkpoint = Checkpoint::current(output_directory);
        if (time_stepping.enabled)
          message =
            stop.where() + "; " +
            (checkpoint.empty() ? "no checkpoint was written yet"
                                : "continue with --resume from " + checkpoint);
        else if (cycle == 0)
          message += "no cycle was complete";
        else if (cycle == 1)
          message +=
            "the results of cycle 0 are complete in " + output_directory;
        else
          message += "the results of cycles 0 to " + std::to_string(cycle - 1) +
                     " are complete in " + output_directory;
        log << '\n' << RunInterrupted(stop.signal(), message).what() << '\n';
        write_statistics();
        timer->print_summary();
        log << '\n' << timer_text.str();
        timer.reset();
        throw RunInterrupted(stop.signal(), message);
      }
    catch (...)
      {
        timer.reset();
        throw;
      }
  }

  template <int dim>
  void
  Simulator<dim>::start_output()
  {
    log.open(output_directory + "/log.txt");
    on_all_ranks(communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          OutputFile out(output_directory + "/parameters.prm");
          prm.print_parameters(out, ParameterHandler::ShortPRM);
          out.commit();
        }
    });
  }

  template <int dim>
  void
  Simulator<dim>::stop_if_requested(const std::string &phase) const
  {
    interruption::stop_if_requested(communicator, phase);
  }

  template <int dim>
  void
  Simulator<dim>::write_run_header(const bool refine_initially)
  {
    log << "lithostress: " << Utilities::MPI::n_mpi_processes(communicator)
        << " MPI rank(s), output in " << output_directory << "/" << std::endl;
    log << huge_pages_description() << '\n';
    log << memory_budget.description() << '\n';
    log << "Loads:" << (loads.loads().empty() ? " none" : "") << '\n';
    for (const auto &load : loads.loads())
      log << "  " << load->description() << '\n';
    if (loads.densities_stripped())
      log << "Note: densities are stripped; every stress reported is "
             "relative to the reference column.\n";
    if (griffith.adds_lithostatic_pressure())
      log << "Griffith test: the lithostatic stress -rho g depth of each "
             "material is added to the principal stresses before the test "
             "(the model has no full body force), as in the thesis' FAIL.\n";
    if (stress_model->has_viscous_material() && !time_stepping.enabled)
      log << "Note: the viscosities are not used (Time stepping/Enabled = "
             "false): this is the elastic response at t = 0.\n";
    if (goals.stop_tolerance() > 0 && refinement.n_cycles == 1)
      log << "Note: a single refinement cycle: Mesh refinement/Goals/Stop "
             "at relative change has no cycle to compare with.\n";

    TimerOutput::Scope t(*timer, "refine");
    Timer              clock(communicator, true);
    if (refine_initially && refinement.initial_global_refinement > 0)
      triangulation.refine_global(refinement.initial_global_refinement);
    statistics.mesh_time = clock.wall_time();
  }

  template <int dim>
  void
  Simulator<dim>::refine_mesh(const std::string           &mesh,
                              const std::function<void()> &before_change)
  {
    stop_if_requested("mesh refinement");
    TimerOutput::Scope t(*timer, "refine");
    Timer              clock(communicator, true);
    const double dofs_per_cell = static_cast<double>(dof_handler.n_dofs()) /
                                 triangulation.n_global_active_cells();
    // Goal-oriented refinement: the goals' dual solutions on the present
    // operator, weighted by 1/|J_i| (relative accuracy of every goal).
    std::vector<TrilinosWrappers::MPI::Vector> duals;
    std::vector<double>                        weights;
    if (refinement.strategy == MeshRefinement<dim>::Strategy::adaptive &&
        refinement.indicator == MeshRefinement<dim>::Indicator::goal_oriented)
      {
        weights = StressGoals<dim>::weights(
          goals.values(dof_handler, *fe_space, *stress_model, solution));
        SolverReport report;
        duals = solve_dual_problems(
          goals, discrete_problem(), *linear_solver, faults, report);
        log << "  goal-oriented refinement: " << duals.size()
            << " dual solutions, " << report.solver << ' ' << report.iterations
            << " it" << std::endl;
      }
    refinement.refine(
      triangulation,
      dof_handler,
      *fe_space,
      *stress_model,
      solution,
      [&](const double cells, const unsigned int levels) {
        const double level_bytes =
          linear_solver->memory_of_levels(triangulation.n_global_coarse_cells(),
                                          levels);
        memory_budget.check(mesh,
                            cells,
                            dofs_per_cell * cells,
                            linear_solver->name(),
                            linear_solver->memory_per_dof(),
                            level_bytes,
                            "Mesh refinement/Number of cycles, Refine fraction "
                            "or Maximum level" +
                              std::string(level_bytes > 0
                                            ? " (or take Solver/Multigrid "
                                              "hierarchy = local smoothing)"
                                            : ""));
        if (before_change)
          before_change();
      },
      duals,
      weights);
    statistics.mesh_time = clock.wall_time();
  }

  template <int dim>
  void
  Simulator<dim>::compute_cycle()
  {
    stop_if_requested("set-up");
    // An elastic cycle solves the load from the undeformed state: the
    // fault's slip starts from zero on every mesh.
    slip_history = FaultSlipHistory();
    setup_dofs();
    if (cycle == 0)
      goals.check_regions(dof_handler, *fe_space);
    stop_if_requested("assembly");
    assemble_system();
    // The first assembly has evaluated every load on the first mesh:
    // the model is accepted, and only now is anything written.
    if (cycle == 0)
      start_output();
    stop_if_requested("solve");
    solve();
    stop_if_requested("postprocessing");
    postprocess(cycle);
    // The table so far, after every cycle: a run stopped by an error
    // in a later cycle keeps the cycles it finished.
    on_all_ranks(communicator, [&]() {
      if (!study.empty() && Utilities::MPI::this_mpi_process(communicator) == 0)
        {
          OutputFile csv(output_directory + "/convergence.csv");
          study.write_csv(csv);
          csv.commit();
        }
    });
  }

  template <int dim>
  void
  Simulator<dim>::run_cycles()
  {
    write_run_header();
    for (cycle = 0;; ++cycle)
      {
        if (cycle > 0)
          refine_mesh("the mesh of cycle " + std::to_string(cycle));
        compute_cycle();
        const bool last = goals_converged || cycle + 1 == refinement.n_cycles;
        {
          TimerOutput::Scope t(*timer, "output");
          if (!solution_output.last_only || last)
            solution_output.write(output_directory,
                                  cycle,
                                  cycle,
                                  dof_handler,
                                  *fe_space,
                                  *stress_model,
                                  griffith,
                                  solution);
        }
        if (last_cycle())
          break;
      }
    write_final_results();
  }

  template <int dim>
  void
  Simulator<dim>::write_final_results()
  {
    if (!study.empty())
      {
        std::ostringstream table;
        study.print(table);
        log << "\nConvergence table (rates in DoFs; for errors "
               "rate = -dlog(e)/dlog(N)):\n"
            << table.str();
      }
    if (with_force_balance)
      {
        TimerOutput::Scope      t(*timer, "force balance");
        const ForceBalance<dim> balance =
          compute_force_balance(dof_handler,
                                *fe_space,
                                *stress_model,
                                loads,
                                prescribed_displacement,
                                solution);
        log << '\n' << balance.table();
        on_all_ranks(communicator, [&]() {
          if (Utilities::MPI::this_mpi_process(communicator) == 0)
            balance.write_csv(output_directory + "/force_balance.csv");
        });
      }
    {
      TimerOutput::Scope t(*timer, "profiles and figures");
      profiles.write(output_directory,
                     dof_handler,
                     *fe_space,
                     *stress_model,
                     griffith,
                     solution);
      figures.write_data(
        output_directory,
        std::filesystem::path(output_directory).filename().string(),
        dof_handler,
        *fe_space,
        *stress_model,
        griffith,
        solution);
    }
    if (thin_plate.enabled)
      on_all_ranks(communicator, [&]() {
        thin_plate.report(thin_plate_profile,
                          log,
                          Utilities::MPI::this_mpi_process(communicator) == 0
                            ? output_directory + "/thin_plate_comparison.csv"
                            : std::string());
      });
    if (figures.enabled)
      {
        TimerOutput::Scope t(*timer, "profiles and figures");
        figures.plot(output_directory, log);
      }
    if (!statistics.solver.phases.empty())
      {
        log << "\nSolver (" << statistics.solver.solver
            << ", last cycle), wall time by phase:\n";
        std::ostringstream table;
        for (const auto &[phase, seconds] : statistics.solver.phases)
          table << "  " << std::left << std::setw(40) << phase << std::right
                << std::fixed << std::setprecision(3) << std::setw(9) << seconds
                << " s\n";
        log << table.str();
      }
    write_statistics();
    timer->print_summary();
    log << '\n' << timer_text.str();
  }

  template <int dim>
  void
  Simulator<dim>::write_statistics() const
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    const double peak_mb =
      Utilities::MPI::sum(usage.ru_maxrss / 1024.0, communicator);
    const double total = wall_clock.wall_time() - statistics.benchmark_time;
    on_all_ranks(communicator, [&]() {
      if (Utilities::MPI::this_mpi_process(communicator) != 0)
        return;
      OutputFile out(output_directory + "/statistics.json");
      out << "{\"solver\": \"" << statistics.solver.solver
          << "\", \"dofs\": " << statistics.dofs
          << ", \"cells\": " << statistics.cells
          << ", \"ranks\": " << Utilities::MPI::n_mpi_processes(communicator)
          << ", \"huge_pages\": "
          << (huge_pages_for_large_arrays() ? "true" : "false")
          << ", \"iterations\": " << statistics.solver.iterations
          << ", \"nonlinear_iterations\": "
          << statistics.solver.nonlinear_iterations
          << ", \"linear_solves\": " << statistics.solver.linear_solves
          << ", \"setup_s\": " << statistics.mesh_time + statistics.setup_time
          << ", \"assemble_s\": " << statistics.assemble_time
          << ", \"solve_s\": " << statistics.solve_time
          << ", \"preconditioner_setup_s\": " << statistics.solver.setup_time
          << ", \"matvec_ms\": "
          << 1e3 * statistics.solver.matrix_vector_product_time
          << ", \"level_matvec_ms\": "
          << 1e3 * statistics.solver.level_matrix_vector_product_time
          << ", \"total_s\": " << total << ", \"peak_rss_mb\": " << peak_mb
          << ", \"solver_memory_mb\": "
          << statistics.solver.memory_bytes / 1048576. << ", \"phases\": {";
      out << "\"set-up: mesh refinement\": " << statistics.mesh_time;
      const char *separator = ", ";
      for (const auto &[phase, seconds] : statistics.setup_phases)
        {
          out << separator << "\"set-up: " << phase << "\": " << seconds;
          separator = ", ";
        }
      for (const auto &[phase, seconds] : statistics.solver.phases)
        {
          out << separator << '"' << phase << "\": " << seconds;
          separator = ", ";
        }
      out << "}}\n";
      out.commit();
    });
  }

  template class Simulator<2>;
} // namespace lithostress

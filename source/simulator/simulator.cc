#include <deal.II/base/utilities.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/manifold.h>

#include <lithostress/base/huge_pages.h>
#include <lithostress/base/input_error.h>
#include <lithostress/base/output_file.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/boundary_conditions/rigid_body_support.h>
#include <lithostress/geometry/coarse_mesh_writer.h>
#include <lithostress/geometry/mesh_check.h>
#include <lithostress/simulator/simulator.h>
#include <lithostress/simulator/viscoelastic_time_loop.h>
#include <lithostress/time_integration/checkpoint.h>

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
    TemperatureSelector<dim>::declare_parameters(prm);
    MaterialLibrary::declare_parameters(prm, first_pass);
    PrescribedDisplacement<dim>::declare_parameters(prm, first_pass);
    FaultInterface<dim>::declare_parameters(prm, first_pass);
    FrictionalSlidingSolver<dim>::declare_parameters(prm);
    LoadCollection<dim>::declare_parameters(prm, first_pass);
    RefinementCycles<dim>::declare_parameters(prm);
    LinearSolverSelector<dim>::declare_parameters(prm);
    MemoryBudget::declare_parameters(prm);
    GriffithFailure::declare_parameters(prm);
    GravityField::declare_parameters(prm);
    TimeStepping::declare_parameters(prm);
    prm.enter_subsection("Convergence study");
    ReferenceSolutionSelector<dim>::declare_parameters(prm);
    prm.leave_subsection();
    PostprocessorList<dim>::declare_parameters(prm);
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
      , wall_clock(communicator, true)
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
    prm.enter_subsection("Geometry");
    length_unit = prm.get("Length unit");
    prm.leave_subsection();
    model.gravity = GravityField::parse_parameters(prm, length_scale);
    read_geometry();
    read_physics();
    read_numerics();
    check_well_posed();
    lithostress::check_output_directory(output_directory, communicator);
  }

  template <int dim>
  void
  Simulator<dim>::read_geometry()
  {
    prm.enter_subsection("Discretization");
    const unsigned int degree         = prm.get_integer("Polynomial degree");
    const unsigned int mapping_degree = prm.get_integer("Mapping degree");
    const bool         use_manifolds  = prm.get_bool("Use manifolds");
    prm.leave_subsection();
    geometry = GeometrySelector<dim>::create(prm);
    geometry->create_coarse_mesh(triangulation);
    // Every cell as the computation will see it (curved by the manifolds
    // and the mapping), before anything is written.
    check_coarse_cells(triangulation,
                       MappingQ<dim>(use_manifolds ? mapping_degree : 1),
                       *geometry,
                       length_scale,
                       length_unit);
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
    faults.parse_parameters(prm,
                            geometry->fault_traces(),
                            model.gravity,
                            length_scale);
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
    if (curved)
      fe_space->cache_mapping_of(triangulation);
  }

  template <int dim>
  void
  Simulator<dim>::read_physics()
  {
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
    reference = ReferenceSolutionSelector<dim>::create(
      prm, materials, plane_state, length_scale, model.gravity);
    prm.leave_subsection();

    for (const auto &part : geometry->boundary_parts())
      if (boundary_ids.count(part.second) != 0)
        model.boundary_parts.insert(part);
    model.length_scale = length_scale;
    model.reference    = reference.get();
    temperature        = TemperatureSelector<dim>::create(prm, length_scale);
    model.temperature  = temperature.get();
    loads.parse_parameters(prm, model);
    for (const auto &load : loads.loads())
      load->check_against_mesh(triangulation, fe_space->mapping());
    std::vector<const InitialStressSource<dim> *> initial_stresses;
    for (const auto &load : loads.loads())
      initial_stresses.push_back(load.get());
    stress_model = std::make_unique<StressModel<dim>>(prm,
                                                      materials,
                                                      plane_state,
                                                      initial_stresses);
    if (temperature)
      {
        temperature->check_against_mesh(triangulation);
        TemperatureMesh<dim> temperature_mesh;
        temperature_mesh.triangulation = &triangulation;
        temperature_mesh.mapping       = &fe_space->mapping();
        for (const Material &material : materials.materials())
          temperature_mesh.materials[material.name] = material.id;
        temperature_mesh.boundary_parts = model.boundary_parts;
        temperature->attach_mesh(temperature_mesh);
      }
    stress_model->attach_temperature(temperature.get());
    prescribed_displacement.parse_parameters(prm, model);
    griffith.parse_parameters(prm, model.gravity);
    griffith.resolve_lithostatic_pressure(loads.without_body_force() ||
                                          loads.densities_stripped());
  }

  template <int dim>
  void
  Simulator<dim>::read_numerics()
  {
    cycles.parse_parameters(prm, length_scale);
    time_stepping.parse_parameters(prm);
    if (time_stepping.enabled && time_stepping.resume)
      Checkpoint::check_resumable(output_directory, prm, communicator);
    if (time_stepping.enabled)
      creep = std::make_unique<CreepIntegrator<dim>>(
        triangulation,
        fe_space->degree() + 1,
        stress_model->history_layout(),
        stress_model->has_nonlinear_material());
    auto linear_solver = LinearSolverSelector<dim>::create(
      prm,
      *fe_space,
      loads,
      prescribed_displacement.has_rigid_components()
        ? "a `rigid` boundary component ties DoFs along a whole edge"
        : "",
      stress_model->may_be_unsymmetric());
    memory_budget.parse_parameters(prm, communicator);
    cycles.set_memory_budget(memory_budget);
    problem = std::make_unique<ElasticProblem<dim>>(
      typename ElasticProblem<dim>::Model{communicator,
                                          triangulation,
                                          *fe_space,
                                          *stress_model,
                                          loads,
                                          prescribed_displacement,
                                          faults},
      std::move(linear_solver),
      sliding_solver,
      log,
      *timer);
    access = std::make_unique<SimulatorAccess<dim>>(
      SimulatorAccess<dim>{communicator,
                           output_directory,
                           log,
                           *timer,
                           length_scale,
                           length_unit,
                           model,
                           triangulation,
                           problem->dof_handler(),
                           *fe_space,
                           materials,
                           *stress_model,
                           loads,
                           prescribed_displacement,
                           faults,
                           problem->fault_history(),
                           griffith,
                           reference.get(),
                           problem->solution(),
                           problem->statistics(),
                           cycles.convergence_study(),
                           wall_clock});
    postprocessors.parse_parameters(prm, *access);
  }

  template <int dim>
  void
  Simulator<dim>::check_well_posed()
  {
    // Rigid-body motions on the coarse mesh, where the test is exact.
    DoFHandler<dim> dof_handler(triangulation);
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
                                 materials.largest_youngs_modulus(),
                                 faults.blocks(),
                                 faults.interface_points(dof_handler,
                                                         *fe_space),
                                 length_scale,
                                 length_unit);

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
        problem->linear_solver().name(),
        problem->linear_solver().memory_per_dof(interior_dofs * cells +
                                                boundary_dofs * growth),
        problem->linear_solver().memory_of_levels(
          coarse_cells, triangulation.n_global_levels() + refinements),
        "Mesh refinement/Initial global refinement" +
          std::string(cycles.settings().strategy ==
                          MeshRefinement<dim>::Strategy::global
                        ? " or Number of cycles"
                        : ""));
    };
    const unsigned int first = cycles.settings().initial_global_refinement;
    check_mesh("the first mesh (cycle 0)", first);
    if (cycles.settings().strategy == MeshRefinement<dim>::Strategy::global &&
        cycles.settings().n_cycles > 1)
      check_mesh("the mesh of the last cycle (" +
                   std::to_string(cycles.settings().n_cycles - 1) + ")",
                 std::min(first + cycles.settings().n_cycles - 1,
                          std::max(first, cycles.settings().max_level)));
  }

  template <int dim>
  void
  Simulator<dim>::run()
  {
    try
      {
        write_run_header(!(time_stepping.enabled && time_stepping.resume));
        if (time_stepping.enabled)
          ViscoelasticTimeLoop<dim>(time_stepping,
                                    {*problem,
                                     cycles,
                                     postprocessors,
                                     *access,
                                     *creep,
                                     *stress_model,
                                     prm,
                                     [&]() { start_output(); }})
            .run();
        else
          cycles.run(
            *problem, postprocessors, *access, [&]() { start_output(); }, true);
        postprocessors.finish(*access);
        timer->print_summary();
        log << '\n' << timer_text.str();
      }
    catch (const RunInterrupted &stop)
      {
        // Stopped at a safe point: what is written is complete; add the
        // statistics and the timing table so far, and say where it stopped.
        const std::string message = interruption_message(stop.where());
        log << '\n' << RunInterrupted(stop.signal(), message).what() << '\n';
        postprocessors.interrupted(*access);
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
  std::string
  Simulator<dim>::interruption_message(const std::string &where) const
  {
    if (time_stepping.enabled)
      {
        const std::string checkpoint = Checkpoint::current(output_directory);
        return where + "; " +
               (checkpoint.empty()
                  ? "no checkpoint was written yet"
                  : "continue with --resume from " + checkpoint);
      }
    const unsigned int cycle = cycles.cycle();
    std::string message = where + " of cycle " + std::to_string(cycle) + "; ";
    if (cycle == 0)
      return message + "no cycle was complete";
    if (cycle == 1)
      return message + "the results of cycle 0 are complete in " +
             output_directory;
    return message + "the results of cycles 0 to " + std::to_string(cycle - 1) +
           " are complete in " + output_directory;
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
    using Refinement = MeshRefinement<dim>;
    if (faults.active() &&
        cycles.settings().strategy == Refinement::Strategy::adaptive &&
        cycles.settings().indicator == Refinement::Indicator::kelly)
      log << "Note: the Kelly indicator takes the two sides of a fault (two "
             "displacement fields) for a jump of the gradient and refines "
             "along the fault's whole trace; Mesh refinement/Indicator = "
             "stress recovery recovers each side's stress on its own "
             "(doc/faults.md).\n";
    if (cycles.goals().stop_tolerance() > 0 && cycles.settings().n_cycles == 1)
      log << "Note: a single refinement cycle: Mesh refinement/Goals/Stop "
             "at relative change has no cycle to compare with.\n";

    TimerOutput::Scope t(*timer, "refine");
    Timer              clock(communicator, true);
    if (refine_initially)
      cycles.refine_initially(triangulation);
    problem->statistics().mesh_time = clock.wall_time();
  }

  template class Simulator<2>;
} // namespace lithostress

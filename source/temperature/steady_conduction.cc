#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/numerics/vector_tools.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/temperature/steady_conduction.h>

#include <limits>

namespace lithostress
{
  template <int dim>
  SteadyConductionTemperature<dim>::~SteadyConductionTemperature()
  {
    for (auto &connection : connections)
      connection.disconnect();
  }

  template <int dim>
  void
  SteadyConductionTemperature<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Steady conduction");
    prm.declare_entry("Thermal conductivity",
                      "2.5",
                      Patterns::Anything(),
                      "k [W/(m K)] of every material: one number for all, "
                      "or `name: value, ...` with every material of "
                      "Materials/Names; above 0.");
    prm.declare_entry("Radiogenic heat production",
                      "0",
                      Patterns::Anything(),
                      "H [W/m^3] of every material (continental upper "
                      "crust about 1e-6): one number for all, or `name: "
                      "value, ...` with every material; at least 0.");
    prm.declare_entry("Top temperature",
                      "273",
                      Patterns::Double(0),
                      "T on the Top boundary [K], above 0.");
    prm.declare_entry("Base temperature",
                      "1623",
                      Patterns::Double(0),
                      "T on the Base boundary [K], above 0.");
    prm.declare_entry("Top boundary",
                      "top",
                      Patterns::Anything(),
                      "The boundary parts held at the Top temperature, "
                      "comma separated (the subduction zone's top is "
                      "`ocean_floor, land`).");
    prm.declare_entry("Base boundary",
                      "base",
                      Patterns::Anything(),
                      "The boundary parts held at the Base temperature, "
                      "comma separated; the other boundaries are "
                      "insulating.");
    prm.leave_subsection();
  }

  template <int dim>
  void
  SteadyConductionTemperature<dim>::parse_parameters(ParameterHandler &prm,
                                                     const double)
  {
    prm.enter_subsection("Steady conduction");
    conductivity_text    = prm.get("Thermal conductivity");
    heat_production_text = prm.get("Radiogenic heat production");
    top_temperature      = prm.get_double("Top temperature");
    base_temperature     = prm.get_double("Base temperature");
    top_names            = split_list(prm.get("Top boundary"));
    base_names           = split_list(prm.get("Base boundary"));
    prm.leave_subsection();
    const std::string entry = "Temperature/Steady conduction/";
    if (!(top_temperature > 0))
      throw_input_error(entry + "Top temperature",
                        "must be above 0 K (an absolute temperature)");
    if (!(base_temperature > 0))
      throw_input_error(entry + "Base temperature",
                        "must be above 0 K (an absolute temperature)");
  }

  template <int dim>
  std::map<types::material_id, double>
  SteadyConductionTemperature<dim>::per_material(
    const std::string          &text,
    const std::string          &entry,
    const TemperatureMesh<dim> &mesh)
  {
    std::map<types::material_id, double> values;
    if (text.find(':') == std::string::npos)
      {
        const double value = parse_number(text, entry);
        for (const auto &material : mesh.materials)
          values[material.second] = value;
        return values;
      }
    for (const std::string &item : split_list(text))
      {
        const auto colon = item.find(':');
        if (colon == std::string::npos)
          throw_input_error(entry,
                            "has `" + item +
                              "` where `name: value` is "
                              "expected");
        const std::string name  = Utilities::trim(item.substr(0, colon));
        const auto        found = mesh.materials.find(name);
        if (found == mesh.materials.end())
          throw_input_error(entry,
                            "names `" + name +
                              "`, which is no material of "
                              "Materials/Names");
        values[found->second] = parse_number(item.substr(colon + 1), entry);
      }
    for (const auto &material : mesh.materials)
      if (values.count(material.second) == 0)
        throw_input_error(entry,
                          "gives no value for the material `" + material.first +
                            "`");
    return values;
  }

  template <int dim>
  void
  SteadyConductionTemperature<dim>::attach_mesh(
    const TemperatureMesh<dim> &run_mesh)
  {
    mesh                    = run_mesh;
    const std::string entry = "Temperature/Steady conduction/";
    conductivity =
      per_material(conductivity_text, entry + "Thermal conductivity", mesh);
    heat_production = per_material(heat_production_text,
                                   entry + "Radiogenic heat production",
                                   mesh);
    for (const auto &k : conductivity)
      if (!(k.second > 0))
        throw_input_error(entry + "Thermal conductivity",
                          "must be above 0 in every material");
    for (const auto &h : heat_production)
      if (h.second < 0)
        throw_input_error(entry + "Radiogenic heat production",
                          "must be at least 0 in every material");
    const auto boundary = [&](const std::string &name,
                              const std::string &which) {
      const auto found = mesh.boundary_parts.find(name);
      if (found == mesh.boundary_parts.end())
        {
          std::string parts;
          for (const auto &part : mesh.boundary_parts)
            parts += (parts.empty() ? "" : ", ") + part.first;
          throw_input_error(entry + which,
                            "is `" + name +
                              "`, which is no boundary part of "
                              "the mesh (it has: " +
                              parts + ")");
        }
      return found->second;
    };
    top_ids.clear();
    base_ids.clear();
    for (const std::string &name : top_names)
      top_ids.insert(boundary(name, "Top boundary"));
    for (const std::string &name : base_names)
      {
        const types::boundary_id id = boundary(name, "Base boundary");
        if (top_ids.count(id) > 0)
          throw_input_error(entry + "Base boundary",
                            "names `" + name +
                              "`, which is a Top boundary too");
        base_ids.insert(id);
      }
    if (top_ids.empty() || base_ids.empty())
      throw_input_error(entry +
                          (top_ids.empty() ? "Top boundary" : "Base boundary"),
                        "names no boundary part");
    dof_handler = std::make_unique<DoFHandler<dim>>(*mesh.triangulation);
    solve();
    auto &signals = mesh.triangulation->signals;
    if (dynamic_cast<const parallel::distributed::Triangulation<dim> *>(
          mesh.triangulation) != nullptr)
      {
        connections.push_back(
          signals.post_distributed_refinement.connect([this]() { solve(); }));
        connections.push_back(
          signals.post_distributed_repartition.connect([this]() { solve(); }));
        connections.push_back(
          signals.post_distributed_load.connect([this]() { solve(); }));
      }
    else
      connections.push_back(
        signals.post_refinement.connect([this]() { solve(); }));
  }

  template <int dim>
  void
  SteadyConductionTemperature<dim>::solve()
  {
    const MPI_Comm comm = mesh.triangulation->get_communicator();
    dof_handler->distribute_dofs(fe);
    const IndexSet owned = dof_handler->locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(*dof_handler, relevant);
    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(*dof_handler, constraints);
    const Functions::ConstantFunction<dim> top(top_temperature),
      base(base_temperature);
    std::map<types::boundary_id, const Function<dim> *> held;
    for (const types::boundary_id id : top_ids)
      held[id] = &top;
    for (const types::boundary_id id : base_ids)
      held[id] = &base;
    VectorTools::interpolate_boundary_values(*mesh.mapping,
                                             *dof_handler,
                                             held,
                                             constraints);
    constraints.close();

    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(*dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    TrilinosWrappers::SparseMatrix matrix;
    matrix.reinit(owned, owned, dsp, comm);
    TrilinosWrappers::MPI::Vector rhs(owned, comm), solution(owned, comm);

    FEValues<dim>                        fe_values(*mesh.mapping,
                            fe,
                            QGauss<dim>(fe.degree + 1),
                            update_values | update_gradients |
                              update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    Vector<double>                       cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          const double k = conductivity.at(cell->material_id());
          const double h = heat_production.at(cell->material_id());
          cell_matrix    = 0;
          cell_rhs       = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            for (unsigned int i = 0; i < n; ++i)
              {
                for (unsigned int j = 0; j < n; ++j)
                  cell_matrix(i, j) += k * fe_values.shape_grad(i, q) *
                                       fe_values.shape_grad(j, q) *
                                       fe_values.JxW(q);
                cell_rhs(i) +=
                  h * fe_values.shape_value(i, q) * fe_values.JxW(q);
              }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, dofs, matrix, rhs);
        }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);

    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = true;
    TrilinosWrappers::PreconditionAMG amg;
    amg.initialize(matrix, data);
    SolverControl control(2000, 1e-12 * rhs.l2_norm());
    try
      {
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(matrix, solution, rhs, amg);
      }
    catch (const SolverControl::NoConvergence &)
      {
        throw_input_error("Temperature/Steady conduction/Thermal "
                          "conductivity",
                          "gives a conduction problem that CG did not solve "
                          "in 2000 iterations (conductivities too different?)");
      }
    iterations = control.last_step();
    constraints.distribute(solution);
    temperature.reinit(owned, relevant, comm);
    temperature = solution;
  }

  template <int dim>
  void
  SteadyConductionTemperature<dim>::values(
    const typename Triangulation<dim>::active_cell_iterator &cell,
    const std::vector<Point<dim>>                           &points,
    std::vector<double>                                     &temperatures) const
  {
    Assert(dof_handler != nullptr, ExcMessage("attach_mesh() first"));
    const typename DoFHandler<dim>::active_cell_iterator dof_cell(
      &dof_handler->get_triangulation(),
      cell->level(),
      cell->index(),
      dof_handler.get());
    std::vector<Point<dim>> unit(points.size());
    mesh.mapping->transform_points_real_to_unit_cell(cell, points, unit);
    Vector<double> nodal(fe.n_dofs_per_cell());
    dof_cell->get_dof_values(temperature, nodal);
    temperatures.assign(points.size(), 0.);
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        if (unit[q][0] == std::numeric_limits<double>::infinity())
          unit[q] = mesh.mapping->transform_real_to_unit_cell(cell, points[q]);
        for (unsigned int i = 0; i < nodal.size(); ++i)
          temperatures[q] += nodal[i] * fe.shape_value(i, unit[q]);
      }
  }

  template class SteadyConductionTemperature<2>;

  LITHOSTRESS_REGISTER_TEMPERATURE_MODEL(
    SteadyConductionTemperature,
    "steady conduction",
    "the steady geotherm of conduction with radiogenic heat, solved on the "
    "mesh (Temperature/Steady conduction)");
} // namespace lithostress

#include <deal.II/base/timer.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/preconditioned_cg.h>
#include <lithostress/solvers/two_field_multigrid_solver.h>

namespace lithostress
{
  template <int dim>
  TwoFieldMultigridSolver<dim>::TwoFieldMultigridSolver(
    const Settings &settings)
      : settings(settings)
  {
  }

  template <int dim>
  SolverReport
  TwoFieldMultigridSolver<dim>::solve(const DiscreteProblem<dim>    &problem,
                                      TrilinosWrappers::MPI::Vector &solution)
  {
    const DoFHandler<dim>   &dof_handler = problem.dof_handler;
    const LinearSystem<dim> &system      = problem.system;
    const MPI_Comm           comm        = dof_handler.get_communicator();
    SolverReport             report;
    report.solver = "two-field multigrid";
    Timer timer(comm, true);
    // The operator version's upper half counts the meshes
    // (ElasticProblem::operator_version).
    const unsigned long long mesh = problem.operator_version >> 32;
    if (!multigrid || mesh != mesh_version)
      {
        multigrid = std::make_unique<TwoFieldMultigrid<dim>>();
        multigrid->make_hierarchy(dof_handler,
                                  problem.fe_space.fe_collection());
        mesh_version     = mesh;
        operator_version = ~0ULL;
      }
    if (operator_version != problem.operator_version)
      {
        multigrid->initialize(system.matrix,
                              system.constraints,
                              typename TwoFieldMultigrid<dim>::Settings());
        operator_version = problem.operator_version;
      }
    report.setup_time = timer.wall_time();

    timer.restart();
    solve_by_preconditioned_cg(system,
                               *multigrid,
                               settings.relative_tolerance,
                               settings.max_iterations,
                               name(),
                               comm,
                               solution,
                               report,
                               problem.initial_guess,
                               problem.symmetric);
    report.solve_time   = timer.wall_time();
    report.memory_bytes = multigrid->memory_consumption();
    // Elastic cycles release the levels before the next mesh.
    if (!problem.keep_setup)
      {
        multigrid.reset();
        mesh_version = operator_version = ~0ULL;
      }
    return report;
  }

  template <int dim>
  void
  TwoFieldMultigridSolver<dim>::declare_parameters(ParameterHandler &)
  {
  }

  template <int dim>
  std::unique_ptr<LinearSolver<dim>>
  TwoFieldMultigridSolver<dim>::create(ParameterHandler              &prm,
                                       const FiniteElementSpace<dim> &fe_space)
  {
    (void)fe_space;
    Settings s;
    s.relative_tolerance = prm.get_double("Relative tolerance");
    s.max_iterations     = prm.get_integer("Maximum iterations");
    return std::make_unique<TwoFieldMultigridSolver<dim>>(s);
  }

  template class TwoFieldMultigridSolver<2>;
  LITHOSTRESS_REGISTER_LINEAR_SOLVER(
    TwoFieldMultigridSolver,
    "two-field multigrid",
    "CG with a geometric multigrid V-cycle on the assembled matrix, "
    "Galerkin coarse levels (faulted models whose faults are locked or slip "
    "by a prescribed amount; a stiff normal spring defeats its smoother)")
} // namespace lithostress

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_solver.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/amg_solver.h>
#include <lithostress/solvers/preconditioned_cg.h>
#include <lithostress/solvers/rigid_body_modes.h>

#include <Teuchos_ParameterList.hpp>

namespace lithostress
{
  template <int dim>
  AMGSolver<dim>::AMGSolver(const Settings &settings)
      : settings(settings)
  {
  }

  template <int dim>
  SolverReport
  AMGSolver<dim>::solve(const DiscreteProblem<dim>    &problem,
                        TrilinosWrappers::MPI::Vector &solution)
  {
    const DoFHandler<dim>   &dof_handler = problem.dof_handler;
    const LinearSystem<dim> &system      = problem.system;
    SolverReport             report;
    report.solver = "amg";
    Timer timer(dof_handler.get_communicator(), true);

    const bool reuse = problem.keep_setup && kept_amg &&
                       kept_version == problem.operator_version;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg =
      reuse ? std::move(kept_amg)
            : std::make_unique<TrilinosWrappers::PreconditionAMG>();
    kept_amg.reset();
    if (!reuse)
      {
        const Epetra_CrsMatrix &matrix = system.matrix.trilinos_matrix();
        std::unique_ptr<Epetra_MultiVector> modes =
          make_rigid_body_modes(dof_handler,
                                problem.fe_space,
                                matrix.DomainMap());
        initialize_elasticity_amg<dim>(
          *amg, system.matrix, *modes, settings, true);
      }
    const TrilinosWrappers::PreconditionAMG &preconditioner = *amg;
    report.setup_time                                       = timer.wall_time();

    timer.restart();
    solve_by_preconditioned_cg(system,
                               preconditioner,
                               settings.relative_tolerance,
                               settings.max_iterations,
                               name(),
                               dof_handler.get_communicator(),
                               solution,
                               report,
                               problem.initial_guess,
                               problem.symmetric);
    report.solve_time = timer.wall_time();
    if (problem.keep_setup)
      {
        kept_amg     = std::move(amg);
        kept_version = problem.operator_version;
      }
    if (settings.time_matrix_vector_product)
      {
        // The machine's speed in the operation that bounds CG + AMG, to
        // compare benchmark figures across machines.
        Timer benchmark(dof_handler.get_communicator(), true);
        TrilinosWrappers::MPI::Vector y(system.rhs);
        report.matrix_vector_product_time =
          fastest_of(20, dof_handler.get_communicator(), [&]() {
            system.matrix.vmult(y, system.rhs);
          });
        report.benchmark_time = benchmark.wall_time();
      }
    return report;
  }

  template <int dim>
  void
  initialize_elasticity_amg(TrilinosWrappers::PreconditionAMG       &amg,
                            const TrilinosWrappers::SparseMatrix    &matrix,
                            const Epetra_MultiVector                &modes,
                            const typename AMGSolver<dim>::Settings &settings,
                            const bool higher_order_elements)
  {
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = higher_order_elements;
    data.smoother_sweeps       = settings.smoother_sweeps;
    data.aggregation_threshold = settings.aggregation_threshold;
    data.smoother_type         = settings.smoother.c_str();
    data.coarse_type           = "Amesos-KLU";
    Teuchos::ParameterList              parameters;
    std::unique_ptr<Epetra_MultiVector> unused_modes;
    data.set_parameters(parameters, unused_modes, matrix);
    parameters.set("null space: type", "pre-computed");
    parameters.set("null space: dimension", modes.NumVectors());
    parameters.set("null space: vectors", modes.Values());
    parameters.set("PDE equations", dim);
    amg.initialize(matrix, parameters);
  }

  template <int dim>
  void
  AMGSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("AMG smoother",
                      "Chebyshev",
                      Patterns::Selection("Chebyshev|symmetric Gauss-Seidel"),
                      "Smoother of the AMG V-cycle.");
    prm.declare_entry("AMG smoother sweeps",
                      "2",
                      Patterns::Integer(1),
                      "Smoother sweeps (Chebyshev degree) in the V-cycle.");
    prm.declare_entry("AMG aggregation threshold",
                      "1e-4",
                      Patterns::Double(0, 1),
                      "ML aggregation threshold (strength of connection).");
  }

  template <int dim>
  std::unique_ptr<LinearSolver<dim>>
  AMGSolver<dim>::create(ParameterHandler              &prm,
                         const FiniteElementSpace<dim> &fe_space)
  {
    (void)fe_space;
    Settings s;
    s.relative_tolerance         = prm.get_double("Relative tolerance");
    s.max_iterations             = prm.get_integer("Maximum iterations");
    s.smoother_sweeps            = prm.get_integer("AMG smoother sweeps");
    s.aggregation_threshold      = prm.get_double("AMG aggregation threshold");
    s.smoother                   = prm.get("AMG smoother");
    s.time_matrix_vector_product = prm.get_bool("Time matrix-vector product");
    return std::make_unique<AMGSolver<dim>>(s);
  }

  template class AMGSolver<2>;
  LITHOSTRESS_REGISTER_LINEAR_SOLVER(
    AMGSolver,
    "AMG",
    "CG with algebraic multigrid on the assembled matrix (all rigid-body "
    "modes as near-null space)")
  template void
  initialize_elasticity_amg<2>(TrilinosWrappers::PreconditionAMG &,
                               const TrilinosWrappers::SparseMatrix &,
                               const Epetra_MultiVector &,
                               const AMGSolver<2>::Settings &,
                               const bool);
} // namespace lithostress

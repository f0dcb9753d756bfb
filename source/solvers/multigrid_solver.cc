#include <cmath>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/vector_memory.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_transfer_matrix_free.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/active_operator.h>
#include <lithostress/solvers/coarse_grid_solver.h>
#include <lithostress/solvers/multigrid_preconditioner.h>
#include <lithostress/solvers/preconditioned_cg.h>

#include <map>
#include <optional>

namespace lithostress
{
  namespace
  {
    /** Copy the owned entries between a Trilinos vector and a matrix-free
     * vector with the same owned DoFs (@p owned, in order). */
    void
    copy_owned_entries(const IndexSet                             &owned,
                       const TrilinosWrappers::MPI::Vector        &from,
                       LinearAlgebra::distributed::Vector<double> &to)
    {
      AssertThrow(owned.n_elements() == to.locally_owned_size(),
                  ExcInternalError());
      unsigned int k = 0;
      for (const types::global_dof_index i : owned)
        to.local_element(k++) = from[i];
    }

    void
    copy_owned_entries(const IndexSet                                   &owned,
                       const LinearAlgebra::distributed::Vector<double> &from,
                       TrilinosWrappers::MPI::Vector                    &to)
    {
      unsigned int k = 0;
      for (const types::global_dof_index i : owned)
        to[i] = from.local_element(k++);
      to.compress(VectorOperation::insert);
    }

    /** The V-cycle of local smoothing on the levels of the p4est forest
     * (step-37/step-50): MGTransferMatrixFree with MGConstrainedDoFs for
     * refinement edges and prescribed displacements, edge matrices at
     * refinement edges, the level-0 matrix solved by CoarseGridSolver. */
    template <int dim, int degree, typename number>
    class LocalSmoothingPreconditioner
        : public MultigridCycle<dim,
                                degree,
                                number,
                                MGTransferMatrixFree<dim, number>>
    {
    public:
      using Cycle =
        MultigridCycle<dim, degree, number, MGTransferMatrixFree<dim, number>>;
      using LevelVectorType = typename Cycle::LevelVectorType;
      using LevelOperator   = typename Cycle::LevelOperator;
      using Settings        = typename Cycle::Settings;

      LocalSmoothingPreconditioner(const DiscreteProblem<dim> &problem,
                                   const Settings             &settings,
                                   SolverReport               &report);

      ~LocalSmoothingPreconditioner() override
      {
        this->release_cycle();
      }

    private:
      MGConstrainedDoFs                 constrained_dofs;
      MGTransferMatrixFree<dim, number> transfer;
      MGLevelObject<MatrixFreeOperators::MGInterfaceOperator<LevelOperator>>
                                  interface_operators;
      mg::Matrix<LevelVectorType> mg_interface;
    };

    template <int dim, int degree, typename number>
    LocalSmoothingPreconditioner<dim, degree, number>::
      LocalSmoothingPreconditioner(const DiscreteProblem<dim> &problem,
                                   const Settings             &settings,
                                   SolverReport               &report)
        : Cycle(problem.dof_handler)
    {
      const DoFHandler<dim>    &dof_handler     = this->dof_handler;
      auto                     &level_operators = this->level_operators;
      const Triangulation<dim> &tria = dof_handler.get_triangulation();
      const std::map<types::boundary_id, double> springs =
        problem.loads.vertical_springs(tria.get_boundary_ids());
      const auto material_moduli = multigrid_tools::material_moduli(problem);

      Timer              timer(dof_handler.get_communicator(), true);
      const unsigned int n_levels = tria.n_global_levels();
      constrained_dofs.initialize(dof_handler);
      for (const auto &[id, mask] :
           problem.prescribed_displacement.constrained_components(
             problem.fe_space))
        constrained_dofs.make_zero_boundary_constraints(dof_handler,
                                                        {id},
                                                        mask);

      // A law whose tangent varies in space: every level takes its cells'
      // averaged tangents (multigrid_tools::level_tangents()).
      using LevelTangents =
        decltype(multigrid_tools::level_tangents(problem, 1u));
      std::optional<LevelTangents> level_tangent;
      if (!problem.stress_model.uniform_tangents())
        on_all_ranks(dof_handler.get_communicator(), [&]() {
          level_tangent.emplace(
            multigrid_tools::level_tangents(problem, degree + 1));
        });

      level_operators.resize(0, n_levels - 1);
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          AffineConstraints<double> level_constraints;
          level_constraints.reinit(
            DoFTools::extract_locally_relevant_level_dofs(dof_handler, level));
          level_constraints.add_lines(
            constrained_dofs.get_boundary_indices(level));
          level_constraints.close();

          typename MatrixFree<dim, number>::AdditionalData data;
          multigrid_tools::set_operator_flags(data, springs);
          data.mg_level    = level;
          auto matrix_free = std::make_shared<MatrixFree<dim, number>>();
          matrix_free->reinit(problem.fe_space.mapping(),
                              dof_handler,
                              level_constraints,
                              QGauss<1>(degree + 1),
                              data);
          level_operators[level].initialize(matrix_free,
                                            constrained_dofs,
                                            level);
          level_operators[level].set_cell_moduli(material_moduli);
          if (level_tangent)
            on_all_ranks(dof_handler.get_communicator(), [&]() {
              level_operators[level].set_point_tangents(*level_tangent);
            });
          level_operators[level].set_vertical_springs(springs);
        }
      report.phases.emplace_back("matrix-free set-up (levels)",
                                 timer.wall_time());
      timer.restart();
      for (unsigned int level = 0; level < n_levels; ++level)
        level_operators[level].compute_diagonal();
      report.phases.emplace_back("level diagonals", timer.wall_time());

      timer.restart();
      // The level vectors get the operators' own partitioners, so that the
      // operators never re-create a vector the V-cycle hands them (which
      // costs a copy and raises the peak memory at the first cycle).
      std::vector<std::shared_ptr<const Utilities::MPI::Partitioner>>
        partitioners(n_levels);
      for (unsigned int level = 0; level < n_levels; ++level)
        partitioners[level] =
          level_operators[level].get_matrix_free()->get_vector_partitioner();
      transfer.initialize_constraints(constrained_dofs);
      transfer.build(dof_handler, partitioners);
      report.phases.emplace_back("transfer set-up", timer.wall_time());

      this->set_up_cycle(transfer,
                         settings,
                         report,
                         [&](CoarseGridSolver<dim, number> &coarse) {
                           coarse.initialize(dof_handler,
                                             problem.fe_space,
                                             constrained_dofs,
                                             material_moduli,
                                             springs,
                                             settings.coarse_solver_amg);
                         });
      interface_operators.resize(0, n_levels - 1);
      for (unsigned int level = 0; level < n_levels; ++level)
        interface_operators[level].initialize(level_operators[level]);
      mg_interface.initialize(interface_operators);
      this->multigrid->set_edge_matrices(mg_interface, mg_interface);
    }

    /** The outer CG on the active mesh with either hierarchy. */
    template <int dim, int degree, typename number>
    class MultigridImplementation
        : public MatrixFreeMultigridSolver<dim>::Implementation
    {
    public:
      using Settings       = typename MatrixFreeMultigridSolver<dim>::Settings;
      using SystemOperator = ActiveOperator<dim>;
      using VectorType     = LinearAlgebra::distributed::Vector<double>;

      SolverReport
      solve(const DiscreteProblem<dim>    &problem,
            TrilinosWrappers::MPI::Vector &solution,
            const Settings                &settings) override;

    private:
      /** The set-up kept for the next solve (DiscreteProblem::keep_setup)
       * and the operator version it was made for. */
      std::unique_ptr<SystemOperator> kept_operator;
      std::unique_ptr<MultigridPreconditioner<dim, degree, number>>
                         kept_preconditioner;
      unsigned long long kept_version = 0;
    };

    /** The time of one product with the active operator (the fastest of
     * 20, into @p dst) and with the finest level's, for statistics.json. */
    template <typename Operator, typename Preconditioner, typename Vector>
    void
    time_products(SolverReport   &report,
                  const Operator &op,
                  Preconditioner &preconditioner,
                  Vector         &dst,
                  const Vector   &src)
    {
      const MPI_Comm communicator = src.get_mpi_communicator();
      Timer          benchmark(communicator, true);
      report.matrix_vector_product_time =
        fastest_of(20, communicator, [&]() { op.vmult(dst, src); });
      report.level_matrix_vector_product_time =
        preconditioner.time_finest_level_product();
      report.benchmark_time = benchmark.wall_time();
    }

    template <int dim, int degree, typename number>
    SolverReport
    MultigridImplementation<dim, degree, number>::solve(
      const DiscreteProblem<dim>    &problem,
      TrilinosWrappers::MPI::Vector &solution,
      const Settings                &settings)
    {
      const DoFHandler<dim> &dof_handler  = problem.dof_handler;
      const MPI_Comm         communicator = dof_handler.get_communicator();
      const std::map<types::boundary_id, double> springs =
        problem.loads.vertical_springs(
          dof_handler.get_triangulation().get_boundary_ids());

      SolverReport report;
      report.solver = "mf-gmg";
      Timer timer(communicator, true), total(communicator, true);

      std::unique_ptr<SystemOperator> system_operator;
      std::unique_ptr<MultigridPreconditioner<dim, degree, number>>
                 preconditioner;
      const bool reuse = problem.keep_setup && kept_operator &&
                         kept_version == problem.operator_version;
      if (reuse)
        {
          system_operator = std::move(kept_operator);
          preconditioner  = std::move(kept_preconditioner);
        }
      kept_operator.reset();
      kept_preconditioner.reset();
      // The operator on the active mesh (double precision).
      if (!reuse)
        {
          system_operator =
            make_active_operator<dim, degree>(problem.fe_space.mapping(),
                                              dof_handler,
                                              problem.system.constraints,
                                              multigrid_tools::material_moduli(
                                                problem),
                                              springs,
                                              vectorized_operator_built());
          // A law whose tangent varies in space: the active operator takes
          // it at each quadrature point (the levels their cells' averages).
          if (!problem.stress_model.uniform_tangents())
            on_all_ranks(communicator, [&]() {
              system_operator->set_point_tangents(
                multigrid_tools::point_tangents(problem, degree + 1));
            });
        }
      report.phases.emplace_back("matrix-free set-up (active mesh)",
                                 timer.wall_time());

      // The right-hand side in the matrix-free vector layout (same owned
      // DoFs); the Trilinos copy is released before the hierarchy is built.
      VectorType rhs, x;
      system_operator->initialize_dof_vector(rhs);
      system_operator->initialize_dof_vector(x);
      copy_owned_entries(problem.system.locally_owned, problem.system.rhs, rhs);
      problem.system.rhs.clear();
      if (problem.initial_guess != nullptr)
        {
          copy_owned_entries(problem.system.locally_owned,
                             *problem.initial_guess,
                             x);
          problem.system.constraints.set_zero(x);
        }

      if (!reuse)
        preconditioner =
          settings.global_coarsening
            ? make_global_coarsening_preconditioner<dim, degree, number>(
                problem, settings, report)
            : make_local_smoothing_preconditioner<dim, degree, number>(problem,
                                                                       settings,
                                                                       report);
      else
        report.phases.emplace_back("set-up reused", 0.0);
      report.setup_time = total.wall_time();

      timer.restart();
      const double rhs_norm = rhs.l2_norm();
      check_right_hand_side(rhs_norm);
      SolverControl control(settings.max_iterations,
                            settings.relative_tolerance * rhs_norm,
                            false,
                            false);
      if (rhs_norm > 0)
        {
          try
            {
              solve_by_krylov(control,
                              problem.symmetric,
                              communicator,
                              *system_operator,
                              x,
                              rhs,
                              *preconditioner);
            }
          catch (const SolverControl::NoConvergence &exc)
            {
              rethrow_solver_failure(exc,
                                     communicator,
                                     "CG with matrix-free multigrid",
                                     rhs_norm,
                                     "raise Solver/Maximum iterations or use "
                                     "Solver/Type = AMG");
            }
        }
      report.iterations = iterations_of(control);
      report.final_residual =
        rhs_norm > 0 ? control.last_value() / rhs_norm : 0;
      report.solve_time = timer.wall_time();
      for (const auto &[phase, seconds] : preconditioner->cycle_phases())
        report.phases.emplace_back("V-cycle: " + phase, seconds);

      report.memory_bytes =
        Utilities::MPI::sum(static_cast<double>(
                              system_operator->memory_consumption() +
                              preconditioner->memory_consumption()),
                            communicator);

      // Into the right-hand side, which the solve has finished with, so
      // that the measurement does not raise the peak memory.
      if (settings.time_matrix_vector_product)
        time_products(report, *system_operator, *preconditioner, rhs, x);

      // Keep the set-up for the next solve of the same operator, or
      // release the hierarchy, the operator and the vectors CG and the
      // V-cycle left in deal.II's pools before the Trilinos solution is
      // made: it does not add to the solve's peak memory.
      if (problem.keep_setup)
        {
          kept_operator       = std::move(system_operator);
          kept_preconditioner = std::move(preconditioner);
          kept_version        = problem.operator_version;
        }
      preconditioner.reset();
      system_operator.reset();
      rhs.reinit(0);
      GrowingVectorMemory<VectorType>::release_unused_memory();
      GrowingVectorMemory<
        typename MultigridPreconditioner<dim, degree, number>::
          LevelVectorType>::release_unused_memory();
      solution.reinit(problem.system.locally_owned, communicator);
      copy_owned_entries(problem.system.locally_owned, x, solution);
      return report;
    }

    template <int dim, int degree>
    std::unique_ptr<typename MatrixFreeMultigridSolver<dim>::Implementation>
    make_implementation(const bool single_precision)
    {
      if (single_precision)
        return std::make_unique<MultigridImplementation<dim, degree, float>>();
      return std::make_unique<MultigridImplementation<dim, degree, double>>();
    }
  } // namespace

  template <int dim, int degree, typename number>
  std::unique_ptr<MultigridPreconditioner<dim, degree, number>>
  make_local_smoothing_preconditioner(
    const DiscreteProblem<dim>                              &problem,
    const typename MatrixFreeMultigridSolver<dim>::Settings &settings,
    SolverReport                                            &report)
  {
    return std::make_unique<LocalSmoothingPreconditioner<dim, degree, number>>(
      problem, settings, report);
  }

  template <int dim>
  MatrixFreeMultigridSolver<dim>::MatrixFreeMultigridSolver(
    const Settings    &settings,
    const unsigned int fe_degree)
      : settings(settings)
  {
    switch (fe_degree)
      {
      case 1:
        implementation =
          make_implementation<dim, 1>(settings.single_precision_levels);
        break;
      case 2:
        implementation =
          make_implementation<dim, 2>(settings.single_precision_levels);
        break;
      case 3:
        implementation =
          make_implementation<dim, 3>(settings.single_precision_levels);
        break;
      default:
        AssertThrow(false, ExcNotImplemented());
      }
  }

  template <int dim>
  MatrixFreeMultigridSolver<dim>::~MatrixFreeMultigridSolver() = default;

  template <int dim>
  double
  MatrixFreeMultigridSolver<dim>::memory_of_levels(
    const double       n_coarse_cells,
    const unsigned int n_levels) const
  {
    if (!settings.global_coarsening)
      return 0;
    const double children = GeometryInfo<dim>::max_children_per_cell;
    return 3 * sizeof(unsigned int) * n_coarse_cells *
           (std::pow(children, n_levels) - 1) / (children - 1);
  }

  template <int dim>
  bool
  MatrixFreeMultigridSolver<dim>::applies_to(
    const FiniteElementSpace<dim> &fe_space,
    const LoadCollection<dim>     &loads,
    std::string                   &reason)
  {
    if (fe_space.n_fields() != 1)
      reason = "the model has more than one displacement field (a fault)";
    else if (fe_space.degree() < 1 || fe_space.degree() > 3)
      reason = "it is built for polynomial degrees 1 to 3";
    else if (!loads.stiffness_is_vertical_springs())
      reason = "a load adds stiffness other than a vertical boundary spring";
    else
      return true;
    return false;
  }

  template <int dim>
  void
  MatrixFreeMultigridSolver<dim>::prepare_dof_handler(
    DoFHandler<dim> &dof_handler) const
  {
    // Global coarsening builds its own meshes and DoF handlers per level.
    if (!settings.global_coarsening)
      dof_handler.distribute_mg_dofs();
  }

  template <int dim>
  SolverReport
  MatrixFreeMultigridSolver<dim>::solve(const DiscreteProblem<dim>    &problem,
                                        TrilinosWrappers::MPI::Vector &solution)
  {
    return implementation->solve(problem, solution, settings);
  }

  template <int dim>
  void
  MatrixFreeMultigridSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Multigrid smoother degree",
                      "5",
                      Patterns::Integer(1, 20),
                      "Degree of the Chebyshev smoother on each level of "
                      "the matrix-free multigrid (operator products per "
                      "smoothing step). Type = two-field multigrid smooths "
                      "with degree 4 and range 20; the sliding solver's "
                      "multigrid with Faults/Sliding solver/Multigrid "
                      "smoother degree.");
    prm.declare_entry("Multigrid smoothing range",
                      "20",
                      Patterns::Double(1.5),
                      "Ratio of the largest eigenvalue to the smallest one "
                      "the matrix-free multigrid's Chebyshev smoother "
                      "damps.");
    prm.declare_entry("Multigrid level precision",
                      "single",
                      Patterns::Selection("single|double"),
                      "Floating-point precision of the multigrid levels "
                      "(the outer CG is always double precision).");
    prm.declare_entry("Multigrid coarse solver",
                      "direct",
                      Patterns::Selection("direct|AMG"),
                      "Solver of the multigrid's coarsest level (the coarse "
                      "mesh): a sparse direct factorisation (Amesos KLU), or "
                      "CG with AMG to a relative residual of 1e-8 in every "
                      "V-cycle, for coarse meshes too large to factorise "
                      "(tens of thousands of cells).");
    prm.declare_entry("Multigrid hierarchy",
                      "local smoothing",
                      Patterns::Selection("local smoothing|global coarsening"),
                      "Levels of the multigrid: the levels of the refined "
                      "mesh's cell hierarchy, smoothed only where they are "
                      "refined (local smoothing, with edge terms at "
                      "refinement edges), or a sequence of meshes each "
                      "coarsened once globally from the one above (global "
                      "coarsening: every level covers the whole domain, "
                      "hanging nodes on the levels). The same answer to the "
                      "solver tolerance; see doc/performance.md for when "
                      "each is faster.");
  }

  template <int dim>
  std::unique_ptr<LinearSolver<dim>>
  MatrixFreeMultigridSolver<dim>::create(
    ParameterHandler              &prm,
    const FiniteElementSpace<dim> &fe_space)
  {
    Settings s;
    s.relative_tolerance = prm.get_double("Relative tolerance");
    s.max_iterations     = prm.get_integer("Maximum iterations");
    s.smoother_degree    = prm.get_integer("Multigrid smoother degree");
    s.smoothing_range    = prm.get_double("Multigrid smoothing range");
    s.single_precision_levels =
      prm.get("Multigrid level precision") == "single";
    s.coarse_solver_amg = prm.get("Multigrid coarse solver") == "AMG";
    s.global_coarsening = prm.get("Multigrid hierarchy") == "global coarsening";
    s.time_matrix_vector_product = prm.get_bool("Time matrix-vector product");
    return std::make_unique<MatrixFreeMultigridSolver<dim>>(s,
                                                            fe_space.degree());
  }

  template class MatrixFreeMultigridSolver<2>;
  LITHOSTRESS_REGISTER_LINEAR_SOLVER(
    MatrixFreeMultigridSolver,
    "matrix-free multigrid",
    "CG with a matrix-free geometric multigrid V-cycle (no matrix is "
    "assembled; one displacement field of degree 1-3)")
} // namespace lithostress

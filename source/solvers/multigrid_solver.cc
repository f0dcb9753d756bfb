#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/vector_memory.h>
#include <deal.II/multigrid/mg_constrained_dofs.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/mg_transfer_matrix_free.h>
#include <deal.II/multigrid/multigrid.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/coarse_grid_solver.h>
#include <lithostress/solvers/elastic_operator.h>
#include <lithostress/solvers/multigrid_solver.h>

#include <map>

namespace lithostress
{
  namespace
  {
    /** Accumulates wall time of the multigrid phases through the signals of
     * deal.II's Multigrid class. */
    class PhaseClock
    {
    public:
      PhaseClock(const MPI_Comm communicator)
          : timer(communicator, false)
      {
      }

      std::function<void(const bool, const unsigned int)>
      slot(const std::string &phase)
      {
        return [this, phase](const bool start, const unsigned int) {
          if (start)
            timer.restart();
          else
            elapsed[phase] += timer.wall_time();
        };
      }

      std::map<std::string, double> elapsed;

    private:
      Timer timer;
    };

    template <int dim, int degree, typename number>
    class MultigridImplementation
        : public MatrixFreeMultigridSolver<dim>::Implementation
    {
    public:
      using Settings        = typename MatrixFreeMultigridSolver<dim>::Settings;
      using SystemOperator  = ElasticOperator<dim, degree, double>;
      using LevelOperator   = ElasticOperator<dim, degree, number>;
      using VectorType      = LinearAlgebra::distributed::Vector<double>;
      using LevelVectorType = LinearAlgebra::distributed::Vector<number>;
      using SmootherType =
        PreconditionChebyshev<LevelOperator, LevelVectorType>;

      SolverReport
      solve(const DiscreteProblem<dim>    &problem,
            TrilinosWrappers::MPI::Vector &solution,
            const Settings                &settings) override;
    };

    template <int dim, int degree, typename number>
    SolverReport
    MultigridImplementation<dim, degree, number>::solve(
      const DiscreteProblem<dim>    &problem,
      TrilinosWrappers::MPI::Vector &solution,
      const Settings                &settings)
    {
      const DoFHandler<dim>    &dof_handler  = problem.dof_handler;
      const MPI_Comm            communicator = dof_handler.get_communicator();
      const Mapping<dim>       &mapping      = problem.fe_space.mapping();
      const Triangulation<dim> &tria         = dof_handler.get_triangulation();
      const std::map<types::boundary_id, double> springs =
        problem.loads.vertical_springs(tria.get_boundary_ids());

      // Moduli of a (level or active) cell: those of its material.
      const auto material_moduli = [&problem](const auto &cell) {
        return problem.stress_model.moduli(cell->material_id())
          .lame_parameters();
      };

      SolverReport report;
      report.solver = "mf-gmg";
      Timer timer(communicator, true), total(communicator, true);

      // The operator on the active mesh (double precision).
      const auto flags = [&springs](auto &data) {
        data.tasks_parallel_scheme =
          std::remove_reference_t<decltype(data)>::none;
        data.mapping_update_flags = update_gradients | update_JxW_values;
        if (!springs.empty())
          data.mapping_update_flags_boundary_faces =
            update_values | update_normal_vectors | update_JxW_values;
      };
      SystemOperator system_operator;
      {
        typename MatrixFree<dim, double>::AdditionalData data;
        flags(data);
        auto matrix_free = std::make_shared<MatrixFree<dim, double>>();
        matrix_free->reinit(mapping,
                            dof_handler,
                            problem.system.constraints,
                            QGauss<1>(degree + 1),
                            data);
        system_operator.initialize(matrix_free);
        system_operator.set_cell_moduli(material_moduli);
        system_operator.set_vertical_springs(springs);
      }
      report.phases.emplace_back("matrix-free set-up (active mesh)",
                                 timer.wall_time());

      // The level operators.
      timer.restart();
      const unsigned int n_levels = tria.n_global_levels();
      MGConstrainedDoFs  constrained_dofs;
      constrained_dofs.initialize(dof_handler);
      for (const auto &[id, mask] :
           problem.prescribed_displacement.constrained_components(
             problem.fe_space))
        constrained_dofs.make_zero_boundary_constraints(dof_handler,
                                                        {id},
                                                        mask);

      MGLevelObject<LevelOperator> level_operators(0, n_levels - 1);
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          AffineConstraints<double> level_constraints;
          level_constraints.reinit(
            DoFTools::extract_locally_relevant_level_dofs(dof_handler, level));
          level_constraints.add_lines(
            constrained_dofs.get_boundary_indices(level));
          level_constraints.close();

          typename MatrixFree<dim, number>::AdditionalData data;
          flags(data);
          data.mg_level    = level;
          auto matrix_free = std::make_shared<MatrixFree<dim, number>>();
          matrix_free->reinit(mapping,
                              dof_handler,
                              level_constraints,
                              QGauss<1>(degree + 1),
                              data);
          level_operators[level].initialize(matrix_free,
                                            constrained_dofs,
                                            level);
          level_operators[level].set_cell_moduli(material_moduli);
          level_operators[level].set_vertical_springs(springs);
        }
      report.phases.emplace_back("matrix-free set-up (levels)",
                                 timer.wall_time());
      timer.restart();
      for (unsigned int level = 0; level < n_levels; ++level)
        level_operators[level].compute_diagonal();
      report.phases.emplace_back("level diagonals", timer.wall_time());

      timer.restart();
      MGTransferMatrixFree<dim, number> transfer(constrained_dofs);
      transfer.build(dof_handler);
      report.phases.emplace_back("transfer set-up", timer.wall_time());

      timer.restart();
      mg::SmootherRelaxation<SmootherType, LevelVectorType> smoother;
      MGLevelObject<typename SmootherType::AdditionalData>  smoother_data(
        0, n_levels - 1);
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          smoother_data[level].smoothing_range = settings.smoothing_range;
          smoother_data[level].degree          = settings.smoother_degree;
          // deal.II's default: the same V-cycle iteration counts as 12
          // Lanczos steps on every test and benchmark, at 2/3 the cost.
          smoother_data[level].eig_cg_n_iterations = 8;
          smoother_data[level].preconditioner =
            level_operators[level].get_matrix_diagonal_inverse();
        }
      smoother.initialize(level_operators, smoother_data);
      for (unsigned int level = 1; level < n_levels; ++level)
        {
          LevelVectorType v;
          level_operators[level].initialize_dof_vector(v);
          smoother[level].estimate_eigenvalues(v);
        }
      // The eigenvalue estimates' CG vectors would stay in deal.II's
      // vector pool for the rest of the run.
      GrowingVectorMemory<LevelVectorType>::release_unused_memory();
      report.phases.emplace_back("smoother set-up (eigenvalues)",
                                 timer.wall_time());

      timer.restart();
      CoarseGridSolver<dim, number> coarse;
      coarse.initialize(dof_handler,
                        problem.fe_space,
                        constrained_dofs,
                        material_moduli,
                        springs,
                        settings.coarse_solver_amg);
      report.phases.emplace_back(settings.coarse_solver_amg
                                   ? "coarse matrix and AMG set-up"
                                   : "coarse matrix and factorisation",
                                 timer.wall_time());

      mg::Matrix<LevelVectorType> mg_matrix(level_operators);
      MGLevelObject<MatrixFreeOperators::MGInterfaceOperator<LevelOperator>>
        interface_operators(0, n_levels - 1);
      for (unsigned int level = 0; level < n_levels; ++level)
        interface_operators[level].initialize(level_operators[level]);
      mg::Matrix<LevelVectorType> mg_interface(interface_operators);

      Multigrid<LevelVectorType> multigrid(
        mg_matrix, coarse, transfer, smoother, smoother);
      multigrid.set_edge_matrices(mg_interface, mg_interface);
      PhaseClock clock(communicator);
      multigrid.connect_pre_smoother_step(clock.slot("smoothing"));
      multigrid.connect_post_smoother_step(clock.slot("smoothing"));
      multigrid.connect_residual_step(clock.slot("level residuals"));
      multigrid.connect_restriction(clock.slot("transfer"));
      multigrid.connect_prolongation(clock.slot("transfer"));
      multigrid.connect_edge_prolongation(clock.slot("transfer"));
      multigrid.connect_coarse_solve(clock.slot("coarse solve"));
      PreconditionMG<dim, LevelVectorType, MGTransferMatrixFree<dim, number>>
        preconditioner(dof_handler, multigrid, transfer);
      report.setup_time = total.wall_time();

      // Solve in the matrix-free vector layout (same owned DoFs).
      timer.restart();
      VectorType rhs, x;
      system_operator.initialize_dof_vector(rhs);
      system_operator.initialize_dof_vector(x);
      AssertThrow(problem.system.locally_owned.n_elements() ==
                    rhs.locally_owned_size(),
                  ExcInternalError());
      {
        unsigned int k = 0;
        for (const types::global_dof_index i : problem.system.locally_owned)
          rhs.local_element(k++) = problem.system.rhs[i];
      }
      const double  rhs_norm = rhs.l2_norm();
      SolverControl control(settings.max_iterations,
                            settings.relative_tolerance * rhs_norm,
                            false,
                            false);
      if (rhs_norm > 0)
        {
          SolverCG<VectorType> cg(control);
          try
            {
              cg.solve(system_operator, x, rhs, preconditioner);
            }
          catch (const SolverControl::NoConvergence &exc)
            {
              throw ComputationError(
                "CG with matrix-free multigrid did not converge: residual " +
                std::to_string(exc.last_residual / rhs_norm) +
                " (relative) after " + std::to_string(exc.last_step) +
                " iterations; raise Solver/Maximum iterations or use "
                "Solver/Type = AMG");
            }
        }
      {
        unsigned int k = 0;
        for (const types::global_dof_index i : problem.system.locally_owned)
          solution[i] = x.local_element(k++);
        solution.compress(VectorOperation::insert);
      }
      report.iterations = control.last_step();
      report.final_residual =
        rhs_norm > 0 ? control.last_value() / rhs_norm : 0;
      report.solve_time = timer.wall_time();
      for (const auto &[phase, seconds] : clock.elapsed)
        report.phases.emplace_back("V-cycle: " + phase, seconds);

      report.memory_bytes =
        system_operator.memory_consumption() + transfer.memory_consumption();
      for (unsigned int level = 0; level < n_levels; ++level)
        report.memory_bytes += level_operators[level].memory_consumption();
      report.memory_bytes =
        Utilities::MPI::sum(report.memory_bytes, communicator);

      if (settings.time_matrix_vector_product)
        {
          // On vectors the solve has finished with, so that the
          // measurement does not raise the peak memory.
          Timer benchmark(communicator, true);
          report.matrix_vector_product_time =
            fastest_of(20, communicator, [&]() {
              system_operator.vmult(x, rhs);
            });
          LevelVectorType &level_x = multigrid.defect[n_levels - 1];
          LevelVectorType &level_y = multigrid.solution[n_levels - 1];
          if (level_x.size() == 0)
            {
              level_operators[n_levels - 1].initialize_dof_vector(level_x);
              level_operators[n_levels - 1].initialize_dof_vector(level_y);
            }
          level_x = 1.;
          report.level_matrix_vector_product_time =
            fastest_of(20, communicator, [&]() {
              level_operators[n_levels - 1].vmult(level_y, level_x);
            });
          report.benchmark_time = benchmark.wall_time();
        }
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
    dof_handler.distribute_mg_dofs();
  }

  template <int dim>
  SolverReport
  MatrixFreeMultigridSolver<dim>::solve(const DiscreteProblem<dim>    &problem,
                                        TrilinosWrappers::MPI::Vector &solution)
  {
    return implementation->solve(problem, solution, settings);
  }

  template class MatrixFreeMultigridSolver<2>;
} // namespace lithostress

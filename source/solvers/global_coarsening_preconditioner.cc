#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_transfer_global_coarsening.h>

#include <cstdint>
#include <limits>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/coarse_grid_solver.h>
#include <lithostress/solvers/multigrid_preconditioner.h>

namespace lithostress
{
  namespace
  {
    /**
     * The V-cycle of global coarsening (Munch, Heister, Prieto Saavedra &
     * Kronbichler 2023, "Efficient distributed matrix-free multigrid
     * methods on locally refined meshes for FEM computations"): level l is
     * the active mesh of a triangulation coarsened globally (every cell
     * once) from level l + 1, the finest level is the problem's own mesh
     * and DoF handler. Every level covers the whole domain and carries its
     * own hanging-node and prescribed-displacement constraints, so there
     * are no refinement edges; MGTwoLevelTransfer moves vectors between
     * neighbouring levels; the coarse mesh's stiffness is solved by
     * CoarseGridSolver on its active DoFs.
     */
    template <int dim, int degree, typename number>
    class GlobalCoarseningPreconditioner
        : public MultigridCycle<dim,
                                degree,
                                number,
                                MGTransferGlobalCoarsening<
                                  dim,
                                  LinearAlgebra::distributed::Vector<number>>>
    {
    public:
      using LevelVectorType = LinearAlgebra::distributed::Vector<number>;
      using Transfer        = MGTransferGlobalCoarsening<dim, LevelVectorType>;
      using Cycle           = MultigridCycle<dim, degree, number, Transfer>;
      using Settings        = typename Cycle::Settings;

      GlobalCoarseningPreconditioner(const DiscreteProblem<dim> &problem,
                                     const Settings             &settings,
                                     SolverReport               &report);

      ~GlobalCoarseningPreconditioner() override
      {
        this->release_cycle();
      }

    private:
      std::vector<std::shared_ptr<const Triangulation<dim>>>  triangulations;
      std::vector<std::unique_ptr<DoFHandler<dim>>>           coarser_dofs;
      std::vector<const DoFHandler<dim> *>                    level_dofs;
      MGLevelObject<AffineConstraints<number>>                constraints;
      MGLevelObject<MGTwoLevelTransfer<dim, LevelVectorType>> transfers;
      std::unique_ptr<Transfer>                               transfer;
    };

    template <int dim, int degree, typename number>
    GlobalCoarseningPreconditioner<dim, degree, number>::
      GlobalCoarseningPreconditioner(const DiscreteProblem<dim> &problem,
                                     const Settings             &settings,
                                     SolverReport               &report)
        : Cycle(problem.dof_handler)
    {
      const DoFHandler<dim>    &dof_handler     = this->dof_handler;
      auto                     &level_operators = this->level_operators;
      const MPI_Comm            communicator = dof_handler.get_communicator();
      const Mapping<dim>       &mapping      = problem.fe_space.mapping();
      const Triangulation<dim> &tria         = dof_handler.get_triangulation();
      const std::map<types::boundary_id, double> springs =
        problem.loads.vertical_springs(tria.get_boundary_ids());
      const auto material_moduli = multigrid_tools::material_moduli(problem);
      const auto prescribed =
        problem.prescribed_displacement.constrained_components(
          problem.fe_space);

      // deal.II 9.4 numbers the cells of all levels of the coarsening
      // sequence (CellIDTranslator) in types::global_cell_index, 32 bits
      // unless deal.II is built with 64-bit indices.
      {
        std::uint64_t n_ids = 0;
        for (unsigned int level = 0; level < tria.n_global_levels(); ++level)
          n_ids += Utilities::pow<std::uint64_t>(
                     GeometryInfo<dim>::max_children_per_cell, level) *
                   tria.n_global_coarse_cells();
        if (n_ids - 1 > std::numeric_limits<types::global_cell_index>::max())
          throw ComputationError(
            "the multigrid's global coarsening cannot number the cells of a "
            "mesh with " +
            std::to_string(tria.n_global_levels()) + " levels on " +
            std::to_string(tria.n_global_coarse_cells()) +
            " coarse cells with this deal.II build (32-bit cell indices); "
            "use Solver/Multigrid hierarchy = local smoothing");
      }

      Timer timer(communicator, true);
      triangulations =
        MGTransferGlobalCoarseningTools::create_geometric_coarsening_sequence(
          tria);
      const unsigned int n_levels = triangulations.size();
      level_dofs.resize(n_levels);
      for (unsigned int level = 0; level + 1 < n_levels; ++level)
        {
          coarser_dofs.push_back(
            std::make_unique<DoFHandler<dim>>(*triangulations[level]));
          coarser_dofs.back()->distribute_dofs(
            problem.fe_space.fe_collection());
          level_dofs[level] = coarser_dofs.back().get();
        }
      level_dofs[n_levels - 1] = &dof_handler;
      report.phases.emplace_back("coarsened meshes and DoFs",
                                 timer.wall_time());

      timer.restart();
      constraints.resize(0, n_levels - 1);
      level_operators.resize(0, n_levels - 1);
      for (unsigned int level = 0; level < n_levels; ++level)
        {
          const DoFHandler<dim>    &dofs = *level_dofs[level];
          AffineConstraints<double> level_constraints;
          level_constraints.reinit(
            DoFTools::extract_locally_relevant_dofs(dofs));
          DoFTools::make_hanging_node_constraints(dofs, level_constraints);
          for (const auto &[id, mask] : prescribed)
            DoFTools::make_zero_boundary_constraints(dofs,
                                                     id,
                                                     level_constraints,
                                                     mask);
          level_constraints.close();
          constraints[level].copy_from(level_constraints);

          typename MatrixFree<dim, number>::AdditionalData data;
          multigrid_tools::set_operator_flags(data, springs);
          auto matrix_free = std::make_shared<MatrixFree<dim, number>>();
          matrix_free->reinit(
            mapping, dofs, constraints[level], QGauss<1>(degree + 1), data);
          level_operators[level].initialize(matrix_free);
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
      transfers.resize(0, n_levels - 1);
      for (unsigned int level = 1; level < n_levels; ++level)
        transfers[level].reinit_geometric_transfer(*level_dofs[level],
                                                   *level_dofs[level - 1],
                                                   constraints[level],
                                                   constraints[level - 1]);
      transfer = std::make_unique<Transfer>(
        transfers, [this](const unsigned int level, LevelVectorType &v) {
          this->level_operators[level].initialize_dof_vector(v);
        });
      report.phases.emplace_back("transfer set-up", timer.wall_time());

      AffineConstraints<double> coarse_constraints;
      coarse_constraints.copy_from(constraints[0]);
      this->set_up_cycle(*transfer,
                         settings,
                         report,
                         [&](CoarseGridSolver<dim, number> &coarse) {
                           coarse.initialize(*level_dofs[0],
                                             problem.fe_space,
                                             coarse_constraints,
                                             material_moduli,
                                             springs,
                                             settings.coarse_solver_amg);
                         });
    }
  } // namespace

  template <int dim, int degree, typename number>
  std::unique_ptr<MultigridPreconditioner<dim, degree, number>>
  make_global_coarsening_preconditioner(
    const DiscreteProblem<dim>                              &problem,
    const typename MatrixFreeMultigridSolver<dim>::Settings &settings,
    SolverReport                                            &report)
  {
    return std::make_unique<
      GlobalCoarseningPreconditioner<dim, degree, number>>(problem,
                                                           settings,
                                                           report);
  }

#define INSTANTIATE(DEGREE, NUMBER)                                    \
  template std::unique_ptr<MultigridPreconditioner<2, DEGREE, NUMBER>> \
  make_global_coarsening_preconditioner<2, DEGREE, NUMBER>(            \
    const DiscreteProblem<2> &,                                        \
    const MatrixFreeMultigridSolver<2>::Settings &,                    \
    SolverReport &);

  INSTANTIATE(1, float)
  INSTANTIATE(1, double)
  INSTANTIATE(2, float)
  INSTANTIATE(2, double)
  INSTANTIATE(3, float)
  INSTANTIATE(3, double)
#undef INSTANTIATE
} // namespace lithostress

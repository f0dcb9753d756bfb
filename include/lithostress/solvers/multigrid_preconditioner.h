#ifndef lithostress_solvers_multigrid_preconditioner_h
#define lithostress_solvers_multigrid_preconditioner_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/vector_memory.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/multigrid.h>

#include <lithostress/base/input_error.h>
#include <lithostress/solvers/coarse_grid_solver.h>
#include <lithostress/solvers/elastic_operator.h>
#include <lithostress/solvers/linear_solver.h>
#include <lithostress/solvers/multigrid_solver.h>

#include <functional>
#include <map>
#include <string>

namespace lithostress
{
  /**
   * One V-cycle of a geometric multigrid for the elasticity operator, as
   * the preconditioner of the outer double-precision CG: the part in which
   * the two hierarchies of MatrixFreeMultigridSolver differ (local
   * smoothing on the levels of the p4est forest, or global coarsening on a
   * sequence of coarsened meshes). Level operators are ElasticOperator in
   * precision @p number.
   */
  template <int dim, int degree, typename number>
  class MultigridPreconditioner
  {
  public:
    using VectorType      = LinearAlgebra::distributed::Vector<double>;
    using LevelVectorType = LinearAlgebra::distributed::Vector<number>;
    using LevelOperator   = ElasticOperator<dim, degree, number>;

    virtual ~MultigridPreconditioner() = default;

    /** Apply one V-cycle to @p src. */
    virtual void
    vmult(VectorType &dst, const VectorType &src) const = 0;

    /** Wall time of the V-cycle phases accumulated so far. */
    virtual std::map<std::string, double>
    cycle_phases() const = 0;

    /** Memory of the level operators and transfers [bytes]. */
    virtual std::size_t
    memory_consumption() const = 0;

    /** Wall time of one product with the finest level's operator, the
     * fastest of 20 (benchmark). */
    virtual double
    time_finest_level_product() = 0;
  };

  /** The local-smoothing hierarchy (MGTransferMatrixFree with
   * MGConstrainedDoFs and edge matrices) of the levels of @p problem's mesh;
   * set-up phases go to @p report. */
  template <int dim, int degree, typename number>
  std::unique_ptr<MultigridPreconditioner<dim, degree, number>>
  make_local_smoothing_preconditioner(
    const DiscreteProblem<dim>                              &problem,
    const typename MatrixFreeMultigridSolver<dim>::Settings &settings,
    SolverReport                                            &report);

  /** The global-coarsening hierarchy (MGTransferGlobalCoarsening) of the
   * meshes obtained by coarsening @p problem's mesh globally, down to the
   * coarse mesh; set-up phases go to @p report. */
  template <int dim, int degree, typename number>
  std::unique_ptr<MultigridPreconditioner<dim, degree, number>>
  make_global_coarsening_preconditioner(
    const DiscreteProblem<dim>                              &problem,
    const typename MatrixFreeMultigridSolver<dim>::Settings &settings,
    SolverReport                                            &report);

  namespace multigrid_tools
  {
    /** Accumulates wall time of the multigrid phases through the signals
     * of deal.II's Multigrid class. */
    class PhaseClock
    {
    public:
      explicit PhaseClock(const MPI_Comm communicator)
          : timer(communicator, false)
      {
      }

      /** A slot for Multigrid's signal of @p phase. */
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

      /** Connect the slots to the phases of @p multigrid. */
      template <typename VectorType>
      void
      connect(Multigrid<VectorType> &multigrid)
      {
        multigrid.connect_pre_smoother_step(slot("smoothing"));
        multigrid.connect_post_smoother_step(slot("smoothing"));
        multigrid.connect_residual_step(slot("level residuals"));
        multigrid.connect_restriction(slot("transfer"));
        multigrid.connect_prolongation(slot("transfer"));
        multigrid.connect_edge_prolongation(slot("transfer"));
        multigrid.connect_coarse_solve(slot("coarse solve"));
      }

      std::map<std::string, double> elapsed;

    private:
      Timer timer;
    };

    /** The moduli of a (level or active) cell: the step moduli of its
     * material (relaxed in a visco-elastic time step). */
    template <int dim>
    auto
    material_moduli(const DiscreteProblem<dim> &problem)
    {
      return [&problem](const auto &cell) {
        return problem.stress_model.step_moduli(cell->material_id())
          .lame_parameters();
      };
    }

    /**
     * The tangent at quadrature point q (of QGauss(@p n_points_1d)) of an
     * active cell: StressModel::tangent() there, for a law whose tangent
     * varies from point to point (ActiveOperator::set_point_tangents()).
     */
    template <int dim>
    auto
    point_tangents(const DiscreteProblem<dim> &problem,
                   const unsigned int          n_points_1d)
    {
      using TriaCell = typename Triangulation<dim>::cell_iterator;
      auto fe        = std::make_shared<FE_Q<dim>>(1);
      auto values = std::make_shared<FEValues<dim>>(problem.fe_space.mapping(),
                                                    *fe,
                                                    QGauss<dim>(n_points_1d),
                                                    update_quadrature_points);
      // The cell whose points `values` holds (none yet), and the
      // linearisation of a non-linear law's step there (LinearisedStress).
      auto last =
        std::make_shared<std::pair<bool, TriaCell>>(false, TriaCell());
      auto linearisation =
        std::make_shared<std::vector<LinearisedStress<dim>>>();
      return [&problem, fe, values, last, linearisation](const auto &cell,
                                                         const unsigned int q)
               -> SymmetricTensor<4, dim> {
        const StressModel<dim> &model = problem.stress_model;
        const bool linearised         = model.linearised(cell->material_id());
        if (!last->first || last->second != TriaCell(cell))
          {
            *last = {true, TriaCell(cell)};
            values->reinit(last->second);
            if (linearised)
              model.linearisation_at(
                typename Triangulation<dim>::active_cell_iterator(last->second),
                *linearisation);
          }
        if (linearised)
          return (*linearisation)[q].tangent;
        return model.tangent(cell->material_id(), values->quadrature_point(q));
      };
    }

    /**
     * The tangent of a level cell for the multigrid's level operators of a
     * law whose tangent varies in space: the volume average of
     * point_tangents() over the cell's active descendants (each active
     * cell's mean over its quadrature points), so that yielding zones and
     * weak creeping regions are soft on every level as on the active mesh.
     * A level cell some of whose descendants this rank does not own (near
     * a partition boundary) takes its material's step moduli, as before;
     * the preconditioner then depends on the partition, the solution does
     * not. The second argument (the quadrature point) is ignored: the
     * tangent is constant per level cell.
     */
    template <int dim>
    auto
    level_tangents(const DiscreteProblem<dim> &problem,
                   const unsigned int          n_points_1d)
    {
      using Sum = std::pair<SymmetricTensor<4, dim>, double>;
      const Triangulation<dim> &tria = problem.dof_handler.get_triangulation();
      auto sums = std::make_shared<std::vector<std::map<unsigned int, Sum>>>(
        tria.n_levels());
      auto               tangent = point_tangents(problem, n_points_1d);
      const unsigned int n_q     = Utilities::pow(n_points_1d, dim);
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            SymmetricTensor<4, dim> mean;
            for (unsigned int q = 0; q < n_q; ++q)
              mean += tangent(cell, q);
            mean /= n_q;
            const double volume = cell->measure();
            for (typename Triangulation<dim>::cell_iterator c(cell);;
                 c = c->parent())
              {
                Sum &sum = (*sums)[c->level()][c->index()];
                sum.first += volume * mean;
                sum.second += volume;
                if (c->level() == 0)
                  break;
              }
          }
      return [&problem, sums](const auto &cell,
                              const unsigned int) -> SymmetricTensor<4, dim> {
        const auto &level = (*sums)[cell->level()];
        const auto  found = level.find(cell->index());
        if (found != level.end() &&
            found->second.second >= (1 - 1e-3) * cell->measure())
          return found->second.first / found->second.second;
        return problem.stress_model.step_moduli(cell->material_id())
          .stiffness();
      };
    }

    /** MatrixFree flags of the elasticity operator: gradients and JxW in
     * cells, values, normals and JxW on boundary faces if there are
     * @p springs. */
    template <typename AdditionalData>
    void
    set_operator_flags(AdditionalData                             &data,
                       const std::map<types::boundary_id, double> &springs)
    {
      data.tasks_parallel_scheme = AdditionalData::none;
      data.mapping_update_flags  = update_gradients | update_JxW_values;
      if (!springs.empty())
        data.mapping_update_flags_boundary_faces =
          update_values | update_normal_vectors | update_JxW_values;
    }

    /** Chebyshev smoothers on the inverse diagonals of @p operators, with
     * their eigenvalue estimates (levels above 0). */
    template <typename Operator, typename VectorType, typename Settings>
    void
    set_up_chebyshev(
      mg::SmootherRelaxation<PreconditionChebyshev<Operator, VectorType>,
                             VectorType> &smoother,
      const MGLevelObject<Operator>      &operators,
      const Settings                     &settings)
    {
      using Smoother = PreconditionChebyshev<Operator, VectorType>;
      MGLevelObject<typename Smoother::AdditionalData> data(
        operators.min_level(), operators.max_level());
      for (unsigned int level = operators.min_level();
           level <= operators.max_level();
           ++level)
        {
          data[level].smoothing_range = settings.smoothing_range;
          data[level].degree          = settings.smoother_degree;
          // deal.II's default: the same V-cycle iteration counts as 12
          // Lanczos steps on every test and benchmark, at 2/3 the cost.
          data[level].eig_cg_n_iterations = 8;
          data[level].preconditioner =
            operators[level].get_matrix_diagonal_inverse();
        }
      smoother.initialize(operators, data);
      for (unsigned int level = operators.min_level() + 1;
           level <= operators.max_level();
           ++level)
        {
          VectorType v;
          operators[level].initialize_dof_vector(v);
          smoother[level].estimate_eigenvalues(v);
        }
      // The eigenvalue estimates' CG vectors would stay in deal.II's
      // vector pool for the rest of the run.
      GrowingVectorMemory<VectorType>::release_unused_memory();
    }

    /** Memory of the level operators [bytes]. */
    template <typename Operator>
    std::size_t
    memory_consumption(const MGLevelObject<Operator> &operators)
    {
      std::size_t bytes = 0;
      for (unsigned int level = operators.min_level();
           level <= operators.max_level();
           ++level)
        bytes += operators[level].memory_consumption();
      return bytes;
    }

    /** Wall time of one product with the finest level's operator, the
     * fastest of 20, on the V-cycle's vectors of that level (which the
     * solve has finished with: the measurement does not raise the peak
     * memory). */
    template <typename Operator, typename VectorType>
    double
    time_finest_level_product(const MGLevelObject<Operator> &operators,
                              Multigrid<VectorType>         &multigrid,
                              const MPI_Comm                 communicator)
    {
      const unsigned int top = operators.max_level();
      VectorType        &x   = multigrid.defect[top];
      VectorType        &y   = multigrid.solution[top];
      if (x.size() == 0)
        {
          operators[top].initialize_dof_vector(x);
          operators[top].initialize_dof_vector(y);
        }
      x = 1.;
      return fastest_of(20, communicator, [&]() {
        operators[top].vmult(y, x);
      });
    }
  } // namespace multigrid_tools
  /**
   * What the two hierarchies share once their level operators and
   * transfer exist: Chebyshev smoothers, the coarse solve, deal.II's
   * Multigrid and PreconditionMG objects, the phase clock, and the
   * MultigridPreconditioner interface on top of them. @p Transfer is
   * MGTransferMatrixFree or MGTransferGlobalCoarsening.
   */
  template <int dim, int degree, typename number, typename Transfer>
  class MultigridCycle : public MultigridPreconditioner<dim, degree, number>
  {
  public:
    using Base            = MultigridPreconditioner<dim, degree, number>;
    using VectorType      = typename Base::VectorType;
    using LevelVectorType = typename Base::LevelVectorType;
    using LevelOperator   = typename Base::LevelOperator;
    using Settings        = typename MatrixFreeMultigridSolver<dim>::Settings;

    void
    vmult(VectorType &dst, const VectorType &src) const override
    {
      preconditioner->vmult(dst, src);
    }

    std::map<std::string, double>
    cycle_phases() const override
    {
      return clock.elapsed;
    }

    std::size_t
    memory_consumption() const override
    {
      return transfer->memory_consumption() +
             multigrid_tools::memory_consumption(level_operators);
    }

    double
    time_finest_level_product() override
    {
      return multigrid_tools::time_finest_level_product(
        level_operators, *multigrid, dof_handler.get_communicator());
    }

  protected:
    explicit MultigridCycle(const DoFHandler<dim> &dof_handler)
        : dof_handler(dof_handler)
        , clock(dof_handler.get_communicator())
    {
    }

    /**
     * Set up the smoothers on level_operators, the coarse solve by
     * @p initialize_coarse (called with `coarse`), and the V-cycle with
     * @p level_transfer (which must outlive this object); phases go to
     * @p report.
     */
    template <typename InitializeCoarse>
    void
    set_up_cycle(const Transfer         &level_transfer,
                 const Settings         &settings,
                 SolverReport           &report,
                 const InitializeCoarse &initialize_coarse)
    {
      Timer timer(dof_handler.get_communicator(), true);
      multigrid_tools::set_up_chebyshev(smoother, level_operators, settings);
      report.phases.emplace_back("smoother set-up (eigenvalues)",
                                 timer.wall_time());

      timer.restart();
      initialize_coarse(coarse);
      report.phases.emplace_back(settings.coarse_solver_amg
                                   ? "coarse matrix and AMG set-up"
                                   : "coarse matrix and factorisation",
                                 timer.wall_time());

      transfer = &level_transfer;
      mg_matrix.initialize(level_operators);
      multigrid = std::make_unique<Multigrid<LevelVectorType>>(
        mg_matrix, coarse, level_transfer, smoother, smoother);
      clock.connect(*multigrid);
      preconditioner =
        std::make_unique<PreconditionMG<dim, LevelVectorType, Transfer>>(
          dof_handler, *multigrid, level_transfer);
    }

    /** Destroy the V-cycle and the level operators' MatrixFree data,
     * which point to the transfer, edge operators and level DoF handlers
     * of the derived class: its destructor calls this. */
    void
    release_cycle()
    {
      preconditioner.reset();
      multigrid.reset();
      for (unsigned int level = level_operators.min_level();
           level <= level_operators.max_level();
           ++level)
        level_operators[level].clear();
    }

    const DoFHandler<dim>        &dof_handler;
    MGLevelObject<LevelOperator>  level_operators;
    CoarseGridSolver<dim, number> coarse;

  private:
    mg::SmootherRelaxation<
      PreconditionChebyshev<LevelOperator, LevelVectorType>,
      LevelVectorType>
                                smoother;
    mg::Matrix<LevelVectorType> mg_matrix;
    const Transfer             *transfer = nullptr;
    multigrid_tools::PhaseClock clock;

  protected:
    std::unique_ptr<Multigrid<LevelVectorType>> multigrid;

  private:
    std::unique_ptr<PreconditionMG<dim, LevelVectorType, Transfer>>
      preconditioner;
  };
} // namespace lithostress

#endif

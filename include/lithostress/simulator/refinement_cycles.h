#ifndef lithostress_simulator_refinement_cycles_h
#define lithostress_simulator_refinement_cycles_h

#include <deal.II/base/parameter_handler.h>

#include <lithostress/base/memory_budget.h>
#include <lithostress/analysis/convergence_study.h>
#include <lithostress/postprocessors/postprocessor.h>
#include <lithostress/refinement/mesh_refinement.h>
#include <lithostress/refinement/stress_goals.h>
#include <lithostress/simulator/elastic_problem.h>

#include <functional>
#include <string>

namespace lithostress
{
  using namespace dealii;

  /**
   * The refinement cycles: set up, assemble, solve and postprocess on a
   * mesh, then refine it (globally, by an error indicator, or
   * goal-oriented), until `Number of cycles` or until the goals have
   * converged (Mesh refinement/Goals). The one cycle loop of the program:
   * the elastic runs are these cycles, and a visco-elastic run starts with
   * them (its elastic response at t = 0); the time loop refines with
   * refine_mesh() as well. Owns the refinement settings, the goals and the
   * convergence table.
   */
  template <int dim>
  class RefinementCycles
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read Mesh refinement and its Goals; @p length_scale converts the
     * goals' boxes. */
    void
    parse_parameters(ParameterHandler &prm, const double length_scale);

    /**
     * Run the cycles on @p problem at model time 0. @p accepted runs once
     * the first assembly has accepted the model (then output may be
     * written); with @p cycle_output the postprocessors' per-cycle files
     * (ParaView) are written too.
     */
    void
    run(ElasticProblem<dim>          &problem,
        PostprocessorList<dim>       &postprocessors,
        const SimulatorAccess<dim>   &access,
        const std::function<void()>  &accepted,
        const bool                    cycle_output);

    /**
     * Refine the mesh of @p problem once; @p mesh names it in the memory
     * check, @p before_change runs once the cells are marked, before the
     * mesh changes (to attach data to transfer).
     */
    void
    refine_mesh(ElasticProblem<dim>         &problem,
                const SimulatorAccess<dim>  &access,
                const std::string           &mesh,
                const std::function<void()> &before_change = {});

    /** The cycle being computed (for the message of an interrupted run). */
    unsigned int
    cycle() const
    {
      return present_cycle;
    }

    const ConvergenceStudy &
    convergence_study() const
    {
      return study;
    }

    const MeshRefinement<dim> &
    settings() const
    {
      return refinement;
    }

    const StressGoals<dim> &
    goals() const
    {
      return stress_goals;
    }

    /** Refine the coarse mesh `Initial global refinement` times. */
    void
    refine_initially(parallel::distributed::Triangulation<dim> &tria) const;

    /** The memory budget the refinement checks each new mesh against
     * (the Simulator's; set before run()). */
    void
    set_memory_budget(const MemoryBudget &budget)
    {
      memory_budget = &budget;
    }

  private:
    /** Set up, assemble, solve and postprocess cycle present_cycle. */
    void
    compute_cycle(ElasticProblem<dim>         &problem,
                  PostprocessorList<dim>      &postprocessors,
                  const SimulatorAccess<dim>  &access,
                  const std::function<void()> &accepted);

    /** The goals' values of this cycle: convergence table, log, and
     * whether they have converged. */
    void
    record_goals(const SimulatorAccess<dim> &access);

    /** Whether the cycle just computed is the last: the goals have
     * converged, or it is the last of `Number of cycles` (then a
     * ComputationError if the goals were to converge and have not). */
    bool
    last_cycle(const SimulatorAccess<dim> &access) const;

    MeshRefinement<dim> refinement;
    /** Quantities of interest: goal-oriented refinement and the stopping
     * test of the cycles. */
    StressGoals<dim>    stress_goals;
    ConvergenceStudy    study;
    const MemoryBudget *memory_budget   = nullptr;
    unsigned int        present_cycle   = 0;
    bool                goals_converged = false;
  };
} // namespace lithostress

#endif

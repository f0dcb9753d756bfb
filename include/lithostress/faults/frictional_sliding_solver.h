#ifndef lithostress_faults_frictional_sliding_solver_h
#define lithostress_faults_frictional_sliding_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/faults/fault_history.h>
#include <lithostress/faults/fault_interface.h>
#include <lithostress/solvers/linear_solver.h>

#include <functional>
#include <memory>
#include <string>

namespace lithostress
{
  using namespace dealii;

  template <int dim>
  struct KeptSlidingOperator;

  /**
   * Solves the elasticity problem of a model whose fault slides by Coulomb
   * friction (thesis §5.5): the bulk is linear, the fault's law
   * (CoulombFriction) is piecewise linear in the jump, so its
   * linearisation at an iterate is an affine law per interface point.
   *
   * `newton` (default): a semi-smooth Newton method with the consistent
   * tangent, as the active-set method of deal.II step-42. Its first solve
   * is the elastic predictor (every point stuck); each further iteration
   * takes the return mapping at the last iterate (stuck, sliding or open
   * at each point), solves the system with the tangent K + ∫[v]·D[u] and
   * the affine part on the right-hand side, and takes the step with a
   * backtracking line search on the residual norm. It stops when the
   * residual ‖K u − f + ∫[v]·t(u)‖ (constrained rows left out) is below
   * the tolerance times ‖f‖ and the excess shear — the largest difference
   * between the traction of the linearised law the iterate was solved with
   * and the return mapping's — is below its tolerance: then the states no
   * longer change and the solution satisfies the law exactly. The tangent
   * is not symmetric while a point slides (the friction limit depends on
   * the normal jump): GMRES with the elasticity AMG (ILU smoothing, for the
   * stiff normal spring) solves it.
   *
   * `thesis`: the iteration of the thesis (§5.5, FSHEAR): the fault stays
   * elastic in the matrix (the AMG set up once), and the shear beyond
   * the friction limit is removed by equal and opposite forces on the two
   * sides, times the convergence factor, accumulated in the slip p, re-solved
   * until the excess shear is below its tolerance. Kept for comparison.
   *
   * solve() sets up the context both methods share (the problem, the
   * faults, the slip history, the iterate, the report and the log) and
   * runs one of them; both are in frictional_sliding_solver.cc.
   */
  template <int dim>
  class FrictionalSlidingSolver
  {
  public:
    /** The sliding iteration: semi-smooth Newton, or the thesis's (§5.5,
     * FSHEAR). */
    enum class Method
    {
      newton,
      thesis
    };

    /** The preconditioner of the sliding steps' Krylov solves: the
     * elasticity AMG, a sparse factorisation of the tangent kept while
     * it pays (Cholesky in exact contact on one rank, else Amesos KLU), or
     * the geometric multigrid of the two fields (TwoFieldMultigrid). */
    enum class Preconditioner
    {
      automatic,
      amg,
      direct,
      multigrid
    };

    /** The `Faults/Sliding solver` entries (thesis §5.5's convergence
     * factor among them). */
    struct Settings
    {
      Method       method                 = Method::newton;
      unsigned int max_iterations         = 100;
      double       residual_tolerance     = 1e-9;
      double       excess_shear_tolerance = 1e3;
      double       convergence_factor     = 1;
      /** Thesis method: a point over the friction limit at the first
       * iteration is held at the limit thereafter, even where it unloads
       * (FSHEAR's IIT flag); false: it re-sticks. */
      bool hold_at_limit = false;
      /** Thesis method: the excess shear from FSHEAR's reading of the
       * stresses, one value per fault element (FaultElementStresses),
       * instead of the traction at each interface point. */
      bool   element_stresses = false;
      bool   line_search      = true;
      double linear_tolerance = 1e-11;
      /** Newton, while the points' states change: each step's linear
       * solve stops at this times the current nonlinear residual (inexact
       * Newton), if that is above linear_tolerance times its right-hand
       * side. */
      double linear_reduction = 1e-3;
      /** Newton in exact contact: the tangent includes the friction
       * limits' dependence on the contact reactions
       * (FrictionLimitCoupling); false: the reactions are taken as given
       * (a fixed point, Anderson-accelerated). */
      bool reaction_in_tangent = true;
      /** The preconditioner of each step's Krylov solve (`Linear
       * solver`); automatic: the factorisation on one rank up to
       * multigrid_limit DoFs (direct_limit with the normal spring), the
       * two fields' multigrid above it in exact contact, handing over to
       * the factorisation up to direct_limit where it is slow, and on
       * more ranks the multigrid, or the AMG with the normal spring. */
      Preconditioner preconditioner  = Preconditioner::automatic;
      double         direct_limit    = 2e6;
      double         multigrid_limit = 2e5;
      /** Degree of the two fields' multigrid's Chebyshev smoother
       * (`Multigrid smoother degree`). */
      unsigned int smoother_degree = 4;
      /** Layers of its exact solve around the fault nodes
       * (`Multigrid fault zone layers`; TwoFieldMultigrid). */
      unsigned int fault_zone_layers = 6;
    };

    FrictionalSlidingSolver();
    ~FrictionalSlidingSolver();

    /**
     * The preconditioner `automatic` stands for, for a model of
     * @p n_dofs DoFs on @p n_ranks ranks, in exact contact or not
     * (@p contact): the factorisation on one rank up to the Multigrid
     * limit in exact contact (the Direct solver limit with the thesis's
     * normal spring); above it and on several ranks the two fields'
     * multigrid in exact contact, the AMG with the spring. Any other
     * choice is
     * returned as it is. The sliding steps and the dual problems of
     * goal-oriented refinement take the same; the sliding steps hand a
     * slow multigrid over to the factorisation up to the Direct solver
     * limit on one rank (hands_over_to_direct()).
     */
    static Preconditioner
    chosen_preconditioner(const Settings               &settings,
                          const bool                    contact,
                          const types::global_dof_index n_dofs,
                          const unsigned int            n_ranks);

    /**
     * Whether `automatic`'s multigrid (chosen_preconditioner()) may hand
     * over to the factorisation: on one rank, in exact contact, up to the
     * Direct solver limit. The sliding solver does so when the
     * multigrid's second solve on an operator takes more than
     * slow_multigrid_iterations.
     */
    static bool
    hands_over_to_direct(const Settings               &settings,
                         const bool                    contact,
                         const types::global_dof_index n_dofs,
                         const unsigned int            n_ranks);

    /** Iterations of the multigrid's second solve above which
     * hands_over_to_direct() takes the factorisation: a V-cycle costs
     * about 13 products with the assembled matrix, and on the thesis's
     * thin layers a Newton step with the kept Cholesky factor costs
     * about as much as 8 V-cycles (the thrust fault at 1.65 M DoFs:
     * 8.5 s per step against 1.1 s per iteration; doc/performance.md). */
    static constexpr unsigned int slow_multigrid_iterations = 8;

    /** Declare `Faults/Sliding solver`: the method, its tolerances and
     * the linear solver of each step (thesis §5.5). */
    static void
    declare_parameters(ParameterHandler &prm);

    /** Read `Faults/Sliding solver`; throws InputError for a convergence
     * factor that is not positive. */
    void
    parse_parameters(ParameterHandler &prm);

    /** The settings read by parse_parameters(). */
    const Settings &
    settings() const
    {
      return parameters;
    }

    /**
     * Solve @p problem (its matrix and right-hand side without the
     * frictional fault) with the fault of @p faults, from the committed slip
     * of @p history; its trial slip and states get the result (the caller
     * commits them). @p solution gets the
     * owned solution with its constraints distributed, @p report the
     * iterations and solves. @p progress gets a line per iteration. Throws
     * ComputationError if the iteration does not converge, with
     * @p solution, @p history and @p report holding the last iterate.
     */
    void
    solve(const DiscreteProblem<dim>             &problem,
          const FaultInterface<dim>              &faults,
          FaultHistory                           &history,
          TrilinosWrappers::MPI::Vector          &solution,
          SolverReport                           &report,
          const std::function<void(std::string)> &progress);

    /**
     * The next solve's Newton iteration starts from @p iterate (this
     * rank's owned entries on the next solve's mesh) instead of the
     * elastic predictor: a coarser mesh's solution interpolated onto the
     * refined one (nested iteration). Used by that solve only; the thesis
     * iteration ignores it.
     */
    void
    start_next_solve_from(const TrilinosWrappers::MPI::Vector &iterate)
    {
      next_start = iterate;
    }

  private:
    Settings parameters;
    /** The next solve's first iterate (empty: none). */
    TrilinosWrappers::MPI::Vector next_start;
    /** The linearised operator, exact contact's ties and the
     * preconditioner, kept from one solve to the next of the same bulk
     * operator (DiscreteProblem::operator_version): the time loop's steps
     * start from the last step's factor and open set. */
    std::unique_ptr<KeptSlidingOperator<dim>> kept;
  };
} // namespace lithostress

#endif

#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/interruption.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/faults/fault_element_stresses.h>
#include <lithostress/faults/fault_strip_stiffness.h>
#include <lithostress/faults/friction_limit_coupling.h>
#include <lithostress/faults/frictional_sliding_solver.h>
#include <lithostress/faults/normal_contact.h>
#include <lithostress/solvers/amg_solver.h>
#include <lithostress/solvers/rigid_body_modes.h>
#include <lithostress/solvers/sparse_cholesky.h>
#include <lithostress/solvers/two_field_multigrid.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace lithostress
{
  namespace
  {
    /** The entries of `Faults/Sliding solver` that choose and tune the
     * linear solver of the sliding steps (the caller is in that
     * subsection). */
    void
    declare_linear_solver_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(
        "Linear solver",
        "automatic",
        Patterns::Selection("automatic|AMG|direct|multigrid"),
        "The preconditioner of each sliding step's Krylov "
        "solve (CG in exact contact, GMRES with the normal "
        "spring): AMG = the elasticity AMG with the rigid "
        "modes of each block (Chebyshev smoothing in exact "
        "contact; ILU with the stiff spring); direct = a "
        "sparse factorisation of the tangent (its Cholesky "
        "factor in exact contact on one rank, else Amesos "
        "KLU), kept until the iterations it costs beyond its "
        "first solve's have taken longer than making it "
        "(the later steps' tangents differ only at the "
        "fault) and across the time steps of one step size; "
        "multigrid = a geometric multigrid V-cycle on the two "
        "fields with Galerkin coarse operators (exact contact), "
        "kept in the same way (made again when the open set "
        "changes, or when kept levels stall); "
        "automatic = in exact contact, direct on one rank up "
        "to Multigrid limit DoFs, above it multigrid, handing "
        "over to direct up to Direct solver limit where the "
        "multigrid is slow (Multigrid limit), and multigrid "
        "on several ranks; with the normal spring direct on "
        "one rank up to Direct solver limit, else AMG. The "
        "goal-oriented dual "
        "problems take the same in exact contact (KLU with "
        "the normal spring).");
      prm.declare_entry("Multigrid smoother degree",
                        "4",
                        Patterns::Integer(1, 20),
                        "Linear solver = multigrid (or automatic choosing "
                        "it): the degree of the Chebyshev smoother on each "
                        "level of the two fields' V-cycle (products with the "
                        "level matrix per smoothing step), preconditioned by "
                        "the inverse of each node's block. From 27 k to "
                        "1.65 M DoFs on the thesis's normal fault, graben and "
                        "thrust the iterations per Newton step change by "
                        "+16, +12 and -16 % with 4; 6 takes about a fifth "
                        "fewer iterations, each dearer (doc/performance.md).");
      prm.declare_entry("Multigrid fault zone layers",
                        "6",
                        Patterns::Integer(0, 100),
                        "Linear solver = multigrid (or automatic choosing "
                        "it): on each level of the two fields' V-cycle, the "
                        "DoFs within this many layers of the level matrix's "
                        "graph from the fault nodes are solved exactly after "
                        "the pre-smoothing and before the post-smoothing "
                        "(0: none). On the plane thrust at 991 k DoFs 6 "
                        "layers take 53 linear iterations in 8 Newton steps "
                        "instead of 78 (doc/performance.md).");
      prm.declare_entry("Direct solver limit",
                        "2e6",
                        Patterns::Double(0),
                        "Linear solver = automatic: the largest number of "
                        "DoFs for which one rank factorises the tangent "
                        "(at 1.65e6 DoFs the run's peak memory was 2.6-3.7 KB "
                        "per DoF; doc/performance.md).");
      prm.declare_entry("Multigrid limit",
                        "2e5",
                        Patterns::Double(0),
                        "Linear solver = automatic on one rank, exact "
                        "contact: above this many DoFs (up to Direct solver "
                        "limit) the sliding steps start with the two fields' "
                        "multigrid, and hand over to the kept factorisation "
                        "if the multigrid's second solve takes more than 8 "
                        "iterations (a Newton step with the factor costs "
                        "about 8 V-cycles on the thesis's layers); below it "
                        "the factorisation. Measured at 416 k and 1.65 M "
                        "DoFs: the multigrid 13-27 % faster than the factor "
                        "on the normal fault and the graben (5 iterations per "
                        "solve), the factor 1.5-2 times faster on the "
                        "low-angle thrust (10-11; doc/performance.md).");
    }
  } // namespace

  template <int dim>
  void
  FrictionalSlidingSolver<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Faults");
    prm.enter_subsection("Sliding solver");
    prm.declare_entry("Method",
                      "newton",
                      Patterns::Selection("newton|thesis"),
                      "How a frictional fault's sliding is found: newton = "
                      "semi-smooth Newton with the consistent tangent and a "
                      "line search; thesis = the thesis's iteration (§5.5, "
                      "FSHEAR): excess shear removed by nodal forces times "
                      "the Convergence factor, re-solved with the elastic "
                      "fault.");
    prm.declare_entry("Maximum iterations",
                      "100",
                      Patterns::Integer(1),
                      "Nonlinear iterations (linear solves) before the run "
                      "stops with the last iterate written out.");
    prm.declare_entry("Residual tolerance",
                      "1e-9",
                      Patterns::Double(0),
                      "Newton stops when the residual norm is below this "
                      "times the norm of the right-hand side (and the excess "
                      "shear below its tolerance).");
    prm.declare_entry("Excess shear tolerance",
                      "1e3",
                      Patterns::Double(0),
                      "[Pa] Both methods stop when the shear traction "
                      "exceeds the friction limit (thesis) or the law the "
                      "iterate was solved with (Newton) by less than this "
                      "everywhere on the fault.");
    prm.declare_entry("Convergence factor",
                      "1",
                      Patterns::Double(0),
                      "Thesis method: the excess-shear forces are multiplied "
                      "by this (the thesis used 15 for k_s = 5e10 N/m).");
    prm.declare_entry("Hold sliding points at the limit",
                      "false",
                      Patterns::Bool(),
                      "Thesis method: true = as FSHEAR (its IIT flag), a "
                      "point whose shear exceeded the friction limit at the "
                      "first iteration has its shear moved to the limit at "
                      "every later iteration, even where it has unloaded "
                      "below it (it may slide back); false = such a point "
                      "sticks again once its shear is below the limit.");
    prm.declare_entry("Thesis stress reading",
                      "interface points",
                      Patterns::Selection("interface points|element centroids"),
                      "Thesis method: where the excess shear is read. "
                      "interface points = the fault's traction at each "
                      "interface point; element centroids = as FSHEAR, one "
                      "value per fault element (face pair): the stresses of "
                      "the two cells beside it at their centroids, with the "
                      "lithostatic stress at each centroid's depth, "
                      "averaged, less the pore pressure at the face's "
                      "midpoint, applied to all of the face's points.");
    prm.declare_entry("Line search",
                      "true",
                      Patterns::Bool(),
                      "Newton: halve the step until the residual norm "
                      "falls (at most 6 times).");
    prm.declare_entry("Linear solver tolerance",
                      "1e-11",
                      Patterns::Double(0),
                      "Relative tolerance of each linear solve of a "
                      "frictional fault (whatever Solver/Type says): the "
                      "residual is brought below this times the right-hand "
                      "side, or below Linear solver reduction times the "
                      "Newton residual, whichever is larger.");
    prm.declare_entry("Linear solver reduction",
                      "1e-3",
                      Patterns::Double(0, 1),
                      "Newton: while the points' states (stuck, sliding, "
                      "open) change, each step's linear solve stops once "
                      "its residual is below this times the current "
                      "nonlinear residual (an inexact Newton method; "
                      "Eisenstat & Walker 1996): those steps are not solved "
                      "to round-off. A step whose states stood still may be "
                      "the last and is solved to the Linear solver "
                      "tolerance, as is the first step from the time loop's "
                      "extrapolation where its states are the last "
                      "solution's (unless friction limits follow contact "
                      "reactions the tangent takes as given: Reaction in "
                      "tangent = false); so is every step with 0.");
    prm.declare_entry("Reaction in tangent",
                      "true",
                      Patterns::Bool(),
                      "Newton in exact normal contact: the tangent includes "
                      "the friction limit's dependence on the contact "
                      "reaction (mu times the tie's reaction, a linear "
                      "function of the displacement; a non-symmetric term, "
                      "solved by GMRES), so that the iteration ends in one "
                      "step once the states stand still. false: the "
                      "reaction is taken as given at each iterate, a fixed "
                      "point with Anderson acceleration (symmetric tangent, "
                      "CG), which contracts by about 0.2 per iteration on "
                      "the thrust fault.");
    declare_linear_solver_parameters(prm);
    prm.leave_subsection();
    prm.leave_subsection();
  }

  template <int dim>
  void
  FrictionalSlidingSolver<dim>::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Faults");
    prm.enter_subsection("Sliding solver");
    parameters.method =
      prm.get("Method") == "thesis" ? Method::thesis : Method::newton;
    parameters.max_iterations     = prm.get_integer("Maximum iterations");
    parameters.residual_tolerance = prm.get_double("Residual tolerance");
    parameters.excess_shear_tolerance =
      prm.get_double("Excess shear tolerance");
    parameters.convergence_factor = prm.get_double("Convergence factor");
    parameters.hold_at_limit = prm.get_bool("Hold sliding points at the limit");
    parameters.element_stresses =
      prm.get("Thesis stress reading") == "element centroids";
    parameters.line_search         = prm.get_bool("Line search");
    parameters.linear_tolerance    = prm.get_double("Linear solver tolerance");
    parameters.linear_reduction    = prm.get_double("Linear solver reduction");
    parameters.reaction_in_tangent = prm.get_bool("Reaction in tangent");
    const std::string solver       = prm.get("Linear solver");
    parameters.preconditioner      = solver == "direct" ? Preconditioner::direct
                                     : solver == "AMG"  ? Preconditioner::amg
                                     : solver == "multigrid"
                                       ? Preconditioner::multigrid
                                       : Preconditioner::automatic;
    parameters.direct_limit        = prm.get_double("Direct solver limit");
    parameters.multigrid_limit     = prm.get_double("Multigrid limit");
    parameters.smoother_degree = prm.get_integer("Multigrid smoother degree");
    parameters.fault_zone_layers =
      prm.get_integer("Multigrid fault zone layers");
    if (!(parameters.convergence_factor > 0))
      throw_input_error("Faults/Sliding solver/Convergence factor",
                        "must be positive");
    // The thesis method's readings mean nothing to Newton: say so rather
    // than ignore them.
    if (parameters.method == Method::newton &&
        (parameters.element_stresses || parameters.hold_at_limit))
      throw_input_error(std::string("Faults/Sliding solver/") +
                          (parameters.element_stresses
                             ? "Thesis stress reading"
                             : "Hold sliding points at the limit"),
                        "applies to Method = thesis only (Method is "
                        "newton)");
    for (const auto &[entry, value] :
         {std::make_pair("Residual tolerance", parameters.residual_tolerance),
          std::make_pair("Linear solver tolerance",
                         parameters.linear_tolerance)})
      if (!(value > 0))
        throw_input_error(std::string("Faults/Sliding solver/") + entry,
                          "must be positive (a tolerance of 0 is never "
                          "reached)");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  namespace
  {
    /** Σ_ab m[a][b] e_a ⊗ e_b with e_0 = @p s, e_1 = @p n: a tensor of the
     * (shear, normal) frame in the (x, y) frame. */
    template <int dim>
    Tensor<2, dim>
    from_local_frame(const Tensor<2, 2>   &m,
                     const Tensor<1, dim> &s,
                     const Tensor<1, dim> &n)
    {
      const Tensor<1, dim> e[2] = {s, n};
      Tensor<2, dim>       result;
      for (unsigned int a = 0; a < 2; ++a)
        for (unsigned int b = 0; b < 2; ++b)
          result += m[a][b] * outer_product(e[a], e[b]);
      return result;
    }

  } // namespace

  /**
   * What the sliding steps keep from one solve to the next of the same
   * bulk operator (the steps of the visco-elastic loop between changes of
   * the mesh or the step size): exact contact's open set and ties, the
   * linearised matrix (the bulk and the interface tangent it holds) and its
   * preconditioner with the bookkeeping that decides when to make it again.
   * A new solve then assembles only its right-hand side.
   */
  template <int dim>
  struct KeptSlidingOperator
  {
    /** Nothing kept yet, for @p problem's operator, the next solve
     * starting from @p solution (empty: none). */
    KeptSlidingOperator(const DiscreteProblem<dim>          &problem,
                        const TrilinosWrappers::MPI::Vector &solution)
        : operator_version(problem.operator_version)
        , dof_handler(&problem.dof_handler)
        , solution(solution)
    {
    }

    /** The operator (DiscreteProblem::operator_version) and DoF handler it
     * was made for. */
    unsigned long long     operator_version = 0;
    const DoFHandler<dim> *dof_handler      = nullptr;
    /** Exact normal contact, if a fault has it. */
    std::unique_ptr<NormalContact<dim>> contact;
    /** The linearised system: its matrix, right-hand side and (exact
     * contact) constraints. */
    LinearSystem<dim> linearised;
    /** Exact contact: the model's stiffness from the linearised matrix and
     * the strip of cells along the faults (the model's own matrix is not
     * assembled), made with it. */
    FaultStripStiffness<dim> strip;
    /** The interface tangent per point in the matrix: a set-up adds
     * only the change, onto the bulk assembled (and its constraints
     * made) once per set of active constraints. */
    std::vector<Tensor<2, dim>>         assembled_tangents;
    bool                                assembled         = false;
    unsigned int                        assembled_version = 0;
    std::unique_ptr<Epetra_MultiVector> modes;
    TrilinosWrappers::PreconditionAMG   amg;
    /** Whether the preconditioner is kept for the next solve. The
     * tangent and the active constraints change only at the fault's
     * points, a change of low rank for a Krylov method: a preconditioner
     * is kept until the iterations it has cost beyond those of its first
     * solve took longer than making it (preconditioner_cost). */
    bool preconditioner_current = false;
    /** The wall time of making the preconditioner, the time its
     * iterations beyond those of its first solve have taken since, and
     * the iterations of that first solve. */
    double        preconditioner_cost = 0, stale_cost = 0;
    unsigned int  first_iterations = numbers::invalid_unsigned_int;
    SolverControl factorization_control;
    std::unique_ptr<TrilinosWrappers::SolverDirect> factorization;
    std::unique_ptr<SparseCholesky>                 cholesky;
    std::unique_ptr<TwoFieldMultigrid<dim>>         multigrid;
    /** `automatic`'s multigrid on this operator: its solves so far, and
     * whether it was handed over to the factorisation
     * (FrictionalSlidingSolver::hands_over_to_direct()). */
    unsigned int multigrid_solves   = 0;
    bool         multigrid_declined = false;
    /** The last converged Newton solution, where the next solve starts
     * (empty: none yet), or the start given for it: a coarser mesh's
     * solution, or the time loop's extrapolation (`predicted_start`). */
    TrilinosWrappers::MPI::Vector solution;
    bool                          predicted_start = false;
    /** The points' states at that converged solution (this rank's points),
     * against which a warm start's states are compared
     * (solve_by_newton()), and whether there is one (on every rank). */
    std::vector<SlipState> converged_states;
    bool                   has_converged_states = false;

    /** Whether it was made for @p problem's operator. */
    bool
    made_for(const DiscreteProblem<dim> &problem) const
    {
      return dof_handler == &problem.dof_handler &&
             operator_version == problem.operator_version;
    }
  };

  namespace
  {
    /**
     * What the two methods of FrictionalSlidingSolver share (thesis §5.5,
     * FSHEAR, and the Newton method that replaces it): the problem with
     * its faults, the slip history, the iterate u with its residual, the
     * law each solve linearised, the linearised system and its solver, the
     * report and the progress log.
     */
    template <int dim>
    class SlidingContext
    {
    public:
      using Settings    = typename FrictionalSlidingSolver<dim>::Settings;
      using PointValues = typename FaultInterface<dim>::PointValues;
      /** An interface law at a point: the traction @p t and its tangent
       * @p D = ∂t/∂w at the point's jump. */
      using Law = std::function<
        void(const PointValues &, Tensor<1, dim> &t, Tensor<2, dim> &D)>;

      /** The context of a solve of @p problem with @p faults from the
       * committed slip of @p history (reinitialised for this mesh's
       * interface points), from u = the constraints' inhomogeneities. */
      SlidingContext(const Settings                         &settings,
                     const DiscreteProblem<dim>             &problem,
                     const FaultInterface<dim>              &faults,
                     FaultSlipHistory                       &history,
                     SolverReport                           &report,
                     const std::function<void(std::string)> &progress,
                     KeptSlidingOperator<dim>               &kept);

      /** The elastic law with the slip @p slip per point (thesis §5.5: the
       * fault stays elastic, its slip moves the springs' rest length),
       * recorded as the law the next solve linearises. */
      Law
      stuck_law(const std::vector<double> &slip);

      /** The Coulomb law's return mapping from the committed slip at the
       * point @p values (CoulombFriction::respond), its response kept. */
      void
      return_mapping(const PointValues &values,
                     Tensor<1, dim>    &t,
                     Tensor<2, dim>    &D);

      /** The Coulomb law at the point @p values from the slip @p p_old:
       * CoulombFriction::respond(), or respond_in_contact() with the
       * point's reaction in exact contact. */
      CoulombFriction::Response
      respond(const PointValues &values, const double p_old) const
      {
        const auto            &p   = values.point;
        const Tensor<1, dim>  &w   = values.jump;
        const CoulombFriction &law = faults.friction(p.fault);
        if (p.at_tip)
          return law.welded(w * p.shear, p_old);
        if (contact && contact->exact(values.index))
          return law.respond_in_contact(w * p.shear,
                                        contact->normal_traction(values.index),
                                        contact->closed(values.index),
                                        p_old,
                                        p.overburden_depth);
        return law.respond(w * p.shear,
                           w * p.normal,
                           p_old,
                           p.overburden_depth);
      }

      /** Exact contact: the normal tractions at @p owned, from the residual
       * K u − f with the interface's other forces (the shear, and the open
       * points' normal traction) at the last tractions; u_ghost gets
       * @p owned, residual K u − f. */
      void
      contact_tractions(const TrilinosWrappers::MPI::Vector &owned);

      /** The return mapping, recorded as the law the next solve
       * linearises (the Newton tangent). */
      void
      newton_law(const PointValues &values,
                 Tensor<1, dim>    &t,
                 Tensor<2, dim>    &D);

      /** The residual norm ‖K u − f + ∫[v]·t(u)‖ (constrained rows left
       * out; in exact contact of the tied system, condense_ties()) at
       * @p owned, with the return mapping from the committed slip;
       * u_ghost gets @p owned, excess the largest excess shear against the
       * law of the last solve. */
      double
      residual_norm(const TrilinosWrappers::MPI::Vector &owned);

      /** A warm start on a new operator in exact contact (the iterate is
       * a coarser mesh's solution): the contact's nodes open where the
       * iterate's faces are apart, and the ties of the others, which the
       * first residual condenses. */
      void
      start_contact_from_iterate()
      {
        if (!contact || !nested_start)
          return;
        residual_norm(u);
        contact->start_from(normal_jumps,
                            1e-10 * u.linfty_norm(),
                            constraints,
                            linearised.constraints);
      }

      /** Exact contact: @p r := C^T @p r for the ties of the closed nodes
       * (each tied row's residual added to the DoFs its tie takes it from,
       * with the tie's weights, and the tied row zeroed). */
      void
      condense_ties(TrilinosWrappers::MPI::Vector &r) const;

      /** Assemble the linearised matrix without interface tangent for
       * the current active constraints (exact contact: with the strip
       * that gives the model's stiffness), and its bulk right-hand side. */
      void
      assemble_operator();

      /** The system of the law @p law linearised at u_ghost (the bulk
       * matrix with ∫[v]·D[u], the right-hand side less the affine part),
       * and its AMG. */
      void
      set_up(const Law &law);

      /** Bytes of the factorisation's factor, where it can be measured
       * (the Cholesky factor), else 0. */
      double
      preconditioner_memory() const
      {
        return cholesky    ? cholesky->memory_consumption()
               : multigrid ? multigrid->memory_consumption()
                           : 0.;
      }

      /** rhs := bulk_rhs, ready for additions on every rank. */
      void
      reset_rhs()
      {
        rhs = bulk_rhs;
        // A copy between different maps leaves a pending insertion, which
        // the first addition would flush collectively: flush it here, on
        // every rank (a rank without fault points adds nothing).
        rhs.compress(VectorOperation::insert);
      }

      /** The right-hand side with the affine part of @p law at zero jump
       * (the thesis method: only the slip changes between its solves). */
      void
      assemble_rhs(const Law &law);

      /** Solve the linearised system for @p x from @p x to the Linear
       * solver tolerance or the forcing, whichever is larger (CG in exact
       * contact, else GMRES; with the factorisation, or the AMG, whose
       * ILU smoothing for the spring goes on with Chebyshev if it stalls),
       * with the active constraints distributed. */
      void
      linear_solve(TrilinosWrappers::MPI::Vector &x);

      /** Exact contact: the normal tractions the next linearisation takes
       * (NormalContact::accelerate()), afresh if @p restart (a state or
       * the active set changed). */
      void
      accelerate_tractions(const bool restart)
      {
        if (contact && !settings.reaction_in_tangent)
          contact->accelerate(restart);
      }

      /** Exact contact with Reaction in tangent: the tangent's term for
       * the friction limits' dependence on the reactions at u
       * (FrictionLimitCoupling, from the return mapping of the last
       * set_up()), and its share M u of the right-hand side; none after
       * the elastic predictor (@p newton false). */
      void
      couple_friction_limits(const bool newton);

      /** Whether a point's state at the last evaluated iterate differs
       * from the last call's (true at the first call), on any rank. */
      bool
      states_changed()
      {
        bool changed = newton_states.size() != responses.size();
        newton_states.resize(responses.size());
        for (unsigned int i = 0; i < responses.size(); ++i)
          {
            changed = changed || responses[i].state != newton_states[i];
            newton_states[i] = responses[i].state;
          }
        return Utilities::MPI::logical_or(changed, communicator);
      }

      /** Whether the states at a warm start's iterate differ from those of
       * the kept operator's last converged solution (true without a warm
       * start on this operator, or with none kept): where they do not (the
       * time loop's extrapolation on an unchanged operator), the first step
       * may be the last and is solved to the Linear solver tolerance. */
      bool
      states_changed_since_converged()
      {
        if (!warm_start || nested_start || !kept.has_converged_states)
          return true;
        newton_states = kept.converged_states;
        return states_changed();
      }

      /** Whether a point slides in exact contact, on any rank: its
       * friction limit then follows the contact reaction, which the
       * tangent takes as given, so that no step is exact even while the
       * states stand still (a fixed point in the tractions). */
      bool
      limits_follow_reactions() const
      {
        bool follows = false;
        if (contact && !settings.reaction_in_tangent)
          for (const auto &r : responses)
            follows = follows || r.state == SlipState::sliding;
        return Utilities::MPI::logical_or(follows, communicator);
      }

      /** Whether the linearised system is symmetric (exact contact
       * without the friction limits' coupling): CG, else GMRES. */
      bool
      symmetric() const
      {
        return contact && !coupling.active();
      }

      /** "<n> sliding, <m> open of <N> points" over all ranks. */
      std::string
      count_states() const;

      /** The constraints of the linearised system: the problem's, with the
       * ties of the closed nodes in exact contact. */
      const AffineConstraints<double> &
      active_constraints() const
      {
        return contact ? linearised.constraints : constraints;
      }

      /** Exact contact: the active-set update at the iterate of the last
       * residual_norm() (NormalContact::update()); whether it changed.
       * Without exact contact: false. */
      bool
      update_active_set()
      {
        return contact && contact->update(responses, normal_jumps);
      }

      KeptSlidingOperator<dim>               &kept;
      const Settings                         &settings;
      const DiscreteProblem<dim>             &problem;
      const FaultInterface<dim>              &faults;
      FaultSlipHistory                       &history;
      SolverReport                           &report;
      const std::function<void(std::string)> &progress;
      const DoFHandler<dim>                  &dof_handler;
      const FiniteElementSpace<dim>          &fe_space;
      const LinearSystem<dim>                &system;
      const AffineConstraints<double>        &constraints;
      const MPI_Comm                          communicator;
      unsigned int                            n_points = 0;
      // The law each solve linearised (t = D w + c per point) and the
      // return mapping's response at the last evaluated iterate.
      std::vector<Tensor<2, dim>>            tangents;
      std::vector<Tensor<1, dim>>            affine;
      std::vector<CoulombFriction::Response> responses;
      /** w_n at each point at the last evaluated iterate. */
      std::vector<double> normal_jumps;
      /** The states at the last states_changed(). */
      std::vector<SlipState> newton_states;
      /** Exact normal contact, if a fault has it. */
      std::unique_ptr<NormalContact<dim>> &contact = kept.contact;
      /** The linearised system: its matrix, right-hand side and (exact
       * contact) constraints. */
      LinearSystem<dim>             &linearised = kept.linearised;
      TrilinosWrappers::MPI::Vector &rhs        = linearised.rhs;
      TrilinosWrappers::MPI::Vector  u, u_ghost, residual, force;
      /** ‖f‖; the last residual norm; the last excess shear [Pa]. */
      double f = 0, r_norm = 0, excess = 0;
      /** The last iteration. */
      unsigned int iteration = 0;
      /** Whether u started from the last solve's solution; whether that
       * was another mesh's (start_next_solve_from()), on this new operator. */
      bool warm_start = false, nested_start = false;
      /** Whether Newton with the reaction in the tangent diverged
       * (solve_by_newton()): the caller solves again with the reactions
       * taken as given. */
      bool diverged = false;
      /** Whether the steps are preconditioned by a factorisation
       * (`Linear solver`); the residual a linear solve must reach beyond
       * the Linear solver tolerance (inexact Newton). */
      bool   direct  = false;
      double forcing = 0;
      /** Whether the last linear solve went to the Linear solver
       * tolerance (the forcing was below it). */
      bool to_tolerance = false;
      /** Whether they are preconditioned by TwoFieldMultigrid, and
       * whether it may hand over to the factorisation (`automatic`). */
      bool use_multigrid = false, may_hand_over = false;
      /** The tangent's coupling of the friction limits to the reactions
       * (exact contact, Reaction in tangent). */
      FrictionLimitCoupling<dim> coupling;
      /** The iterations of the last Krylov solve. */
      unsigned int last_iterations = 0;
      /** Wall time [s] of assembly, preconditioner set-up, Krylov solves
       * and residual evaluations (with the contact's reactions). */
      double time_assembly = 0, time_preconditioner = 0, time_solve = 0,
             time_residual = 0;

      /** The times above added to @p phases, by name (entries made as
       * needed). */
      void
      add_phase_times(std::vector<std::pair<std::string, double>> &phases) const
      {
        for (const auto &[name, seconds] :
             {std::make_pair("sliding: assembly", time_assembly),
              std::make_pair("sliding: preconditioner set-up",
                             time_preconditioner),
              std::make_pair("sliding: Krylov solves", time_solve),
              std::make_pair("sliding: residuals and reactions",
                             time_residual)})
          {
            auto phase =
              std::find_if(phases.begin(), phases.end(), [&](const auto &p) {
                return p.first == name;
              });
            if (phase == phases.end())
              phases.emplace_back(name, seconds);
            else
              phase->second += seconds;
          }
      }

    private:
      /** The interface's forces ∫[v]·t at u_ghost into force (with the
       * problem's constraints); with @p contact_normal the closed points'
       * normal tractions too. */
      void
      add_interface_forces(const bool contact_normal);


      TrilinosWrappers::SparseMatrix &matrix = linearised.matrix;
      /** The bulk right-hand side (with the active constraints in exact
       * contact), to which each set-up adds the interface's affine part;
       * whether this solve assembled it. */
      TrilinosWrappers::MPI::Vector     bulk_rhs;
      bool                              bulk_rhs_assembled = false;
      typename AMGSolver<dim>::Settings ilu_settings, chebyshev_settings;
      // The kept operator's parts (KeptSlidingOperator).
      std::unique_ptr<Epetra_MultiVector> &modes      = kept.modes;
      TrilinosWrappers::PreconditionAMG   &amg        = kept.amg;
      std::vector<Tensor<2, dim>> &assembled_tangents = kept.assembled_tangents;
      bool                        &assembled          = kept.assembled;
      unsigned int                &assembled_version  = kept.assembled_version;
      bool          &preconditioner_current = kept.preconditioner_current;
      double        &preconditioner_cost    = kept.preconditioner_cost;
      double        &stale_cost             = kept.stale_cost;
      unsigned int  &first_iterations       = kept.first_iterations;
      SolverControl &factorization_control  = kept.factorization_control;
      std::unique_ptr<TrilinosWrappers::SolverDirect> &factorization =
        kept.factorization;
      std::unique_ptr<SparseCholesky>         &cholesky  = kept.cholesky;
      std::unique_ptr<TwoFieldMultigrid<dim>> &multigrid = kept.multigrid;

      /** The preconditioner of the linearised system: the factorisation
       * or the AMG, built afresh if it is not current. */
      void
      set_up_preconditioner();

      /** `automatic` (may_hand_over): the factorisation from the next
       * solve on if the multigrid's second solve on this operator took
       * more than FrictionalSlidingSolver::slow_multigrid_iterations. */
      void
      hand_over_if_slow();

      /** linear_solve() with the multigrid: its levels made again and the
       * solve repeated if kept levels (from an earlier tangent) stall. */
      void
      multigrid_solve(TrilinosWrappers::MPI::Vector &x, const double target);

      /** Solve the linearised system for @p x to the residual @p target
       * by @p Krylov (SolverCG or SolverGMRES) with the preconditioner
       * @p preconditioner, counting its iterations; false if it did not
       * converge in @p max_iterations and @p may_fail. */
      template <typename Krylov, typename Preconditioner>
      bool
      krylov_solve(TrilinosWrappers::MPI::Vector &x,
                   const double                   target,
                   const Preconditioner          &preconditioner,
                   const unsigned int             max_iterations,
                   const bool                     may_fail);
    };

    template <int dim>
    SlidingContext<dim>::SlidingContext(
      const Settings                         &settings,
      const DiscreteProblem<dim>             &problem,
      const FaultInterface<dim>              &faults,
      FaultSlipHistory                       &history,
      SolverReport                           &report,
      const std::function<void(std::string)> &progress,
      KeptSlidingOperator<dim>               &kept)
        : kept(kept)
        , settings(settings)
        , problem(problem)
        , faults(faults)
        , history(history)
        , report(report)
        , progress(progress)
        , dof_handler(problem.dof_handler)
        , fe_space(problem.fe_space)
        , system(problem.system)
        , constraints(problem.system.constraints)
        , communicator(problem.dof_handler.get_communicator())
        , u(problem.system.locally_owned, communicator)
        , u_ghost(problem.system.locally_owned,
                  problem.system.locally_relevant,
                  communicator)
        , residual(problem.system.rhs)
        , force(problem.system.rhs)
    {
      std::vector<double>       distances;
      std::vector<unsigned int> fault_of_point;
      for (const auto &p : faults.interface_quadrature(dof_handler, fe_space))
        {
          distances.push_back(p.distance);
          fault_of_point.push_back(p.fault);
        }
      n_points = distances.size();
      history.reinit(fault_of_point,
                     distances,
                     problem.operator_version >> 32,
                     communicator);
      tangents.resize(n_points);
      affine.resize(n_points);
      responses.resize(n_points);
      normal_jumps.resize(n_points);
      rhs                      = problem.system.rhs;
      linearised.locally_owned = system.locally_owned;
      if (faults.contact() && !contact)
        {
          contact =
            std::make_unique<NormalContact<dim>>(faults,
                                                 dof_handler,
                                                 fe_space,
                                                 system.locally_owned,
                                                 system.locally_relevant);
        }
      // Newton starts from the last solution on this operator (the last
      // time step's) or from a coarser mesh's (start_next_solve_from()),
      // else from zero.
      warm_start =
        settings.method == FrictionalSlidingSolver<dim>::Method::newton &&
        kept.solution.size() == u.size();
      nested_start = warm_start && !kept.assembled;
      if (warm_start)
        u = kept.solution;
      else
        u = 0;
      constraints.distribute(u);
      u_ghost = u;
      f       = std::max(system.rhs.l2_norm(), 1e-300);
      check_right_hand_side(f);
      // A fault's normal spring is far stiffer than the rock next to it
      // (thesis: 1e15 N/m, i.e. k_n l / E h ~ 1e3): it ties the two fields'
      // DoFs at each fault node into stiff pairs, which point smoothers
      // (Chebyshev, Gauss-Seidel) damp poorly -- about 400 GMRES iterations
      // per solve on the normal fault -- and ILU smoothing takes together:
      // 45-55 per solve from 7 k to 416 k DoFs (doc/faults.md). ILU(0) of a
      // sliding tangent can fail, though (the thrust fault): a solve that
      // has not converged after 300 iterations goes on with the Chebyshev
      // smoother. Neither is symmetric here: every solve is GMRES.
      ilu_settings.smoother = "ILU";
      using Solver          = FrictionalSlidingSolver<dim>;
      using Preconditioner  = typename Solver::Preconditioner;
      const Preconditioner chosen =
        Solver::chosen_preconditioner(settings,
                                      faults.contact(),
                                      dof_handler.n_dofs(),
                                      Utilities::MPI::n_mpi_processes(
                                        communicator));
      direct        = chosen == Preconditioner::direct;
      use_multigrid = chosen == Preconditioner::multigrid;
      if (use_multigrid && Solver::hands_over_to_direct(
                             settings,
                             faults.contact(),
                             dof_handler.n_dofs(),
                             Utilities::MPI::n_mpi_processes(communicator)))
        {
          may_hand_over = !kept.multigrid_declined;
          use_multigrid = may_hand_over;
          direct        = !may_hand_over;
        }
      assembled_tangents.resize(n_points);
    }

    template <int dim>
    typename SlidingContext<dim>::Law
    SlidingContext<dim>::stuck_law(const std::vector<double> &slip)
    {
      return [this, &slip](const PointValues &values,
                           Tensor<1, dim>    &t,
                           Tensor<2, dim>    &D) {
        const auto        &p = values.point;
        const unsigned int i = values.index;
        D                    = faults.stuck_tangent(p);
        t                    = D * values.jump -
            faults.friction(p.fault).shear_stiffness * slip[i] * p.shear;
        tangents[i] = D;
        affine[i]   = t - D * values.jump;
      };
    }

    template <int dim>
    void
    SlidingContext<dim>::return_mapping(const PointValues &values,
                                        Tensor<1, dim>    &t,
                                        Tensor<2, dim>    &D)
    {
      const auto           &p = values.point;
      const Tensor<1, dim> &w = values.jump;
      const unsigned int    i = values.index;
      normal_jumps[i]         = w * p.normal;
      responses[i]            = respond(values, history.slip[i]);
      t                       = responses[i].shear_traction * p.shear +
          responses[i].normal_traction * p.normal;
      D = from_local_frame<dim>(responses[i].tangent, p.shear, p.normal);
    }

    template <int dim>
    void
    SlidingContext<dim>::newton_law(const PointValues &values,
                                    Tensor<1, dim>    &t,
                                    Tensor<2, dim>    &D)
    {
      return_mapping(values, t, D);
      // A closed point's normal traction is its constraint's reaction,
      // not a load.
      const unsigned int i = values.index;
      if (contact && contact->exact(i) && contact->closed(i))
        t -= (t * values.point.normal) * values.point.normal;
      tangents[i] = D;
      affine[i]   = t - D * values.jump;
    }

    template <int dim>
    void
    SlidingContext<dim>::add_interface_forces(const bool contact_normal)
    {
      force                                      = 0;
      double                                  ex = 0;
      typename FaultInterface<dim>::FaceTerms terms(fe_space);
      faults.for_each_interface_point(
        dof_handler, fe_space, &u_ghost, [&](const PointValues &values) {
          const unsigned int i = values.index;
          Tensor<1, dim>     t;
          Tensor<2, dim>     D;
          return_mapping(values, t, D);
          // (The law solved with: the tangent, the affine part and the
          // reaction's term, at this point's reaction now.)
          const double reaction_term =
            contact ? coupling.shear_change(i, contact->normal_traction(i))
                    : 0.;
          ex = std::max(ex,
                        std::abs((t - tangents[i] * values.jump - affine[i]) *
                                   values.point.shear -
                                 reaction_term));
          // A closed point's normal traction acts along its tie's normal.
          if (contact && contact->exact(i) && contact->closed(i))
            t = (t * values.point.shear) * values.point.shear +
                (contact_normal ? responses[i].normal_traction : 0.) *
                  contact->normal(i);
          terms.add_traction(values, t);
          if (!values.last_of_pair)
            return;
          constraints.distribute_local_to_global(terms.force,
                                                 values.dofs,
                                                 force);
          terms.clear();
        });
      force.compress(VectorOperation::add);
      excess = Utilities::MPI::max(ex, communicator);
    }

    template <int dim>
    void
    SlidingContext<dim>::contact_tractions(
      const TrilinosWrappers::MPI::Vector &owned)
    {
      u_ghost = owned;
      // (The model's stiffness is read from the linearised matrix: the
      // first residual of a solve comes before its first set-up.)
      if (!assembled)
        assemble_operator();
      kept.strip.vmult(residual, matrix, owned);
      residual -= system.rhs;
      add_interface_forces(false);
      force += residual;
      TrilinosWrappers::MPI::Vector ghosted(system.locally_owned,
                                            system.locally_relevant,
                                            communicator);
      ghosted = force;
      contact->compute_tractions(ghosted);
    }

    template <int dim>
    double
    SlidingContext<dim>::residual_norm(
      const TrilinosWrappers::MPI::Vector &owned)
    {
      Timer timer;
      if (contact)
        {
          // The residual of the tied system, C^T (K u - f + the shear): a
          // tied row's onto the DoFs its tie takes it from. The contact
          // tractions (the ties' reactions) are internal to the ties: the
          // residual does not depend on how they are read from the
          // reactions, which on hanging fault faces is a weighted mean.
          contact_tractions(owned);
          // (Again, after contact_tractions()'s pass: the friction limits
          // take the tractions just read.)
          add_interface_forces(false);
          residual += force;
          condense_ties(residual);
        }
      else
        {
          u_ghost = owned;
          system.matrix.vmult(residual, owned);
          residual -= system.rhs;
          add_interface_forces(true);
          residual += force;
        }
      constraints.set_zero(residual);
      const double norm = residual.l2_norm();
      time_residual += timer.wall_time();
      return norm;
    }

    template <int dim>
    void
    SlidingContext<dim>::condense_ties(TrilinosWrappers::MPI::Vector &r) const
    {
      lithostress::condense_ties(linearised.constraints,
                                 constraints,
                                 system.locally_owned,
                                 system.locally_relevant,
                                 r);
    }

    template <int dim>
    void
    SlidingContext<dim>::assemble_operator()
    {
      if (contact)
        {
          // The old preconditioner refers to the matrix about to be
          // made again: freed first, which also lowers the peak memory.
          if (!cholesky)
            {
              factorization.reset();
              amg.clear();
            }
          contact->assemble_bulk(problem, linearised);
          kept.strip.reinit(problem, faults, linearised.constraints);
          assembled_version = contact->open_set_version();
        }
      else
        {
          matrix.copy_from(system.matrix);
          rhs = system.rhs;
        }
      bulk_rhs           = rhs;
      bulk_rhs_assembled = true;
      // The matrix was made again (with the sparsity of the new
      // constraints): the AMG and Amesos refer to the old one; a
      // Cholesky factor is the preconditioner's own.
      if (!cholesky)
        preconditioner_current = false;
      std::fill(assembled_tangents.begin(),
                assembled_tangents.end(),
                Tensor<2, dim>());
      assembled = true;
    }

    template <int dim>
    void
    SlidingContext<dim>::set_up(const Law &law)
    {
      Timer      timer;
      const bool fresh =
        !assembled ||
        (contact && contact->open_set_version() != assembled_version);
      if (fresh)
        assemble_operator();
      else if (!bulk_rhs_assembled)
        {
          // A new solve on the kept operator: only its right-hand side.
          if (contact)
            contact->assemble_bulk_rhs(problem, linearised);
          else
            rhs = system.rhs;
          bulk_rhs           = rhs;
          bulk_rhs_assembled = true;
        }
      reset_rhs();
      // The matrix gets the change of the interface tangent, the
      // right-hand side the whole affine part (and the whole tangent's
      // share of the constraints' inhomogeneities).
      typename FaultInterface<dim>::FaceTerms terms(fe_space), change(fe_space);
      faults.for_each_interface_point(
        dof_handler, fe_space, &u_ghost, [&](const PointValues &values) {
          Tensor<1, dim> t;
          Tensor<2, dim> D;
          law(values, t, D);
          terms.add_tangent(values, D);
          terms.add_affine(values, t - D * values.jump);
          change.add_tangent(values, D - assembled_tangents[values.index]);
          assembled_tangents[values.index] = D;
          if (!values.last_of_pair)
            return;
          active_constraints().distribute_local_to_global(change.matrix,
                                                          values.dofs,
                                                          matrix);
          if (contact)
            kept.strip.add_interface_tangent(change.matrix,
                                             values.dofs,
                                             active_constraints());
          active_constraints().distribute_local_to_global(terms.rhs,
                                                          values.dofs,
                                                          rhs,
                                                          terms.matrix);
          terms.clear();
          change.clear();
        });
      matrix.compress(VectorOperation::add);
      if (contact)
        kept.strip.compress();
      rhs.compress(VectorOperation::add);
      time_assembly += timer.wall_time();
      // A kept preconditioner (the factorisation, or the multigrid's
      // Galerkin levels and smoothers) was made from an earlier tangent,
      // which differs from this one only at the fault: it is made again
      // once its extra iterations cost more than making it
      // (linear_solve()).
      if (!preconditioner_current)
        set_up_preconditioner();
    }

    template <int dim>
    void
    SlidingContext<dim>::set_up_preconditioner()
    {
      Timer timer;
      if (use_multigrid)
        {
          if (!multigrid)
            {
              multigrid = std::make_unique<TwoFieldMultigrid<dim>>();
              multigrid->make_hierarchy(dof_handler, fe_space.fe_collection());
            }
          typename TwoFieldMultigrid<dim>::Settings smoothing;
          smoothing.smoother_degree   = settings.smoother_degree;
          smoothing.fault_zone_layers = settings.fault_zone_layers;
          multigrid->initialize(matrix, active_constraints(), smoothing);
        }
      else if (direct)
        {
          // Exact contact's tangent is symmetric: on one rank its
          // Cholesky factor, else an LU factorisation (Amesos KLU).
          if (contact && Utilities::MPI::n_mpi_processes(communicator) == 1)
            {
              if (!cholesky)
                cholesky = std::make_unique<SparseCholesky>();
              cholesky->factorize(matrix);
            }
          else
            {
              factorization = std::make_unique<TrilinosWrappers::SolverDirect>(
                factorization_control);
              factorization->initialize(matrix);
            }
        }
      else
        {
          if (!modes)
            modes = make_rigid_body_modes(dof_handler,
                                          fe_space,
                                          matrix.trilinos_matrix().DomainMap());
          // Exact contact leaves a symmetric tangent without stiff springs:
          // the elasticity AMG with its Chebyshev smoother, as for a locked
          // fault.
          initialize_elasticity_amg<dim>(amg,
                                         matrix,
                                         *modes,
                                         contact ? chebyshev_settings
                                                 : ilu_settings,
                                         true);
        }
      preconditioner_current = true;
      preconditioner_cost    = timer.wall_time();
      stale_cost             = 0;
      first_iterations       = numbers::invalid_unsigned_int;
      time_preconditioner += preconditioner_cost;
    }

    template <int dim>
    void
    SlidingContext<dim>::couple_friction_limits(const bool newton)
    {
      if (!newton || !contact || !settings.reaction_in_tangent)
        {
          coupling.clear();
          return;
        }
      coupling.reinit(faults,
                      dof_handler,
                      fe_space,
                      *contact,
                      responses,
                      kept.strip.model_rows(),
                      linearised.constraints,
                      system.locally_owned,
                      system.locally_relevant);
      // L x + M (x − u) = b: the reactions' change from u's.
      coupling.vmult_add(rhs, u);
    }

    template <int dim>
    void
    SlidingContext<dim>::assemble_rhs(const Law &law)
    {
      reset_rhs();
      typename FaultInterface<dim>::FaceTerms terms(fe_space);
      faults.for_each_interface_point(
        dof_handler, fe_space, nullptr, [&](const PointValues &values) {
          Tensor<1, dim> t;
          Tensor<2, dim> D;
          law(values, t, D);
          terms.add_tangent(values, D);
          terms.add_affine(values, t - D * values.jump);
          if (!values.last_of_pair)
            return;
          // The tangent only for the constraints' inhomogeneities.
          active_constraints().distribute_local_to_global(terms.rhs,
                                                          values.dofs,
                                                          rhs,
                                                          terms.matrix);
          terms.clear();
        });
      rhs.compress(VectorOperation::add);
    }

    /** A factorisation as a preconditioner: its solve. */
    class FactorisationPreconditioner
    {
    public:
      explicit FactorisationPreconditioner(
        TrilinosWrappers::SolverDirect &factorization)
          : factorization(factorization)
      {
      }

      void
      vmult(TrilinosWrappers::MPI::Vector       &dst,
            const TrilinosWrappers::MPI::Vector &src) const
      {
        factorization.solve(dst, src);
      }

    private:
      TrilinosWrappers::SolverDirect &factorization;
    };

    template <int dim>
    template <typename Krylov, typename Preconditioner>
    bool
    SlidingContext<dim>::krylov_solve(TrilinosWrappers::MPI::Vector &x,
                                      const double                   target,
                                      const Preconditioner &preconditioner,
                                      const unsigned int    max_iterations,
                                      const bool            may_fail)
    {
      SolverControl control(max_iterations, target, false, false);
      try
        {
          // GMRES with right preconditioning measures the true residual,
          // which the tolerance refers to.
          typename Krylov::AdditionalData data;
          if constexpr (std::is_same_v<
                          Krylov,
                          SolverGMRES<TrilinosWrappers::MPI::Vector>>)
            data = typename Krylov::AdditionalData(100, true);
          Krylov solver(control, data);
          stop_on_signal(solver, communicator);
          if (coupling.active())
            solver.solve(CoupledTangent<dim>{matrix, coupling},
                         x,
                         rhs,
                         preconditioner);
          else
            solver.solve(matrix, x, rhs, preconditioner);
        }
      catch (const SolverControl::NoConvergence &exc)
        {
          report.iterations += exc.last_step;
          if (may_fail && !interruption::signal_on_any_rank(communicator))
            return false;
          rethrow_solver_failure(
            exc,
            communicator,
            std::string(symmetric() ? "CG" : "GMRES") + " with " +
              (use_multigrid ? "multigrid"
               : direct      ? "a factorisation"
                             : "AMG"),
            rhs.l2_norm(),
            "raise Faults/Sliding solver/Linear solver tolerance");
        }
      report.iterations += iterations_of(control);
      last_iterations = iterations_of(control);
      // The Krylov basis goes back to the system, not to deal.II's pool:
      // held in the pool it would add to the residual's temporaries after
      // the solve, and that sum was the run's peak memory.
      GrowingVectorMemory<
        TrilinosWrappers::MPI::Vector>::release_unused_memory();
      return true;
    }

    template <int dim>
    void
    SlidingContext<dim>::multigrid_solve(TrilinosWrappers::MPI::Vector &x,
                                         const double                   target)
    {
      using CG    = SolverCG<TrilinosWrappers::MPI::Vector>;
      using GMRES = SolverGMRES<TrilinosWrappers::MPI::Vector>;
      // Levels kept from an earlier tangent (first_iterations known) get
      // a few times their first solve's iterations; a stiffened fault point
      // can leave their smoothers' eigenvalue bounds behind.
      const bool kept_levels =
        first_iterations != numbers::invalid_unsigned_int;
      const unsigned int limit =
        kept_levels ? std::max(50U, 4 * first_iterations) : 5000;
      const auto solve = [&](const unsigned int iterations,
                             const bool         may_fail) {
        if (symmetric())
          return krylov_solve<CG>(x, target, *multigrid, iterations, may_fail);
        return krylov_solve<GMRES>(x, target, *multigrid, iterations, may_fail);
      };
      if (solve(limit, kept_levels))
        return;
      // Continued from where the kept levels stalled (GMRES's iterate has
      // a smaller residual than its start, CG's a smaller error in the
      // energy norm; no copy of the start is held, a vector at the solve's
      // peak memory).
      progress("  sliding: the kept multigrid levels stalled; made again");
      set_up_preconditioner();
      solve(5000, false);
    }

    template <int dim>
    void
    SlidingContext<dim>::linear_solve(TrilinosWrappers::MPI::Vector &x)
    {
      Timer        timer;
      const double target =
        std::max(settings.linear_tolerance * rhs.l2_norm(), forcing);
      to_tolerance = forcing <= settings.linear_tolerance * rhs.l2_norm();
      using CG     = SolverCG<TrilinosWrappers::MPI::Vector>;
      using GMRES  = SolverGMRES<TrilinosWrappers::MPI::Vector>;
      if (use_multigrid)
        multigrid_solve(x, target);
      else if (cholesky && symmetric())
        krylov_solve<CG>(x, target, *cholesky, 5000, false);
      else if (cholesky)
        krylov_solve<GMRES>(x, target, *cholesky, 5000, false);
      else if (direct)
        {
          const FactorisationPreconditioner p(*factorization);
          if (symmetric())
            krylov_solve<CG>(x, target, p, 5000, false);
          else
            krylov_solve<GMRES>(x, target, p, 5000, false);
        }
      else if (contact && symmetric())
        krylov_solve<CG>(x, target, amg, 5000, false);
      else if (contact)
        krylov_solve<GMRES>(x, target, amg, 5000, false);
      else if (!krylov_solve<GMRES>(x, target, amg, 300, true))
        {
          // ILU(0) of a sliding tangent can fail (the thrust fault).
          progress("  sliding: GMRES with ILU smoothing stalled; continuing "
                   "with Chebyshev smoothing");
          initialize_elasticity_amg<dim>(
            amg, matrix, *modes, chebyshev_settings, true);
          krylov_solve<GMRES>(x, target, amg, 5000, false);
        }
      active_constraints().distribute(x);
      ++report.linear_solves;
      const double seconds = timer.wall_time();
      time_solve += seconds;
      // The iterations beyond the first solve's are the price of keeping
      // the preconditioner; once they cost more than making it, it is made
      // again. (The ILU smoothing of the spring is made for each tangent.)
      if (first_iterations == numbers::invalid_unsigned_int)
        first_iterations = last_iterations;
      stale_cost +=
        seconds *
        (last_iterations - std::min(last_iterations, first_iterations)) /
        (last_iterations + 1.);
      // (Decided on rank 0's clock: every rank must make it again or none.)
      if (Utilities::MPI::broadcast(communicator,
                                    stale_cost > preconditioner_cost) ||
          (!contact && !direct))
        preconditioner_current = false;
      if (may_hand_over)
        hand_over_if_slow();
    }

    template <int dim>
    void
    SlidingContext<dim>::hand_over_if_slow()
    {
      // Judged at the second solve: the first is often the elastic
      // predictor, every point stuck, which any fault's multigrid solves
      // as fast as a locked fault's.
      if (++kept.multigrid_solves < 2)
        return;
      may_hand_over = false;
      using Solver  = FrictionalSlidingSolver<dim>;
      if (last_iterations <= Solver::slow_multigrid_iterations)
        return;
      progress("  sliding: the multigrid took " +
               std::to_string(last_iterations) +
               " iterations; the kept factorisation from here on");
      kept.multigrid_declined = true;
      use_multigrid           = false;
      direct                  = true;
      multigrid.reset();
      preconditioner_current = false;
    }

    template <int dim>
    std::string
    SlidingContext<dim>::count_states() const
    {
      unsigned int n[3] = {0, 0, 0};
      for (const auto &r : responses)
        ++n[static_cast<int>(r.state)];
      std::ostringstream out;
      out << Utilities::MPI::sum(n[1], communicator) << " sliding, "
          << Utilities::MPI::sum(n[2], communicator) << " open of "
          << Utilities::MPI::sum(n_points, communicator) << " points";
      return out.str();
    }

    /**
     * The semi-smooth Newton method (FrictionalSlidingSolver's `newton`,
     * replacing thesis §5.5's iteration): the elastic predictor, then
     * Newton steps with the return mapping's consistent tangent and a
     * backtracking line search on the residual norm. Returns whether the
     * residual and the excess shear fell below their tolerances; @p c
     * holds the last iterate.
     */
    template <int dim>
    bool
    solve_by_newton(SlidingContext<dim> &c)
    {
      using PointValues    = typename SlidingContext<dim>::PointValues;
      const auto &settings = c.settings;
      // x: the linear solve's solution, then the step from c.u (one
      // vector fewer at the solves' peak memory).
      TrilinosWrappers::MPI::Vector x(c.u), trial(c.u);
      c.start_contact_from_iterate();
      c.r_norm = c.residual_norm(c.u);
      if (c.nested_start)
        {
          std::ostringstream line;
          line << "  sliding: Newton starts from "
               << (c.kept.predicted_start ? "the last steps' extrapolation"
                                          : "the last mesh's solution")
               << ": residual " << std::setprecision(3) << c.r_norm / c.f
               << ", " << c.count_states();
          c.progress(line.str());
        }
      // Whether the last iteration changed exact contact's open nodes (the
      // next step satisfies other constraints than the iterate, and is
      // taken whole), and whether it changed them or a point's state.
      bool set_changed = false, changed = c.states_changed_since_converged();
      const double start_norm = c.r_norm;
      for (c.iteration = 1; c.iteration <= settings.max_iterations;
           ++c.iteration)
        {
          // The elastic predictor (every point stuck), unless the last
          // solution's states are the guess.
          const bool predictor = c.iteration == 1 && !c.warm_start;
          if (predictor)
            c.set_up(c.stuck_law(c.history.slip));
          else
            c.set_up([&c](const PointValues &values,
                          Tensor<1, dim>    &t,
                          Tensor<2, dim> &D) { c.newton_law(values, t, D); });
          c.couple_friction_limits(!predictor);
          // Inexact while the states change or the friction limits follow
          // the reactions (each step then reduces the residual by the fixed
          // point's contraction only); once neither holds the step may be
          // the last one (the law is piecewise linear), and is solved to
          // the Linear solver tolerance.
          x         = c.u;
          c.forcing = changed || c.limits_follow_reactions()
                        ? settings.linear_reduction * c.r_norm
                        : 0.;
          c.linear_solve(x);
          x -= c.u;
          double alpha = 1, trial_norm = 0;
          for (unsigned int halving = 0;; ++halving)
            {
              trial = c.u;
              trial.add(alpha, x);
              trial_norm = c.residual_norm(trial);
              if (!settings.line_search ||
                  (c.iteration == 1 && !c.warm_start) || set_changed ||
                  trial_norm <= (1 - 1e-4 * alpha) * c.r_norm || halving == 6)
                break;
              alpha /= 2;
            }
          const double previous_norm = c.r_norm;
          c.u                        = trial;
          c.r_norm                   = trial_norm;
          set_changed                = c.update_active_set();
          changed                    = c.states_changed() || set_changed;
          if (!std::isfinite(c.r_norm))
            throw ComputationError(
              "the Newton iteration for the sliding on " +
              c.faults.frictional_names() +
              " produced a residual that is not finite in iteration " +
              std::to_string(c.iteration));
          std::ostringstream line;
          line << "  sliding: Newton iteration " << c.iteration << ": residual "
               << std::setprecision(3) << c.r_norm / c.f << ", excess shear "
               << c.excess << " Pa, " << c.count_states() << ", "
               << c.last_iterations << " linear iterations"
               << (alpha < 1 ? ", step " + std::to_string(alpha) : "");
          c.progress(line.str());
          if (c.r_norm <= settings.residual_tolerance * c.f &&
              c.excess <= settings.excess_shear_tolerance && !set_changed)
            return true;
          // The friction limits' coupling to the reactions can send the
          // active set astray, each whole step opening more of the fault
          // (the listric normal fault at 1.32 M DoFs: 23 open points at
          // 1.3e-4 of the load, then 41, 52, 62 ... at 3, 5, 28 times the
          // load, with the factor and the multigrid alike), where the fixed
          // point in the reactions converges. An iterate twice as far from
          // equilibrium as the start, past the first few steps, ends it.
          if (c.coupling.active() && c.iteration > 4 &&
              c.r_norm > 2 * start_norm)
            {
              c.diverged = true;
              return false;
            }
          // The states stood still and the step was solved to the Linear
          // solver tolerance, yet the step did not halve the residual: it
          // is at the round-off of the linear solves (1.65 M DoFs on 2
          // ranks with CG + AMG: 1.04e-9, 1.03e-9, 1.03e-9 of the load).
          // Within 100 times the tolerance that is the solution.
          if (!changed && c.to_tolerance &&
              c.excess <= settings.excess_shear_tolerance &&
              c.r_norm > 0.5 * previous_norm &&
              c.r_norm <= 100 * settings.residual_tolerance * c.f)
            {
              std::ostringstream note;
              note << std::setprecision(3)
                   << "  sliding: the residual stopped falling at "
                   << c.r_norm / c.f
                   << " of the load (the linear solves' round-off): "
                      "converged";
              c.progress(note.str());
              return true;
            }
          c.accelerate_tractions(changed);
        }
      return false;
    }

    /** c.u_ghost := c.u, and in exact contact the normal tractions of c.u:
     * what the thesis iteration's excess shear is read from. */
    template <int dim>
    void
    read_iterate(SlidingContext<dim> &c)
    {
      if (c.contact)
        c.contact_tractions(c.u);
      else
        c.u_ghost = c.u;
    }

    /** The shear @p tau beyond the friction limit @p limit, signed as
     * @p tau (FSHEAR's STEXS = SHAV -+ FRS); negative where |tau| is below
     * the limit (a point held at it). */
    inline double
    beyond_limit(const double tau, const double limit)
    {
      return tau - (tau < 0 ? -1 : 1) * limit;
    }

    /**
     * FSHEAR's step at point @p i: the excess @p e moved into @p slip times
     * the convergence factor (nodal forces e through the spring k_s);
     * @p slid marks the point if e moves it; at the first iteration a
     * point @p over the limit is @p held there from then on (Hold sliding
     * points at the limit); its state in c.responses follows.
     */
    template <int dim>
    void
    move_excess_into_slip(SlidingContext<dim> &c,
                          const unsigned int   i,
                          const double         e,
                          const bool           over,
                          const double         shear_stiffness,
                          std::vector<double> &slip,
                          std::vector<bool>   &slid,
                          std::vector<bool>   &held)
    {
      if (c.iteration == 1 && c.settings.hold_at_limit && over)
        held[i] = true;
      if (e != 0)
        slid[i] = true;
      slip[i] += c.settings.convergence_factor * e / shear_stiffness;
      SlipState &state = c.responses[i].state;
      state            = state == SlipState::open ? SlipState::open
                         : slid[i]                ? SlipState::sliding
                                                  : SlipState::stuck;
    }

    /**
     * The largest excess shear over the friction limit at the elastic
     * traction of c.u (thesis §5.5, FSHEAR), moved into @p slip times the
     * convergence factor; @p slid marks the points that ever slid, @p held
     * those held at the limit (Hold sliding points at the limit).
     * c.responses get the states.
     */
    template <int dim>
    double
    thesis_excess_shear(SlidingContext<dim> &c,
                        std::vector<double> &slip,
                        std::vector<bool>   &slid,
                        std::vector<bool>   &held)
    {
      using PointValues = typename SlidingContext<dim>::PointValues;
      read_iterate(c);
      double ex = 0;
      c.faults.for_each_interface_point(
        c.dof_handler, c.fe_space, &c.u_ghost, [&](const PointValues &values) {
          const auto           &p = values.point;
          const Tensor<1, dim> &w = values.jump;
          const unsigned int    i = values.index;
          // The excess over the limit at the elastic traction.
          const CoulombFriction     &law = c.faults.friction(p.fault);
          CoulombFriction::Response &r   = c.responses[i];
          r                              = c.respond(values, slip[i]);
          const double tau = law.shear_stiffness * (w * p.shear - slip[i]);
          const double e   = r.state == SlipState::open ? tau
                             : r.state == SlipState::sliding || held[i]
                               ? beyond_limit(tau, r.friction_limit)
                               : 0.;
          ex               = std::max(ex, std::abs(e));
          move_excess_into_slip(c,
                                i,
                                e,
                                r.state == SlipState::sliding,
                                law.shear_stiffness,
                                slip,
                                slid,
                                held);
        });
      return Utilities::MPI::max(ex, c.communicator);
    }

    /**
     * As thesis_excess_shear(), with FSHEAR's reading of the stresses
     * (FaultElementStresses): one excess per face pair, from the shear and
     * effective normal stress of its two cells' centroids, moved into the
     * slip of all of its points.
     */
    template <int dim>
    double
    thesis_element_excess_shear(SlidingContext<dim>       &c,
                                FaultElementStresses<dim> &elements,
                                std::vector<double>       &slip,
                                std::vector<bool>         &slid,
                                std::vector<bool>         &held)
    {
      using PointValues = typename SlidingContext<dim>::PointValues;
      read_iterate(c);
      double                    ex = 0;
      std::vector<unsigned int> face;
      Point<dim>                first;
      c.faults.for_each_interface_point(
        c.dof_handler, c.fe_space, &c.u_ghost, [&](const PointValues &values) {
          const unsigned int i = values.index;
          if (face.empty())
            first = values.point.position;
          face.push_back(i);
          c.responses[i] = c.respond(values, slip[i]);
          if (!values.last_of_pair)
            return;
          const Point<dim> midpoint = 0.5 * (first + values.point.position);
          const auto       r = elements.read(values, midpoint, c.u_ghost);
          const CoulombFriction &law = c.faults.friction(values.point.fault);
          const double           limit =
            law.friction_coefficient * std::max(0., -r.effective_normal);
          const bool   over = std::abs(r.shear) > limit;
          const double e =
            over || held[face[0]] ? beyond_limit(r.shear, limit) : 0.;
          ex = std::max(ex, std::abs(e));
          for (const unsigned int j : face)
            move_excess_into_slip(
              c, j, e, over, law.shear_stiffness, slip, slid, held);
          face.clear();
        });
      return Utilities::MPI::max(ex, c.communicator);
    }

    /**
     * The thesis's iteration (thesis §5.5, FSHEAR; FrictionalSlidingSolver's
     * `thesis`): the fault stays elastic in the matrix (set up once), its
     * excess shear moves into the slip, re-solved until the excess shear
     * is below its tolerance. Returns whether it was; throws
     * ComputationError if the excess shear grows by orders of magnitude
     * (thesis §6.1.5). @p c holds the last iterate, with the residual of
     * the thesis's last states.
     */
    template <int dim>
    bool
    solve_by_thesis_iteration(SlidingContext<dim> &c)
    {
      const auto         &settings = c.settings;
      std::vector<double> slip     = c.history.slip;
      std::vector<bool>   slid(c.n_points, false), held(c.n_points, false);
      std::unique_ptr<FaultElementStresses<dim>> elements;
      if (settings.element_stresses)
        elements =
          std::make_unique<FaultElementStresses<dim>>(c.fe_space,
                                                      c.problem.stress_model,
                                                      c.faults);
      bool converged = false;
      c.set_up(c.stuck_law(slip));
      double first_excess = 0;
      for (c.iteration = 1; c.iteration <= settings.max_iterations;
           ++c.iteration)
        {
          if (c.iteration > 1)
            c.assemble_rhs(c.stuck_law(slip));
          c.linear_solve(c.u);
          c.excess =
            elements
              ? thesis_element_excess_shear(c, *elements, slip, slid, held)
              : thesis_excess_shear(c, slip, slid, held);
          if (c.iteration == 1)
            first_excess = c.excess;
          // Growing by orders of magnitude, or overflowing: the factor is
          // too large for this stiffness (thesis §6.1.5).
          if (!std::isfinite(c.excess) || c.excess > 1e3 * first_excess)
            {
              std::ostringstream what;
              what << std::setprecision(3)
                   << "the thesis iteration for the sliding on "
                   << c.faults.frictional_names()
                   << " diverges: the excess shear grew from " << first_excess
                   << " Pa to " << c.excess << " Pa in " << c.iteration
                   << " iterations; lower Faults/Sliding solver/Convergence "
                      "factor (now "
                   << settings.convergence_factor << ")";
              c.report.nonlinear_iterations = c.iteration;
              throw ComputationError(what.str());
            }
          std::ostringstream line;
          line << "  sliding: thesis iteration " << c.iteration
               << ": excess shear " << std::setprecision(3) << c.excess
               << " Pa, " << c.count_states();
          if (c.iteration == 1 || c.iteration % 50 == 0 ||
              c.excess <= settings.excess_shear_tolerance)
            c.progress(line.str());
          if (c.excess <= settings.excess_shear_tolerance)
            {
              converged = true;
              break;
            }
        }
      // The residual with the states of the thesis's last iterate.
      const std::vector<CoulombFriction::Response> thesis = c.responses;
      c.r_norm    = c.residual_norm(c.u);
      c.responses = thesis;
      return converged;
    }
  } // namespace

  template <int dim>
  void
  FrictionalSlidingSolver<dim>::solve(
    const DiscreteProblem<dim>             &problem,
    const FaultInterface<dim>              &faults,
    FaultSlipHistory                       &history,
    TrilinosWrappers::MPI::Vector          &solution,
    SolverReport                           &report,
    const std::function<void(std::string)> &progress)
  {
    const bool newton    = parameters.method == Method::newton;
    report               = SolverReport();
    report.solver        = newton ? "newton" : "thesis";
    report.linear_solves = 0;
    Timer timer(problem.dof_handler.get_communicator(), true);
    if (!kept || !kept->made_for(problem))
      kept = std::make_unique<KeptSlidingOperator<dim>>(
        problem, TrilinosWrappers::MPI::Vector());
    // Newton starts from a coarser mesh's solution (nested iteration), or
    // in the time loop from the last steps' extrapolation
    // (SolutionPredictor), or from the kept operator's last solution.
    kept->predicted_start = false;
    if (next_start.size() == problem.dof_handler.n_dofs())
      kept->solution = next_start;
    else if (problem.initial_guess != nullptr && newton)
      {
        kept->solution        = *problem.initial_guess;
        kept->predicted_start = true;
      }
    next_start.clear();
    Settings                             settings = parameters;
    const TrilinosWrappers::MPI::Vector  start    = kept->solution;
    std::unique_ptr<SlidingContext<dim>> context;
    bool                                 converged           = false;
    unsigned int                         diverged_iterations = 0;
    for (;;)
      {
        context = std::make_unique<SlidingContext<dim>>(
          settings, problem, faults, history, report, progress, *kept);
        try
          {
            converged = newton ? solve_by_newton(*context)
                               : solve_by_thesis_iteration(*context);
          }
        catch (...)
          {
            // The kept operator may be half updated.
            context.reset();
            kept.reset();
            throw;
          }
        if (!context->diverged)
          break;
        std::ostringstream line;
        line << std::setprecision(3)
             << "  sliding: Newton with the reaction in the tangent diverged "
                "(residual "
             << context->r_norm / context->f << " of the load in iteration "
             << context->iteration
             << "); solving again with the reactions taken as given";
        progress(line.str());
        diverged_iterations += context->iteration;
        context->add_phase_times(report.phases);
        // Afresh from the start: the kept operator holds the diverged
        // active set.
        context.reset();
        kept = std::make_unique<KeptSlidingOperator<dim>>(problem, start);
        settings.reaction_in_tangent = false;
      }
    SlidingContext<dim> &c = *context;
    // The last iterate's slip and states: the trial history, committed by
    // the caller (or, if not converged, shown).
    for (unsigned int i = 0; i < c.n_points; ++i)
      {
        history.trial_slip[i]      = c.responses[i].plastic_slip;
        history.trial_states[i]    = c.responses[i].state;
        history.normal_traction[i] = c.responses[i].normal_traction;
      }
    report.nonlinear_iterations =
      diverged_iterations + std::min(c.iteration, parameters.max_iterations);
    report.final_residual = c.r_norm / c.f;
    report.solve_time     = timer.wall_time();
    report.memory_bytes   = c.preconditioner_memory();
    c.add_phase_times(report.phases);
    solution = c.u;
    if (converged && newton)
      {
        kept->solution = c.u;
        kept->converged_states.resize(c.n_points);
        for (unsigned int i = 0; i < c.n_points; ++i)
          kept->converged_states[i] = c.responses[i].state;
        kept->has_converged_states = true;
      }
    if (!converged)
      {
        std::ostringstream what;
        what << std::setprecision(3) << "the frictional sliding on "
             << faults.frictional_names() << " did not converge in "
             << parameters.max_iterations << " " << report.solver
             << " iterations (residual " << c.r_norm / c.f
             << " of the load, excess "
             << "shear " << c.excess
             << " Pa); the last iterate is written out. Raise Faults/Sliding "
                "solver/Maximum iterations"
             << (newton ? ""
                        : ", or change the Convergence factor (raise it "
                          "while the excess shear falls steadily, lower it "
                          "where it oscillates near the factor at which the "
                          "iteration diverges)");
        throw ComputationError(what.str());
      }
  }

  template <int dim>
  FrictionalSlidingSolver<dim>::FrictionalSlidingSolver() = default;

  template <int dim>
  FrictionalSlidingSolver<dim>::~FrictionalSlidingSolver() = default;

  template <int dim>
  typename FrictionalSlidingSolver<dim>::Preconditioner
  FrictionalSlidingSolver<dim>::chosen_preconditioner(
    const Settings               &settings,
    const bool                    contact,
    const types::global_dof_index n_dofs,
    const unsigned int            n_ranks)
  {
    if (settings.preconditioner != Preconditioner::automatic)
      return settings.preconditioner;
    if (n_ranks == 1 && n_dofs <= settings.direct_limit &&
        (!contact || n_dofs <= settings.multigrid_limit))
      return Preconditioner::direct;
    // The two fields' multigrid where no factorisation is taken, in exact
    // contact (the spring's stiff pairs need the AMG's ILU smoothing): on
    // 2 ranks the thrust fault at 106 k DoFs took 7.5 s with it (206 CG
    // iterations) against 15.7 s with the AMG (1 138).
    return contact ? Preconditioner::multigrid : Preconditioner::amg;
  }

  template <int dim>
  bool
  FrictionalSlidingSolver<dim>::hands_over_to_direct(
    const Settings               &settings,
    const bool                    contact,
    const types::global_dof_index n_dofs,
    const unsigned int            n_ranks)
  {
    return settings.preconditioner == Preconditioner::automatic && contact &&
           n_ranks == 1 && n_dofs > settings.multigrid_limit &&
           n_dofs <= settings.direct_limit;
  }

  template class FrictionalSlidingSolver<2>;
} // namespace lithostress

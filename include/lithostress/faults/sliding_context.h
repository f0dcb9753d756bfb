#ifndef lithostress_faults_sliding_context_h
#define lithostress_faults_sliding_context_h

// The parts of FrictionalSlidingSolver that its source files share
// (faults/frictional_sliding_solver.h is the interface): the operator kept
// between solves, the context of one solve, and the two methods. Included
// only by source/faults/frictional_sliding_*.cc and sliding_*.cc.

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
#include <lithostress/solvers/newton_method.h>
#include <lithostress/solvers/rigid_body_modes.h>
#include <lithostress/solvers/sparse_cholesky.h>
#include <lithostress/solvers/two_field_multigrid.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace lithostress
{
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
     * is kept until the iterations its solves have taken beyond those of
     * its first solve outnumber what making it costs, counted in the same
     * iterations (SlidingContext::set_up_in_iterations()). Counts, not
     * clocks: every run, build and rank decides alike. */
    bool preconditioner_current = false;
    /** What making the kept preconditioner cost in iterations of its
     * Krylov solves, the iterations beyond those of its first solve since
     * it was made, and the iterations of that first solve. */
    double        setup_iterations = 0;
    unsigned int  stale_iterations = 0;
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

  namespace sliding
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
                     FaultHistory                           &history,
                     SolverReport                           &report,
                     const std::function<void(std::string)> &progress,
                     KeptSlidingOperator<dim>               &kept);

      /** Each point's history, by its index: the committed one, or the
       * thesis iteration's slip. */
      using HistoryOf = std::function<ArrayView<const double>(unsigned int)>;

      /** The laws' elastic predictor (InterfaceLaw::predictor()) with the
       * history @p history per point (thesis §5.5: the fault stays
       * elastic, its slip moves the springs' rest length), recorded as the
       * law the next solve linearises. */
      Law
      stuck_law(const HistoryOf &history);

      /** The laws' return mapping from the committed history at the point
       * @p values, its response kept. */
      void
      return_mapping(const PointValues &values,
                     Tensor<1, dim>    &t,
                     Tensor<2, dim>    &D);

      /** The law of the point @p values evaluated from the history
       * @p history (InterfaceLaw::evaluate()), with the point's reaction
       * in exact contact. */
      InterfaceResponse
      respond(const PointValues             &values,
              const ArrayView<const double> &history) const
      {
        const auto        &p  = values.point;
        InterfaceLawInputs in = FaultInterface<dim>::law_inputs(
          p, values.jump, history, problem.stress_model.time_step());
        if (!p.at_tip && contact && contact->exact(values.index))
          {
            in.in_contact       = true;
            in.closed           = contact->closed(values.index);
            in.contact_traction = contact->normal_traction(values.index);
          }
        return faults.law(p.fault).evaluate(in);
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
       * and its preconditioner; with @p check_blocks, check_blocks_held()
       * on the new tangent before the preconditioner is made (a
       * factorisation of a singular system fails without saying why). */
      void
      set_up(const Law &law, const bool check_blocks = false);

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

      /** Throw a ComputationError (on every rank) if the faults' tangents
       * of the last set_up() and the active constraints leave a block of
       * the body free to move as a rigid body (RigidBodySupport over the
       * blocks the faults cut, each point holding its two blocks with its
       * tangent): the linearised system is then singular, and no Krylov
       * solve can end it (a graben whose faults carry no normal stress,
       * their points open or sliding freely). */
      void
      check_blocks_held() const;

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
      FaultHistory                           &history;
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
      std::vector<Tensor<2, dim>>    tangents;
      std::vector<Tensor<1, dim>>    affine;
      std::vector<InterfaceResponse> responses;
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
       * was another mesh's (start_next_solve_from()), on this new operator.
       */
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
      double        &setup_iterations       = kept.setup_iterations;
      unsigned int  &stale_iterations       = kept.stale_iterations;
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

      /** What making the preconditioner now held costs in iterations of
       * its Krylov solve: for the Cholesky factor a multiple of its flops
       * over a CG iteration's (SparseCholesky::factorization_in_solves()),
       * for the AMG, the two fields' multigrid and the LU factorisation of
       * several ranks a measured ratio (doc/faults.md, "Preconditioners").
       * A count, so that every run, build and rank decides alike. */
      double
      set_up_in_iterations() const;

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


    /** The semi-smooth Newton method for the sliding (doc/faults.md):
     * true if it converged. */
    template <int dim>
    bool
    solve_by_newton(SlidingContext<dim> &c);

    /** The Newton method of the sliding on @p c's faults: its settings
     * from c.settings, its messages naming them. */
    template <int dim>
    NewtonMethod<TrilinosWrappers::MPI::Vector>
    newton_method(const SlidingContext<dim> &c);

    /** The thesis's iteration (§5.5, FSHEAR): true if it converged. */
    template <int dim>
    bool
    solve_by_thesis_iteration(SlidingContext<dim> &c);
  } // namespace sliding
} // namespace lithostress

#endif

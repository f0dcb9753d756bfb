#include <lithostress/faults/sliding_context.h>

namespace lithostress
{
  namespace sliding
  {
    namespace
    {
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
    } // namespace

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
      // the preconditioner; once they outnumber what making it costs in
      // iterations, it is made again. (The ILU smoothing of the spring is
      // made for each tangent.)
      if (first_iterations == numbers::invalid_unsigned_int)
        first_iterations = last_iterations;
      stale_iterations +=
        last_iterations - std::min(last_iterations, first_iterations);
      if (stale_iterations > setup_iterations || (!contact && !direct))
        preconditioner_current = false;
      if (may_hand_over)
        hand_over_if_slow();
    }


    template void
    SlidingContext<2>::multigrid_solve(TrilinosWrappers::MPI::Vector &,
                                       const double);
    template void
    SlidingContext<2>::linear_solve(TrilinosWrappers::MPI::Vector &);
  } // namespace sliding
} // namespace lithostress

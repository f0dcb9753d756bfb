#include <deal.II/base/timer.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <lithostress/base/input_error.h>
#include <lithostress/base/interruption.h>
#include <lithostress/base/parameter_file.h>
#include <lithostress/faults/frictional_sliding_solver.h>
#include <lithostress/solvers/amg_solver.h>
#include <lithostress/solvers/rigid_body_modes.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace lithostress
{
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
    prm.declare_entry("Line search",
                      "true",
                      Patterns::Bool(),
                      "Newton: halve the step until the residual norm "
                      "falls (at most 6 times).");
    prm.declare_entry("Linear solver tolerance",
                      "1e-11",
                      Patterns::Double(0),
                      "Relative tolerance of each linear solve of a "
                      "frictional fault (GMRES with the elasticity AMG, "
                      "whatever Solver/Type says: the tangent is not "
                      "symmetric).");
    prm.declare_entry("Linear solver",
                      "GMRES with AMG",
                      Patterns::Selection("GMRES with AMG|direct"),
                      "How each Newton step's linear system is solved: GMRES "
                      "with the elasticity AMG (ILU smoothing, Chebyshev if "
                      "that stalls), or a sparse direct factorisation "
                      "(Amesos KLU, every step; far faster below ~1e5 DoFs, "
                      "where the stiff fault springs cost GMRES hundreds of "
                      "iterations).");
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
    parameters.line_search        = prm.get_bool("Line search");
    parameters.linear_tolerance   = prm.get_double("Linear solver tolerance");
    parameters.direct_solver      = prm.get("Linear solver") == "direct";
    if (!(parameters.convergence_factor > 0))
      throw_input_error("Faults/Sliding solver/Convergence factor",
                        "must be positive");
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

  template <int dim>
  void
  FrictionalSlidingSolver<dim>::solve(
    const DiscreteProblem<dim>             &problem,
    const FaultInterface<dim>              &faults,
    FaultSlipHistory                       &history,
    TrilinosWrappers::MPI::Vector          &solution,
    SolverReport                           &report,
    const std::function<void(std::string)> &progress) const
  {
    using InterfacePoint = typename FaultInterface<dim>::InterfacePoint;
    const DoFHandler<dim>           &dof_handler = problem.dof_handler;
    const FiniteElementSpace<dim>   &fe_space    = problem.fe_space;
    const LinearSystem<dim>         &system      = problem.system;
    const AffineConstraints<double> &constraints = system.constraints;
    const MPI_Comm communicator = dof_handler.get_communicator();
    const bool     newton       = parameters.method == Method::newton;
    report                      = SolverReport();
    report.solver               = newton ? "newton" : "thesis";
    report.linear_solves        = 0;
    Timer timer(communicator, true);

    std::vector<double>       distances;
    std::vector<unsigned int> fault_of_point;
    for (const InterfacePoint &p :
         faults.interface_quadrature(dof_handler, fe_space))
      {
        distances.push_back(p.distance);
        fault_of_point.push_back(p.fault);
      }
    const unsigned int n_points = distances.size();
    history.reinit(fault_of_point,
                   distances,
                   problem.operator_version >> 32,
                   communicator);
    // The law each solve linearised (t = D w + c per point) and the return
    // mapping's response at the last evaluated iterate.
    std::vector<Tensor<2, dim>>            tangents(n_points);
    std::vector<Tensor<1, dim>>            affine(n_points);
    std::vector<CoulombFriction::Response> responses(n_points);
    // The thesis method's slip, updated by the excess shear.
    std::vector<double> thesis_slip = history.slip;
    std::vector<bool>   slid(n_points, false);

    const auto stuck_law = [&](const std::vector<double> &slip) {
      return [&faults, &slip, &tangents, &affine](const unsigned int    i,
                                                  const InterfacePoint &p,
                                                  const Tensor<1, dim> &w,
                                                  Tensor<1, dim>       &t,
                                                  Tensor<2, dim>       &D) {
        D = faults.stuck_tangent(p);
        t =
          D * w - faults.friction(p.fault).shear_stiffness * slip[i] * p.shear;
        tangents[i] = D;
        affine[i]   = t - D * w;
      };
    };
    const auto return_mapping = [&](const unsigned int    i,
                                    const InterfacePoint &p,
                                    const Tensor<1, dim> &w,
                                    Tensor<1, dim>       &t,
                                    Tensor<2, dim>       &D) {
      responses[i] = faults.friction(p.fault).respond(w * p.shear,
                                                      w * p.normal,
                                                      history.slip[i],
                                                      p.depth);
      t            = responses[i].shear_traction * p.shear +
          responses[i].normal_traction * p.normal;
      D = from_local_frame<dim>(responses[i].tangent, p.shear, p.normal);
    };
    const auto newton_law = [&](const unsigned int    i,
                                const InterfacePoint &p,
                                const Tensor<1, dim> &w,
                                Tensor<1, dim>       &t,
                                Tensor<2, dim>       &D) {
      return_mapping(i, p, w, t, D);
      tangents[i] = D;
      affine[i]   = t - D * w;
    };

    TrilinosWrappers::MPI::Vector u(system.locally_owned, communicator),
      u_ghost(system.locally_owned, system.locally_relevant, communicator),
      rhs(system.rhs), residual(system.rhs), force(system.rhs);
    u = 0;
    constraints.distribute(u);
    u_ghost        = u;
    const double f = std::max(system.rhs.l2_norm(), 1e-300);
    check_right_hand_side(f);

    // The residual norm at u (ghosted as u_ghost) with the return mapping
    // from the committed slip, and the largest excess shear against the law
    // of the last solve.
    double     excess        = 0;
    const auto residual_norm = [&](const TrilinosWrappers::MPI::Vector &owned) {
      u_ghost = owned;
      system.matrix.vmult(residual, owned);
      residual -= system.rhs;
      force     = 0;
      double ex = 0;
      faults.assemble_interface(
        dof_handler,
        fe_space,
        constraints,
        &u_ghost,
        [&](const unsigned int    i,
            const InterfacePoint &p,
            const Tensor<1, dim> &w,
            Tensor<1, dim>       &t,
            Tensor<2, dim>       &D) {
          return_mapping(i, p, w, t, D);
          ex =
            std::max(ex, std::abs((t - tangents[i] * w - affine[i]) * p.shear));
        },
        nullptr,
        nullptr,
        &force);
      residual += force;
      constraints.set_zero(residual);
      excess = Utilities::MPI::max(ex, communicator);
      return residual.l2_norm();
    };

    TrilinosWrappers::SparseMatrix      matrix;
    std::unique_ptr<Epetra_MultiVector> modes;
    TrilinosWrappers::PreconditionAMG   amg;
    // A fault's normal spring is far stiffer than the rock next to it
    // (thesis: 1e15 N/m, i.e. k_n l / E h ~ 1e3): it ties the two fields'
    // DoFs at each fault node into stiff pairs, which point smoothers
    // (Chebyshev, Gauss-Seidel) damp poorly -- about 400 GMRES iterations
    // per solve on the normal fault -- and ILU smoothing takes together:
    // 45-55 per solve from 7 k to 416 k DoFs (doc/faults.md). ILU(0) of a
    // sliding tangent can fail, though (the thrust fault): a solve that
    // has not converged after 300 iterations goes on with the Chebyshev
    // smoother. Neither is symmetric here: every solve is GMRES.
    typename AMGSolver<dim>::Settings ilu_settings, chebyshev_settings;
    ilu_settings.smoother = "ILU";
    const auto set_up     = [&](const auto &law_at_point) {
      matrix.copy_from(system.matrix);
      rhs = system.rhs;
      faults.assemble_interface(dof_handler,
                                fe_space,
                                constraints,
                                &u_ghost,
                                law_at_point,
                                &matrix,
                                &rhs,
                                nullptr);
      if (parameters.direct_solver)
        return;
      if (!modes)
        modes = make_rigid_body_modes(dof_handler,
                                      fe_space,
                                      matrix.trilinos_matrix().DomainMap());
      initialize_elasticity_amg<dim>(amg, matrix, *modes, ilu_settings, true);
    };
    // GMRES with right preconditioning measures the true residual, which
    // the tolerance refers to.
    const auto linear_solve = [&](TrilinosWrappers::MPI::Vector &x) {
      if (parameters.direct_solver)
        {
          SolverControl                  control(1, 0);
          TrilinosWrappers::SolverDirect direct(control);
          direct.initialize(matrix);
          direct.solve(x, rhs);
          constraints.distribute(x);
          ++report.linear_solves;
          return;
        }
      const double target = parameters.linear_tolerance * rhs.l2_norm();
      const auto   gmres  = [&](const unsigned int max_iterations) {
        SolverControl control(max_iterations, target, false, false);
        try
          {
            SolverGMRES<TrilinosWrappers::MPI::Vector> solver(
              control,
              typename SolverGMRES<
                TrilinosWrappers::MPI::Vector>::AdditionalData(100, true));
            stop_on_signal(solver, communicator);
            solver.solve(matrix, x, rhs, amg);
          }
        catch (const SolverControl::NoConvergence &exc)
          {
            report.iterations += exc.last_step;
            if (max_iterations < 5000 &&
                !interruption::signal_on_any_rank(communicator))
              return false;
            rethrow_solver_failure(exc,
                                   communicator,
                                   "GMRES with AMG",
                                   rhs.l2_norm(),
                                   "raise Faults/Sliding solver/Linear "
                                      "solver tolerance");
          }
        report.iterations += iterations_of(control);
        return true;
      };
      if (!gmres(300))
        {
          progress("  sliding: GMRES with ILU smoothing stalled; continuing "
                   "with Chebyshev smoothing");
          initialize_elasticity_amg<dim>(
            amg, matrix, *modes, chebyshev_settings, true);
          gmres(5000);
        }
      constraints.distribute(x);
      ++report.linear_solves;
    };
    const auto count_states = [&]() {
      unsigned int n[3] = {0, 0, 0};
      for (const auto &r : responses)
        ++n[static_cast<int>(r.state)];
      std::ostringstream out;
      out << Utilities::MPI::sum(n[1], communicator) << " sliding, "
          << Utilities::MPI::sum(n[2], communicator) << " open of "
          << Utilities::MPI::sum(n_points, communicator) << " points";
      return out.str();
    };

    double       r_norm    = 0;
    bool         converged = false;
    unsigned int iteration = 0;
    if (newton)
      {
        // The elastic predictor, then Newton steps.
        TrilinosWrappers::MPI::Vector x(u), step(u), trial(u);
        r_norm = residual_norm(u);
        for (iteration = 1; iteration <= parameters.max_iterations; ++iteration)
          {
            if (iteration == 1)
              set_up(stuck_law(history.slip));
            else
              set_up(newton_law);
            x = u;
            linear_solve(x);
            step = x;
            step -= u;
            double alpha = 1, trial_norm = 0;
            for (unsigned int halving = 0;; ++halving)
              {
                trial = u;
                trial.add(alpha, step);
                trial_norm = residual_norm(trial);
                if (!parameters.line_search || iteration == 1 ||
                    trial_norm <= (1 - 1e-4 * alpha) * r_norm || halving == 6)
                  break;
                alpha /= 2;
              }
            u      = trial;
            r_norm = trial_norm;
            if (!std::isfinite(r_norm))
              throw ComputationError(
                "the Newton iteration for the sliding on " +
                faults.frictional_names() +
                " produced a residual that is not "
                "finite in iteration " +
                std::to_string(iteration));
            std::ostringstream line;
            line << "  sliding: Newton iteration " << iteration << ": residual "
                 << std::setprecision(3) << r_norm / f << ", excess shear "
                 << excess << " Pa, " << count_states()
                 << (alpha < 1 ? ", step " + std::to_string(alpha) : "");
            progress(line.str());
            if (r_norm <= parameters.residual_tolerance * f &&
                excess <= parameters.excess_shear_tolerance)
              {
                converged = true;
                break;
              }
          }
      }
    else
      {
        // The fault stays elastic in the matrix; its excess shear moves
        // into the slip.
        set_up(stuck_law(thesis_slip));
        double first_excess = 0;
        for (iteration = 1; iteration <= parameters.max_iterations; ++iteration)
          {
            if (iteration > 1)
              {
                rhs = system.rhs;
                faults.assemble_interface(dof_handler,
                                          fe_space,
                                          constraints,
                                          nullptr,
                                          stuck_law(thesis_slip),
                                          nullptr,
                                          &rhs,
                                          nullptr);
              }
            linear_solve(u);
            u_ghost   = u;
            double ex = 0;
            faults.assemble_interface(
              dof_handler,
              fe_space,
              constraints,
              &u_ghost,
              [&](const unsigned int    i,
                  const InterfacePoint &p,
                  const Tensor<1, dim> &w,
                  Tensor<1, dim> &,
                  Tensor<2, dim> &) {
                // The excess over the limit at the elastic traction.
                const CoulombFriction     &law = faults.friction(p.fault);
                CoulombFriction::Response &r   = responses[i];
                r                              = law.respond(w * p.shear,
                                w * p.normal,
                                thesis_slip[i],
                                p.depth);
                const double tau =
                  law.shear_stiffness * (w * p.shear - thesis_slip[i]);
                double e = 0;
                if (r.state == SlipState::open)
                  e = tau;
                else if (r.state == SlipState::sliding)
                  e = tau - (tau > 0 ? 1 : -1) * r.friction_limit;
                ex = std::max(ex, std::abs(e));
                if (e != 0)
                  slid[i] = true;
                thesis_slip[i] +=
                  parameters.convergence_factor * e / law.shear_stiffness;
                r.state = r.state == SlipState::open ? SlipState::open
                          : slid[i]                  ? SlipState::sliding
                                                     : SlipState::stuck;
              },
              nullptr,
              nullptr,
              nullptr);
            excess = Utilities::MPI::max(ex, communicator);
            if (iteration == 1)
              first_excess = excess;
            // Growing by orders of magnitude, or overflowing: the factor is
            // too large for this stiffness (thesis §6.1.5).
            if (!std::isfinite(excess) || excess > 1e3 * first_excess)
              {
                std::ostringstream what;
                what << std::setprecision(3)
                     << "the thesis iteration for the sliding on "
                     << faults.frictional_names()
                     << " diverges: the excess shear "
                     << "grew from " << first_excess << " Pa to " << excess
                     << " Pa in " << iteration
                     << " iterations; lower Faults/Sliding solver/Convergence "
                        "factor (now "
                     << parameters.convergence_factor << ")";
                report.nonlinear_iterations = iteration;
                throw ComputationError(what.str());
              }
            std::ostringstream line;
            line << "  sliding: thesis iteration " << iteration
                 << ": excess shear " << std::setprecision(3) << excess
                 << " Pa, " << count_states();
            if (iteration == 1 || iteration % 50 == 0 ||
                excess <= parameters.excess_shear_tolerance)
              progress(line.str());
            if (excess <= parameters.excess_shear_tolerance)
              {
                converged = true;
                break;
              }
          }
        // The residual with the states of the thesis's last iterate.
        const std::vector<CoulombFriction::Response> thesis = responses;
        r_norm                                              = residual_norm(u);
        responses                                           = thesis;
      }
    // The last iterate's slip and states: the trial history, committed by
    // the caller (or, if not converged, shown).
    for (unsigned int i = 0; i < n_points; ++i)
      {
        history.trial_slip[i]   = responses[i].plastic_slip;
        history.trial_states[i] = responses[i].state;
      }
    report.nonlinear_iterations =
      std::min(iteration, parameters.max_iterations);
    report.final_residual = r_norm / f;
    report.solve_time     = timer.wall_time();
    solution              = u;
    if (!converged)
      {
        std::ostringstream what;
        what << std::setprecision(3) << "the frictional sliding on "
             << faults.frictional_names() << " did not converge in "
             << parameters.max_iterations << " " << report.solver
             << " iterations (residual " << r_norm / f
             << " of the load, excess "
             << "shear " << excess
             << " Pa); the last iterate is written out. Raise Faults/Sliding "
                "solver/Maximum iterations"
             << (newton ? "" : " or the Convergence factor");
        throw ComputationError(what.str());
      }
  }

  template class FrictionalSlidingSolver<2>;
} // namespace lithostress

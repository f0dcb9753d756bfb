#include <lithostress/faults/sliding_context.h>

namespace lithostress
{
  namespace sliding
  {
    namespace
    {
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
          c.dof_handler,
          c.fe_space,
          &c.u_ghost,
          [&](const PointValues &values) {
            const auto           &p = values.point;
            const Tensor<1, dim> &w = values.jump;
            const unsigned int    i = values.index;
            // The excess over the limit at the elastic traction.
            const CoulombFriction &law = c.faults.coulomb_friction(p.fault);
            InterfaceResponse     &r   = c.responses[i];
            r = c.respond(values, ArrayView<const double>(&slip[i], 1));
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
          c.dof_handler,
          c.fe_space,
          &c.u_ghost,
          [&](const PointValues &values) {
            const unsigned int i = values.index;
            if (face.empty())
              first = values.point.position;
            face.push_back(i);
            c.responses[i] =
              c.respond(values, ArrayView<const double>(&slip[i], 1));
            if (!values.last_of_pair)
              return;
            const Point<dim> midpoint = 0.5 * (first + values.point.position);
            const auto       r = elements.read(values, midpoint, c.u_ghost);
            const CoulombFriction &law =
              c.faults.coulomb_friction(values.point.fault);
            const double limit =
              law.friction_coefficient * std::max(0., -r.effective_normal);
            // (An elastic fault never slides.)
            const bool   slides = c.faults.law(values.point.fault).nonlinear();
            const bool   over   = slides && std::abs(r.shear) > limit;
            const double e      = slides && (over || held[face[0]])
                                    ? beyond_limit(r.shear, limit)
                                    : 0.;
            ex                  = std::max(ex, std::abs(e));
            for (const unsigned int j : face)
              move_excess_into_slip(
                c, j, e, over, law.shear_stiffness, slip, slid, held);
            face.clear();
          });
        return Utilities::MPI::max(ex, c.communicator);
      }
    } // namespace

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
      const auto &settings = c.settings;
      // Defined for Coulomb friction (thesis §5.5): another law is refused
      // before anything is evaluated.
      for (unsigned int k = 0; k < c.faults.n_faults(); ++k)
        if (c.faults.has_face_terms(k))
          c.faults.coulomb_friction(k);
      std::vector<double> slip(c.n_points, 0.);
      for (unsigned int i = 0; i < c.n_points; ++i)
        if (c.history.committed(i).size() > 0)
          slip[i] = c.history.committed(i)[0];
      std::vector<bool> slid(c.n_points, false), held(c.n_points, false);
      std::unique_ptr<FaultElementStresses<dim>> elements;
      if (settings.element_stresses)
        elements =
          std::make_unique<FaultElementStresses<dim>>(c.fe_space,
                                                      c.problem.stress_model,
                                                      c.faults);
      bool       converged   = false;
      const auto thesis_slip = [&slip](const unsigned int i) {
        return ArrayView<const double>(&slip[i], 1);
      };
      c.set_up(c.stuck_law(thesis_slip));
      double first_excess = 0;
      for (c.iteration = 1; c.iteration <= settings.max_iterations;
           ++c.iteration)
        {
          if (c.iteration > 1)
            c.assemble_rhs(c.stuck_law(thesis_slip));
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
      const std::vector<InterfaceResponse> thesis = c.responses;
      c.r_norm                                    = c.residual_norm(c.u);
      c.responses                                 = thesis;
      return converged;
    }

    template bool
    solve_by_thesis_iteration(SlidingContext<2> &);
  } // namespace sliding
} // namespace lithostress

#include <deal.II/base/bounding_box.h>

#include <lithostress/faults/sliding_context.h>

#include <tuple>

namespace lithostress
{
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

    /** The set-up costs of SlidingContext::set_up_in_iterations(), each
     * the wall time of making the preconditioner over the time of one
     * iteration of its first solve, measured on the thesis's normal fault
     * and thrust at refinements 4 and 5 (doc/faults.md, "Nothing is made
     * again that has not changed"): the two fields' multigrid 7.6-8, the
     * AMG 17.7-19.6, the LU factorisation of two ranks 9.4-19; the
     * Cholesky factor's set-up took 1.2-1.5 times its flops' share. */
    constexpr double multigrid_set_up_iterations = 8,
                     amg_set_up_iterations = 18, lu_set_up_iterations = 16,
                     factorization_overhead = 1.4;

  } // namespace

  namespace sliding
  {
    template <int dim>
    SlidingContext<dim>::SlidingContext(
      const Settings                         &settings,
      const DiscreteProblem<dim>             &problem,
      const FaultInterface<dim>              &faults,
      FaultHistory                           &history,
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
                     faults.history_names(),
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
    SlidingContext<dim>::stuck_law(const HistoryOf &history)
    {
      return [this, history](const PointValues &values,
                             Tensor<1, dim>    &t,
                             Tensor<2, dim>    &D) {
        const auto             &p = values.point;
        const unsigned int      i = values.index;
        const InterfaceResponse r =
          faults.law(p.fault).predictor(FaultInterface<dim>::law_inputs(
            p, values.jump, history(i), problem.stress_model.time_step()));
        D           = from_local_frame<dim>(r.tangent, p.shear, p.normal);
        t           = r.shear_traction * p.shear + r.normal_traction * p.normal;
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
      responses[i]            = respond(values, history.committed(i));
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
    SlidingContext<dim>::set_up(const Law &law, const bool check_blocks)
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
      if (check_blocks)
        check_blocks_held();
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
      setup_iterations       = set_up_in_iterations();
      stale_iterations       = 0;
      first_iterations       = numbers::invalid_unsigned_int;
      time_preconditioner += timer.wall_time();
    }

    template <int dim>
    double
    SlidingContext<dim>::set_up_in_iterations() const
    {
      if (use_multigrid)
        return multigrid_set_up_iterations;
      if (cholesky && direct && contact &&
          Utilities::MPI::n_mpi_processes(communicator) == 1)
        return cholesky->factorization_in_solves() * factorization_overhead;
      if (direct)
        return lu_set_up_iterations;
      return amg_set_up_iterations;
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

    template <int dim>
    void
    SlidingContext<dim>::check_blocks_held() const
    {
      const RigidBodies<dim> blocks = faults.blocks();
      const double E = problem.stress_model.materials.largest_youngs_modulus();
      const BoundingBox<dim> box(
        dof_handler.get_triangulation().get_vertices());
      const double size = box.get_boundary_points().first.distance(
        box.get_boundary_points().second);
      const auto points = faults.interface_quadrature(dof_handler, fe_space);
      std::vector<BodyCoupling<dim>> couplings(points.size());
      for (unsigned int i = 0; i < points.size(); ++i)
        {
          couplings[i].position = points[i].position;
          couplings[i].JxW      = points[i].JxW;
          std::tie(couplings[i].body_0, couplings[i].body_1) =
            faults.blocks_of_fault(points[i].fault);
          couplings[i].stiffness = assembled_tangents[i] * (size / E);
        }
      const bool        km = size > 1e4;
      const std::string free =
        RigidBodySupport<dim>::free_motion(dof_handler,
                                           fe_space,
                                           active_constraints(),
                                           problem.loads,
                                           E,
                                           blocks,
                                           couplings,
                                           km ? 1e3 : 1.,
                                           km ? "km" : "m");
      if (free.empty())
        return;
      std::ostringstream what;
      what << "the states of the fault points leave the linearised system "
              "singular after Newton iteration "
           << iteration << " (" << count_states() << " on "
           << faults.frictional_names() << "): " << free
           << ". A fault whose points open or slide without friction holds "
              "nothing: is there a normal stress on it (gravity, Lithostatic "
              "density, loads that press it shut)?";
      throw ComputationError(what.str());
    }

    template class SlidingContext<2>;
  } // namespace sliding
} // namespace lithostress

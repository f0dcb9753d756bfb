#ifndef lithostress_time_integration_creep_integrator_h
#define lithostress_time_integration_creep_integrator_h

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <lithostress/discretization/finite_element_space.h>
#include <lithostress/materials/cell_history.h>
#include <lithostress/materials/stress_model.h>
#include <lithostress/time_integration/time_stepping.h>

#include <algorithm>
#include <functional>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /**
   * The update of the laws' history at the cell quadrature points in one
   * time step (thesis §3.9, doc/equations.md §10), for the integrators of
   * TimeStepping. Each law's history h is a set of named components
   * (Rheology::history_names(), in the records of a CellHistory); what
   * follows is written for MaxwellRheology's creep strain c, and holds for
   * any history whose rate the law gives (RheologyOutputs::history_rate).
   * The implicit schemes share one form: before the solve a
   * history strain c* (begin_step()), the solve with the relaxed moduli
   * G/(1 + w Δt/τ) and c* as initial strain, after it
   * c_{n+1} = c* + w Δt s_{n+1}/(2η) with s_{n+1} the deviator of the
   * step's stress (finish_implicit_step()):
   * - BDF2 (variable step, ω = Δt_n/Δt_{n−1}):
   *   c* = ((1+ω)² c_n − ω² c_{n−1})/(1+2ω), w = (1+ω)/(1+2ω); its first
   *   step (no c_{n−1} yet) is a trapezoidal step;
   * - generalised midpoint (weight θ): c* = c_n + (1 − θ) Δt s_n/(2η),
   *   w = θ;
   * - thesis (§3.9): the elastic moduli with the history strain
   *   c_n + Δc, where Δc = Δt (s_n + s_{n+1})/(4η) is re-evaluated from
   *   each new solution (update_thesis_history()) until the stress stops
   *   changing; then c_{n+1} = c_n + Δc (finish_thesis_step()).
   * s_n is the deviatoric stress of the start of the step (elastic moduli,
   * creep strain c_n). Materials whose law keeps no history are skipped.
   */
  template <int dim>
  class CreepIntegrator
  {
  public:
    /**
     * The size of a step's creep-strain change and its estimated local
     * error, for the output and the step control (doc/equations.md). For
     * a first-order step the local error of the creep increment is
     * estimated as (Δt/2) ‖ċ_{n+1} − ċ_n‖, the difference between the
     * first-order increment and one with the average rate; for a BDF2 step
     * as (8/5) ‖c_{n+1} − c_n − (Δt/2)(ċ_n + ċ_{n+1})‖, its difference
     * from the trapezoidal rule scaled by the ratio of the two methods'
     * error constants (2/9 against 2/9 − 1/12), an O(Δt³) estimate.
     */
    struct Increment
    {
      /** max ‖c_{n+1} − c_n‖ over the nodes (Rheology::history_norm()). */
      double creep_change = 0;
      /** max (Δt/2) ‖ċ_{n+1} − ċ_n‖ over the nodes. */
      double local_error = 0;
      /** max ‖s_{n+1}‖/(2G) = τ ‖ċ_{n+1}‖ over the nodes of creeping
       * materials (τ: Rheology::relaxation_time()). */
      double elastic_strain = 0;

      /** Include one node of a material with law @p law: history @p c_old
       * → @p c_new over a step of length @p dt with start and end rates
       * @p rate_start, @p rate_end, and the elastic strain
       * @p elastic_strain at the end (RheologyOutputs::elastic_strain). */
      void
      add(const Rheology<dim>           &law,
          const ArrayView<const double> &c_old,
          const ArrayView<const double> &c_new,
          const ArrayView<const double> &rate_start,
          const ArrayView<const double> &rate_end,
          const double                   dt,
          const double                   elastic_strain,
          const bool                     second_order = false);


      /** local_error relative to @p scale, the largest elastic strain of
       * the run so far (0 if nothing has been stressed). */
      double
      relative_error(const double scale) const
      {
        return scale > 0 ? local_error / scale : 0.0;
      }

      /** Room for a combination of histories. */
      std::vector<double> work;
    };

    /** History fields on @p triangulation with the assembly's Gauss
     * points (@p n_points_1d per direction), each record laid out by
     * @p layout (StressModel::history_layout()), and the field of Newton's
     * linearisation if @p nonlinear (some law is non-linear). */
    CreepIntegrator(
      const parallel::distributed::Triangulation<dim> &triangulation,
      const unsigned int                               n_points_1d,
      const HistoryLayout                             &layout,
      const bool                                       nonlinear = false);

    /** The history h_n (the creep strain c_n): what persists (transferred
     * with the mesh, written to checkpoints). */
    CellHistory<dim> &
    cell_history()
    {
      return creep;
    }

    /** The history h* (the history strain c*) the step's assembly uses. */
    const CellHistory<dim> &
    step_history() const
    {
      return history;
    }

    /** Attach the creep strain, the start rate and the previous step's
     * creep strain to the triangulation's next save() (collective). */
    void
    prepare_for_checkpoint()
    {
      creep.prepare_for_checkpoint();
      start_rate.prepare_for_checkpoint();
      previous.prepare_for_checkpoint();
    }

    /** After triangulation.load(): read them back (in the order of
     * prepare_for_checkpoint()) and size the work fields; @p previous_dt
     * is the length of the step before (0: none), from the checkpoint's
     * state. */
    void
    load_from_checkpoint(const double previous_dt)
    {
      creep.load_from_checkpoint();
      start_rate.load_from_checkpoint();
      previous.load_from_checkpoint();
      history.setup();
      end_rate.setup();
      linearised.setup();
      flow.setup();
      start_rate_current = true;
      previous_step      = previous_dt;
    }

    /** Before the triangulation is refined or coarsened: attach the fields
     * the next step needs (c_n and c_{n−1}); collective. */
    void
    prepare_for_mesh_change()
    {
      creep.prepare_for_mesh_change();
      previous.prepare_for_mesh_change();
    }

    /** After it: transfer them and size the work fields; the start rate is
     * computed anew. */
    void
    finish_mesh_change()
    {
      creep.finish_mesh_change();
      previous.finish_mesh_change();
      setup_step_fields();
    }

    /** The length of the last accepted step (0 before the first), which
     * BDF2 needs with c_{n−1}; kept in checkpoints. */
    double
    previous_step_length() const
    {
      return previous_step;
    }

    /** Remember the creep strain c_n at the start of a step. */
    void
    keep_start()
    {
      start_values = creep.values();
    }

    /** Back to the creep strain of keep_start() (a rejected step). */
    void
    restore_start()
    {
      creep.assign(start_values);
    }

    /** A history of zero creep on the current mesh, before the first
     * step (no previous step). */
    void
    start_history();

    /** Size the step's work fields for the current mesh: the start rate
     * is computed anew. */
    void
    setup_step_fields();

    /**
     * Begin a step of length @p dt from the solution @p solution (with the
     * creep strain c_n): the start rate s_n/(2η) and the history strain c*
     * of @p scheme (for the generalised midpoint rule with weight
     * @p theta), or the thesis scheme's explicit predictor
     * c_n + Δt s_n/(2η). Returns the weight w of the step's relaxed moduli
     * G/(1 + w Δt/τ) (for the thesis scheme: 0, the elastic moduli).
     */
    double
    begin_step(const DoFHandler<dim>               &dof_handler,
               const FiniteElementSpace<dim>       &fe_space,
               const StressModel<dim>              &stress_model,
               const TrilinosWrappers::MPI::Vector &solution,
               const double                         dt,
               const TimeStepping::Scheme           scheme,
               const double                         theta);

    /** Whether the step of begin_step() is a second-order BDF2 step (its
     * local error ∝ Δt³; the start step of BDF2 is estimated as first
     * order). */
    bool
    second_order_step() const
    {
      return bdf2_step;
    }

    /**
     * Newton's linearisation of the step of begin_step() at the iterate
     * @p solution, for the materials whose law is non-linear: at every node
     * the tangent C_k and σ₀ = σ(ε_k) − σ_init − C_k ε_k (LinearisedStress)
     * into linearisation(), which StressModel::attach_linearisation() then
     * gives the assembly. Unless @p first, returns how far the previous
     * linearisation missed the stress at the new iterate,
     * max ‖σ(ε_k) − σ_lin(ε_k)‖ over max ‖dev σ(ε_k)‖ (in-plane; all
     * ranks): the residual of the step's equilibrium that the last linear
     * solve left, since that solve balanced σ_lin exactly. Newton's method
     * makes it fall quadratically (doc/equations.md §12).
     */
    double
    linearise(const DoFHandler<dim>               &dof_handler,
              const FiniteElementSpace<dim>       &fe_space,
              const StressModel<dim>              &stress_model,
              const TrilinosWrappers::MPI::Vector &solution,
              const bool                           first);

    /** How the non-linear laws' rocks flow at the end of the last
     * accepted step, at the nodes: `effective_viscosity` τ_II/(2 ε̇_II)
     * [Pa s], `strain_rate_II` ε̇_II of the inelastic strain [1/s] and
     * `yielding` (1 where plastic, else 0); zero on a new mesh until the
     * next step, and where the law is linear. No components without a
     * non-linear law. ParaView fields (StressModel::attach_flow_state()). */
    const CellHistory<dim> &
    flow_state() const
    {
      return flow;
    }

    /** The linearisation of the last linearise(). */
    const CellHistory<dim> &
    linearisation() const
    {
      return linearised;
    }

    /** End an implicit step with the new solution: c_{n+1} from the step
     * stress with the weight of begin_step() (the stress model's step
     * moduli must be those of the step). */
    Increment
    finish_implicit_step(const DoFHandler<dim>               &dof_handler,
                         const FiniteElementSpace<dim>       &fe_space,
                         const StressModel<dim>              &stress_model,
                         const TrilinosWrappers::MPI::Vector &solution);

    /** One fixed-point update of the thesis scheme from the new solution;
     * returns the largest change of the deviatoric stress relative to
     * @p stress_scale, which is raised to the largest deviatoric stress
     * if that is larger (the run's largest so far: a relaxing stress is
     * measured against its initial size, not against round-off). */
    double
    update_thesis_history(const DoFHandler<dim>               &dof_handler,
                          const FiniteElementSpace<dim>       &fe_space,
                          const StressModel<dim>              &stress_model,
                          const TrilinosWrappers::MPI::Vector &solution,
                          double                              &stress_scale);

    /** End a thesis step: c_{n+1} = c_n + Δc of the last update. */
    Increment
    finish_thesis_step(const StressModel<dim> &stress_model);

    /** The step is accepted: its end rate is the next step's start rate
     * (the same state), which is then not computed again. */
    void
    accept_step()
    {
      start_rate.swap_values(end_rate);
      start_rate_current = true;
      previous.assign(start_values);
      previous_step = step;
    }

  private:
    /**
     * Call @p visit(cell, nodes) for every owned cell whose law keeps a
     * history, with the inputs of the law at its nodes (quadrature
     * points): the position, the strain of @p solution and the temperature
     * (where the model has one) set; the rest is the caller's.
     */
    void
    for_each_cell_with_history(
      const DoFHandler<dim>               &dof_handler,
      const FiniteElementSpace<dim>       &fe_space,
      const StressModel<dim>              &stress_model,
      const TrilinosWrappers::MPI::Vector &solution,
      const std::function<
        void(const typename Triangulation<dim>::active_cell_iterator &,
             std::vector<RheologyInputs<dim>> &)> &visit) const;

    /** Put material @p id's history values @p values into @p record (a
     * record of the layout, from CellHistory::get()). */
    void
    store(const types::material_id   id,
          const std::vector<double> &values,
          Vector<double>            &record) const;

    /** The 3-D stress tensor of a stress state. */
    static SymmetricTensor<2, 3>
    tensor_3d(const StressState<dim> &s);

    /** Maximum over all ranks of the two parts of @p increment. */
    Increment
    all_ranks(const Increment &increment) const;


    /** Where each law's history lies in a record. */
    const HistoryLayout &layout;
    /** c_n, the step's history strain c*, the rates at the start and end
     * of the step, and c_{n−1}. */
    CellHistory<dim> creep, history, start_rate, end_rate, previous;
    /** Newton's linearisation of a step (records of LinearisedStress; no
     * components without a non-linear law). */
    CellHistory<dim> linearised;
    /** flow_state(). */
    CellHistory<dim> flow;
    /** Whether start_rate belongs to the current creep strain and
     * solution (false after a mesh change). */
    bool                                  start_rate_current = false;
    typename CellHistory<dim>::VectorType start_values;
    /** The step length of begin_step(), and of the last accepted step. */
    double step = 0, previous_step = 0;
    /** Whether the step of begin_step() is a BDF2 step. */
    bool bdf2_step = false;
    /** The weight w of the end rate in the step of begin_step(). */
    double step_weight = 0;
  };
} // namespace lithostress

#endif

#ifndef lithostress_materials_stress_model_h
#define lithostress_materials_stress_model_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <lithostress/materials/cell_history.h>
#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/history_layout.h>
#include <lithostress/materials/initial_stress_source.h>
#include <lithostress/materials/linearised_stress.h>
#include <lithostress/materials/material.h>
#include <lithostress/materials/rheology.h>
#include <lithostress/temperature/temperature_model.h>

#include <map>
#include <memory>
#include <vector>

namespace lithostress
{
  /**
   * The constitutive law as every result sees it (thesis eq. 3.38,
   * σ = C(ε − ε0)): the Rheology of each material (elastic, Maxwell, ...,
   * `Materials/<name>/Rheology`) in the model's plane state, given the
   * stresses of the initial strains carried by loads (thermal strain,
   * §3.8). Output, point values, stress–depth profiles, error norms,
   * refinement indicators and the creep update all take their stress from
   * here, so that an initial strain enters every result once and in the
   * same way.
   *
   * With creeping materials (thesis §3.9) the model also holds the laws'
   * history at the cell quadrature points (attach_cell_history(), laid out
   * by history_layout()): every reported stress is then the law's with the
   * history at the point, and a time step's linear system uses the step
   * moduli of its laws (set_time_step()).
   */
  template <int dim>
  class StressModel
  {
  public:
    /** The rock laws of @p materials (each made from the registry and
     * reading its parameters from @p prm, `Materials/<name>`) in
     * @p plane_state, with the initial stresses of those @p sources that
     * carry one (the model's loads). */
    StressModel(ParameterHandler      &prm,
                const MaterialLibrary &materials,
                const PlaneState       plane_state,
                const std::vector<const InitialStressSource<dim> *> &sources);

    /** The stress at @p p in a cell of material @p id with strain @p strain
     * and no history. */
    StressState<dim>
    stress(const types::material_id       id,
           const Point<dim>              &p,
           const SymmetricTensor<2, dim> &strain) const;

    /** The stress at @p p for strain @p strain and the history @p history
     * of material @p id's law (its history_names()). */
    StressState<dim>
    stress(const types::material_id       id,
           const Point<dim>              &p,
           const SymmetricTensor<2, dim> &strain,
           const ArrayView<const double> &history) const;

    /**
     * The stress at the point @p p of @p cell whose unit-cell coordinates
     * are @p unit: the cell history attached to the model, if any, is
     * evaluated there. What every reported stress goes through.
     */
    StressState<dim>
    stress(const typename Triangulation<dim>::active_cell_iterator &cell,
           const Point<dim>                                        &unit,
           const Point<dim>                                        &p,
           const SymmetricTensor<2, dim> &strain) const;

    /**
     * The law of material @p id at one point: the loads' initial stresses
     * at in.position (with the moduli the law uses for @p in) are put into
     * @p in, then Rheology::evaluate(). The creep update of a time step.
     */
    void
    evaluate(const types::material_id id,
             RheologyInputs<dim>     &in,
             RheologyOutputs<dim>    &out) const;

    /**
     * The stress of the history @p history of material @p id's law alone —
     * at zero strain, without the loads' initial stresses — in the current
     * step's linear system, or with @p of_state in a state: the history's
     * share of the right-hand side, −∫ ε(v) : σ_h (a creep strain is an
     * initial strain, thesis eq. 3.38).
     */
    StressState<dim>
    history_stress(const types::material_id       id,
                   const Point<dim>              &p,
                   const ArrayView<const double> &history,
                   const bool                     of_state = false) const;

    /** Where each material's history lies in the records of the cell
     * history (the union of the laws' history_names()). */
    const HistoryLayout &
    history_layout() const
    {
      return layout;
    }

    /** Whether material @p id's law keeps a history. */
    bool
    has_history(const types::material_id id) const
    {
      return layout.size(id) > 0;
    }

    /** The rock law of material @p id. */
    const Rheology<dim> &
    rheology(const types::material_id id) const
    {
      return *rheology_of.at(id);
    }

    /** The elastic moduli of material @p id. */
    const ElasticModuli<dim> &
    moduli(const types::material_id id) const
    {
      return rheology_of.at(id)->elastic_moduli();
    }

    /** The moduli of the current time step's linear system (assembly and
     * matrix-free operators): relaxed for Maxwell materials, elastic
     * before the first step. */
    const ElasticModuli<dim> &
    step_moduli(const types::material_id id) const
    {
      return rheology_of.at(id)->step_moduli();
    }

    /** Whether the law of material @p id has the same tangent at every
     * point (Rheology::uniform_tangent()). */
    bool
    uniform_tangent(const types::material_id id) const
    {
      return rheology_of.at(id)->uniform_tangent();
    }

    /** Whether every material's law has a uniform tangent: the linear
     * system is then assembled with one tangent per material. */
    bool
    uniform_tangents() const;

    /**
     * The tangent dσ/dε of the current step (set_time_step()) at the point
     * @p p of a cell of material @p id, at zero strain and without history
     * (a tangent that depends on the state needs the Newton iterate, which
     * no caller gives yet), or with @p of_state the instantaneous one
     * (the stress of a state): step_moduli()'s (elastic_moduli()'s)
     * stiffness for a law with a uniform tangent, else
     * RheologyOutputs::tangent of the law's evaluate() there. What the
     * matrix assembly, the matrix-free operator and the force balance use
     * at each quadrature point.
     */
    SymmetricTensor<4, dim>
    tangent(const types::material_id id,
            const Point<dim>        &p,
            const bool               of_state = false) const;

    /**
     * Whether the step of a cell of material @p id is linearised: its law
     * is non-linear (Rheology::nonlinear()), a step is under way
     * (time_step() > 0) and a linearisation is attached. The assembly then
     * takes the tangent and σ₀ of linearisation() at each quadrature point
     * instead of the law's tangent and history stress.
     */
    bool
    linearised(const types::material_id id) const
    {
      return linearisation != nullptr && step_length > 0 &&
             rheology_of.at(id)->nonlinear();
    }

    /** The linearisation at the quadrature points (CellHistory's nodes) of
     * the owned @p cell, whose law is linearised(), into @p values. */
    void
    linearisation_at(
      const typename Triangulation<dim>::active_cell_iterator &cell,
      std::vector<LinearisedStress<dim>>                      &values) const;

    /** Whether the current operator is symmetric: false where a linearised
     * law's tangent lacks the major symmetry (Rheology::symmetric_tangent(),
     * a non-associated flow rule). */
    bool
    symmetric_operator() const;

    /** Whether some material's law can have a tangent without the major
     * symmetry once it is linearised (a non-associated flow rule): a
     * property of the input, known before anything is solved. */
    bool
    may_be_unsymmetric() const;

    /** Whether some material's law is non-linear: the time loop's steps
     * are then Newton iterations. */
    bool
    has_nonlinear_material() const;

    /** Assemble non-linear laws' steps with @p field (records of
     * LinearisedStress, owned by CreepIntegrator; nullptr: none). Marks a
     * new operator (moduli_version()): call after every change of the
     * field's values. */
    void
    attach_linearisation(const CellHistory<dim> *field)
    {
      linearisation = field;
      ++version;
    }

    /** The stress of the strain @p strain under the current step's
     * tangent at @p p (no history, no initial stress): the linear law of
     * the operator the goals' dual problems solve. */
    StressState<dim>
    step_stress(const types::material_id       id,
                const Point<dim>              &p,
                const SymmetricTensor<2, dim> &strain) const;

    /** Whether any material creeps. */
    bool
    has_viscous_material() const;

    /** Use the step moduli of a step of length @p dt with weight
     * @p theta (dt = 0: the elastic moduli). */
    void
    set_time_step(const double dt, const double theta);

    /** The length of the current step (set_time_step(); 0: a state, as
     * in an elastic solve) [s]. */
    double
    time_step() const
    {
      return step_length;
    }

    /** Give the model the section's temperature (`Temperature/Model`;
     * null: none), owned by the caller, for the laws and the output that
     * read it. Throws InputError naming the material whose law needs a
     * temperature (Rheology::needs_temperature()) if there is none. */
    void
    attach_temperature(const TemperatureModel<dim> *model);

    /** The temperature attached, or null where the model has none. */
    const TemperatureModel<dim> *
    temperature_model() const
    {
      return temperature;
    }

    /** Changes whenever set_time_step() changes the step moduli. */
    unsigned long long
    moduli_version() const
    {
      return version;
    }

    /** Include the history @p history (laid out by history_layout()) in
     * every reported stress (nullptr: none). */
    void
    attach_cell_history(const CellHistory<dim> *history)
    {
      cell_history = history;
    }

    /** Write the fields of @p state (CreepIntegrator::flow_state(): the
     * non-linear laws' effective viscosity, strain rate and yielding) with
     * the solution (nullptr: none). */
    void
    attach_flow_state(const CellHistory<dim> *state)
    {
      flow_state = state;
    }

    /** The attached flow state, or nullptr. */
    const CellHistory<dim> *
    attached_flow_state() const
    {
      return flow_state;
    }

    /** The attached cell history, or nullptr. */
    const CellHistory<dim> *
    attached_cell_history() const
    {
      return cell_history;
    }

    /** Whether any load carries an initial strain. */
    bool
    has_initial_stress() const
    {
      return !initial_stress_loads.empty();
    }

    /** The pressure [Pa] of the reference state the stresses are relative
     * to at @p p (every load's InitialStressSource::reference_pressure()):
     * what a law that reads the pressure adds to that of the stress. */
    double
    reference_pressure(const Point<dim> &p) const;

    const MaterialLibrary &materials;
    const PlaneState       plane_state;

  private:
    /** The loads' initial stresses at @p p in material @p id with
     * @p moduli. */
    StressState<dim>
    initial_stress(const types::material_id  id,
                   const Point<dim>         &p,
                   const ElasticModuli<dim> &moduli) const;

    std::map<types::material_id, std::unique_ptr<Rheology<dim>>> rheology_of;
    /** Where each law's history lies in a record, and as many zeros as
     * the largest history has (the history of a state without one). */
    HistoryLayout                                 layout;
    std::vector<double>                           zero_history;
    std::vector<const InitialStressSource<dim> *> initial_stress_loads;
    /** Every load, for reference_pressure(). */
    std::vector<const InitialStressSource<dim> *> all_sources;
    const CellHistory<dim>                       *cell_history  = nullptr;
    const CellHistory<dim>                       *linearisation = nullptr;
    const CellHistory<dim>                       *flow_state    = nullptr;
    const TemperatureModel<dim>                  *temperature   = nullptr;
    double             step_length = 0, step_theta = 1;
    unsigned long long version = 0;
  };
} // namespace lithostress

#endif

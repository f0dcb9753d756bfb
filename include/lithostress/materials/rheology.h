#ifndef lithostress_materials_rheology_h
#define lithostress_materials_rheology_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <lithostress/base/plugin_registry.h>
#include <lithostress/materials/elastic_moduli.h>
#include <lithostress/materials/material.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace lithostress
{
  /** The stress at a point: the in-plane tensor and σ_zz (tension positive). */
  template <int dim>
  struct StressState
  {
    SymmetricTensor<2, dim> in_plane;
    double                  zz = 0;
  };

  /**
   * What a rock law is given at one quadrature point for one time step
   * (doc/equations.md §10): the strain at the end of the step, the step,
   * the temperature and pressure, and the known part of the law's history
   * at the end of the step.
   */
  template <int dim>
  struct RheologyInputs
  {
    /** Where the point is [m]. */
    Point<dim> position;
    /** ε_{n+1}, the in-plane strain at the end of the step. */
    SymmetricTensor<2, dim> strain;
    /** Δε = ε_{n+1} − ε_n (zero when the law is asked for the stress of a
     * state rather than a step). */
    SymmetricTensor<2, dim> strain_increment;
    /** Δt [s]; 0 asks for the instantaneous (elastic) response. */
    double time_step = 0;
    /**
     * The weight w of the step's end rate: the history at the end of the
     * step is h* + w Δt ḣ_{n+1} (BDF2, the generalised midpoint rule;
     * w = 0: the thesis scheme's elastic solve, CreepIntegrator).
     */
    double weight = 0;
    /** Temperature [K] and pressure [Pa, compression positive]. */
    double temperature = 0, pressure = 0;
    /** h*, the known part of the history at the end of the step, one
     * value per Rheology::history_names() (empty for a law without
     * history). */
    ArrayView<const double> history;
    /** The stress of the loads' initial strains at the point (thermal
     * strain, thesis §3.8, eq. 3.38), computed with the moduli of
     * Rheology::moduli_for(): part of the stress the law creeps under. */
    StressState<dim> initial_stress;
  };

  /**
   * What a rock law returns at one point: the stress, its consistent
   * tangent dσ/dε, the history at the end of the step and its rate there,
   * and diagnostics.
   */
  template <int dim>
  struct RheologyOutputs
  {
    /** The stress of the law (without the loads' initial stresses, which
     * StressModel adds). */
    StressState<dim> stress;
    /** dσ/dε, in-plane. */
    SymmetricTensor<4, dim> tangent;
    /** ḣ_{n+1} and h_{n+1} = h* + w Δt ḣ_{n+1}, one value per history
     * component. */
    std::vector<double> history_rate, history;
    /** The effective viscosity τ_II/(2 ε̇_II) of the creep [Pa s]; 0 for
     * a law that does not creep. */
    double effective_viscosity = 0;
    /** The elastic deviatoric strain ‖s‖/(2G) of the stress: the scale of
     * the time loop's step control (CreepIntegrator::Increment). */
    double elastic_strain = 0;
    /** The second invariant ε̇_II of the inelastic (creep and plastic)
     * strain rate [1/s], and whether the point yields (plasticity). */
    double inelastic_strain_rate = 0;
    bool   yielding              = false;
  };

  /** The two branches of a strength envelope at a point [Pa]: the brittle
   * (yield) stress and the ductile stress that creeps at a reference strain
   * rate; infinite where the law has no such branch. */
  struct StrengthEnvelope
  {
    double brittle = std::numeric_limits<double>::infinity();
    double ductile = std::numeric_limits<double>::infinity();
  };

  /**
   * A rock law evaluated point by point (in the way of ASPECT's
   * MaterialModel::Interface): each material of a model has one, chosen by
   * `Materials/<name>/Rheology`, and everything that needs the stress — the
   * reported stresses, the creep update of a time step, the linear system's
   * tangent — asks it (through StressModel). A law declares the names of
   * the history it keeps at every quadrature point; CreepIntegrator carries
   * that history through time steps, refinement and checkpoints.
   *
   * Adding a law is a class derived from this one in its own files and one
   * line, LITHOSTRESS_REGISTER_RHEOLOGY, in its source file
   * (doc/architecture.md, "Adding a rheology").
   */
  template <int dim>
  class Rheology
  {
  public:
    virtual ~Rheology() = default;

    /**
     * Read the law from the subsection of @p material (entered): its own
     * entries and the common ones in @p material (elastic constants,
     * viscosity); throws InputError naming the entry.
     */
    virtual void
    parse_parameters(ParameterHandler &prm,
                     const Material   &material,
                     const PlaneState  plane_state) = 0;

    /** The names of the components of the history at a point (empty: the
     * law keeps none). */
    virtual std::vector<std::string>
    history_names() const
    {
      return {};
    }

    /**
     * The size of a history (or of its change or rate) @p h, one value per
     * history_names(): what the time loop's step control measures the
     * creep increment and its local error with (CreepIntegrator). The
     * Euclidean norm unless the law says otherwise (a tensor's norm for a
     * creep strain).
     */
    virtual double
    history_norm(const ArrayView<const double> &h) const
    {
      double sum = 0;
      for (const double v : h)
        sum += v * v;
      return std::sqrt(sum);
    }

    /** The instantaneous (elastic) response. */
    virtual const ElasticModuli<dim> &
    elastic_moduli() const = 0;

    /** Whether the law creeps, so that its history changes in time. */
    virtual bool
    creeps() const
    {
      return false;
    }

    /**
     * Whether the tangent of a step is step_moduli() at every point of the
     * material (a linear, homogeneous law): the matrix assembly and the
     * matrix-free operator then take it per cell. A law whose tangent
     * varies from point to point returns false, and they take
     * RheologyOutputs::tangent of evaluate() at each quadrature point
     * (StressModel::tangent()).
     */
    virtual bool
    uniform_tangent() const
    {
      return true;
    }

    /**
     * Whether the stress of a step depends non-linearly on the strain
     * (power-law creep, plasticity): the time loop then solves each step by
     * Newton's method, assembling at every iterate the tangent and stress of
     * evaluate() there (LinearisedStress, doc/equations.md §12). Such a law
     * has no uniform tangent.
     */
    virtual bool
    nonlinear() const
    {
      return false;
    }

    /** Whether the consistent tangent of evaluate() has the major
     * symmetry C_ijkl = C_klij (CG applies); a non-associated flow rule's
     * has not, and the linear solvers then use GMRES. */
    virtual bool
    symmetric_tangent() const
    {
      return true;
    }

    /** Whether evaluate() reads RheologyInputs::temperature (a
     * temperature-activated creep law): the model must then have a
     * `Temperature/Model`. */
    virtual bool
    needs_temperature() const
    {
      return false;
    }

    /**
     * The strength envelope of the intact rock (Goetze & Evans 1979) at
     * temperature @p temperature [K] and pressure @p pressure [Pa,
     * compression positive]: the τ_II at which it yields and the τ_II at
     * which it creeps at ε̇_II = @p strain_rate [1/s]. Both infinite for a
     * law without yield or creep (the default).
     */
    virtual StrengthEnvelope
    strength_envelope(const double temperature,
                      const double pressure,
                      const double strain_rate) const
    {
      (void)temperature;
      (void)pressure;
      (void)strain_rate;
      return {};
    }

    /** The time over which the law relaxes stress [s] (0: it does not):
     * the time loop's first step and its step limits. */
    virtual double
    relaxation_time() const
    {
      return 0;
    }

    /**
     * The moduli of the current step where the tangent is the same at
     * every point of the material (a linear law): what the matrix, the
     * matrix-free operator and the loads' initial stresses of a step use.
     * The elastic moduli until set_time_step() is called.
     */
    virtual const ElasticModuli<dim> &
    step_moduli() const = 0;

    /** Use a step of length @p dt with weight @p weight (see
     * RheologyInputs::weight) from now on: step_moduli() and evaluate()
     * with in.time_step > 0 are then those of this step. */
    virtual void
    set_time_step(const double dt, const double weight) = 0;

    /** The moduli evaluate() works with for @p in: elastic_moduli() for
     * the stress of a state (in.time_step = 0), step_moduli() in a step. */
    const ElasticModuli<dim> &
    moduli_for(const RheologyInputs<dim> &in) const
    {
      return in.time_step == 0 ? elastic_moduli() : step_moduli();
    }

    /**
     * The stress of @p in: the state's stress with history h* (in.time_step
     * = 0), or the stress at the end of the step of the last
     * set_time_step(); in.initial_stress included. What every reported
     * stress goes through.
     */
    virtual StressState<dim>
    stress(const RheologyInputs<dim> &in) const = 0;

    /**
     * stress() with its tangent dσ/dε, the history rate ḣ_{n+1} there (the
     * flow law at that stress), the history h* + w Δt ḣ_{n+1} at the end of
     * the step and diagnostics: a time step's update at a quadrature
     * point. Sizes out.history and out.history_rate.
     */
    virtual void
    evaluate(const RheologyInputs<dim> &in,
             RheologyOutputs<dim>      &out) const = 0;
  };

  /** The rock laws `Materials/<name>/Rheology` selects. */
  template <int dim>
  using RheologyRegistry = PluginRegistry<Rheology<dim>>;
} // namespace lithostress

/**
 * Register the rock-law class template @p classname (a Rheology with a
 * static `declare_parameters(ParameterHandler &)` for its entries of a
 * material's subsection, which may be none) as `Materials/<name>/Rheology =
 * name`; one line in its source file.
 */
#define LITHOSTRESS_REGISTER_RHEOLOGY(classname, name, description) \
  LITHOSTRESS_REGISTER_PLUGIN(                                      \
    ::lithostress::RheologyRegistry<2>,                             \
    {name,                                                          \
     description,                                                   \
     [](ParameterHandler &prm, ParameterHandler *) {                \
       classname<2>::declare_parameters(prm);                       \
     },                                                             \
     []() -> std::unique_ptr<::lithostress::Rheology<2>> {          \
       return std::make_unique<classname<2>>();                     \
     }})

#endif

#ifndef lithostress_faults_interface_law_h
#define lithostress_faults_interface_law_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/tensor.h>

#include <lithostress/base/gravity_field.h>
#include <lithostress/base/plugin_registry.h>

#include <memory>
#include <string>
#include <vector>

namespace lithostress
{
  using namespace dealii;

  /** The state of a point of a fault. */
  enum class SlipState
  {
    /** |τ| < τ_F: the interface deforms elastically. */
    stuck,
    /** |τ| = τ_F: the fault slides, the slip grows. */
    sliding,
    /** σ_n,eff ≥ 0: the fault is in tension and carries no shear. */
    open
  };

  /** "stuck", "sliding" or "open" (the `state` column of fault.csv). */
  std::string
  to_string(const SlipState state);

  /**
   * What an interface law sees at one point of its fault (thesis chapter
   * 5's fault element at a node pair), in the fault's frame: the jump w =
   * u(hanging wall) − u(footwall) along the shear direction s and the
   * normal n into the hanging wall, the contact reaction where exact
   * contact holds the normal jump, the step and the point's history.
   */
  struct InterfaceLawInputs
  {
    /** w·s and w·n [m]. */
    double shear_jump = 0, normal_jump = 0;
    /** The depth d of the law's overburden at the point [m]
     * (FaultInterface::InterfacePoint::overburden_depth). */
    double overburden_depth = 0;
    /** Whether the point is a buried tip, whose jump the weld holds at
     * zero: the law does not act there. */
    bool welded = false;
    /** Exact normal contact at the point: whether it is closed (its normal
     * jump held at zero) and the normal traction t_n that holds it (the
     * constraint's reaction) [Pa]. */
    bool   in_contact = false, closed = false;
    double contact_traction = 0;
    /** The time step Δt [s] of the visco-elastic loop's step being solved
     * (StressModel::time_step(); 0 in an elastic solve). */
    double time_step = 0;
    /** The point's history at the start of the step, in the order of
     * InterfaceLaw::history_names(). */
    ArrayView<const double> history;
  };

  /**
   * What an interface law gives back at a point: the traction (t_s, t_n)
   * in the fault's frame, the consistent tangent d(t_s, t_n)/d(w_s, w_n),
   * the history at the end of the step, the point's state and the
   * diagnostics that the fault output and exact contact read.
   */
  struct InterfaceResponse
  {
    /** t_s and the model's t_n [Pa] (tension positive). */
    double shear_traction = 0, normal_traction = 0;
    /** σ_n,eff = t_n less the law's overburden, and the shear strength
     * τ_F [Pa]. */
    double effective_normal_stress = 0, friction_limit = 0;
    /** The friction coefficient μ of the strength τ_F = μ max(0,
     * −σ_n,eff) at this response (0: the law has no friction): how the
     * strength follows a contact reaction (FrictionLimitCoupling). */
    double friction_coefficient = 0;
    /** d(t_s, t_n)/d(w_s, w_n): index 0 = shear, 1 = normal. */
    Tensor<2, 2> tangent;
    /** The history after this response. */
    std::vector<double> history;
    SlipState           state = SlipState::stuck;
  };

  /**
   * A fault's interface law (thesis chapter 5), evaluated point by point in
   * the fault's frame, in the way of a rock law (Rheology): each fault of a
   * model has one, chosen by `Faults/<name>/Interface law`. A law either
   * ties the two sides by constraints (locked, prescribed slip: the jump is
   * given) or acts through face terms ∫ [v]·t(w) ds (elastic, frictional),
   * linearised by its tangent; a law that is nonlinear, or has exact normal
   * contact, is solved by FrictionalSlidingSolver. A law declares the names
   * of the history it keeps at every interface point; FaultHistory carries
   * it through solves, time steps, refinement and checkpoints.
   *
   * Adding a law is a class derived from this one in its own files and one
   * line, LITHOSTRESS_REGISTER_INTERFACE_LAW, in its source file
   * (doc/architecture.md, "Adding a fault law").
   */
  template <int dim>
  class InterfaceLaw
  {
  public:
    virtual ~InterfaceLaw() = default;

    /**
     * Read the law from the subsection of the fault @p fault (entered;
     * messages name `Faults/<fault>/<entry>`), with lengths in units of
     * @p length_scale metres and g from @p gravity; throws InputError
     * naming the entry.
     */
    virtual void
    parse_parameters(ParameterHandler   &prm,
                     const std::string  &fault,
                     const GravityField &gravity,
                     const double        length_scale) = 0;

    /** The names of the components of the history at a point (empty: the
     * law keeps none). */
    virtual std::vector<std::string>
    history_names() const
    {
      return {};
    }

    /** Whether the jump is given (locked, prescribed slip): exact
     * constraints, no face terms. */
    virtual bool
    constrains_jump() const
    {
      return false;
    }

    /** Whether a law that constrains the jump gives a nonzero one
     * (prescribed_jump()); false: the jump is zero (locked). */
    virtual bool
    has_prescribed_jump() const
    {
      return false;
    }

    /** A law that constrains the jump: (the slip down the dip, the opening
     * along the normal) [m] at the distance @p s along the fault [m] and
     * the time @p time [s]; zero by default (locked). */
    virtual Tensor<1, 2>
    prescribed_jump(const double s, const double time) const
    {
      (void)s;
      (void)time;
      return Tensor<1, 2>();
    }

    /** Whether the law adds face terms ∫ [v]·t(w) ds. */
    virtual bool
    has_face_terms() const
    {
      return false;
    }

    /** Whether the traction is nonlinear in the jump (a law that slides):
     * solved by FrictionalSlidingSolver. */
    virtual bool
    nonlinear() const
    {
      return false;
    }

    /** Whether the law has exact normal contact (no normal spring: the
     * normal traction is a constraint's reaction). */
    virtual bool
    exact_contact() const
    {
      return false;
    }

    /** Whether the depth of the overburden is measured from y = 0 (sea
     * level) rather than from the fault's upper end. */
    virtual bool
    overburden_from_sea_level() const
    {
      return false;
    }

    /** The compression the law adds to the model's normal traction at
     * depth @p depth [Pa] (σ_n,eff = t_n − overburden). */
    virtual double
    overburden(const double depth) const
    {
      (void)depth;
      return 0;
    }

    /** The stiffness while nothing slides, diag(k_s, k_n) in the fault's
     * (shear, normal) frame [Pa/m], with k_n = 0 in exact contact: the
     * face terms of a linear solve and the elastic predictor's tangent. */
    virtual Tensor<2, 2>
    stuck_stiffness() const
    {
      return Tensor<2, 2>();
    }

    /** The response at @p in if nothing slides in this step (the elastic
     * predictor, and the traction of a state whose history is @p
     * in.history): the stuck stiffness acting on the jump less the
     * history's inelastic part. */
    virtual InterfaceResponse
    predictor(const InterfaceLawInputs &in) const = 0;

    /** The response at @p in (the return mapping of a frictional law):
     * traction, consistent tangent, new history and state. */
    virtual InterfaceResponse
    evaluate(const InterfaceLawInputs &in) const = 0;
  };

  /** The fault laws `Faults/<name>/Interface law` selects. */
  template <int dim>
  using InterfaceLawRegistry = PluginRegistry<InterfaceLaw<dim>>;

  /** The number in the entry @p name of the fault @p fault's subsection
   * (entered), at least (@p inclusive) or above @p lowest; an InputError
   * naming `Faults/<fault>/<name>` if it is empty ("is needed by the <law>
   * law"), not a number or out of range. */
  double
  fault_law_number(const ParameterHandler &prm,
                   const std::string      &fault,
                   const std::string      &name,
                   const std::string      &law,
                   const double            lowest,
                   const bool              inclusive);
} // namespace lithostress

/**
 * Register the fault-law class template @p classname (an InterfaceLaw
 * with a static `declare_parameters(ParameterHandler &)` for its entries
 * of a fault's subsection, which may be none) as `Faults/<name>/Interface
 * law = name`, at @p position in the list of values; one line in its
 * source file.
 */
#define LITHOSTRESS_REGISTER_INTERFACE_LAW(classname,          \
                                           name,               \
                                           description,        \
                                           position)           \
  LITHOSTRESS_REGISTER_PLUGIN(                                 \
    ::lithostress::InterfaceLawRegistry<2>,                    \
    {name,                                                     \
     description,                                              \
     [](ParameterHandler &prm, ParameterHandler *) {           \
       classname<2>::declare_parameters(prm);                  \
     },                                                        \
     []() -> std::unique_ptr<::lithostress::InterfaceLaw<2>> { \
       return std::make_unique<classname<2>>();                \
     },                                                        \
     position})

#endif

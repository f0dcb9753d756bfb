#ifndef lithostress_faults_prescribed_slip_interface_h
#define lithostress_faults_prescribed_slip_interface_h

#include <deal.II/base/function_parser.h>

#include <lithostress/faults/locked_interface.h>

namespace lithostress
{
  /**
   * `Interface law = prescribed slip`: the jump is given, w = slip(s, t) d
   * + opening(s, t) n with d the down-dip direction (kinematic, as
   * PyLith's faults), exact through the locked law's constraints with
   * inhomogeneities (FaultInterface::add_constraints()): the locked law
   * with a jump.
   */
  template <int dim>
  class PrescribedSlipInterface : public LockedInterface<dim>
  {
  public:
    /** `Slip` and `Opening`. */
    static void
    declare_parameters(ParameterHandler &prm);

    /** The two expressions of s and t; an InputError naming the entry if
     * one is not. */
    void
    parse_parameters(ParameterHandler   &prm,
                     const std::string  &fault,
                     const GravityField &gravity,
                     const double        length_scale) override;

    bool
    has_prescribed_jump() const override
    {
      return true;
    }

    /** (Slip, Opening) at (@p s, @p time). */
    Tensor<1, 2>
    prescribed_jump(const double s, const double time) const override;

  private:
    /** Slip and opening [m] as functions of s [m] and t [s]. */
    std::shared_ptr<FunctionParser<1>> slip, opening;
  };
} // namespace lithostress

#endif

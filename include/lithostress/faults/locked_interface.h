#ifndef lithostress_faults_locked_interface_h
#define lithostress_faults_locked_interface_h

#include <lithostress/faults/interface_law.h>

namespace lithostress
{
  /**
   * `Interface law = locked`: the displacement is continuous across the
   * fault, by exact constraints (thesis §5's k = 1e15 N/m without its
   * penalty; FaultInterface::add_constraints()). No face terms, no
   * history.
   */
  template <int dim>
  class LockedInterface : public InterfaceLaw<dim>
  {
  public:
    /** It has no entries. */
    static void
    declare_parameters(ParameterHandler &)
    {
    }

    void
    parse_parameters(ParameterHandler &,
                     const std::string &,
                     const GravityField &,
                     const double) override
    {
    }

    bool
    constrains_jump() const override
    {
      return true;
    }

    /** Zero: the constraints hold the jump (never evaluated). */
    InterfaceResponse
    predictor(const InterfaceLawInputs &) const override
    {
      return InterfaceResponse();
    }

    /** Zero: the constraints hold the jump (never evaluated). */
    InterfaceResponse
    evaluate(const InterfaceLawInputs &) const override
    {
      return InterfaceResponse();
    }
  };
} // namespace lithostress

#endif

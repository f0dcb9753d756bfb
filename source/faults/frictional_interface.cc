#include <lithostress/faults/frictional_interface.h>

namespace lithostress
{
  template <int dim>
  void
  FrictionalInterface<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Friction coefficient",
                      "0.1",
                      Patterns::Anything(),
                      "mu of the frictional law (thesis: 0.1).");
    prm.declare_entry(
      "Lithostatic density",
      "2911",
      Patterns::Anything(),
      "rho_l [kg/m^3] of the lithostatic normal stress rho_l g depth "
      "that the frictional law adds to the model's normal traction "
      "(FSHEAR's 2911, for models without body forces); 0 = none, for "
      "models whose stresses include gravity.");
    prm.declare_entry("Pore fluid density",
                      "1000",
                      Patterns::Anything(),
                      "rho_w [kg/m^3] of the hydrostatic pore pressure "
                      "rho_w g depth subtracted from the compression "
                      "(FSHEAR's 1000); 0 = dry.");
    prm.declare_entry(
      "Overburden depth from",
      "fault top",
      Patterns::Selection("fault top|sea level"),
      "Where the depth of the lithostatic and pore pressures is "
      "measured from: fault top = the upper end of the fault's trace "
      "(on the top surface; above a buried tip, where its welded "
      "extension meets the surface); sea level = y = 0, as FSHEAR "
      "measures both (thesis appendix: SLITH = 2911 g y and POREP = "
      "1000 g y with y the coordinate below sea level), which adds the "
      "water depth above a submarine fault's trace to both.");
  }

  template <int dim>
  void
  FrictionalInterface<dim>::parse_parameters(ParameterHandler   &prm,
                                             const std::string  &fault,
                                             const GravityField &gravity,
                                             const double        length_scale)
  {
    this->parse_stiffnesses(prm, fault, "frictional", length_scale);
    CoulombFriction &f      = this->friction;
    const auto       number = [&](const std::string &name) {
      return fault_law_number(prm, fault, name, "frictional", 0, true);
    };
    f.slides               = true;
    f.friction_coefficient = number("Friction coefficient");
    f.lithostatic_density  = number("Lithostatic density");
    f.pore_fluid_density   = number("Pore fluid density");
    f.gravity              = gravity.acceleration;
    from_sea_level         = prm.get("Overburden depth from") == "sea level";
  }

  template <int dim>
  InterfaceResponse
  FrictionalInterface<dim>::evaluate(const InterfaceLawInputs &in) const
  {
    return this->respond(in, in.history.size() == 0 ? 0. : in.history[0]);
  }

  template class FrictionalInterface<2>;
  LITHOSTRESS_REGISTER_INTERFACE_LAW(
    FrictionalInterface,
    "frictional",
    "elastic until the shear traction reaches mu |sigma_n,eff|, then "
    "Coulomb sliding (thesis §5.5; solved by the Sliding solver)",
    20)
} // namespace lithostress

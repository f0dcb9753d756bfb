#include <lithostress/base/input_error.h>
#include <lithostress/materials/creep_strain.h>
#include <lithostress/materials/visco_elasto_plastic_rheology.h>

#include <array>
#include <cmath>
#include <limits>

namespace lithostress
{
  namespace
  {
    /** The inelastic-strain tensor's components of a history @p h. */
    template <int dim>
    ArrayView<const double>
    inelastic_strain(const ArrayView<const double> &h)
    {
      return ArrayView<const double>(h.data(), CreepStrain<dim>::n_components);
    }
  } // namespace

  template <int dim>
  void
  ViscoElastoPlasticRheology<dim>::declare_parameters(ParameterHandler &prm)
  {
    CreepMechanism::declare_parameters(prm, "Dislocation creep", 3.5);
    CreepMechanism::declare_parameters(prm, "Diffusion creep", 1);
    DruckerPrager::declare_parameters(prm);
    prm.declare_entry("Minimum viscosity",
                      "0",
                      Patterns::Double(0),
                      "The lower bound of the effective viscosity "
                      "tau_II/(2 eps_II) of the creep [Pa s]; 0: none "
                      "(Rheology = visco-elasto-plastic)");
    prm.declare_entry("Maximum viscosity",
                      "0",
                      Patterns::Double(0),
                      "The upper bound of the effective viscosity [Pa s]; "
                      "0: none (Rheology = visco-elasto-plastic)");
  }

  template <int dim>
  void
  ViscoElastoPlasticRheology<dim>::parse_parameters(
    ParameterHandler &prm,
    const Material   &material,
    const PlaneState  plane_state)
  {
    const std::string entry = "Materials/" + material.name + "/";
    if (plane_state != PlaneState::plane_strain)
      throw_input_error(entry + "Rheology",
                        "visco-elasto-plastic needs plane strain (the "
                        "3-D deviator's creep with sigma_zz = 0 is not "
                        "implemented)");
    dislocation.parse_parameters(prm, "Dislocation creep", material.name);
    diffusion.parse_parameters(prm, "Diffusion creep", material.name);
    plasticity.parse_parameters(prm, material.name, material.tensile_strength);
    minimum_viscosity = prm.get_double("Minimum viscosity");
    maximum_viscosity = prm.get_double("Maximum viscosity");
    viscosity         = material.viscosity;
    if (!(viscosity > 0) && !dislocation.active() && !diffusion.active() &&
        !plasticity.active())
      throw_input_error(entry + "Rheology",
                        "visco-elasto-plastic needs a Viscosity, a "
                        "Dislocation or Diffusion creep prefactor, or a "
                        "Cohesion or Friction angle");
    if (maximum_viscosity > 0 && maximum_viscosity < minimum_viscosity)
      throw_input_error(entry + "Maximum viscosity",
                        "is below the Minimum viscosity");
    shear_modulus = material.shear_modulus();
    bulk_modulus  = material.lame_lambda() + 2.0 / 3.0 * shear_modulus;
    elastic.emplace(material, plane_state);
  }

  template <int dim>
  std::vector<std::string>
  ViscoElastoPlasticRheology<dim>::history_names() const
  {
    std::vector<std::string> names = CreepStrain<dim>::names();
    if (plasticity.active())
      names.emplace_back("plastic_strain");
    return names;
  }

  template <int dim>
  double
  ViscoElastoPlasticRheology<dim>::history_norm(
    const ArrayView<const double> &h) const
  {
    // The accumulated plastic strain is measured with the tensor.
    double norm = CreepStrain<dim>::tensor(inelastic_strain<dim>(h)).norm();
    if (plasticity.active())
      norm = std::hypot(norm, h[CreepStrain<dim>::n_components]);
    return norm;
  }

  template <int dim>
  bool
  ViscoElastoPlasticRheology<dim>::needs_temperature() const
  {
    return dislocation.activated() || diffusion.activated();
  }

  template <int dim>
  double
  ViscoElastoPlasticRheology<dim>::relaxation_time() const
  {
    if (viscosity > 0)
      return viscosity / shear_modulus;
    if (minimum_viscosity > 0)
      return minimum_viscosity / shear_modulus;
    return std::numeric_limits<double>::infinity();
  }

  template <int dim>
  typename ViscoElastoPlasticRheology<dim>::FlowRate
  ViscoElastoPlasticRheology<dim>::flow_rate(const double tau,
                                             const double temperature,
                                             const double pressure) const
  {
    // The mechanisms in series: their rates add.
    FlowRate f;
    if (viscosity > 0)
      {
        f.rate += tau / (2 * viscosity);
        f.d_tau += 1 / (2 * viscosity);
      }
    for (const CreepMechanism *m : {&diffusion, &dislocation})
      if (m->active())
        {
          const double a    = m->rate_factor(temperature, pressure);
          const double tn_1 = std::pow(tau, m->exponent - 1);
          f.rate += a * tn_1 * tau;
          f.d_tau += m->exponent * a * tn_1;
          if (m->activation_volume != 0 && temperature > 0)
            f.d_pressure -= m->activation_volume /
                            (CreepMechanism::gas_constant * temperature) * a *
                            tn_1 * tau;
        }
    // The bounds of the effective viscosity τ/(2 ε̇): at τ = 0 that is
    // 1/(2 dε̇/dτ). A bound's rate τ/(2 η_bound) does not depend on P.
    const double effective =
      tau > 0 ? (f.rate > 0 ? tau / (2 * f.rate)
                            : std::numeric_limits<double>::infinity())
              : (f.d_tau > 0 ? 1 / (2 * f.d_tau)
                             : std::numeric_limits<double>::infinity());
    if (maximum_viscosity > 0 && effective > maximum_viscosity)
      return {tau / (2 * maximum_viscosity), 1 / (2 * maximum_viscosity), 0};
    if (minimum_viscosity > 0 && effective < minimum_viscosity)
      return {tau / (2 * minimum_viscosity), 1 / (2 * minimum_viscosity), 0};
    return f;
  }

  template <int dim>
  std::pair<double, double>
  ViscoElastoPlasticRheology<dim>::flow(const double tau,
                                        const double temperature,
                                        const double pressure) const
  {
    const FlowRate f = flow_rate(tau, temperature, pressure);
    return {f.rate, f.d_tau};
  }

  template <int dim>
  bool
  ViscoElastoPlasticRheology<dim>::symmetric_tangent() const
  {
    for (const CreepMechanism *m : {&diffusion, &dislocation})
      if (m->active() && m->activation_volume != 0)
        return false;
    return plasticity.symmetric_tangent();
  }

  template <int dim>
  double
  ViscoElastoPlasticRheology<dim>::return_stress(const double tau_trial,
                                                 const double k,
                                                 const double temperature,
                                                 const double pressure) const
  {
    if (k == 0 || tau_trial == 0)
      return tau_trial;
    // g(τ) = τ + k ε̇(τ) − τ_tr rises from −τ_tr at 0 to k ε̇(τ_tr) ≥ 0 at
    // τ_tr. Newton's method in x = ln τ (a power law is an exponential in
    // x, so that stiff steps converge in a few iterations), kept inside
    // the bracket [low, high] by bisection.
    double low = 0, high = tau_trial, tau = tau_trial;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const auto [rate, derivative] = flow(tau, temperature, pressure);
        const double g                = tau + k * rate - tau_trial;
        if (std::abs(g) <= 1e-15 * tau_trial)
          return tau;
        (g > 0 ? high : low) = tau;
        double next = tau * std::exp(-g / (tau * (1 + k * derivative)));
        if (!(next > low && next < high))
          next = low > 0 ? std::sqrt(low * high) : 0.5 * high;
        if (std::abs(next - tau) <= 1e-16 * tau)
          return next;
        tau = next;
      }
    return tau;
  }

  template <int dim>
  StressState<dim>
  ViscoElastoPlasticRheology<dim>::stress(const RheologyInputs<dim> &in) const
  {
    RheologyOutputs<dim> out;
    evaluate(in, out);
    return out.stress;
  }


  template <int dim>
  std::pair<double, double>
  ViscoElastoPlasticRheology<dim>::plastic_increment(
    const double tau_trial,
    const double pressure,
    const double plastic_strain,
    const double temperature,
    const double k,
    const bool   tension) const
  {
    // r(Δγ) = τ_tr − k ε̇(τ) − 2G Δγ − τ with τ = τ_y(ε_p* + Δγ, P(Δγ)),
    // P(Δγ) = P + 2K sin ψ Δγ (the pressure held by a tension cut-off);
    // r(0) > 0 (the creep return lies above the yield stress) and
    // r(τ_tr/(2G)) ≤ 0: Newton's method kept in that bracket.
    const double dilation =
      tension ? 0 : 2 * bulk_modulus * std::sin(plasticity.dilation);
    const auto at = [&](const double dg) {
      const DruckerPrager::Strength s =
        plasticity.strength(plastic_strain + dg);
      const double p     = pressure + dilation * dg;
      const double tau   = s.at(p);
      const double slope = tau > 0 ? s.d_cohesion_term + p * s.d_sin_friction +
                                       s.sin_friction * dilation
                                   : 0.0;
      const FlowRate f   = flow_rate(tau, temperature, p);
      return std::array<double, 3>{
        {tau_trial - k * f.rate - 2 * shear_modulus * dg - tau,
         -k * (f.d_tau * slope + f.d_pressure * dilation) - 2 * shear_modulus -
           slope,
         slope}};
    };
    double low = 0, high = tau_trial / (2 * shear_modulus), dg = 0;
    for (unsigned int i = 0; i < 200; ++i)
      {
        const std::array<double, 3> r = at(dg);
        if (std::abs(r[0]) <= 1e-15 * tau_trial)
          return {dg, r[2]};
        (r[0] > 0 ? low : high) = dg;
        double next = r[1] < 0 ? dg - r[0] / r[1] : 0.5 * (low + high);
        if (!(next > low && next < high))
          next = 0.5 * (low + high);
        if (std::abs(next - dg) <= 1e-16 * high)
          return {next, at(next)[2]};
        dg = next;
      }
    return {dg, at(dg)[2]};
  }

  template <int dim>
  typename ViscoElastoPlasticRheology<dim>::Return
  ViscoElastoPlasticRheology<dim>::return_mapping(
    const double                   tau_trial,
    const double                   pressure_trial,
    const SymmetricTensor<2, dim> &direction,
    const double                   plastic_strain,
    const double                   temperature,
    const double                   extra_pressure,
    const double                   k) const
  {
    const double                  G = shear_modulus, K = bulk_modulus;
    const SymmetricTensor<2, dim> unit = unit_symmetric_tensor<dim>();
    Return                        r;
    // The tension cut-off: the mean stress −P stays at most the tensile
    // strength, a volumetric plastic strain opening the rest.
    r.pressure = pressure_trial;
    if (k > 0 && plasticity.tension_cutoff &&
        pressure_trial + extra_pressure < -plasticity.tensile_strength)
      {
        r.tension         = true;
        r.pressure        = -plasticity.tensile_strength - extra_pressure;
        r.tension_opening = (r.pressure - pressure_trial) / K;
      }
    const double p = r.pressure + extra_pressure;
    r.tau          = return_stress(tau_trial, k, temperature, p);
    // g(τ, P) = τ + k ε̇(τ, P) − τ_tr = 0: a1 dτ = dτ_tr − k ∂ε̇/∂P dP,
    // a1 = 1 + k ∂ε̇/∂τ (the pressure term: an activation volume).
    const FlowRate creep = flow_rate(r.tau, temperature, p);
    const double   a1    = 1 + k * creep.d_tau;
    r.d_pressure         = r.tension ? SymmetricTensor<2, dim>() : -K * unit;
    r.d_tau = (G * direction - k * creep.d_pressure * r.d_pressure) / a1;
    if (k == 0 || !plasticity.active() ||
        r.tau <= plasticity.strength(plastic_strain).at(p))
      return r;

    // Yielding: back to the yield surface with the plastic increment Δγ.
    r.yielding             = true;
    const auto [dg, slope] = plastic_increment(
      tau_trial, p, plastic_strain, temperature, k, r.tension);
    r.plastic_increment  = dg;
    const double sin_psi = r.tension ? 0.0 : std::sin(plasticity.dilation);
    r.pressure += 2 * K * sin_psi * dg;
    const DruckerPrager::Strength s = plasticity.strength(plastic_strain + dg);
    r.tau                           = s.at(r.pressure + extra_pressure);
    const double   p_end            = r.pressure + extra_pressure;
    const FlowRate yield_flow       = flow_rate(r.tau, temperature, p_end);
    const double   a                = 1 + k * yield_flow.d_tau;
    const double   k_p              = k * yield_flow.d_pressure;
    // dτ = sin φ dP_tr + H dΔγ, dP = dP_tr + 2K sin ψ dΔγ and
    // a dτ + k ∂ε̇/∂P dP + 2G dΔγ = dτ_tr (H = dτ/dΔγ): with
    // dτ_tr = G ŝ:dε and dP_tr = −K tr dε (0 under the cut-off).
    const double                  sin_phi = r.tau > 0 ? s.sin_friction : 0.0;
    const SymmetricTensor<2, dim> d_pressure_trial =
      r.tension ? SymmetricTensor<2, dim>() : -K * unit;
    const SymmetricTensor<2, dim> d_increment =
      (G * direction - (a * sin_phi + k_p) * d_pressure_trial) /
      (a * slope + k_p * 2 * K * sin_psi + 2 * G);
    r.d_tau      = sin_phi * d_pressure_trial + slope * d_increment;
    r.d_pressure = d_pressure_trial + 2 * K * sin_psi * d_increment;
    return r;
  }

  namespace
  {
    /** The 3-D tensor of a stress state. */
    template <int dim>
    SymmetricTensor<2, 3>
    tensor_3d(const StressState<dim> &s)
    {
      SymmetricTensor<2, 3> t;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          t[i][j] = s.in_plane[i][j];
      if (dim == 2)
        t[2][2] = s.zz;
      return t;
    }

    /** The in-plane part of a 3-D tensor. */
    template <int dim>
    SymmetricTensor<2, dim>
    in_plane(const SymmetricTensor<2, 3> &t)
    {
      SymmetricTensor<2, dim> result;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          result[i][j] = t[i][j];
      return result;
    }
  } // namespace

  template <int dim>
  void
  ViscoElastoPlasticRheology<dim>::evaluate(const RheologyInputs<dim> &in,
                                            RheologyOutputs<dim> &out) const
  {
    const ElasticModuli<dim> &m = *elastic;
    const double              G = shear_modulus, K = bulk_modulus;
    // The trial state: the elastic stress of ε with the history c*.
    const SymmetricTensor<2, 3> c_star =
      CreepStrain<dim>::tensor(inelastic_strain<dim>(in.history));
    const double plastic_strain =
      plasticity.active() ? in.history[CreepStrain<dim>::n_components] : 0.0;
    StressState<dim> trial;
    trial.in_plane = m.stress(in.strain) + in.initial_stress.in_plane;
    trial.zz       = m.sigma_zz(in.strain) + in.initial_stress.zz;
    const auto [sigma_c, zz_c] = m.initial_strain_stress(c_star);
    trial.in_plane += sigma_c;
    trial.zz += zz_c;
    const SymmetricTensor<2, 3> sigma_trial = tensor_3d(trial);
    const SymmetricTensor<2, 3> s_trial     = deviator(sigma_trial);
    const double tau_trial = std::sqrt(0.5 * scalar_product(s_trial, s_trial));
    const SymmetricTensor<2, 3> direction =
      tau_trial > 0 ? s_trial / tau_trial : SymmetricTensor<2, 3>();
    const double weighted_step = in.weight * in.time_step;
    const double k             = 2 * G * weighted_step;
    const Return r             = return_mapping(tau_trial,
                                    -trace(sigma_trial) / 3,
                                    in_plane<dim>(direction),
                                    plastic_strain,
                                    in.temperature,
                                    in.pressure,
                                    k);
    const double creep_rate =
      flow(r.tau, in.temperature, r.pressure + in.pressure).first;

    // ċ = ε̇_II ŝ + γ̇ (ŝ + (2/3) sin ψ 1) + (opening/(3 w Δt)) 1, the
    // inelastic strain c = c* + w Δt ċ and σ = σ_tr − C (c − c*).
    SymmetricTensor<2, 3> c_rate       = creep_rate * direction;
    double                plastic_rate = 0;
    if (weighted_step > 0)
      {
        plastic_rate = r.plastic_increment / weighted_step;
        const double volumetric =
          (r.tension
             ? r.tension_opening
             : 2 * std::sin(plasticity.dilation) * r.plastic_increment) /
          (3 * weighted_step);
        c_rate +=
          plastic_rate * direction + volumetric * unit_symmetric_tensor<3>();
      }
    const SymmetricTensor<2, 3> dc = weighted_step * c_rate;
    const SymmetricTensor<2, 3> sigma =
      sigma_trial - 2 * G * deviator(dc) -
      K * trace(dc) * unit_symmetric_tensor<3>();
    out.history_rate.resize(history_names().size());
    out.history.resize(history_names().size());
    const unsigned int n = CreepStrain<dim>::n_components;
    CreepStrain<dim>::components(c_rate,
                                 ArrayView<double>(out.history_rate.data(), n));
    CreepStrain<dim>::components(c_star + dc,
                                 ArrayView<double>(out.history.data(), n));
    if (plasticity.active())
      {
        out.history_rate[n] = plastic_rate;
        out.history[n]      = plastic_strain + r.plastic_increment;
      }
    out.stress.in_plane       = in_plane<dim>(sigma);
    out.stress.zz             = sigma[2][2];
    out.inelastic_strain_rate = creep_rate + plastic_rate;
    out.yielding              = r.yielding;
    out.effective_viscosity   = out.inelastic_strain_rate > 0
                                  ? r.tau / (2 * out.inelastic_strain_rate)
                                  : std::numeric_limits<double>::infinity();
    out.elastic_strain        = std::sqrt(2.0) * r.tau / (2 * G);

    // C_k = 2Gα P_dev + ŝ ⊗ (∂τ/∂ε − αG ŝ) − 1 ⊗ ∂P/∂ε.
    const double alpha =
      tau_trial > 0
        ? r.tau / tau_trial
        : 1 /
            (1 + k * flow(0, in.temperature, r.pressure + in.pressure).second);
    const SymmetricTensor<2, dim> unit  = unit_symmetric_tensor<dim>();
    const SymmetricTensor<2, dim> s_hat = in_plane<dim>(direction);
    out.tangent =
      2 * G * alpha *
        (identity_tensor<dim>() - (1.0 / 3.0) * outer_product(unit, unit)) +
      outer_product(s_hat, r.d_tau - alpha * G * s_hat) -
      outer_product(unit, r.d_pressure);
  }

  template <int dim>
  StrengthEnvelope
  ViscoElastoPlasticRheology<dim>::strength_envelope(
    const double temperature,
    const double pressure,
    const double strain_rate) const
  {
    StrengthEnvelope envelope;
    if (plasticity.active())
      envelope.brittle = plasticity.strength(0).at(pressure);
    // ε̇_II(τ) rises from 0: bracket the root by decades, then bisect in
    // ln τ to 1e-12.
    const auto rate = [&](const double tau) {
      return flow(tau, temperature, pressure).first;
    };
    double high = 1;
    while (rate(high) < strain_rate && high < 1e15)
      high *= 10;
    if (!(strain_rate > 0) || rate(high) < strain_rate)
      return envelope;
    double low = high / 10;
    while (low > 1e-12 && rate(low) > strain_rate)
      low /= 10;
    for (unsigned int i = 0; i < 200 && high > low * (1 + 1e-12); ++i)
      {
        const double middle                       = std::sqrt(low * high);
        (rate(middle) < strain_rate ? low : high) = middle;
      }
    envelope.ductile = std::sqrt(low * high);
    return envelope;
  }

  template class ViscoElastoPlasticRheology<2>;
  LITHOSTRESS_REGISTER_RHEOLOGY(
    ViscoElastoPlasticRheology,
    "visco-elasto-plastic",
    "Elasticity in series with a linear Viscosity, diffusion and "
    "dislocation creep (power laws of the 3-D deviator, temperature "
    "activated; doc/equations.md section 12)")
} // namespace lithostress

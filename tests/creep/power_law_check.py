"""Power-law creep in a homogeneous block (issue 51; doc/equations.md §12).

The block of power_law_block.prm has a uniform strain, so that every point
follows the creep law's ordinary differential equation (G the shear modulus,
s the 3-D deviator, tau = tau_II = sqrt(s:s/2), A_T = A exp(-E/(R T))):
  de/dt = (ds/dt)/(2G) + A_T tau^(n-1) s.
1. Relaxation at a held strain (every boundary displacement prescribed):
   d tau/dt = -2 G A_T tau^n, so
     tau(t) = [tau0^(1-n) + (n-1) 2 G A_T t]^(1/(1-n));
   asserted to 0.5 % over 100 relaxation times 1/(2 G A_T tau0^(n-1)) at
   1200 K, and at 1100 K, where A_T is 15 times smaller (the temperature
   dependence); the error must fall as the step control's tolerance does.
2. n = 1 is Maxwell's law: a linear Viscosity, and diffusion creep with
   A = 1/(2 eta), against the Maxwell rheology's run with the same steps
   (to 1e-9 of the stress) and exp(-t/tau_M).
3. A constant strain rate: tau rises to the steady creep stress
   (eps_II/A_T)^(1/n); the whole curve against an RK4 integration of
   d tau/dt = 2 G (eps_II - A_T tau^n) (steps of 1/500 of the relaxation
   time: its error is far below the tolerance), to 0.5 %.
4. The same block with u_y free (sigma_yy = 0, the strain eps_yy an unknown
   of the step): against an RK4 integration of the point's equations with
   eps_yy = (2 G c_yy - lambda eps_xx)/(lambda + 2 G), to 0.5 %; and the
   Newton iteration of each step converges quadratically in steps of five
   relaxation times (check_quadratic_newton: the order estimate
   log(r_k+1/r_k)/log(r_k/r_k-1) >= 1.7, where a linear iteration gives 1
   and the secant method 1.62),
   with at most 8 iterations per step.
1b. The activation volume: P in exp(-(E + P V)/(R T)) is the full
   stress's pressure plus, in a density-stripped model, the reference
   column's lithostatic pressure (doc/equations.md §12): the relaxation of
   a block under a column of 441 MPa with V = 1e-5 m^3/mol against the
   closed form with A_T = A exp(-(E + P V)/(R T)), to 0.5 %; without
   P_ref the closed form misses by more than ten times that.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import (check, check_quadratic_newton, finish, read_csv, read_prm, run,  # noqa: E402
                       step_newton_residuals)

YEAR = 365.25 * 24 * 3600
R = 8.314
PRM = "creep/power_law_block.prm"
PARTS = ("left", "right", "base", "top")

prm = read_prm(os.path.join(os.path.dirname(os.path.abspath(__file__)), "power_law_block.prm"))
E_young = float(prm["Materials/rock/Young's modulus"])
nu = float(prm["Materials/rock/Poisson's ratio"])
A = float(prm["Materials/rock/Dislocation creep prefactor"])
n = float(prm["Materials/rock/Dislocation creep stress exponent"])
Q = float(prm["Materials/rock/Dislocation creep activation energy"])
G = E_young / (2 * (1 + nu))
lam = E_young * nu / ((1 + nu) * (1 - 2 * nu))
e1, e2 = 2e-4, -1e-4


def tau_of(r):
    """tau_II of a point_history.csv row (s_zz included)."""
    sxx, syy, szz, sxy = r["s_xx"], r["s_yy"], r["s_zz"], r["s_xy"]
    p = (sxx + syy + szz) / 3
    return math.sqrt(0.5 * ((sxx - p) ** 2 + (syy - p) ** 2 + (szz - p) ** 2) + sxy ** 2)


def simulate(name, sets):
    out = os.path.abspath("output_power_law_" + name)
    result = run(PRM, out, 1, sets)
    return out, read_csv(os.path.join(out, "point_history.csv")), result.stdout


def a_t(T):
    return A * math.exp(-Q / (R * T))


def point_ode(strain, a_factor, exponent, times, free_yy=False, viscosity=0.0):
    """RK4 integration of the point's creep c (diagonal, deviatoric) under the
    strain (eps_xx, eps_yy)(t) = strain(t); with free_yy, eps_yy follows from
    sigma_yy = 0. Returns [(t, tau, sigma_xx)] at @p times (seconds)."""
    def state(t, c):
        exx, eyy = strain(t)
        if free_yy:
            eyy = (2 * G * c[1] - lam * exx) / (lam + 2 * G)
        eps = (exx, eyy, 0.0)
        tr = exx + eyy
        sigma = [lam * tr + 2 * G * (eps[i] - c[i]) for i in range(3)]
        p = sum(sigma) / 3
        s = [x - p for x in sigma]
        tau = math.sqrt(0.5 * sum(x * x for x in s))
        return tau, sigma, s

    def rate(t, c):
        tau, _, s = state(t, c)
        f = a_factor * tau ** (exponent - 1) + (1 / (2 * viscosity) if viscosity else 0)
        return [f * x for x in s], tau

    c = [0.0, 0.0, 0.0]
    t = 0.0
    result = []
    for target in times:
        while t < target:
            _, tau = rate(t, c)
            softness = a_factor * tau ** (exponent - 1) + (1 / (2 * viscosity) if viscosity else 0)
            relax = 1 / (2 * G * softness) if softness > 0 else math.inf
            h = min(relax / 500, YEAR, target - t)
            k1, _ = rate(t, c)
            k2, _ = rate(t + h / 2, [c[i] + h / 2 * k1[i] for i in range(3)])
            k3, _ = rate(t + h / 2, [c[i] + h / 2 * k2[i] for i in range(3)])
            k4, _ = rate(t + h, [c[i] + h * k3[i] for i in range(3)])
            c = [c[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]) for i in range(3)]
            t += h
        tau, sigma, _ = state(t, c)
        result.append((target, tau, sigma[0]))
    return result


# 1. Relaxation after a sudden strain, two temperatures, two tolerances.
errors = {}
for T, tolerance in ((1200, 1e-4), (1200, 1e-5), (1100, 1e-4)):
    out, rows, _ = simulate("relaxation_%d_%g" % (T, tolerance),
                            ["Temperature/Function/Expression=%d" % T,
                             "Time stepping/Creep strain tolerance=%g" % tolerance])
    tau0 = tau_of(rows[0])
    exact0 = 2 * G * math.sqrt(0.5 * sum(d * d for d in (e1 - (e1 + e2) / 3, e2 - (e1 + e2) / 3,
                                                         -(e1 + e2) / 3)))
    check(abs(tau0 - exact0) <= 1e-10 * exact0,
          "T = %d K: the elastic tau_II at t = 0 is 2 G e_II (%.6g Pa against %.6g)" % (T, tau0, exact0))
    relaxation_time = 1 / (2 * G * a_t(T) * tau0 ** (n - 1))
    worst = 0.0
    for r in rows:
        exact = (tau0 ** (1 - n) + (n - 1) * 2 * G * a_t(T) * r["time"]) ** (1 / (1 - n))
        worst = max(worst, abs(tau_of(r) - exact) / exact)
    span = rows[-1]["time"] / relaxation_time
    errors[(T, tolerance)] = worst
    if T == 1200:
        check(span >= 99, "T = 1200 K: the run covers %.0f relaxation times (at least 100)" % span)
    check(worst <= 5e-3,
          "relaxation, n = %g, T = %d K, tolerance %g: tau(t) against the closed form over %.0f "
          "relaxation times, largest relative error %.2e (at most 0.5 %%)" % (n, T, tolerance, span, worst))
check(errors[(1200, 1e-4)] / errors[(1200, 1e-5)] >= 3,
      "the relaxation's error falls with the step control's tolerance: %.2e (1e-4) -> %.2e (1e-5)"
      % (errors[(1200, 1e-4)], errors[(1200, 1e-5)]))

# 1b. The pressure of the activation volume includes the reference column's
# lithostatic pressure in a density-stripped model: the block (density 0)
# at depths 15-20 km (Gravity field/Depth origin = 20 km) under a column of
# 3000 kg/m^3 to 15 km and 0 below, so that its stripped body force is zero
# and P_ref = 3000 g 15 km everywhere in it.
V = 1e-5
P_ref = 3000 * 9.81 * 15e3
_, rows, _ = simulate("activation_volume",
                      ["Temperature/Function/Expression=1200",
                       "Materials/rock/Dislocation creep activation volume=%g" % V,
                       "Materials/rock/Density=0", "Loads/Gravity/Enabled=false",
                       "Gravity field/Depth origin=20",
                       "Loads/Density stripping/Reference column=0, 15: 3000; 15, 25: 0"])
tau0 = tau_of(rows[0])
P = P_ref - (rows[0]["s_xx"] + rows[0]["s_yy"] + rows[0]["s_zz"]) / 3


def relaxation_error(pressure):
    a_p = a_t(1200) * math.exp(-pressure * V / (R * 1200))
    return max(abs(tau_of(r) - (tau0 ** (1 - n) + (n - 1) * 2 * G * a_p * r["time"]) ** (1 / (1 - n)))
               / tau_of(r) for r in rows)


with_reference, without_reference = relaxation_error(P), relaxation_error(P - P_ref)
check(with_reference <= 5e-3,
      "activation volume %g m^3/mol under a stripped column: the relaxation with P = P_ref + P_stress "
      "= %.4g MPa, largest relative error %.2e (at most 0.5 %%)" % (V, P / 1e6, with_reference))
check(without_reference >= 10 * 5e-3,
      "the reference pressure matters: without it the closed form is off by %.2e" % without_reference)

# 2. n = 1: a linear viscosity and linear diffusion creep are Maxwell's law.
eta = 1.262304e21
fixed = ["Time stepping/Adaptive time steps=false", "Time stepping/First time step=25",
         "Time stepping/End time=3000", "Time stepping/Output times=0, 500, 1000, 2000, 3000"]
_, maxwell, _ = simulate("maxwell", fixed + ["Materials/rock/Rheology=maxwell",
                                              "Materials/rock/Dislocation creep prefactor=0",
                                              # maxwell reads no creep law: its entries at their defaults
                                              "Materials/rock/Dislocation creep activation energy=0",
                                              "Materials/rock/Viscosity=%.17g" % eta])
scale = 2 * G * max(abs(e1), abs(e2))
for label, sets in (("a linear Viscosity", ["Materials/rock/Viscosity=%.17g" % eta]),
                    ("diffusion creep with n = 1, A = 1/(2 eta)",
                     ["Materials/rock/Diffusion creep prefactor=%.17g" % (1 / (2 * eta))])):
    _, rows, _ = simulate("linear_" + label.split()[1], fixed + ["Materials/rock/Dislocation creep prefactor=0"]
                          + sets)
    worst = max(abs(a[k] - b[k]) for a, b in zip(rows, maxwell) for k in ("s_xx", "s_yy", "s_xy", "s_zz"))
    tau_m = eta / G
    exact_worst = max(abs(tau_of(r) / tau_of(rows[0]) - math.exp(-r["time"] / tau_m)) for r in rows)
    check(len(rows) == len(maxwell) and worst <= 1e-9 * scale,
          "n = 1, %s: the stresses equal the Maxwell rheology's with the same steps (largest "
          "difference %.1e of 2G|e|)" % (label, worst / scale))
    check(exact_worst <= 2e-3,
          "n = 1, %s: tau(t)/tau0 against exp(-t/tau_M), largest difference %.1e (BDF2 with "
          "steps of tau_M/40)" % (label, exact_worst))

# 3. A constant strain rate: build-up to the steady creep stress.
t0 = 1000 * YEAR
rate_sets = ["Time stepping/End time=5000", "Time stepping/Output times=0, 100, 300, 1000, 3000, 5000",
             "Time stepping/Creep strain tolerance=1e-5"]
for part in PARTS:
    rate_sets += ["Boundary conditions/%s/x=e1 * x * t / t0" % part,
                  "Boundary conditions/%s/y=e2 * y * t / t0" % part,
                  "Boundary conditions/%s/Constants=e1=2e-4, e2=-1e-4, t0=%.17g" % (part, t0)]
_, rows, _ = simulate("rate", rate_sets)
times = [r["time"] for r in rows[::2]]
reference = point_ode(lambda t: (e1 * t / t0, e2 * t / t0), a_t(1200), n, times)
worst = max(abs(tau_of(r) - ref[1]) / max(ref[1], 1e-30)
            for r, ref in zip(rows[2::2], reference[1:]))
check(worst <= 5e-3, "constant strain rate: tau(t) against the RK4 integration, largest relative "
      "error %.2e (at most 0.5 %%)" % worst)
edot = math.sqrt(0.5 * sum(d * d for d in (e1 - (e1 + e2) / 3, e2 - (e1 + e2) / 3, -(e1 + e2) / 3))) / t0
steady = (edot / a_t(1200)) ** (1 / n)
final = tau_of(rows[-1])
check(abs(final - steady) <= 5e-3 * steady,
      "constant strain rate: tau at 5 kyr = %.5g Pa, the steady creep stress (eps_II/A_T)^(1/n) = "
      "%.5g Pa (%.2e relative)" % (final, steady, abs(final - steady) / steady))

# 4. sigma_yy = 0: eps_yy is an unknown, Newton's iteration does work.
free = ["Boundary conditions/%s/y=" % part for part in ("left", "right", "top")]
for label, sets in (("adaptive steps", ["Time stepping/Creep strain tolerance=1e-5"]),
                    ("fixed steps of 5 relaxation times",
                     ["Time stepping/Adaptive time steps=false", "Time stepping/First time step=500",
                      "Time stepping/Output times=0, 1000, 3000, 10000"])):
    _, rows, log = simulate("free_" + label.split()[0], free + sets)
    steps = step_newton_residuals(log)
    if label.startswith("adaptive"):
        # Steps of a tenth of a relaxation time converge in two iterations:
        # no triple to estimate the order from.
        check(max(len(r) for r in steps) <= 8 and all(r[-1] <= 1e-8 for r in steps),
              "sigma_yy = 0, adaptive steps: %d steps, at most %d Newton iterations each, every "
              "last residual <= 1e-8" % (len(steps), max(len(r) for r in steps)))
    else:
        check_quadratic_newton("sigma_yy = 0, " + label, steps)
    if label.startswith("adaptive"):
        times = [r["time"] for r in rows[::2]]
        reference = point_ode(lambda t: (e1, e2), a_t(1200), n, times, free_yy=True)
        worst = max(max(abs(tau_of(r) - ref[1]) / ref[1], abs(r["s_xx"] - ref[2]) / abs(ref[2]))
                    for r, ref in zip(rows[::2], reference))
        check(worst <= 5e-3, "sigma_yy = 0: tau_II and sigma_xx against the RK4 integration of the "
              "point's equations, largest relative error %.2e (at most 0.5 %%)" % worst)
        check(max(abs(r["s_yy"]) for r in rows) <= 1e-6 * abs(rows[0]["s_xx"]),
              "sigma_yy = 0: s_yy vanishes (largest %.1e Pa)" % max(abs(r["s_yy"]) for r in rows))
finish()

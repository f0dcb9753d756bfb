"""Homogeneous Maxwell blocks with closed forms (issue 15, verification 2).

Every boundary displacement of the block is prescribed, u = E x f(t) with
E = diag(e1, e2) (plane strain, eps_zz = 0), so the strain is uniform and the
stress has the closed forms (tau = eta/G, K the bulk modulus)
  relaxation, f = 1:        sigma = K tr(E) I + 2 G dev(E) exp(-t/tau)
  constant rate, f = t/tau: sigma = K tr(E) t/tau I + 2 G dev(E) (1 - exp(-t/tau))
(dev on the 3-D tensor, so sigma_zz is checked too).

Two truths are asserted for each integrator:
1. The program reproduces the discrete recurrence of its scheme to round-off:
   with S the scalar factor of 2 G dev(E),
     S_{n+1} = [S_n (1 - (1 - theta) h/tau) + 2 G (f_{n+1} - f_n)] / (1 + theta h/tau)
   (theta = 1 backward Euler, 1/2 trapezoidal; the thesis scheme converges
   to the trapezoidal rule, up to its fixed-point tolerance); for BDF2 (the
   default), with the creep factor c = f - S,
     c_1 (1 + h/(2 tau)) = c_0 + h/(2 tau) (S_0 + f_1)      (trapezoidal start)
     c_{n+1} (1 + 2h/(3 tau)) = (4 c_n - c_{n-1})/3 + 2h/(3 tau) f_{n+1}.
   Q2 elements represent the linear displacement exactly, so nothing else
   enters.
2. The error against the closed form falls with the step as the scheme's
   order: 1 for backward Euler, 2 for theta = 1/2, BDF2 and the thesis
   scheme (steps tau/10, tau/20, tau/40).

Plane stress (sigma_zz = 0, eps_zz free): the in-plane sum A = s_xx + s_yy
and difference D = s_xx - s_yy decouple. With the 3-D deviator creeping,
  eps_xx - eps_yy:  D'/(2G) + D/(2 eta) = (e1 - e2) f'
  eps_xx + eps_yy:  A'/A_e + A/(6 eta) = (e1 + e2) f',
  A_e = 18 G K/(3K + 4G) = E/(1 - nu)  (the elastic plane-stress value),
so D relaxes with tau and A with tau_A = 6 eta/A_e = tau (1 + 4G/(3K)):
  relaxation: D = 2G (e1 - e2) exp(-t/tau),  A = A_e (e1 + e2) exp(-t/tau_A)
  rate:       D = 2G (e1 - e2)(1 - exp(-t/tau)),
              A = A_e (e1 + e2)(tau_A/tau)(1 - exp(-t/tau_A)).
BDF2 and backward Euler must converge to these with their orders, and
sigma_zz must vanish.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, finish, read_csv, read_prm, run  # noqa: E402

YEAR = 365.25 * 24 * 3600
PRM = "viscoelastic/maxwell_block.prm"
PARTS = ("left", "right", "base", "top")


def closed_form(case, t, G, K, tau, e1, e2):
    f = 1.0 if case == "relaxation" else t / tau
    tr = e1 + e2
    dev = (e1 - tr / 3, e2 - tr / 3, -tr / 3)
    S = math.exp(-t / tau) if case == "relaxation" else 1 - math.exp(-t / tau)
    return [K * tr * f + 2 * G * d * S for d in dev]


def closed_form_plane_stress(case, t, G, K, tau, e1, e2):
    """(s_xx, s_yy, s_zz) of the plane-stress block (module docstring)."""
    A_e = 18 * G * K / (3 * K + 4 * G)
    tau_A = tau * (1 + 4 * G / (3 * K))
    if case == "relaxation":
        D = 2 * G * (e1 - e2) * math.exp(-t / tau)
        A = A_e * (e1 + e2) * math.exp(-t / tau_A)
    else:
        D = 2 * G * (e1 - e2) * (1 - math.exp(-t / tau))
        A = A_e * (e1 + e2) * tau_A / tau * (1 - math.exp(-t / tau_A))
    return [(A + D) / 2, (A - D) / 2, 0.0]


def discrete(case, times, h, theta, G, K, tau, e1, e2):
    """The scheme's own recurrence, at the output times (seconds, each a
    multiple of the step h)."""
    tr = e1 + e2
    dev = (e1 - tr / 3, e2 - tr / 3, -tr / 3)
    f = (lambda t: 1.0) if case == "relaxation" else (lambda t: t / tau)
    factors = [f(0.0)]
    for k in range(1, int(round(max(times) / h)) + 1):
        factors.append((factors[-1] * (1 - (1 - theta) * h / tau) + f(k * h) - f((k - 1) * h))
                       / (1 + theta * h / tau))
    return {t: [K * tr * f(t) + 2 * G * d * factors[int(round(t / h))] for d in dev]
            for t in times}


def discrete_bdf2(case, times, h, G, K, tau, e1, e2):
    """BDF2's recurrence (trapezoidal first step) at the output times."""
    tr = e1 + e2
    dev = (e1 - tr / 3, e2 - tr / 3, -tr / 3)
    f = (lambda t: 1.0) if case == "relaxation" else (lambda t: t / tau)
    n = int(round(max(times) / h))
    c = [0.0]
    c.append((c[0] + h / (2 * tau) * (f(0.0) - c[0] + f(h))) / (1 + h / (2 * tau)))
    for k in range(2, n + 1):
        c.append(((4 * c[-1] - c[-2]) / 3 + 2 * h / (3 * tau) * f(k * h)) / (1 + 2 * h / (3 * tau)))
    return {t: [K * tr * f(t) + 2 * G * d * (f(t) - c[int(round(t / h))]) for d in dev]
            for t in times}


def check_order(label, errors, order):
    """The errors at steps tau/10, tau/20, tau/40 fall with the order."""
    rates = [math.log2(errors[i] / errors[i + 1]) for i in range(2)]
    check(all(abs(r - order) < 0.1 for r in rates),
          "%s: error against the closed form %s of 2G|e|, order %s (expected %g)"
          % (label, ", ".join("%.2e" % e for e in errors),
             ", ".join("%.2f" % r for r in rates), order))


def simulate(case, scheme, theta, step_years, plane_state="plane strain"):
    out = os.path.abspath("output_maxwell_%s_%s_%g_%g_%s"
                          % (case, scheme.replace(" ", "_"), theta, step_years,
                             plane_state.replace(" ", "_")))
    sets = ["Plane state=" + plane_state, "Time stepping/Scheme=" + scheme, "Time stepping/Theta=%g" % theta,
            "Time stepping/First time step=%g" % step_years,
            "Time stepping/Fixed point tolerance=1e-12"]
    if case == "rate":
        for part in PARTS:
            sets += ["Boundary conditions/%s/x=e1 * x * t / tau" % part,
                     "Boundary conditions/%s/y=e2 * y * t / tau" % part,
                     "Boundary conditions/%s/Constants=e1=2e-4, e2=-1e-4, tau=%.17g"
                     % (part, 1000 * YEAR)]
    run(PRM, out, 1, sets)
    return out


prm = read_prm(os.path.join(os.path.dirname(os.path.abspath(__file__)), "maxwell_block.prm"))
E = float(prm["Materials/rock/Young's modulus"])
nu = float(prm["Materials/rock/Poisson's ratio"])
eta = float(prm["Materials/rock/Viscosity"])
G, K = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
tau = eta / G
check(abs(tau / YEAR - 1000) < 1e-9, "tau = eta/G = %.9g years" % (tau / YEAR))
e1, e2 = 2e-4, -1e-4
scale = 2 * G * max(abs(e1), abs(e2))       # the size of the deviatoric stress

for case in ("relaxation", "rate"):
    for scheme, theta, order in (("generalized midpoint", 1.0, 1.0),
                                 ("generalized midpoint", 0.5, 2.0),
                                 ("BDF2", 1.0, 2.0), ("thesis", 1.0, 2.0)):
        label = "%s, %s%s" % (case, scheme, ", theta = 0.5" if theta == 0.5 else "")
        errors = []
        for h in (100.0, 50.0, 25.0):
            out = simulate(case, scheme, theta, h)
            rows = read_csv(os.path.join(out, "point_history.csv"))
            times = sorted({r["time"] for r in rows})
            check(len(rows) == 2 * 5 and abs(times[-1] / YEAR - 3000) < 1e-6
                  and abs(times[2] - 1000 * YEAR) <= 1e-12 * times[2],
                  "%s, h = %g yr: output times 0, 500, 1000, 2000, 3000 yr landed on exactly (s)"
                  % (label, h))
            if scheme == "BDF2":
                ref = discrete_bdf2(case, [r["time"] for r in rows], h * YEAR, G, K, tau, e1, e2)
            else:
                ref = discrete(case, [r["time"] for r in rows], h * YEAR,
                               0.5 if scheme == "thesis" else theta, G, K, tau, e1, e2)
            worst_discrete = worst_exact = worst_shear = 0.0
            for r in rows:
                got = (r["s_xx"], r["s_yy"], r["s_zz"])
                exact = closed_form(case, r["time"], G, K, tau, e1, e2)
                worst_discrete = max(worst_discrete,
                                     max(abs(a - b) for a, b in zip(got, ref[r["time"]])) / scale)
                worst_exact = max(worst_exact, max(abs(a - b) for a, b in zip(got, exact)) / scale)
                worst_shear = max(worst_shear, abs(r["s_xy"]) / scale)
            # Round-off: the prescribed strain is ~1e-4 and the stress
            # ~1e7 Pa, CG to 1e-10; the thesis scheme stops at a relative
            # stress change of 1e-12 per step.
            check(worst_discrete < 1e-8,
                  "%s, h = %g yr: the scheme's recurrence reproduced, largest difference %.1e of 2G|e|"
                  % (label, h, worst_discrete))
            check(worst_shear < 1e-8, "%s, h = %g yr: no shear stress (%.1e)" % (label, h, worst_shear))
            errors.append(worst_exact)
        check_order(label, errors, order)

for case in ("relaxation", "rate"):
    for scheme, order in (("BDF2", 2.0), ("generalized midpoint", 1.0)):
        label = "plane stress, %s, %s" % (case, scheme)
        errors = []
        for h in (100.0, 50.0, 25.0):
            out = simulate(case, scheme, 1.0, h, "plane stress")
            rows = read_csv(os.path.join(out, "point_history.csv"))
            worst_exact = worst_zz = 0.0
            for r in rows:
                exact = closed_form_plane_stress(case, r["time"], G, K, tau, e1, e2)
                worst_exact = max(worst_exact, max(abs(a - b) for a, b in
                                                   zip((r["s_xx"], r["s_yy"]), exact)) / scale)
                worst_zz = max(worst_zz, abs(r["s_zz"]) / scale)
            check(len(rows) == 2 * 5 and worst_zz < 1e-8,
                  "%s, h = %g yr: sigma_zz = 0 (largest %.1e of 2G|e|)" % (label, h, worst_zz))
            errors.append(worst_exact)
        check_order(label, errors, order)
finish()

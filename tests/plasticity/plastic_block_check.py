"""Drucker-Prager plasticity in a homogeneous block (issue 51;
doc/equations.md §13).

Every boundary displacement of plastic_block.prm follows u = E x t with
E = diag(e1, e2), plane strain: the strain is uniform and rises
proportionally, so that the trial deviator keeps the direction of dev(E)
and backward Euler's return is exact whatever the step (the end state of a
monotone proportional path depends on the end strain alone). With
e_II = sqrt(dev(E):dev(E)/2), K, G the moduli, gamma the accumulated
plastic strain (its e_II) and P = -tr(sigma)/3:
  elastic:  tau = 2 G e_II t,  P = -K tr(E) t;
  yielding: tau = 2 G (e_II t - gamma),  P = -K tr(E) t + 2 K sin(psi) gamma,
            tau = C(gamma) cos(phi(gamma)) + P sin(phi(gamma)),
a scalar equation for gamma (linear without softening:
gamma = [2G e_II t - C cos(phi) + K tr(E) t sin(phi)] / (2G + 2K sin(psi) sin(phi))).
The stress is sigma = -P 1 + tau dev(E)/e_II. Asserted to 1e-9 of tau:
1. phi = 30 deg, psi = 0: the yield stress rises with the pressure; a
   second confinement (e2 = 0) changes tau at yield by sin(phi) times the
   change of P;
2. psi = 10 deg: the dilation's pressure;
3. softening of C and phi over gamma in (0, 1e-4);
4. extension with a Tensile strength of 1 MPa: the mean stress stays at
   1 MPa once reached (P = -1 MPa), tau = min(2 G e_II t, C cos(phi) - sin(phi) 1 MPa).
5. u_y free (sigma_yy = 0; eps_yy an unknown) with psi = 0 < phi, whose
   consistent tangent is unsymmetric: Newton's iteration through GMRES with
   the matrix-free multigrid, GMRES with AMG and the direct solver (KLU)
   converges quadratically (check_quadratic_newton: order estimate >= 1.7),
   at most 8 iterations per step (Newton from the step's start, `Newton
   start = step start`: from the default extrapolation the steps end in
   three iterations, too few for an order estimate above the linear
   solves' accuracy), sigma_yy = 0 and tau on the yield surface at every
   output once yielding; the three solvers agree to 1e-8 of tau.
6. The strength envelope of a stress-depth profile (Output/Strength
   envelope strain rate 1e-15 1/s) with a linear viscosity eta and
   dislocation creep A tau^n added: tau_II is the sample's, strength_brittle
   C cos(phi) + P sin(phi) at the sample's pressure, strength_ductile the
   root of tau/(2 eta) + A tau^n = 1e-15 (bisection here), strength their
   minimum, each to 1e-9; the ParaView record lists effective_viscosity,
   strain_rate_II, yielding and plastic_strain.
7. Density stripping: the brittle strength adds the reference column's
   lithostatic pressure P_ref(d) = g sum rho_i h_i (a column of three
   densities whose interval bottoms cross the block) to the pressure of
   the stripped stress, to 1e-9.
8. Load steps: the block confined laterally under a pressure on its top
   raised by Loads/Slab pull/Time factor = t/2 to 50 MPa: sigma_yy follows
   the factor and the stress the closed form of the uniaxial strain at
   each output, through yield, to 1e-8 (the direct solver's tolerance on an
   unsymmetric tangent).
Case 1 also asserts the profile's plastic_strain and yielding columns.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import (check, check_quadratic_newton, finish, read_csv, read_prm, run,  # noqa: E402
                       step_newton_residuals)

PRM = "plasticity/plastic_block.prm"
PARTS = ("left", "right", "base", "top")
prm = read_prm(os.path.join(os.path.dirname(os.path.abspath(__file__)), "plastic_block.prm"))
E_young = float(prm["Materials/rock/Young's modulus"])
nu = float(prm["Materials/rock/Poisson's ratio"])
G = E_young / (2 * (1 + nu))
K = E_young / (3 * (1 - 2 * nu))
C0 = float(prm["Materials/rock/Cohesion"])
PHI0 = math.radians(float(prm["Materials/rock/Friction angle"]))


def tau_p(r):
    """tau_II and P of a point_history.csv row."""
    sxx, syy, szz, sxy = r["s_xx"], r["s_yy"], r["s_zz"], r["s_xy"]
    p = (sxx + syy + szz) / 3
    return math.sqrt(0.5 * ((sxx - p) ** 2 + (syy - p) ** 2 + (szz - p) ** 2) + sxy ** 2), -p


def strain_sets(e1, e2):
    sets = []
    for part in PARTS:
        sets.append("Boundary conditions/%s/Constants=e1=%.17g, e2=%.17g" % (part, e1, e2))
    return sets


def closed_form(t, e1, e2, strength, psi=0.0, cutoff=None):
    """(tau, P) at t for the strength(gamma) -> (C cos phi, sin phi)."""
    tr = e1 + e2
    dev = (e1 - tr / 3, e2 - tr / 3, -tr / 3)
    e_ii = math.sqrt(0.5 * sum(d * d for d in dev))
    p_trial = -K * tr * t
    tension = cutoff is not None and p_trial < -cutoff
    p0 = -cutoff if tension else p_trial
    dil = 0.0 if tension else 2 * K * math.sin(psi)

    def residual(gamma):
        c_term, sin_phi = strength(gamma)
        tau_yield = max(c_term + (p0 + dil * gamma) * sin_phi, 0.0)
        return 2 * G * (e_ii * t - gamma) - tau_yield

    if residual(0.0) <= 0:
        return 2 * G * e_ii * t, p0
    lo, hi = 0.0, e_ii * t
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if residual(mid) > 0:
            lo = mid
        else:
            hi = mid
    gamma = 0.5 * (lo + hi)
    return 2 * G * (e_ii * t - gamma), p0 + dil * gamma


def perfect(c, phi):
    return lambda gamma: (c * math.cos(phi), math.sin(phi))


def simulate(name, sets):
    out = os.path.abspath("output_plastic_block_" + name)
    result = run(PRM, out, 1, sets)
    return read_csv(os.path.join(out, "point_history.csv")), result.stdout


def compare(label, rows, e1, e2, strength, psi=0.0, cutoff=None):
    worst, yielded = 0.0, 0
    for r in rows:
        tau, p = tau_p(r)
        ref_tau, ref_p = closed_form(r["time"], e1, e2, strength, psi, cutoff)
        yielded += ref_tau < 2 * G * math.sqrt(0.5 * sum(
            d * d for d in (e1 - (e1 + e2) / 3, e2 - (e1 + e2) / 3, -(e1 + e2) / 3))) * r["time"] * (1 - 1e-9)
        worst = max(worst, abs(tau - ref_tau) / ref_tau, abs(p - ref_p) / max(ref_tau, abs(ref_p)))
    check(worst <= 1e-9 and yielded >= 4,
          "%s: tau_II and P against the closed form at %d outputs (%d of them yielding), largest "
          "relative difference %.1e" % (label, len(rows), yielded, worst))
    return worst


# 1. Pressure-dependent yield, two confinements.
e1, e2 = -2e-4, 0.5e-4
rows, _ = simulate("phi30", ["Output/Stress-depth profiles=5"])
compare("phi = 30 deg, psi = 0", rows, e1, e2, perfect(C0, PHI0))
# The profile's plastic_strain is gamma = e_II t - tau/(2G) at the end
# (t = 2 s), the same at every point, and yielding is 1 there.
tau_end, _ = closed_form(2.0, e1, e2, perfect(C0, PHI0))
e_ii = math.sqrt(0.5 * sum(d * d for d in (e1 - (e1 + e2) / 3, e2 - (e1 + e2) / 3, -(e1 + e2) / 3)))
gamma_end = e_ii * 2.0 - tau_end / (2 * G)
profile = read_csv(os.path.join(os.path.abspath("output_plastic_block_phi30"), "stress_depth_x5.csv"))
worst = max(abs(r["plastic_strain"] - gamma_end) for r in profile) / gamma_end
check(len(profile) == 101 and gamma_end > 0 and worst <= 1e-9
      and all(abs(r["yielding"] - 1) <= 1e-12 for r in profile),
      "the profile's plastic_strain %.6g is gamma of the closed form to %.1e and yielding is 1 at its %d points"
      % (gamma_end, worst, len(profile)))
rows_b, _ = simulate("phi30_confined", strain_sets(e1, 0.0))
compare("phi = 30 deg, psi = 0, e2 = 0", rows_b, e1, 0.0, perfect(C0, PHI0))
last_a, last_b = rows[-1], rows_b[-1]
(tau_a, p_a), (tau_b, p_b) = tau_p(last_a), tau_p(last_b)
check(abs((tau_b - tau_a) - math.sin(PHI0) * (p_b - p_a)) <= 1e-9 * tau_a,
      "the yield stress depends on the pressure: at t = 2 s, delta tau = %.6g Pa = sin(phi) delta P "
      "(delta P = %.6g Pa)" % (tau_b - tau_a, p_b - p_a))

# 2. Dilation.
psi = math.radians(10)
rows, _ = simulate("dilation", ["Materials/rock/Dilation angle=10"])
compare("phi = 30 deg, psi = 10 deg", rows, e1, e2, perfect(C0, PHI0), psi)

# 3. Softening over gamma in (0, 1e-4): C 2 -> 0.5 MPa, phi 30 -> 20 deg.
def softened(gamma):
    w = min(max(gamma / 1e-4, 0.0), 1.0)
    c = C0 + w * (0.5e6 - C0)
    phi = PHI0 + w * (math.radians(20) - PHI0)
    return c * math.cos(phi), math.sin(phi)


rows, _ = simulate("softening", ["Materials/rock/Cohesion after softening=0.5e6",
                                 "Materials/rock/Friction angle after softening=20",
                                 "Materials/rock/Softening plastic strain=0, 1e-4"])
compare("softening of C and phi", rows, e1, e2, softened)

# 4. Extension with a tension cut-off.
rows, _ = simulate("tension", strain_sets(2e-4, 1e-4) + ["Materials/rock/Tensile strength=1e6"])
compare("extension, Tensile strength 1 MPa", rows, 2e-4, 1e-4, perfect(C0, PHI0), 0.0, 1e6)
check(all(tau_p(r)[1] >= -1e6 * (1 + 1e-9) for r in rows),
      "extension: the mean stress never exceeds the tensile strength (largest %.6g Pa)"
      % max(-tau_p(r)[1] for r in rows))

# 5. sigma_yy = 0: an unsymmetric tangent, three solvers.
free = ["Boundary conditions/%s/y=" % part for part in ("left", "right", "top")]
results = {}
for solver in ("matrix-free multigrid", "AMG", "direct"):
    rows, log = simulate("free_" + solver.split()[0],
                         free + ["Solver/Type=" + solver, "Time stepping/Newton start=step start"])
    check_quadratic_newton("sigma_yy = 0, " + solver, step_newton_residuals(log))
    on_surface = 0
    for r in rows:
        tau, p = tau_p(r)
        yield_stress = C0 * math.cos(PHI0) + p * math.sin(PHI0)
        check(abs(r["s_yy"]) <= 1e-6 * tau and tau <= yield_stress * (1 + 1e-9),
              "sigma_yy = 0, %s, t = %g s: s_yy = %.1e Pa, tau = %.6g Pa within the yield stress %.6g Pa"
              % (solver, r["time"], r["s_yy"], tau, yield_stress))
        on_surface += abs(tau - yield_stress) <= 1e-9 * yield_stress
    check(on_surface >= 6, "sigma_yy = 0, %s: %d of %d outputs on the yield surface"
          % (solver, on_surface, len(rows)))
    results[solver] = rows
scale = max(tau_p(r)[0] for r in results["direct"])
worst = max(abs(a[k] - b[k]) for s in ("matrix-free multigrid", "AMG")
            for a, b in zip(results[s], results["direct"]) for k in ("s_xx", "s_yy", "s_zz"))
check(worst <= 1e-8 * scale, "sigma_yy = 0: the three solvers agree to %.1e of tau" % (worst / scale))

# 6. The strength envelope and the ParaView fields of the rock's flow.
ETA, A_DISL, N_DISL, RATE = 1e22, 1e-30, 3.5, 1e-15
out = os.path.abspath("output_plastic_block_envelope")
run(PRM, out, 1, ["Output/Write ParaView files=true", "Output/Stress-depth profiles=5",
                  "Materials/rock/Viscosity=%g" % ETA, "Materials/rock/Dislocation creep prefactor=%g" % A_DISL])
profile = read_csv(os.path.join(out, "stress_depth_x5.csv"))
lo, hi = 1.0, 1e12
for _ in range(200):
    mid = math.sqrt(lo * hi)
    if mid / (2 * ETA) + A_DISL * mid ** N_DISL < RATE:
        lo = mid
    else:
        hi = mid
ductile = math.sqrt(lo * hi)
worst = 0.0
for r in profile:
    mean = (r["sigma_xx"] + r["sigma_yy"] + r["sigma_zz"]) / 3
    tau = math.sqrt(0.5 * ((r["sigma_xx"] - mean) ** 2 + (r["sigma_yy"] - mean) ** 2
                           + (r["sigma_zz"] - mean) ** 2) + r["sigma_xy"] ** 2)
    brittle = C0 * math.cos(PHI0) - mean * math.sin(PHI0)
    worst = max(worst, abs(r["tau_II"] - tau) / tau, abs(r["strength_brittle"] - brittle) / brittle,
                abs(r["strength_ductile"] - ductile) / ductile,
                abs(r["strength"] - min(brittle, ductile)) / min(brittle, ductile))
check(len(profile) == 101 and worst <= 1e-9,
      "strength envelope at %d profile points: tau_II, brittle %.6g Pa, ductile %.6g Pa and their minimum "
      "to %.1e" % (len(profile), profile[0]["strength_brittle"], ductile, worst))

# 7. Under density stripping the yield pressure adds the reference column's
# lithostatic pressure: the block at depths 15-20 km (Gravity field/Depth
# origin = 20 km) under a column of three densities whose bottoms at 16 and
# 18 km cross it; strength_brittle = C cos(phi) + (P_ref(d) + P) sin(phi).
COLUMN = ((0.0, 16e3, 2700.0), (16e3, 18e3, 3000.0), (18e3, 25e3, 3300.0))


def column_pressure(d):
    return 9.81 * sum(rho * max(0.0, min(d, bottom) - top) for top, bottom, rho in COLUMN)


stripped = os.path.abspath("output_plastic_block_stripped")
run(PRM, stripped, 1, ["Output/Stress-depth profiles=5", "Loads/Gravity/Enabled=false",
                       "Gravity field/Depth origin=20",
                       "Loads/Density stripping/Reference column=" +
                       "; ".join("%g, %g: %g" % (t / 1e3, b / 1e3, rho) for t, b, rho in COLUMN)])
worst = 0.0
for r in read_csv(os.path.join(stripped, "stress_depth_x5.csv")):
    mean = (r["sigma_xx"] + r["sigma_yy"] + r["sigma_zz"]) / 3
    brittle = C0 * math.cos(PHI0) + (column_pressure(20e3 - r["y"]) - mean) * math.sin(PHI0)
    worst = max(worst, abs(r["strength_brittle"] - brittle) / brittle)
check(worst <= 1e-9, "density stripping: strength_brittle with the column's pressure (%.4g to %.4g MPa) "
      "to %.1e" % (column_pressure(15e3) / 1e6, column_pressure(20e3) / 1e6, worst))

# 8. Load steps (Loads/Slab pull/Time factor): the block confined
# laterally (u_x = 0 on both sides, u_y = 0 at the base) under a pressure
# p f(t) on its top, f = t/2 (50 MPa at t = 2 s): sigma_yy = -p f(t)
# exactly, and the strain is uniaxial, eps = diag(0, e, 0), a proportional
# path whose state at each output is the closed form of the strain
# e1 = 0, e2 = e (t = 1) with e the root of sigma_yy(e) = -p f(t).
PRESSURE, WIDTH = 50e6, 10e3


def confined(load):
    def sigma_yy(e):
        tau, p = closed_form(1.0, 0.0, e, perfect(C0, PHI0))
        return -p - tau * (2.0 / 3.0) / math.sqrt(1.0 / 3.0)
    lo, hi = -1.0, 0.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if sigma_yy(mid) < -load:
            lo = mid
        else:
            hi = mid
    return closed_form(1.0, 0.0, 0.5 * (lo + hi), perfect(C0, PHI0))


# The block's input without the top's prescribed displacement (a part
# that prescribes nothing is refused, so the top leaves the list).
text = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "plastic_block.prm")).read()
text = re.sub(r"\n  subsection top\n.*?\n  end", "", text, flags=re.S).replace(
    "Prescribed displacement parts = left, right, base, top", "Prescribed displacement parts = left, right, base")
check("subsection top" not in text and "parts = left, right, base\n" in text,
      "load steps: the block's input without the top's prescribed displacement")
loaded_prm = os.path.abspath("plastic_block_loaded_top.prm")
with open(loaded_prm, "w") as f:
    f.write(text)
steps_sets = ["Boundary conditions/left/x=0", "Boundary conditions/left/y=",
              "Boundary conditions/right/x=0", "Boundary conditions/right/y=",
              "Boundary conditions/base/x=", "Boundary conditions/base/y=0",
              "Loads/Slab pull/Enabled=true", "Loads/Slab pull/Boundary part=top",
              "Loads/Slab pull/Vertical force=%.17g" % (PRESSURE * WIDTH),
              "Loads/Slab pull/Time factor=t/2"]
loaded_out = os.path.abspath("output_plastic_block_load_steps")
result = run(loaded_prm, loaded_out, 1, steps_sets)
rows = read_csv(os.path.join(loaded_out, "point_history.csv"))
# The issue's bound on Newton's iterations per step (its order is case 5's:
# a step where points start to yield mid-iteration converges more slowly).
newton = step_newton_residuals(result.stdout)
check(len(newton) >= 20 and max(len(r) for r in newton) <= 8,
      "load steps: %d steps, at most %d Newton iterations each (at most 8)"
      % (len(newton), max(len(r) for r in newton)))
worst, yielded = 0.0, 0
for r in rows:
    load = PRESSURE * r["time"] / 2
    tau, p = tau_p(r)
    ref_tau, ref_p = confined(load)
    yielded += ref_tau < (1 - 1e-6) * (1 - 2 * nu) / (1 - nu) * load / math.sqrt(3)
    worst = max(worst, abs(r["s_yy"] + load) / load, abs(tau - ref_tau) / ref_tau,
                abs(p - ref_p) / ref_p)
check(len(rows) >= 5 and yielded >= 3 and worst <= 1e-8,
      "load steps: sigma_yy = -p t/2, tau_II and P of the confined closed form at %d outputs (%d yielding), "
      "largest relative difference %.1e" % (len(rows), yielded, worst))

record = open(os.path.join(out, "solution_005.pvtu")).read()
fields = ("effective_viscosity", "strain_rate_II", "yielding", "plastic_strain")
check(all('Name="%s"' % f in record for f in fields),
      "the ParaView record lists %s" % ", ".join(fields))
finish()

"""Stress amplification (issue 15, verification 3): prm/stress_amplification.prm,
an elastic layer (30 km) over a Maxwell layer (70 km, eta/G = 0.042 Myr)
pushed by a rigid edge with 3e12 N/m, against the exact history of
tests/viscoelastic/amplification_reference.py.

The exact solution is laterally uniform with a displacement linear in x and
piecewise linear in y, which Q2 elements represent exactly: what remains is
the time discretisation, so the tolerances are those of the schemes:
* BDF2 (the default) with the .prm's step tolerance 1e-3: measured 3.9e-4
  of sigma_0 = F/h_e = 100 MPa at the worst output time, checked < 1e-3;
* backward Euler (generalized midpoint, theta = 1) with the same step
  control: first order, measured 2.2e-3, checked < 3e-3;
* the trapezoidal rule (theta = 1/2) with the same step control: measured
  1.3e-5, checked < 1e-4 -- the spread between the three schemes shows the
  error is the time step's alone;
* t = 0: the layers share F in the ratio of E h / (1 - nu^2), to round-off;
* 5 Myr (120 Maxwell times): the force over the elastic layer, the integral
  of sigma_xx over its depth, is F to 1e-4 (the exact remainder is 1e-6,
  the schemes' lag < 2e-5), and the Maxwell layer's deviatoric stress is
  below 1e-4 sigma_0: the elastic layer carries the whole load;
* 2 ranks (the rigid edge's constraint then spans ranks) give the same
  history to 1e-9.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
import amplification_reference as reference  # noqa: E402
from lithotest import check, finish, read_csv, read_prm, run  # noqa: E402

PRM = os.path.join(os.path.dirname(os.path.dirname(HERE)), "prm", "stress_amplification.prm")
prm = read_prm(PRM)
check(prm["Boundary conditions/right/x"] == "rigid"
      and prm["Loads/Tractions/right/Resultant force"] == "-3e12, 0"
      and prm["Materials/viscoelastic/Viscosity"] == "1e23",
      "the .prm: rigid right edge, 3e12 N/m, eta = 1e23 Pa s")
model = reference.model()
exact = reference.history(model)
SIGMA0 = model["F"] / model["h_e"]
H_E = model["h_e"]


def history(out):
    """{(time, point): (s_xx, s_zz)}; point 1 in the elastic layer, 2 below."""
    return {(r["time"], int(r["point"])): (r["s_xx"], r["s_zz"])
            for r in read_csv(os.path.join(out, "point_history.csv"))}


def worst_error(values):
    worst = 0.0
    for (t, point), (sxx, szz) in values.items():
        e = exact(t)[0:2] if point == 1 else exact(t)[2:4]
        worst = max(worst, abs(sxx - e[0]) / SIGMA0, abs(szz - e[1]) / SIGMA0)
    return worst


# Profile points avoid the interface at 30 km (40 points over 100 km).
PROFILE = ["Output/Points per profile=40"]
default = os.path.abspath("output_amplification")
run(PRM, default, 1, PROFILE)
values = history(default)
check(len(values) == 18, "two points at nine output times")
err_bdf2 = worst_error(values)
check(err_bdf2 < 1e-3, "BDF2 against the exact history: %.2e sigma_0" % err_bdf2)

MIDPOINT = "Time stepping/Scheme=generalized midpoint"
euler = os.path.abspath("output_amplification_backward_euler")
run(PRM, euler, 1, [MIDPOINT])
err_euler = worst_error(history(euler))
check(err_euler < 3e-3, "backward Euler against the exact history: %.2e sigma_0" % err_euler)

trapezoid = os.path.abspath("output_amplification_trapezoid")
run(PRM, trapezoid, 1, [MIDPOINT, "Time stepping/Theta=0.5"])
err_trapezoid = worst_error(history(trapezoid))
check(err_trapezoid < 1e-4, "trapezoidal rule against the exact history: %.2e sigma_0" % err_trapezoid)

# t = 0: the elastic share of the force.
Ep = lambda E, nu: E / (1 - nu ** 2)  # noqa: E731
share = (Ep(model["E_e"], model["nu_e"]) * H_E
         / (Ep(model["E_e"], model["nu_e"]) * H_E + Ep(model["E_v"], model["nu_v"]) * model["h_v"]))
s0 = values[(0.0, 1)][0]
check(abs(s0 * H_E / -model["F"] - share) < 1e-9,
      "t = 0: the elastic layer carries %.6f of the force (E h / (1 - nu^2) share %.6f)"
      % (s0 * H_E / -model["F"], share))
print("     elastic sigma_xx: %.2f MPa at t = 0, %.2f MPa at 5 Myr (exact %.2f)"
      % (s0 / 1e6, values[(max(t for t, _ in values), 1)][0] / 1e6, exact(5 * 3.15576e13)[0] / 1e6))

# 5 Myr: the integral of sigma_xx over the elastic layer (trapezoidal rule
# on the profile points inside it, the stress held constant to the
# interface: it is uniform in depth).
profile = read_csv(os.path.join(default, "stress_depth_x250.csv"))
inside = [(r["depth"], r["sigma_xx"]) for r in profile if r["depth"] < H_E]
force = sum(0.5 * (a[1] + b[1]) * (b[0] - a[0]) for a, b in zip(inside, inside[1:]))
force += inside[0][1] * inside[0][0] + inside[-1][1] * (H_E - inside[-1][0])
check(abs(force / -model["F"] - 1) < 1e-4,
      "5 Myr: integral of sigma_xx over the elastic layer %.6e N/m = %.6f of the applied force"
      % (force, force / -model["F"]))
below = [r for r in profile if r["depth"] > H_E]
deviatoric = max(max(abs(r["deviatoric_xx"]), abs(r["deviatoric_yy"]), abs(r["deviatoric_zz"]),
                     abs(r["deviatoric_xy"])) for r in below)
check(deviatoric < 1e-4 * SIGMA0,
      "5 Myr: largest deviatoric stress in the Maxwell layer %.3g Pa (< 1e-4 sigma_0)" % deviatoric)

# 2 ranks.
parallel = os.path.abspath("output_amplification_2_ranks")
run(PRM, parallel, 2)
other = history(parallel)
gap = max(abs(a - b) / SIGMA0 for k in values for a, b in zip(values[k], other[k]))
check(gap < 1e-9, "2 ranks against 1: largest difference %.1e sigma_0" % gap)
finish()

"""Faults (issue 16, first part).

A locked fault: tests/faults/locked_fault.prm, a
block cut by a planar fault, under gravity and a uniform horizontal strain
e. The exact solution (plane strain, sigma_yy = rho g y from the free top,
sigma_xx = nu/(1 - nu) sigma_yy + E/(1 - nu^2) e, u_x = e x,
u_y = integral of eps_yy from the base) is linear in x and quadratic in y,
so it lies in the Q2 space; with the fault locked by exact constraints the
two displacement fields must reproduce it to round-off:
* Q2 on adaptively refined meshes whose fault faces hang from either side
  (four cycles), on 1 and 2 ranks;
* Q1 without gravity (then the solution is linear), where the constraints
  of a hanging fault face interpolate linearly.
Round-off: the solver stops at 1e-12 of the right-hand side; the points'
values are compared relative to the largest displacement and stress:
1e-9.

An elastic fault: tests/faults/elastic_fault.prm, a block cut by a
vertical fault with normal stiffness k_n [Pa/m] per unit area, pulled
apart by a displacement delta of its right side: the two blocks and the
interface are springs in series, sigma_xx = delta / ((a + b)/E' + 1/k_n)
uniform (E' = E/(1 - nu^2), sigma_yy = 0), the fault opens by
sigma_xx/k_n, and u is linear in each block, so it is exact on every mesh
(Q2, three cycles of global refinement, 1 and 2 ranks): the
stiffness is per unit area, the answer does not depend on the mesh.
In shear (tests/faults/elastic_fault_shear.prm: left side fixed, shear
traction tau on top, base and right side, k_s given the thesis's way as an
element stiffness of 1e10 N/m for 1 km fault elements, i.e. 1e7 Pa/m):
sigma_xy = tau everywhere, u = (0, tau x/G) plus the slip tau/k_s in the
hanging wall.

A frictional fault (the interface patch test, tests/faults/frictional_fault.prm):
the same block and vertical fault with nu = 0 (so that a uniform stress
fits the fixed left side), k_s = 1e7 Pa/m, k_n = 1e10 Pa/m, mu = 0.6 and
no lithostatic or pore-pressure term, under a normal pressure P = 100 MPa.
Sliding: the right side moved up by d = 40 m, top and base loaded with
tau_F = mu P; the fault must slide with shear traction exactly mu |sigma_n|
everywhere, and the hanging wall moves up by the slip d - tau_F L/G
relative to the footwall (u_y = tau_F x/G in the footwall). Stuck:
tractions tau = 30 MPa < mu P on top, base and right side: slip tau/k_s,
every point stuck, one solve. Both are linear in each block, so exact on
every mesh (two cycles, 1 and 2 ranks). The thesis iteration (excess shear
as forces, factor 1) reaches the same state within its stopping tolerance.

A prescribed slip (tests/faults/prescribed_slip.prm): the locked-fault block
with its left side fixed and no load, the fault given a uniform slip of 2 m
down the dip and an opening of 0.5 m: the hanging wall moves rigidly by
w = 2 d + 0.5 n, the footwall stays, both stress-free, on adaptive meshes
with hanging fault faces, 1 and 2 ranks: to round-off (displacements 1e-9
of |w|, stresses 1e-9 of E |w| / L).
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, check_settled_newton, finish, newton_solves, read_csv, run  # noqa: E402

PRM = "faults/locked_fault.prm"
E, NU, RHO, G, STRAIN = 0.85e11, 0.25, 2750.0, 9.81, 1e-4
BASE = -10e3


def exact(x, y, gravity=True):
    """(u_x, u_y, s_xx, s_yy, s_xy, s_zz) of the block."""
    g = G if gravity else 0.0
    a = NU / (1 - NU)
    b = E / (1 - NU ** 2) * STRAIN
    s_yy = RHO * g * y
    s_xx = a * s_yy + b
    # eps_yy = (1 + nu)/E [(1 - nu) s_yy - nu s_xx], integrated from the base.
    c = (1 + NU) / E
    u_y = c * (((1 - NU) - NU * a) * RHO * g * (y * y - BASE * BASE) / 2 - NU * b * (y - BASE))
    return (STRAIN * x, u_y, s_xx, s_yy, 0.0, NU * (s_xx + s_yy))


def compare(out, gravity, label):
    rows = read_csv(os.path.join(out, "point_values.csv"))
    keys = ("u_x", "u_y", "sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz")
    exacts = [exact(r["x"], r["y"], gravity) for r in rows]
    u_scale = max(max(abs(e[0]), abs(e[1])) for e in exacts)
    s_scale = max(max(abs(v) for v in e[2:]) for e in exacts)
    worst = 0.0
    for r, e in zip(rows, exacts):
        for k, v in zip(keys, e):
            worst = max(worst, abs(r[k] - v) / (u_scale if k[0] == "u" else s_scale))
    check(len(rows) == 6 and worst < 1e-9,
          "%s: %d points on, beside and away from the fault equal the exact solution, "
          "largest relative difference %.1e" % (label, len(rows), worst))


for ranks in (1, 2):
    out = os.path.abspath("output_locked_fault_%d" % ranks)
    result = run(PRM, out, ranks)
    cycles = [line for line in result.stdout.splitlines() if re.match(r"cycle \d+: ", line)]
    check(len(cycles) == 4, "Q2, %d rank(s): 4 adaptive cycles (%s)" % (ranks, cycles[-1] if cycles else "none"))
    compare(out, True, "Q2, %d rank(s)" % ranks)

def elastic_exact(x, y, delta=10.0, k_n=1e7, a=5e3, b=5e3, plane_stress=False):
    """(u_x, u_y, s_xx, s_yy, s_xy, s_zz) of the elastic-fault block: in
    plane strain E' = E/(1 - nu^2), eps_yy = -nu (1 + nu) s/E and s_zz = nu
    s; in plane stress E' = E, eps_yy = -nu s/E and s_zz = 0."""
    Ep = E if plane_stress else E / (1 - NU ** 2)
    s = delta / ((a + b) / Ep + 1 / k_n)
    u_x = s * x / Ep + (s / k_n if x > a else 0.0)
    eps_yy = -NU * s / E if plane_stress else -NU * (1 + NU) * s / E
    return (u_x, eps_yy * (y - BASE), s, 0.0, 0.0, 0.0 if plane_stress else NU * s)


for ranks in (1, 2):
    out = os.path.abspath("output_elastic_fault_%d" % ranks)
    run("faults/elastic_fault.prm", out, ranks)
    rows = read_csv(os.path.join(out, "point_values.csv"))
    keys = ("u_x", "u_y", "sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz")
    exacts = [elastic_exact(r["x"], r["y"]) for r in rows]
    worst = max(abs(r[k] - v) / max(abs(e[2]) if k[0] == "s" else abs(e[0]), 1.0)
                for r, e in zip(rows, exacts) for k, v in zip(keys, e))
    opening = rows[1]["u_x"] - rows[0]["u_x"] - exacts[0][2] * 20 / (E / (1 - NU ** 2))
    check(len(rows) == 6 and worst < 1e-9 and abs(opening - exacts[4][2] / 1e7) < 1e-9 * abs(opening),
          "elastic fault, %d rank(s): sigma_xx = %.6e Pa (springs in series: %.6e), "
          "opening %.6f m (sigma/k_n = %.6f m), largest relative difference %.1e"
          % (ranks, rows[4]["sigma_xx"], exacts[4][2], opening, exacts[4][2] / 1e7, worst))

# The elastic fault in plane stress (the path the fault terms take with
# the plane-stress moduli): springs in series with E' = E, so the stress
# and the opening are smaller than in plane strain by their E' ratio;
# sigma_zz = 0.
out = os.path.abspath("output_elastic_fault_plane_stress")
run("faults/elastic_fault.prm", out, 1, ["Plane state=plane stress"])
rows = read_csv(os.path.join(out, "point_values.csv"))
keys = ("u_x", "u_y", "sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz")
exacts = [elastic_exact(r["x"], r["y"], plane_stress=True) for r in rows]
worst = max(abs(r[k] - v) / max(abs(e[2]) if k[0] == "s" else abs(e[0]), 1.0)
            for r, e in zip(rows, exacts) for k, v in zip(keys, e))
strain = elastic_exact(0, 0)[2]
check(len(rows) == 6 and worst < 1e-9,
      "elastic fault in plane stress: sigma_xx = %.6e Pa (springs in series with E' = E: "
      "%.6e; plane strain %.6e), largest relative difference %.1e"
      % (rows[4]["sigma_xx"], exacts[4][2], strain, worst))

# The elastic fault tends to the locked (continuous) block as k_n grows:
# sigma_xx = delta / ((a + b)/E' + 1/k_n), so the relative difference from
# the continuum's delta E'/(a + b) is c/(1 + c), c = E'/((a + b) k_n):
# first order in 1/k_n, a factor 10 per decade of k_n.
Ep = E / (1 - NU ** 2)
continuum = 10.0 * Ep / 10e3
gaps = []
for k_n in (1e8, 1e9, 1e10):
    out = os.path.abspath("output_elastic_fault_k%g" % k_n)
    run("faults/elastic_fault.prm", out, 1, ["Faults/fault/Normal stiffness=%g" % k_n])
    s_xx = read_csv(os.path.join(out, "point_values.csv"))[4]["sigma_xx"]
    c = Ep / (10e3 * k_n)
    gaps.append((s_xx - continuum) / continuum)
    check(abs(gaps[-1] + c / (1 + c)) < 1e-9,
          "elastic fault, k_n = %g Pa/m: sigma_xx differs from the continuum by %.6e (expected "
          "-c/(1 + c) = %.6e)" % (k_n, gaps[-1], -c / (1 + c)))
rates = [math.log10(gaps[i] / gaps[i + 1]) for i in range(2)]
check(all(abs(r - 1) < 0.05 for r in rates),
      "elastic fault -> continuum as k_n grows: order %s in 1/k_n (expected 1)"
      % ", ".join("%.3f" % r for r in rates))

TAU, K_S, GS = 1e7, 1e10 / 1e3, E / (2 * (1 + NU))
for ranks in (1, 2):
    out = os.path.abspath("output_elastic_fault_shear_%d" % ranks)
    run("faults/elastic_fault_shear.prm", out, ranks)
    rows = read_csv(os.path.join(out, "point_values.csv"))
    worst = 0.0
    for r in rows:
        u_y = TAU * r["x"] / GS + (TAU / K_S if r["x"] > 5e3 else 0.0)
        worst = max(worst, abs(r["u_x"]) / 1.0, abs(r["u_y"] - u_y) / 1.0,
                    abs(r["sigma_xy"] - TAU) / TAU, abs(r["sigma_xx"]) / TAU,
                    abs(r["sigma_yy"]) / TAU, abs(r["sigma_zz"]) / TAU)
    slip = rows[1]["u_y"] - rows[0]["u_y"] - TAU * 20 / GS
    check(len(rows) == 6 and worst < 1e-9 and abs(slip - TAU / K_S) < 1e-9 * TAU / K_S,
          "elastic fault in shear, %d rank(s): slip %.9f m (tau/k_s = %.9f m), sigma_xy = tau, "
          "largest relative difference %.1e" % (ranks, slip, TAU / K_S, worst))

P, MU, D_RIGHT, L = 1e8, 0.6, 40.0, 10e3
G0 = E / 2  # nu = 0
TAU_F = MU * P


def read_summary(out):
    import json
    with open(os.path.join(out, "fault_summary.json")) as f:
        return json.load(f)


def read_fault(out):
    with open(os.path.join(out, "fault.csv")) as f:
        header = f.readline().strip()
        rows = [line.strip().split(",") for line in f if line.strip()]
    check(header == "s,x,y,slip,opening,shear_traction,normal_traction,state",
          "fault.csv has the columns s,x,y,slip,opening,shear_traction,normal_traction,state")
    return [dict(zip(header.split(","), [float(v) for v in r[:7]] + [r[7]])) for r in rows]


def block_check(out, tau, slip):
    """Points and fault.csv against the uniform-stress solution with the
    hanging wall moved up by @p slip."""
    rows = read_csv(os.path.join(out, "point_values.csv"))
    worst = 0.0
    # Displacements relative to the largest one (the solver's tolerance is
    # relative to the load).
    scale = max(max(abs(r["u_x"]), abs(r["u_y"])) for r in rows)
    for r in rows:
        hanging = r["x"] > 5e3
        u_x = -P * r["x"] / E - (P / 1e10 if hanging else 0.0)
        u_y = tau * r["x"] / G0 + (slip if hanging else 0.0)
        worst = max(worst, abs(r["u_x"] - u_x) / scale, abs(r["u_y"] - u_y) / scale,
                    abs(r["sigma_xy"] - tau) / P, abs(r["sigma_xx"] + P) / P,
                    abs(r["sigma_yy"]) / P)
    fault = read_fault(out)
    for f in fault:
        worst = max(worst, abs(f["slip"] + slip) / scale, abs(f["shear_traction"] + tau) / P,
                    abs(f["normal_traction"] + P) / P, abs(f["opening"] + P / 1e10) / scale)
    return rows, fault, worst


for ranks in (1, 2):
    out = os.path.abspath("output_frictional_fault_%d" % ranks)
    result = run("faults/frictional_fault.prm", out, ranks)
    slip = D_RIGHT - TAU_F * L / G0
    rows, fault, worst = block_check(out, TAU_F, slip)
    summary = read_summary(out)
    check(len(rows) == 6 and len(fault) == 24 and all(f["state"] == "sliding" for f in fault)
          and worst < 1e-9,
          "frictional fault sliding, %d rank(s): all %d points slide with shear traction "
          "mu|sigma_n| = %.6e Pa (exact %.6e), slip %.9f m (d - tau_F L/G = %.9f m), "
          "largest relative difference %.1e"
          % (ranks, len(fault), -fault[0]["shear_traction"], TAU_F, -fault[0]["slip"], slip, worst))
    # The elastic predictor, then the active set: measured 4 iterations.
    # Asserted: one linear solve per iteration, each step with the states
    # standing still reduces the residual by the linear solve's accuracy
    # (the settled problem is linear), and at most twice the measured count.
    check(summary["nonlinear_iterations"] <= 8 and summary["linear_solves"] == summary["nonlinear_iterations"],
          "frictional fault sliding, %d rank(s): semi-smooth Newton converges in %d iterations, "
          "one linear solve each (at most 8, twice the 4 measured)"
          % (ranks, summary["nonlinear_iterations"]))
    check_settled_newton("frictional fault sliding, %d rank(s)" % ranks, newton_solves(result.stdout))

stuck = open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "frictional_fault.prm")).read()
stuck = stuck.replace("set Prescribed displacement parts = left, right",
                      "set Prescribed displacement parts = left")
stuck = stuck.replace("  subsection right\n    set y = 40\n  end\n", "")
stuck = stuck.replace("set Shear traction = 6e7", "set Shear traction = 3e7")
stuck = stuck.replace("      set Normal traction = -1e8\n",
                      "      set Normal traction = -1e8\n      set Shear traction = -3e7\n")
with open("frictional_fault_stuck.prm", "w") as f:
    f.write(stuck)
for ranks in (1, 2):
    out = os.path.abspath("output_frictional_fault_stuck_%d" % ranks)
    run(os.path.abspath("frictional_fault_stuck.prm"), out, ranks)
    rows, fault, worst = block_check(out, 3e7, 3e7 / 1e7)
    summary = read_summary(out)
    check(len(fault) == 24 and all(f["state"] == "stuck" for f in fault) and worst < 1e-9
          and summary["nonlinear_iterations"] == 1,
          "frictional fault stuck (tau = 30 MPa < mu P), %d rank(s): slip tau/k_s = %.9f m, "
          "every point stuck, one solve, largest relative difference %.1e"
          % (ranks, -fault[0]["slip"], worst))

# The thesis iteration: stops when the excess shear is below 1 kPa.
out = os.path.abspath("output_frictional_fault_thesis")
run("faults/frictional_fault.prm", out, 1,
    ["Faults/Sliding solver/Method=thesis", "Faults/Sliding solver/Excess shear tolerance=1e3",
     "Faults/Sliding solver/Maximum iterations=1000"])
fault = read_fault(out)
summary = read_summary(out)
slip = D_RIGHT - TAU_F * L / G0
worst_tau = max(abs(-f["shear_traction"] - TAU_F) for f in fault)
worst_slip = max(abs(-f["slip"] - slip) for f in fault)
# An excess e is a slip deficit of about e (1/k_s + L/G) (the fault's spring
# and the block in series), and the iteration removes the fraction 1 - r of
# a deficit per solve, r = (L/G) / (1/k_s + L/G): the corrections still to
# come add up to at most e (1/k_s + L/G) / (1 - r).
compliance = 1 / 1e7 + L / G0
r = (L / G0) / compliance
bound = 1e3 * compliance / (1 - r)
check(all(f["state"] == "sliding" for f in fault) and worst_tau <= 1e3 and worst_slip <= bound,
      "thesis iteration (factor 1): %d solves, all points sliding, shear traction within %.0f Pa "
      "of mu|sigma_n| (tolerance 1 kPa), slip within %.1e m (bound %.1e m from the 1 kPa "
      "tolerance and the contraction %.2f per solve)"
      % (summary["linear_solves"], worst_tau, worst_slip, bound, r))

# FSHEAR's hold at the limit (Faults/Sliding solver/Hold sliding points at
# the limit; thesis appendix, FSHEAR's IIT flag). The iteration moves
# factor x e / k_s of slip per solve and removes the fraction f (1 - r) of
# the excess of the uniform slip mode (0.89 at f = 3), but up to f of a
# mode that alternates along the fault, whose bulk compliance is small
# beside 1/k_s: such modes overshoot below the limit once f > 1.
# Re-sticking freezes the overshoot, so the iteration stops with points
# below mu|sigma_n| by far more than its tolerance; held at the limit, the
# iteration is the plain over-relaxation, stable only for f < 2 (those
# modes), which must converge to the exact state at f = 2 and stop with an
# error naming the factor at f = 3.
THESIS = ["Faults/Sliding solver/Method=thesis", "Faults/Sliding solver/Excess shear tolerance=1e3",
          "Faults/Sliding solver/Maximum iterations=1000"]
HOLD = "Faults/Sliding solver/Hold sliding points at the limit=true"
out = os.path.abspath("output_frictional_fault_thesis_hold")
run("faults/frictional_fault.prm", out, 1, THESIS + [HOLD, "Faults/Sliding solver/Convergence factor=2"])
fault = read_fault(out)
worst_tau = max(abs(-f["shear_traction"] - TAU_F) for f in fault)
worst_slip = max(abs(-f["slip"] - slip) for f in fault)
check(all(f["state"] == "sliding" for f in fault) and worst_tau <= 1e3 and worst_slip <= bound,
      "thesis iteration, points held at the limit, factor 2: all points sliding, shear traction "
      "within %.0f Pa of mu|sigma_n|, slip within %.1e m (bound %.1e m)" % (worst_tau, worst_slip, bound))
out = os.path.abspath("output_frictional_fault_thesis_factor3")
run("faults/frictional_fault.prm", out, 1, THESIS + ["Faults/Sliding solver/Convergence factor=3"])
lowest = min(-f["shear_traction"] for f in read_fault(out))
check(TAU_F - lowest > 1e6,
      "thesis iteration re-sticking, factor 3: the overshoot of the fault's short modes is frozen, "
      "the lowest shear traction %.4e Pa lies %.2f MPa below mu|sigma_n| (tolerance 1 kPa)"
      % (lowest, (TAU_F - lowest) / 1e6))
out = os.path.abspath("output_frictional_fault_thesis_hold_factor3")
result = run("faults/frictional_fault.prm", out, 1,
             THESIS + [HOLD, "Faults/Sliding solver/Convergence factor=3"], expect_success=False)
check(result.returncode != 0 and "Convergence factor" in result.stderr + result.stdout,
      "thesis iteration held at the limit, factor 3 > 2: stops (exit %d) with a message naming "
      "Faults/Sliding solver/Convergence factor" % result.returncode)

# The overburden's depth from sea level (Faults/<fault>/Overburden depth
# from; FSHEAR measures SLITH and POREP from y = 0): the stuck block (mu
# 10) with its top 5 km below y = 0 and the thesis's densities. The
# displacements do not see the overburden while every point sticks; the
# normal stress fault.csv reports must be compressed by exactly
# (2911 - 1000) g 5 km more than with the depth from the fault's top.
SUNK = ["Geometry/Layered box/Layer interfaces=-5, -15", "Faults/fault/Friction coefficient=10",
        "Faults/fault/Lithostatic density=2911", "Faults/fault/Pore fluid density=1000",
        "Convergence study/Points=4.99, -7; 5.01, -7; 1, -10; 9, -13"]
sunk = {}
for origin in ("fault top", "sea level"):
    out = os.path.abspath("output_frictional_fault_" + origin.replace(" ", "_"))
    run("faults/frictional_fault.prm", out, 1, SUNK + ["Faults/fault/Overburden depth from=" + origin])
    sunk[origin] = (read_fault(out), read_csv(os.path.join(out, "point_values.csv")))
shift = (2911 - 1000) * G * 5e3
(top_fault, top_points), (sea_fault, sea_points) = sunk["fault top"], sunk["sea level"]
worst_shift = max(abs((a["normal_traction"] - b["normal_traction"]) - shift) / shift
                  for a, b in zip(top_fault, sea_fault))
worst_u = max(abs(a[k] - b[k]) for a, b in zip(top_points, sea_points) for k in ("u_x", "u_y"))
check(all(f["state"] == "stuck" for f in top_fault + sea_fault) and len(top_fault) == len(sea_fault)
      and worst_shift < 1e-9 and worst_u < 1e-9,
      "overburden depth from sea level, fault top 5 km below y = 0: every point stuck, the same "
      "displacements (largest difference %.1e m), the effective normal stress %.4e Pa more "
      "compressive at every point (1911 g 5 km, relative difference %.1e)" % (worst_u, shift, worst_shift))

DIP = math.radians(63.43)
d = (math.cos(DIP), -math.sin(DIP))
n = (math.sin(DIP), math.cos(DIP))
w = (2 * d[0] + 0.5 * n[0], 2 * d[1] + 0.5 * n[1])
w_norm = math.hypot(*w)
for ranks in (1, 2):
    out = os.path.abspath("output_prescribed_slip_%d" % ranks)
    result = run("faults/prescribed_slip.prm", out, ranks)
    rows = read_csv(os.path.join(out, "point_values.csv"))
    worst = 0.0
    for r in rows:
        hanging = r["x"] > 4e3 + (-r["y"]) / 2 + 1.0
        u = w if hanging else (0.0, 0.0)
        worst = max(worst, abs(r["u_x"] - u[0]) / w_norm, abs(r["u_y"] - u[1]) / w_norm,
                    max(abs(r[k]) for k in ("sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz"))
                    / (E * w_norm / 1e4))
    check(len(rows) == 6 and sum(1 for r in rows if r["x"] > 4e3 + (-r["y"]) / 2 + 1.0) == 2
          and worst < 1e-9,
          "prescribed slip 2 m + opening 0.5 m, %d rank(s): hanging wall offset by w = (%.6f, %.6f) m, "
          "footwall fixed, no stress, largest relative difference %.1e" % (ranks, w[0], w[1], worst))

# A curved locked fault: the block's fault is the circle of radius
# sqrt(586) km about (-15, -15) km (dipping 52 degrees at the surface, 78 at
# the base), carried by a manifold; without gravity the solution is linear,
# which the isoparametric Q2 space holds on curved cells, so it must be
# exact to round-off on uniformly refined meshes (three cycles); and every
# interface point stays on the circle. (Where a curved face hangs, the
# finer side's nodes lie on the arc and the coarser side's trace is its Q2
# interpolant, O(h^3) apart: measured 1.1e-5 relative on these adaptive
# meshes, so the exactness is asserted without hanging faces.)
ARC = ["Geometry/Layered box/Fault surface x=auto",
       "Geometry/Layered box/Fault arc centre=-15, -15",
       "Geometry/Layered box/Fault arc radius=%.12f" % math.sqrt(586.0),
       "Loads/Gravity/Enabled=false", "Mesh refinement/Strategy=global",
       "Mesh refinement/Number of cycles=3"]
for ranks in (1, 2):
    out = os.path.abspath("output_curved_locked_fault_%d" % ranks)
    run(PRM, out, ranks, ARC)
    compare(out, False, "curved locked fault, %d rank(s)" % ranks)
out = os.path.abspath("output_curved_elastic_fault")
run(PRM, out, 1, ARC + ["Faults/fault/Interface law=elastic", "Faults/fault/Shear stiffness=1e9",
                        "Faults/fault/Normal stiffness=1e9"])
with open(os.path.join(out, "fault.csv")) as f:
    f.readline()
    points = [tuple(float(v) for v in line.split(",")[1:3]) for line in f if line.strip()]
off = max(abs(math.hypot(x + 15e3, y + 15e3) - math.sqrt(586.0) * 1e3) for x, y in points)
check(len(points) > 12 and off < 1e-6 * math.sqrt(586.0) * 1e3,
      "curved fault: all %d interface points of the refined meshes lie on the arc (largest distance "
      "%.1e m of a 24.2 km radius)" % (len(points), off))

out = os.path.abspath("output_locked_fault_q1")
run(PRM, out, 1, ["Discretization/Polynomial degree=1", "Loads/Gravity/Enabled=false"])
compare(out, False, "Q1 without gravity")
finish()

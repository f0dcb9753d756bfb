"""Several faults per model, and faults read from Gmsh physical curves
(issue 16).

tests/faults/two_faults.prm: a 9 km x 4 km block cut by two parallel faults
a and b dipping 63.43 degrees (tan = 2) to the right; the middle block is
the hanging wall of a and the footwall of b, so the two displacement
fields alternate and fault b's field-0 side is its hanging wall (the face
terms and constraints must orient the jump per fault). Left side fixed.

1. Elastic faults (k_s = 1e7, k_n = 2e7 Pa/m) under a uniform shear stress
   tau = 10 MPa (shear tractions on top, base and right side): the stress
   is uniform, each fault's jump is w = K^-1 (sigma n) = (t_s/k_s) s +
   (t_n/k_n) n with t_s = tau cos 2 delta, t_n = tau sin 2 delta, and
   u = (0, tau x / G) + (number of faults left of x) w: linear in each
   block, so exact on every mesh (three global cycles), 1 and 2 ranks.
2. Prescribed slips, a: 2 m, b: 1 m and 0.5 m opening, no load: the blocks
   move rigidly by 0, w_a, w_a + w_b, stress-free.
3. The same block read from a Gmsh file whose faults are physical curves
   (tests/faults/gmsh_writer.py writes the generator's coarse mesh): case 1
   exact again, 1 and 2 ranks.
4. A curved fault from a Gmsh physical curve on the circle of radius
   sqrt(586) km about (-15, -15) km (`Fault arc centres`), through the
   block of locked_fault.prm: locked and without gravity the solution is
   linear, so exact to round-off on uniformly refined meshes; elastic, its
   fault.csv equals the layered box's arc fault point by point (same
   manifold, same trace) and every point lies on the circle.
5. prm/graben.prm: two frictional normal faults dipping towards each other
   (traces at 480 and 520 km) in the 20 km layer of the thesis's normal
   fault under 50 MPa tension. The model is mirror-symmetric about
   x = 500 km in its stresses (the tension is uniform, the right edge's
   u_x = 0 only fixes a translation) and its mesh, so the two throws and
   the surface's u_y at mirrored points must agree to the Newton
   tolerance (1e-6 of the throw); the block between the faults subsides
   (both throws positive, the hanging wall of both) and the footwalls
   rise next to the faults (rift shoulders, u_y > 0).
6. The same graben with both faults buried, from 5 km down to the base
   (`Fault top depth = 5`, rows every 5 km): two faults with buried tips
   in one model, on 2 ranks. Asserted: the largest slips of the two faults
   agree to 1e-6 (the mirror symmetry), both are normal slip, the slip at
   each upper tip is zero and fault_summary gives the tip's depth, 5 km.
Round-off: the solver stops at 1e-12; values relative to |w| or tau: 1e-9.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from gmsh_writer import layered_box_msh  # noqa: E402
from lithotest import check, finish, read_csv, run  # noqa: E402

E, NU, TAU, K_S, K_N = 0.85e11, 0.25, 1e7, 1e7, 2e7
G = E / (2 * (1 + NU))
DIP = math.atan(2.0)
D = (math.cos(DIP), -math.sin(DIP))   # down dip = the shear direction s
N = (math.sin(DIP), math.cos(DIP))    # into the hanging wall


def fault_x(surface_km):
    return lambda y: surface_km + (-y) / 2.0


FAULTS = [("a", fault_x(2.5)), ("b", fault_x(5.5))]


def faults_left_of(x_m, y_m):
    return sum(1 for _, f in FAULTS if x_m > f(y_m / 1e3) * 1e3)


def w_of(slip, opening):
    return (slip * D[0] + opening * N[0], slip * D[1] + opening * N[1])


t_s, t_n = TAU * math.cos(2 * DIP), TAU * math.sin(2 * DIP)
W_ELASTIC = w_of(t_s / K_S, t_n / K_N)


def check_shear(out, label):
    rows = read_csv(os.path.join(out, "point_values.csv"))
    worst = 0.0
    for r in rows:
        n = faults_left_of(r["x"], r["y"])
        u = (n * W_ELASTIC[0], TAU * r["x"] / G + n * W_ELASTIC[1])
        worst = max(worst, abs(r["u_x"] - u[0]), abs(r["u_y"] - u[1]),
                    abs(r["sigma_xy"] - TAU) / TAU * 1.0,
                    max(abs(r[k]) for k in ("sigma_xx", "sigma_yy", "sigma_zz")) / TAU)
    blocks = sorted({faults_left_of(r["x"], r["y"]) for r in rows})
    check(len(rows) == 7 and blocks == [0, 1, 2] and worst < 1e-9,
          "%s: uniform shear, each fault opens and slips by K^-1 sigma n = (%.6f, %.6f) m, "
          "all three blocks exact (largest difference %.1e m or of tau)"
          % (label, W_ELASTIC[0], W_ELASTIC[1], worst))
    for name in ("a", "b"):
        fault = read_csv(os.path.join(out, "fault_%s.csv" % name))
        slip = max(abs(f["slip"] - t_s / K_S) for f in fault)
        opening = max(abs(f["opening"] - t_n / K_N) for f in fault)
        check(len(fault) > 0 and slip < 1e-9 and opening < 1e-9
              and os.path.exists(os.path.join(out, "fault_summary_%s.json" % name)),
              "%s: fault_%s.csv: slip t_s/k_s = %.3f m and opening t_n/k_n = %.3f m at all %d points"
              % (label, name, t_s / K_S, t_n / K_N, len(fault)))


for ranks in (1, 2):
    out = os.path.abspath("output_two_faults_%d" % ranks)
    run("faults/two_faults.prm", out, ranks)
    check_shear(out, "two faults, %d rank(s)" % ranks)

SLIP = ["Faults/a/Interface law=prescribed slip", "Faults/a/Slip=2",
        "Faults/b/Interface law=prescribed slip", "Faults/b/Slip=1", "Faults/b/Opening=0.5",
        "Loads/Tractions/top/Shear traction=0", "Loads/Tractions/base/Shear traction=0",
        "Loads/Tractions/right/Shear traction=0"]
w_a, w_b = w_of(2.0, 0.0), w_of(1.0, 0.5)
for ranks in (1, 2):
    out = os.path.abspath("output_two_faults_slip_%d" % ranks)
    run("faults/two_faults.prm", out, ranks, SLIP)
    rows = read_csv(os.path.join(out, "point_values.csv"))
    worst = 0.0
    for r in rows:
        n = faults_left_of(r["x"], r["y"])
        u = [(0.0, 0.0), w_a, (w_a[0] + w_b[0], w_a[1] + w_b[1])][n]
        worst = max(worst, abs(r["u_x"] - u[0]), abs(r["u_y"] - u[1]),
                    max(abs(r[k]) for k in ("sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz"))
                    / (E * 2.0 / 4e3))
    check(len(rows) == 7 and worst < 1e-9,
          "two faults with prescribed slip, %d rank(s): the blocks move rigidly by 0, "
          "(%.6f, %.6f) and (%.6f, %.6f) m, stress-free (largest difference %.1e)"
          % (ranks, w_a[0], w_a[1], w_a[0] + w_b[0], w_a[1] + w_b[1], worst))

# 3. From Gmsh.
msh = os.path.abspath("two_faults.msh")
layered_box_msh(msh, 9.0, [-4.0, -2.0, 0.0], FAULTS, [0, 2, 4, 6])
GMSH = ["Geometry/Model=gmsh", "Geometry/Gmsh/Mesh file=" + msh, "Geometry/Gmsh/Fault curves=a, b"]
for ranks in (1, 2):
    out = os.path.abspath("output_two_faults_gmsh_%d" % ranks)
    run("faults/two_faults.prm", out, ranks, GMSH)
    check_shear(out, "two faults from Gmsh physical curves, %d rank(s)" % ranks)

# 4. A curved fault from Gmsh.
R = math.sqrt(586.0)
arc_x = lambda y: -15.0 + math.sqrt(R * R - (y + 15.0) ** 2)  # noqa: E731
msh = os.path.abspath("arc_fault.msh")
layered_box_msh(msh, 10.0, [-10.0, -7.5, -5.0, -2.5, 0.0], [("fault", arc_x)], [0, 3, 4])
ARC_GMSH = ["Geometry/Model=gmsh", "Geometry/Gmsh/Mesh file=" + msh,
            "Geometry/Gmsh/Fault curves=fault", "Geometry/Gmsh/Fault arc centres=fault: -15, -15",
            "Loads/Gravity/Enabled=false", "Mesh refinement/Strategy=global",
            "Mesh refinement/Number of cycles=3"]
STRAIN, BASE = 1e-4, -10e3
out = os.path.abspath("output_arc_fault_gmsh")
run("faults/locked_fault.prm", out, 1, ARC_GMSH)
rows = read_csv(os.path.join(out, "point_values.csv"))
b = E / (1 - NU ** 2) * STRAIN
worst = 0.0
for r in rows:
    u = (STRAIN * r["x"], -(1 + NU) / E * NU * b * (r["y"] - BASE))
    worst = max(worst, max(abs(r["u_x"] - u[0]), abs(r["u_y"] - u[1])) / (STRAIN * 10e3),
                abs(r["sigma_xx"] - b) / b, abs(r["sigma_yy"]) / b, abs(r["sigma_xy"]) / b,
                abs(r["sigma_zz"] - NU * b) / b)
check(len(rows) == 6 and worst < 1e-9,
      "locked arc fault from a Gmsh physical curve: the linear solution exact on the curved "
      "cells (largest relative difference %.1e)" % worst)

ELASTIC = ["Faults/fault/Interface law=elastic", "Faults/fault/Shear stiffness=1e9",
           "Faults/fault/Normal stiffness=1e9"]
out_gmsh = os.path.abspath("output_arc_fault_gmsh_elastic")
run("faults/locked_fault.prm", out_gmsh, 1, ARC_GMSH + ELASTIC)
out_box = os.path.abspath("output_arc_fault_box_elastic")
run("faults/locked_fault.prm", out_box, 1, ELASTIC + [
    "Geometry/Layered box/Fault surface x=auto", "Geometry/Layered box/Fault arc centre=-15, -15",
    "Geometry/Layered box/Fault arc radius=%.12f" % R, "Loads/Gravity/Enabled=false",
    "Mesh refinement/Strategy=global", "Mesh refinement/Number of cycles=3"])
a = read_csv(os.path.join(out_gmsh, "fault.csv"))
b_rows = read_csv(os.path.join(out_box, "fault.csv"))
scale = max(abs(r["slip"]) for r in b_rows)
diff = max(max(abs(p["s"] - q["s"]), abs(p["x"] - q["x"]), abs(p["y"] - q["y"])) / 1e3
           + abs(p["slip"] - q["slip"]) / scale for p, q in zip(a, b_rows)) if len(a) == len(b_rows) else 1.0
off = max(abs(math.hypot(p["x"] + 15e3, p["y"] + 15e3) - R * 1e3) for p in a)
check(len(a) == len(b_rows) and len(a) > 12 and diff < 1e-6 and off < 1e-6 * R * 1e3,
      "elastic arc fault from Gmsh equals the layered box's at all %d points (s, x, y [km] and "
      "slip, largest relative difference %.1e), all on the circle (%.1e m)" % (len(a), diff, off))
# 5. A symmetric graben.
import json  # noqa: E402
ROOT = os.path.dirname(os.path.dirname(HERE))
out = os.path.abspath("output_graben")
run(os.path.join(ROOT, "prm", "graben.prm"), out, 2,
    ["Mesh refinement/Initial global refinement=2", "Output/Write ParaView files=false",
     "Output/Figures/Enabled=false"])
throws = []
for name in ("west", "east"):
    with open(os.path.join(out, "fault_summary_%s.json" % name)) as f:
        throws.append(json.load(f)["throw_m"])
# (The traces themselves carry two values, one per side: left out.)
profile = {round(r["x"], 3): r["u_y"] for r in read_csv(os.path.join(out, "surface_profile.csv"))
           if min(abs(r["x"] - 480e3), abs(r["x"] - 520e3)) > 1.0}
pairs = [(x, abs(u - profile[round(1e6 - x, 3)])) for x, u in profile.items() if round(1e6 - x, 3) in profile]
asym = max(d for x, d in pairs if abs(x - 500e3) <= 200e3)
# The edges differ (a traction on the left, rollers on the right), which
# the fault's flexure only reaches by its tail, throw sqrt(2)
# exp(-480 km / alpha), alpha = 54 km (see normal_fault_check.py).
alpha = (4 * E * 20e3 ** 3 / (12 * (1 - NU ** 2)) / (2900.0 * 9.81)) ** 0.25
edge = max(d for x, d in pairs)
shoulders = [max(u for x, u in profile.items() if x < 480e3), max(u for x, u in profile.items() if x > 520e3)]
tail = throws[0] * math.sqrt(2) * math.exp(-480e3 / alpha)
check(min(throws) > 0 and abs(throws[0] - throws[1]) <= 1e-6 * throws[0] and asym <= 1e-6 * throws[0]
      and edge <= tail and min(shoulders) > 0,
      "graben (2 ranks): the block subsides by throws %.3f and %.3f m on the two faults, the surface "
      "is symmetric about 500 km to %.1e m within 200 km of it (%.1e m at the edges, within the "
      "flexure's tail %.1e m), the shoulders rise by %.1f and %.1f m"
      % (throws[0], throws[1], asym, edge, tail, shoulders[0], shoulders[1]))

# 6. The graben with buried upper tips.
out = os.path.abspath("output_graben_buried")
run(os.path.join(ROOT, "prm", "graben.prm"), out, 2,
    ["Mesh refinement/Initial global refinement=1", "Geometry/Layered box/Cells per layer=4",
     "Geometry/Layered box/Fault top depth=5", "Output/Write ParaView files=false",
     "Output/Figures/Enabled=false"])
summaries, tips = [], []
for name in ("west", "east"):
    with open(os.path.join(out, "fault_summary_%s.json" % name)) as f:
        summaries.append(json.load(f))
    rows = read_csv(os.path.join(out, "fault_%s.csv" % name))
    tips.append(max(abs(r["slip"]) for r in rows if r["s"] == 0))
slips = [sm["max_slip_m"] for sm in summaries]
check(min(slips) > 0 and abs(slips[0] - slips[1]) <= 1e-6 * slips[0] and max(tips) == 0
      and all(abs(sm["upper_tip_depth_m"] - 5000) <= 1e-6 and sm["throw_m"] == 0 for sm in summaries),
      "graben with both faults buried below 5 km (2 ranks): largest normal slips %.4f and %.4f m, "
      "zero at the upper tips (%s), tips at %s m"
      % (slips[0], slips[1], tips, [sm["upper_tip_depth_m"] for sm in summaries]))
finish()

"""The two fields' multigrid with prescribed-slip faults (issue 52):
`Solver/Type = two-field multigrid` (CG with the geometric multigrid of the
two displacement fields, the fault's jump a set of inhomogeneous
constraints) against the direct solver.

1. tests/faults/prescribed_slip.prm: a uniform slip of 2 m and an opening
   of 0.5 m on a fault through a block fixed on its left side: the
   hanging wall moves rigidly by w = 2 d + 0.5 n and nothing is stressed,
   on adaptive meshes with hanging fault faces, on 1 and 2 ranks: the
   point values within 1e-9 of |w| and stresses within 1e-9 of E|w|/L
   (CG to 1e-12 of the load: the exact solution is in the space, so only
   the solver's residual and round-off are left).
2. A thrust dipping 30 degrees from the surface to a buried lower tip at
   10 km with a prescribed uniform slip of 1 m (the model of
   tests/faults/buried_layered_box.prm in a 600 x 200 km box of 10 km
   cells, evenly divided), three uniform cycles (10 k, 39 k and 155 k
   DoFs): the surface displacement at four points equals the direct
   solver's to 1e-8 of its largest value (CG to 1e-12; measured below),
   and the iterations do not grow with the mesh: the finest cycle needs at
   most 1.5 times the middle one's (measured 29 against 23; the coarsest
   is the coarse level itself, a direct solve).
3. The same fault under adaptive refinement (stress recovery, Doerfler
   0.5, four cycles, hanging nodes at the tips): the same meshes as the
   direct solver's and the same surface displacement to 1e-8.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, fail, finish, read_csv, run, table  # noqa: E402

MG = ["Solver/Type=two-field multigrid", "Solver/Relative tolerance=1e-12"]
DIRECT = ["Solver/Type=direct"]
E = 0.85e11


def iterations(out):
    """CG iterations per cycle from log.txt (fails if none is found)."""
    counts = []
    for line in open(os.path.join(out, "log.txt")):
        if line.startswith("cycle ") and "two-field multigrid" in line:
            counts.append(int(line.split("two-field multigrid")[1].split()[0]))
    if not counts:
        fail("%s: no two-field multigrid line in log.txt" % out)
    return counts


# 1. The rigid offset of the hanging wall.
DIP = math.radians(63.43)  # the fault's `Fault dip`
d = (math.cos(DIP), -math.sin(DIP))
n = (math.sin(DIP), math.cos(DIP))
w = (2 * d[0] + 0.5 * n[0], 2 * d[1] + 0.5 * n[1])
w_norm = math.hypot(*w)
for ranks in (1, 2):
    out = os.path.abspath("output_two_field_prescribed_slip_%d" % ranks)
    run("faults/prescribed_slip.prm", out, ranks, MG)
    rows = read_csv(os.path.join(out, "point_values.csv"))
    worst, hanging = 0.0, 0
    for r in rows:
        on_hanging_wall = r["x"] > 4e3 + (-r["y"]) / 2 + 1.0
        hanging += on_hanging_wall
        u = w if on_hanging_wall else (0.0, 0.0)
        worst = max(worst, abs(r["u_x"] - u[0]) / w_norm, abs(r["u_y"] - u[1]) / w_norm,
                    max(abs(r[k]) for k in ("sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz"))
                    / (E * w_norm / 1e4))
    counts = iterations(out)
    check(len(rows) == 6 and hanging == 2 and worst < 1e-9,
          "prescribed slip 2 m + opening 0.5 m, two-field multigrid, %d rank(s): the hanging wall "
          "offset by w, footwall fixed, no stress, largest relative difference %.1e (CG iterations %s)"
          % (ranks, worst, counts))

# 2.-3. The buried-tip thrust.
THRUST = ["Geometry/Layered box/Fault cell size=0", "Geometry/Layered box/Width=600",
          "Geometry/Layered box/Layer interfaces=0,-200", "Geometry/Layered box/Cells per layer=20",
          "Geometry/Layered box/Cells across=60", "Geometry/Layered box/Fault surface x=200",
          "Geometry/Layered box/Fault top depth=0",
          "Convergence study/Points=170, 0; 200, 0; 230, 0; 260, 0"]
ADAPTIVE = ["Mesh refinement/Strategy=adaptive", "Mesh refinement/Indicator=stress recovery",
            "Mesh refinement/Marking=fraction of error", "Mesh refinement/Refine fraction=0.5",
            "Mesh refinement/Number of cycles=4"]


def compare(name, sets, n_cycles):
    outs = {}
    for solver, extra in (("mg", MG), ("direct", DIRECT)):
        outs[solver] = os.path.abspath("output_two_field_prescribed_slip_%s_%s" % (name, solver))
        run("faults/buried_layered_box.prm", outs[solver], 1, THRUST + sets + extra)
    a, b = table(outs["mg"]), table(outs["direct"])
    if len(a) != n_cycles or len(b) != n_cycles:
        fail("%s: %d and %d cycles in convergence.csv (%d expected)" % (name, len(a), len(b), n_cycles))
    keys = [k for k in a[0] if k.startswith("u_x@") or k.startswith("u_y@")]
    if len(keys) != 8:
        fail("%s: %d displacement columns (8 expected)" % (name, len(keys)))
    largest = max(abs(r[k]) for r in b for k in keys)
    worst = max(abs(x[k] - y[k]) for x, y in zip(a, b) for k in keys) / largest
    same_meshes = [x["dofs"] for x in a] == [y["dofs"] for y in b]
    check(same_meshes and worst <= 1e-8,
          "%s: two-field multigrid = direct to %.1e of the largest surface displacement on every "
          "cycle (DoFs %s)" % (name, worst, [int(x["dofs"]) for x in a]))
    return iterations(outs["mg"])


uniform = compare("uniform", ["Mesh refinement/Number of cycles=3"], 3)
check(len(uniform) == 3 and uniform[2] <= 1.5 * uniform[1],
      "uniform cycles: CG iterations %s, the finest at most 1.5 times the middle one's" % uniform)
adaptive = compare("adaptive", ADAPTIVE, 4)
check(len(adaptive) == 4 and max(adaptive) <= 2 * max(uniform),
      "adaptive cycles: CG iterations %s (at most twice the uniform meshes' largest)" % adaptive)
finish()

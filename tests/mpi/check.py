"""MPI: the cantilever (global refinement) and the adaptive L-shaped
problem on 2 ranks agree with 1 rank to 1e-8 relative: point values
relative to the largest value of the field, errors relative to the norm of
the solution (the rel_* columns). CG is run to 1e-13 so that the solver's contribution (which
depends on the partition through AMG) is far below 1e-8; the adaptive
marking only sums over ranks, so both runs refine the same cells."""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

TOL = 1e-8
for name, prm, sets in [("cantilever", "cantilever/cantilever.prm", ["Mesh refinement/Number of cycles=5"]),
                        ("l_shaped", "l_shaped/l_shaped_adaptive.prm", ["Mesh refinement/Number of cycles=16"])]:
    sets = sets + ["Solver/Relative tolerance=1e-13"]
    tables = []
    for ranks in (1, 2):
        out = os.path.abspath("output_mpi_%s_%d" % (name, ranks))
        run(prm, out, ranks, sets)
        tables.append(table(out))
    one, two = tables
    check(len(one) == len(two), "%s: same number of cycles" % name)
    worst = 0.0
    for a, b in zip(one, two):
        check(a["dofs"] == b["dofs"] and a["cells"] == b["cells"],
              "%s cycle %d: same mesh (%d DoFs)" % (name, a["cycle"], a["dofs"]))
        umax = max(abs(a[k]) for k in a if k.startswith("u_") and "@" in k)
        smax = max(abs(a[k]) for k in a if k.startswith("s_") and "@" in k)
        for key in a:
            if a[key] != a[key]:
                continue
            if key.startswith("rel_"):
                # errors relative to the solution's norm: compare absolutely
                diff = abs(a[key] - b[key])
            elif key.startswith("u_") or key.startswith("err_u"):
                diff = abs(a[key] - b[key]) / umax
            elif key.startswith("s_"):
                diff = abs(a[key] - b[key]) / smax
            else:
                continue
            worst = max(worst, diff)
    check(worst < TOL, "%s: largest relative difference 1 vs 2 ranks %.1e < %.0e" % (name, worst, TOL))
finish()

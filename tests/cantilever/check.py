"""Thesis §4.3: the end-loaded cantilever against the exact
Timoshenko-Goodier solution under global refinement. Q2 theory: L2 error of
u ~ h^3 = N^-1.5, energy error ~ h^2 = N^-1. The rates are taken as the
least-squares slope over the four finest meshes; the tolerance 0.1 on the
rate covers the pre-asymptotic curvature visible on the coarse meshes (the
measured slopes are within 0.05 of theory)."""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

out = os.path.abspath("output_cantilever")
run("cantilever/cantilever.prm", out)
rows = table(out)
r_l2 = slope(rows, "L2(u)", len(rows) - 4)
r_en = slope(rows, "energy", len(rows) - 4)
r_st = slope(rows, "L2(stress)", len(rows) - 4)
check(abs(r_l2 - 1.5) < 0.1, "L2(u) rate %.3f in DoFs (%.2f in h), expected 1.5 (3)" % (r_l2, 2 * r_l2))
check(abs(r_en - 1.0) < 0.1, "energy rate %.3f in DoFs (%.2f in h), expected 1 (2)" % (r_en, 2 * r_en))
check(abs(r_st - 1.0) < 0.1, "L2(stress) rate %.3f in DoFs, expected 1" % r_st)
check(rows[-1]["rel_L2(u)"] < 1e-6, "finest relative L2 error %.2e < 1e-6" % rows[-1]["rel_L2(u)"])

# Tip deflection at (0, 0): exact -P l^3/(3 E' I) in plane strain.
P, l, c, E, nu = 5e4, 10.0, 1.25, 0.85e7, 0.35
Ep = E / (1 - nu * nu)
I = 2 * c ** 3 / 3
tip = -P * l ** 3 / (3 * Ep * I)
for row in rows:
    check(abs(row["u_y@P1"] - tip) < 2e-3 * abs(tip),
          "cycle %d: tip deflection %.5f vs exact %.5f (within 0.2%%)" % (row["cycle"], row["u_y@P1"], tip))
finish()

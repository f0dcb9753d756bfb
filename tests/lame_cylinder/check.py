"""Lame's cylinder on the quarter annulus: the curved-geometry test. With
the degree-2 mapping on the polar manifold, L2(u) ~ h^3 (N^-1.5). Checks of
the check: with a degree-1 mapping the geometry error limits the rate to
h^2 (N^-1); without the manifold (new vertices on straight chords) the
error stalls at the coarse polygon's geometry error."""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

def rates(tag, sets):
    out = os.path.abspath("output_lame_" + tag)
    run("lame_cylinder/lame.prm", out, 1, sets)
    rows = table(out)
    return rows, slope(rows, "L2(u)", len(rows) - 3), slope(rows, "energy", len(rows) - 3)

rows, r2, e2 = rates("q2", [])
check(abs(r2 - 1.5) < 0.1, "Q2 mapping: L2 rate %.3f in DoFs (%.2f in h), expected 1.5 (3)" % (r2, 2 * r2))
check(abs(e2 - 1.0) < 0.1, "Q2 mapping: energy rate %.3f, expected 1" % e2)
check(rows[-1]["rel_L2(u)"] < 1e-7, "Q2 mapping: finest relative L2 error %.2e" % rows[-1]["rel_L2(u)"])

rows1, r1, e1 = rates("q1", ["Discretization/Mapping degree=1"])
check(abs(r1 - 1.0) < 0.1, "Q1 mapping: L2 rate %.3f in DoFs (%.2f in h), expected 1 (2)" % (r1, 2 * r1))
check(rows1[-1]["rel_L2(u)"] > 100 * rows[-1]["rel_L2(u)"], "Q1 mapping error %.2e >> Q2 mapping error %.2e" % (rows1[-1]["rel_L2(u)"], rows[-1]["rel_L2(u)"]))

rowsf, rf, ef = rates("flat", ["Discretization/Use manifolds=false"])
check(abs(rf) < 0.05, "no manifold: L2 rate %.3f, error stalls" % rf)
check(rowsf[-1]["rel_L2(u)"] > 1e-2, "no manifold: finest relative error %.2e stays at the polygon's geometry error" % rowsf[-1]["rel_L2(u)"])

# The same cylinder read from a Gmsh file (quarter_annulus.msh, physical
# groups named inner/outer/left/base/body), with the arcs declared in the
# .prm: PolarManifold on the arcs, TransfiniteInterpolationManifold on the
# cells next to them. Optimal rate again, and the same order of error.
out = os.path.abspath("output_lame_gmsh")
run("lame_cylinder/lame.prm", out, 1,
    ["Geometry/Model=gmsh",
     "Geometry/Gmsh/Mesh file=" + os.path.join(SOURCE, "lame_cylinder", "quarter_annulus.msh"),
     "Geometry/Gmsh/Circular arcs=inner: 0, 0; outer: 0, 0",
     "Materials/body/Material id=",
     "Mesh refinement/Number of cycles=5"])
rows = table(out)
rg = slope(rows, "L2(u)", len(rows) - 3)
check(abs(rg - 1.5) < 0.1, "Gmsh mesh with declared arcs: L2 rate %.3f, expected 1.5" % rg)
check(rows[-1]["rel_L2(u)"] < 1e-6, "Gmsh mesh: finest relative L2 error %.2e" % rows[-1]["rel_L2(u)"])

# Composite cylinder: body in a stiff bonded shell (thesis §4.5 geometry).
out = os.path.abspath("output_lame_shell")
run("lame_cylinder/lame.prm", out, 1,
    ["Geometry/Quarter annulus/Shell thickness=0.121212121212", "Geometry/Quarter annulus/Cells around=4",
     "Convergence study/Lame cylinder/Shell thickness=0.121212121212",
     "Materials/Names=body, shell", "Materials/shell/Material id=1",
     "Materials/shell/Young's modulus=3e7", "Materials/shell/Poisson's ratio=0.3015",
     "Mesh refinement/Number of cycles=4"])
rows = table(out)
rs = slope(rows, "L2(u)", 1)
check(abs(rs - 1.5) < 0.15, "composite cylinder: L2 rate %.3f, expected 1.5" % rs)
finish()

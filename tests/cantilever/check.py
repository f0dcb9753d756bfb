"""Thesis §4.3: the end-loaded cantilever against the exact
Timoshenko-Goodier solution under global refinement. Q2 theory: L2 error of
u ~ h^3 = N^-1.5, energy error ~ h^2 = N^-1. The rates are taken as the
least-squares slope over the four finest meshes; the tolerance 0.1 on the
rate covers the pre-asymptotic curvature visible on the coarse meshes (the
measured slopes are within 0.05 of theory). The tip deflection against the
exact value on every mesh, to a bound falling as h^3; the thesis's
fully clamped 27-node mesh against the thesis's analytic tip deflection."""
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

# Plane stress: the same rates against the plane-stress form of the exact
# solution (the one Timoshenko & Goodier print).
out = os.path.abspath("output_cantilever_plane_stress")
run("cantilever/cantilever.prm", out, 1, ["Plane state=plane stress", "Mesh refinement/Number of cycles=5"])
ps = table(out)
r = slope(ps, "L2(u)", len(ps) - 3)
check(abs(r - 1.5) < 0.1, "plane stress: L2(u) rate %.3f, expected 1.5" % r)
check(ps[-1]["rel_L2(u)"] < 1e-6, "plane stress: finest relative L2 error %.2e" % ps[-1]["rel_L2(u)"])

# Tip deflection at (0, 0): on the neutral fibre the exact solution is beam
# theory, -P l^3/(3 E I) (plane stress) and -P l^3/(3 E' I), E' = E/(1 - nu^2)
# (plane strain). The tip is a node of every mesh; its error falls like the
# L2 error of u, h^3: measured relative errors (plane strain, cycles 0-5,
# 54 to 33 k DoFs) 5.7e-4, 8.8e-5, 8.6e-6, 8.8e-7, 9.5e-8, 1.1e-8 (a factor
# 6.5-10 per halving of h); plane stress (cycles 0-4) 8.0e-4, 1.1e-4,
# 1.1e-5, 1.1e-6, 1.2e-7. Bound: C 8^-cycle with C = 1.2e-3 (plane strain)
# and 1.6e-3 (plane stress), 1.7-3.4x the measured error on every mesh.
# The solver (CG to 1e-12) is not visible: the errors fall at h^3 down to
# the finest mesh's 1e-8.
P, l, c, E, nu = 5e4, 10.0, 1.25, 0.85e7, 0.35
I = 2 * c ** 3 / 3
tip_ps = -P * l ** 3 / (3 * E * I)
error = abs(ps[-1]["u_y@P1"] / tip_ps - 1)
bound = 1.6e-3 * 8.0 ** -ps[-1]["cycle"]
check(error <= bound, "plane stress, cycle %d: tip deflection %.9f vs exact -P l^3/(3EI) = %.9f "
      "(relative error %.1e, allowed %.1e)" % (ps[-1]["cycle"], ps[-1]["u_y@P1"], tip_ps, error, bound))

Ep = E / (1 - nu * nu)
tip = -P * l ** 3 / (3 * Ep * I)
for row in rows:
    error = abs(row["u_y@P1"] / tip - 1)
    bound = 1.2e-3 * 8.0 ** -row["cycle"]
    check(error <= bound, "cycle %d: tip deflection %.9f vs exact %.9f (relative error %.1e, allowed %.1e)"
          % (row["cycle"], row["u_y@P1"], tip, error, bound))

# The thesis's support: the whole end x = l fixed. Physical truth: fixing
# the whole end section restrains the warping of the section, so the tip
# deflects more than beam theory (= the exact solution with the horizontal
# neutral-fibre element clamped, T&G) and less than the exact solution with
# the vertical element clamped, which adds the shear deflection
# P l c^2 / (2 I G) (T&G §21).
out = os.path.abspath("output_cantilever_thesis_clamp")
run("cantilever/cantilever_thesis_clamp.prm", out)
rows = table(out)
G = E / (2 * (1 + nu))
shear_extra = P * l * c * c / (2 * I * G)
converged = rows[-1]["u_y@P1"]
# The clamped corners (x = l, y = +-c) are stress singularities, so the tip
# deflection converges slowly; the last change bounds the remaining error.
check(abs(rows[-1]["change_u_y@P1"]) < 5e-4 * abs(converged), "fully clamped: tip deflection converged to %.5f (last change %.1e)" % (converged, rows[-1]["change_u_y@P1"]))
check(tip - shear_extra < converged < tip,
      "fully clamped tip %.5f lies between beam theory %.5f and the vertical-element clamp %.5f"
      % (converged, tip, tip - shear_extra))

# The thesis's own comparison (§4.3.2, figure 4.7): on its 27-node mesh the
# isoparametric model "predicts almost identical displacements to the
# analytic solution" it prints in §4.3.1, v(0) = P l^3/(3 E I) (beam theory
# = the exact neutral fibre), while the 27-node CST and CSQ meshes reach
# only 58 % and 83 % of it. No tip value of the isoparametric mesh is
# printed, so the value compared is that analytic solution. §4.3 does not
# say which plane state it used; compared here in plane strain (E' for E),
# this test's state. What is compared: our 4 x 1 Q2 quadrilaterals with the
# thesis's support (every node of x = l fixed) have the thesis mesh's 27
# nodes but not its elements (8 six-node triangles). Measured: the Q2 mesh
# gives +1.49 % (-1.34115); the thesis's element on the same 27 nodes (P2
# triangles with either diagonal, consistent end load; computed by
# thesis_mesh_elements.py, whose Q2 result reproduces the program's to 12
# digits) gives -1.5 % (-1.3018): on this mesh both are "almost identical"
# to within ~1.5 %, the coarse mesh's stiffness roughly cancelling the
# extra deflection of the clamped end (the converged value is +4.4 %). (In
# plane stress: Q2 +2.8 %, P2 triangles +1.3 %.) Tolerance 2.5 %: 1.7x the
# measured difference, far from the CST and CSQ results the thesis
# contrasts; the converged fully clamped value would fail it.
coarse = rows[0]["u_y@P1"]
check(rows[0]["dofs"] == 54 and abs(coarse / tip - 1) <= 0.025,
      "thesis mesh (4 x 1 Q2 cells, 27 nodes, whole end fixed): tip %.5f vs the thesis's analytic "
      "P l^3/(3 E' I) = %.5f: %+.2f %% (allowed 2.5 %%; converged fully clamped %.5f, %+.1f %%)"
      % (coarse, tip, 100 * (coarse / tip - 1), converged, 100 * (converged / tip - 1)))

# The thesis's constant-strain elements on the same 27 nodes (§4.3.2): its
# CST mesh reaches 58 % and its CSQ mesh 83 % of beam theory. Computed by
# thesis_mesh_elements.py (CSTs with the squares' diagonals one way, CSQs
# as four CSTs about a centre node, the end load consistent with linear
# edges): CST 52.5 % (plane strain) and 56.7 % (plane stress), CSQ 89.5 %
# and 88.5 %. The thesis states neither its diagonals nor its plane state;
# the tolerance is doc/thesis_comparison.md's 10 % of the thesis's value,
# which both plane states meet, and which separates the two elements.
sys.path.insert(0, os.path.join(SOURCE, "cantilever"))
import thesis_mesh_elements  # noqa: E402
for strain in (True, False):
    r = thesis_mesh_elements.thesis_cantilever(strain)
    for element, thesis in (("CST", 58.0), ("CSQ", 83.0)):
        fraction = 100 * r[element] / r["beam"]
        check(abs(fraction / thesis - 1) <= 0.1,
              "%s, 27 nodes, plane %s: %.1f %% of beam theory, thesis %.0f %% (allowed 10 %%)"
              % (element, "strain" if strain else "stress", fraction, thesis))

# The lithostatic column on the thesis's nine nodes and eight CSTs
# (§4.4.2): the top left node subsides 10 % too far and the top right one
# 10 % too little, the principal axes turn by up to 13 degrees and the
# stresses err by up to 10 %. The subsidences within the same 10 % of the
# thesis's 10 % as above; the stress errors relative to the column's largest
# stress (rho g h), the reading doc/thesis_comparison.md explains.
column = thesis_mesh_elements.lithostatic_column_cst(diagonal=1)
check(abs(column["left"] - 110) <= 1 and abs(column["right"] - 90) <= 1,
      "nine-node CST column: top corners subside %.1f %% and %.1f %% of equation 4.4, "
      "thesis 110 %% and 90 %% (allowed 1 %%)" % (column["left"], column["right"]))
check(column["rotation"] <= 13 and column["magnitude_of_column"] <= 10,
      "nine-node CST column: principal axes turned by up to %.1f degrees (thesis up to 13), "
      "stresses err by up to %.1f %% of rho g h (thesis up to 10 %%)"
      % (column["rotation"], column["magnitude_of_column"]))
finish()

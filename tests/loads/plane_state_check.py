"""Plane strain and plane stress (issue 4, verification 5), and a traction
set by its resultant.

Uniaxial tension sigma_0 of a free block (left and base on rollers) has a
linear displacement field, exact in Q2 (direct solver; tolerance 1e-9):
plane strain eps_xx = (1 - nu^2) sigma_0/E, eps_yy = -nu(1 + nu) sigma_0/E;
plane stress eps_xx = sigma_0/E, eps_yy = -nu sigma_0/E. Setting the same
load as a resultant F = sigma_0 H (uniform profile) must give the same
solution, and the reaction of the left side must be -F.
"""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

E, nu, s0, L, H = 0.85e11, 0.25, 1e7, 10e3, 5e3
cases = [("plane_strain", [], (1 - nu * nu) * s0 / E, -nu * (1 + nu) * s0 / E),
         ("plane_stress", ["Plane state=plane stress"], s0 / E, -nu * s0 / E)]
for label, sets, exx, eyy in cases:
    for how, extra in (("traction", []),
                       ("resultant", ["Loads/Tractions/right/Normal traction=0",
                                      "Loads/Tractions/right/Resultant force=%r, 0" % (s0 * H)])):
        out = os.path.abspath("output_uniaxial_%s_%s" % (label, how))
        run("loads/uniaxial.prm", out, 1, ["Solver/Type=direct"] + sets + extra)
        corner, inner = read_csv(os.path.join(out, "point_values.csv"))
        ux, uy = exx * L, eyy * H
        check(abs(corner["u_x"] - ux) < 1e-9 * abs(ux) and abs(corner["u_y"] - uy) < 1e-9 * abs(uy),
              "%s, %s: corner (%.9g, %.9g) m, exact (%.9g, %.9g) m" % (label, how, corner["u_x"], corner["u_y"], ux, uy))
        check(abs(inner["sigma_xx"] - s0) < 1e-9 * s0 and abs(inner["sigma_yy"]) < 1e-9 * s0,
              "%s, %s: sigma_xx = %.9g Pa, sigma_yy = %.3g Pa" % (label, how, inner["sigma_xx"], inner["sigma_yy"]))
        szz = nu * s0 if label == "plane_strain" else 0.0
        check(abs(inner["sigma_zz"] - szz) < 1e-9 * s0, "%s, %s: sigma_zz = %.6g Pa, exact %.6g" % (label, how, inner["sigma_zz"], szz))
        f = forces(out)
        check(abs(f[("reaction", "left")][0] + s0 * H) < 1e-9 * s0 * H and abs(f[("reaction", "left")][1]) < 1e-9 * s0 * H,
              "%s, %s: reaction of the left side (%.9g, %.3g) N/m = -F" % (label, how, *f[("reaction", "left")]))
finish()

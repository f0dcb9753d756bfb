"""Thermal strain (issue 4, verification 4; thesis §3.8).

A uniform temperature change dT with linear coefficient alpha gives the
initial strain alpha dT in every direction. The exact solutions are linear
displacement fields, which Q2 represents exactly: round-off with the direct
solver (tolerance 1e-9 of the scale E alpha dT or of the displacement).

- Free block (left and base on rollers), plane strain: no in-plane stress,
  in-plane strain (1 + nu) alpha dT, sigma_zz = -E alpha dT.
- Plane stress: strain alpha dT, sigma_zz = 0.
- A volumetric coefficient: the linear strain is alpha dT / 3.
- Confined in x, free top, plane strain: sigma_xx = sigma_zz =
  -E alpha dT/(1 - nu), sigma_yy = 0, top rises by (1 + nu)/(1 - nu) alpha dT H.
"""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

E, nu, alpha, dT, L = 0.85e11, 0.25, 1e-5, 100.0, 10e3
s_scale = E * alpha * dT


def points(out):
    return read_csv(os.path.join(out, "point_values.csv"))


def free_block(label, sets, strain, szz):
    out = os.path.abspath("output_thermal_" + label)
    run("loads/thermal.prm", out, 1, ["Solver/Type=direct"] + sets)
    corner, inner = points(out)
    u = strain * L
    check(abs(corner["u_x"] - u) < 1e-9 * u and abs(corner["u_y"] - u) < 1e-9 * u,
          "%s: corner moves (%.9f, %.9f) m, exact %.9f m both" % (label, corner["u_x"], corner["u_y"], u))
    worst = max(abs(inner[c]) for c in ("sigma_xx", "sigma_yy", "sigma_xy"))
    check(worst < 1e-9 * s_scale, "%s: in-plane stress-free, max |sigma| = %.3g Pa" % (label, worst))
    check(abs(inner["sigma_zz"] - szz) < 1e-9 * s_scale,
          "%s: sigma_zz = %.6g Pa, exact %.6g Pa" % (label, inner["sigma_zz"], szz))


free_block("plane_strain", [], (1 + nu) * alpha * dT, -E * alpha * dT)
free_block("plane_stress", ["Plane state=plane stress"], alpha * dT, 0.0)
free_block("volumetric", ["Loads/Thermal strain/Coefficient type=volumetric"],
           (1 + nu) * alpha * dT / 3, -E * alpha * dT / 3)

out = os.path.abspath("output_thermal_confined")
run("loads/thermal_confined.prm", out, 1, ["Solver/Type=direct"])
corner, inner = points(out)
sxx = -E * alpha * dT / (1 - nu)
check(abs(inner["sigma_xx"] - sxx) < 1e-9 * s_scale and abs(inner["sigma_yy"]) < 1e-9 * s_scale
      and abs(inner["sigma_xy"]) < 1e-9 * s_scale,
      "confined: sigma = (%.6g, %.3g, %.3g) Pa, exact (%.6g, 0, 0)" % (inner["sigma_xx"], inner["sigma_yy"],
                                                                    inner["sigma_xy"], sxx))
check(abs(inner["sigma_zz"] - sxx) < 1e-9 * s_scale, "confined: sigma_zz = %.6g Pa = sigma_xx" % inner["sigma_zz"])
rise = (1 + nu) / (1 - nu) * alpha * dT * L
check(abs(corner["u_y"] - rise) < 1e-9 * rise and abs(corner["u_x"]) < 1e-9 * rise,
      "confined: top rises %.9f m, exact %.9f m" % (corner["u_y"], rise))
finish()

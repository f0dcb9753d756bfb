"""Isostatic restoring force (issue 4, verification 2; thesis §3.7.2.3).

Flat base: a block under a uniform top pressure p on a fluid base, sides on
vertical rollers, is in uniaxial strain; Q2 represents the exact solution
(linear displacement), so the base sinks by exactly p/(rho_f g), sigma_yy =
-p and sigma_xx = nu/(1-nu) sigma_yy to round-off. The direct solver is used
so that "exact" means round-off: tolerance 1e-9 relative, which allows a
condition number of ~1e6 times machine precision.

Sloping base (y from -20 to -40 km): the restoring force is rho_f g u_y per
unit HORIZONTAL length (weak form with |n_y| ds), so rho_f g times the
integral of u_y dx over the base must equal -p W. The integral is taken from
surface_profile.csv of the base by Simpson's rule on each Q2 face, which is
exact for the quadratic u_y (an implementation weighting by ds instead
would be off by the slope's cos = 0.98). The solver tolerance (AMG,
1e-10 relative residual) bounds the error: tolerance 1e-7.
"""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

p, rho_f, g, E, nu, W, H = 1e7, 3300.0, 9.81, 0.85e11, 0.25, 100e3, 20e3
lam = E * nu / ((1 + nu) * (1 - 2 * nu))
mu = E / (2 * (1 + nu))

out = os.path.abspath("output_isostatic_flat")
run("loads/isostatic_flat.prm", out, 1, ["Solver/Type=direct"])
pv = read_csv(os.path.join(out, "point_values.csv"))
sink = -p / (rho_f * g)
check(abs(pv[0]["u_y"] - sink) < 1e-9 * abs(sink),
      "flat base sinks by %.9f m, exact -p/(rho_f g) = %.9f m" % (pv[0]["u_y"], sink))
top = sink - p / (lam + 2 * mu) * H
check(abs(pv[1]["u_y"] - top) < 1e-9 * abs(top),
      "top moves by %.9f m, exact %.9f m (sinking + elastic shortening)" % (pv[1]["u_y"], top))
check(abs(pv[2]["sigma_yy"] + p) < 1e-9 * p and abs(pv[2]["sigma_xx"] + nu / (1 - nu) * p) < 1e-9 * p
      and abs(pv[2]["sigma_xy"]) < 1e-9 * p,
      "stress (%.6g, %.6g, %.3g) Pa, exact (%.6g, %.6g, 0)" % (pv[2]["sigma_xx"], pv[2]["sigma_yy"],
                                                             pv[2]["sigma_xy"], -nu / (1 - nu) * p, -p))
base = read_csv(os.path.join(out, "surface_profile.csv"))
check(max(abs(r["u_y"] - sink) for r in base) < 1e-9 * abs(sink), "the whole base sinks uniformly")
f = forces(out)
restoring = [v for k, v in f.items() if k[0] == "load" and k[1].startswith("isostatic")][0]
check(abs(restoring[1] - p * W) < 1e-9 * p * W and abs(restoring[0]) < 1e-9 * p * W,
      "restoring force (%.6g, %.9g) N/m = p W = %.9g" % (restoring[0], restoring[1], p * W))


def simpson_integral(rows):
    rows = sorted(rows, key=lambda r: r["x"])
    check(len(rows) % 2 == 1, "base profile has 2 points per Q2 face plus one (%d)" % len(rows))
    total = 0.0
    for i in range(0, len(rows) - 2, 2):
        a, m, b = rows[i], rows[i + 1], rows[i + 2]
        total += (b["x"] - a["x"]) / 6 * (a["u_y"] + 4 * m["u_y"] + b["u_y"])
    return total


out = os.path.abspath("output_isostatic_sloping")
run("loads/isostatic_sloping.prm", out, 1,
    ["Geometry/Gmsh/Mesh file=" + os.path.join(SOURCE, "loads", "isostatic_sloping.msh")])
integral = simpson_integral(read_csv(os.path.join(out, "surface_profile.csv")))
total = rho_f * g * integral
check(abs(total + p * W) < 1e-7 * p * W,
      "sloping base: rho_f g * integral u_y dx = %.9g N/m, exact -p W = %.9g" % (total, -p * W))
f = forces(out)
restoring = [v for k, v in f.items() if k[0] == "load" and k[1].startswith("isostatic")][0]
check(abs(restoring[1] - p * W) < 1e-7 * p * W,
      "sloping base: restoring force %.9g N/m = p W" % restoring[1])
finish()

"""Density stripping (issue 4, verification 3; thesis §7.3).

A laterally uniform column on rollers is in uniaxial strain: sigma_yy(d) =
-g * integral of (rho - rho_ref) from the top to depth d, sigma_xx =
sigma_zz = nu/(1-nu) sigma_yy. With layer interfaces on cell faces the
displacement is piecewise quadratic in depth, which Q2 represents exactly,
so the stresses are exact to round-off (direct solver; tolerance 1e-9 of
the stress scale g * 100 kg/m^3 * 10 km ~ 1e7 Pa).

1. Densities equal to the reference: no body force, stress-free.
2. One anomalous layer (+100 kg/m^3 from 10 to 20 km): the hand-computed
   profile above, along the stress-depth lines x = 5 and 2.5 km.
"""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

g, nu, drho = 9.81, 0.25, 100.0
scale = g * drho * 10e3

out = os.path.abspath("output_stripping_uniform")
run("loads/stripping.prm", out, 1,
    ["Solver/Type=direct", "Loads/Density stripping/Reference column=0, 10: 2800; 10, 20: 3000; 20, 30: 3300"])
rows = read_csv(os.path.join(out, "stress_depth_x5.csv"))
worst = max(abs(r[c]) for r in rows for c in ("sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz"))
check(len(rows) == 31 and worst <= 1e-9 * scale,
      "reference densities: stress-free, max |sigma| = %.3g Pa over %d points" % (worst, len(rows)))


def expected_syy(depth):
    return -g * drho * min(max(depth - 10e3, 0.0), 10e3)


out = os.path.abspath("output_stripping_anomaly")
result = run("loads/stripping.prm", out, 1, ["Solver/Type=direct"])
check("relative to the reference column" in result.stdout, "the log says stresses are relative to the reference")
check("lithostatic stress" in result.stdout, "the log says the Griffith test adds the lithostatic stress")
for line in ("x5", "x2.5"):
    rows = read_csv(os.path.join(out, "stress_depth_%s.csv" % line))
    err = 0.0
    for r in rows:
        syy = expected_syy(r["depth"])
        sxx = nu / (1 - nu) * syy
        err = max(err, abs(r["sigma_yy"] - syy), abs(r["sigma_xx"] - sxx), abs(r["sigma_zz"] - sxx),
                  abs(r["sigma_xy"]))
    check(len(rows) == 31 and abs(rows[-1]["depth"] - 30e3) < 1e-6 * 30e3,
          "%s: 31 points from the top to 30 km depth" % line)
    check(err <= 1e-9 * scale, "%s: anomalous layer, max stress error %.3g Pa (scale %.3g Pa)" % (line, err, scale))
    mid = min(rows, key=lambda r: abs(r["depth"] - 15e3))
    check(abs(mid["sigma_yy"] + g * drho * 5e3) < 1e-9 * scale,
          "%s: sigma_yy at 15 km = %.6g Pa, by hand -g 100 (5 km) = %.6g Pa" % (line, mid["sigma_yy"], -g * drho * 5e3))

# The Griffith test adds the lithostatic stress -rho g depth of the point's
# own material before the test (FAIL; the stripped stresses lack the
# overburden). At 15 km in the anomalous layer (T = 10 MPa) the stripped
# stresses alone would put the point in the tensile regime with C ~ 0.88;
# with the overburden (-441 MPa) it is in the closed-crack regime with
# C = 1 - tau_m sqrt(mu^2 + 1) / (mu (sigma_c - sigma_m) + 2 sqrt(T^2 - T sigma_c)),
# sigma_c = -4.19 T, mu = 1 (the defaults). Tolerance 1e-9: the stresses are exact.
out = os.path.abspath("output_stripping_griffith")
run("loads/stripping.prm", out, 1, ["Solver/Type=direct", "Materials/anomaly/Tensile strength=1e7"])
rows = read_csv(os.path.join(out, "stress_depth_x5.csv"))
r = min(rows, key=lambda r: abs(r["depth"] - 15e3))
T, sc, mu_f = 1e7, -4.19e7, 1.0
litho = -3000.0 * g * r["depth"]
s1, s2 = r["sigma_1"] + litho, r["sigma_2"] + litho
sm, tm = (s1 + s2) / 2, (s1 - s2) / 2
check(sm < sc - 2 * mu_f * (T * T - T * sc) ** 0.5, "15 km: sigma_m = %.4g Pa is in the closed-crack regime" % sm)
C = 1 - tm * (mu_f ** 2 + 1) ** 0.5 / (mu_f * (sc - sm) + 2 * (T * T - T * sc) ** 0.5)
check(r["griffith_regime"] == 3 and abs(r["griffith_C"] - C) < 1e-9,
      "15 km: Griffith regime %d, C = %.9f, by hand with the lithostatic stress %.9f" % (r["griffith_regime"], r["griffith_C"], C))
finish()

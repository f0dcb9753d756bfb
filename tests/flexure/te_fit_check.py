"""scripts/outer_rise_fit.py, the effective elastic thickness of a bent
plate (doc/plasticity.md), on synthetic data whose answers are known:

1. The deflection of a broken thin plate, w = exp(-d/a)(c1 cos(d/a) +
   c2 sin(d/a)) with a = 80 km, c1 = -1000 m, c2 = 300 m: the fit returns
   the flexural parameter to 1e-4 (golden sections on log a to 60
   iterations: far below) and Te = (12 (1 - nu^2) drho g a^4 / (4 E))^(1/3)
   with it; the rms misfit is below 1e-3 m. The same profile shifted by a
   trench at x = 200 km (--trench 200) gives the same.
2. The moment-curvature Te: a stress profile of pure bending over a plate
   of h = 40 km, sigma_xx = -E/(1 - nu^2) kappa (y - y_mid) with kappa the
   surface's curvature at the profile: M = -D kappa with D = E h^3 /
   (12 (1 - nu^2)), so Te = h; to 1e-3 (the curvature from a parabola
   through the surface points within 10 km: its error is of order
   (10 km / a)^2 / 12 of kappa, 1e-3 here).
Runs with Debian's python3 (the script's interpreter)."""
import csv
import math
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, finish  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "outer_rise_fit.py")
E, NU, DRHO, G = 7e10, 0.25, 2300.0, 9.81
A, C1, C2, H = 80e3, -1000.0, 300.0, 40e3


def w(d):
    return math.exp(-d / A) * (C1 * math.cos(d / A) + C2 * math.sin(d / A))


def curvature(d):
    # d2w/dd2 of exp(-d/a)(c1 cos + c2 sin) = (2/a^2) exp(-d/a)(c1 sin - c2 cos).
    return 2 / A ** 2 * math.exp(-d / A) * (C1 * math.sin(d / A) - C2 * math.cos(d / A))


def make(directory, trench):
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    with open(os.path.join(directory, "parameters.prm"), "w") as f:
        f.write("subsection Materials\n  set Names = plate\n  subsection plate\n"
                "    set Young's modulus = %g\n    set Poisson's ratio = %g\n  end\nend\n"
                "subsection Loads\n  subsection Isostatic restoring force\n"
                "    set Fluid densities = %g\n  end\nend\n" % (E, NU, DRHO))
    with open(os.path.join(directory, "surface_profile.csv"), "w") as f:
        f.write("x,u_x,u_y,y\n")
        for k in range(601):
            x = trench + k * 1e3
            f.write("%.17g,0,%.17g,0\n" % (x, w(x - trench)))
    d0 = 100e3
    kappa = curvature(d0)
    with open(os.path.join(directory, "stress_depth_x%g.csv" % ((trench + d0) / 1e3)), "w") as f:
        f.write("x,y,depth,sigma_xx\n")
        for k in range(121):
            y = -k * H / 120
            f.write("%.17g,%.17g,%.17g,%.17g\n"
                    % (trench + d0, y, -y, -E / (1 - NU ** 2) * kappa * (y + H / 2)))


te_expected = (12 * (1 - NU ** 2) * DRHO * G * A ** 4 / (4 * E)) ** (1 / 3)
for trench in (0.0, 200e3):
    directory = os.path.abspath("output_te_fit_%g" % (trench / 1e3))
    make(directory, trench)
    result = subprocess.run(["/usr/bin/python3", SCRIPT, directory, "--trench", "%g" % (trench / 1e3)],
                            capture_output=True, text=True)
    check(result.returncode == 0, "trench at %g km: outer_rise_fit.py runs (%s)"
          % (trench / 1e3, result.stderr.strip()[-200:]))
    fit = list(csv.DictReader(open(os.path.join(directory, "outer_rise_fit.csv"))))
    alpha, te, misfit = (float(fit[0][k]) for k in ("alpha_m", "Te_m", "rms_misfit_m"))
    check(abs(alpha - A) <= 1e-4 * A and abs(te - te_expected) <= 1e-4 * te_expected and misfit < 1e-3,
          "trench at %g km: alpha %.6g m (exact %.6g), Te %.6g m (exact %.6g), rms misfit %.1e m"
          % (trench / 1e3, alpha, A, te, te_expected, misfit))
    mc = list(csv.DictReader(open(os.path.join(directory, "outer_rise_moment_curvature.csv"))))
    te_mc = float(mc[0]["Te_m"]) if mc else math.nan
    check(len(mc) == 1 and abs(te_mc - H) <= 1e-3 * H,
          "trench at %g km: moment-curvature Te %.6g m of a pure-bending profile over %.6g m"
          % (trench / 1e3, te_mc, H))
finish()

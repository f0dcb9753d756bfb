"""Plate flexure (thesis §6.1.2): the default experiment against
thin-plate theory, computed here from the model's own inputs.

The plate's parameters are read from the parameters.prm the run writes (the
parameters as run): Young's modulus E and Poisson's ratio nu of its
material, the thickness h of the thin-plate geometry, the fluid density
rho_f and g of the isostatic restoring force on its base, and the line load
P and its position x0. Nothing is taken from `Thin plate comparison` (the
program's own copy of the thin-plate curve and its inputs). Thin plate on a
fluid (Winkler) foundation, plane strain, line load P on an infinite plate:
    D = E h^3 / (12 (1 - nu^2)),   alpha = (4 D / (rho_f g))^(1/4),
    w(x) = w0 e^(-xi) (cos xi + sin xi),  xi = |x - x0| / alpha,
    w0 = P alpha^3 / (8 D);
the forebulge crest is at xi = pi, w = -w0 e^(-pi) (uplift).

A thin plate neglects shear deformation. With it (Timoshenko plate on the
Winkler foundation k = rho_f g = 4 D / alpha^4) the deflection obeys
    D w'''' - (D k / (kappa G h)) w'' + k w = q - (D / (kappa G h)) q'',
so exp(-s x) solves the homogeneous equation for
    (alpha s)^4 - 4 eps (alpha s)^2 + 4 = 0,  alpha s = sqrt(1 + eps) +- i sqrt(1 - eps),
    eps = D / (kappa G h alpha^2) = h^2 / (6 kappa (1 - nu) alpha^2),
kappa = 5/6 (eps = 0: the thin plate's 1 +- i). To first order in eps the
decay rate grows and the wave number shrinks by eps/2, which changes w by
-eps w0 xi e^(-xi) cos xi, and the amplitudes change by O(eps): the
difference between a plate with shear deformation and the thin plate is
|dw| <= eps w0 e^(-xi) (a + xi) with a = O(1). eps = 3.7 % here
(h = 20 km, alpha = 54 km, nu = 0.25). The 2-D plate is such a plate (plus
O(eps) effects of its own through the thickness).

Checks:
1. The surface profile u_y(x) (surface_profile.csv: every Q2 support point
   of the top, 801 points on the test's mesh of 400 x 8 cells) against
   -w(x) point by point, for |x - x0| >= 3 h = 1.1 alpha (near the load the
   line force is a point singularity of the 2-D solution: a local
   indentation a few thicknesses wide, 79 m at the load, that no plate
   theory describes) and at least 2 alpha from the ends (the ends on
   vertical rollers are held in rotation; their effect, the mirror image of
   the load, is e^(-2) of the infinite plate's already tiny deflection
   there). Bound: |u_y + w| <= K eps w0 e^(-xi) (1 + xi), the first-order
   shear correction with a = 1, K = 1. Measured: the largest ratio
   |u_y + w| / (eps w0 e^(-xi) (1 + xi)) is 0.75, at the far edge of the
   window (xi = 7.2, 0.11 m against a bound of 0.15 m, where the accumulated
   phase term dominates; 0.71 against the mirror-imaged finite plate), and
   0.39 at its near edge (5.7 m at xi = 1.2, the amplitude term): K = 1 is
   1.3x the measured value. E wrong by 10 % (alpha by 2.5 %) gives a ratio
   of 1.41 (the test fails; checked).
2. The forebulge from the profile (each side's highest point, refined by
   a parabola through it and its neighbours) against the thin plate's
   crest: height within 2 eps (measured 3.9 % lower: to first order the
   2-D plate is stiffer, the amplitude term) and position within eps
   (measured 0.31 % nearer; the profile's points are h/16 = 0.7 % of
   pi alpha apart before the parabola).
3. The deflection one alpha from the load within 2 eps (measured 1.5 %
   less).
4. The profile away from the load converges: the change of u_y at the
   convergence study's points 100, 150 and 250 km from the load between
   the two meshes is far below the thin-plate difference."""
import sys, os, csv, math
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

ROOT = os.path.dirname(SOURCE)


def numbers(text):
    """'a, b; c, d' as a list of lists of floats."""
    return [[float(v) for v in part.split(",")] for part in text.split(";") if part.strip()]


out = os.path.abspath("output_flexure")
run(os.path.join(ROOT, "prm", "flexure.prm"), out, 1,
    ["Mesh refinement/Initial global refinement=1", "Mesh refinement/Number of cycles=2",
     "Output/Write ParaView files=false"])

# The model's own inputs, as run.
prm = read_prm(os.path.join(out, "parameters.prm"))
unit = {"km": 1e3, "m": 1.0}[prm["Geometry/Length unit"]]
check(prm["Geometry/Model"] == "thin plate" and prm["Plane state"] == "plane strain",
      "the model is a thin-plate geometry in plane strain")
material = prm["Materials/Names"].split(",")[0].strip()
E = float(prm["Materials/%s/Young's modulus" % material])
nu = float(prm["Materials/%s/Poisson's ratio" % material])
h = float(prm["Geometry/Thin plate/Thickness"]) * unit
length = float(prm["Geometry/Thin plate/Length"]) * unit
parts = [p.strip() for p in prm["Loads/Isostatic restoring force/Boundary parts"].split(",")]
densities = [float(v) for v in prm["Loads/Isostatic restoring force/Fluid densities"].split(",")]
check(parts == ["base"], "the fluid foundation acts on the base only")
rho_f = densities[0]
g = float(prm["Gravity field/Acceleration"])
load_points = numbers(prm["Loads/Line forces/Points"])
load_forces = numbers(prm["Loads/Line forces/Forces"])
check(len(load_points) == 1 and load_forces[0][0] == 0 and load_forces[0][1] < 0,
      "one downward line load")
x0 = load_points[0][0] * unit
P = -load_forces[0][1]

D = E * h ** 3 / (12 * (1 - nu * nu))
alpha = (4 * D / (rho_f * g)) ** 0.25
w0 = P * alpha ** 3 / (8 * D)
kappa = 5.0 / 6.0
eps = h * h / (6 * kappa * (1 - nu) * alpha * alpha)
print("info E = %g Pa, nu = %g, h = %g m, rho_f = %g kg/m^3, g = %g, P = %g N/m at x0 = %g m:"
      " D = %.4e N m, alpha = %.2f km, w0 = %.2f m, eps = %.2f %%"
      % (E, nu, h, rho_f, g, P, x0, D, alpha / 1e3, w0, 100 * eps))


def w(x):
    xi = abs(x - x0) / alpha
    return w0 * math.exp(-xi) * (math.cos(xi) + math.sin(xi))


profile = read_csv(os.path.join(out, "surface_profile.csv"))
xs = [r["x"] for r in profile]
uy = [r["u_y"] for r in profile]
check(all(math.isfinite(v) for v in xs + uy) and len(profile) > 100,
      "surface profile: %d finite points" % len(profile))

# 1. Point by point away from the load and the ends.
K = 1.0
worst_ratio, worst_diff, n = 0.0, 0.0, 0
for x, u in zip(xs, uy):
    d = abs(x - x0)
    if d < 3 * h or x < 2 * alpha or x > length - 2 * alpha:
        continue
    xi = d / alpha
    diff = abs(u + w(x))
    ratio = diff / (eps * w0 * math.exp(-xi) * (1 + xi))
    if ratio > worst_ratio:
        worst_ratio, at = ratio, x
    worst_diff = max(worst_diff, diff)
    n += 1
check(n > 100, "%d profile points compared with the thin plate" % n)
check(worst_ratio <= K,
      "u_y against -w(x): largest |u_y + w| / (eps w0 e^-xi (1 + xi)) = %.2f at %.0f km from the "
      "load (allowed %.1f)" % (worst_ratio, abs(at - x0) / 1e3, K))
print("info largest |u_y + w| in the window: %.2f m = %.2f %% of w0 (eps = %.2f %%)"
      % (worst_diff, 100 * worst_diff / w0, 100 * eps))

# 2. The forebulge crest on each side.
crest_tp = w0 * math.exp(-math.pi)
for side, sign in (("left", -1), ("right", 1)):
    idx = [i for i, x in enumerate(xs) if sign * (x - x0) > 3 * h and 0 < i < len(xs) - 1]
    i = max(idx, key=lambda k: uy[k])
    (xa, ya), (xb, yb), (xc, yc) = [(xs[k], uy[k]) for k in (i - 1, i, i + 1)]
    # vertex of the parabola through the three points
    den = (xa - xb) * (xa - xc) * (xb - xc)
    A = (xc * (yb - ya) + xb * (ya - yc) + xa * (yc - yb)) / den
    B = (xc * xc * (ya - yb) + xb * xb * (yc - ya) + xa * xa * (yb - yc)) / den
    Cc = (xb * xc * (xb - xc) * ya + xc * xa * (xc - xa) * yb + xa * xb * (xa - xb) * yc) / den
    xv = -B / (2 * A)
    height = Cc - B * B / (4 * A)
    distance = abs(xv - x0)
    check(abs(height / crest_tp - 1) <= 2 * eps,
          "%s forebulge height %.2f m vs thin plate %.2f m (%.1f %%, allowed %.1f %%)"
          % (side, height, crest_tp, 100 * (height / crest_tp - 1), 200 * eps))
    check(abs(distance / (math.pi * alpha) - 1) <= eps,
          "%s forebulge %.1f km from the load vs thin plate pi alpha = %.1f km (%.2f %%, allowed %.1f %%)"
          % (side, distance / 1e3, math.pi * alpha / 1e3,
             100 * (distance / (math.pi * alpha) - 1), 100 * eps))

# 3. One alpha from the load (both sides, linear interpolation between the
# profile's points, spaced h/16 = 0.02 alpha).
for side, sign in (("left", -1), ("right", 1)):
    xt = x0 + sign * alpha
    k = max(i for i, x in enumerate(xs) if x <= xt)
    u = uy[k] + (uy[k + 1] - uy[k]) * (xt - xs[k]) / (xs[k + 1] - xs[k])
    check(abs(-u / w(xt) - 1) <= 2 * eps,
          "%s: deflection one alpha from the load %.1f m vs thin plate %.1f m (%.1f %%)"
          % (side, -u, w(xt), 100 * (-u / w(xt) - 1)))

# 4. Points 2-4 are 100, 150 and 250 km from the load: the change of u_y
# between the two meshes must be far below the thin-plate difference.
rows = table(out)
for p in (2, 3, 4):
    change = rows[-1]["change_u_y@P%d" % p]
    check(change < 1e-3 * abs(rows[-1]["u_y@P%d" % p]) + 1e-3,
          "u_y at P%d converged: change %.1e m between meshes" % (p, change))
finish()

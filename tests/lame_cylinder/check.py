"""Lame's cylinder on the quarter annulus: the curved-geometry test. With
the degree-2 mapping on the polar manifold, L2(u) ~ h^3 (N^-1.5). Checks of
the check: with a degree-1 mapping the geometry error limits the rate to
h^2 (N^-1); without the manifold (new vertices on straight chords) the
error stalls at the coarse polygon's geometry error.

The closed forms are also evaluated here, independently of the program's
reference solution (plane strain: lambda = E nu / ((1 + nu)(1 - 2 nu)),
mu = E / (2 (1 + nu))): in each layer u_r = A r + B / r, u_theta = 0,
sigma_rr = 2 (lambda + mu) A - 2 mu B / r^2, sigma_tt = 2 (lambda + mu) A
+ 2 mu B / r^2, sigma_zz = nu (sigma_rr + sigma_tt). Lame's single cylinder
under internal pressure p: sigma_rr = p a^2/(b^2 - a^2) (1 - b^2/r^2),
sigma_tt = p a^2/(b^2 - a^2) (1 + b^2/r^2), u_r = (1 + nu)/E p a^2/(b^2 -
a^2) ((1 - 2 nu) r + b^2 / r). The composite cylinder (body a < r < b
bonded in a shell b < r < b + t): A, B in each layer from sigma_rr(a) = -p,
u_r and sigma_rr continuous at b, sigma_rr(b + t) = 0. The program's
point values (Convergence study/Points, point_values.csv of the finest
mesh) are compared with them at several radii and angles, including the
loaded and the free surface (tractions -p and 0)."""
import math, sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

P_INT, A_IN, B_OUT = 1e3, 2.0, 4.0


def moduli(E, nu):
    """Plane-strain Lame constants."""
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def constants(text):
    """'a=1, b=2' as {"a": 1.0, "b": 2.0}."""
    return {k.strip(): float(v) for k, v in (c.split("=") for c in text.split(",") if c.strip())}


def points_at(polar):
    """'x, y; ...' for a list of (r, theta in degrees)."""
    return "; ".join("%.15g, %.15g" % (r * math.cos(math.radians(t)), r * math.sin(math.radians(t)))
                     for r, t in polar)


def compare_points(tag, out, polar, exact, tol_u, tol_s):
    """point_values.csv of <out> against exact(r) = (u_r, s_rr, s_tt, s_zz)
    at the (r, theta) of @polar: u_r and u_theta relative to the largest
    u_r, stresses relative to p."""
    rows = read_csv(os.path.join(out, "point_values.csv"))
    check(len(rows) == len(polar), "%s: %d point values written" % (tag, len(rows)))
    umax = max(abs(exact(r)[0]) for r, _ in polar)
    worst_u = worst_s = 0.0
    for row, (r, t) in zip(rows, polar):
        c, s = math.cos(math.radians(t)), math.sin(math.radians(t))
        check(abs(row["x"] - r * c) < 1e-9 and abs(row["y"] - r * s) < 1e-9,
              "%s: point r = %g, theta = %g" % (tag, r, t))
        ur = row["u_x"] * c + row["u_y"] * s
        ut = -row["u_x"] * s + row["u_y"] * c
        srr = row["sigma_xx"] * c * c + row["sigma_yy"] * s * s + 2 * row["sigma_xy"] * c * s
        stt = row["sigma_xx"] * s * s + row["sigma_yy"] * c * c - 2 * row["sigma_xy"] * c * s
        e_ur, e_srr, e_stt, e_szz = exact(r)
        du = max(abs(ur - e_ur), abs(ut)) / umax
        ds = max(abs(srr - e_srr), abs(stt - e_stt), abs(row["sigma_zz"] - e_szz)) / P_INT
        worst_u, worst_s = max(worst_u, du), max(worst_s, ds)
        print("info %s r = %.4f: u_r %.9e (exact %.9e), sigma_rr %.6f (%.6f), sigma_tt %.6f (%.6f), "
              "sigma_zz %.6f (%.6f)" % (tag, r, ur, e_ur, srr, e_srr, stt, e_stt, row["sigma_zz"], e_szz))
    check(worst_u <= tol_u, "%s: u_r, u_theta at %d points: largest error %.1e of max u_r (allowed %.1e)"
          % (tag, len(polar), worst_u, tol_u))
    check(worst_s <= tol_s, "%s: sigma_rr, sigma_tt, sigma_zz at %d points: largest error %.1e of p "
          "(allowed %.1e)" % (tag, len(polar), worst_s, tol_s))

def rates(tag, sets):
    out = os.path.abspath("output_lame_" + tag)
    run("lame_cylinder/lame.prm", out, 1, sets)
    rows = table(out)
    return rows, slope(rows, "L2(u)", len(rows) - 3), slope(rows, "energy", len(rows) - 3)

# Points at several radii and angles (inside: not on cell faces of any
# refinement, the radii are not a + dyadic fractions of b - a, the angles
# not dyadic fractions of 90 degrees), the first on the loaded and the last
# on the free surface (there at the vertices on the symmetry lines: a point
# on a curved boundary between vertices can lie outside the coarse mesh).
LAME_POINTS = [(2.0, 0), (2.3, 25), (2.7, 40), (3.3, 55), (3.7, 70), (4.0, 90)]
rows, r2, e2 = rates("q2", ["Convergence study/Points=" + points_at(LAME_POINTS)])
check(abs(r2 - 1.5) < 0.1, "Q2 mapping: L2 rate %.3f in DoFs (%.2f in h), expected 1.5 (3)" % (r2, 2 * r2))
check(abs(e2 - 1.0) < 0.1, "Q2 mapping: energy rate %.3f, expected 1" % e2)
check(rows[-1]["rel_L2(u)"] < 1e-7, "Q2 mapping: finest relative L2 error %.2e" % rows[-1]["rel_L2(u)"])

# Elements of degree 3 and 4 (with mappings of the same degree on the
# polar manifold): L2(u) ~ h^(p+1), the energy norm ~ h^p, i.e. rates
# (p+1)/2 and p/2 in DoFs (measured on 2026-12-02 over cycles 2-4: 2.03,
# 1.52 for p = 3; 2.52, 2.02 for p = 4), and on each mesh the higher
# degree's error is the smaller. Five cycles, 33 282 DoFs at most: the
# degree 4's last rate is still 2.52 at an L2 error of 1.6e-12, not yet
# at the solver's tolerance.
by_degree = {2: rows}
for p in (3, 4):
    rows_p, rate_l2, rate_energy = rates(
        "q%d" % p, ["Discretization/Polynomial degree=%d" % p,
                    "Discretization/Mapping degree=%d" % p,
                    "Mesh refinement/Number of cycles=5"])
    check(abs(rate_l2 - (p + 1) / 2) < 0.1 and abs(rate_energy - p / 2) < 0.1,
          "Q%d elements: L2 rate %.3f and energy rate %.3f in DoFs, expected %.1f and %.1f"
          % (p, rate_l2, rate_energy, (p + 1) / 2, p / 2))
    by_degree[p] = rows_p
for p in (3, 4):
    worse = [c for c in range(5) if not by_degree[p][c]["L2(u)"] < by_degree[p - 1][c]["L2(u)"]]
    check(not worse, "Q%d: the L2 error below Q%d's on every one of the 5 meshes (not on %s)"
          % (p, p - 1, worse))

# Lame's closed form at the points, from the inputs as run.
prm = read_prm(os.path.join(os.path.abspath("output_lame_q2"), "parameters.prm"))
E, nu = float(prm["Materials/body/Young's modulus"]), float(prm["Materials/body/Poisson's ratio"])
a, b = float(prm["Geometry/Quarter annulus/Inner radius"]), float(prm["Geometry/Quarter annulus/Outer radius"])
check(prm["Loads/Tractions/inner/Normal traction"] == "-p" and prm["Plane state"] == "plane strain"
      and constants(prm["Loads/Tractions/inner/Constants"]) == {"p": P_INT}
      and (a, b) == (A_IN, B_OUT), "Lame cylinder: plane strain, a = %g, b = %g, pressure %g inside" % (a, b, P_INT))
q = P_INT * a * a / (b * b - a * a)
lame = lambda r: ((1 + nu) / E * q * ((1 - 2 * nu) * r + b * b / r),
                  q * (1 - b * b / (r * r)), q * (1 + b * b / (r * r)), nu * 2 * q)
# Tolerances: the largest point errors on the finest mesh (64 x 64 cells,
# 33 k DoFs) are 4.9e-8 of max u_r (u_r at r = 2.3) and 2.8e-4 of p
# (sigma_rr at the loaded vertex r = a, where the stress of the cell is
# extrapolated to its corner; 7e-5 of p at the interior points); the bounds
# are ~2x those. A wrong modulus, Poisson's ratio or plane state changes
# u_r or sigma_zz by O(1e-2) and more.
compare_points("Lame cylinder", os.path.abspath("output_lame_q2"), LAME_POINTS, lame, 1e-7, 6e-4)

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

# Composite cylinder: body in a stiff bonded shell, thesis §4.5.2
# at t = 0 (elastic): body E = 1e5, nu = 0.3333, a = 2, b = 4, shell
# E = 3e7, nu = 0.3015, thickness 4/33, internal pressure 1e3.
SHELL_T = 4.0 / 33.0
SHELL_POINTS = [(2.0, 0), (2.3, 25), (2.7, 40), (3.3, 55), (3.7, 70), (3.95, 20),
                (4.0 + SHELL_T / 3, 35), (4.0 + SHELL_T, 90)]
out = os.path.abspath("output_lame_shell")
run("lame_cylinder/lame.prm", out, 1,
    ["Geometry/Quarter annulus/Shell thickness=%.15g" % SHELL_T, "Geometry/Quarter annulus/Cells around=4",
     "Convergence study/Lame cylinder/Shell thickness=%.15g" % SHELL_T,
     "Materials/Names=body, shell", "Materials/body/Poisson's ratio=0.3333", "Materials/shell/Material id=1",
     "Materials/shell/Young's modulus=3e7", "Materials/shell/Poisson's ratio=0.3015",
     "Mesh refinement/Number of cycles=5", "Convergence study/Points=" + points_at(SHELL_POINTS)])
rows = table(out)
rs = slope(rows, "L2(u)", 1)
check(abs(rs - 1.5) < 0.15, "composite cylinder: L2 rate %.3f, expected 1.5" % rs)

prm = read_prm(os.path.join(out, "parameters.prm"))
layers = [moduli(float(prm["Materials/%s/Young's modulus" % m]), float(prm["Materials/%s/Poisson's ratio" % m]))
          for m in ("body", "shell")]
nus = [float(prm["Materials/%s/Poisson's ratio" % m]) for m in ("body", "shell")]
youngs = [float(prm["Materials/%s/Young's modulus" % m]) for m in ("body", "shell")]
t_shell = float(prm["Geometry/Quarter annulus/Shell thickness"])
check(abs(t_shell - SHELL_T) < 1e-12 and nus == [0.3333, 0.3015] and youngs == [1e5, 3e7]
      and constants(prm["Loads/Tractions/inner/Constants"]) == {"p": P_INT},
      "composite cylinder: the thesis's body and shell (t = %.6f)" % t_shell)
srr_row = lambda layer, r: [2 * sum(layers[layer]), -2 * layers[layer][1] / (r * r)]
(l0, m0), (l1, m1) = layers
A0, B0, A1, B1 = solve_dense([srr_row(0, A_IN) + [0, 0],
                        [B_OUT, 1 / B_OUT, -B_OUT, -1 / B_OUT],
                        srr_row(0, B_OUT) + [-v for v in srr_row(1, B_OUT)],
                        [0, 0] + srr_row(1, B_OUT + t_shell)],
                       [-P_INT, 0, 0, 0])


def composite(r):
    layer, A, B = (0, A0, B0) if r <= B_OUT else (1, A1, B1)
    lam, mu = layers[layer]
    srr, stt = 2 * (lam + mu) * A - 2 * mu * B / (r * r), 2 * (lam + mu) * A + 2 * mu * B / (r * r)
    return A * r + B / r, srr, stt, nus[layer] * (srr + stt)


# The thesis prints the t = 0 solution as sigma_r = -p (f + (b/r)^2 g),
# sigma_t = -p (f - (b/r)^2 g) with f(0) = 1 - 0.005363 - 0.6331 and
# g(0) = 0.001341 + 0.1583 (the sign of 0.1583 corrected, see
# doc/viscoelastic_cylinder_derivation.md) for the shell taken as a ring of
# radial stiffness E_s t/((1 - nu_s^2) b^2) (that closed form reproduces the
# printed f(0) to 1e-5). The resolved shell differs from the ring by O(t/b)
# of the shell's share (~0.3 % of p, doc/viscoelastic_cylinder_derivation.md):
# measured 0.34 % of p (sigma_t at r = a); the closed form above must agree
# with the print to 0.5 % of p (a check of the closed form, not of the
# program).
f0, g0 = 1 - 0.005363 - 0.6331, 0.001341 + 0.1583
thesis = max(max(abs(composite(r)[1] + P_INT * (f0 + (B_OUT / r) ** 2 * g0)),
                 abs(composite(r)[2] + P_INT * (f0 - (B_OUT / r) ** 2 * g0))) for r in (2.0, 2.5, 3.0, 3.5, 4.0))
check(thesis <= 5e-3 * P_INT, "composite cylinder closed form against the thesis's printed t = 0 stresses: "
      "largest difference %.2f %% of p (ring vs resolved shell, allowed 0.5 %%)" % (100 * thesis / P_INT))
# Tolerances: the largest point errors on the finest mesh (4 x (2 + 1)
# coarse cells refined 4 times, 25 k DoFs) are 1.1e-6 of max u_r (r = 2.3)
# and 6.0e-4 of p (sigma_rr at the loaded vertex r = a); bounds 3e-6 and
# 1.5e-3, ~2.5x those and below the 3.4e-3 of p by which a shell taken as
# a ring would differ.
compare_points("composite cylinder", out, SHELL_POINTS, composite, 3e-6, 1.5e-3)
finish()

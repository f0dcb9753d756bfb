"""Temperature/Model = steady conduction (doc/equations.md §11) against
closed forms of -div(k grad T) = H, through both inputs that offer it.

1. The layered box of conduction.prm: a crust 0 < d < d1 (k1, H1) on a
   mantle d1 < d < d2 (k2, H2 = 0), T(0) = T0, T(d2) = Tb, insulating
   sides. In each layer T is quadratic in the depth d (Turcotte & Schubert
   2014, eq. 4.31 with constant H): with q0 the surface heat flow,
   T = T0 + q0 d/k1 - H1 d^2/(2 k1) in the crust, and with q1 = q0 - H1 d1,
   T = T1 + q1 (d - d1)/k2 in the mantle; q0 from T(d2) = Tb. The Q2
   elements hold it exactly where the layer interface is a row of cell
   faces, so the profile's temperature column must match it to 1e-9 of
   Tb - T0 (the solve's 1e-12, the CSV's 10 digits) on 1 and 2 ranks and
   after adaptive refinement (the field is solved again on each new mesh).
2. A quarter annulus a < r < b (the quarter annulus geometry and the same
   cylinder read from a Gmsh file), T(a) = Ti, T(b) = To, constant k and H:
   T = -H r^2/(4 k) + A ln r + B. Not a polynomial, so the error at the
   report points falls with the mesh: under uniform refinement at the rate
   of Q2 elements on the exact (degree-2 mapped) geometry, h^3 in the
   maximum at fixed points (asserted > 2.5 between the two finest meshes),
   and under adaptive refinement (Kelly on the displacement of Lame's
   load, half of the cells refined per cycle) by at least 10 over 3
   cycles."""
import sys, os, math
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

# 1. The layered box.
T0, Tb, d1, d2 = 273.0, 1573.0, 20e3, 60e3
k1, H1, k2 = 2.5, 1e-6, 3.3
# Tb = T0 + q0 d1/k1 - H1 d1^2/(2 k1) + (q0 - H1 d1)(d2 - d1)/k2
q0 = (Tb - T0 + H1 * d1 ** 2 / (2 * k1) + H1 * d1 * (d2 - d1) / k2) / (d1 / k1 + (d2 - d1) / k2)
T1 = T0 + q0 * d1 / k1 - H1 * d1 ** 2 / (2 * k1)


def layered(d):
    """The two-layer geotherm at depth d [m]."""
    if d <= d1:
        return T0 + q0 * d / k1 - H1 * d * d / (2 * k1)
    return T1 + (q0 - H1 * d1) * (d - d1) / k2


print("surface heat flow q0 = %.2f mW/m^2, T(d1) = %.1f K" % (q0 * 1e3, T1))
cases = [("1 rank", 1, []), ("2 ranks", 2, []),
         ("adaptive, 3 cycles", 1, ["Mesh refinement/Strategy=adaptive",
                                    "Mesh refinement/Number of cycles=3"])]
for label, ranks, sets in cases:
    out = os.path.abspath("output_conduction_%s" % label.replace(" ", "_").replace(",", ""))
    run("temperature/conduction.prm", out, ranks, sets)
    rows = read_csv(os.path.join(out, "stress_depth_x30.csv"))
    check(len(rows) == 25 and all("temperature" in r for r in rows),
          "%s: 25 profile rows with a temperature column" % label)
    worst = max(abs(r["temperature"] - layered(-r["y"])) for r in rows) if rows else float("inf")
    check(worst < 1e-9 * (Tb - T0),
          "%s: the layered geotherm to 1e-9 of Tb - T0 (%.2e K)" % (label, worst))

# 2. The quarter annulus, by the geometry model and from Gmsh.
a, b, Ti, To, k, H = 2.0, 4.0, 1300.0, 300.0, 2.0, 50.0
# T = -H r^2/(4k) + A ln r + B through (a, Ti), (b, To)
A = (To - Ti + H * (b * b - a * a) / (4 * k)) / math.log(b / a)
B = Ti + H * a * a / (4 * k) - A * math.log(a)


def annulus(r):
    """The annulus's geotherm at radius r."""
    return -H * r * r / (4 * k) + A * math.log(r) + B


polar = [(r, t) for r in (2.3, 2.9, 3.6) for t in (10, 45, 80)]
points = "; ".join("%.15g, %.15g" % (r * math.cos(math.radians(t)), r * math.sin(math.radians(t)))
                   for r, t in polar)
conduction = ["Temperature/Model=steady conduction",
              "Temperature/Steady conduction/Thermal conductivity=%g" % k,
              "Temperature/Steady conduction/Radiogenic heat production=%g" % H,
              "Temperature/Steady conduction/Top boundary=inner",
              "Temperature/Steady conduction/Top temperature=%g" % Ti,
              "Temperature/Steady conduction/Base boundary=outer",
              "Temperature/Steady conduction/Base temperature=%g" % To,
              "Convergence study/Reference solution=none",
              "Convergence study/Points=" + points,
              "Mesh refinement/Number of cycles=1"]
gmsh = ["Geometry/Model=gmsh",
        "Geometry/Gmsh/Mesh file=" + os.path.join(SOURCE, "lame_cylinder", "quarter_annulus.msh"),
        "Geometry/Gmsh/Circular arcs=inner: 0, 0; outer: 0, 0",
        "Materials/body/Material id="]


def annulus_error(tag, sets):
    """The largest |T_h - T| at the report points [K]."""
    out = os.path.abspath("output_conduction_annulus_%s" % tag)
    run("lame_cylinder/lame.prm", out, 1, conduction + sets)
    rows = read_csv(os.path.join(out, "point_values.csv"))
    check(len(rows) == len(polar), "%s: %d report points" % (tag, len(polar)))
    if not rows:
        return float("inf")
    return max(abs(row["temperature"] - annulus(math.hypot(row["x"], row["y"]))) for row in rows)


for name, sets in (("quarter annulus", []), ("Gmsh", gmsh)):
    tag = name.split()[-1].lower()
    errors = [annulus_error("%s_%d" % (tag, level), sets + ["Mesh refinement/Initial global refinement=%d" % level])
              for level in range(4)]
    print("%s, uniform: max errors %s K" % (name, ", ".join("%.3e" % e for e in errors)))
    check(all(errors[i + 1] < errors[i] for i in range(3)),
          "%s: the error falls under uniform refinement" % name)
    rate = math.log2(errors[-2] / errors[-1])
    check(rate > 2.5, "%s: rate %.2f between the two finest meshes (Q2 on the exact geometry: 3)"
          % (name, rate))
    adaptive = [annulus_error("%s_adaptive_%d" % (tag, cycles),
                              sets + ["Mesh refinement/Strategy=adaptive",
                                      "Mesh refinement/Marking=fraction of cells",
                                      "Mesh refinement/Refine fraction=0.5",
                                      "Mesh refinement/Initial global refinement=1",
                                      "Mesh refinement/Number of cycles=%d" % cycles])
                for cycles in (1, 4)]
    print("%s, adaptive: %.3e K after 1 cycle, %.3e K after 4" % (name, adaptive[0], adaptive[1]))
    check(adaptive[1] < adaptive[0] / 10,
          "%s: adaptive refinement reduces the error by at least 10 over 3 cycles" % name)

# Several parts held at the Top temperature: the subduction zone's top is
# the ocean floor and the land (prm/subduction_viscoplastic.prm, its
# elastic t = 0 solve on the coarse mesh). The top of a profile on each
# part is at 273 K (an insulating land would be far warmer: the base is at
# 1623 K), the base at 1623 K, and the maximum principle holds between
# (no heat sources in the oceanic profile; radiogenic heat in the
# continental crust raises no point above the base's 1623 K here).
out = os.path.abspath("output_conduction_subduction")
run(os.path.join(os.path.dirname(SOURCE), "prm", "subduction_viscoplastic.prm"), out, 1,
    ["Time stepping/Enabled=false", "Mesh refinement/Initial global refinement=0",
     "Output/Stress-depth profiles=300, 800", "Output/Figures/Enabled=false",
     "Output/Write ParaView files=false"])
for x, part in ((300, "ocean_floor"), (800, "land")):
    profile = sorted(read_csv(os.path.join(out, "stress_depth_x%d.csv" % x)), key=lambda r: r["depth"])
    top, base = profile[0]["temperature"], profile[-1]["temperature"]
    inside = [r["temperature"] for r in profile[1:-1]]
    check(abs(top - 273) <= 1e-9 * 273 and abs(base - 1623) <= 1e-9 * 1623
          and all(273 < t < 1623 for t in inside),
          "subduction zone, x = %d km (%s): T = %.10g K at the top, %.10g K at the base, "
          "%.6g to %.6g K between" % (x, part, top, base, min(inside), max(inside)))
finish()

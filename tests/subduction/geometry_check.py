"""The subduction-zone section of thesis §7.2 (Geometry/Model = subduction
zone; issue 17), checked as geometry before any physics:

1. The area of each of the six regions (material ids) against closed forms
   and quadratures of the section as defined (flat oceanic layers, the
   slab's layers between circles about (445.456, -305) km of radius 300,
   295 and 270 km, the continental layers 10 and 35 km below a surface
   rising linearly from the trench (500, -10) km to the coast, all above
   the base at -95 km and right of the plate boundary): the gravity load
   of a run where one region has density 1 and the others 0 is -g times
   its area. For the three layouts of the continental blocks: the coast at
   575 km (the default: the lower crust's block spans the coast, its top
   kinks), 620 km (the mantle's block spans it) and 700 km (right of the
   slab: every layer a wedge and a flat block). Measured within 4e-8 on the coarse mesh (510
   cells; what is left is the Q2 mapping of the cells next to the arcs);
   tolerance 1e-6, while a region given the wrong material id, or a layer
   boundary off its curve by a cell, changes an area by > 0.1 %.
2. A uniform strain (every boundary part given u = (e1 x, e2 y), every
   region the same moduli, the plate boundary locked) is reproduced to
   round-off at points in every plate on two uniformly refined meshes, on
   1 and 2 ranks: the isoparametric Q2 space holds the linear field on the
   curved cells, the fault's constraints are consistent.
3. With an elastic plate boundary, every interface point of the refined
   meshes lies on the circle of radius 300 km, and s runs from 0 at the
   trench to the arc length to the base.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, finish, read_csv, run  # noqa: E402

PRM = "subduction/uniform_strain.prm"
REGIONS = ["oceanic_crust", "oceanic_lid", "oceanic_mantle", "upper_crust", "lower_crust",
           "continental_mantle"]
CX, CY, R = 445.456e3, -305e3, 300e3
W, BASE, SEA, XT, LAND = 920e3, -95e3, -5e3, 500e3, 0.0
XC = 575e3
TC, TE, CE, CC = 5e3, 30e3, 10e3, 35e3
YT = CY + math.sqrt(R * R - (XT - CX) ** 2)


def segment(r):
    """Area of {x >= CX, y >= BASE, |p - c| <= r}."""
    a = BASE - CY
    return r * r * math.pi / 4 - (a / 2 * math.sqrt(r * r - a * a) + r * r / 2 * math.asin(a / r))


def integrate(f, a, b, n=20000):
    """Composite Simpson on [a, b] (n even)."""
    h = (b - a) / n
    return h / 3 * (f(a) + f(b) + sum((4 if k % 2 else 2) * f(a + k * h) for k in range(1, n)))


def land(x):
    return LAND if x >= XC else YT + (LAND - YT) * (x - XT) / (XC - XT)


def arc_y(x):
    """Height of the plate boundary at x (below the base beyond it)."""
    d = R * R - (x - CX) ** 2
    return max(CY + math.sqrt(d), BASE) if d > 0 else BASE


def continental(depth_top, depth_bottom):
    """Area between depth_top and depth_bottom below the land, above the
    plate boundary and the base (split where the integrand kinks)."""
    def f(x):
        top = max(land(x) - depth_top, arc_y(x))
        bottom = max(land(x) - depth_bottom, arc_y(x)) if depth_bottom is not None else arc_y(x)
        return top - bottom
    xs = sorted({XT, XC, W, CX + math.sqrt(R * R - (BASE - CY) ** 2)}
                | {x for x in crossings(depth_top, depth_bottom)})
    return sum(integrate(f, a, b) for a, b in zip(xs, xs[1:]))


def crossings(*depths):
    """x where land - depth meets the plate boundary (bisection)."""
    out = []
    for d in depths:
        if d is None:
            continue
        lo, hi = XT, CX + math.sqrt(R * R - (BASE - CY) ** 2)
        g = lambda x: land(x) - d - arc_y(x)  # noqa: E731
        if g(lo) * g(hi) > 0:
            continue
        for _ in range(200):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if g(mid) * g(lo) > 0 else (lo, mid)
        out.append(lo)
    return out


G = 9.81
worst = 0.0
for coast in (575e3, 620e3, 700e3):
    XC = coast
    exact = {
        "oceanic_crust": CX * TC + segment(R) - segment(R - TC),
        "oceanic_lid": CX * (TE - TC) + segment(R - TC) - segment(R - TE),
        "oceanic_mantle": CX * (SEA - TE - BASE) + segment(R - TE),
        "upper_crust": continental(0.0, CE),
        "lower_crust": continental(CE, CC),
        "continental_mantle": continental(CC, None),
    }
    for region in REGIONS:
        out = os.path.abspath("output_subduction_area_%s" % region)
        sets = ["Mesh refinement/Number of cycles=1", "Output/Force balance=true",
                "Loads/Gravity/Enabled=true", "Output/Figures/Enabled=false",
                "Output/Write ParaView files=false",
                "Geometry/Subduction zone/Coast position=%g" % (coast / 1e3)]
        sets += ["Materials/%s/Density=%d" % (r, 1 if r == region else 0) for r in REGIONS]
        run(PRM, out, 1, sets)
        rows = read_csv(os.path.join(out, "force_balance.csv"))
        area = -[r for r in rows if r["kind"] == "load"][0]["F_y"] / G
        worst = max(worst, abs(area - exact[region]) / exact[region])
        check(abs(area - exact[region]) <= 1e-6 * exact[region],
              "coast %g km, %s: area %.6f km^2 (exact %.6f km^2)"
              % (coast / 1e3, region, area / 1e6, exact[region] / 1e6))
XC = 575e3

E1, E2 = 1e-4, -5e-5
E, NU = 0.85e11, 0.25
lam, mu = E * NU / ((1 + NU) * (1 - 2 * NU)), E / (2 * (1 + NU))
s_xx, s_yy = lam * (E1 + E2) + 2 * mu * E1, lam * (E1 + E2) + 2 * mu * E2
for ranks in (1, 2):
    out = os.path.abspath("output_subduction_uniform_%d" % ranks)
    run(PRM, out, ranks, ["Output/Figures/Enabled=false", "Output/Write ParaView files=false"])
    rows = read_csv(os.path.join(out, "point_values.csv"))
    diff = max(max(abs(r["u_x"] - E1 * r["x"]), abs(r["u_y"] - E2 * r["y"])) / (E1 * W)
               + max(abs(r["sigma_xx"] - s_xx), abs(r["sigma_yy"] - s_yy), abs(r["sigma_xy"]))
               / s_xx for r in rows)
    check(len(rows) == 7 and diff < 1e-9,
          "uniform strain, %d rank(s): exact at %d points in both plates and the slab on 2 040 "
          "cells (largest relative difference %.1e)" % (ranks, len(rows), diff))

out = os.path.abspath("output_subduction_elastic_boundary")
run(PRM, out, 1, ["Faults/plate_boundary/Interface law=elastic",
                  "Faults/plate_boundary/Shear stiffness=1e9",
                  "Faults/plate_boundary/Normal stiffness=1e9",
                  "Output/Figures/Enabled=false", "Output/Write ParaView files=false"])
fault = read_csv(os.path.join(out, "fault.csv"))
off = max(abs(math.hypot(p["x"] - CX, p["y"] - CY) - R) for p in fault)
length = R * (math.asin((CX + math.sqrt(R * R - (BASE - CY) ** 2) - CX) / R) - math.asin((XT - CX) / R))
check(len(fault) > 20 and off < 1e-6 * R and abs(fault[0]["s"]) < 1e-6 * R
      and abs(fault[-1]["s"] - length) < 1e-6 * R,
      "plate boundary: all %d interface points on the circle (%.1e m off), s from 0 at the "
      "trench to %.3f km at the base (arc length %.3f km)"
      % (len(fault), off, fault[-1]["s"] / 1e3, length / 1e3))
finish()

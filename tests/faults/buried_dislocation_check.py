"""Faults with buried tips (issue 27): a uniform prescribed slip on a fault
between the depths 6 and 14 km in an elastic half-space, against the
closed form of the 2-D dislocation (tests/faults/dislocation_reference.py).

A fault between the depths D1 and D2 with the uniform jump b d is, by
superposition, the fault from the surface to D2 less the fault from the
surface to D1 (the same plane and jump), so its surface displacement is
U(x; D2) - U(x; D1) with U the closed form of a fault reaching the surface.
The fault is a Gmsh physical curve whose two ends lie inside the mesh; the
program continues it along the mesh's edges to the surface and to the base
as welded extensions (doc/faults.md, "Buried tips").

Two runs: dipping 60 degrees with normal slip (b = +1 m), from a graded
mesh of 1 km cells within 40 km of the fault, and dipping 30 degrees with
thrust slip (b = -1 m), from 2 km cells within 24 km refined once
everywhere. The mesh's columns follow the fault's plane, so at 30 degrees
its cells far below are long parallelograms whose error (0.5 % of the
surface displacement without the global refinement, measured) the
refinement does not reach, since the indicator sits at the tips. Each run
has five adaptive cycles (Kelly indicator, Doerfler marking of half the
squared error). Asserted, for each:
- the surface displacement at 16 points from -30 to 40 km equals the
  closed form to 1 % of the largest surface displacement on the last cycle
  (the issue's tolerance; measured 0.29 % at 60 and 0.40 % at 30 degrees;
  what is left is the far boundary 50 000 km away, where the field decays
  as L/r, the far cells, and the slip's step at each tip, which the Q2
  trace takes over the cell next to the tip);
- the error falls by at least 1.6 times per cycle over the first three
  cycles (measured 2.0-2.3) while the DoFs grow by less than 3 % per
  cycle: the refinement goes to the tips, where the error is (uniform
  refinement halves it per four times the DoFs: bench/run --problems
  buried).
A wrong sign or a missing term in the closed form, a jump in the wrong
frame, or a tip that does not end the slip moves the surface by more than
5 % of its largest displacement.
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
sys.path.insert(0, HERE)
from dislocation_reference import buried_surface_displacement  # noqa: E402
from buried_meshes import half_space_msh  # noqa: E402
from lithotest import check, finish, read_csv, run, table  # noqa: E402

TOP, BOTTOM = 6.0, 14.0


def errors(out, slip, dip):
    """The largest surface-displacement error of each cycle, relative to
    the largest surface displacement of the closed form at the points."""
    points = [r["x"] / 1e3 for r in read_csv(os.path.join(out, "point_values.csv"))]
    exact = [buried_surface_displacement(x, slip, 0.0, dip, TOP, BOTTOM) for x in points]
    largest = max(max(abs(u[0]), abs(u[1])) for u in exact)
    result = []
    for row in table(out):
        e = max(max(abs(row["u_x@P%d" % (k + 1)] - u[0]), abs(row["u_y@P%d" % (k + 1)] - u[1]))
                for k, u in enumerate(exact))
        result.append((int(row["dofs"]), e / largest))
    return result, len(points)


for dip_degrees, slip, sense, fine, n_fine, refinement in ((60.0, 1.0, "normal", 1.0, 40, 0),
                                                          (30.0, -1.0, "thrust", 2.0, 12, 1)):
    dip = math.radians(dip_degrees)
    msh = os.path.abspath("buried_half_space_%g.msh" % dip_degrees)
    half_space_msh(msh, dip, fine, n_fine, TOP, BOTTOM)
    out = os.path.abspath("output_buried_dislocation_%g" % dip_degrees)
    run("faults/buried_dislocation.prm", out, 1,
        ["Geometry/Gmsh/Mesh file=" + msh, "Faults/fault/Slip=%g" % slip,
         "Mesh refinement/Initial global refinement=%d" % refinement])
    cycles, n_points = errors(out, slip, dip)
    dofs, last = cycles[-1]
    check(n_points == 16 and last <= 1e-2,
          "%g-degree fault, %s slip %g m, buried from %g to %g km: the surface displacement "
          "equals the closed form to %.3f %% of its largest value at %d points (%d DoFs)"
          % (dip_degrees, sense, slip, TOP, BOTTOM, 100 * last, n_points, dofs))
    early = cycles[:3]
    falls = [a[1] / b[1] for a, b in zip(early, early[1:])]
    growth = [b[0] / a[0] - 1 for a, b in zip(early, early[1:])]
    check(len(cycles) == 5 and min(falls) >= 1.6 and max(growth) < 0.03,
          "%g degrees: adaptive cycles cut the error %s times while the DoFs grow %s %%"
          % (dip_degrees, ", ".join("%.2f" % f for f in falls),
             ", ".join("%.1f" % (100 * g) for g in growth)))
finish()

"""FSHEAR as the thesis ran it, on the plane normal fault (thesis §6.1,
prm/normal_fault.prm): the excess shear read at the centroids of the two
elements beside each fault element (`Faults/Sliding solver/Thesis stress
reading = element centroids`), a point that slid at the first iteration
held at the limit (`Hold sliding points at the limit`), the thesis's
convergence factor 15 (§6.1.5), and the thesis's 1e5 Pa of excess shear.

1. The reading converges to the fault's own traction as the mesh is
   refined: the stresses are read half a cell from the fault, so the
   throw's difference from the interface-point reading must fall at least
   like h (by a factor >= 1.6 per refinement; measured 1.7-2.0) at 30 MPa
   on 200, 800 and 3 200 cells.
2. On the thesis's fault discretisation, two fault elements along the
   22.36 km fault (200 cells): factor 15 reaches the state of factor 1
   (the throws within 1 %) in far fewer solves, and the throw at 30 MPa is
   the thesis's 26 m within 10 %, sliding to the thesis's 10 km.
3. At 50 MPa the thesis's 620 m lies between the throws with one fault
   element (50 cells) and two (200 cells): the thesis's larger throw is the
   reading on its coarse fault (doc/thesis_comparison.md).
4. The convergence factor's limit (§6.1.5: "factors greater than [15]
   produced divergence") is set by the mesh's fault, and the thesis's lies
   between ours: with the stiffness per unit area that makes factor 1 take
   the thesis's 1 023 iterations on each mesh (fault elements 19.7 and
   16.9 km long: the count is proportional to it), factor 15 converges on
   200 cells in no more than the thesis's 76 iterations and does not
   contract on 800 cells (it fails, or wanders into the tolerance by chance
   after at least ten times factor 10's iterations), where factor 10 does
   (doc/thesis_comparison.md, "Iteration counts": on 800 cells factor 10
   takes 102, 12 takes 302, 13 does not converge, so the limit is near
   12.5; on 200 cells factor 35 converges, 38 does not. Factor 10 is
   asserted, not 12, which sits at the limit and whose count grows
   without bound as the limit moves). Factor 1's counts are
   held to 2 % of 1 023 (measured 1 023 and 1 024): the calibration the
   other two rest on.
5. The frame and signs of the reading (shear s.sigma.n, normal n.sigma.n,
   compression negative) on the sliding patch test of
   tests/faults/frictional_fault.prm, whose final stress is uniform: the
   slip d - tau_F L/G and the traction mu P. The reading holds one mean
   per face, so the non-uniform slip of the first iterations (the 40 m
   displacement load) is not removed inside a face: the state is exact
   only to that (measured 0.2 % in the slip, 1.2 % in the traction); a
   wrong sign or frame gives errors of order one. Asserted within 1 % and
   2 %.
"""
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, finish, run  # noqa: E402

PRM = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                   "prm", "normal_fault.prm")
FSHEAR = ["Faults/Sliding solver/Method=thesis", "Faults/Sliding solver/Excess shear tolerance=1e5",
          "Faults/Sliding solver/Maximum iterations=3000",
          "Faults/Sliding solver/Thesis stress reading=element centroids",
          "Faults/Sliding solver/Hold sliding points at the limit=true",
          "Output/Write ParaView files=false", "Output/Figures/Enabled=false"]


def throw(name, sets):
    """(throw [m], sliding depth [km], nonlinear iterations) of a run."""
    out = os.path.abspath(name)
    run(PRM, out, 1, sets)
    with open(os.path.join(out, "fault_summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "statistics.json")) as f:
        iterations = json.load(f)["nonlinear_iterations"]
    return summary["throw_m"], summary["sliding_depth_m"] / 1e3, iterations


def mesh(refinement):
    return ["Mesh refinement/Initial global refinement=%d" % refinement]


T30 = ["Loads/Tractions/left/Normal traction=3e7"]
differences = []
for refinement in (1, 2, 3):
    element, _, _ = throw("centroids_%d" % refinement,
                          FSHEAR + mesh(refinement) + T30 + ["Faults/Sliding solver/Convergence factor=1"])
    interface, _, _ = throw("interface_%d" % refinement, mesh(refinement) + T30)
    differences.append(element - interface)
ratios = [differences[i] / differences[i + 1] for i in range(2)]
check(all(d > 0 for d in differences) and min(ratios) >= 1.6,
      "30 MPa: the centroid reading's throw tends to the interface traction's like h: differences "
      "%s m on 200, 800, 3 200 cells, ratios %s (>= 1.6)"
      % (", ".join("%.2f" % d for d in differences), ", ".join("%.2f" % r for r in ratios)))

one_factor, depth, slow = throw("fshear_30_factor1", FSHEAR + mesh(1) + T30 +
                                ["Faults/Sliding solver/Convergence factor=1"])
fifteen, depth15, fast = throw("fshear_30_factor15", FSHEAR + mesh(1) + T30 +
                               ["Faults/Sliding solver/Convergence factor=15"])
check(abs(fifteen - one_factor) <= 0.01 * one_factor and fast < slow,
      "two fault elements, 30 MPa: factor 15 reaches factor 1's state (throw %.2f m against %.2f m) "
      "in %d solves instead of %d" % (fifteen, one_factor, fast, slow))
check(abs(fifteen - 26) <= 2.6 and abs(depth15 - 10) <= 0.5,
      "two fault elements, 30 MPa: throw %.2f m (thesis 26 m, within 10 %%), sliding to %.2f km "
      "(thesis 10 km)" % (fifteen, depth15))

T50 = ["Faults/Sliding solver/Convergence factor=15"]
one, _, _ = throw("fshear_50_one_element", FSHEAR + mesh(0) + T50)
two, _, _ = throw("fshear_50_two_elements", FSHEAR + mesh(1) + T50)
check(two < 620 < one,
      "50 MPa: the thesis's 620 m lies between the throws with two fault elements (%.1f m) and one "
      "(%.1f m)" % (two, one))


def limit_run(cells, factor, expect_success=True):
    """The 50 MPa run of doc/thesis_comparison.md's factor limits on 200 or
    800 cells: (exit code, nonlinear iterations or None, stderr)."""
    refinement, length = {200: (1, 19.7), 800: (2, 16.9)}[cells]
    out = os.path.abspath("limit_%d_factor%d" % (cells, factor))
    result = run(PRM, out, 1, FSHEAR + mesh(refinement) + [
        "Faults/fault/Thesis element length=%g" % length,
        "Faults/Sliding solver/Convergence factor=%d" % factor], expect_success=expect_success)
    iterations = None
    if result.returncode == 0:
        with open(os.path.join(out, "statistics.json")) as f:
            iterations = json.load(f)["nonlinear_iterations"]
    return result.returncode, iterations, result.stderr


calibration = [limit_run(cells, 1)[1] for cells in (200, 800)]
check(all(abs(n - 1023) <= 0.02 * 1023 for n in calibration),
      "factor 1 takes the thesis's 1 023 iterations on 200 and 800 cells (%d, %d; within 2 %%)"
      % tuple(calibration))
_, on_200, _ = limit_run(200, 15)
check(on_200 <= 76, "200 cells: factor 15 converges in %d iterations (thesis 76: no more)" % on_200)
_, below, _ = limit_run(800, 10)
code, wandering, message = limit_run(800, 15, expect_success=False)
# Past its limit the iteration oscillates without contracting; it either
# exhausts its iterations (exit 1, naming the entry) or, the oscillation
# being chaotic, lands below the tolerance by chance after many times the
# iterations of a factor that contracts (seen once at 1 971 against factor
# 10's 102, on another processor). Below the limit a larger factor takes
# fewer iterations, not more, so ten times factor 10's count is past it.
diverged = code != 0 and "Convergence factor" in message
wandered = code == 0 and below is not None and wandering is not None and wandering >= 10 * below
check(below is not None and (diverged or wandered),
      "800 cells: factor 10 converges (%s iterations), factor 15 does not contract (exit %d, %s): "
      "the thesis's limit of 15 lies between the two meshes'"
      % (below, code, "naming the entry" if diverged else "%s iterations" % wandering))

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
out = os.path.abspath("fshear_patch")
run(os.path.join(SOURCE, "faults", "frictional_fault.prm"), out, 1,
    FSHEAR[:1] + ["Faults/Sliding solver/Excess shear tolerance=1e3"] + FSHEAR[2:5])
with open(os.path.join(out, "fault.csv")) as f:
    rows = list(csv.DictReader(f))
E, P, MU, D, L = 0.85e11, 1e8, 0.6, 40.0, 10e3
exact_slip = D - MU * P * L / (E / 2)
worst_slip = max(abs(-float(r["slip"]) - exact_slip) for r in rows) / exact_slip
worst_tau = max(abs(-float(r["shear_traction"]) - MU * P) for r in rows) / (MU * P)
check(all(r["state"] == "sliding" for r in rows) and worst_slip <= 0.01 and worst_tau <= 0.02,
      "sliding patch test read at the element centroids: every point sliding, slip within %.2f %% "
      "of d - tau_F L/G = %.4f m, shear traction within %.2f %% of mu P"
      % (100 * worst_slip, exact_slip, 100 * worst_tau))
finish()

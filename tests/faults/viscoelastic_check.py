"""A frictional fault in the visco-elastic loop (issue 16, verification 6;
issue 27 for the buried fault): tests/faults/viscoelastic_fault.prm, an
elastic layer over a Maxwell layer cut by a normal fault, under constant
tension for 10 Maxwell times; and the same fault buried between 5 km and
the top of the Maxwell layer (20 km), both ends tips inside the body.

For each:
1. As the lower layer relaxes, its share of the tension moves into the
   elastic layer and the fault slides further: the largest slip grows at
   every output time (fault-NNNNN.csv, one per output time), and so does
   the throw at the surface trace (the fault reaching the surface) or the
   slip stays zero at both tips (the buried fault).
2. Checkpoint and restart carry the slip history: a run to 5 kyr resumed
   on 2 ranks to 10 kyr (its checkpoint's slip carried onto the new
   partition along the fault) ends with the uninterrupted run's fault.csv
   and time steps (to 1e-8 relative: the sliding solver stops at a residual
   of 1e-9 of the load).
"""
import csv
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, finish, read_csv, run  # noqa: E402

PRM = "faults/viscoelastic_fault.prm"
YEAR = 3.15576e7
LABEL = {"": "visco-elastic fault", "_buried": "buried visco-elastic fault"}
BURIED = ["Geometry/Layered box/Cells per layer=4, 1", "Geometry/Layered box/Fault top depth=5",
          "Geometry/Layered box/Fault bottom depth=20", "Mesh refinement/Initial global refinement=0"]


def fault_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def relaxation(name, sets, buried):
    """Item 1 for the variant @name (its runs' extra entries @sets)."""
    reference = os.path.abspath("output_viscoelastic_fault" + name)
    run(PRM, reference, 1, sets)
    slips, tops, tips = [], [], []
    for k in range(5):
        rows = fault_rows(os.path.join(reference, "fault-%05d.csv" % k))
        slips.append(max(float(r["slip"]) for r in rows))
        # The shallowest point's slip stands for the throw.
        top = min(rows, key=lambda r: float(r["s"]))
        bottom = max(rows, key=lambda r: float(r["s"]))
        tops.append(float(top["slip"]))
        tips.append(max(abs(float(top["slip"])), abs(float(bottom["slip"]))))
    what = LABEL[name]
    check(all(b > a for a, b in zip(slips, slips[1:])) and slips[0] > 0,
          "%s: the largest slip grows as the lower layer relaxes: %s m at 0, 1, 2, 5, 10 kyr"
          % (what, ["%.3f" % s for s in slips]))
    if buried:
        check(max(tips) == 0, "%s: the slip at both tips stays zero (largest %.1e m)" % (what, max(tips)))
    else:
        check(all(b > a for a, b in zip(tops, tops[1:])),
              "%s: the slip at the surface trace grows too: %s m" % (what, ["%.3f" % s for s in tops]))
    return reference


def restart(name, sets, reference):
    """Item 2 for the variant @name."""
    partial = os.path.abspath("output_viscoelastic_fault_restart" + name)
    run(PRM, partial, 1, sets + ["Time stepping/End time=5000",
                                 "Time stepping/Output times=0, 1000, 2000, 5000"])
    run(PRM, partial, 2, sets + ["Time stepping/Resume=true"], keep_output=True)
    # That the second run resumed, from the first run's last checkpoint at
    # 5 kyr, rather than running from t = 0 again.
    with open(os.path.join(partial, "log.txt")) as f:
        resumed = re.search(r"Resumed from (\S+): step (\d+), t = [^(]*\(([0-9.e+-]+) s\)", f.read())
    check(resumed is not None and resumed.group(1).startswith(partial)
          and abs(float(resumed.group(3)) - 5000 * YEAR) <= 1e-6 * 5000 * YEAR,
          "%s: the second run resumed from %s at step %s, t = %s s (5 kyr)"
          % ((LABEL[name],) + ((resumed.group(1), resumed.group(2), resumed.group(3))
                                            if resumed else ("nothing", "-", "-"))))
    a = fault_rows(os.path.join(reference, "fault.csv"))
    b = fault_rows(os.path.join(partial, "fault.csv"))
    scale = max(abs(float(r["slip"])) for r in a)
    stress = max(abs(float(r["normal_traction"])) for r in a)
    worst = 0.0
    for x, y in zip(a, b):
        worst = max(worst, abs(float(x["slip"]) - float(y["slip"])) / scale,
                    abs(float(x["shear_traction"]) - float(y["shear_traction"])) / stress,
                    abs(float(x["normal_traction"]) - float(y["normal_traction"])) / stress)
    same_states = all(x["state"] == y["state"] for x, y in zip(a, b))
    steps_a = read_csv(os.path.join(reference, "time_steps.csv"))
    steps_b = read_csv(os.path.join(partial, "time_steps.csv"))
    # The step lengths follow the creep estimate of the solution (doubled
    # or kept against the tolerance, rescaled by it after a rejection), and
    # 2 ranks reproduce the solution to where the sliding solver stops (a
    # residual of 1e-9 of the load; the fault to 1e-8, asserted here), so
    # the times are compared to the same 1e-8 relative, not bit for bit.
    time_worst = max([abs(x["time"] - y["time"]) / x["time"] for x, y in zip(steps_a, steps_b)],
                     default=0.0)
    same_steps = (len(steps_a) == len(steps_b) > 0
                  and [x["step"] for x in steps_a] == [y["step"] for y in steps_b]
                  and time_worst <= 1e-8)
    check(len(a) == len(b) > 0 and same_states and same_steps and worst <= 1e-8,
          "%s: run to 5 kyr, resumed on 2 ranks to 10 kyr = uninterrupted run "
          "(%d and %d steps, times to %.1e relative; %d and %d fault points, largest relative "
          "difference %.1e; both allowed 1e-8)"
          % (LABEL[name], len(steps_a), len(steps_b), time_worst, len(a), len(b), worst))


for name, sets, buried in (("", [], False), ("_buried", BURIED, True)):
    restart(name, sets, relaxation(name, sets, buried))
finish()

"""The memory check before each refinement (Resources/Memory limit): an
adaptive run whose next mesh would exceed the limit stops before p4est
makes it, with exit status 1 and one line giving the estimate, the limit and
the entries to change, and keeps the cycles it finished. The estimate is
the refined mesh's own: its cells (from the refinement flags, after
deal.II's smoothing) and DoFs must match what an unlimited run then has."""
import csv, os, re, sys
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, finish, run, table

PRM = "l_shaped/l_shaped_adaptive.prm"
# 160 MB per rank plus 0.4 kB per DoF: about 7 500 DoFs fit, which the
# adaptive L-shaped run passes between cycles 24 and 25.
LIMIT = "163 MB"

limited = os.path.abspath("output_memory_limited")
r = run(PRM, limited, 1, ["Resources/Memory limit=" + LIMIT], expect_success=False)
lines = [l for l in r.stderr.splitlines() if l.strip()]
check(r.returncode == 1, "exit status %d (expected 1)" % r.returncode)
check(len(lines) == 1, "one line on stderr: %s" % " | ".join(lines))
m = re.search(r"parameter <Resources/Memory limit>: the mesh of cycle (\d+) would have about ([0-9.e+]+) cells "
              r"and ([0-9.e+]+) DoFs and need about .* against 163 MB, the limit set by Resources/Memory limit; "
              r"lower Mesh refinement/Number of cycles", lines[0] if lines else "")
check(m is not None, "the line gives the mesh, the estimate and the limit: %s" % (lines[0] if lines else ""))
if m:
    stopped, cells, dofs = int(m.group(1)), float(m.group(2)), float(m.group(3))
    rows = table(limited)
    check(len(rows) == stopped, "cycles 0 to %d kept in convergence.csv (%d rows)" % (stopped - 1, len(rows)))
    full = os.path.abspath("output_memory_unlimited")
    run(PRM, full, 1, ["Mesh refinement/Number of cycles=%d" % (stopped + 1)])
    actual = table(full)[stopped]
    check(abs(cells / actual["cells"] - 1) < 0.01,
          "estimated cells of cycle %d: %g, the unlimited run has %d" % (stopped, cells, actual["cells"]))
    # DoFs are estimated as the current DoFs per cell times the new cells.
    check(abs(dofs / actual["dofs"] - 1) < 0.05,
          "estimated DoFs of cycle %d: %g, the unlimited run has %d" % (stopped, dofs, actual["dofs"]))
finish()

"""The memory check before each refinement (Resources/Memory limit): an
adaptive run whose next mesh would exceed the limit stops before p4est
makes it, with exit status 1 and one line giving the estimate, the limit and
the entries to change, and keeps the cycles it finished. The estimate is
the refined mesh's own: its cells (from the refinement flags, after
deal.II's smoothing) and DoFs must match what an unlimited run then has."""
import os, re, sys
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, finish, run, table

PRM = "l_shaped/l_shaped_adaptive.prm"

# The unlimited run: its meshes, and the program's size per rank at start
# (in its log; the base of every estimate).
full = os.path.abspath("output_memory_unlimited")
run(PRM, full, 1, ["Mesh refinement/Number of cycles=34"])
rows_full = table(full)
log = open(os.path.join(full, "log.txt")).read()
size = re.search(r"Memory: ([0-9.]+) MB per rank when the model was read", log)
check(size is not None, "log.txt gives the size per rank at start")
base_mb = float(size.group(1)) if size else 400.0
# A limit 4 MB above the size at start: the estimate (0.4 kB per DoF with
# the matrix-free multigrid) passes it near 10 000 DoFs. The size at start
# varies by about 2 MB from run to run (page faults), so the cycle at which
# the limited run stops varies too; what must hold is that it stops before
# the mesh whose estimate exceeds the limit, and that the estimate is that
# mesh's.
limit_mb = base_mb + 4.0

limited = os.path.abspath("output_memory_limited")
r = run(PRM, limited, 1, ["Resources/Memory limit=%.1f MB" % limit_mb, "Mesh refinement/Number of cycles=34"],
        expect_success=False)
lines = [l for l in r.stderr.splitlines() if l.strip()]
check(r.returncode == 1, "exit status %d (expected 1)" % r.returncode)
check(len(lines) == 1, "one line on stderr: %s" % " | ".join(lines))
m = re.search(r"parameter <Resources/Memory limit>: the mesh of cycle (\d+) would have about ([0-9.e+]+) cells "
              r"and ([0-9.e+]+) DoFs and need about ([0-9.]+) MB .* against ([0-9.]+) MB, the limit set by "
              r"Resources/Memory limit; lower Mesh refinement/Number of cycles", lines[0] if lines else "")
check(m is not None, "the line gives the mesh, the estimate and the limit: %s" % (lines[0] if lines else ""))
if m:
    stopped, cells, dofs = int(m.group(1)), float(m.group(2)), float(m.group(3))
    need, have = float(m.group(4)), float(m.group(5))
    # need > have, printed to 0.1 MB: equal after rounding is possible.
    check(10 <= stopped < len(rows_full) and need >= have,
          "stopped before cycle %d, whose estimate %.1f MB exceeds the limit %.1f MB" % (stopped, need, have))
    rows = table(limited)
    check(len(rows) == stopped, "cycles 0 to %d kept in convergence.csv (%d rows)" % (stopped - 1, len(rows)))
    actual = rows_full[stopped]
    check(abs(cells / actual["cells"] - 1) < 0.01,
          "estimated cells of cycle %d: %g, the unlimited run has %d" % (stopped, cells, actual["cells"]))
    # DoFs are estimated as the current DoFs per cell times the new cells.
    check(abs(dofs / actual["dofs"] - 1) < 0.05,
          "estimated DoFs of cycle %d: %g, the unlimited run has %d" % (stopped, dofs, actual["dofs"]))
finish()

"""The visco-elastic time loop's two ways of giving up, each named in one
line (exit status 3, "the computation failed"), with the results up to
the failure complete:

1. The minimum time step: tests/viscoelastic/maxwell_block.prm with
   adaptive steps, a creep-strain tolerance of 1e-12 (the first step's
   increment is of order 1e-4: a step of about 1e-8 of the 100-year
   first step would be needed) and a Minimum time step of 10 years. The
   line names the Minimum time step and the time of the step.
2. The thesis scheme's fixed point: Scheme = thesis with at most 1
   fixed-point iteration and a tolerance of 1e-14 (the first iteration
   changes the stress by 11 %). The line names the step, the iterations
   and the stress change against the tolerance, and says what to change.

Both on 1 and 2 ranks (the same line), and in each the point history
(point_history.csv) holds every step before the failure and no later
one: the t = 0 rows only, since both fail in their first step.
"""
import csv
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from lithotest import check, finish, run  # noqa: E402

PRM = os.path.join("viscoelastic", "maxwell_block.prm")
CASES = {
    "minimum time step": (["Time stepping/Adaptive time steps=true",
                           "Time stepping/Creep strain tolerance=1e-12",
                           "Time stepping/Minimum time step=10"],
                          "the time step from t = 0 years would have to be shorter than "
                          "the Minimum time step (10 years)"),
    "fixed point": (["Time stepping/Scheme=thesis",
                     "Time stepping/Maximum fixed point iterations=1",
                     "Time stepping/Fixed point tolerance=1e-14"],
                    "the thesis scheme's fixed-point iteration of the step from t = 0 years "
                    "to 100 years did not converge in 1 iterations (relative stress change "),
}


def main():
    for name, (sets, expected) in CASES.items():
        lines = []
        for ranks in (1, 2):
            label = "%s, %d rank%s" % (name, ranks, "s" if ranks > 1 else "")
            out = "out_failure_%s_%d" % (name.replace(" ", "_"), ranks)
            r = run(PRM, out, ranks=ranks, sets=sets, expect_success=False,
                    extra_env={"OMPI_MCA_orte_execute_quiet": "1"})
            err = [l for l in r.stderr.splitlines() if l.strip()]
            check(r.returncode == 3, "%s: exit status %d (3: the computation failed)"
                  % (label, r.returncode))
            check(len(err) == 1 and expected in err[0],
                  "%s: one line naming it: %s" % (label, " | ".join(err)))
            with open(os.path.join(out, "point_history.csv")) as f:
                rows = list(csv.DictReader(f))
            times = sorted({float(row["time"]) for row in rows}) if rows else None
            check(times == [0.0] and len(rows) == 2,
                  "%s: point_history.csv holds the steps before the failure: the t = 0 "
                  "rows of the 2 points only (times %s, %d rows)" % (label, times, len(rows)))
            lines.append(err[0] if err else "")
        check(lines[0] == lines[1], "%s: the same line on 1 and 2 ranks" % name)
    finish()


main()

"""Every linear solver option gives the same solution: Lame's cylinder
(tests/lame_cylinder/lame.prm, exact solution, curved boundary) on five
global cycles (to 8 450 DoFs), solved by

* AMG with each smoother (Chebyshev, the default, and symmetric
  Gauss-Seidel, with 1 and 3 sweeps);
* the direct solver with each factorisation (Cholesky, the default, and
  Trilinos Amesos's KLU, MUMPS and SuperLU_DIST), on 1 and 2 ranks. A
  package this build's Trilinos lacks (Debian's has no SuperLU_DIST) must
  be refused before anything is solved, in one line naming the entry and
  the packages there are (it used to end in Trilinos's exception with a
  stack trace at the first solve); at least the default and KLU must be
  there;

against the default solver's run. The discretisation error is the same
whichever solver reaches the same discrete solution: every cycle's L2(u)
error must equal the default's to 1e-6 of itself (the iterative solves
stop at a relative residual of 1e-12, so their solutions differ from the
exact discrete one by about 1e-12 relative to u, far below 1e-6 of an
error of 1e-4 to 1e-7 of u), and the L2 rate over the last three
cycles is Q2's 1.5 in DoFs.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from lithotest import check, finish, run, slope, table  # noqa: E402

PRM = os.path.join("lame_cylinder", "lame.prm")
BASE = ["Mesh refinement/Number of cycles=5"]
OPTIONS = {
    "AMG, Chebyshev": ["Solver/Type=AMG"],
    "AMG, symmetric Gauss-Seidel, 1 sweep": ["Solver/Type=AMG",
                                             "Solver/AMG smoother=symmetric Gauss-Seidel",
                                             "Solver/AMG smoother sweeps=1"],
    "AMG, symmetric Gauss-Seidel, 3 sweeps": ["Solver/Type=AMG",
                                              "Solver/AMG smoother=symmetric Gauss-Seidel",
                                              "Solver/AMG smoother sweeps=3"],
    "direct, Cholesky": ["Solver/Type=direct", "Solver/Direct solver=Cholesky"],
    "direct, Amesos_Klu": ["Solver/Type=direct", "Solver/Direct solver=Amesos_Klu"],
    "direct, Amesos_Mumps": ["Solver/Type=direct", "Solver/Direct solver=Amesos_Mumps"],
    "direct, Amesos_Superludist": ["Solver/Type=direct",
                                   "Solver/Direct solver=Amesos_Superludist"],
}


def main():
    reference = table(run_case("default", [], 1))
    solved = set()
    for name, sets in OPTIONS.items():
        for ranks in ((1, 2) if name.startswith("direct") else (1,)):
            label = "%s, %d rank%s" % (name, ranks, "s" if ranks > 1 else "")
            out = run_case(name, sets, ranks, expect_success=False)
            if out is None:
                continue
            solved.add(name)
            rows = table(out)
            worst = max(abs(r["L2(u)"] - q["L2(u)"]) / q["L2(u)"] for r, q in zip(rows, reference))
            rate = slope(rows, "L2(u)", len(rows) - 3)
            check(len(rows) == len(reference) and worst < 1e-6 and abs(rate - 1.5) < 0.1,
                  "%s: L2(u) on %d cycles equals the default solver's to %.1e of itself "
                  "(< 1e-6), rate %.3f (1.5)" % (label, len(rows), worst, rate))
    check({"direct, Cholesky", "direct, Amesos_Klu"} <= solved and len(solved) >= 5,
          "%d of the %d options solve (the default factorisation and KLU among them)"
          % (len(solved), len(OPTIONS)))
    finish()


def run_case(name, sets, ranks, expect_success=True):
    """The output directory of a run, or None where the option refuses
    these ranks in one line (checked here)."""
    out = os.path.abspath("output_options_%s_%d" % (
        "".join(c if c.isalnum() else "_" for c in name), ranks))
    r = run(PRM, out, ranks=ranks, sets=BASE + list(sets), expect_success=expect_success,
            extra_env={"OMPI_MCA_orte_execute_quiet": "1"})
    if r.returncode == 0:
        return out
    lines = [l for l in r.stderr.splitlines() if l.strip()]
    check(r.returncode == 1 and len(lines) == 1 and
          "Solver/Direct solver>: <" in lines[0] and "available: Cholesky" in lines[0],
          "%s, %d rank(s): refused in one line naming the entry and the packages there are: %s"
          % (name, ranks, " | ".join(lines)))
    return None


main()

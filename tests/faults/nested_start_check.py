"""Nested iteration: on each refined mesh the frictional Newton iteration
starts from the last mesh's solution, interpolated (ElasticProblem::
carry_solution_to_next_mesh, FrictionalSlidingSolver::start_next_solve_from).

prm/graben.prm (two frictional normal faults in exact contact, 50 MPa
tension; sliding, stuck and open points on both faults) with three
global refinement cycles from `Initial global refinement = 1`, against a
single cycle on the same finest mesh (`Initial global refinement = 3`),
which starts from the elastic predictor.

1. The solution does not depend on where Newton starts: every point's
   slip, opening, tractions and state, and both throws, equal the single
   cycle's. Both runs stop at a residual below 1e-9 of the load; slips
   and openings are compared relative to the largest slip, tractions
   relative to the largest traction, to 1e-6 (as the graben's mirror
   symmetry in several_faults_check.py).
2. The start is used, and it is a better start: the log says so on
   cycles 1 and 2, and on the finest mesh (a) the points' states at the
   start are nearer their converged states than after the elastic
   predictor's step, counted as the differences of the numbers of
   sliding and open points (measured 4 against 16), and (b) the first
   Newton step from there leaves at most a tenth of the residual the
   predictor's step leaves (measured 0.0125 against 0.53 of the load, 42
   times less). The numbers of Newton iterations are not compared: with
   the reaction in the tangent the last steps converge linearly and where
   an inexact linear solve stops moves a count by one (the Debug build
   took 6 from either start at Linear solver reduction 1e-3, the Release
   build 5 against 6), while the first step's residual is set by the
   states the start gets wrong, not by where a linear solve stops.
3. On 2 ranks the nested run gives the same fault results, to 1e-6.
"""
import json
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from lithotest import check, finish, newton_solves, read_csv, run  # noqa: E402

PRM = os.path.join("..", "prm", "graben.prm")
BASE = ["Output/Write ParaView files=false", "Output/Figures/Enabled=false"]
NESTED = BASE + ["Mesh refinement/Initial global refinement=1",
                 "Mesh refinement/Number of cycles=3",
                 "Mesh refinement/Strategy=global"]
SINGLE = BASE + ["Mesh refinement/Initial global refinement=3"]
FAULTS = ("west", "east")


def results(output):
    """Per fault: (its points' rows, its summary)."""
    out = {}
    for name in FAULTS:
        rows = read_csv(os.path.join(output, "fault_%s.csv" % name))
        with open(os.path.join(output, "fault_summary_%s.json" % name)) as f:
            out[name] = (rows, json.load(f))
    return out


def compare(label, a, b):
    for name in FAULTS:
        rows_a, summary_a = a[name]
        rows_b, summary_b = b[name]
        check(len(rows_a) == len(rows_b) and len(rows_a) > 0,
              "%s, fault %s: %d and %d points" % (label, name, len(rows_a), len(rows_b)))
        slip = max(abs(r["slip"]) for r in rows_b)
        traction = max(max(abs(r["shear_traction"]), abs(r["normal_traction"])) for r in rows_b)
        d_jump = max(max(abs(p["slip"] - q["slip"]), abs(p["opening"] - q["opening"]))
                     for p, q in zip(rows_a, rows_b)) / slip
        d_traction = max(max(abs(p["shear_traction"] - q["shear_traction"]),
                             abs(p["normal_traction"] - q["normal_traction"]))
                         for p, q in zip(rows_a, rows_b)) / traction
        states = sum(p["state"] != q["state"] for p, q in zip(rows_a, rows_b))
        d_throw = abs(summary_a["throw_m"] - summary_b["throw_m"]) / abs(summary_b["throw_m"])
        check(d_jump < 1e-6 and d_traction < 1e-6 and d_throw < 1e-6 and states == 0,
              "%s, fault %s: slip/opening differ by %.2e of the largest slip (%.1f m), "
              "tractions by %.2e, throw by %.2e, %d states differ (each < 1e-6, 0)"
              % (label, name, d_jump, slip, d_traction, d_throw, states))


def main():
    single, nested, nested2 = "out_single", "out_nested", "out_nested_2"
    single_log = run(PRM, single, sets=SINGLE).stdout
    log = run(PRM, nested, sets=NESTED).stdout
    compare("nested against single cycle", results(nested), results(single))
    starts = log.count("Newton starts from the last mesh's solution")
    check(starts == 2, "the Newton iteration started from the last mesh's solution "
          "on %d of the 2 refined meshes" % starts)
    # The finest mesh: the nested run's last solve, the single run's only.
    start = re.findall(r"Newton starts from the last mesh's solution: residual (\S+), "
                       r"(\d+) sliding, (\d+) open", log)
    check(len(start) == 2, "the nested run's log gives both starts' residuals and states")
    nested_solve = newton_solves(log)[-1]
    single_solve = newton_solves(single_log)[-1]
    final = (single_solve[-1]["sliding"], single_solve[-1]["open"])
    nested_final = (nested_solve[-1]["sliding"], nested_solve[-1]["open"])
    check(nested_final == final, "finest mesh: the same converged states, %d sliding and %d "
          "open, from either start (%d and %d)" % (final + nested_final))
    at_start = abs(int(start[-1][1]) - final[0]) + abs(int(start[-1][2]) - final[1])
    after_predictor = (abs(single_solve[0]["sliding"] - final[0]) +
                       abs(single_solve[0]["open"] - final[1]))
    check(at_start < after_predictor,
          "finest mesh: the states at the last mesh's solution are nearer the converged "
          "ones than after the elastic predictor's step (%d against %d points by the "
          "counts of sliding and open points)" % (at_start, after_predictor))
    first, predictor = nested_solve[0]["residual"], single_solve[0]["residual"]
    check(first <= 0.1 * predictor,
          "finest mesh: the first Newton step from the last mesh's solution leaves %.3g of "
          "the load, at most a tenth of the elastic predictor's step's %.3g" % (first, predictor))
    run(PRM, nested2, ranks=2, sets=NESTED)
    compare("2 ranks against 1", results(nested2), results(nested))
    finish()


main()

"""The performance guard (bench/run --guard [--update]): a handful of small
cases -- elastic, visco-elastic, a frictional fault, the subduction
coupling -- solved with the Debug build that the test suite uses, and what
of them does not depend on the machine compared with the baseline
committed in bench/guard_baseline.json:

* DoFs and cells: exactly (the same meshes);
* iteration counts (linear, Newton, linear solves, time steps): within
  max(2, 25 %) of the baseline -- where an inexact solve stops and the
  build (fused multiply-adds) move a count by one or two, a lost
  preconditioner or a worse Newton start by far more;
* times divided by the machine's own matrix-vector product time, measured
  in the same run as the fastest of three runs: the assembled stiffness
  matrix's product (matvec_ms of the elastic case) for the cases solved
  on assembled matrices, the matrix-free operator's (matvec_ms of the
  elastic_multigrid case) for the matrix-free multigrid -- at most twice
  the baseline's, where the baseline is at least 250 products long
  (shorter phases are start-up and timer noise). On one machine the
  ratios moved by up to 1.6x between runs while a single product's time
  varied from 1.6 to 2.3 ms (hence the fastest of three); the
  slowdown the guard is for was 2.4x (the chapter-7 set, 95 -> 229 s).
  The matrix-free multigrid was once divided by the assembled product
  and measured 3.4x its baseline on CI's machine, whose assembled product
  was as fast as here (1.82 ms): the optimised Trilinos product and the
  matrix-free kernels do not scale alike between machines, and the
  active operator's cell batches are 4 doubles wide only where the CPU
  has AVX2 (active_operator_bits in statistics.json, printed with each
  row): against a baseline of another width, the matrix-free case's
  counts are compared and its times are not (a line says so).

Every case's row is printed as a JSON line; a figure that moved is named
with its case, its value and the baseline's, and the guard exits 1.
--update rewrites the baseline from this run (say why in the commit).
The guard runs as the ctest test performance_guard (alone: RUN_SERIAL),
so CI runs it on every change."""
import json
import os
import shutil
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BASELINE = os.path.join(ROOT, "bench", "guard_baseline.json")
QUIET = ["Output/Write ParaView files=false", "Output/Figures/Enabled=false"]
COUNT_TOLERANCE = (2, 0.25)
TIME_TOLERANCE = 2.0
# Times shorter than this many matrix-vector products (about 0.6 s here)
# are start-up and timer noise: not compared.
SHORTEST = 250
REPEAT_MATVEC = 3

# name: (prm, --set overrides, the counts to compare)
CASES = {
    "elastic": ("prm/flexure.prm",
                QUIET + ["Mesh refinement/Number of cycles=1",
                         "Mesh refinement/Initial global refinement=3",
                         "Output/Stress-depth profiles=", "Thin plate comparison/Enabled=false",
                         "Solver/Type=AMG", "Solver/Relative tolerance=1e-10",
                         "Solver/Time matrix-vector product=true"],
                ["iterations"]),
    "elastic_multigrid": ("prm/flexure.prm",
                          QUIET + ["Mesh refinement/Number of cycles=1",
                                   "Mesh refinement/Initial global refinement=3",
                                   "Output/Stress-depth profiles=",
                                   "Thin plate comparison/Enabled=false",
                                   "Solver/Type=matrix-free multigrid",
                                   "Solver/Relative tolerance=1e-10",
                                   "Solver/Time matrix-vector product=true"],
                          ["iterations"]),
    "viscoelastic": ("prm/viscoelastic_cylinder.prm", QUIET,
                     ["iterations", "linear_solves", "steps"]),
    # The fault cases' linear iterations are compared since 2026-12-03:
    # whether the kept preconditioner is made again is decided on counts of
    # iterations (SlidingContext::set_up_in_iterations), no longer on
    # wall-clock costs, which had moved them from 46 to 60 (normal fault)
    # and 45 to 80 (coupling) between runs on one machine.
    "frictional_fault": ("prm/normal_fault.prm",
                         QUIET + ["Faults/fault/Normal stiffness=exact",
                                  "Mesh refinement/Initial global refinement=3"],
                         ["nonlinear_iterations", "linear_solves", "iterations"]),
    "subduction_coupling": ("prm/subduction_coupling.prm",
                            QUIET + ["Time stepping/Enabled=false"],
                            ["nonlinear_iterations", "linear_solves", "iterations"]),
}
TIMES = ["total_s", "solve_s"]
# The case whose matrix-vector product each case's times are divided by
# (the product of the operator the case solves with).
PRODUCT = {name: "elastic" for name in CASES}
PRODUCT["elastic_multigrid"] = "elastic_multigrid"


def run_case(binary, name, env, output):
    """The statistics of one case (statistics.json, and the number of time
    steps from time_steps.csv where the run has a time loop)."""
    prm, sets, _ = CASES[name]
    out = os.path.join(output, name)
    shutil.rmtree(out, ignore_errors=True)
    cmd = [binary, os.path.join(ROOT, prm), "--set", "Output directory=" + out]
    for s in sets:
        cmd += ["--set", s]
    result = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if result.returncode != 0:
        sys.stderr.write(result.stdout[-2000:] + result.stderr[-2000:])
        sys.exit("guard: the case %s failed (exit %d): %s" % (name, result.returncode, " ".join(cmd)))
    with open(os.path.join(out, "statistics.json")) as f:
        stats = json.load(f)
    steps = os.path.join(out, "time_steps.csv")
    if os.path.exists(steps):
        with open(steps) as f:
            stats["steps"] = max(0, sum(1 for line in f if line.strip()) - 1)
    return stats


def figures(stats, name, matvec_ms):
    """The machine-independent figures of a case, its times divided by
    @p matvec_ms (the product of PRODUCT[name])."""
    row = {"dofs": stats["dofs"], "cells": stats["cells"],
           "active_operator_bits": stats["active_operator_bits"]}
    for count in CASES[name][2]:
        if count not in stats:
            sys.exit("guard: the case %s has no %s in its statistics" % (name, count))
        row[count] = stats[count]
    for t in TIMES:
        row[t + "_per_matvec"] = round(1e3 * stats[t] / matvec_ms, 1)
    return row


def compare(name, row, base):
    """The figures of @row that moved from @base beyond their tolerance."""
    moved = []
    for key, value in base.items():
        if key not in row:
            moved.append("%s: %s is missing" % (name, key))
        elif key == "active_operator_bits":
            continue
        elif key in ("dofs", "cells"):
            if row[key] != value:
                moved.append("%s: %s %d, baseline %d (must be equal)" % (name, key, row[key], value))
        elif key.endswith("_per_matvec"):
            if value >= SHORTEST and row[key] > TIME_TOLERANCE * value:
                moved.append("%s: %s %.1f, baseline %.1f (at most %.1fx)"
                             % (name, key, row[key], value, TIME_TOLERANCE))
        else:
            allowed = max(COUNT_TOLERANCE[0], COUNT_TOLERANCE[1] * value)
            if abs(row[key] - value) > allowed:
                moved.append("%s: %s %d, baseline %d (within %.0f)"
                             % (name, key, row[key], value, allowed))
    return moved


def main(argv, env):
    """bench/run --guard [--update] [--binary PATH] [--output DIR]."""
    update = "--update" in argv
    binary = os.path.join(ROOT, "build-debug", "lithostress")
    if "--binary" in argv:
        binary = argv[argv.index("--binary") + 1]
    else:
        subprocess.run(["bash", os.path.join(ROOT, "scripts", "build.sh"), "build-debug", "Debug"],
                       check=True, stdout=sys.stderr)
    if not os.access(binary, os.X_OK):
        sys.exit("guard: no program at %s" % binary)
    output = os.path.join(ROOT, "output", "guard")
    if "--output" in argv:
        output = os.path.abspath(argv[argv.index("--output") + 1])
    stats = {name: run_case(binary, name, env, output) for name in CASES}
    # One product takes 1.6-2.3 ms here from process to process (where the
    # matrix landed in memory): the fastest of three runs' fastest of 20.
    matvec_ms = {}
    for product in sorted(set(PRODUCT.values())):
        runs = [stats[product]] + [run_case(binary, product, env, output)
                                   for _ in range(REPEAT_MATVEC - 1)]
        stats[product] = min(runs, key=lambda s: s["total_s"])
        matvec_ms[product] = min(s["matvec_ms"] for s in runs)
        if not matvec_ms[product] > 0:
            sys.exit("guard: the case %s measured no matrix-vector product time" % product)
    rows = {name: figures(s, name, matvec_ms[PRODUCT[name]]) for name, s in stats.items()}
    for name, row in rows.items():
        print(json.dumps(dict({"guard": name, "total_s": round(stats[name]["total_s"], 2),
                               "matvec_ms": round(matvec_ms[PRODUCT[name]], 3)}, **row)),
              flush=True)
    if update:
        with open(BASELINE, "w") as f:
            json.dump({"build": "Debug", "note": "bench/run --guard --update; bench/guard.py",
                       "cases": rows}, f, indent=1, sort_keys=True)
            f.write("\n")
        print("guard: baseline written to %s" % os.path.relpath(BASELINE, ROOT))
        return 0
    if not os.path.exists(BASELINE):
        sys.exit("guard: no baseline %s; run bench/run --guard --update" % BASELINE)
    with open(BASELINE) as f:
        baseline = json.load(f)["cases"]
    moved = []
    for name in CASES:
        if name not in baseline:
            moved.append("%s: not in the baseline" % name)
            continue
        base = dict(baseline[name])
        bits = base.get("active_operator_bits")
        if PRODUCT[name] != "elastic" and bits != rows[name]["active_operator_bits"]:
            # A matrix-free solve in a build of another vector width: its
            # counts are compared, its times are not.
            print("guard: %s: the active operator's batches are %d bits wide, the baseline's %s:"
                  " its times are not compared" % (name, rows[name]["active_operator_bits"], bits))
            base = {k: v for k, v in base.items() if not k.endswith("_per_matvec")}
        moved += compare(name, rows[name], base)
    for m in moved:
        print("guard: FAIL " + m, flush=True)
    if moved:
        return 1
    print("guard: all %d cases within their tolerances of the baseline" % len(CASES))
    return 0

#!/usr/bin/python3
"""Convergence of the chapter-7 subduction experiments' key numbers under
uniform and adaptive refinement (elastic response; issue 17).

For each configuration of scripts/reproduce_subduction.py, the key numbers
(the thesis's quoted maxima at the edges and above the anomaly, measured as
in subduction_comparison.csv, and the goals of the .prm files: regional
means over boxes) on

  uniform:  Initial global refinement 0, 1, 2, 3 (510 ... 32 640 cells)
  adaptive: the .prm files' goal-oriented refinement from the coarse mesh
            (the stress-recovery indicators of the solution and of each
            goal's dual solution multiplied; each goal refines its share
            of 30 % of the cells), cycles 1 ... N

and writes OUTDIR/subduction_convergence.csv with the columns
experiment,refinement,level,cells,dofs,quantity,value,change_percent,
error_percent (change from the previous level; difference from the
finest uniform level), prints per configuration and strategy the DoFs at
which every key number is within 1 % of the finest uniform mesh's, and
where the .prm files' own stopping rule (the goals change by < 1 % while
the DoFs double) ends the cycles.

Usage: subduction_convergence.py OUTDIR [--binary PATH] [--only NAME,...]
                                 [--levels 4] [--cycles 6] [--measure-only]
"""
import argparse
import csv
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reproduce_subduction as rs  # noqa: E402

# Key numbers per experiment: the rows of subduction_comparison.csv (by the
# start of their quantity text) whose convergence is tracked.
KEYS = {
    "density": ["largest horizontal deviatoric tension",
                "largest vertical tension"],
    "slab_pull": ["largest horizontal deviatoric tension",
                  "mean horizontal stress in the subducting plate's elastic lid",
                  "mean horizontal stress in the continental upper crust"],
    "coupling": ["mean horizontal stress in the subducting plate's elastic lid",
                 "mean horizontal stress in the continental crust",
                 "mean horizontal stress in the continental mantle"],
    "basal_shear": ["horizontal stress at the surface above",
                    "largest horizontal tension beneath it"],
    "thermal": ["horizontal stress at the top of the crust",
                "largest horizontal compression above"],
}


def keys_of(name):
    """The tracked quantities of experiment name: its key rows and every
    goal."""
    for prefix, keys in KEYS.items():
        if name.startswith(prefix):
            return keys + ["goal "]
    return ["goal "]


def measure_once(binary, name, prm, sets, directory, measure_only=False):
    stats = rs.run(binary, prm, directory, sets, True, 1, measure_only)
    table = rs.Table()
    rs.measure(table, name, directory, "elastic", {})
    values = {}
    for key in keys_of(name):
        for _, quantity, ours, _, _ in table.rows:
            if quantity.startswith(key):
                # A goal's text names the cycles and DoFs: keep its name.
                label = quantity.split(" (")[0] if key == "goal " else quantity
                values[label] = ours
                if key != "goal ":
                    break
    return stats, values


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir")
    parser.add_argument("--binary", default=os.path.join(rs.ROOT, "build", "lithostress"))
    parser.add_argument("--only", default="")
    parser.add_argument("--levels", type=int, default=4)
    parser.add_argument("--cycles", type=int, default=6)
    parser.add_argument("--measure-only", action="store_true",
                        help="measure the runs already in OUTDIR again, without running them")
    args = parser.parse_args()
    outdir = os.path.abspath(args.outdir)
    os.makedirs(outdir, exist_ok=True)
    only = [s for s in args.only.split(",") if s]
    rows, summary = [], {}
    for name, prm, sets in rs.CONFIGS:
        if only and name not in only:
            continue
        results = {}
        for strategy, runs in (
                ("uniform", [(level, ["Mesh refinement/Initial global refinement=%d" % level,
                                      "Mesh refinement/Number of cycles=1"])
                             for level in range(args.levels)]),
                ("adaptive", [(cycle, ["Mesh refinement/Goals/Stop at relative change=0",
                                       "Mesh refinement/Number of cycles=%d" % cycle])
                              for cycle in range(1, args.cycles + 1)])):
            results[strategy] = []
            for level, extra in runs:
                d = os.path.join(outdir, "%s_%s_%d" % (name, strategy, level))
                stats, values = measure_once(args.binary, name, prm,
                                             list(sets) + extra + ["Output/Figures/Enabled=false"], d,
                                             args.measure_only)
                results[strategy].append((level, stats, values))
                print("%-20s %-9s %d: %6d DoFs" % (name, strategy, level, stats["dofs"]), flush=True)
        # Where the .prm file's own rule stops the cycles.
        d = os.path.join(outdir, "%s_stop" % name)
        stats = rs.run(args.binary, prm, d, list(sets) + ["Output/Figures/Enabled=false"], True, 1,
                       args.measure_only)
        with open(os.path.join(d, "convergence.csv")) as f:
            stopped = list(csv.DictReader(f))
        summary[(name, "stop")] = {"cycles": len(stopped), "dofs": stats["dofs"]}
        print("%-20s stops after %d cycles at %d DoFs" % (name, len(stopped), stats["dofs"]),
              flush=True)
        reference = results["uniform"][-1][2]
        for strategy, levels in results.items():
            previous = None
            for level, stats, values in levels:
                worst = 0.0
                for quantity, value in values.items():
                    change = (abs(value - previous[quantity]) / max(abs(value), 1e-12) * 100
                              if previous else float("nan"))
                    error = abs(value - reference[quantity]) / max(abs(reference[quantity]), 1e-12) * 100
                    worst = max(worst, error)
                    rows.append([name, strategy, level, stats["cells"], stats["dofs"], quantity,
                                 "%.5g" % value, "%.3g" % change, "%.3g" % error])
                is_reference = strategy == "uniform" and level == levels[-1][0]
                if worst < 1 and not is_reference and (name, strategy) not in summary:
                    summary[(name, strategy)] = stats["dofs"]
                previous = values
    with open(os.path.join(outdir, "subduction_convergence.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["experiment", "refinement", "level", "cells", "dofs", "quantity", "value",
                    "change_percent", "error_percent"])
        w.writerows(rows)
    with open(os.path.join(outdir, "subduction_convergence_summary.json"), "w") as f:
        json.dump({"%s %s" % k: v for k, v in summary.items()}, f, indent=1)
    for (name, strategy), dofs in sorted(summary.items()):
        if strategy != "stop":
            print("%-20s %-9s within 1 %% of the finest uniform mesh at %d DoFs"
                  % (name, strategy, dofs))


if __name__ == "__main__":
    main()

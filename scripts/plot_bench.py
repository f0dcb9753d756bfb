#!/usr/bin/env python3
"""Plot time per DoF against DoFs from bench/run's JSON lines:
  scripts/plot_bench.py bench.jsonl figure.png
One line per (problem, solver, ranks); total_s / dofs in microseconds.
A flat line is O(N) cost."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    rows = [json.loads(line) for line in open(sys.argv[1]) if line.strip().startswith("{")]
    series = {}
    for r in rows:
        if r["problem"] == "default":
            continue
        series.setdefault((r["problem"], r["solver"], r["ranks"]), []).append(r)
    fig, ax = plt.subplots(figsize=(9.5, 4.8))
    colours = {"amg": "tab:red", "mf-gmg": "tab:blue", "direct": "tab:grey",
               "petsc-gamg": "tab:green"}
    markers = {"flexure": "o", "column": "s"}
    for (problem, solver, ranks), rs in sorted(series.items()):
        rs.sort(key=lambda r: r["dofs"])
        ax.plot([r["dofs"] for r in rs], [1e6 * r["total_s"] / r["dofs"] for r in rs],
                color=colours.get(solver, "k"), marker=markers.get(problem, "^"),
                linestyle="-" if ranks == 1 else "--",
                label="%s, %s, %d rank%s" % (problem, solver, ranks, "" if ranks == 1 else "s"))
    ax.set_xscale("log")
    ax.set_xlabel("degrees of freedom")
    ax.set_ylabel("total wall time per DoF [µs]")
    ax.set_ylim(bottom=0)
    ax.grid(True, which="both", alpha=0.3)
    ax.set_title("lithostress bench/run: time per DoF (Q2 elasticity, CG to 1e-10;\n"
                 "petsc-gamg = dolfinx + PETSc GAMG on the same machine)", fontsize=9)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=130)


if __name__ == "__main__":
    main()

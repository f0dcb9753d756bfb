#!/usr/bin/python3
"""Figure of the visco-elastic cylinder (thesis §4.5): sigma_r and sigma_theta
against time at the report points of OUTDIR/point_history.csv, computed
(markers), exact for the model (lines, tests/viscoelastic/
cylinder_reference.py, resolved shell) and the thesis's printed curves
(dashed, sign of the 0.1583 term corrected, see
doc/viscoelastic_cylinder_derivation.md).

Usage: python3 scripts/plot_cylinder.py OUTDIR [PNG]
(PNG defaults to OUTDIR/cylinder_stresses.png). Needs python3-matplotlib.
"""
import csv
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tests", "viscoelastic"))
sys.path.insert(0, os.path.join(ROOT, "tests"))
import cylinder_reference as reference  # noqa: E402

out = sys.argv[1]
png = sys.argv[2] if len(sys.argv) > 2 else os.path.join(out, "cylinder_stresses.png")
rows = list(csv.DictReader(open(os.path.join(out, "point_history.csv"))))
radii = sorted({float(r["x"]) for r in rows})
fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharex=True)
times = [0.01 * k for k in range(1001)]
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
for i, r in enumerate(radii):
    c = colours[i % len(colours)]
    mine = [row for row in rows if float(row["x"]) == r]
    for ax, key, index in ((axes[0], "s_xx", 0), (axes[1], "s_yy", 1)):
        ax.plot(times, [reference.stresses(r, t, "shell")[index] for t in times], color=c,
                label="exact, r = %g" % r)
        ax.plot(times, [reference.thesis_stresses(r, t)[index] for t in times], "--", color=c,
                linewidth=0.8)
        ax.plot([float(m["time"]) for m in mine], [float(m[key]) for m in mine], "o", color=c,
                markersize=5)
for ax, name in ((axes[0], r"$\sigma_r$"), (axes[1], r"$\sigma_\theta$")):
    ax.set_xlabel(r"t / ($\eta$/G)")
    ax.set_ylabel(name + " (internal pressure 1000)")
    ax.grid(alpha=0.3)
axes[0].legend(fontsize=8)
fig.suptitle("Visco-elastic cylinder (thesis §4.5): lithostress (o), exact (—), thesis (- -)")
fig.tight_layout()
fig.savefig(png, dpi=110)
print("wrote", png)

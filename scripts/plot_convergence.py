#!/usr/bin/python3
"""Plot convergence studies: error versus DoFs on log-log axes, one curve
per (convergence.csv, column) pair, with reference slopes.

  plot_convergence.py out.png "label:path/convergence.csv:column" ... \
      [--slope 1.5] [--slope 1@2] [--title TEXT]

Uses Debian's python3-matplotlib; exits with a warning (status 0) if it is
missing, so that runs do not fail for want of a plotting library."""
import argparse
import csv
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.stderr.write("plot_convergence: matplotlib is missing (apt install python3-matplotlib); no figure made\n")
    sys.exit(0)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output")
    parser.add_argument("curves", nargs="+", help="label:csv:column")
    parser.add_argument("--slope", action="append", default=[],
                        help="reference line N^-S through the last point of curve K: S or S@K (K from 0)")
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    fig, ax = plt.subplots(figsize=(6.4, 4.8))
    markers = "os^vD<>p*"
    anchors = []
    for k, curve in enumerate(args.curves):
        label, path, column = curve.rsplit(":", 2)
        with open(path) as f:
            rows = [r for r in csv.DictReader(f) if r[column] not in ("", "nan")]
        n = [float(r["dofs"]) for r in rows]
        e = [float(r[column]) for r in rows]
        ax.loglog(n, e, marker=markers[k % len(markers)], label=label)
        anchors.append((n[-1], e[-1], n[0]))
    for spec in args.slope:
        s, _, k = spec.partition("@")
        s = float(s)
        n1, e1, n0 = anchors[int(k) if k else 0]
        if True:
            xs = [n0, n1]
            ys = [e1 * (x / n1) ** (-s) for x in xs]
            ax.loglog(xs, ys, "k--", linewidth=0.8)
            ax.annotate("$N^{-%g}$" % s, (xs[0], ys[0]), fontsize=9)
    ax.set_xlabel("degrees of freedom N")
    ax.set_ylabel("error")
    ax.grid(True, which="both", linewidth=0.3)
    ax.legend(fontsize=8)
    if args.title:
        ax.set_title(args.title)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)


if __name__ == "__main__":
    main()

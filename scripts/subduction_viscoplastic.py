#!/usr/bin/python3
"""The chapter-7 basal shear (thesis section 7.6.1) when the plates creep
and yield (issue 51; doc/plasticity.md): the stresses the thesis quotes for
it, measured as scripts/reproduce_subduction.py measures them, in one table

  quantity, thesis, elastic, maxwell_5Myr, viscoplastic_share,
  viscoplastic_total, viscoplastic_background, unit

elastic and maxwell_5Myr: prm/subduction_basal_shear.prm (the shear alone,
elastic and after 5 Myr of Maxwell relaxation); viscoplastic_total:
prm/subduction_viscoplastic.prm after 5 Myr of the shear (t = 5.2 Myr: the
stripped densities with their trench pressures raised in 0.1 Myr, the
shear in the next 0.1 Myr); viscoplastic_background: the same without the
shear; viscoplastic_share: total - background, the shear's share of a
non-linear response (not a superposition: for peaks, the difference of the
peaks). Writes OUTDIR/subduction_viscoplastic.csv and prints the table.

Usage: subduction_viscoplastic.py OUTDIR [--binary PATH] [--measure-only]
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import reproduce_subduction as rs  # noqa: E402

RUNS = (("elastic", "subduction_basal_shear.prm", [], True),
        ("maxwell_5Myr", "subduction_basal_shear.prm", [], False),
        ("viscoplastic_total", "subduction_viscoplastic.prm", [], False),
        ("viscoplastic_background", "subduction_viscoplastic.prm",
         ["Loads/Tractions/base/Shear traction=0"], False))


def yielding_fraction(directory):
    """The fraction of the section's sample grid (principal_stresses.csv)
    that yields at the end."""
    with open(os.path.join(directory, "principal_stresses.csv")) as f:
        rows = list(csv.DictReader(f))
    flags = [float(r["yielding"]) > 0.5 for r in rows if r.get("yielding", "") != ""]
    return sum(flags) / len(flags) if flags else 0.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir")
    parser.add_argument("--binary", default=os.path.join(rs.ROOT, "build", "lithostress"))
    parser.add_argument("--measure-only", action="store_true")
    args = parser.parse_args()
    outdir = os.path.abspath(args.outdir)
    os.makedirs(outdir, exist_ok=True)
    values, units, thesis = {}, {}, {}
    for label, prm, sets, elastic in RUNS:
        directory = os.path.join(outdir, label)
        rs.run(args.binary, prm, directory, sets, elastic, 1, args.measure_only)
        table = rs.Table()
        # The thesis's numbers are those of its elastic section 7.6.1.
        rs.measure(table, "basal_shear", directory, "5Myr",
                   rs.THESIS[("basal_shear", "elastic")])
        for _, quantity, value, number, unit in table.rows:
            values.setdefault(quantity, {})[label] = value
            units[quantity] = unit
            thesis[quantity] = "" if number is None else number
        if label.startswith("viscoplastic"):
            values.setdefault("yielding", {})[label] = 100 * yielding_fraction(directory)
            units["yielding"] = "% of the section"
    columns = ["quantity", "thesis", "elastic", "maxwell_5Myr", "viscoplastic_share",
               "viscoplastic_total", "viscoplastic_background", "unit"]
    path = os.path.join(outdir, "subduction_viscoplastic.csv")
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(columns)
        for quantity, by_run in values.items():
            share = None
            if "viscoplastic_total" in by_run and "viscoplastic_background" in by_run:
                share = by_run["viscoplastic_total"] - by_run["viscoplastic_background"]
            row = [quantity, thesis.get(quantity, ""),
                   *("%.4g" % by_run[r] if r in by_run and by_run[r] is not None else ""
                     for r in ("elastic", "maxwell_5Myr")),
                   "%.4g" % share if share is not None else "",
                   *("%.4g" % by_run[r] if r in by_run and by_run[r] is not None else ""
                     for r in ("viscoplastic_total", "viscoplastic_background")),
                   units[quantity]]
            writer.writerow(row)
            print(" | ".join(str(c) for c in row))
    print("wrote", path)
    return 0


if __name__ == "__main__":
    sys.exit(main())

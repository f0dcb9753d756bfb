#!/usr/bin/env python3
"""Compare the results of two runs of the same model, number by number.

    python3 scripts/compare_outputs.py OLD_DIR NEW_DIR [--tolerance 1e-10]

Every CSV file and every JSON file (except statistics.json, which holds
timings) present in OLD_DIR must be in NEW_DIR with the same columns and
rows; numbers must agree to the relative tolerance, measured against the
largest magnitude of their column (so that a value that is round-off next
to its column's scale does not count as a relative change). Columns of
wall times are skipped. Prints the largest relative difference per file
and exits 1 if any file differs. Used to show that a restructuring leaves
the results of prm/*.prm unchanged.
"""
import argparse
import csv
import json
import math
import os
import sys

SKIPPED_COLUMNS = {"wall_time"}
SKIPPED_FILES = {"statistics.json"}


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def compare_csv(old_path, new_path):
    with open(old_path) as f:
        old = list(csv.reader(f))
    with open(new_path) as f:
        new = list(csv.reader(f))
    if not old or not new or old[0] != new[0]:
        return math.inf, "columns differ"
    if len(old) != len(new):
        return math.inf, "%d rows against %d" % (len(old), len(new))
    header = old[0]
    scale = [0.0] * len(header)
    for row in old[1:]:
        for c, text in enumerate(row):
            x = number(text)
            if x is not None and math.isfinite(x):
                scale[c] = max(scale[c], abs(x))
    worst, where = 0.0, ""
    for r, (a, b) in enumerate(zip(old[1:], new[1:]), 2):
        for c, (x, y) in enumerate(zip(a, b)):
            if c < len(header) and header[c] in SKIPPED_COLUMNS:
                continue
            u, v = number(x), number(y)
            if u is None or v is None:
                if x != y:
                    return math.inf, "row %d, %s: %r against %r" % (r, header[c], x, y)
                continue
            if math.isnan(u) and math.isnan(v):
                continue
            d = abs(u - v) / max(scale[c], 1e-300)
            if d > worst:
                worst, where = d, "row %d, %s" % (r, header[c] if c < len(header) else c)
    return worst, where


def flatten(value, prefix=""):
    if isinstance(value, dict):
        for k, v in value.items():
            yield from flatten(v, prefix + "/" + k)
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from flatten(v, prefix + "[%d]" % i)
    else:
        yield prefix, value


def compare_json(old_path, new_path):
    old = dict(flatten(json.load(open(old_path))))
    new = dict(flatten(json.load(open(new_path))))
    if old.keys() != new.keys():
        return math.inf, "keys differ"
    worst, where = 0.0, ""
    for key, x in old.items():
        y = new[key]
        if isinstance(x, (int, float)) and isinstance(y, (int, float)):
            if isinstance(x, float) and math.isnan(x) and math.isnan(y):
                continue
            d = abs(x - y) / max(abs(x), 1e-300) if x != y else 0.0
            if d > worst:
                worst, where = d, key
        elif x != y:
            return math.inf, "%s: %r against %r" % (key, x, y)
    return worst, where


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("old")
    parser.add_argument("new")
    parser.add_argument("--tolerance", type=float, default=1e-10)
    args = parser.parse_args()
    bad = 0
    for folder, _, files in os.walk(args.old):
        for name in sorted(files):
            if name in SKIPPED_FILES or not name.endswith((".csv", ".json")):
                continue
            old_path = os.path.join(folder, name)
            rel = os.path.relpath(old_path, args.old)
            new_path = os.path.join(args.new, rel)
            if not os.path.exists(new_path):
                print("%-40s missing in %s" % (rel, args.new))
                bad += 1
                continue
            compare = compare_csv if name.endswith(".csv") else compare_json
            worst, where = compare(old_path, new_path)
            ok = worst <= args.tolerance
            bad += 0 if ok else 1
            print("%-40s %s largest relative difference %.2e %s"
                  % (rel, "ok  " if ok else "DIFF", worst, where))
    print("%d file(s) differ" % bad)
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()

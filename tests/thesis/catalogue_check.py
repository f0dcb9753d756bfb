"""The catalogue of the thesis's quantitative statements
(scripts/thesis_statements.csv) and what reads it: every row well formed
(a number, a unit, the thesis's words; a stated range contains the
thesis's number, an upper bound is that number), each (experiment,
quantity) once, and every key that scripts/reproduce_thesis.py measures
or scripts/thesis_explanations.csv explains is in the catalogue, so that
no measured number silently misses its row. Standard library only."""
import csv
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, finish  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
with open(os.path.join(ROOT, "scripts", "thesis_statements.csv")) as f:
    reader = csv.DictReader(f)
    columns = reader.fieldnames
    rows = list(reader)
check(columns == ["chapter", "section", "experiment", "quantity", "thesis", "low", "high",
                  "unit", "quote"], "catalogue columns %s" % columns)
keys = [(r["experiment"], r["quantity"]) for r in rows]
check(len(set(keys)) == len(keys), "each (experiment, quantity) once (%d rows)" % len(rows))
check(len(rows) > 60, "more than 60 statements (%d)" % len(rows))
bad = []
for r in rows:
    try:
        value = float(r["thesis"])
        low = float(r["low"]) if r["low"] else -float("inf")
        high = float(r["high"]) if r["high"] else float("inf")
        ok = (r["chapter"] in ("4", "6", "7") and r["unit"] and r["quote"] and r["section"]
              and low <= value <= high and (not r["high"] or r["low"] or value == high))
    except ValueError:
        ok = False
    if not ok:
        bad.append((r["experiment"], r["quantity"]))
check(not bad, "every row well formed (bad: %s)" % bad)

known = set(keys)
experiments = {k[0] for k in known}
with open(os.path.join(ROOT, "scripts", "reproduce_thesis.py")) as f:
    script = f.read()
# Literal (experiment, quantity) pairs in the script whose experiment is in
# the catalogue (keys have capitals: plane_normal_fault_50MPa,
# vertical_stress_applied_over_A_A), and the keys its format strings make.
literal = set(re.findall(r'\(\s*"([A-Za-z0-9_]+)",\s*"([A-Za-z0-9_]+)"\s*\)', script))
pairs = {p for p in literal if p[0] in experiments}
check(len(pairs) >= len(experiments),
      "reproduce_thesis.py: %d literal keys of the catalogue's %d experiments found (at least one "
      "per experiment: a parser that finds nothing must fail)" % (len(pairs), len(experiments)))
pairs |= {("cantilever_%s_27node" % e, "max_neutral_fibre_deflection_fraction_of_analytic")
          for e in ("cst", "csq")}
missing = sorted(pairs - known)
check(not missing, "%d keys measured by reproduce_thesis.py are in the catalogue (missing: %s)"
      % (len(pairs), missing))
with open(os.path.join(ROOT, "scripts", "thesis_explanations.csv")) as f:
    explained = {(r["experiment"], r["quantity"]) for r in csv.DictReader(f)}
check(len(explained) > 0 and explained <= known,
      "%d explanations, every one naming a catalogue row (unknown: %s)"
      % (len(explained), sorted(explained - known)))
finish()

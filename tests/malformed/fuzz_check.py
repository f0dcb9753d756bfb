"""Hostile input, one entry at a time: each shipped model of prm/ is run
with one of its entries changed to a hostile value -- negative, zero, NaN,
infinite, huge, tiny, empty, text, or a broken function, by the kind of
value the entry holds -- written into a copy of the model's file (so an
empty value is an empty value, not a malformed --set).

Every run must either succeed or end with one line on stderr from the
program itself ("lithostress: ..."), exit status 1 (the input refused) or
3 (the computation stopped, the state named), no signal, no stack trace,
no empty message, within a minute. A run that is still going after
--cap seconds (20 by default) has accepted the value -- a tolerance of
1e-300 is a legal, slow request -- and is stopped; it counts as accepted.

The ctest run (fuzz_input) tries a fixed sample: SAMPLE entries of each
model, each with a value drawn for its kind, by a seeded generator, so
that the same cases run every time and every model is covered, plus one
case of each kind of entry the draws missed, so that every kind is. `--all` tries every entry with every value of
its kind (some 4 000 runs; for a review, not for CI), `--sample N` N
entries per model. Each outcome is
printed; the summary counts the runs refused, stopped, accepted (still
running at the cap), succeeded and failed.

    python3 tests/malformed/fuzz_check.py [--all | --sample N] [--cap SECONDS]
"""
import concurrent.futures
import os
import random
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from lithotest import BINARY, check, env, finish  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(HERE))
MODELS = os.path.join(ROOT, "prm")
SAMPLE = 6
SEED = 52
LIMIT = 60
# Entries not tried: where the output goes (the test sets it) and whether
# ParaView files and figures are written (off, to keep the runs short).
SKIPPED = {"Output directory", "Output/Write ParaView files", "Output/Figures/Enabled"}
QUIET = ["Output/Write ParaView files = false"]

NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")
HOSTILE = {
    "number": ["-1", "0", "nan", "inf", "-inf", "1e300", "1e-300", "", "abc"],
    "list": ["", "nan, 1", "1, abc", "-1e300, 0", ",,"],
    "bool": ["", "maybe"],
    "function": ["x +* 2", "", "1/0", "sqrt(-1 - x*x)", "q*x", "nan"],
    "text": ["", "nonsense", "0"],
}


def kind(value):
    """The kind of value an entry holds, read off its value in the model."""
    v = value.strip()
    if NUMBER.match(v):
        return "number"
    if v in ("true", "false"):
        return "bool"
    parts = [p.strip() for p in v.split(",")]
    if len(parts) > 1 and all(NUMBER.match(p) for p in parts if p):
        return "list"
    if re.search(r"[xyt]\b", v) and re.search(r"[-+*/()^]", v):
        return "function"
    return "text"


def entries(text):
    """The set lines of a .prm text: (line index, entry path, value)."""
    found, sections = [], []
    for i, line in enumerate(text.splitlines()):
        code = line.split("#", 1)[0].strip()
        if code.startswith("subsection "):
            sections.append(code[len("subsection "):].strip())
        elif code == "end" and sections:
            sections.pop()
        elif code.startswith("set ") and "=" in code:
            key, value = code[len("set "):].split("=", 1)
            path = "/".join(sections + [key.strip()])
            if path not in SKIPPED:
                found.append((i, path, value.strip()))
    return found


def cases(all_cases, sample):
    """(model, line index, path, original value, hostile value) to try:
    every entry with every value of its kind, or @p sample entries per
    model, each with one value of its kind."""
    rng = random.Random(SEED)
    out, every = [], []
    for model in sorted(f for f in os.listdir(MODELS) if f.endswith(".prm")):
        with open(os.path.join(MODELS, model)) as f:
            found = entries(f.read())
        every += [(model, i, p, v) for i, p, v in found]
        if all_cases:
            out += [(model, i, p, v, h) for i, p, v in found for h in HOSTILE[kind(v)]]
        else:
            for i, p, v in rng.sample(found, min(sample, len(found))):
                out.append((model, i, p, v, rng.choice(HOSTILE[kind(v)])))
    # Every kind of entry at least once, whatever the models' sample drew
    # (a new model shifts the seeded draws): one more case of each missing
    # kind, drawn from all the models' entries of that kind.
    for missing in sorted(set(HOSTILE) - {kind(c[3]) for c in out}):
        candidates = [c for c in every if kind(c[3]) == missing]
        if candidates:
            model, i, p, v = rng.choice(candidates)
            out.append((model, i, p, v, rng.choice(HOSTILE[missing])))
    return out


def run_case(number, case, cap):
    """Run one case in a directory of its own; returns (outcome, detail,
    seconds) with outcome one of succeeded, refused, accepted, failed."""
    model, index, path, value, hostile = case
    work = os.path.abspath("fuzz_%04d" % number)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    with open(os.path.join(MODELS, model)) as f:
        lines = f.read().splitlines()
    key = lines[index].split("=", 1)[0]
    lines[index] = key + "= " + hostile
    prm = os.path.join(work, model)
    with open(prm, "w") as f:
        f.write("\n".join(lines) + "\n")
    cmd = [BINARY, prm, "--set", "Output directory=" + os.path.join(work, "output")]
    for s in QUIET:
        cmd += ["--set", s.replace(" = ", "=")]
    start = time.time()
    process = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               text=True, env=env(), cwd=ROOT)
    try:
        _, stderr = process.communicate(timeout=cap)
    except subprocess.TimeoutExpired:
        process.kill()
        process.communicate()
        shutil.rmtree(work, ignore_errors=True)
        return "accepted", "still running after %d s" % cap, time.time() - start
    seconds = time.time() - start
    shutil.rmtree(work, ignore_errors=True)
    lines = [line for line in stderr.splitlines() if line.strip()]
    code = process.returncode
    if code == 0:
        return "succeeded", "", seconds
    if code < 0:
        return "failed", "killed by signal %d; stderr: %s" % (-code, stderr[-300:]), seconds
    # 1: an input error; 3: the computation failed (both one line of the
    # program's own, app/main.cc); 2 is an internal error, 128 + n a signal.
    if code not in (1, 3):
        return "failed", "exit %d; stderr: %s" % (code, stderr[-300:]), seconds
    if len(lines) != 1:
        return "failed", "%d lines on stderr: %s" % (len(lines), stderr[-400:]), seconds
    line = lines[0]
    if (not line.startswith("lithostress: ") or len(line) < len("lithostress: ") + 10
            or "Stacktrace" in stderr or "internal error" in line):
        return "failed", "not one clear line: %s" % line, seconds
    if seconds > LIMIT:
        return "failed", "refused after %.0f s (> %d s): %s" % (seconds, LIMIT, line), seconds
    return ("refused" if code == 1 else "stopped"), line, seconds


def main(argv):
    all_cases = "--all" in argv
    cap = int(argv[argv.index("--cap") + 1]) if "--cap" in argv else 20
    sample = int(argv[argv.index("--sample") + 1]) if "--sample" in argv else SAMPLE
    todo = cases(all_cases, sample)
    kinds = {kind(c[3]) for c in todo}
    check(len({c[0] for c in todo}) >= 14 and kinds == set(HOSTILE),
          "%d cases over %d models, every kind of entry (%s)"
          % (len(todo), len({c[0] for c in todo}), ", ".join(sorted(kinds))))
    # Two runs at a time: the test holds two processors.
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(lambda nc: run_case(nc[0], nc[1], cap), enumerate(todo)))
    counts = {}
    for case, (outcome, detail, seconds) in zip(todo, results):
        model, _, path, value, hostile = case
        counts[outcome] = counts.get(outcome, 0) + 1
        label = "%s: %s = <%s> (was <%s>)" % (model, path, hostile, value)
        message = "%s: %s in %.1f s%s" % (label, outcome, seconds, ": " + detail if detail else "")
        if outcome == "failed":
            check(False, message)
        else:
            print("     " + message)
    print("outcomes: " + ", ".join("%d %s" % (n, o) for o, n in sorted(counts.items())))
    check(counts.get("refused", 0) > 0, "some hostile values are refused (the parser of "
          "outcomes finds what it counts)")
    finish()


main(sys.argv)

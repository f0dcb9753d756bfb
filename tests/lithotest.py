"""Helpers for the lithostress ctest suite: run the program on a .prm file
(optionally on several MPI ranks, with --set overrides) and read its
convergence table. Only the Python standard library is used."""
import csv
import math
import os
import shutil
import subprocess
import sys

BINARY = os.environ.get("LITHOSTRESS_BINARY", "")
SOURCE = os.path.dirname(os.path.abspath(__file__))


def env():
    e = dict(os.environ)
    e["OMPI_ALLOW_RUN_AS_ROOT"] = "1"
    e["OMPI_ALLOW_RUN_AS_ROOT_CONFIRM"] = "1"
    e["OMPI_MCA_rmaps_base_oversubscribe"] = "1"
    return e


def run(prm, output, ranks=1, sets=(), expect_success=True, extra_env=None,
        keep_output=False):
    """Run lithostress on tests/<prm> writing into <output> (with the
    environment variables @extra_env added); returns the CompletedProcess.
    Fails the test if the run fails unexpectedly. The output directory is
    removed first unless keep_output (a resumed run)."""
    if os.path.isdir(output) and not keep_output:
        shutil.rmtree(output)
    cmd = [BINARY, os.path.join(SOURCE, prm), "--set", "Output directory=" + output]
    for s in sets:
        cmd += ["--set", s]
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
    environment = env()
    environment.update(extra_env or {})
    result = subprocess.run(cmd, capture_output=True, text=True, env=environment)
    if expect_success and result.returncode != 0:
        print(result.stdout)
        print(result.stderr)
        fail("lithostress failed on %s (exit %d)" % (prm, result.returncode))
    return result


def table(output):
    """The rows of <output>/convergence.csv as a list of dicts of floats."""
    with open(os.path.join(output, "convergence.csv")) as f:
        rows = []
        for row in csv.DictReader(f):
            rows.append({k: (float(v) if v != "" else math.nan) for k, v in row.items()})
        return rows


def read_csv(path):
    """The rows of a CSV file as dicts; numbers become floats, other
    fields stay strings."""
    def value(v):
        try:
            return float(v)
        except ValueError:
            return v
    with open(path) as f:
        return [{k: value(v) for k, v in row.items()} for row in csv.DictReader(f)]


def read_prm(path):
    """A .prm file (e.g. the parameters.prm a run writes) as
    {"Section/Subsection/Entry": value string}."""
    entries, sections = {}, []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                sections.append(line[len("subsection "):].strip())
            elif line == "end":
                sections.pop()
            elif line.startswith("set "):
                key, value = line[len("set "):].split("=", 1)
                entries["/".join(sections + [key.strip()])] = value.strip()
    return entries


def solve_dense(M, rhs):
    """The solution of the small dense system M x = rhs (Gaussian
    elimination with partial pivoting)."""
    n = len(rhs)
    A = [list(map(float, row)) + [float(rhs[i])] for i, row in enumerate(M)]
    for k in range(n):
        piv = max(range(k, n), key=lambda r: abs(A[r][k]))
        A[k], A[piv] = A[piv], A[k]
        for r in range(k + 1, n):
            m = A[r][k] / A[k][k]
            for j in range(k, n + 1):
                A[r][j] -= m * A[k][j]
    x = [0.0] * n
    for k in reversed(range(n)):
        x[k] = (A[k][n] - sum(A[k][j] * x[j] for j in range(k + 1, n))) / A[k][k]
    return x


def forces(output):
    """force_balance.csv of <output> as {(kind, name): (F_x, F_y)}."""
    return {(r["kind"], r["name"]): (r["F_x"], r["F_y"])
            for r in read_csv(os.path.join(output, "force_balance.csv"))}


def slope(rows, column, first=0):
    """Least-squares rate -dlog(e)/dlog(N) over rows[first:]."""
    xs = [math.log(r["dofs"]) for r in rows[first:]]
    ys = [math.log(r[column]) for r in rows[first:]]
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    sxx = sum((x - mx) ** 2 for x in xs)
    return -sxy / sxx


FAILURES = []


def newton_solves(log_text):
    """The frictional Newton iterations of a run's log, one list per solve
    (a new solve starts at iteration 1): dicts with iteration, residual
    (relative to the load), sliding and open. Fails the test if the log
    has none: a parser that finds nothing must not pass."""
    import re
    solves = []
    for m in re.finditer(r"Newton iteration (\d+): residual (\S+), .*? (\d+) sliding, "
                         r"(\d+) open", log_text):
        if m.group(1) == "1" or not solves:
            solves.append([])
        solves[-1].append({"iteration": int(m.group(1)), "residual": float(m.group(2)),
                           "sliding": int(m.group(3)), "open": int(m.group(4))})
    if not solves:
        fail("the log has no frictional Newton iteration lines")
    return solves


def settled_steps(solve):
    """The Newton steps of @solve taken with the states standing still:
    those whose sliding and open counts equal the step before's (a change
    that keeps the counts is missed, which only lengthens what is
    counted)."""
    return [i for i in range(1, len(solve))
            if (solve[i]["sliding"], solve[i]["open"]) ==
            (solve[i - 1]["sliding"], solve[i - 1]["open"])]


def check_settled_newton(label, solves, reduction=1e-2, floor=1e-11):
    """Once the fault states stand still the frictional problem is linear:
    a Newton step solves it to its linear solve's accuracy (Linear solver
    reduction 1e-3 or tighter), so each settled step of every solve in
    @solves (newton_solves) reduces the residual by at least @reduction,
    down to the round-off @floor of the residual relative to the load (10x
    margin on the linear solve's 1e-3). At least one step must be settled
    above the floor (a solve started from a converged solution has none):
    with none the check would test nothing."""
    ratios, n_steps, n_settled = [], 0, 0
    for solve in solves:
        steps = settled_steps(solve)
        n_steps += len(solve)
        n_settled += len(steps)
        ratios += [solve[i]["residual"] / solve[i - 1]["residual"] for i in steps
                   if solve[i - 1]["residual"] > floor]
    check(n_settled > 0 and len(ratios) > 0 and all(r <= reduction for r in ratios),
          "%s: %d Newton steps in %d solves, %d with the states standing still, residual ratios "
          "there %s (each <= %g above %g: the settled problem is linear)"
          % (label, n_steps, len(solves), n_settled, ", ".join("%.1e" % r for r in ratios),
             reduction, floor))


def step_newton_residuals(log_text):
    """The relative residuals of each time step's Newton iteration (a
    non-linear rheology), from the log's "relative residuals a, b, ..."
    lists. Fails the test if the log has none."""
    import re
    steps = [[float(x) for x in m.group(1).split(", ")]
             for m in re.finditer(r"Newton iterations \(relative residuals ([^)]*)\)", log_text)]
    if not steps:
        fail("the log has no Newton residuals of a time step")
    return steps


def check_quadratic_newton(label, steps, noise=1e-7, floor=1e-11, order=1.7, most=8):
    """Newton's method converges quadratically: for each step of @steps
    (step_newton_residuals) the order estimate log(r_k+1/r_k)/log(r_k/r_k-1)
    of its triples r_k-1, r_k, r_k+1 clear of the linear solves' accuracy
    (r_k > @noise, r_k+1 > @floor, where the residual stops falling) reaches
    @order at least once (a linearly converging iteration gives about 1
    throughout, the secant method 1.62, Newton's method 2 once it is close,
    lower before); every step with such a triple is counted, and there must
    be one. Every step takes at most @most iterations."""
    import math
    orders = []
    for r in steps:
        estimates = [math.log(c / b) / math.log(b / a)
                     for a, b, c in zip(r, r[1:], r[2:]) if b > noise and c > floor]
        if estimates:
            orders.append(max(estimates))
    longest = max(steps, key=len)
    check(max(len(r) for r in steps) <= most,
          "%s: %d steps, at most %d Newton iterations each (at most %d)"
          % (label, len(steps), len(longest), most))
    check(len(orders) > 0 and min(orders) >= order,
          "%s: quadratic convergence, each step's best order estimate %.2f to %.2f over %d steps "
          "(at least %g; e.g. %s)"
          % (label, min(orders or [0]), max(orders or [0]), len(orders), order,
             ", ".join("%.1e" % x for x in longest)))


def check(condition, message):
    status = "ok  " if condition else "FAIL"
    print("%s %s" % (status, message))
    if not condition:
        FAILURES.append(message)


def fail(message):
    print("FAIL " + message)
    sys.exit(1)


def finish():
    if FAILURES:
        print("%d check(s) failed" % len(FAILURES))
        sys.exit(1)
    print("all checks passed")

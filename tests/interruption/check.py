"""SIGTERM during a run (1 and 2 MPI ranks; SIGINT on 1 rank; on 2 ranks the
signal goes to the rank processes, as a batch system sends it): the program
stops at the next safe point (between two phases of a cycle or two CG
iterations) on all ranks together, says on one line in which phase of which
cycle it stopped, exits with 128 + the signal number (Open MPI's mpirun
turns any non-zero exit of its ranks into 1), and leaves only complete
files: every CSV has its header's number of fields in every row, every JSON
and ParaView file parses, no temporary file is left, the convergence table
has one row for each cycle the message calls complete, and log.txt ends with
the timing table."""
import csv, glob, json, os, re, shutil, signal, subprocess, sys, time
import xml.etree.ElementTree as ET
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import check, finish, env, BINARY, SOURCE

PRM = os.path.join(os.path.dirname(SOURCE), "prm", "flexure.prm")
# Largest time from the signal to the exit. In a Debug build the longest
# phase that cannot be interrupted (the set-up of a 108 k-DoF mesh with its
# multigrid levels, or the assembly) takes 2-6 s here; Release takes a
# fifth of that (doc/verification.md).
LATEST_EXIT_S = 20


def children_of(pid):
    """The process ids whose parent is @pid (from /proc: no procps needed)."""
    result = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open("/proc/%s/stat" % entry) as f:
                    # pid (comm) state ppid ...: comm may contain blanks.
                    fields = f.read().rsplit(")", 1)[1].split()
                if int(fields[1]) == pid:
                    result.append(entry)
            except (OSError, IndexError, ValueError):
                pass
    return result


def complete_files(out, label):
    names = sorted(os.listdir(out))
    check(not any(".part-" in n for n in names), "%s: no temporary files left (%s)" % (label, ", ".join(names)))
    for path in glob.glob(os.path.join(out, "*.csv")):
        with open(path) as f:
            rows = list(csv.reader(f))
        check(len(rows) >= 1 and all(len(r) == len(rows[0]) for r in rows),
              "%s: %s complete (%d rows, all with %d fields)" % (label, os.path.basename(path), len(rows) - 1, len(rows[0]) if rows else 0))
    for path in glob.glob(os.path.join(out, "*.json")):
        try:
            json.load(open(path))
            ok = True
        except ValueError:
            ok = False
        check(ok, "%s: %s parses as JSON" % (label, os.path.basename(path)))
    for pattern in ("*.pvd", "*.pvtu", "*.vtu"):
        for path in glob.glob(os.path.join(out, pattern)):
            try:
                ET.parse(path)
                ok = True
            except ET.ParseError:
                ok = False
            check(ok, "%s: %s parses as XML" % (label, os.path.basename(path)))
    log = open(os.path.join(out, "log.txt")).read()
    check("stopped by" in log and log.rstrip().endswith("+"), "%s: log.txt says where it stopped and ends with the timing table" % label)


def wait_for_first_cycle(process, out):
    """Until log.txt in @out says cycle 0 is complete (or the run ended,
    or 600 s), then one second more: the signal then comes in cycle 1."""
    log = os.path.join(out, "log.txt")
    deadline = time.time() + 600
    while time.time() < deadline and process.poll() is None:
        if os.path.exists(log) and "cycle 0:" in open(log).read():
            break
        time.sleep(0.2)
    time.sleep(1.0)


for ranks, sig in ((1, signal.SIGTERM), (2, signal.SIGTERM), (1, signal.SIGINT)):
    name = "SIGTERM" if sig == signal.SIGTERM else "SIGINT"
    label = "%s on %d rank%s" % (name, ranks, "s" if ranks > 1 else "")
    out = os.path.abspath("output_interrupted_%d_%s" % (ranks, name))
    shutil.rmtree(out, ignore_errors=True)
    cmd = [BINARY, PRM, "--set", "Output directory=" + out, "--set", "Mesh refinement/Number of cycles=4"]
    environment = env()
    if ranks > 1:
        cmd = ["mpirun", "-np", str(ranks)] + cmd
        environment["OMPI_MCA_orte_execute_quiet"] = "1"
    process = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=environment)
    # Wait until the first cycle is complete, then signal (mpirun forwards
    # it to every rank).
    wait_for_first_cycle(process, out)
    check(process.poll() is None, "%s: the run is still going after cycle 0" % label)
    sent = time.time()
    if ranks == 1:
        process.send_signal(sig)
    else:
        # The ranks themselves, as a batch system's cancel does (mpirun
        # would kill them one second after forwarding a signal).
        children = children_of(process.pid)
        check(len(children) == ranks, "%s: %d rank processes found" % (label, len(children)))
        for pid in children:
            os.kill(int(pid), sig)
    try:
        stdout, stderr = process.communicate(timeout=120)
    except subprocess.TimeoutExpired:
        process.kill()
        check(False, "%s: stops (killed after 120 s)" % label)
        continue
    seconds = time.time() - sent
    lines = [l for l in stderr.splitlines() if l.strip()]
    expected_status = 128 + sig  # mpirun passes its ranks' status on
    check(process.returncode == expected_status, "%s: exit status %d (expected %d)" % (label, process.returncode, expected_status))
    check(seconds < LATEST_EXIT_S, "%s: stopped %.1f s after the signal" % (label, seconds))
    check(len(lines) == 1, "%s: one line on stderr: %s" % (label, " | ".join(lines)))
    m = re.search(r"stopped by %s in (.+) of cycle (\d+); " % name, lines[0] if lines else "")
    check(m is not None, "%s: the line says where: %s" % (label, lines[0] if lines else ""))
    if m:
        stopped_cycle = int(m.group(2))
        rows = list(csv.DictReader(open(os.path.join(out, "convergence.csv"))))
        check(stopped_cycle >= 1 and len(rows) == stopped_cycle,
              "%s: stopped in cycle %d (%s) with %d complete cycles in convergence.csv" % (label, stopped_cycle, m.group(1), len(rows)))
    complete_files(out, label)

# A second signal before the run has stopped ends it at once, by the
# signal's default action (base/interruption.cc): two SIGTERMs 10 ms apart,
# too close for the first to reach a safe point and stop (writing the
# timing table and closing the files takes longer), end the process by
# SIGTERM itself, not with the orderly stop's status 128 + 15.
out = os.path.abspath("output_interrupted_twice")
shutil.rmtree(out, ignore_errors=True)
process = subprocess.Popen([BINARY, PRM, "--set", "Output directory=" + out,
                            "--set", "Mesh refinement/Number of cycles=4"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env())
wait_for_first_cycle(process, out)
check(process.poll() is None, "second SIGTERM: the run is still going after cycle 0")
# The launcher execs the program (app/launcher.cc): the same process.
target = process.pid
sent = time.time()
os.kill(target, signal.SIGTERM)
time.sleep(0.01)
os.kill(target, signal.SIGTERM)
try:
    process.communicate(timeout=60)
except subprocess.TimeoutExpired:
    process.kill()
    check(False, "second SIGTERM: stops (killed after 60 s)")
seconds = time.time() - sent
check(process.returncode == -signal.SIGTERM and seconds < 5,
      "second SIGTERM: ends at once (status %d, %.2f s after the first signal)"
      % (process.returncode, seconds))
finish()

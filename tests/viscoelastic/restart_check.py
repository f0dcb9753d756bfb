"""Checkpoint and restart of the visco-elastic loop (issue 15, verification 5)
on the cylinder of prm/viscoelastic_cylinder.prm (coarse mesh, BDF2 with 1e-4 step
tolerance, a checkpoint every 10 steps):

1. an uninterrupted run on 1 rank is the reference;
2. a run killed (SIGKILL) as soon as its checkpoint of step 20 is current
   (polled every millisecond; in any case before its final one), with a half-written checkpoint directory left behind as a
   kill during the next checkpoint would leave it, resumes (--resume) on
   2 ranks from the last complete checkpoint and ends with the reference's
   answer to 1e-10 relative (point history, every step's time and step);
3. resumed on 1 rank from its final checkpoint with a longer end time, it
   continues the same series;
4. with CG + AMG, whose iterations depend on where CG starts (each step
   starts from the last two steps' extrapolation, SolutionPredictor, whose
   solutions the checkpoint keeps): a run to t = 1 s (one Maxwell time,
   while the body still relaxes) continued to 2 s takes the same steps
   (times to 2e-11 relative: the 12 digits time_steps.csv writes) and the
   same CG iterations in every step as a run straight to 2 s, and gives
   its answer to 1e-12. (With the multigrid of parts 1-3 this mesh solves in
   2 iterations from any start, so a lost predictor would not show there;
   with the AMG the first step after the resume then takes more
   iterations.)
Input errors (no checkpoint, another model's) are in malformed/check.py.
"""
import os
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from lithotest import BINARY, check, env, finish, read_csv, run  # noqa: E402

PRM = os.path.join(os.path.dirname(os.path.dirname(HERE)), "prm", "viscoelastic_cylinder.prm")
SETS = ["Mesh refinement/Initial global refinement=0",
        "Time stepping/Creep strain tolerance=1e-4",
        "Time stepping/Checkpoint interval=10",
        "Output/Write ParaView files=false",
        "Output/Figures/Enabled=false"]


def arguments(out):
    args = [BINARY, PRM, "--set", "Output directory=" + out]
    for s in SETS:
        args += ["--set", s]
    return args


def history(out):
    return read_csv(os.path.join(out, "point_history.csv"))


def same_steps(a, b, tolerance):
    """(the same step numbers, each time within @tolerance relative, the
    largest relative time difference) of two time_steps.csv tables; False
    when either is empty. The step numbers are integers and compared
    exactly; the times are sums of step lengths, compared relatively."""
    worst = max([abs(x["time"] - y["time"]) / abs(x["time"]) for x, y in zip(a, b)], default=0.0)
    return (len(a) > 0 and [r["step"] for r in a] == [r["step"] for r in b]
            and worst <= tolerance), worst


def relative_difference(a, b):
    """Largest difference of displacements and stresses, each relative to
    the largest magnitude of its column (s_xy is zero on the x axis but
    for round-off)."""
    worst = 0.0
    for k in ("u_x", "s_xx", "s_yy", "s_xy", "s_zz"):
        scale = max(max(abs(x[k]) for x in a), max(abs(x["s_xx"]) for x in a) if k[0] == "s" else 0)
        worst = max(worst, max(abs(x[k] - y[k]) for x, y in zip(a, b)) / scale)
    return worst


reference = os.path.abspath("output_restart_reference")
run(PRM, reference, 1, SETS)
ref_rows = history(reference)
ref_steps = read_csv(os.path.join(reference, "time_steps.csv"))
check(len(ref_steps) > 40 and open(os.path.join(reference, "checkpoint.current")).read().strip()
      == "checkpoint-%06d" % len(ref_steps),
      "reference: %d steps, final checkpoint checkpoint-%06d" % (len(ref_steps), len(ref_steps)))

killed = os.path.abspath("output_restart_killed")
shutil.rmtree(killed, ignore_errors=True)
process = subprocess.Popen(arguments(killed), stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL, env=env())
pointer = os.path.join(killed, "checkpoint.current")
deadline = time.time() + 600
# Polled every millisecond: in a Release build ten steps of this mesh take
# a few tens of milliseconds.
while time.time() < deadline and process.poll() is None:
    try:
        if open(pointer).read().strip() == "checkpoint-000020":
            break
    except OSError:
        pass
    time.sleep(0.001)
process.send_signal(signal.SIGKILL)
process.wait()
current = open(pointer).read().strip()
final = "checkpoint-%06d" % len(ref_steps)
check("checkpoint-000020" <= current < final,
      "killed with %s as the last complete checkpoint (before the final %s)" % (current, final))
# What a kill in the middle of the next checkpoint leaves: a directory
# without its state, never named by checkpoint.current.
half = os.path.join(killed, "checkpoint-000099")
shutil.copytree(os.path.join(killed, current), half)
os.remove(os.path.join(half, "state.txt"))
with open(os.path.join(half, "mesh"), "wb") as f:
    f.write(b"\0" * 16)

resumed = run(PRM, killed, 2, SETS + ["Time stepping/Resume=true"], keep_output=True)
check("Resumed from %s/%s" % (killed, current) in open(os.path.join(killed, "log.txt")).read(),
      "resumed on 2 ranks from %s, not from the half-written directory" % current)
rows = history(killed)
steps = read_csv(os.path.join(killed, "time_steps.csv"))
difference = relative_difference(ref_rows, rows)
check(len(rows) == len(ref_rows) and difference <= 1e-10,
      "resumed run = uninterrupted run: %d rows, largest relative difference %.1e"
      % (len(rows), difference))
# The step lengths double (or are kept) by comparing the creep estimate
# with the tolerance, and after a rejection scale with (tol / estimate)^(1/3):
# they follow the solution, which 2 ranks reproduce to the solver's
# tolerance (Solver/Relative tolerance, 1e-10; the answer above to 1e-10),
# so the times are compared to 1e-10 relative, not bit for bit (that is
# also above the 1e-11 a last-digit flip of time_steps.csv's 12 digits is).
equal, worst = same_steps(steps, ref_steps, 1e-10)
check(equal, "the same %d steps at the same times (%d in the reference; largest relative "
      "difference %.1e, allowed 1e-10)" % (len(steps), len(ref_steps), worst))
check(not os.path.exists(half), "the half-written checkpoint directory is removed")

# Continue the finished run to a later end time.
longer = SETS + ["Time stepping/Resume=true", "Time stepping/End time=12",
                 "Time stepping/Output times=0, 0.5, 1, 2, 5, 10, 12"]
run(PRM, killed, 1, longer, keep_output=True)
rows = history(killed)
check(len(rows) == len(ref_rows) + 3 and relative_difference(ref_rows, rows[:len(ref_rows)]) <= 1e-10
      and abs(rows[-1]["time"] - 12) < 1e-12,
      "continued to t = 12 s: the earlier rows unchanged, three more at t = 12")
# 4. The predictor's solutions go through the checkpoint.
amg = [s for s in SETS if "global refinement" not in s] + [
    "Solver/Type=AMG", "Mesh refinement/Initial global refinement=1"]
to_two = ["Time stepping/End time=2", "Time stepping/Output times=0, 0.5, 1, 2"]
straight = os.path.abspath("output_restart_amg_straight")
run(PRM, straight, 1, amg + to_two)
continued = os.path.abspath("output_restart_amg_continued")
run(PRM, continued, 1, amg + ["Time stepping/End time=1", "Time stepping/Output times=0, 0.5, 1"])
run(PRM, continued, 1, amg + to_two + ["Time stepping/Resume=true"], keep_output=True)
a = read_csv(os.path.join(straight, "time_steps.csv"))
b = read_csv(os.path.join(continued, "time_steps.csv"))
at_one = [r["step"] for r in b if abs(r["time"] - 1) < 1e-9]
after = [(r["step"], r["time"], r["linear_iterations"]) for r in b if r["time"] > 1 + 1e-9]
# The same build on the same rank: with the predictor's solutions restored
# both runs do the same arithmetic, so the CG iterations must be equal (a
# lost predictor changes the first step's). The times to 2e-11 relative:
# time_steps.csv writes 12 significant digits (a last-digit flip is up to
# 1e-11 relative; twice that allowed), and the step lengths follow the
# solution, which agrees to 1e-12 here (asserted below).
times_equal, worst = same_steps(a, b, 2e-11)
check(at_one and after and times_equal and
      [r["linear_iterations"] for r in a] == [r["linear_iterations"] for r in b],
      "CG + AMG, resumed at t = 1 s (step %s): the same %d steps (%d), times (largest relative "
      "difference %.1e, allowed 2e-11) and CG iterations as the run straight to 2 s (after the "
      "resume: %s iterations)"
      % ("%d" % at_one[0] if at_one else "?", len(a), len(b), worst,
         ", ".join("%d" % x[2] for x in after[:4])))
difference = relative_difference(history(straight), history(continued))
check(len(history(straight)) == len(history(continued)) and difference <= 1e-12,
      "CG + AMG, resumed at t = 1 s: the answer of the run straight to 2 s to %.1e" % difference)
finish()

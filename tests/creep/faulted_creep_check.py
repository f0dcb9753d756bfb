"""A frictional fault over a creeping layer whose law is non-linear
(issue 51, item 4: one time loop treats the rock laws and the fault laws
together). tests/faults/viscoelastic_fault.prm: an elastic layer over a
Maxwell layer (eta = 1e21 Pa s, Maxwell time 940 yr) cut by a normal
fault, under 20 MPa of tension held for 10 kyr (tests/faults/
viscoelastic_check.py verifies it with the linear Maxwell law).

Each time step's Newton iteration linearises the rock law at the iterate
and solves the linearised body with the fault laws exactly (the sliding
solver's semi-smooth Newton, warm-started from the last iterate and its
states); the next iterate re-linearises the rock. Verified here:

1. The same law through the Newton path: the viscous layer as
   `Rheology = visco-elasto-plastic` with the same linear `Viscosity`,
   and again with a linear dislocation creep (n = 1, A = 1/(2 eta): the
   invariant form's linear law), gives the Maxwell run's fault (slip and
   tractions at every output time) and its time steps to 1e-7 relative:
   each step's Newton iteration ends at 1e-8 of the stress (its
   tolerance) and the sliding solves at 1e-9 of the load; the Maxwell
   run's own restart agrees to 1e-8 (viscoelastic_check.py). Both with
   the normal spring and with exact normal contact (the body then assembled
   by the contact solver itself, with the rock law's tangent).
2. Power-law creep, n = 3 (A = 4e-36 Pa^-3 s^-1, no activation energy:
   an effective viscosity of 1e21 Pa s near 11 MPa), on adaptive meshes
   refined in the time loop. Without body forces the model is homogeneous
   of degree one in the stress: elasticity, the fault's springs, Coulomb
   friction and the isostatic base are linear or positively homogeneous,
   and the overburden term of the friction law scales with its densities.
   Scaling the load, the fault's densities and the stress by lambda, the
   creep rate A tau^n grows by lambda^n, the elastic rates by lambda, so
   the solution is that of time lambda^(n-1) t (d sigma/dt =
   C (d eps/dt - A f(sigma)) with sigma = lambda s, t = T / lambda^(n-1)):
   slip(t; 2 P) = 2 slip(4 t; P), tractions likewise. Asserted at every
   output time to 1e-7 relative (the runs' time steps are the same in
   scaled time: the first is given, 25 and 6.25 yr, the error control and
   every tolerance but the sliding solver's 1 kPa excess shear are
   relative), with the slip growing by more than half in the run (a law
   that did not creep, or crept with another exponent, fails: a time
   factor of 2^(n-1) is exact only for this n).
3. Newton converges quadratically in every step of the power-law run
   (the order estimate >= 1.7, at most 8 iterations a step).
4. The power-law run stopped at 5 kyr and resumed on 2 ranks ends with
   the uninterrupted run's fault and time steps (1e-8 relative).
"""
import csv
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import (check, check_quadratic_newton, finish, read_csv, run,  # noqa: E402
                       step_newton_residuals)

PRM = "faults/viscoelastic_fault.prm"
ETA = 1e21
N, A = 3.0, 4e-36
OUTPUTS = 5
VEP = ["Materials/viscous/Rheology=visco-elasto-plastic"]
LINEAR_CREEP = VEP + ["Materials/viscous/Viscosity=0",
                      "Materials/viscous/Dislocation creep prefactor=%.17g" % (1 / (2 * ETA)),
                      "Materials/viscous/Dislocation creep stress exponent=1"]
POWER_LAW = VEP + ["Materials/viscous/Viscosity=0",
                   "Materials/viscous/Dislocation creep prefactor=%g" % A,
                   "Materials/viscous/Dislocation creep stress exponent=%g" % N,
                   "Mesh refinement/Initial global refinement=2",
                   "Mesh refinement/Strategy=adaptive",
                   "Mesh refinement/Number of cycles=2",
                   "Mesh refinement/Maximum level=4",
                   "Time stepping/Refinement interval=10",
                   "Time stepping/First time step=25"]
# The load, the friction law's densities (2911 and 1000 by default) and
# the time scaled for item 2: lambda = 2, time by lambda^(n - 1) = 4.
SCALED = ["Loads/Tractions/left/Normal traction=4e7",
          "Faults/fault/Lithostatic density=5822",
          "Faults/fault/Pore fluid density=2000",
          "Time stepping/End time=2500",
          "Time stepping/First time step=6.25",
          "Time stepping/Output times=0, 250, 500, 1250, 2500"]
EXACT = ["Faults/fault/Normal stiffness=exact"]
# The first step given: by default it is the Maxwell time's fraction,
# which a law without a Viscosity does not have.
FIRST = ["Time stepping/First time step=40"]


def fault_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def faults(output):
    return [fault_rows(os.path.join(output, "fault-%05d.csv" % k)) for k in range(OUTPUTS)]


def difference(a, b, factor=1.0):
    """The largest difference of @factor times the fault files @a against
    @b, over every output time: of slip relative to the largest slip, of
    the tractions relative to the largest normal traction."""
    worst = 0.0
    for fa, fb in zip(a, b):
        if len(fa) != len(fb) or len(fa) == 0:
            return math.inf
        scale = factor * max(abs(float(r["slip"])) for r in fa)
        stress = factor * max(abs(float(r["normal_traction"])) for r in fa)
        for x, y in zip(fa, fb):
            worst = max(worst, abs(factor * float(x["slip"]) - float(y["slip"])) / scale,
                        abs(factor * float(x["shear_traction"]) - float(y["shear_traction"]))
                        / stress,
                        abs(factor * float(x["normal_traction"]) - float(y["normal_traction"]))
                        / stress)
    return worst


def step_times(output):
    return [r["time"] for r in read_csv(os.path.join(output, "time_steps.csv"))]


def same_steps(a, b, tolerance):
    ta, tb = step_times(a), step_times(b)
    return len(ta) == len(tb) > 0 and all(abs(x - y) <= tolerance * max(abs(x), 1.0)
                                          for x, y in zip(ta, tb))


def log_text(output):
    with open(os.path.join(output, "log.txt")) as f:
        return f.read()


def linear_laws():
    """Item 1."""
    for contact, extra in (("normal spring", []), ("exact contact", EXACT)):
        suffix = "_exact" if extra else ""
        maxwell = os.path.abspath("output_faulted_creep_maxwell" + suffix)
        run(PRM, maxwell, 1, extra + FIRST)
        for label, sets in (("linear Viscosity", VEP), ("dislocation creep n = 1", LINEAR_CREEP)):
            out = os.path.abspath("output_faulted_creep_%s%s" % (label.split()[0], suffix))
            run(PRM, out, 1, extra + FIRST + sets)
            worst = difference(faults(maxwell), faults(out))
            steps = same_steps(maxwell, out, 1e-7)
            check(worst <= 1e-7 and steps,
                  "%s, visco-elasto-plastic with a %s = Maxwell: fault at %d output times to "
                  "%.1e relative (allowed 1e-7), %d and %d time steps, the same times: %s"
                  % (contact, label, OUTPUTS, worst, len(step_times(maxwell)),
                     len(step_times(out)), steps))
            newton = step_newton_residuals(log_text(out))
            check(max(len(r) for r in newton) <= 2,
                  "%s, %s: a linear law ends each step's Newton iteration at its first "
                  "re-linearisation (at most 2 iterations; largest %d over %d steps)"
                  % (contact, label, max(len(r) for r in newton), len(newton)))


def power_law():
    """Items 2-4."""
    out = os.path.abspath("output_faulted_creep_power_law")
    run(PRM, out, 1, POWER_LAW)
    power = faults(out)
    slips = [max(float(r["slip"]) for r in f) for f in power]
    sliding = [sum(r["state"] == "sliding" for r in f) for f in power]
    check(all(b > a for a, b in zip(slips, slips[1:])) and slips[-1] > 1.5 * slips[0] > 0,
          "power law n = 3: the largest slip grows by more than half as the lower layer creeps: "
          "%s m at 0, 1, 2, 5, 10 kyr (%s of %s fault points sliding)"
          % (["%.4f" % s for s in slips], sliding, [len(f) for f in power]))
    scaled = os.path.abspath("output_faulted_creep_power_law_scaled")
    run(PRM, scaled, 1, POWER_LAW + SCALED)
    worst = difference(power, faults(scaled), 2.0)
    check(worst <= 1e-7,
          "power law n = 3: twice the load = twice the stress and slip at a quarter of the time "
          "(2^(n-1)): fault at %d output times to %.1e relative (allowed 1e-7)"
          % (OUTPUTS, worst))
    check_quadratic_newton("power law n = 3 with a frictional fault",
                           step_newton_residuals(log_text(out)))
    partial = os.path.abspath("output_faulted_creep_power_law_restart")
    window = ["Time stepping/End time=5000", "Time stepping/Output times=0, 1000, 2000, 5000"]
    run(PRM, partial, 1, POWER_LAW + window)
    run(PRM, partial, 2, POWER_LAW + ["Time stepping/Resume=true"], keep_output=True)
    worst = difference([fault_rows(os.path.join(out, "fault.csv"))],
                       [fault_rows(os.path.join(partial, "fault.csv"))])
    steps = same_steps(out, partial, 1e-8)
    check(worst <= 1e-8 and steps,
          "power law n = 3: run to 5 kyr, resumed on 2 ranks to 10 kyr = uninterrupted run "
          "(fault to %.1e relative, allowed 1e-8; %d and %d steps, the same times: %s)"
          % (worst, len(step_times(out)), len(step_times(partial)), steps))


linear_laws()
power_law()
finish()

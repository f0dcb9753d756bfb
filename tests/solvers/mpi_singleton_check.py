"""The `lithostress` launcher (app/launcher.cc) starts a run that no MPI
launcher started as an isolated Open MPI singleton with the self transport
only, instead of Open MPI's defaults (a forked runtime daemon and every
network transport). What is checked:

- the transports the run opens (Open MPI's own report with
  OMPI_MCA_btl_base_verbose): `self` only through the launcher, others
  too without it (here `tcp` and `vader`), and the user's own
  OMPI_MCA_btl kept;
- the results do not change by a digit: the cantilever's convergence table
  through the launcher equals the one of the program started directly,
  with Open MPI's defaults (the same arithmetic on the same values);
- a 2-rank run under mpirun, which names the ranks in the environment, is
  left alone: with `self` as its only transport its ranks could not talk,
  and it agrees with the serial run to the solver tolerance.
"""
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import lithotest
from lithotest import *

# The settings the launcher makes, and the variables by which it knows a
# launcher's rank, as the environment of a user who made none of them
# (kept below only where a check sets them itself).
for name in ("OMPI_MCA_ess_singleton_isolated", "OMPI_MCA_pml", "OMPI_MCA_btl",
             "HWLOC_PLUGINS_BLACKLIST", "OMPI_COMM_WORLD_SIZE", "PMIX_RANK",
             "PMI_RANK", "PMI_SIZE"):
    os.environ.pop(name, None)

LAUNCHER = lithotest.BINARY
PROGRAM = os.path.join(os.path.dirname(LAUNCHER), "lithostress-bin")
VERBOSE = {"OMPI_MCA_btl_base_verbose": "10", "LITHOSTRESS_HUGE_PAGES": "off"}
PRM = "cantilever/cantilever.prm"
SETS = ["Mesh refinement/Number of cycles=3", "Solver/Type=AMG"]


def opened(result):
    """The BTL components Open MPI reports as opened."""
    text = result.stdout + result.stderr
    return sorted({line.split("component ")[1].split()[0]
                   for line in text.splitlines()
                   if "components_open: component" in line and "open function successful" in line})


def run_with(binary, output, ranks=1, extra=None):
    lithotest.BINARY = binary
    environment = dict(VERBOSE)
    environment.update(extra or {})
    result = run(PRM, os.path.abspath(output), ranks, SETS, extra_env=environment)
    lithotest.BINARY = LAUNCHER
    return result


through_launcher = run_with(LAUNCHER, "output_singleton_launcher")
check(opened(through_launcher) == ["self"],
      "through the launcher the singleton opens the self transport only: %s"
      % opened(through_launcher))
directly = run_with(PROGRAM, "output_singleton_direct")
check(set(opened(directly)) - {"self"},
      "started directly, Open MPI's defaults open transports between processes too: %s"
      % opened(directly))
users_own = run_with(LAUNCHER, "output_singleton_users_own",
                     extra={"OMPI_MCA_btl": "self,vader"})
check(opened(users_own) == ["self", "vader"],
      "the user's own OMPI_MCA_btl=self,vader is kept: %s" % opened(users_own))

tables = [open(os.path.join(os.path.abspath(o), "convergence.csv")).read()
          for o in ("output_singleton_launcher", "output_singleton_direct")]
check(tables[0] == tables[1] and len(tables[0]) > 0,
      "convergence table identical through the launcher and started directly (%d bytes)"
      % len(tables[0]))

# Under mpirun every rank must reach the others: the launcher leaves the
# transports to Open MPI, and the answer is the serial one to the solver
# tolerance (relative 1e-8 of the largest displacement; CG stops at 1e-10
# of the residual on these 3 cycles).
parallel = run_with(LAUNCHER, "output_singleton_mpirun", ranks=2)
check("tcp" in opened(parallel) or "vader" in opened(parallel),
      "under mpirun the ranks open a transport between processes: %s" % opened(parallel))
serial_rows = read_csv(os.path.join(os.path.abspath("output_singleton_launcher"), "convergence.csv"))
parallel_rows = read_csv(os.path.join(os.path.abspath("output_singleton_mpirun"), "convergence.csv"))
check(len(serial_rows) == len(parallel_rows) == 3, "three cycles on 1 and 2 ranks")
columns = [c for c in serial_rows[0] if c.startswith("u_")]
scale = max(abs(r[c]) for r in serial_rows for c in columns)
for column in columns:
    worst = max(abs(a[column] - b[column]) for a, b in zip(serial_rows, parallel_rows)) / scale
    check(worst < 1e-8, "%s on 2 ranks equals 1 rank to %.1e of the largest displacement"
          % (column, worst))
finish()

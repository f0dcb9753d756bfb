#!/usr/bin/python3
"""The subduction-zone experiments of thesis chapter 7, number by number.

Runs the eleven configurations of thesis §7.3-7.6 / issue 17, each elastic
and after 5 Myr of visco-elastic relaxation:

  density              prm/subduction_density.prm       (§7.3)
  slab_pull_90 ... _27 prm/subduction_slab_pull.prm     (§7.4, dips 90,
                                                          63.43, 45, 26.57)
  coupling_1e10 ... _1e9 prm/subduction_coupling.prm    (§7.5, k_s 1e10,
                                                          5e9, 1e9 N/m)
  basal_shear          prm/subduction_basal_shear.prm   (§7.6.1)
  thermal              prm/subduction_thermal.prm       (§7.6.2, alpha
                                                          linear)
  thermal_volumetric   the same, alpha read as volumetric

and writes

  OUTDIR/subduction_comparison.csv  experiment,quantity,ours,thesis,unit:
      one row for every number thesis §7.3-7.6 quotes (thesis empty where
      the thesis gives none, e.g. after 5 Myr for §7.5 and §7.6), and one for
      each goal of the .prm files (regional means over boxes), converged by
      goal-oriented adaptive refinement from the coarse mesh until they
      change by < 1 % while the DoFs double
  OUTDIR/<name>_elastic/, OUTDIR/<name>_5Myr/  each run's output
  OUTDIR/figures/  thesis-style figures: principal-stress crosses per run,
      deviatoric sigma_xx against depth at the left and right edges for the
      coupling series (thesis figures 7.66, 7.67), slip along the plate
      boundary, the Griffith failure regions

Stresses are the stripped (relative) stresses the thesis discusses; edge
profiles are the vertical lines 1 km inside the edges. How each quantity
is measured is in the `quantity` text and in doc/subduction.md.

Usage: reproduce_subduction.py OUTDIR [--binary PATH] [--global-refinement N]
                               [--only NAME,...] [--elastic-only] [--ranks N]
                               [--width 920] [--measure-only] [--set ENTRY=VALUE]
(--set entries go to every run: pick the runs they concern by --only.)
"""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu_reader  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# The right edge (Geometry/Subduction zone/Width; --width changes it).
WIDTH_KM = 920.0
TRENCH_KM = 500.0
PLATE_BOUNDARY_BASE_KM = 659.7
# The overlying plate's surface (Geometry/Subduction zone defaults): 10 km
# deep at the trench, rising linearly to the land height 0 at the coast.
TRENCH_DEPTH_KM = 10.0
COAST_KM = 575.0
# The depths of a 5 km thick top row's Gauss points (0.211 and 0.789 of
# it): where the thesis's program reads stresses near the surface (its
# STRESS and FAIL work per Gauss point; §7.6.2's failure "at 1 km depth"
# is the upper one).
THESIS_GAUSS_DEPTHS_KM = (1.06, 3.94)
A_A_KM = 659.7 - 484.3


def profiles():
    """x [km] of the stress-depth profiles: 1 km inside the edges, and
    across the section."""
    return "1, 300, 500, 580, 659.7, 780, %g" % (WIDTH_KM - 1)

from subduction_configurations import CONFIGS  # noqa: E402


def run(binary, prm, directory, sets, elastic, ranks, measure_only=False):
    """Run one configuration into directory (measure_only: only read the
    statistics of an earlier run there); return its statistics."""
    if measure_only:
        with open(os.path.join(directory, "statistics.json")) as f:
            return json.load(f)
    if os.path.isdir(directory):
        shutil.rmtree(directory)
    command = ([binary] if ranks == 1 else
               ["mpirun", "-np", str(ranks), binary])
    command += [os.path.join(ROOT, "prm", prm),
                "--set", "Output directory=" + directory,
                "--set", "Output/Stress-depth profiles=" + profiles(),
                "--set", "Geometry/Subduction zone/Width=%g" % WIDTH_KM,
                "--set", "Output/Points per profile=191"]
    for s in sets:
        command += ["--set", s]
    if elastic:
        command += ["--set", "Time stepping/Enabled=false"]
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    result = subprocess.run(command, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, env=env)
    if result.returncode != 0:
        sys.exit("%s failed:\n%s" % (" ".join(command), result.stdout[-3000:]))
    with open(os.path.join(directory, "statistics.json")) as f:
        return json.load(f)


def profile(directory, x_km):
    """The stress-depth profile at x [km]: dict of numpy columns."""
    with open(os.path.join(directory, "stress_depth_x%g.csv" % x_km)) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) if r[k] not in ("", "nan") else math.nan
                         for r in rows]) for k in rows[0]}


def land_surface_y(x):
    """y [m] of the overlying plate's surface at x [m] (x > trench)."""
    rise = np.clip((x / 1e3 - TRENCH_KM) / (COAST_KM - TRENCH_KM), 0.0, 1.0)
    return -TRENCH_DEPTH_KM * 1e3 * (1.0 - rise)


def largest_compression_at_depth(n, x_range_km, depth_km):
    """The largest horizontal compression [Pa] at @p depth_km below the
    overlying plate's surface over @p x_range_km: sigma_xx interpolated
    linearly in depth along each vertical line of output nodes that
    brackets that depth."""
    inside = (n["x"] > x_range_km[0] * 1e3) & (n["x"] < x_range_km[1] * 1e3)
    x, s = n["x"][inside], n["stress"][:, 0][inside]
    depth = (land_surface_y(x) - n["y"][inside]) / 1e3
    # The nodes by vertical line, each line by depth.
    order = np.lexsort((depth, x))
    x, depth, s = x[order], depth[order], s[order]
    starts = np.flatnonzero(np.r_[True, x[1:] != x[:-1], True])
    largest = 0.0
    for a, b in zip(starts[:-1], starts[1:]):
        if b - a >= 2 and depth[a] <= depth_km <= depth[b - 1]:
            largest = max(largest, -np.interp(depth_km, depth[a:b], s[a:b]))
    return largest


def band_mean(p, key, top_km, bottom_km):
    """Mean of column key over depths top..bottom [km] (trapezoids)."""
    d = p["depth"] / 1e3
    inside = (d >= top_km - 1e-9) & (d <= bottom_km + 1e-9)
    return float(np.trapz(p[key][inside], d[inside]) /
                 (d[inside][-1] - d[inside][0]))


def peak(p, key, sign, top_km=0, bottom_km=1e9):
    """(value, depth km) of the largest sign*p[key] within a depth band."""
    d = p["depth"] / 1e3
    inside = np.where((d >= top_km) & (d <= bottom_km))[0]
    i = inside[np.argmax(sign * p[key][inside])]
    return float(p[key][i]), float(d[i])


def nodes_at(directory):
    """The nodal fields of the run's last output: the last refinement
    cycle of an elastic run, the last output time of a visco-elastic one."""
    series = vtu_reader.read_pvd(directory)
    return vtu_reader.read_pvtu(series[-1][1])


def force_balance(directory):
    with open(os.path.join(directory, "force_balance.csv")) as f:
        return {r["name"]: (float(r["F_x"]), float(r["F_y"]))
                for r in csv.DictReader(f)}


MPA = 1e-6


class Table:
    def __init__(self):
        self.rows = []

    def add(self, experiment, quantity, ours, thesis, unit):
        self.rows.append((experiment, quantity, ours, thesis, unit))

    def write(self, path):
        with open(path, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["experiment", "quantity", "ours", "thesis", "unit"])
            for e, q, o, t, u in self.rows:
                w.writerow([e, q, "%.4g" % o if o is not None else "",
                            "" if t is None else t, u])


def goals(directory):
    """The goals of the run's last refinement cycle (convergence.csv) and
    the cycles and DoFs it took: ({goal: value [Pa]}, cycles, dofs)."""
    with open(os.path.join(directory, "convergence.csv")) as f:
        rows = list(csv.DictReader(f))
    fixed = {"cycle", "cells", "dofs"}
    last = rows[-1]
    values = {k: float(v) for k, v in last.items()
              if k not in fixed and not k.startswith("change_") and v != ""
              and not k.startswith("rel_err_")}
    return values, len(rows), int(last["dofs"])


# The goals (Mesh refinement/Goals of the .prm files): what each box is.
GOAL_TEXT = {
    "right_crust": "mean horizontal deviatoric stress in the continental "
                   "crust at the right edge, 5-10 km (x 900-920 km)",
    "trench": "mean vertical stress in the subducting lid beneath the "
              "trench (x 470-500 km, 20-40 km deep)",
    "rise": "mean vertical stress beneath the outer rise (x 250-400 km, "
            "5-35 km deep)",
    "left_lid": "mean horizontal stress in the subducting lid at the left "
                "edge (x 0-20 km, 0-30 km below the sea floor)",
    "right_upper_crust": "mean horizontal stress in the continental upper "
                         "crust at the right edge (x 900-920 km, 0-10 km)",
    "right_mantle": "mean horizontal stress in the continental mantle at "
                    "the right edge (x 900-920 km, 35-95 km)",
    "forearc": "mean horizontal stress near the surface of the forearc (x "
               "600-700 km, top 2 km)",
    "fault_base_top": "mean horizontal stress above the plate boundary's "
                      "base (x 650-670 km, top 5 km)",
    "fault_base_deep": "mean horizontal stress beneath it (x 650-670 km, "
                       "15-35 km)",
    "right_plate": "mean horizontal stress in the overlying plate at the "
                   "right edge (x 900-920 km, whole thickness)",
    "left_plate": "mean horizontal stress in the subducting plate at the "
                  "left edge (x 0-20 km, whole thickness)",
    "anomaly_top": "mean horizontal stress at the top above the anomaly "
                   "(x 770-790 km, top 5 km)",
    "anomaly_base": "mean horizontal stress at the base above the anomaly "
                    "(x 770-790 km, 75-95 km)",
}


def measure(table, name, directory, stage, thesis):
    """Add the rows of one run (stage 'elastic' or '5Myr'); thesis maps a
    quantity key to the thesis's number (None: not quoted)."""
    left, right = profile(directory, 1), profile(directory, WIDTH_KM - 1)
    exp = "%s (%s)" % (name, stage)

    def add(key, text, value, unit):
        table.add(exp, text, value, thesis.get(key), unit)

    # The goals, converged by goal-oriented refinement (the .prm files stop
    # the cycles once they change by < 1 % while the DoFs double): the
    # elastic response's (the cycles come before the time loop).
    values, cycles, dofs = goals(directory) if stage == "elastic" else ({}, 0, 0)
    texts = dict(GOAL_TEXT)
    if name.startswith("coupling"):
        # The coupling series' crust goal is sigma_xx over 0-35 km.
        texts["right_crust"] = ("mean horizontal stress in the continental "
                                "crust at the right edge (x 900-920 km, "
                                "0-35 km)")
    for goal, value in values.items():
        add("goal_" + goal, "goal %s: %s (%d adaptive cycles, %d DoFs)"
            % (goal, texts.get(goal, goal), cycles, dofs), value * MPA,
            "MPa")

    if name == "density" or name.startswith("slab_pull"):
        value, depth = peak(right, "deviatoric_xx", +1, 0, 35)
        add("right_tension", "largest horizontal deviatoric tension in the "
            "continental crust at the right edge", value * MPA, "MPa")
        add("right_tension_depth", "its depth below the surface", depth,
            "km")
    if name == "density" and stage == "elastic":
        n = nodes_at(directory)
        syy = n["stress"][:, 4]
        # The trench point, where the ocean floor, the land and the plate
        # boundary meet, is a corner of the stress field: its own value
        # grows without bound under refinement, so the largest tension is
        # taken at least 10 km from it.
        below_trench = (n["x"] > 480e3) & (n["x"] < 700e3) & \
            (n["material_id"] <= 2) & \
            (np.hypot(n["x"] - TRENCH_KM * 1e3, n["y"] + 10e3) > 10e3)
        add("trench_tension", "largest vertical tension in the subducting "
            "plate near the trench (x 480-700 km, > 10 km from the trench "
            "point)", syy[below_trench].max() * MPA, "MPa")
        rise = (n["x"] > 250e3) & (n["x"] < 400e3)
        add("rise_compression", "largest vertical compression beneath the "
            "outer rise (x 250-400 km)", -syy[rise].min() * MPA, "MPa")
    if name.startswith("slab_pull") or name.startswith("coupling"):
        fb = force_balance(directory)
        pull = [v for k, v in fb.items() if k.startswith("slab pull")][0]
        if stage == "elastic":
            add("pull", "vertical slab pull balancing the model's loads",
                -pull[1], "N/m")
            add("pull_stress", "vertical slab-pull stress over A-A "
                "(175.4 km)", -pull[1] / (A_A_KM * 1e3) * MPA, "MPa")
            upthrust = [v for k, v in fb.items() if k.startswith("tractions")]
            add("upthrust", "net upthrust of the trench and outer-rise "
                "pressures", upthrust[0][1], "N/m")
        # Regional stresses: the elastic layers' mean sigma_xx at the edges.
        add("left_regional", "mean horizontal stress in the subducting "
            "plate's elastic lid at the left edge (0-30 km below the sea "
            "floor)", band_mean(left, "sigma_xx", 0, 30) * MPA, "MPa")
        add("right_regional", "mean horizontal stress in the continental "
            "upper crust at the right edge (0-10 km)",
            band_mean(right, "sigma_xx", 0, 10) * MPA, "MPa")
        # The continental layers' means, of sigma_xx and of its deviatoric
        # part (the thesis's §7.5 numbers are deviatoric stresses, its
        # figures 7.66, 7.67).
        for column, suffix, what in (("sigma_xx", "", "horizontal stress"),
                                     ("deviatoric_xx", "_dev", "horizontal deviatoric stress")):
            for layer, top, bottom in (("crust", 0, 35), ("mantle", 35, 95)):
                add("right_%s%s" % (layer, suffix), "mean %s in the continental %s at the right "
                    "edge (%d-%d km)" % (what, layer, top, bottom),
                    band_mean(right, column, top, bottom) * MPA, "MPa")
    if name == "slab_pull_90":
        n = nodes_at(directory)
        lid = (n["material_id"] <= 1) & (n["x"] < TRENCH_KM * 1e3)
        add("bending", "largest bending stress |sigma_xx| in the subducting "
            "plate's elastic lid seaward of the trench",
            np.abs(n["stress"][:, 0][lid]).max() * MPA, "MPa")
        top = (n["x"] < 440e3) & (n["y"] > -5e3 - 1.0)
        x, uy = n["x"][top], n["displacement"][:, 1][top]
        add("flexure", "distance of the up-flexure's crest seaward of the "
            "trench", TRENCH_KM - x[np.argmax(uy)] / 1e3, "km")
    if name.startswith("coupling"):
        n = nodes_at(directory)
        land = (n["x"] > TRENCH_KM * 1e3) & (n["x"] < 700e3) & \
            (n["y"] >= land_surface_y(n["x"]) - 1e3 - 1.0)
        add("surface_compression", "largest near-surface horizontal "
            "compression between the trench and 700 km (top 1 km)",
            -n["stress"][:, 0][land].min() * MPA, "MPa")
        add("surface_compression_gauss", "largest horizontal compression "
            "between the trench and 700 km at the thesis's top-row Gauss "
            "points (1.06 and 3.94 km below the surface)",
            max(largest_compression_at_depth(n, (TRENCH_KM, 700), d)
                for d in THESIS_GAUSS_DEPTHS_KM) * MPA, "MPa")
        with open(os.path.join(directory, "fault_summary.json")) as f:
            summary = json.load(f)
        add("newton", "Newton iterations (last solve)",
            summary.get("nonlinear_iterations"), "")
    if name == "basal_shear":
        column = profile(directory, 659.7)
        add("left_regional", "mean horizontal stress in the subducting plate "
            "at the left edge (whole thickness)",
            band_mean(left, "sigma_xx", 0, 90) * MPA, "MPa")
        add("right_regional_all", "mean horizontal stress in the overlying "
            "plate at the right edge (whole thickness)",
            band_mean(right, "sigma_xx", 0, 95) * MPA, "MPa")
        add("fault_base_surface", "horizontal stress at the surface above "
            "the plate boundary's base (x = 659.7 km)",
            column["sigma_xx"][0] * MPA, "MPa")
        add("fault_base_compression", "largest horizontal compression "
            "beneath it (0-35 km)",
            -peak(column, "sigma_xx", -1, 0, 35)[0] * MPA, "MPa")
        add("fault_base_compression_all", "largest horizontal compression "
            "beneath it over the whole column (0-95 km)",
            -peak(column, "sigma_xx", -1, 0, 95)[0] * MPA, "MPa")
        # The overlying plate left of the load (thesis §7.6.1 and its
        # thermal section: "the overlying plate" seaward of the basal
        # shear): the wedge above the plate boundary at x = 580 km (the
        # boundary's circle, centre (445.456, -305) km, radius 300 km, is
        # 36.8 km below sea level there).
        wedge = profile(directory, 580)
        boundary_y = -(305.0 - math.sqrt(300.0 ** 2 - (580.0 - 445.456) ** 2))
        boundary_depth = wedge["y"][0] / 1e3 - boundary_y
        add("left_of_load", "mean horizontal stress in the overlying plate "
            "left of the load (x = 580 km, above the plate boundary)",
            band_mean(wedge, "sigma_xx", 0, boundary_depth) * MPA, "MPa")
        add("right_surface", "horizontal stress at the surface at the right "
            "edge", right["sigma_xx"][0] * MPA, "MPa")
        # Above 85 km: the base's corner at the right edge, where the shear
        # traction meets the roller, is singular.
        add("right_tension", "largest horizontal tension beneath it "
            "(0-85 km)", peak(right, "sigma_xx", +1, 0, 85)[0] * MPA, "MPa")
    if name.startswith("thermal"):
        column = profile(directory, 780)
        add("top_tension", "horizontal stress at the top of the crust above "
            "the anomaly's centre (x = 780 km)",
            column["sigma_xx"][0] * MPA, "MPa")
        add("base_compression", "largest horizontal compression above the "
            "anomaly's centre", -peak(column, "sigma_xx", -1)[0] * MPA, "MPa")
        failed = column["griffith_C"] <= 0
        add("failure_depth", "depth of Griffith failure above the anomaly's "
            "centre", float(column["depth"][failed].max() / 1e3)
            if failed.any() else 0.0, "km")
        add("left_regional", "mean horizontal stress in the subducting plate "
            "at the left edge (whole thickness)",
            band_mean(left, "sigma_xx", 0, 90) * MPA, "MPa")
    if name in ("basal_shear",) or name.startswith("thermal"):
        n = nodes_at(directory)
    if name.startswith("thermal"):
        # The flexure's axis (thesis §7.6.2: "a flexure of the overlying
        # plate with an axis at the centre of the temperature anomaly"):
        # where the bending's tension at the land surface (y = 0) peaks.
        land = (np.abs(n["y"]) < 1.0) & (n["x"] > 600e3)
        axis = n["x"][land][np.argmax(n["stress"][:, 0][land])]
        add("flexure_axis", "x of the largest horizontal tension at the land "
            "surface (the flexure's axis)", float(axis / 1e3), "km")
    if name in ("basal_shear",) or name.startswith("thermal"):
        failed = n["griffith_degree_of_failure"] <= 0
        away = failed & (np.abs(n["x"] - 780e3) > 60e3) \
            if name.startswith("thermal") else failed
        add("failed_area", "output nodes failed by the Griffith criterion" +
            (" more than 60 km from the anomaly's centre"
             if name.startswith("thermal") else ""),
            float(away.sum()), "nodes")


# The thesis's numbers (§7.3-7.6) by experiment, stage and quantity key.
THESIS = {
    ("density", "elastic"): {"right_tension": 22.5, "goal_right_crust": 22.5,
                             "right_tension_depth": "5-10",
                             "trench_tension": 100, "rise_compression": 10},
    ("density", "5Myr"): {"right_tension": 38, "right_tension_depth": "5-10"},
    ("slab_pull_90", "elastic"): {"right_tension": 31.5,
                                  "goal_right_crust": 31.5,
                                  "right_tension_depth": "5-10",
                                  "pull": 8.95e12, "pull_stress": 51.05,
                                  "upthrust": 3.95e12, "bending": 110,
                                  "flexure": 75},
    ("basal_shear", "elastic"): {"left_regional": -4,
                                 "right_regional_all": -4,
                                 "fault_base_surface": 4,
                                 "fault_base_compression": 10,
                                 "right_surface": 0, "right_tension": 14,
                                 "left_of_load": -4, "failed_area": 0},
    ("basal_shear", "5Myr"): {"failed_area": 0},
    ("thermal", "elastic"): {"flexure_axis": 780, "top_tension": 62, "base_compression": 130,
                             "failure_depth": 1, "failed_area": 0,
                             "left_regional": -60},
    ("thermal_volumetric", "elastic"): {"top_tension": 62,
                                        "base_compression": 130,
                                        "failure_depth": 1, "failed_area": 0,
                                        "left_regional": -60},
}


def comparisons(table, rows):
    """Rows that compare runs: the dip series and the coupling series."""
    def value(exp, text_start):
        for e, q, o, t, u in rows:
            if e == exp and q.startswith(text_start):
                return o
        return None

    def change(before, after, text_start):
        """value(after) - value(before), or None if either is missing."""
        a, b = value(before, text_start), value(after, text_start)
        return None if None in (a, b) else b - a

    for stage in ("elastic", "5Myr"):
        a = value("slab_pull_63 (%s)" % stage, "mean horizontal stress in the "
                  "subducting")
        b = value("slab_pull_27 (%s)" % stage, "mean horizontal stress in the "
                  "subducting")
        c = value("slab_pull_63 (%s)" % stage, "mean horizontal stress in the "
                  "continental upper")
        d = value("slab_pull_27 (%s)" % stage, "mean horizontal stress in the "
                  "continental upper")
        if None not in (a, b, c, d):
            table.add("slab_pull 63.43 -> 26.57 (%s)" % stage,
                      "growth of the regional horizontal tension in the "
                      "subducting plate's lid", b - a,
                      115 if stage == "elastic" else None, "MPa")
            table.add("slab_pull 63.43 -> 26.57 (%s)" % stage,
                      "growth of the regional horizontal compression in the "
                      "overlying plate's upper crust", c - d,
                      115 if stage == "elastic" else None, "MPa")
        locked = "slab_pull_45 (%s)" % stage
        weak = "coupling_1e9 (%s)" % stage
        for key, text, thesis in (
                ("mean horizontal stress in the continental mantle",
                 "fall of the overlying plate's regional compression in the "
                 "mantle (right edge, 35-95 km), locked -> k_s 1e9", 40),
                ("mean horizontal stress in the continental crust",
                 "fall of the overlying plate's regional compression in the "
                 "crust (right edge, 0-35 km), locked -> k_s 1e9", 17.5)):
            lo, we = value(locked, key), value(weak, key)
            if None not in (lo, we):
                table.add("coupling (%s)" % stage, text, we - lo,
                          thesis if stage == "elastic" else None, "MPa")
        # What the down-dip slab pull's horizontal component adds to the
        # overlying plate (thesis §7.5.2: "< 5 MPa" of compression at
        # k_s 1e9): deviatoric layer means against the 90 degree run, which
        # has none.
        vertical = "slab_pull_90 (%s)" % stage
        elastic = stage == "elastic"
        for layer, depths, thesis in (("crust", "0-35 km", 17.5), ("mantle", "35-95 km", 40)):
            key = "mean horizontal deviatoric stress in the continental " + layer
            fall = change(locked, weak, key)
            if fall is not None:
                table.add("coupling (%s)" % stage, "fall of the overlying plate's "
                          "regional deviatoric compression in the %s (right edge, %s), "
                          "locked -> k_s 1e9" % (layer, depths), fall,
                          thesis if elastic else None, "MPa")
            for run_name, label in ((locked, "locked"), (weak, "k_s 1e9")):
                added = change(run_name, vertical, key)
                if added is not None:
                    table.add("coupling (%s)" % stage,
                              "compression the 45 degree slab pull adds to the "
                              "overlying plate's %s (deviatoric, right edge, %s), "
                              "%s, against the 90 degree run" % (layer, depths, label),
                              added, "< 5" if (elastic and label != "locked"
                                               and layer == "crust") else None, "MPa")
        rise = change(locked, weak, "mean horizontal stress in the subducting plate's elastic lid")
        if rise is not None:
            table.add("coupling (%s)" % stage, "rise of the subducting lid's regional "
                      "tension (left edge, 0-30 km below the sea floor), locked -> k_s 1e9",
                      rise, 40 if elastic else None, "MPa")
        added = change("density (%s)" % stage, "slab_pull_90 (%s)" % stage,
                       "largest horizontal deviatoric tension in the continental crust")
        if added is not None:
            table.add("slab_pull 90 - density (%s)" % stage, "right-edge tension the vertical "
                      "slab pull adds to the lateral density model's", added,
                      10 if elastic else None, "MPa")
        we = value(weak, "mean horizontal stress in the continental crust")
        if we is not None:
            table.add("coupling (%s)" % stage, "regional compression left in "
                      "the overlying plate's crust at k_s 1e9 (right edge, "
                      "0-35 km)", -we, "< 5" if stage == "elastic" else None,
                      "MPa")
        s = value(weak, "largest near-surface horizontal compression")
        if s is not None:
            table.add("coupling (%s)" % stage, "near-surface compression "
                      "between the trench and 700 km at k_s 1e9", s,
                      25 if stage == "elastic" else None, "MPa")
        s = value(weak, "largest horizontal compression between the trench "
                  "and 700 km at the thesis's top-row Gauss points")
        if s is not None:
            table.add("coupling (%s)" % stage, "the same at the thesis's top-row "
                      "Gauss points (1.06 and 3.94 km deep)", s,
                      25 if stage == "elastic" else None, "MPa")


def figures(outdir, names, stages):
    """Thesis-style figures from the runs (matplotlib)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig_dir = os.path.join(outdir, "figures")
    os.makedirs(fig_dir, exist_ok=True)
    # Each run's own figures.
    for name in names:
        for stage in stages:
            d = os.path.join(outdir, "%s_%s" % (name, stage))
            for png in ("principal_stresses.png", "fault.png",
                        "stress_depth_x%g.png" % (WIDTH_KM - 1), "stress_depth_x1.png"):
                if os.path.exists(os.path.join(d, png)):
                    shutil.copy(os.path.join(d, png), os.path.join(
                        fig_dir, "%s_%s_%s" % (name, stage, png)))
    series = [("locked", "slab_pull_45"), ("k_s 1e10 N/m", "coupling_1e10"),
              ("k_s 5e9 N/m", "coupling_5e9"), ("k_s 1e9 N/m", "coupling_1e9")]
    series = [s for s in series if s[1] in names]
    for stage in stages:
        if len(series) > 1:
            fig, axes = plt.subplots(1, 2, figsize=(10, 6), sharey=True)
            for ax, x, title in ((axes[0], WIDTH_KM - 1, "right edge, overlying plate "
                                  "(thesis fig. 7.66)"),
                                 (axes[1], 1, "left edge, subducting plate "
                                  "(thesis fig. 7.67)")):
                for label, name in series:
                    p = profile(os.path.join(outdir, "%s_%s" % (name, stage)),
                                x)
                    ax.plot(p["deviatoric_xx"] * MPA, p["depth"] / 1e3,
                            label=label)
                ax.axvline(0, color="k", lw=0.5)
                ax.set_title(title, fontsize=10)
                ax.set_xlabel("horizontal deviatoric stress [MPa] "
                              "(tension > 0)")
            axes[0].set_ylabel("depth [km]")
            axes[0].invert_yaxis()
            axes[0].legend()
            fig.suptitle("45° slab pull, plate coupling (§7.5), %s" %
                         ("elastic" if stage == "elastic" else
                          "after 5 Myr"))
            fig.tight_layout()
            fig.savefig(os.path.join(fig_dir, "coupling_%s_edges.png" % stage),
                        dpi=120)
            plt.close(fig)
            fig, ax = plt.subplots(figsize=(8, 4.5))
            for label, name in series[1:]:
                with open(os.path.join(outdir, "%s_%s" % (name, stage),
                                       "fault.csv")) as f:
                    rows = list(csv.DictReader(f))
                ax.plot([float(r["s"]) / 1e3 for r in rows],
                        [float(r["slip"]) for r in rows], label=label)
            ax.set_xlabel("distance along the plate boundary from the trench "
                          "[km]")
            ax.set_ylabel("slip [m] (< 0: the slab slides down-dip\nbeneath the overlying plate)")
            ax.set_title("Slip along the plate boundary, %s" %
                         ("elastic" if stage == "elastic" else "after 5 Myr"))
            ax.legend()
            fig.tight_layout()
            fig.savefig(os.path.join(fig_dir, "coupling_%s_slip.png" % stage),
                        dpi=120)
            plt.close(fig)
        # Griffith failure regions of every run.
        fig, axes = plt.subplots(len(names), 1, figsize=(10, 1.9 * len(names)),
                                 sharex=True, squeeze=False)
        for ax, name in zip(axes[:, 0], names):
            d = os.path.join(outdir, "%s_%s" % (name, stage))
            n = nodes_at(d)
            c = n["griffith_degree_of_failure"]
            ax.scatter(n["x"] / 1e3, n["y"] / 1e3, s=0.2, c="0.85",
                       rasterized=True)
            f = c <= 0
            ax.scatter(n["x"][f] / 1e3, n["y"][f] / 1e3, s=2, c="tab:red",
                       rasterized=True)
            ax.set_ylabel(name, rotation=0, ha="right", fontsize=8)
            ax.set_aspect(2)
            ax.set_yticks([-95, -50, 0])
            ax.tick_params(labelsize=7)
        axes[-1, 0].set_xlabel("x [km]")
        fig.suptitle("Griffith failure (red: C <= 0; y [km] exaggerated 2x), %s" %
                     ("elastic" if stage == "elastic" else "after 5 Myr"))
        fig.tight_layout(rect=(0, 0, 1, 0.985))
        fig.savefig(os.path.join(fig_dir, "griffith_%s.png" % stage), dpi=110)
        plt.close(fig)


def main():
    global WIDTH_KM
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir")
    parser.add_argument("--binary", default=os.path.join(ROOT, "build",
                                                         "lithostress"))
    parser.add_argument("--global-refinement", type=int, default=None)
    parser.add_argument("--only", default="")
    parser.add_argument("--elastic-only", action="store_true")
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--measure-only", action="store_true",
                        help="measure the runs already in OUTDIR again, "
                             "without running them")
    parser.add_argument("--set", action="append", default=[],
                        help="an extra --set for every run (repeatable), e.g. "
                             "\"Faults/plate_boundary/Overburden depth from=sea level\"")
    parser.add_argument("--width", type=float, default=WIDTH_KM,
                        help="x of the right edge [km] (the thesis does not state it)")
    args = parser.parse_args()
    WIDTH_KM = args.width
    os.makedirs(args.outdir, exist_ok=True)
    outdir = os.path.abspath(args.outdir)
    only = [s for s in args.only.split(",") if s]
    configs = [c for c in CONFIGS if not only or c[0] in only]
    stages = ["elastic"] + ([] if args.elastic_only else ["5Myr"])
    table = Table()
    timing = []
    for name, prm, sets in configs:
        sets = list(sets) + args.set
        if args.global_refinement is not None:
            sets.append("Mesh refinement/Initial global refinement=%d" %
                        args.global_refinement)
        for stage in stages:
            d = os.path.join(outdir, "%s_%s" % (name, stage))
            stats = run(args.binary, prm, d, sets, stage == "elastic",
                        args.ranks, args.measure_only)
            timing.append((name, stage, stats))
            measure(table, name, d, stage, THESIS.get((name, stage), {}))
            print("%-20s %-8s done" % (name, stage), flush=True)
    comparisons(table, list(table.rows))
    table.write(os.path.join(outdir, "subduction_comparison.csv"))
    with open(os.path.join(outdir, "runs.json"), "w") as f:
        json.dump([{"experiment": n, "stage": s, "statistics": st}
                   for n, s, st in timing], f, indent=1)
    figures(outdir, [c[0] for c in configs], stages)
    print("wrote", os.path.join(outdir, "subduction_comparison.csv"))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Graben widths of thesis §6.1.7 (tables 6.3 and 6.4).

Runs the plane normal fault (prm/normal_fault.prm: 1000 km, fault dipping
63.43 degrees at the centre, left edge pulled, right edge on rollers, fluid
base, Coulomb friction mu = 0.1) with elastic layers 10, 20 and 30 km thick
under the tensions of table 6.3, and writes

  OUTDIR/graben_widths.csv   thickness_km,tension_MPa,distance_km,sliding_depth_km
  OUTDIR/graben_widths_comparison.csv   the same with the thesis's width
      (table 6.3), the thin-beam bounds pi alpha/4 and pi alpha/2 (table
      6.4), the crest of the flexure on the downthrown side, the throw and
      the Newton iterations
  OUTDIR/graben_widths.png   widths against tension, ours and the thesis's

distance_km is the model's tensile_failure_distance_m: the distance from
the fault's surface trace to where the top surface of the downthrown side
is most likely to fail in tension (the largest sigma_1 there; thesis: "the
distance from the fault where failure is most likely to occur").

The fault's stiffnesses are the thesis's element stiffnesses (5e10 and
1e15 N/m) for fault elements of length l = h / (2 sin 63.43 deg): two
elements along the fault, the layout assumed for the 20 km model
(doc/faults.md).

Usage: graben_widths.py OUTDIR [--binary PATH] [--global-refinement N]
                               [--ranks N]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Table 6.3 (thesis FE, km) and the tensions it was run at (MPa).
THESIS = {10: {20: 22.5, 30: 26.5, 40: 27.2, 50: 27.2},
          20: {20: 15.0, 40: 15.0, 60: 45.5, 80: 45.5},
          30: {40: 10.5, 60: 17.0, 80: 57.5}}
E, NU, RHO_F, G = 0.85e11, 0.25, 2900.0, 9.81
DIP = math.atan(2.0)


def flexural_parameter(h_m):
    """alpha = (4D / (rho_f g))^(1/4) of the thin plate on a fluid [m]."""
    D = E * h_m ** 3 / (12 * (1 - NU ** 2))
    return (4 * D / (RHO_F * G)) ** 0.25


def crest_distance(profile, surface_x, direction):
    """Distance from the trace to the first local maximum of u_y on the
    downthrown (hanging-wall) side [m], or NaN."""
    side = sorted((r for r in profile if direction * (r["x"] - surface_x) > 1.0),
                  key=lambda r: abs(r["x"] - surface_x))
    for a, b, c in zip(side, side[1:], side[2:]):
        if b["u_y"] >= a["u_y"] and b["u_y"] > c["u_y"]:
            return abs(b["x"] - surface_x)
    return float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("outdir")
    parser.add_argument("--binary", default=os.path.join(ROOT, "build", "lithostress"))
    parser.add_argument("--global-refinement", type=int, default=4)
    parser.add_argument("--ranks", type=int, default=1)
    args = parser.parse_args()
    if not os.path.exists(args.binary):
        subprocess.run(["bash", os.path.join(ROOT, "scripts", "build.sh"), "build", "Release"],
                       check=True)
    os.makedirs(args.outdir, exist_ok=True)
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    rows = []
    for h, tensions in THESIS.items():
        for tension in sorted(tensions):
            out = os.path.abspath(os.path.join(args.outdir, "h%d_t%d" % (h, tension)))
            element = h / (2 * math.sin(DIP))
            cmd = [args.binary, os.path.join(ROOT, "prm", "normal_fault.prm"),
                   "--set", "Output directory=" + out,
                   "--set", "Geometry/Layered box/Layer interfaces=0, -%g" % h,
                   "--set", "Faults/fault/Thesis element length=%.6f" % element,
                   "--set", "Loads/Tractions/left/Normal traction=%g" % (tension * 1e6),
                   "--set", "Mesh refinement/Initial global refinement=%d" % args.global_refinement,
                   "--set", "Output/Write ParaView files=false",
                   "--set", "Output/Figures/Enabled=false"]
            if args.ranks > 1:
                cmd = ["mpirun", "-np", str(args.ranks)] + cmd
            print("graben widths: %d km layer, %d MPa ..." % (h, tension), flush=True)
            result = subprocess.run(cmd, capture_output=True, text=True, env=env)
            if result.returncode != 0:
                sys.stderr.write(result.stdout[-2000:] + result.stderr)
                sys.exit("graben_widths.py: the run for %d km, %d MPa failed (see %s)"
                         % (h, tension, out))
            with open(os.path.join(out, "fault_summary.json")) as f:
                summary = json.load(f)
            with open(os.path.join(out, "surface_profile.csv")) as f:
                profile = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
            alpha = flexural_parameter(h * 1e3)
            rows.append({
                "thickness_km": h, "tension_MPa": tension,
                "distance_km": summary["tensile_failure_distance_m"] / 1e3,
                "sliding_depth_km": summary["sliding_depth_m"] / 1e3,
                "thesis_distance_km": tensions[tension],
                "thin_beam_min_km": math.pi * alpha / 4e3,
                "thin_beam_max_km": math.pi * alpha / 2e3,
                "crest_km": crest_distance(profile, 500e3, 1) / 1e3,
                "throw_m": summary["throw_m"],
                "nonlinear_iterations": summary["nonlinear_iterations"]})
            r = rows[-1]
            print("  distance %.2f km (thesis %.1f), sliding to %.2f km, crest %.2f km, throw %.2f m"
                  % (r["distance_km"], r["thesis_distance_km"], r["sliding_depth_km"],
                     r["crest_km"], r["throw_m"]), flush=True)
    columns = ["thickness_km", "tension_MPa", "distance_km", "sliding_depth_km"]
    with open(os.path.join(args.outdir, "graben_widths.csv"), "w") as f:
        f.write(",".join(columns) + "\n")
        for r in rows:
            f.write("%d,%d,%.4f,%.4f\n" % tuple(r[c] for c in columns))
    with open(os.path.join(args.outdir, "graben_widths_comparison.csv"), "w") as f:
        keys = list(rows[0].keys())
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join("%.6g" % r[k] for k in keys) + "\n")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("graben_widths.py: matplotlib missing, no figure")
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for h, colour in zip(THESIS, ("tab:blue", "tab:orange", "tab:green")):
        mine = [r for r in rows if r["thickness_km"] == h]
        t = [r["tension_MPa"] for r in mine]
        ax.plot(t, [r["distance_km"] for r in mine], "o-", color=colour,
                label="%d km layer: lithostress" % h)
        ax.plot(t, [r["thesis_distance_km"] for r in mine], "s--", color=colour, mfc="none",
                label="%d km layer: thesis table 6.3" % h)
        ax.axhspan(mine[0]["thin_beam_min_km"], mine[0]["thin_beam_max_km"], color=colour,
                   alpha=0.08)
        ax.axhline(mine[0]["thin_beam_min_km"], color=colour, lw=0.6, ls=":")
    ax.set_xlabel("applied tension [MPa]")
    ax.set_ylabel("graben width: distance of the most likely\n"
                  "tensile failure from the fault [km]")
    ax.set_title("Graben widths (thesis §6.1.7); bands: thin-beam theory (table 6.4)",
                 fontsize=10)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(os.path.join(args.outdir, "graben_widths.png"), dpi=130)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The effective elastic thickness of a bent plate (doc/plasticity.md): fit
the deflection of a broken thin elastic plate on a fluid foundation to the
top-surface displacement of a lithostress run, at every output time.

  outer_rise_fit.py OUTPUT_DIRECTORY [--elastic DIRECTORY] [--window KM]

A plate broken at the trench (x = x_t) under an end load and an end moment
deflects as w(x) = exp(-d/alpha) (c1 cos(d/alpha) + c2 sin(d/alpha)),
d = |x - x_t| (Turcotte & Schubert 2014, section 3.17, with both end
conditions free), with the flexural parameter alpha = (4 D/(drho g))^(1/4):
for each alpha the amplitudes c1, c2 follow by linear least squares, and
alpha minimises the misfit (golden section on log alpha, after a scan).
D gives the effective elastic thickness
Te = (12 (1 - nu^2) D / E)^(1/3) with E, nu of the first material and
drho = the fluid density of Loads/Isostatic restoring force in the run's
parameters.prm. The fit takes the surface from the trench to --window km
(default: 4 alpha of the first scan's best fit, at most the plate).

The moment-curvature Te (McNutt 1984) at each stress-depth profile of the
last output: M = integral of sigma_xx (y - y_mid) dy, kappa from a
parabola through the surface within 10 km, Te = (12 (1 - nu^2)(-M/kappa)/
E)^(1/3), into outer_rise_moment_curvature.csv (x_m, moment_N,
curvature_per_m, Te_m).

Writes, into OUTPUT_DIRECTORY: outer_rise_fit.csv (file, time_Myr, alpha_m,
Te_m, rms_misfit_m, max_deflection_m, trench_deflection_m,
forebulge_distance_m, forebulge_height_m) and outer_rise_deflection.png
(the deflection at each output time with its fitted thin plate, and with
--elastic the deflection of the same plate run elastic, fitted too).
A missing or malformed input is one line on stderr and exit status 1."""
import argparse
import csv
import glob
import math
import os
import re
import sys

import numpy as np

GRAVITY = 9.81
SECONDS_PER_MYR = 365.25 * 86400 * 1e6


class FitError(Exception):
    pass


def read_prm(path):
    """The set entries of a parameter file as {"Section/Entry": value}."""
    entries, stack = {}, []
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        raise FitError("%s: %s" % (path, e.strerror))
    for line in lines:
        line = line.split("#", 1)[0].strip()
        if line.startswith("subsection "):
            stack.append(line[len("subsection "):].strip())
        elif line == "end" and stack:
            stack.pop()
        elif line.startswith("set "):
            key, _, value = line[4:].partition("=")
            entries["/".join(stack + [key.strip()])] = value.strip()
    return entries


def plate_constants(directory):
    """E, nu of the first material and the foundation's density from the
    run's parameters.prm."""
    path = os.path.join(directory, "parameters.prm")
    prm = read_prm(path)
    names = [n.strip() for n in prm.get("Materials/Names", "").split(",") if n.strip()]
    if not names:
        raise FitError("%s: no Materials/Names" % path)
    try:
        young = float(prm["Materials/%s/Young's modulus" % names[0]])
        poisson = float(prm.get("Materials/%s/Poisson's ratio" % names[0], "0.25"))
        fluid = float(prm["Loads/Isostatic restoring force/Fluid densities"].split(",")[0])
    except (KeyError, ValueError) as e:
        raise FitError("%s: needs the first material's Young's modulus and a fluid density (%s)"
                       % (path, e))
    return young, poisson, fluid


def read_profile(path):
    """x and u_y [m] of a surface_profile CSV, sorted by x."""
    try:
        rows = list(csv.DictReader(open(path)))
    except OSError as e:
        raise FitError("%s: %s" % (path, e.strerror))
    if not rows or "x" not in rows[0] or "u_y" not in rows[0]:
        raise FitError("%s: needs the columns x and u_y and at least one row" % path)
    try:
        pairs = sorted((float(r["x"]), float(r["u_y"])) for r in rows)
    except ValueError as e:
        raise FitError("%s: %s" % (path, e))
    return [p[0] for p in pairs], [p[1] for p in pairs]


def amplitudes(d, w, alpha):
    """Least-squares c1, c2 and the rms misfit for one alpha."""
    a11 = a12 = a22 = b1 = b2 = 0.0
    basis = []
    for di, wi in zip(d, w):
        e = math.exp(-di / alpha)
        f1, f2 = e * math.cos(di / alpha), e * math.sin(di / alpha)
        basis.append((f1, f2))
        a11 += f1 * f1
        a12 += f1 * f2
        a22 += f2 * f2
        b1 += f1 * wi
        b2 += f2 * wi
    det = a11 * a22 - a12 * a12
    if det <= 0:
        return 0.0, 0.0, math.inf
    c1 = (a22 * b1 - a12 * b2) / det
    c2 = (a11 * b2 - a12 * b1) / det
    misfit = sum((c1 * f1 + c2 * f2 - wi) ** 2 for (f1, f2), wi in zip(basis, w))
    return c1, c2, math.sqrt(misfit / len(w))


def fit_alpha(d, w, lower, upper):
    """The alpha in [lower, upper] with the smallest misfit: a scan of 60
    values on log alpha, then golden sections around the best."""
    logs = [math.log(lower) + k * (math.log(upper) - math.log(lower)) / 59 for k in range(60)]
    costs = [amplitudes(d, w, math.exp(v))[2] for v in logs]
    k = min(range(60), key=costs.__getitem__)
    a, b = logs[max(k - 1, 0)], logs[min(k + 1, 59)]
    g = (math.sqrt(5) - 1) / 2
    for _ in range(60):
        c, e = b - g * (b - a), a + g * (b - a)
        if amplitudes(d, w, math.exp(c))[2] < amplitudes(d, w, math.exp(e))[2]:
            b = e
        else:
            a = c
    return math.exp(0.5 * (a + b))


def fit(x, uy, trench, window):
    """The thin-plate fit of one profile: alpha, c1, c2, misfit."""
    d_all = [abs(xi - trench) for xi in x]
    span = max(d_all)
    alpha = fit_alpha(d_all, uy, 5e3, span)
    limit = min(window if window else 4 * alpha, span)
    chosen = [(di, wi) for di, wi in zip(d_all, uy) if di <= limit]
    d, w = [c[0] for c in chosen], [c[1] for c in chosen]
    if len(d) < 5:
        raise FitError("fewer than 5 surface points within the fit window")
    alpha = fit_alpha(d, w, 5e3, span)
    c1, c2, misfit = amplitudes(d, w, alpha)
    return alpha, c1, c2, misfit


def describe(x, uy, trench, young, poisson, fluid, window):
    alpha, c1, c2, misfit = fit(x, uy, trench, window)
    rigidity = fluid * GRAVITY * alpha ** 4 / 4
    te = (12 * (1 - poisson ** 2) * rigidity / young) ** (1 / 3)
    # The forebulge: the highest point of the profile seaward of the trench.
    k = max(range(len(uy)), key=uy.__getitem__)
    near = min(range(len(x)), key=lambda i: abs(x[i] - trench))
    return {"alpha_m": alpha, "Te_m": te, "rms_misfit_m": misfit,
            "max_deflection_m": -min(uy), "trench_deflection_m": -uy[near],
            "forebulge_distance_m": abs(x[k] - trench), "forebulge_height_m": uy[k],
            "c1": c1, "c2": c2}


def output_times(directory):
    """Output index -> time [Myr] from solution.pvd."""
    times = {}
    path = os.path.join(directory, "solution.pvd")
    if os.path.exists(path):
        for m in re.finditer(r'timestep="([^"]+)"[^>]*file="solution_(\d+)\.pvtu"', open(path).read()):
            times[int(m.group(2))] = float(m.group(1)) / SECONDS_PER_MYR
    return times


def profiles_of(directory):
    files = sorted(glob.glob(os.path.join(glob.escape(directory), "surface_profile-*.csv")))
    if not files:
        files = [os.path.join(directory, "surface_profile.csv")]
    times = output_times(directory)
    result = []
    for f in files:
        m = re.search(r"surface_profile-(\d+)\.csv$", f)
        result.append((f, times.get(int(m.group(1)), math.nan) if m else math.nan))
    return result


def moment_curvature(directory, x, uy, young, poisson):
    """Te from the bending moment and the curvature at each stress-depth
    profile of the run (McNutt 1984): M = integral of sigma_xx (y - y_mid)
    dy over the profile (the plate carries no net horizontal force, so the
    reference height does not matter), kappa = d2 u_y/dx2 of the top
    surface (a parabola through the surface points within 10 km), D = -M /
    kappa, Te = (12 (1 - nu^2) D / E)^(1/3). Returns [(x, M, kappa, Te)]."""
    result = []
    for path in sorted(glob.glob(os.path.join(glob.escape(directory), "stress_depth_x*.csv"))):
        rows = list(csv.DictReader(open(path)))
        if not rows:
            continue
        y = [float(r["y"]) for r in rows]
        sxx = [float(r["sigma_xx"]) for r in rows]
        order = sorted(range(len(y)), key=y.__getitem__)
        y, sxx = [y[i] for i in order], [sxx[i] for i in order]
        mid = 0.5 * (y[0] + y[-1])
        moment = sum(0.5 * (sxx[i] * (y[i] - mid) + sxx[i + 1] * (y[i + 1] - mid)) * (y[i + 1] - y[i])
                     for i in range(len(y) - 1))
        x0 = float(rows[0]["x"])
        near = [(xi - x0, wi) for xi, wi in zip(x, uy) if abs(xi - x0) <= 10e3]
        if len(near) < 3:
            continue
        # The least-squares parabola's second coefficient: kappa = 2c.
        c = np.polyfit([si for si, _ in near], [wi for _, wi in near], 2)[0]
        kappa = 2 * c
        rigidity = -moment / kappa if kappa != 0 else math.nan
        te = (12 * (1 - poisson ** 2) * rigidity / young) ** (1 / 3) if rigidity > 0 else math.nan
        result.append((x0, moment, kappa, te))
    return sorted(result)


def curve(x, trench, r):
    return [math.exp(-abs(xi - trench) / r["alpha_m"]) *
            (r["c1"] * math.cos(abs(xi - trench) / r["alpha_m"]) +
             r["c2"] * math.sin(abs(xi - trench) / r["alpha_m"])) for xi in x]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory")
    parser.add_argument("--elastic", help="output directory of the same plate run elastic")
    parser.add_argument("--trench", type=float, default=0.0, help="x of the trench [km] (default 0)")
    parser.add_argument("--window", type=float, default=0.0, help="fit window from the trench [km]")
    args = parser.parse_args()
    try:
        young, poisson, fluid = plate_constants(args.directory)
        trench, window = 1e3 * args.trench, 1e3 * args.window
        rows, drawn = [], []
        for path, time in profiles_of(args.directory):
            x, uy = read_profile(path)
            r = describe(x, uy, trench, young, poisson, fluid, window)
            rows.append(dict(file=os.path.basename(path), time_Myr=time, **r))
            drawn.append(("t = %.3g Myr" % time if math.isfinite(time) else os.path.basename(path), x, uy, r))
        elastic = None
        if args.elastic:
            x, uy = read_profile(os.path.join(args.elastic, "surface_profile.csv"))
            r = describe(x, uy, trench, young, poisson, fluid, window)
            rows.append(dict(file="elastic: " + os.path.basename(args.elastic.rstrip("/")),
                             time_Myr=math.nan, **r))
            elastic = (x, uy, r)
    except FitError as e:
        sys.stderr.write("outer_rise_fit: error: %s\n" % e)
        return 1
    columns = ["file", "time_Myr", "alpha_m", "Te_m", "rms_misfit_m", "max_deflection_m",
               "trench_deflection_m", "forebulge_distance_m", "forebulge_height_m"]
    out = os.path.join(args.directory, "outer_rise_fit.csv")
    with open(out, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(columns)
        for r in rows:
            writer.writerow([r[c] if isinstance(r[c], str) else "%.6g" % r[c] for c in columns])
    # Te from the moment and curvature at the profiles (the last output).
    x_last, uy_last = drawn[-1][1], drawn[-1][2]
    pairs = moment_curvature(args.directory, x_last, uy_last, young, poisson)
    with open(os.path.join(args.directory, "outer_rise_moment_curvature.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["x_m", "moment_N", "curvature_per_m", "Te_m"])
        for row in pairs:
            writer.writerow(["%.6g" % v for v in row])
    for x0, moment, kappa, te in pairs:
        print("moment-curvature at x = %5.0f km: M = %.3g N, curvature %.3g 1/m, Te = %.1f km"
              % (x0 / 1e3, moment, kappa, te / 1e3))
    for r in rows:
        print("%-28s t = %6.3g Myr: alpha = %6.1f km, Te = %5.1f km, rms misfit %.3g m, "
              "trench deflection %.0f m, forebulge %.0f m at %.0f km"
              % (r["file"], r["time_Myr"], r["alpha_m"] / 1e3, r["Te_m"] / 1e3, r["rms_misfit_m"],
                 r["trench_deflection_m"], r["forebulge_height_m"], r["forebulge_distance_m"] / 1e3))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write("outer_rise_fit: no matplotlib (apt install python3-matplotlib): no figure\n")
        return 0
    fig, ax = plt.subplots(figsize=(9, 4.8))
    colours = plt.cm.viridis([k / max(1, len(drawn) - 1) for k in range(len(drawn))])
    for (label, x, uy, r), colour in zip(drawn, colours):
        km = [xi / 1e3 for xi in x]
        ax.plot(km, uy, "-", color=colour, linewidth=2,
                label="%s (fit: Te = %.1f km, \u03b1 = %.0f km)" % (label, r["Te_m"] / 1e3, r["alpha_m"] / 1e3))
        ax.plot(km, curve(x, trench, r), "--", color=colour, linewidth=1)
    if elastic:
        x, uy, r = elastic
        km = [xi / 1e3 for xi in x]
        ax.plot(km, uy, "-", color="#d62728", linewidth=1.5,
                label="elastic plate (fit: Te = %.1f km, \u03b1 = %.0f km)" % (r["Te_m"] / 1e3, r["alpha_m"] / 1e3))
        ax.plot(km, curve(x, trench, r), "--", color="#d62728", linewidth=1)
    ax.axhline(0, color="black", linewidth=0.5)
    ax.set_xlabel("x [km] (trench at %.0f km)" % (trench / 1e3))
    ax.set_ylabel("vertical displacement of the top [m]")
    ax.set_title("outer rise: deflection (solid) and fitted broken thin plates (dashed)", fontsize=10)
    ax.grid(True, linewidth=0.3)
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    png = os.path.join(args.directory, "outer_rise_deflection.png")
    fig.savefig(png, dpi=150)
    print("outer_rise_fit: wrote %s and %s" % (out, png))
    return 0


if __name__ == "__main__":
    sys.exit(main())

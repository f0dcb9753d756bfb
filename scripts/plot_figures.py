#!/usr/bin/python3
"""Make the figures of a lithostress run from the CSV files in its output
directory; the PNGs are written next to them.

  plot_figures.py OUTPUT_DIRECTORY [--debug]

The simulator calls this at the end of a run; it can also be run by hand.
Every input is optional: a figure is made when its data exist, and one line
"plot_figures: wrote PATH" is printed per figure.

  input (SI: m, Pa)                  columns (by name)              figure
  figures.json                       length_unit, length_scale,     (settings)
                                     title, stress_unit_scale
  mesh_outline.csv                   x0,y0,x1,y1                    (drawn under the crosses)
  principal_stresses.csv             x,y,sigma_1,sigma_2,angle_1    principal_stresses.png
  surface_profile.csv                x,u_x,u_y[,y]                  surface_profile.png
  thin_plate_comparison.csv          quantity,finite_element,       (dashed thin-plate curve
                                     thin_plate  (or x plus a       on surface_profile.png)
                                     column naming "thin_plate")
  stress_depth_<label>.csv           x,y,depth,sigma_xx,sigma_yy,   stress_depth_<label>.png
                                     sigma_xy,sigma_1,sigma_2,
                                     sigma_zz,deviatoric_xx,
                                     griffith_C
  fault.csv                          s,x,y,slip,opening,            fault.png (and the fault
                                     shear_traction,                trace on
                                     normal_traction,state          principal_stresses.png)
  fault-NNNNN.csv (two or more)      s,slip (as fault.csv)          fault_history.png (slip at
                                                                    each output time)
  fault_summary.json with a tip      upper/lower_tip_depth_m        principal_stresses_tips.png
                                                                    (the crosses around the fault)
  principal_stresses.csv with        yielding, deviatoric_xx        yielding_zones.png
  yielding (visco-elasto-plastic)    [tau_II, strength,             (scripts/yielding_figure.py)
                                     temperature]

figures.json, e.g. {"length_unit": "km", "length_scale": 1000.0,
"title": "plate flexure", "stress_unit_scale": 1e6}: length_scale is metres
per plotting unit, stress_unit_scale pascals per plotting unit. Without it the
length unit is Geometry/Length unit of parameters.prm in the same directory
(m or km), else km; stresses are in MPa. angle_1 is the direction of sigma_1
in degrees counter-clockwise from the x axis (tension positive).

principal_stresses.png: a cross per point, two perpendicular bars of length
proportional to |sigma_1| and |sigma_2| (compression thick blue, tension thin
red with outward arrowheads), the longest 0.8 x the median point spacing,
with equal axis scales, over the mesh outline, and a scale bar. When the
largest |sigma| exceeds 1.3 x the 95th percentile of max(|sigma_1|, |sigma_2|)
over all points (e.g. a singular point load), the bar scale is set by that
percentile instead: its bars are 0.9/1.3 x the spacing, and longer bars are
cut to 1.3 x that and marked by black ticks across their ends (in the key:
"clipped (|sigma| > N)"). A body more
than 8 times as wide as high gets an overview panel plus a panel of a window
8 heights wide around the largest stresses. Points closer than about 0.3 inch
on the page are thinned to one per grid cell (the figure says so).
fault.png: slip along the fault (s from its upper end, points marked by
state: stuck, sliding, open) and, for a frictional fault, |tau|/tau_F with
tau_F = mu max(0, -sigma_n,eff) (mu = Faults/<name>/Friction coefficient of
parameters.prm): 1 where it slides; else the shear and normal tractions.
With several faults, fault_<name>.csv gives fault_<name>.png for each.
stress_depth_*.png: a few singular values (e.g. under a point load) that
would squash a panel are put off scale and named. surface_profile.png:
thin_plate_comparison.csv as written by the simulator (forebulge table) gives
the thin-plate curve through alpha = (forebulge distance)/pi and
w0 = (forebulge height) e^pi, centred on Thin plate comparison/Load position
of parameters.prm (else on the deepest point of the profile).

Uses Debian's python3-matplotlib; exits with a warning (status 0) if it is
missing, so that runs do not fail for want of a plotting library. A malformed
input file is reported on one line naming it, with exit status 1 (the other
figures are still made)."""
import argparse
import csv
import glob
import json
import math
import os
import re
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Rectangle
    import numpy as np
    import yielding_figure
except ImportError:
    sys.stderr.write("plot_figures: matplotlib is missing (apt install python3-matplotlib); no figures made\n")
    sys.exit(0)

DPI = 150
COMPRESSION_COLOUR = "#1f3f99"   # dark blue: thick solid bars
TENSION_COLOUR = "#d62728"       # red: thin bars with outward arrowheads
OUTLINE_COLOUR = "black"
CLIP_COLOUR = "black"            # ticks across the ends of clipped bars
SCALE_PERCENTILE = 95            # |sigma| percentile that sets the bar scale
CLIP_FACTOR = 1.3                # bars are cut at this x the nominal longest bar


class InputError(Exception):
    """A malformed input file: str() is the one-line message naming it."""

    def __init__(self, path, message):
        super().__init__("%s: %s" % (path, message))


# --------------------------------------------------------------------------
# Reading



def save_complete(fig, path):
    """Save @fig as the PNG @path under a temporary name and rename it when
    complete: a run stopped half-way never leaves half a figure."""
    temporary = "%s.part-%d.png" % (path[:-4], os.getpid())
    try:
        fig.savefig(temporary, dpi=DPI)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)

def read_table(path, required, optional=()):
    """Read a CSV file by column name: a dict name -> float array for the
    required and optional columns (an optional column that is missing is
    absent from the dict). Other columns are ignored. Empty fields read as
    nan; any other text that is not a number is an error."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f, skipinitialspace=True)
            if reader.fieldnames is None:
                raise InputError(path, "empty file (no header line)")
            names = [n.strip() for n in reader.fieldnames]
            reader.fieldnames = names
            missing = [c for c in required if c not in names]
            if missing:
                raise InputError(path, "missing column(s) %s (header: %s)"
                                 % (", ".join(missing), ",".join(names)))
            wanted = list(required) + [c for c in optional if c in names]
            values = {c: [] for c in wanted}
            for row in reader:
                line = reader.line_num
                if None in row:
                    raise InputError(path, "line %d has more fields than the header (%d)" % (line, len(names)))
                if any(v is None for v in row.values()):
                    raise InputError(path, "line %d has fewer fields than the header (%d)" % (line, len(names)))
                for c in wanted:
                    text = row[c].strip()
                    if text == "":
                        values[c].append(math.nan)
                        continue
                    try:
                        values[c].append(float(text))
                    except ValueError:
                        raise InputError(path, "line %d, column %s: %r is not a number" % (line, c, text))
    except OSError as e:
        raise InputError(path, e.strerror or str(e))
    except (csv.Error, UnicodeDecodeError) as e:
        raise InputError(path, "not a valid CSV file (%s)" % e)
    return {c: np.array(v, dtype=float) for c, v in values.items()}


def read_prm(path):
    """The entries of a ShortPRM parameter file as {"Section/Sub/Entry": value};
    {} if the file does not exist."""
    entries = {}
    if not os.path.exists(path):
        return entries
    stack = []
    with open(path, errors="replace") as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                stack.append(line[len("subsection "):].strip())
            elif line == "end":
                if stack:
                    stack.pop()
            elif line.startswith("set "):
                key, _, value = line[4:].partition("=")
                entries["/".join(stack + [key.strip()])] = value.strip()
    return entries


STRESS_UNITS = {1.0: "Pa", 1e3: "kPa", 1e6: "MPa", 1e9: "GPa"}
LENGTH_SCALES = {"m": 1.0, "km": 1000.0}


def read_settings(directory):
    """Units and title: from figures.json, else parameters.prm, else km/MPa."""
    path = os.path.join(directory, "figures.json")
    given = {}
    if os.path.exists(path):
        try:
            with open(path) as f:
                given = json.load(f)
        except (OSError, ValueError) as e:
            raise InputError(path, "not valid JSON (%s)" % e)
        if not isinstance(given, dict):
            raise InputError(path, "expected a JSON object")

    def number(key, default):
        v = given.get(key, default)
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not (v > 0 and math.isfinite(v)):
            raise InputError(path, "%s must be a positive number, not %r" % (key, v))
        return float(v)

    unit = given.get("length_unit")
    if unit is not None and not isinstance(unit, str):
        raise InputError(path, "length_unit must be a string")
    if "length_scale" in given:
        scale = number("length_scale", 1000.0)
        if unit is None:
            unit = {1.0: "m", 1000.0: "km"}.get(scale, "%g m" % scale)
    elif unit is not None:
        if unit not in LENGTH_SCALES:
            raise InputError(path, "length_unit %r needs a length_scale" % unit)
        scale = LENGTH_SCALES[unit]
    else:
        prm_unit = read_prm(os.path.join(directory, "parameters.prm")).get("Geometry/Length unit")
        unit = prm_unit if prm_unit in LENGTH_SCALES else "km"
        scale = LENGTH_SCALES[unit]
    stress_scale = number("stress_unit_scale", 1e6)
    stress_unit = given.get("stress_unit", STRESS_UNITS.get(stress_scale, "%g Pa" % stress_scale))
    title = given.get("title", "")
    if not isinstance(title, str):
        raise InputError(path, "title must be a string")
    return {"length_unit": unit, "length_scale": scale, "stress_scale": stress_scale,
            "stress_unit": str(stress_unit), "title": title}


def titled(settings, text):
    return "%s: %s" % (settings["title"], text) if settings["title"] else text


def nice_below(value):
    """The largest 1, 2 or 5 x 10^n not above value (> 0)."""
    e = math.floor(math.log10(value))
    for m in (5, 2, 1):
        if m * 10.0 ** e <= value * (1 + 1e-9):
            return m * 10.0 ** e
    return 10.0 ** e


def ordinal(n):
    """"95th", "99th", "1st", ... for a whole number n."""
    n = int(round(n))
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return "%d%s" % (n, suffix)


def format_number(v):
    return ("%.0f" % v) if v >= 1 else ("%g" % v)


# --------------------------------------------------------------------------
# Principal-stress crosses


def median_spacing(points):
    """Median distance from a point to its nearest (distinct) neighbour;
    estimated from at most 2000 points, in chunks to bound the memory."""
    n = len(points)
    if n < 2:
        return None
    idx = np.arange(n)
    if n > 2000:
        idx = np.random.default_rng(0).choice(n, 2000, replace=False)
    chunk = max(1, int(2e6 // n))
    nearest = []
    for start in range(0, len(idx), chunk):
        rows = idx[start:start + chunk]
        d2 = ((points[rows, None, :] - points[None, :, :]) ** 2).sum(axis=-1)
        d2[d2 == 0] = np.inf  # itself and duplicates
        nearest.append(np.sqrt(d2.min(axis=1)))
    nearest = np.concatenate(nearest)
    nearest = nearest[np.isfinite(nearest)]
    return float(np.median(nearest)) if len(nearest) else None


def thin_to_grid(x, y, x0, y0, cell):
    """Indices of the points kept when thinning to one per square grid cell
    (the point nearest the cell's centre), in their original order."""
    ix, iy = np.floor((x - x0) / cell), np.floor((y - y0) / cell)
    d = (x - x0 - (ix + 0.5) * cell) ** 2 + (y - y0 - (iy + 0.5) * cell) ** 2
    order = np.lexsort((d, iy, ix))
    first = np.ones(len(order), bool)
    first[1:] = (ix[order][1:] != ix[order][:-1]) | (iy[order][1:] != iy[order][:-1])
    return np.sort(order[first])


def cross_segments(x, y, s1, s2, angle, k, barb_max, clip=math.inf, tick=0.0):
    """Bars of length k|sigma| centred on the points, along sigma_1 (angle)
    and sigma_2 (angle + 90 deg): (compression bars, tension bars, arrowhead
    barbs at both ends of the tension bars, pointing outward, clip ticks).
    A bar longer than clip (length units) is cut to clip and gets a
    perpendicular tick of length tick across each end."""
    a = np.radians(angle)
    c, s = np.cos(a), np.sin(a)
    comp, tens, barbs, ticks = [], [], [], []
    spread = math.radians(28)
    for sigma, dx, dy in ((s1, c, s), (s2, -s, c)):
        full = k * np.abs(sigma)
        h = 0.5 * np.minimum(full, clip)
        ends = np.stack([np.stack([x - h * dx, y - h * dy], axis=-1),
                         np.stack([x + h * dx, y + h * dy], axis=-1)], axis=1)
        comp.append(ends[sigma < 0])
        t = sigma > 0
        tens.append(ends[t])
        b = np.minimum(0.45 * h[t], barb_max)
        for sign in (-1, 1):  # both ends; outward direction sign*(dx, dy)
            tip = ends[t][:, 0 if sign < 0 else 1, :]
            ux, uy = sign * dx[t], sign * dy[t]
            for rot in (-spread, spread):
                cr, sr = math.cos(rot), math.sin(rot)
                bx, by = ux * cr - uy * sr, ux * sr + uy * cr
                barbs.append(np.stack([tip, np.stack([tip[:, 0] - b * bx, tip[:, 1] - b * by], axis=-1)], axis=1))
        cut = full > clip
        for end in (0, 1):
            tip = ends[cut][:, end, :]
            px, py = -0.5 * tick * dy[cut], 0.5 * tick * dx[cut]   # half the tick, across the bar
            ticks.append(np.stack([np.stack([tip[:, 0] - px, tip[:, 1] - py], axis=-1),
                                   np.stack([tip[:, 0] + px, tip[:, 1] + py], axis=-1)], axis=1))
    return np.concatenate(comp), np.concatenate(tens), np.concatenate(barbs), np.concatenate(ticks)


def bar_widths(longest_points):
    """Line widths (compression, tension) in points for crosses whose longest
    bar is longest_points long: thinner when the crosses are small, so that
    short bars do not turn into blobs."""
    return (min(2.4, max(0.5, 0.11 * longest_points)), min(0.9, max(0.3, 0.05 * longest_points)))


def draw_crosses(ax, segments, widths):
    comp, tens, barbs, ticks = segments
    ax.add_collection(LineCollection(comp, colors=COMPRESSION_COLOUR, linewidths=widths[0],
                                     capstyle="butt", zorder=3))
    ax.add_collection(LineCollection(tens, colors=TENSION_COLOUR, linewidths=widths[1],
                                     capstyle="butt", zorder=4))
    ax.add_collection(LineCollection(barbs, colors=TENSION_COLOUR, linewidths=widths[1],
                                     capstyle="round", zorder=4))
    if len(ticks):
        ax.add_collection(LineCollection(ticks, colors=CLIP_COLOUR, linewidths=max(0.5, 0.55 * widths[0]),
                                         capstyle="butt", zorder=5))


def draw_outline(ax, outline, width=0.7):
    if outline is not None and len(outline):
        ax.add_collection(LineCollection(outline, colors=OUTLINE_COLOUR, linewidths=width, zorder=2))


def zoom_window(x, magnitude, xmin, xmax, smooth):
    """Centre (within [xmin, xmax]) of the region of largest stress: the
    centre of a sliding window of width smooth (about twice the body's
    height) holding the largest sum of stress magnitudes; of the run of
    equally good centres nearest the largest single value, its middle."""
    centres = np.linspace(xmin, xmax, 2001)
    order = np.argsort(x)
    xs, cum = x[order], np.concatenate([[0.0], np.cumsum(magnitude[order])])
    total = cum[np.searchsorted(xs, centres + smooth / 2, side="right")] - \
        cum[np.searchsorted(xs, centres - smooth / 2, side="left")]
    best = total >= total.max() * (1 - 1e-9)
    peak = x[np.argmax(magnitude)]
    i = np.flatnonzero(best)[np.argmin(np.abs(centres[best] - peak))]
    lo = hi = i
    while lo > 0 and best[lo - 1]:
        lo -= 1
    while hi + 1 < len(best) and best[hi + 1]:
        hi += 1
    return 0.5 * float(centres[lo] + centres[hi])


def bar_scale_stresses(magnitude):
    """(s_ref, s_clip): the |sigma| drawn as the nominal longest bar, and
    the |sigma| above which bars are cut (CLIP_FACTOR x s_ref). s_ref is the
    SCALE_PERCENTILE-th percentile of the magnitudes (of the nonzero ones
    if that is zero), so that a few singular values (e.g. under a point
    load) do not shrink all other crosses to dots; when nothing would be
    cut it is the largest magnitude, as without clipping."""
    finite = magnitude[np.isfinite(magnitude)]
    smax = float(finite.max()) if len(finite) else 0.0
    if smax <= 0:
        return 0.0, 0.0
    ref = float(np.percentile(finite, SCALE_PERCENTILE))
    if ref <= 0:
        ref = float(np.percentile(finite[finite > 0], SCALE_PERCENTILE))
    if smax <= CLIP_FACTOR * ref:
        return smax, smax
    return ref, CLIP_FACTOR * ref


def plot_principal_stresses(directory, settings, window=None, name="principal_stresses.png"):
    """The principal-stress crosses over the body, or within @window
    (x0, x1, y0, y1 in plotting units) into @name."""
    path = os.path.join(directory, "principal_stresses.csv")
    if not os.path.exists(path):
        return None
    t = read_table(path, ["x", "y", "sigma_1", "sigma_2", "angle_1"])
    ok = np.ones(len(t["x"]), bool)
    for v in t.values():
        ok &= np.isfinite(v)
    if window is not None:
        ls = settings["length_scale"]
        ok &= ((t["x"] / ls >= window[0]) & (t["x"] / ls <= window[1])
               & (t["y"] / ls >= window[2]) & (t["y"] / ls <= window[3]))
    if not ok.any():
        sys.stderr.write("plot_figures: %s has no finite rows; no principal-stress figure\n" % path)
        return None
    ls, ss = settings["length_scale"], settings["stress_scale"]
    x, y = t["x"][ok] / ls, t["y"][ok] / ls
    s1, s2, angle = t["sigma_1"][ok] / ss, t["sigma_2"][ok] / ss, t["angle_1"][ok]

    outline = None
    outline_path = os.path.join(directory, "mesh_outline.csv")
    if os.path.exists(outline_path):
        o = read_table(outline_path, ["x0", "y0", "x1", "y1"])
        seg = np.stack([np.stack([o["x0"], o["y0"]], -1), np.stack([o["x1"], o["y1"]], -1)], 1) / ls
        outline = seg[np.isfinite(seg).all(axis=(1, 2))]
        if not len(outline):
            outline = None
    traces = fault_traces(directory, settings)

    if window is not None:
        xmin, xmax, ymin, ymax = window
    elif outline is not None:
        pts = outline.reshape(-1, 2)
        xmin, xmax = min(pts[:, 0].min(), x.min()), max(pts[:, 0].max(), x.max())
        ymin, ymax = min(pts[:, 1].min(), y.min()), max(pts[:, 1].max(), y.max())
    else:
        xmin, xmax, ymin, ymax = x.min(), x.max(), y.min(), y.max()
    width, height = xmax - xmin, ymax - ymin
    size = max(width, height)
    if size == 0:
        size = width = height = 1.0
    small = min(width, height) if min(width, height) > 0 else size

    magnitude = np.maximum(np.abs(s1), np.abs(s2))
    smax = float(magnitude.max())
    s_ref, s_clip = bar_scale_stresses(magnitude)
    aspect = width / height if height > 0 else math.inf
    zoom = aspect > 8 and window is None
    unit, sunit = settings["length_unit"], settings["stress_unit"]

    # Bar scale: the bar for s_ref is a fixed fraction of the median spacing
    # of the points drawn (at most half the smaller extent of the body); bars
    # for |sigma| above s_clip are cut and marked. Points closer than
    # about 0.3 inch in the cross panel are thinned to one per grid cell of
    # that size, so that the crosses stay legible.
    if zoom:
        inch_per_unit = (12.0 - 1.15) / min(8 * height, width)
    else:
        inch_per_unit = min((10.0 - 1.15) / width if width > 0 else math.inf,
                            7.0 / height if height > 0 else math.inf)
    n_samples = len(x)
    spacing = median_spacing(np.stack([x, y], -1))
    cell = 0.3 / inch_per_unit
    if spacing and spacing < cell:
        keep = thin_to_grid(x, y, xmin, ymin, cell)
        x, y, s1, s2, angle, magnitude = (v[keep] for v in (x, y, s1, s2, angle, magnitude))
        spacing = median_spacing(np.stack([x, y], -1))
    thinned = len(x) < n_samples
    # Nominal longest bar (for s_ref): 0.8 x the spacing; when bars are cut,
    # such that the cut ones (CLIP_FACTOR x longer) are 0.9 x the spacing.
    fill = 0.8 if s_clip >= smax else 0.9 / CLIP_FACTOR
    longest = fill * spacing if spacing else 0.1 * small
    longest = min(longest, 0.5 * small)
    k = longest / s_ref if s_ref > 0 else 0.0   # length units per stress unit
    clip = k * s_clip                            # bars longer than this are cut
    n_clipped = int(np.count_nonzero(magnitude > s_clip))
    drawn = k * min(smax, s_clip) if k > 0 else longest   # longest bar drawn
    barb_max = 0.13 * longest
    tick = 0.3 * longest                         # across the ends of clipped bars

    # Panels: (x limits, y limits, outline width, title)
    pad = 0.5 * drawn + 0.02 * small
    panels = []
    if zoom:
        w = min(8 * height, width)
        cx = zoom_window(x, magnitude, xmin, xmax, 2 * height)
        cx = min(max(cx, xmin + w / 2), xmax - w / 2)
        x0, x1 = cx - w / 2, cx + w / 2
        opad = 0.01 * width
        panels.append(((xmin - opad, xmax + opad), (ymin - pad, ymax + pad), 0.5,
                       "whole section (box: window below)"))
        panels.append(((x0, x1), (ymin - pad, ymax + pad), 0.7,
                       "window %s to %s %s (largest stresses)" % (format_number(x0), format_number(x1), unit)))
    else:
        panels.append(((xmin - pad, xmax + pad), (ymin - pad, ymax + pad), 0.7, None))

    # Figure geometry in inches, so that each panel has equal axis scales.
    left, right, top, gap, key_h, bottom = 0.85, 0.3, 0.55, 0.55, 0.45, 0.1
    fig_w = 12.0 if zoom else 10.0
    panel_w = fig_w - left - right
    heights = [panel_w * (p[1][1] - p[1][0]) / (p[0][1] - p[0][0]) for p in panels]
    max_h = 7.0
    if len(panels) == 1 and heights[0] > max_h:
        heights[0] = max_h
        panel_w = max_h * (panels[0][0][1] - panels[0][0][0]) / (panels[0][1][1] - panels[0][1][0])
        fig_w = max(panel_w + left + right, 7.5)
    narrow = fig_w < 9.5   # the title and the note do not fit on one line
    if narrow:
        top += 0.3
    panel_titles = [p[3] is not None for p in panels]
    fig_h = top + sum(heights) + gap * len(panels) + 0.3 * sum(panel_titles[1:]) + key_h + bottom
    fig = plt.figure(figsize=(fig_w, fig_h))
    x_left = left + 0.5 * (fig_w - left - right - panel_w)
    ypos = fig_h - top
    axes = []
    for i, ((xl, yl, outline_width, title), h) in enumerate(zip(panels, heights)):
        if i > 0 and title is not None:
            ypos -= 0.3
        ypos -= h
        ax = fig.add_axes([x_left / fig_w, ypos / fig_h, panel_w / fig_w, h / fig_h])
        ypos -= gap
        draw_outline(ax, outline, outline_width)
        for trace in traces:
            ax.plot(trace[0], trace[1], color="black", linewidth=1.8, zorder=4)
        inside = (x >= xl[0] - drawn) & (x <= xl[1] + drawn)
        widths = bar_widths(longest * panel_w / (xl[1] - xl[0]) * 72)
        if k > 0 and inside.any():
            draw_crosses(ax, cross_segments(x[inside], y[inside], s1[inside], s2[inside], angle[inside],
                                            k, barb_max, clip, tick), widths)
        ax.set_xlim(*xl)
        ax.set_ylim(*yl)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel("x [%s]" % unit)
        ax.set_ylabel("y [%s]" % unit)
        ax.tick_params(labelsize=8)
        if h < 0.15:
            ax.set_yticks([])
            ax.set_ylabel("")
        elif h < 1.0:
            ax.set_yticks([ymin, ymax])
            ax.yaxis.label.set_size(8)
            if h < 0.3:
                ax.tick_params(axis="y", labelsize=6)
        if title:
            ax.set_title(title, fontsize=9, loc="left")
        axes.append(ax)
    if zoom:
        (x0, x1) = panels[1][0]
        axes[0].add_patch(Rectangle((x0, ymin - pad), x1 - x0, height + 2 * pad, fill=False,
                                    edgecolor="0.3", linewidth=1.0, linestyle="--", zorder=5))
    text_left = min(x_left, left)
    fig.text(text_left / fig_w, (fig_h - 0.2) / fig_h,
             titled(settings, "principal stresses (in-plane, tension positive)"),
             fontsize=11, va="top")

    # Key: drawn with the same length scale as the (last) cross panel.
    inch_per_unit = panel_w / (panels[-1][0][1] - panels[-1][0][0])
    key_w = fig_w - text_left - 0.1
    key = fig.add_axes([text_left / fig_w, bottom / fig_h, key_w / fig_w, key_h / fig_h])
    key.set_xlim(0, key_w / inch_per_unit)
    key.set_ylim(0, key_h / inch_per_unit)
    key.set_axis_off()
    if k > 0:
        # The scale bar: a round stress, its bar at most 1.2 inch long.
        scale_stress = nice_below(min(smax, s_clip, 1.2 / (k * inch_per_unit)))
        bar = k * scale_stress                 # length units
        u = 1 / inch_per_unit                  # one inch in data units
        yc = 0.5 * key_h * u
        xpos = 0.0
        comp = cross_segments(np.array([0.0]), np.array([0.0]), np.array([-scale_stress]), np.array([0.0]),
                              np.array([0.0]), k, barb_max)
        tens = cross_segments(np.array([0.0]), np.array([0.0]), np.array([scale_stress]), np.array([0.0]),
                              np.array([0.0]), k, barb_max)
        entries = [("compression", comp, bar, False), ("tension", tens, bar, False)]
        if n_clipped:
            cut = cross_segments(np.array([0.0]), np.array([0.0]), np.array([-2 * s_clip]), np.array([0.0]),
                                 np.array([0.0]), k, barb_max, clip, tick)
            entries.append(("clipped (|\u03c3| > %.3g %s)" % (s_clip, sunit), cut, clip, True))
        for label, segs, length, measure in entries:
            shifted = tuple(s + np.array([xpos + length / 2, yc]) for s in segs)
            draw_crosses(key, shifted, widths)
            text = key.text(xpos + length + 0.1 * u, yc, label, va="center", fontsize=9)
            text_w = 0.09 * len(label)
            if measure:   # the clipped entry's text is much narrower than the estimate
                text_w = text.get_window_extent(fig.canvas.get_renderer()).width / fig.dpi
            xpos += length + (0.1 + text_w + 0.35) * u
        key.plot([xpos, xpos + bar], [yc, yc], color="black", linewidth=1.2, solid_capstyle="butt")
        for xe in (xpos, xpos + bar):
            key.plot([xe, xe], [yc - 0.07 * u, yc + 0.07 * u], color="black", linewidth=1.2)
        key.text(xpos + bar + 0.1 * u, yc, "%s %s" % (format_number(scale_stress), sunit), va="center",
                 fontsize=9)
        note = "bar length \u221d |\u03c3|; largest |\u03c3| = %.3g %s" % (smax, sunit)
        if n_clipped:
            note = ("bar length \u221d |\u03c3|, scaled to its %s percentile; largest |\u03c3| = %.3g %s"
                    % (ordinal(SCALE_PERCENTILE), smax, sunit))
        if thinned:
            note += "\n%d of %d sample points shown (one per %.3g %s cell)" % (len(x), n_samples, cell, unit)
        if narrow:
            fig.text(text_left / fig_w, (fig_h - 0.48) / fig_h,
                     note if n_clipped else note.replace("\n", "; "),   # the longer note: 2 lines
                     fontsize=8, color="0.3", va="top", ha="left")
        else:
            fig.text((x_left + panel_w) / fig_w, (fig_h - 0.2) / fig_h, note,
                     fontsize=8, color="0.3", va="top", ha="right")
    out = os.path.join(directory, name)
    save_complete(fig, out)
    plt.close(fig)
    return out


def plot_tip_stresses(directory, settings):
    """principal_stresses_tips.png: the crosses around a fault with a buried
    tip (fault_summary's upper_tip_depth_m or lower_tip_depth_m), over the
    fault's extent and half as much again on every side."""
    if not os.path.exists(os.path.join(directory, "principal_stresses.csv")):
        return None
    for name, path, _ in fault_files(directory):
        summary_path = os.path.join(directory, "fault_summary%s.json" % ("_" + name if name else ""))
        if not os.path.exists(summary_path):
            continue
        with open(summary_path) as f:
            summary = json.load(f)
        if summary.get("upper_tip_depth_m") is None and summary.get("lower_tip_depth_m") is None:
            continue
        fault = read_fault(path)
        if fault is None or len(fault[1]) == 0:
            continue
        ls = settings["length_scale"]
        x, y = fault[0]["x"] / ls, fault[0]["y"] / ls
        margin = 0.5 * max(x.max() - x.min(), y.max() - y.min())
        # Not above the body: the highest sample point (the top surface's
        # row of crosses) and half a margin's tenth for the bars.
        samples = read_table(os.path.join(directory, "principal_stresses.csv"), ["y"])
        top = min(y.max() + margin, float(np.nanmax(samples["y"])) / ls + 0.05 * margin)
        window = (x.min() - margin, x.max() + margin, y.min() - margin, top)
        return plot_principal_stresses(directory, settings, window, "principal_stresses_tips.png")
    return None


# --------------------------------------------------------------------------
# Surface profile


def fault_files(directory):
    """[(name, csv path, png path)] of the faults with output: fault.csv and
    fault.png for a model's one fault, fault_<name>.csv and
    fault_<name>.png for each of several (names from parameters.prm)."""
    single = os.path.join(directory, "fault.csv")
    if os.path.exists(single):
        return [("", single, os.path.join(directory, "fault.png"))]
    prm_path = os.path.join(directory, "parameters.prm")
    if not os.path.exists(prm_path):
        return []
    names = [n.strip() for n in read_prm(prm_path).get("Faults/Names", "").split(",") if n.strip()]
    return [(n, os.path.join(directory, "fault_%s.csv" % n), os.path.join(directory, "fault_%s.png" % n))
            for n in names if os.path.exists(os.path.join(directory, "fault_%s.csv" % n))]


def read_fault(path):
    """A fault CSV as (columns as arrays, states), or None if there is none."""
    if not os.path.exists(path):
        return None
    names = ("s", "x", "y", "slip", "opening", "shear_traction", "normal_traction")
    columns = {n: [] for n in names}
    states = []
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            missing = [n for n in names + ("state",) if n not in (reader.fieldnames or [])]
            if missing:
                raise InputError(path, "missing column(s) %s" % ", ".join(missing))
            for row in reader:
                try:
                    for n in names:
                        columns[n].append(float(row[n]))
                except (TypeError, ValueError):
                    raise InputError(path, "line %d: a value is not a number" % reader.line_num)
                if row["state"] not in ("stuck", "sliding", "open"):
                    raise InputError(path, "line %d: state %r is not stuck, sliding or open"
                                     % (reader.line_num, row["state"]))
                states.append(row["state"])
    except OSError as e:
        raise InputError(path, e.strerror or str(e))
    return {n: np.array(v) for n, v in columns.items()}, np.array(states)


def fault_traces(directory, settings):
    """Each fault's interface points (x, y) in plotting units."""
    traces = []
    for _, path, _ in fault_files(directory):
        fault = read_fault(path)
        if fault is not None and len(fault[1]) > 0:
            scale = settings["length_scale"]
            traces.append((fault[0]["x"] / scale, fault[0]["y"] / scale))
    return traces


def plot_faults(directory, settings):
    """fault.png (fault_<name>.png) for each fault; the last one's path."""
    out = None
    for name, path, png in fault_files(directory):
        out = plot_fault(directory, settings, name, path, png) or out
    return out


def plot_fault(directory, settings, name, path, png):
    """A fault's figure: slip and the shear against the friction limit
    along the fault."""
    fault = read_fault(path)
    if fault is None or len(fault[1]) == 0:
        return None
    values, states = fault
    prm = read_prm(os.path.join(directory, "parameters.prm"))
    names = [n.strip() for n in prm.get("Faults/Names", "").split(",") if n.strip()]
    key = name or (names[0] if names else "")
    law = prm.get("Faults/%s/Interface law" % key, "") if key else ""
    mu = float(prm.get("Faults/%s/Friction coefficient" % key, "nan")) if key else math.nan
    unit, scale = settings["length_unit"], settings["length_scale"]
    sscale, sunit = settings["stress_scale"], settings["stress_unit"]
    s = values["s"] / scale
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.5, 6.5), sharex=True)
    top.plot(s, values["slip"], color="0.4", linewidth=1)
    styles = {"stuck": ("o", "tab:blue"), "sliding": ("s", "tab:red"), "open": ("^", "tab:orange")}
    for state, (marker, color) in styles.items():
        chosen = states == state
        if chosen.any():
            top.plot(s[chosen], values["slip"][chosen], marker, color=color, markersize=3.5,
                     linestyle="none", label=state)
    top.axhline(0, color="0.7", linewidth=0.6)
    top.set_ylabel("slip [m] (+ normal, - reverse)")
    top.legend(fontsize=8, loc="best")
    top.set_title(titled(settings, "fault%s: slip and shear along the fault"
                         % (" " + name if name else "")), fontsize=10)
    if law == "frictional" and math.isfinite(mu):
        limit = mu * np.maximum(0.0, -values["normal_traction"])
        with np.errstate(divide="ignore", invalid="ignore"):
            ratio = np.where(limit > 0, np.abs(values["shear_traction"]) / limit, np.nan)
        bottom.plot(s, ratio, color="0.4", linewidth=1)
        for state, (marker, color) in styles.items():
            chosen = (states == state) & np.isfinite(ratio)
            if chosen.any():
                bottom.plot(s[chosen], ratio[chosen], marker, color=color, markersize=3.5,
                            linestyle="none")
        bottom.axhline(1, color="black", linewidth=0.8, linestyle="--")
        bottom.set_ylabel("|tau| / tau_F  (tau_F = %g |sigma_n,eff|)" % mu)
        bottom.set_ylim(0, max(1.2, np.nanmax(ratio) * 1.05 if np.isfinite(ratio).any() else 1.2))
        opened = states == "open"
        if opened.any():
            bottom.text(0.01, 0.03, "open (no friction) down to s = %.3g %s"
                        % (s[opened].max(), unit), transform=bottom.transAxes, fontsize=8)
    else:
        bottom.plot(s, values["shear_traction"] / sscale, label="shear traction")
        bottom.plot(s, values["normal_traction"] / sscale, label="normal traction")
        bottom.set_ylabel("traction [%s] (tension +)" % sunit)
        bottom.legend(fontsize=8)
    bottom.set_xlabel("s, distance along the fault from its upper end [%s]" % unit)
    for ax in (top, bottom):
        ax.tick_params(labelsize=8)
    fig.tight_layout()
    save_complete(fig, png)
    plt.close(fig)
    return png


def plot_fault_history(directory, settings):
    """fault_history.png: the slip along the (first) fault at every output
    time of a visco-elastic run (fault-NNNNN.csv, one per `Time
    stepping/Output times`), when there are at least two."""
    paths = sorted(glob.glob(os.path.join(glob.escape(directory), "fault-[0-9][0-9][0-9][0-9][0-9].csv")))
    if len(paths) < 2:
        return None
    prm = read_prm(os.path.join(directory, "parameters.prm"))
    times = [t.strip() for t in prm.get("Time stepping/Output times", "").split(",") if t.strip()]
    end = prm.get("Time stepping/End time", "").strip()
    if end and (not times or float(times[-1]) != float(end)):
        times.append(end)
    time_unit = prm.get("Time stepping/Time unit", "s").strip()
    unit, scale = settings["length_unit"], settings["length_scale"]
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    colors = plt.cm.viridis(np.linspace(0, 0.9, len(paths)))
    for k, (path, color) in enumerate(zip(paths, colors)):
        fault = read_fault(path)
        if fault is None or len(fault[1]) == 0:
            continue
        values = fault[0]
        label = "t = %s %s" % (times[k], time_unit) if k < len(times) else os.path.basename(path)
        ax.plot(values["s"] / scale, values["slip"], color=color, linewidth=1.2, label=label)
    ax.axhline(0, color="0.7", linewidth=0.6)
    ax.set_xlabel("s, distance along the fault from its upper end [%s]" % unit)
    ax.set_ylabel("slip [m] (+ normal, - reverse)")
    ax.set_title(titled(settings, "slip along the fault at the output times"), fontsize=10)
    ax.legend(fontsize=8, loc="best")
    ax.tick_params(labelsize=8)
    fig.tight_layout()
    png = os.path.join(directory, "fault_history.png")
    save_complete(fig, png)
    plt.close(fig)
    return png


def thin_plate_curve(directory, x_profile, uy_profile):
    """The thin-plate comparison as (x [m], u_y [m], forebulge markers) or
    None. thin_plate_comparison.csv is either a curve (columns x and one
    whose name contains "thin_plate") or, as written by ThinPlateFlexure,
    a table quantity,finite_element,thin_plate of forebulge distances and
    heights: then the curve w = w0 exp(-s)(cos s + sin s), s = |x - x_load|/alpha,
    is rebuilt from alpha = (thin-plate forebulge distance)/pi and
    w0 = (thin-plate forebulge height) e^pi, with x_load from parameters.prm
    (Thin plate comparison/Load position) or at the deepest point of the
    profile."""
    path = os.path.join(directory, "thin_plate_comparison.csv")
    if not os.path.exists(path):
        return None
    try:
        with open(path, newline="") as f:
            header = next(csv.reader(f), None)
    except (OSError, csv.Error, UnicodeDecodeError) as e:
        raise InputError(path, "cannot read (%s)" % e)
    if not header:
        raise InputError(path, "empty file (no header line)")
    header = [h.strip() for h in header]
    if "x" in header:
        thin = [h for h in header if "thin" in h.lower()]
        if not thin:
            raise InputError(path, "has x but no thin-plate column (header: %s)" % ",".join(header))
        t = read_table(path, ["x", thin[0]])
        order = np.argsort(t["x"])
        return t["x"][order], t[thin[0]][order], []
    if not {"quantity", "finite_element", "thin_plate"} <= set(header):
        raise InputError(path, "expected columns quantity,finite_element,thin_plate or x,...thin_plate... "
                         "(header: %s)" % ",".join(header))
    table = {}
    with open(path, newline="") as f:
        reader = csv.DictReader(f, skipinitialspace=True)
        reader.fieldnames = [n.strip() for n in reader.fieldnames]
        for row in reader:
            if None in row or any(v is None for v in row.values()):
                raise InputError(path, "line %d does not have %d fields" % (reader.line_num, len(header)))
            try:
                table[row["quantity"].strip()] = (float(row["finite_element"]), float(row["thin_plate"]))
            except ValueError:
                raise InputError(path, "line %d: finite_element and thin_plate must be numbers" % reader.line_num)
    try:
        distance = table["forebulge_distance_right_m"][1]
        bulge = table["forebulge_height_right_m"][1]
    except KeyError:
        raise InputError(path, "no forebulge_distance_right_m / forebulge_height_right_m rows")
    if not (distance > 0 and bulge > 0):
        raise InputError(path, "thin-plate forebulge distance and height must be positive")
    alpha, w0 = distance / math.pi, bulge * math.exp(math.pi)
    prm = read_prm(os.path.join(directory, "parameters.prm"))
    x_load = None
    try:
        prm_scale = LENGTH_SCALES.get(prm.get("Geometry/Length unit", "m"), 1.0)
        x_load = float(prm["Thin plate comparison/Load position"]) * prm_scale
    except (KeyError, ValueError):
        pass
    if x_load is None:
        x_load = float(x_profile[np.nanargmin(uy_profile)])
    xs = np.linspace(x_profile.min(), x_profile.max(), 2001)
    s = np.abs(xs - x_load) / alpha
    uy = -w0 * np.exp(-s) * (np.cos(s) + np.sin(s))
    markers = []
    for side, sign in (("left", -1), ("right", 1)):
        fe = (table.get("forebulge_distance_%s_m" % side), table.get("forebulge_height_%s_m" % side))
        if fe[0] and fe[1]:
            markers.append(("FE", x_load + sign * fe[0][0], fe[1][0]))
            markers.append(("thin plate", x_load + sign * fe[0][1], fe[1][1]))
    return xs, uy, markers


def plot_surface_profile(directory, settings):
    path = os.path.join(directory, "surface_profile.csv")
    if not os.path.exists(path):
        return None
    t = read_table(path, ["x", "u_x", "u_y"], ["y"])
    order = np.argsort(t["x"], kind="stable")
    x, ux, uy = t["x"][order], t["u_x"][order], t["u_y"][order]
    if not np.isfinite(x).any():
        sys.stderr.write("plot_figures: %s has no data rows; no surface-profile figure\n" % path)
        return None
    thin = thin_plate_curve(directory, x, uy)
    ls, unit = settings["length_scale"], settings["length_unit"]
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(9, 6.2), sharex=True,
                                 gridspec_kw={"height_ratios": [2.2, 1]})
    a1.plot(x / ls, uy, color="#1f77b4", linewidth=1.6, label="finite elements")
    if thin is not None:
        tx, tu, markers = thin
        a1.plot(tx / ls, tu, "k--", linewidth=1.2, label="thin plate on fluid foundation")
        for who, mx, mu in markers:
            style = dict(marker="o", color="#1f77b4", markersize=5, linestyle="none") if who == "FE" else \
                dict(marker="x", color="black", markersize=6, linestyle="none")
            a1.plot([mx / ls], [mu], **style)
        if markers:
            a1.plot([], [], marker="o", color="#1f77b4", linestyle="none", markersize=5, label="forebulge (FE)")
            a1.plot([], [], marker="x", color="black", linestyle="none", markersize=6,
                    label="forebulge (thin plate)")
    a1.axhline(0, color="0.5", linewidth=0.6, zorder=0)
    a1.set_ylabel("vertical displacement u$_y$ [m]")
    a1.legend(fontsize=8, loc="lower right")
    a1.grid(True, linewidth=0.3)
    a1.set_title(titled(settings, "surface displacement"), fontsize=11)
    a2.plot(x / ls, ux, color="#2ca02c", linewidth=1.4)
    a2.axhline(0, color="0.5", linewidth=0.6, zorder=0)
    a2.set_ylabel("horizontal u$_x$ [m]")
    a2.set_xlabel("x [%s]" % unit)
    a2.grid(True, linewidth=0.3)
    for a in (a1, a2):
        a.tick_params(labelsize=8)
    a2.set_xlim(np.nanmin(x) / ls, np.nanmax(x) / ls)
    fig.tight_layout()
    out = os.path.join(directory, "surface_profile.png")
    save_complete(fig, out)
    plt.close(fig)
    return out


# --------------------------------------------------------------------------
# Stress-depth profiles

def clip_outliers(ax, curves, depth, sunit):
    """Keep a few singular values (e.g. under a point load) from squashing a
    panel: when the extremes lie far outside the bulk of the values, limit
    the stress axis, mark each off-scale extreme by a triangle at the edge at
    its depth, and return a note naming them ("" if nothing was clipped).
    curves: [(label, values)]."""
    values = np.concatenate([v[np.isfinite(v)] for _, v in curves])
    if len(values) < 8:
        return ""
    q05, q95 = np.percentile(values, [5, 95])
    span = max(q95 - q05, 1e-12 * max(1.0, np.abs(values).max()))
    lo, hi = values.min(), values.max()
    lo_c, hi_c = max(lo, q05 - 1.5 * span), min(hi, q95 + 1.5 * span)
    if lo_c == lo and hi_c == hi:
        return ""
    margin = 0.06 * (hi_c - lo_c)
    ax.set_xlim(lo_c - margin, hi_c + margin)
    notes = []
    for label, v in curves:
        for pick, edge, marker in ((np.nanargmin, lo_c - margin, "<"), (np.nanargmax, hi_c + margin, ">")):
            if not np.isfinite(v).any():
                continue
            i = pick(v)
            if lo_c <= v[i] <= hi_c:
                continue
            ax.plot([edge], [depth[i]], marker=marker, color="black", markersize=6, clip_on=False, zorder=6)
            notes.append("%s %s %.3g" % (marker.replace("<", "\u25c0").replace(">", "\u25b6"), label, v[i]))
    return "off scale: " + ", ".join(notes) + " " + sunit if notes else ""


DEPTH_COLUMNS = ["x", "y", "depth", "sigma_xx", "sigma_yy", "sigma_xy", "sigma_1", "sigma_2",
                 "sigma_zz", "deviatoric_xx", "griffith_C"]


def plot_stress_depth(path, settings):
    label = re.match(r"stress_depth_(.+)\.csv$", os.path.basename(path)).group(1)
    t = read_table(path, DEPTH_COLUMNS)
    keep = np.isfinite(t["depth"])
    if not keep.any():
        sys.stderr.write("plot_figures: %s has no data rows; no figure\n" % path)
        return None
    order = np.argsort(t["depth"][keep], kind="stable")
    t = {c: v[keep][order] for c, v in t.items()}
    ls, ss = settings["length_scale"], settings["stress_scale"]
    unit, sunit = settings["length_unit"], settings["stress_unit"]
    depth = t["depth"] / ls
    few = len(depth) <= 40
    mark = dict(markersize=3) if few else {}

    fig, axes = plt.subplots(1, 3, figsize=(11, 6), sharey=True,
                             gridspec_kw={"width_ratios": [1.2, 1.2, 0.9]})
    a1, a2, a3 = axes
    for col, name, style, colour in (("sigma_xx", "$\\sigma_{xx}$", "-", "#1f77b4"),
                                     ("sigma_yy", "$\\sigma_{yy}$", "--", "#d62728"),
                                     ("sigma_xy", "$\\sigma_{xy}$", "-.", "#2ca02c"),
                                     ("sigma_zz", "$\\sigma_{zz}$", ":", "#9467bd")):
        a1.plot(t[col] / ss, depth, style, color=colour, linewidth=1.5, label=name,
                marker="o" if few else None, **mark)
    for col, name, style, colour in (("sigma_1", "$\\sigma_1$", "-", "#d62728"),
                                     ("sigma_2", "$\\sigma_2$", "--", "#1f3f99"),
                                     ("deviatoric_xx", "deviatoric $\\sigma_{xx}$", "-.", "#444444")):
        a2.plot(t[col] / ss, depth, style, color=colour, linewidth=1.5, label=name,
                marker="o" if few else None, **mark)
    names = {"sigma_xx": "\u03c3xx", "sigma_yy": "\u03c3yy", "sigma_xy": "\u03c3xy", "sigma_zz": "\u03c3zz",
             "sigma_1": "\u03c31", "sigma_2": "\u03c32", "deviatoric_xx": "dev. \u03c3xx"}
    notes = [clip_outliers(a, [(names[c], t[c] / ss) for c in cols], depth, sunit)
             for a, cols in ((a1, ("sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz")),
                             (a2, ("sigma_1", "sigma_2", "deviatoric_xx")))]
    for a, title, note in ((a1, "stress components", notes[0]), (a2, "principal and deviatoric", notes[1])):
        if note:
            a.text(0.5, 1.01, note, transform=a.transAxes, ha="center", va="bottom", fontsize=7, color="0.25")
            title += "\n"
        a.axvline(0, color="0.5", linewidth=0.6, zorder=0)
        a.set_xlabel("stress [%s] (tension positive)" % sunit)
        a.legend(fontsize=8, loc="best")
        a.set_title(title, fontsize=10)
        a.grid(True, linewidth=0.3)

    c = t["griffith_C"]
    tested = np.isfinite(c) & (np.abs(c) < 1e10)
    title = "Griffith degree of failure"
    a3.set_xlabel("C = 1 \u2212 \u03c4$_m$ / r(\u03c3$_m$)")
    if tested.any():
        cmin, cmax = float(np.min(c[tested])), float(np.max(c[tested]))
        lo = min(cmin, -0.25)
        hi = max(cmax, 1.0)
        span = hi - lo
        lo, hi = lo - 0.05 * span, hi + 0.05 * span
        a3.axvspan(lo, 0, color="#f2c4c4", alpha=0.6, zorder=0, linewidth=0)
        cm = np.where(tested, c, np.nan)
        a3.fill_betweenx(depth, np.minimum(cm, 0), 0, where=tested & (c < 0), color="#c0392b", alpha=0.5,
                         linewidth=0, interpolate=True)
        a3.plot(cm, depth, "-", color="black", linewidth=1.5, marker="o" if few else None, **mark)
        a3.set_xlim(lo, hi)
        a3.text(0.5 * lo, 0.02, "failed\n(C < 0)", transform=a3.get_xaxis_transform(), ha="center",
                va="bottom", fontsize=8, color="#8b1a1a")
        a3.text(0.5 * hi, 0.02, "intact\n(C > 0)", transform=a3.get_xaxis_transform(), ha="center",
                va="bottom", fontsize=8, color="0.3")
        if not tested.all():
            title += "\n(gaps: not tested, T = 0)"
    else:
        a3.set_xlim(-0.5, 1.1)
        a3.text(0.5, 0.5, "not tested\n(tensile strength T = 0)", transform=a3.transAxes, ha="center",
                va="center", fontsize=9, color="0.3")
    a3.set_title(title, fontsize=10)
    a3.axvline(0, color="black", linewidth=1.0)
    a3.grid(True, linewidth=0.3)

    a1.set_ylabel("depth [%s]" % unit)
    dmin, dmax = float(depth.min()), float(depth.max())
    if dmax > dmin:
        a1.set_ylim(dmax, dmin)   # depth increases downward
    else:
        a1.invert_yaxis()
    for a in axes:
        a.tick_params(labelsize=8)
    xs = t["x"][np.isfinite(t["x"])]
    where = (" at x = %.4g %s" % (np.median(xs) / ls, unit)) if len(xs) else ""
    fig.suptitle(titled(settings, "stress\u2013depth profile '%s'%s" % (label, where)), fontsize=11)
    fig.tight_layout()
    out = os.path.join(directory_of(path), "stress_depth_%s.png" % label)
    save_complete(fig, out)
    plt.close(fig)
    return out


def plot_strength_envelope(path, settings):
    """The yield-strength envelope of a stress-depth profile (Goetze & Evans
    1979; doc/equations.md section 13): tau_II of the model against depth
    with the brittle (Drucker-Prager) and ductile (creep at the Output/
    Strength envelope strain rate) strengths and their minimum, where the
    profile's CSV has them (Rheology = visco-elasto-plastic); the depths
    where tau_II reaches the strength (yielding) shaded."""
    label = re.match(r"stress_depth_(.+)\.csv$", os.path.basename(path)).group(1)
    t = read_table(path, ["depth"], ("tau_II", "strength_brittle", "strength_ductile", "strength"))
    if "strength" not in t or not np.isfinite(t["strength"]).any():
        return None
    order = np.argsort(t["depth"], kind="stable")
    t = {c: v[order] for c, v in t.items()}
    ls, unit = settings["length_scale"], settings["length_unit"]
    rate = read_prm(os.path.join(directory_of(path), "parameters.prm")).get(
        "Output/Strength envelope strain rate", "1e-15")
    depth = t["depth"] / ls
    fig, ax = plt.subplots(figsize=(5.5, 6.5))
    for col, name, style, colour, width in (
            ("strength_brittle", "brittle: C cos\u03c6 + P sin\u03c6", "--", "#8c564b", 1.2),
            ("strength_ductile", "ductile: creep at %s s$^{-1}$" % rate, "-.", "#1f77b4", 1.2),
            ("strength", "strength (their minimum)", "-", "black", 2.0),
            ("tau_II", "model \u03c4$_{II}$", "-", "#d62728", 1.6)):
        if col in t and np.isfinite(t[col]).any():
            ax.plot(t[col] / 1e6, depth, style, color=colour, linewidth=width, label=name)
    if "tau_II" in t:
        at_strength = np.isfinite(t["tau_II"]) & np.isfinite(t["strength"]) & \
            (t["tau_II"] >= (1 - 1e-3) * t["strength"])
        brittle = t.get("strength_brittle", np.full_like(depth, np.inf))
        ductile = t.get("strength_ductile", np.full_like(depth, np.inf))
        brittle_side = np.nan_to_num(brittle, nan=np.inf) <= np.nan_to_num(ductile, nan=np.inf)
        for where, colour, name in ((at_strength & brittle_side, "#f2c4c4", "yielding (\u03c4$_{II}$ at C cos\u03c6 + P sin\u03c6)"),
                                    (at_strength & ~brittle_side, "#c6dbef",
                                     "creeping at the reference rate or faster")):
            if where.any():
                ax.fill_betweenx(depth, 0, t["tau_II"] / 1e6, where=where, color=colour, alpha=0.8,
                                 linewidth=0, label=name)
    finite = [v for c in ("tau_II", "strength") if c in t for v in t[c][np.isfinite(t[c])]]
    if finite:
        ax.set_xlim(0, 1.1 * max(finite) / 1e6)
    ax.set_xlabel("second invariant of the deviatoric stress [MPa]")
    ax.set_ylabel("depth [%s]" % unit)
    dmin, dmax = float(np.nanmin(depth)), float(np.nanmax(depth))
    if dmax > dmin:
        ax.set_ylim(dmax, dmin)
    ax.grid(True, linewidth=0.3)
    ax.legend(fontsize=8, loc="lower right")
    ax.set_title(titled(settings, "strength envelope '%s'" % label), fontsize=10)
    fig.tight_layout()
    out = os.path.join(directory_of(path), "strength_envelope_%s.png" % label)
    save_complete(fig, out)
    plt.close(fig)
    return out


def directory_of(path):
    return os.path.dirname(path) or "."


# --------------------------------------------------------------------------


def plot_point_history(directory, settings):
    """Stress against time at the report points of a visco-elastic run
    (point_history.csv): s_xx, s_yy, s_xy, s_zz (MPa, or Pa if small) against t in the
    run's time unit, one panel per component, one line per point."""
    path = os.path.join(directory, "point_history.csv")
    if not os.path.exists(path):
        return None
    rows = list(csv.DictReader(open(path)))
    if not rows:
        return None
    prm = read_prm(os.path.join(directory, "parameters.prm"))
    unit = prm.get("Time stepping/Time unit", "s")
    seconds = {"s": 1.0, "years": 365.25 * 86400, "kyr": 365.25 * 86400e3,
               "Myr": 365.25 * 86400e6}.get(unit, 1.0)
    points = sorted({int(r["point"]) for r in rows})
    largest = max(abs(float(r[k])) for r in rows for k in ("s_xx", "s_yy", "s_xy", "s_zz"))
    scale, stress_unit = (1e6, "MPa") if largest >= 1e5 else (1.0, "Pa")
    fig, axes = plt.subplots(2, 2, figsize=(10, 7), sharex=True)
    for ax, key, name in zip(axes.flat, ("s_xx", "s_yy", "s_xy", "s_zz"),
                             (r"$\sigma_{xx}$", r"$\sigma_{yy}$", r"$\sigma_{xy}$",
                              r"$\sigma_{zz}$")):
        for p in points:
            mine = [r for r in rows if int(r["point"]) == p]
            ax.plot([float(r["time"]) / seconds for r in mine],
                    [float(r[key]) / scale for r in mine], "o-", markersize=3,
                    label="P%d (%.4g, %.4g) m" % (p, float(mine[0]["x"]), float(mine[0]["y"])))
        ax.set_ylabel("%s [%s]" % (name, stress_unit))
        ax.grid(alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("t [%s]" % unit)
    axes[0][0].legend(fontsize=7)
    fig.suptitle(titled(settings, "Stress against time at the report points"))
    fig.tight_layout()
    out = os.path.join(directory, "point_history.png")
    save_complete(fig, out)
    plt.close(fig)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("directory", help="output directory of a run")
    parser.add_argument("--debug", action="store_true", help="show a traceback on failure")
    args = parser.parse_args()
    directory = args.directory
    if not os.path.isdir(directory):
        sys.stderr.write("plot_figures: error: %s: not a directory\n" % directory)
        return 1
    try:
        settings = read_settings(directory)
    except InputError as e:
        sys.stderr.write("plot_figures: error: %s\n" % e)
        return 1

    jobs = [("principal stresses", lambda: plot_principal_stresses(directory, settings)),
            ("surface profile", lambda: plot_surface_profile(directory, settings)),
            ("point history", lambda: plot_point_history(directory, settings)),
            ("fault", lambda: plot_faults(directory, settings)),
            ("fault history", lambda: plot_fault_history(directory, settings)),
            ("stresses at the tips", lambda: plot_tip_stresses(directory, settings)),
            ("yielding zones", lambda: yielding_figure.plot_yielding(
                directory, settings, read_table, save_complete, titled, plt))]
    for path in sorted(glob.glob(os.path.join(glob.escape(directory), "stress_depth_*.csv"))):
        jobs.append((os.path.basename(path), lambda p=path: plot_stress_depth(p, settings)))
        jobs.append(("strength envelope of " + os.path.basename(path),
                     lambda p=path: plot_strength_envelope(p, settings)))
    status = 0
    for name, job in jobs:
        try:
            out = job()
        except InputError as e:
            sys.stderr.write("plot_figures: error: %s\n" % e)
            status = 1
            continue
        except Exception as e:  # a bug or an odd file: one line, not a traceback
            if args.debug:
                raise
            sys.stderr.write("plot_figures: error making the %s figure: %s: %s\n"
                             % (name, type(e).__name__, " ".join(str(e).split())))
            status = 1
            plt.close("all")
            continue
        if out:
            print("plot_figures: wrote %s" % out)
    return status


if __name__ == "__main__":
    sys.exit(main())

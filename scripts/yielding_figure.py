"""The figure of where a lithosphere yields (yielding_zones.png), for
scripts/plot_figures.py: from principal_stresses.csv of a run whose rocks
yield or creep (Rheology = visco-elasto-plastic), which then has the columns
yielding (the last step's return mapping reached the yield surface: 1, else
0, interpolated between the quadrature points), plastic_strain, tau_II and
strength (the envelope at Output/Strength envelope strain rate).

Upper panel: the yielding zones, split by the sign of the horizontal
deviatoric stress: yielding in horizontal extension (normal faulting, red)
and in horizontal compression (thrust faulting, blue), as the focal
mechanisms of outer-rise earthquakes are read; the neutral plane
(deviatoric_xx = 0) as a black line. Middle panel: tau_II over the
strength, 1 where the rock is at its strength, with the isotherms where the
run has a temperature (else the accumulated plastic strain). Lower panel,
where the CSV has it: log10 of the effective viscosity of the last step
(blank where nothing flows). All panels with the same vertical
exaggeration, stated in the title."""
import math
import os

import numpy as np

EXTENSION_COLOUR = "#d62728"
COMPRESSION_COLOUR = "#1f3f99"
ISOTHERMS_C = (200, 400, 600, 800, 1000, 1200)


def grid_of(x, y, values):
    """The samples of a regular grid (points outside the body missing) as
    2-D arrays over the unique x and y: NaN where there is no sample."""
    xs, ys = np.unique(x), np.unique(y)
    ix, iy = np.searchsorted(xs, x), np.searchsorted(ys, y)
    fields = {}
    for name, v in values.items():
        a = np.full((len(ys), len(xs)), np.nan)
        a[iy, ix] = v
        fields[name] = a
    return xs, ys, fields


def plot_yielding(directory, settings, read_table, save_complete, titled, plt):
    """yielding_zones.png of @directory, or None when principal_stresses.csv
    has no yielding column or nothing yields anywhere."""
    path = os.path.join(directory, "principal_stresses.csv")
    if not os.path.exists(path):
        return None
    t = read_table(path, ["x", "y", "deviatoric_xx"],
                   ("yielding", "plastic_strain", "tau_II", "strength", "temperature",
                    "effective_viscosity"))
    if "yielding" not in t:
        return None
    ls, unit = settings["length_scale"], settings["length_unit"]
    values = {k: t[k] for k in t if k not in ("x", "y")}
    xs, ys, f = grid_of(t["x"] / ls, t["y"] / ls, values)
    yielding = np.nan_to_num(f["yielding"], nan=0.0) > 0.5
    if not yielding.any():
        return None
    extension = yielding & (f["deviatoric_xx"] > 0)
    compression = yielding & (f["deviatoric_xx"] <= 0)
    width, height = xs[-1] - xs[0], ys[-1] - ys[0]
    # Panels 11 by about 3 inches: the vertical exaggeration that gives.
    exaggeration = (width / 10.0) / (height / 2.6) if height > 0 else 1.0
    with_viscosity = "effective_viscosity" in f and (np.nan_to_num(f["effective_viscosity"]) > 0).any()
    rows = 3 if with_viscosity else 2
    # A column for the colour bars beside every panel (the first's is
    # empty), so that the panels line up.
    fig = plt.figure(figsize=(11, 3.5 * rows))
    grid = fig.add_gridspec(rows, 2, width_ratios=[40, 1], wspace=0.03)
    axes = [fig.add_subplot(grid[0, 0])]
    axes += [fig.add_subplot(grid[k, 0], sharex=axes[0]) for k in range(1, rows)]
    bars = [fig.add_subplot(grid[k, 1]) for k in range(rows)]
    bars[0].axis("off")
    ax = axes[0]
    mode = np.where(extension, 1.0, np.where(compression, 2.0, np.nan))
    mode[np.isnan(f["deviatoric_xx"])] = np.nan
    from matplotlib.colors import ListedColormap
    ax.pcolormesh(xs, ys, np.where(np.isnan(f["deviatoric_xx"]), np.nan, 0.0),
                  cmap=ListedColormap(["#eeeeee"]), shading="nearest")
    ax.pcolormesh(xs, ys, mode, cmap=ListedColormap([EXTENSION_COLOUR, COMPRESSION_COLOUR]),
                  vmin=0.5, vmax=2.5, shading="nearest")
    neutral = ax.contour(xs, ys, f["deviatoric_xx"], levels=[0.0], colors="black", linewidths=1.2)
    handles = [plt.Rectangle((0, 0), 1, 1, color=EXTENSION_COLOUR),
               plt.Rectangle((0, 0), 1, 1, color=COMPRESSION_COLOUR),
               plt.Rectangle((0, 0), 1, 1, color="#eeeeee"),
               plt.Line2D([], [], color="black", linewidth=1.2)]
    labels = ["yielding in horizontal extension (normal faulting): %.0f%% of the section"
              % (100 * extension.sum() / np.isfinite(f["deviatoric_xx"]).sum()),
              "yielding in horizontal compression (thrust faulting): %.0f%%"
              % (100 * compression.sum() / np.isfinite(f["deviatoric_xx"]).sum()),
              "elastic or creeping",
              "neutral plane (horizontal deviatoric stress 0)"]
    if not neutral.allsegs[0]:
        handles, labels = handles[:3], labels[:3]
    ax.legend(handles, labels, fontsize=7, loc="lower left", framealpha=0.9)
    ax.set_ylabel("y [%s]" % unit)
    ax.set_title(titled(settings, "where the lithosphere yields (vertical exaggeration %.1f)" % exaggeration),
                 fontsize=10)
    ax = axes[1]
    if "strength" in f and np.isfinite(f["strength"]).any():
        ratio = f["tau_II"] / f["strength"]
        image = ax.pcolormesh(xs, ys, np.clip(ratio, 0, 1), cmap="magma_r", vmin=0, vmax=1,
                              shading="nearest")
        fig.colorbar(image, cax=bars[1], label="\u03c4$_{II}$ / strength")
    elif "plastic_strain" in f:
        image = ax.pcolormesh(xs, ys, f["plastic_strain"], cmap="viridis", shading="nearest")
        fig.colorbar(image, cax=bars[1], label="accumulated plastic strain")
    if "temperature" in f and np.isfinite(f["temperature"]).any():
        levels = [c for c in ISOTHERMS_C
                  if np.nanmin(f["temperature"]) < c + 273.15 < np.nanmax(f["temperature"])]
        if levels:
            lines = ax.contour(xs, ys, f["temperature"] - 273.15, levels=levels, colors="#2ca02c",
                               linewidths=0.8)
            ax.clabel(lines, fmt="%d \u00b0C", fontsize=7)
    ax.contour(xs, ys, f["deviatoric_xx"], levels=[0.0], colors="black", linewidths=1.2)
    ax.set_ylabel("y [%s]" % unit)
    if with_viscosity:
        ax = axes[2]
        eta = f["effective_viscosity"]
        log_eta = np.where(eta > 0, np.log10(np.where(eta > 0, eta, 1.0)), np.nan)
        image = ax.pcolormesh(xs, ys, log_eta, cmap="viridis", shading="nearest")
        fig.colorbar(image, cax=bars[2], label="log$_{10}$ effective viscosity [Pa s]\n(blank: no flow)")
        ax.set_ylabel("y [%s]" % unit)
    axes[-1].set_xlabel("x [%s]" % unit)
    for a in axes:
        a.set_aspect("auto")
        a.set_xlim(xs[0], xs[-1])
        a.set_ylim(ys[0], ys[-1])
    for a in axes[:-1]:
        a.tick_params(labelbottom=False)
    if not ("strength" in f and np.isfinite(f["strength"]).any()) and "plastic_strain" not in f:
        bars[1].axis("off")
    out = os.path.join(directory, "yielding_zones.png")
    save_complete(fig, out)
    plt.close(fig)
    return out

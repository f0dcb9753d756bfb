#!/usr/bin/python3
"""Plot the modified Griffith failure envelope r(sigma_m) of doc/griffith.md
section 3 in the (sigma_m/T, tau_m/T) plane, with its four regimes
(1 tensile, 2 open-crack shear, 3 intermediate, 4 closed-crack shear), their
boundaries, the failed and intact sides, and, below, the fracture angle theta.

  plot_griffith_envelope.py out.png [--crack-closure-ratio -4.19] [--friction 1.0]
      [--compare-closure-ratio -10] [--compare-friction 0.6] [--no-compare]

sigma_m = (sigma_1 + sigma_2)/2, tau_m = (sigma_1 - sigma_2)/2, tension
positive, everything divided by the tensile strength T. The envelope of the
given parameters (default: the listing's sigma_c/T = -4.19, mu_F = 1.0) is
drawn solid with its regimes shaded; a second pair (default -10, 0.6) is
drawn dashed for comparison. Both must satisfy mu_F^2 (1 - sigma_c/T) >= 1
(doc/griffith.md section 5). Before plotting, the script asserts that r and
theta are continuous (to 1e-9) at every regime boundary of both envelopes.

Uses Debian's python3-matplotlib; exits with a warning (status 0) if it is
missing."""
import argparse
import math
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
except ImportError:
    sys.stderr.write("plot_griffith_envelope: matplotlib is missing (apt install python3-matplotlib); "
                     "no figure made\n")
    sys.exit(0)

T = 1.0  # everything in units of the tensile strength

REGIMES = ["tensile", "open-crack shear", "intermediate", "closed-crack shear"]
COLOURS = ["#f6c9a0", "#f9ecb0", "#bfdcef", "#d5c8e8"]


class Envelope:
    """The envelope of doc/griffith.md section 3 for sigma_c/T and mu_F,
    with T = 1."""

    def __init__(self, closure_ratio, friction):
        self.sc = closure_ratio * T
        self.mu = friction
        self.K = 2 * math.sqrt(T * (T - self.sc))            # 2 sqrt(T^2 - T sigma_c)
        # Lower boundaries of regimes 1, 2, 3 (regime 4 extends to -inf);
        # each regime includes its lower boundary, as in FAIL.
        self.bounds = [-T, self.sc - 2 * T, self.sc - 2 * self.mu * math.sqrt(T * T - T * self.sc)]

    def regime(self, sm):
        """0..3 for regimes 1..4 (sigma_m >= T is regime 1, with r = 0)."""
        for i, b in enumerate(self.bounds):
            if sm >= b:
                return i
        return 3

    def r_of(self, i, sm):
        """The envelope formula of regime i (0..3) at sigma_m (table of section 3)."""
        sc, mu = self.sc, self.mu
        if i == 0:
            return T - sm
        if i == 1:
            return math.sqrt(-4 * T * sm)
        if i == 2:
            return math.sqrt((sc - sm) ** 2 + 4 * T * (T - sc))
        return (mu * (sc - sm) + 2 * math.sqrt(T * T - T * sc)) / math.sqrt(mu * mu + 1)

    def theta_of(self, i, sm):
        """The fracture angle of regime i at sigma_m [rad] (section 3)."""
        sc, mu = self.sc, self.mu
        if i == 0:
            return 0.0
        if i == 1:
            return 0.5 * math.acos(math.sqrt(T / (-sm)))
        if i == 2:
            return 0.5 * math.atan(2 * math.sqrt(T * (T - sc)) / (sc - sm))
        return 0.5 * math.atan(1 / mu)

    def r(self, sm):
        if sm >= T:
            return 0.0   # every tau_m fails (FAIL's IFAIL = -1)
        return self.r_of(self.regime(sm), sm)

    def theta(self, sm):
        if sm >= T:
            return 0.0
        return self.theta_of(self.regime(sm), sm)

    def check_continuity(self, tol=1e-9):
        """Assert that r and theta are continuous at every regime boundary:
        the two adjacent regimes' formulas agree at the boundary to tol, and
        the piecewise functions agree on both sides of it (one ulp apart)."""
        for i, b in enumerate(self.bounds):
            below, above = i + 1, i
            for f in (self.r_of, self.theta_of):
                jump = abs(f(above, b) - f(below, b))
                assert jump <= tol, "%s jumps by %g at sigma_m = %.12g (sigma_c/T = %g, mu_F = %g)" % (
                    f.__name__, jump, b, self.sc, self.mu)
            # theta of regime 2 behaves like sqrt(-T - sigma_m) just below
            # -T, so one ulp there moves it by ~1e-8: a looser bound for theta.
            for f, bound in ((self.r, tol), (self.theta, 1e-7)):
                jump = abs(f(b) - f(math.nextafter(b, -math.inf)))
                assert jump <= bound, "%s jumps by %g across sigma_m = %.12g" % (f.__name__, jump, b)
        # sigma_m = T: the tensile envelope reaches r = 0 where every state fails.
        assert abs(self.r_of(0, T)) <= tol and abs(self.r(T) - self.r(math.nextafter(T, -math.inf))) <= tol


def minus(text):
    """Typographic minus signs in numbers."""
    return text.replace("= -", "= \u2212").replace(", -", ", \u2212").replace("(-", "(\u2212")


def valid(closure_ratio, friction):
    return closure_ratio < 0 and friction > 0 and friction ** 2 * (1 - closure_ratio) >= 1


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output")
    parser.add_argument("--crack-closure-ratio", type=float, default=-4.19, help="sigma_c/T (< 0)")
    parser.add_argument("--friction", type=float, default=1.0, help="mu_F (> 0)")
    parser.add_argument("--compare-closure-ratio", type=float, default=-10.0)
    parser.add_argument("--compare-friction", type=float, default=0.6)
    parser.add_argument("--no-compare", action="store_true", help="draw only the first envelope")
    args = parser.parse_args()

    pairs = [(args.crack_closure_ratio, args.friction)]
    if not args.no_compare and (args.compare_closure_ratio, args.compare_friction) != pairs[0]:
        pairs.append((args.compare_closure_ratio, args.compare_friction))
    for sc, mu in pairs:
        if not valid(sc, mu):
            parser.error("sigma_c/T = %g, mu_F = %g: need sigma_c/T < 0, mu_F > 0 and "
                         "mu_F^2 (1 - sigma_c/T) >= 1 (smallest mu_F: %.4g)"
                         % (sc, mu, 1 / math.sqrt(1 - sc) if sc < 0 else math.nan))
    envelopes = [Envelope(sc, mu) for sc, mu in pairs]
    for e in envelopes:
        e.check_continuity()

    main_env = envelopes[0]
    x_lo = min(e.bounds[2] for e in envelopes) - 4.0
    x_hi = 3.5
    xs = np.linspace(x_lo, x_hi, 4001)
    for e in envelopes:
        xs = np.union1d(xs, e.bounds + [T])
    rs = [np.array([e.r(v) for v in xs]) for e in envelopes]
    thetas = [np.degrees([e.theta(v) for v in xs]) for e in envelopes]
    y_hi = 1.08 * max(r.max() for r in rs)

    fig, (ax, at) = plt.subplots(2, 1, figsize=(9.5, 9.6), sharex=True,
                                 gridspec_kw={"height_ratios": [3.2, 1.2], "hspace": 0.08})
    # Regimes of the main envelope: shaded under the curve (the intact side).
    # regime 1 spans [-T, x_hi] (r = 0 beyond T), then 2, 3, 4 below
    spans = [(main_env.bounds[0], x_hi), (main_env.bounds[1], main_env.bounds[0]),
             (main_env.bounds[2], main_env.bounds[1]), (x_lo, main_env.bounds[2])]
    r0 = rs[0]
    for i, (a, b) in enumerate(spans):
        m = (xs >= a) & (xs <= b)
        ax.fill_between(xs[m], 0, r0[m], color=COLOURS[i], linewidth=0, zorder=1)
        at.axvspan(a, b, color=COLOURS[i], linewidth=0, zorder=0, alpha=0.6)
    # Failed side: above the envelope.
    ax.fill_between(xs, r0, y_hi, facecolor="none", edgecolor="0.65", hatch="///", linewidth=0, zorder=1)
    # Boundaries.
    names = ["\u2212T", "\u03c3$_c$ \u2212 2T", "\u03c3$_c$ \u2212 \u03bc$_F$K"]
    for b, name in zip(main_env.bounds, names):
        ax.plot([b, b], [0, main_env.r(b)], color="0.25", linewidth=0.9, linestyle=":", zorder=2)
        ax.plot([b], [main_env.r(b)], "o", color="black", markersize=4.5, zorder=4)
        ax.annotate(minus("%s\n= %.4g" % (name, b)), (b, main_env.r(b)), xytext=(6, 6), textcoords="offset points",
                    fontsize=8, ha="left", va="bottom", zorder=5,
                    bbox=dict(boxstyle="round,pad=0.2", facecolor="white", edgecolor="none", alpha=0.85))
        at.axvline(b, color="0.25", linewidth=0.9, linestyle=":")
    ax.plot([T], [0], "o", color="black", markersize=4.5, zorder=4)
    ax.text(0.5 * (T + x_hi), 0.5 * T, "\u03c3$_m$ \u2265 T:\nevery \u03c4$_m$\nfails", ha="center",
            va="bottom", fontsize=8, color="0.15", zorder=5,
            bbox=dict(boxstyle="round,pad=0.2", facecolor="white", edgecolor="none", alpha=0.85))
    # Regime names inside the shaded bands, low down.
    for i, (a, b) in enumerate(spans):
        # the tensile band is a small triangle: its label sits low, to the left
        xm, ym, size = (-0.35 * T, 0.08, 8) if i == 0 else (0.5 * (max(a, x_lo) + b), 0.25, 9)
        ax.text(xm, ym, "%d\n%s" % (i + 1, REGIMES[i]), ha="center", va="bottom",
                fontsize=size, color="0.15", zorder=3, linespacing=1.1)
    # Envelopes.
    styles = [dict(color="black", linewidth=2.2, linestyle="-"),
              dict(color="#b2182b", linewidth=1.6, linestyle="--")]
    for e, r, th, (sc, mu), st in zip(envelopes, rs, thetas, pairs, styles):
        label = minus("envelope r(\u03c3$_m$), \u03c3$_c$/T = %g, \u03bc$_F$ = %g" % (sc, mu))
        ax.plot(xs, r, label=label, zorder=6, **st)
        at.plot(xs, th, zorder=6, **st)
        if e is not main_env:
            ax.plot(e.bounds, [e.r(b) for b in e.bounds], "o", markerfacecolor="white",
                    markeredgecolor=st["color"], markersize=5, zorder=7,
                    label=minus("its regime boundaries (\u03c3$_m$/T = %s)"
                                % ", ".join("%.4g" % b for b in e.bounds)))
    ax.text(0.985, 0.965, "FAILED  (C < 0)\n\u03c4$_m$ > r(\u03c3$_m$)", transform=ax.transAxes, ha="right",
            va="top", fontsize=10, color="0.25", fontweight="bold",
            bbox=dict(boxstyle="round,pad=0.3", facecolor="white", edgecolor="0.6"))
    xi = 0.5 * (main_env.bounds[1] + main_env.bounds[0])
    ax.text(xi, 0.45 * main_env.r(xi), "INTACT  (C > 0)\n\u03c4$_m$ < r(\u03c3$_m$)", ha="center", va="center",
            fontsize=10, color="0.25", fontweight="bold", zorder=5)
    ax.set_xlim(x_lo, x_hi)
    ax.set_ylim(0, y_hi)
    ax.set_aspect("equal", adjustable="box")
    ax.set_ylabel("\u03c4$_m$ / T = (\u03c3$_1$ \u2212 \u03c3$_2$) / 2T")
    ax.set_title("Modified Griffith failure envelope (doc/griffith.md \u00a73), "
                 "C = 1 \u2212 \u03c4$_m$ / r(\u03c3$_m$); tension positive", fontsize=11)
    ax.legend(loc="upper center", bbox_to_anchor=(0.47, 1.0), fontsize=8, framealpha=0.95)
    ax.grid(True, linewidth=0.3, zorder=0)
    ax.tick_params(labelbottom=True, labelsize=8)

    at.set_xlim(x_lo, x_hi)
    at.set_ylim(-2, 47)
    at.set_ylabel("fracture angle \u03b8 [\u00b0]")
    at.set_xlabel("\u03c3$_m$ / T = (\u03c3$_1$ + \u03c3$_2$) / 2T")
    at.grid(True, linewidth=0.3)
    at.tick_params(labelsize=8)
    at.text(0.01, 0.93, "\u03b8: between the fracture plane and \u03c3$_2$ (on the envelope)",
            transform=at.transAxes, fontsize=8, va="top", color="0.2")
    # The equal-aspect top panel may be narrower than its box: align the
    # lower panel with it.
    fig.canvas.draw()
    top, low = ax.get_position(), at.get_position()
    at.set_position([top.x0, low.y0, top.width, low.height])
    fig.savefig(args.output, dpi=150, bbox_inches="tight")
    plt.close(fig)
    print("plot_griffith_envelope: wrote %s" % args.output)


if __name__ == "__main__":
    main()

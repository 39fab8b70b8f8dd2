"""Draws a phase diagram into a matplotlib Axes: grid points coloured by l_Delta (white: stable) with the overlay
curves (traced boundaries, the paper's analytic lines) that report/panels.cpp's phase_overlay_json styles; and the
Fig. 6(e) comparison of the post-instability Delta~2 with the simulated mean. Shared by rbcstab_report.py (the
report's figures) and the Python package (Diagram.plot, Trace.plot, Fig6eTable.plot), so both draw by the same
rules. No backend or rcParams are set here: the caller owns the figure."""
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.patches import Patch

LINE_STYLES = {"solid": "-", "dashed": "--", "dotted": ":", "dashdot": "-."}
MARKERS = ["o", "s", "^", "v", "D", "P", "X", "*"]


def greys(n, lo=0.0, hi=0.75):
    """n colours of decreasing darkness-contrast from a lightness-monotonic map (viridis, dark end first)."""
    cmap = plt.get_cmap("viridis")
    return [cmap(lo + (hi - lo) * k / max(1, n - 1)) for k in range(n)]


def _edges(u):
    """Cell edges centred on the sorted values u."""
    u = np.asarray(u)
    mid = (u[1:] + u[:-1]) / 2
    return np.concatenate([[u[0] - (mid[0] - u[0])], mid, [u[-1] + (u[-1] - mid[-1])]])


def _geometric(u):
    """True for positive values evenly spaced in ln but not linearly (a geometric axis such as shear_rate)."""
    u = np.asarray(u, dtype=float)
    if len(u) < 3 or not (u > 0).all():
        return False
    d, q = np.diff(u), np.diff(np.log(u))
    return not np.allclose(d, d[0], rtol=1e-9) and np.allclose(q, q[0], rtol=1e-9)


def draw_phase_diagram(ax, xs, ys, ld, x, y, curves=(), limits=None, title=None, labels=None):
    """Points (xs[k], ys[k]) coloured by their l_Delta ld[k] (l_Delta = 2, stable, left white; a full grid as
    cells centred on the points), then the overlay curves ({"label", "x", "y", "style", "color", "width",
    "label_on_line"}); x and y name the axes. Without points, limits ((x_min, x_max), (y_min, y_max)) frame
    the curves. Returns ax."""
    xs, ys, ld = list(xs), list(ys), list(ld)
    levels = sorted({v for v in ld if v >= 3})
    ux, uy = sorted(set(xs)), sorted(set(ys))
    # Light-to-mid colours only, so the black and red overlay lines stay visible on every class.
    cols = greys(len(levels), 0.35, 0.95) if levels else []
    colour_of = {lv: cols[k] for k, lv in enumerate(levels)}
    extra = []
    if len(ux) * len(uy) == len(xs) and len(ux) > 1 and len(uy) > 1:
        # A full grid: cells centred on the points, white where stable (l_Delta = 2), as the paper draws it.
        ix = {v: k for k, v in enumerate(ux)}
        iy = {v: k for k, v in enumerate(uy)}
        rgba = np.ones((len(uy), len(ux), 4))
        for a_, b_, lv in zip(xs, ys, ld):
            if lv in colour_of:
                rgba[iy[b_], ix[a_]] = colour_of[lv]
        gx, gy = _geometric(ux), _geometric(uy)
        ex = np.exp(_edges(np.log(ux))) if gx else _edges(ux)
        ey = np.exp(_edges(np.log(uy))) if gy else _edges(uy)
        if gx or gy:
            # Cells even in ln on a log axis: pcolormesh on the edges (imshow assumes an even grid).
            from matplotlib.colors import ListedColormap
            code = np.zeros((len(uy), len(ux)))
            for a_, b_, lv in zip(xs, ys, ld):
                if lv in colour_of:
                    code[iy[b_], ix[a_]] = 1 + levels.index(lv)
            ax.pcolormesh(ex, ey, code, cmap=ListedColormap([(1, 1, 1, 1)] + list(cols)), vmin=-0.5,
                          vmax=len(levels) + 0.5, shading="flat", zorder=0)
            if gx:
                ax.set_xscale("log")
            if gy:
                ax.set_yscale("log")
        else:
            ax.imshow(rgba, origin="lower", aspect="auto", interpolation="nearest",
                      extent=(ex[0], ex[-1], ey[0], ey[-1]), zorder=0)
        extra = ([Patch(facecolor="white", edgecolor="0.5", label=r"$l_\Delta = 2$ (stable)")] +
                 [Patch(color=colour_of[lv], label=rf"$l_\Delta = {lv}$") for lv in levels])
        x_lim, y_lim = (ex[0], ex[-1]), (ey[0], ey[-1])
    elif xs:
        for lv in levels:
            px = [a_ for a_, b_ in zip(xs, ld) if b_ == lv]
            py = [a_ for a_, b_ in zip(ys, ld) if b_ == lv]
            ax.scatter(px, py, s=16, marker="s", color=colour_of[lv], edgecolors="none", label=rf"$l_\Delta = {lv}$",
                       zorder=1)
        x_lim, y_lim = (min(xs), max(xs)), (min(ys), max(ys))
    else:
        x_lim, y_lim = limits
    for c in curves:
        if not len(c["x"]):
            continue
        on_line = c.get("label_on_line", False)
        ax.plot(c["x"], c["y"], ls=LINE_STYLES.get(c.get("style", "solid"), "-"), color=c.get("color", "black"),
                lw=c.get("width", 1.6), label=None if on_line else c.get("label"), zorder=3)
        if on_line and c.get("label"):
            # Families of parallel lines (l_* = 2.5, 3.5, ...): labelled at their upper end, not in the legend.
            ax.annotate(c["label"], (c["x"][-1], c["y"][-1]), xytext=(-2, -2), textcoords="offset points",
                        ha="right", va="top", fontsize=8, color=c.get("color", "black"), zorder=4,
                        bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.7))
    ax.set_xlim(*x_lim)
    ax.set_ylim(*y_lim)
    # The overlay's "axes": the library's labels (the parameter table's symbols); no table is kept here.
    labels = labels or {}
    ax.set_xlabel(labels.get("x") or x)
    ax.set_ylabel(labels.get("y") or y)
    ax.grid(False)
    handles, labels = ax.get_legend_handles_labels()
    ax.legend(extra + handles, [h.get_label() for h in extra] + labels, loc="center left",
              bbox_to_anchor=(1.01, 0.5), fontsize=9)
    ax.set_title(title or r"$l_\Delta$ (white: stable, $l_\Delta = 2$)", fontsize=11)
    return ax


def draw_delta2_comparison(ax, theory, simulated, symbols, lam=None, alpha=None, title=None):
    """Fig. 6(e) on ax: theoretical Delta~_2 against the simulated mean Delta-bar_2 as markers (one marker per
    lambda), a diagonal guide, and given alpha an inset of the ratio theory/simulation against ln alpha. Rows where
    either value is not finite (a stable run, outside the domain) are left out: nothing joins across them.
    symbols: the parameters' TeX symbols by name (the parameter table's). Returns ax."""
    th, sim = np.asarray(theory, dtype=float), np.asarray(simulated, dtype=float)
    keep = np.isfinite(th) & np.isfinite(sim)
    th, sim = th[keep], sim[keep]
    lam = None if lam is None else np.asarray(lam, dtype=float)[keep]
    alpha = None if alpha is None else np.asarray(alpha, dtype=float)[keep]
    keys = [None] if lam is None else sorted(set(lam.tolist()))
    groups = [(key, np.arange(len(th)) if key is None else np.flatnonzero(lam == key)) for key in keys]
    for n, (key, idx) in enumerate(groups):
        lab = rf"${symbols['lambda']} = {key:g}$" if key is not None else "simulations"
        ax.scatter(sim[idx], th[idx], marker=MARKERS[n % len(MARKERS)],
                   facecolors="none" if n % 2 else greys(max(2, len(groups)))[n], edgecolors="black",
                   s=36, label=lab, zorder=2)
    if len(th):
        lo, hi = float(min(th.min(), sim.min())), float(max(th.max(), sim.max()))
        ax.plot([lo, hi], [lo, hi], color="0.4", ls="--", lw=1, label="diagonal", zorder=1)
        if lo > 0 and hi / lo > 10:  # values over more than a decade: log axes keep the small ones apart
            ax.set_xscale("log")
            ax.set_yscale("log")
    ax.set_xlabel(r"simulation $\bar{\Delta}_2$")
    ax.set_ylabel(r"theory $\tilde{\Delta}_2$")
    ax.legend(loc="upper left")
    if alpha is not None and len(th):
        ins = ax.inset_axes([0.58, 0.1, 0.38, 0.32])
        for n, (key, idx) in enumerate(groups):
            ins.plot(np.log(alpha[idx]), th[idx] / sim[idx], MARKERS[n % len(MARKERS)], ms=3.5, color="black",
                     mfc="none" if n % 2 else "black")
        ins.set_xlabel(r"$\ln\alpha$", fontsize=9)
        ins.set_ylabel(r"$\tilde{\Delta}_2/\bar{\Delta}_2$", fontsize=9)
        ins.tick_params(labelsize=8)
    if title:
        ax.set_title(title, fontsize=11)
    return ax

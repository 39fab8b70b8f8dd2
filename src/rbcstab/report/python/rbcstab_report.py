#!/usr/bin/python3
"""Figures of an rbcstab report, drawn with matplotlib only (Agg backend, Debian python3-matplotlib).

    rbcstab_report.py report DIR      draw every figure listed in DIR/report.json, write DIR/figures.json
    rbcstab_report.py selftest DIR    draw the hook figures (phase diagram, Delta2 theory, bifurcation, physical map)
                                      from small synthetic data into DIR
    rbcstab_report.py plot SPEC.json OUT.png [WIDTH HEIGHT]
                                      draw the bifurcation diagram a plot spec describes (`rbcstab plot`)

Every plotting function takes the paths of its data files (CSV/JSON beside the figure) and the output
PNG path and pixel size, so other tools can call them directly.  Styles are readable in greyscale:
line styles and markers vary along with colour, colour maps have monotonic lightness (viridis).
"""
import csv
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import colors as mcolors  # noqa: E402
from axis_rules import excess_area_limits, transient_time_scale  # noqa: E402 (beside this script, on sys.path)
from phase_draw import draw_delta2_comparison, draw_phase_diagram, greys  # noqa: E402 (beside this script, on sys.path)

DPI = 100
LINESTYLES = ["-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1)), (0, (8, 2)), (0, (1, 1)), (0, (3, 1, 1, 1))]

plt.rcParams.update({
    "font.size": 11,
    "axes.labelsize": 13,
    "legend.fontsize": 9,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "savefig.dpi": DPI,
})


# ---------------------------------------------------------------------------------------------- data
def read_csv(path):
    """Columns of a CSV file as {name: [float]} (non-numbers become nan)."""
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if r and not r[0].startswith("#")]  # '#' lines are comments
    header, body = rows[0], rows[1:]
    cols = {h: [] for h in header}
    for r in body:
        for h, v in zip(header, r):
            try:
                cols[h].append(float(v))
            except ValueError:
                cols[h].append(float("nan"))
    return cols


def read_json(path):
    with open(path) as f:
        return json.load(f)


def new_figure(size_px, ncols=1, **kw):
    w, h = size_px
    fig, axes = plt.subplots(1, ncols, figsize=(w / DPI, h / DPI), dpi=DPI, layout="constrained", **kw)
    return fig, axes


def hover_data(ax, columns, points):
    """What the page's hover script needs to place the drawn points in the PNG's pixels: the axes' box (left, top,
    right, bottom, from the image's top left), each axis' limits and scale, and the points (x and y first, then
    the other columns' values). Call after the figure was saved (the layout is final then). None for axes other
    than linear or log."""
    if ax.get_xscale() not in ("linear", "log") or ax.get_yscale() not in ("linear", "log"):
        return None
    box, height = ax.get_window_extent(), ax.figure.bbox.height  # display pixels = PNG pixels (dpi=DPI)
    short = lambda v: float(f"{v:.7g}") if isinstance(v, float) else v  # noqa: E731
    return {"axes_px": [round(box.x0, 2), round(height - box.y1, 2), round(box.x1, 2), round(height - box.y0, 2)],
            "x": {"lim": list(ax.get_xlim()), "scale": ax.get_xscale()},
            "y": {"lim": list(ax.get_ylim()), "scale": ax.get_yscale()},
            "columns": list(columns), "points": [[short(v) for v in p] for p in points]}


def save(fig, out, size_px, svg=False, hover=None):
    """The PNG at size_px and, with svg=True, an SVG beside it that the report's page opens on a click (it scales
    without blur): the report asks for it on its line and map figures, in its own staging folder. Shaded 3-D
    surfaces stay PNG only (as vectors, megabytes of polygons); `plot` writes only the file it was asked for.
    hover: (ax, columns, points) of a figure whose page shows the nearest point's values (hover_data)."""
    fig.savefig(out, dpi=DPI)
    entry = {"file": os.path.basename(out), "size_px": list(size_px)}
    if hover is not None:
        data = hover_data(*hover)
        if data is not None:
            entry["hover"] = data
    if svg:
        vector = os.path.splitext(out)[0] + ".svg"
        fig.savefig(vector, dpi=DPI, metadata={"Date": None})  # no date inside: the same figure, the same file
        entry["svg"] = os.path.basename(vector)
    plt.close(fig)
    return entry


def positive(values):
    return [v if v > 0 else float("nan") for v in values]


# ------------------------------------------------------------------------------ Fig. 2: r(t), Psi(t)
def plot_reduced_dynamics(reduced_csv, full_csv, out, size_px=(1200, 450), title=None, full_label=None, svg=False):
    """(a) r(t) and (b) Psi(t): the reduced system (solid) and the l = 2 block of the full run (dashed).
    With only full_csv (a run at the reduced level) it is drawn solid, labelled full_label."""
    fig, (ax_r, ax_p) = new_figure(size_px, ncols=2)
    series = []
    if reduced_csv:
        series.append((read_csv(reduced_csv), "reduced system ($l=2$ only)", dict(color="black", lw=1.8, ls="-")))
    if full_csv:
        style = dict(color="tab:orange", lw=1.4, ls="--") if reduced_csv else dict(color="black", lw=1.8, ls="-")
        series.append((read_csv(full_csv), full_label or "full run, $l=2$ block", style))
    for data, label, style in series:
        ax_r.plot(data["t"], data["r"], label=label, **style)
        ax_p.plot(data["t"], data["Psi"], label=label, **style)
    # Many oscillations turn the curves into a band: show the first 10 (the data files hold the whole run).
    t0 = series[0][0]["t"] if series else []
    r0 = series[0][0]["r"] if series else []
    peaks = [t0[k] for k in range(1, len(r0) - 1) if r0[k] > r0[k - 1] and r0[k] >= r0[k + 1]
             and r0[k] > min(r0) + 0.67 * (max(r0) - min(r0))]
    if len(peaks) > 15:
        t_end = peaks[10]
        for ax in (ax_r, ax_p):
            ax.set_xlim(0, t_end)
        ax_r.set_title(f"(a) amplitude $r(t)$: first 10 of {len(peaks)} oscillations (all in the CSV)",
                       loc="left", fontsize=11)
        visible = [v for data, _, _ in series for tt, v in zip(data["t"], data["Psi"]) if tt <= t_end]
        if visible:
            pad = 0.05 * (max(visible) - min(visible) + 1e-9)
            ax_p.set_ylim(min(visible) - pad, max(visible) + pad)
    ax_r.set_xlabel("$t$")
    ax_r.set_ylabel("$r$")
    ax_p.set_xlabel("$t$")
    ax_p.set_ylabel(r"$\Psi$ (rad)")
    ax_r.set_title("(a) amplitude $r(t)$", loc="left", fontsize=11)
    ax_p.set_title(r"(b) angle $\Psi(t)$", loc="left", fontsize=11)
    ax_r.legend(loc="best")
    if title:
        fig.suptitle(title, fontsize=11)
    return save(fig, out, size_px, svg)


# ------------------------------------------------------------------------------- Fig. 3b/c: Delta_l(t)
def mode_columns(data):
    return sorted((int(k.split("_")[1]), k) for k in data if k.startswith("Delta_"))


def plot_excess_areas(trajectory_csv, out, size_px=(900, 600), title=None, svg=False):
    """Delta_l(t), l = 2..L, on a log axis (the perturbations start at delta ~ 1e-3 or smaller); the time axis is
    logarithmic above the first sample when the transient spans decades (axis_rules.transient_time_scale)."""
    data = read_csv(trajectory_csv)
    modes = mode_columns(data)
    fig, ax = new_figure(size_px)
    # Distinct hues for neighbouring modes; the line styles keep them apart in greyscale.
    cols = [plt.get_cmap("tab10")(k % 10) for k in range(len(modes))]
    for k, (l, key) in enumerate(modes):
        ax.plot(data["t"], positive(data[key]), color=cols[k], ls=LINESTYLES[k % len(LINESTYLES)],
                lw=2.0 if l == 2 else 1.5, label=rf"$\Delta_{{{l}}}$")
    ax.set_yscale("log")
    limits = excess_area_limits([data[key] for _, key in modes])
    if limits:
        ax.set_ylim(*limits)
    scale, t1 = transient_time_scale(data["t"], [data[key] for _, key in modes], limits)
    if scale == "symlog":  # the transient spans decades (axis_rules): t = 0 linear, the rest logarithmic
        ax.set_xscale("symlog", linthresh=t1, linscale=0.25)
        ax.set_xlim(0, max(data["t"]))
    ax.set_xlabel("$t$" + (" (symmetric log: linear below %g)" % t1 if scale == "symlog" else ""))
    ax.set_ylabel(r"$\Delta_l(t)$")
    ax.legend(ncol=2 if len(modes) > 5 else 1, loc="best")
    if title:
        ax.set_title(title, fontsize=11)
    return save(fig, out, size_px, svg)


# ---------------------------------------------------------------------------- Fig. 3d/e: sigma(t)
def plot_tension(trajectory_csv, thresholds_json, out, reduced_csv=None, size_px=(900, 600), title=None,
                 modes=None, svg=False):
    """sigma(t) (black), the reduced system's sigma_R(t) (thick grey) and sigma_l^c (dashed, labelled).

    modes: the l whose sigma_l^c to draw; default: those inside the plotted tension range, at least l = 3, 4."""
    data = read_csv(trajectory_csv)
    th = read_json(thresholds_json)
    fig, ax = new_figure(size_px)
    finite = [s for s in data["sigma"] if math.isfinite(s)]
    lo, hi = (min(finite), max(finite)) if finite else (-1.0, 1.0)
    if reduced_csv:
        red = read_csv(reduced_csv)
        rf = [s for s in red["sigma"] if math.isfinite(s)]
        # The axis follows sigma(t) and the thresholds; sigma_R may leave it (tumbling spikes).
        clipped = bool(rf) and (min(rf) < lo - 0.5 * (hi - lo) or max(rf) > hi + 0.5 * (hi - lo))
        ax.plot(red["t"], red["sigma"], color="0.65", lw=3 if len(red["t"]) < 400 else 1.8,
                label=r"$\sigma_R(t)$ (reduced)" + (", clipped" if clipped else ""), zorder=1)
    ax.plot(data["t"], data["sigma"], color="black", lw=1.3, label=r"$\sigma(t)$", zorder=3)
    span = max(hi - lo, 1e-9)
    sig_c = {int(k): v for k, v in th.get("sigma_c", {}).items() if v is not None}
    if modes is None:
        modes = [l for l, v in sig_c.items() if l >= 3 and lo - 0.5 * span <= v <= hi + 0.5 * span]
        modes = sorted(set(modes) | {l for l in (3, 4) if l in sig_c})
    tmax = max(data["t"]) if data["t"] else 1.0
    shown = []
    for k, l in enumerate(sorted(modes)):
        if l not in sig_c:
            continue
        ax.axhline(sig_c[l], color="tab:blue", ls=LINESTYLES[(k + 1) % len(LINESTYLES)], lw=1.1, zorder=2)
        ax.annotate(rf"$\sigma_{{{l}}}^c$", xy=(1.0, sig_c[l]), xycoords=("axes fraction", "data"),
                    xytext=(3, 0), textcoords="offset points", va="center", fontsize=11, color="tab:blue")
        shown.append(sig_c[l])
    if th.get("sigma_star") is not None:
        ax.axhline(th["sigma_star"], color="tab:red", ls=":", lw=1.3,
                   label=r"$\sigma_* = -4\sqrt{\alpha}$", zorder=2)
        shown.append(th["sigma_star"])
    ymin = min([lo] + shown)
    ymax = max([hi] + shown)
    if reduced_csv and rf and not clipped:
        ymin, ymax = min(ymin, min(rf)), max(ymax, max(rf))
    pad = 0.06 * max(ymax - ymin, 1e-9)
    ax.set_ylim(ymin - pad, ymax + pad)
    ax.set_xlim(0, tmax)
    ax.set_xlabel("$t$")
    ax.set_ylabel(r"$\sigma$")
    ax.plot([], [], color="tab:blue", ls="--", label=r"$\sigma_l^c$ (mode $l$ grows below)")
    ax.legend(loc="best")
    if title:
        ax.set_title(title, fontsize=11)
    return save(fig, out, size_px, svg)


# --------------------------------------------------------------------------------- shapes (Fig. 6)
def exaggeration(rho_values):
    """Factor k for drawing 1 + k (rho - 1): 1 unless the deformation is below 0.1, then it is
    scaled up to about 0.25 (k rounded to one significant digit) so a nearly round cell shows its shape."""
    amp = max(abs(v - 1) for v in rho_values)
    if amp >= 0.1 or amp <= 0:
        return 1.0
    k = 0.25 / amp
    e = 10 ** math.floor(math.log10(k))
    return float(round(k / e) * e)


def grid_from_rho(theta, phi, rho_flat, k=1.0):
    """Cartesian grid of the surface 1 + k (rho - 1) (k: exaggeration; colours keep the true rho)."""
    nj = len(phi)
    X, Y, Z, R = [], [], [], []
    for i, th in enumerate(theta):
        st, ct = math.sin(th), math.cos(th)
        rx, ry, rz, rr = [], [], [], []
        for j, ph in enumerate(phi):
            r = rho_flat[i * nj + j]
            d = 1 + k * (r - 1)
            rx.append(d * st * math.cos(ph))
            ry.append(d * st * math.sin(ph))
            rz.append(d * ct)
            rr.append(r)
        X.append(rx), Y.append(ry), Z.append(rz), R.append(rr)
    return X, Y, Z, R


def shaded_colors(X, Y, Z, R, norm, cmap):
    """Colour by rho, lit by a soft Lambert term (so the colour stays readable against the colour bar)."""
    import numpy as np  # python3-numpy is a dependency of python3-matplotlib

    P = np.stack([X, Y, Z], axis=-1)
    dth = np.gradient(P, axis=0)
    dph = np.gradient(P, axis=1)
    n = np.cross(dth, dph)
    norm_n = np.linalg.norm(n, axis=-1, keepdims=True)
    n = np.where(norm_n > 0, n / np.where(norm_n > 0, norm_n, 1), P / np.maximum(np.linalg.norm(P, axis=-1, keepdims=True), 1e-300))
    light = np.array([-0.4, -0.5, 0.77])
    light = light / np.linalg.norm(light)
    n[0], n[-1] = n[1], n[-2]  # the pole rows are single points: borrow the neighbouring ring's normals
    lam = np.clip((n * light).sum(axis=-1), 0, 1)
    c = cmap(norm(R))
    c[..., :3] *= (0.72 + 0.28 * lam)[..., None]
    return c


def draw_surface(ax, X, Y, Z, R, norm, cmap, elev, azim, axes_labels=True, lim=None):
    """lim: half-width of the cube shown (the same for every frame of an animation)."""
    import numpy as np

    X, Y, Z, R = map(np.asarray, (X, Y, Z, R))
    ax.plot_surface(X, Y, Z, facecolors=shaded_colors(X, Y, Z, R, norm, cmap), rstride=1, cstride=1, linewidth=0,
                    antialiased=False, shade=False)
    m = float(lim) if lim else float(np.nanmax(np.abs([X, Y, Z])))
    for set_lim in (ax.set_xlim, ax.set_ylim, ax.set_zlim):
        set_lim(-m, m)
    ax.view_init(elev=elev, azim=azim)
    if axes_labels:
        ax.set_box_aspect((1, 1, 1))
        ax.set_xlabel("$x$ (flow)")
        ax.set_ylabel("$y$ (gradient)")
        ax.set_zlabel("$z$ (vorticity)")
        ticks = [-1, 0, 1] if m > 1 else [-0.5, 0, 0.5]
        ax.set_xticks(ticks), ax.set_yticks(ticks), ax.set_zticks(ticks)
    else:
        ax.set_box_aspect((1, 1, 1), zoom=1.45)
        ax.set_axis_off()


def shape_view(in_plane):
    """(elev, azim) of the Fig. 6 insets: the out-of-plane start becomes a stomatocyte whose cup opens along -z,
    seen obliquely from below; the in-plane start a trilobe lying in the shear plane, seen from above."""
    return (70.0, -90.0) if in_plane else (-35.0, -60.0)


def draw_shape(ax, shape_csv, elev, azim, axes_labels=True):
    """The shape of a grid CSV (i, j, theta, phi, rho) on a 3-D axes, coloured by rho; returns (k, norm, cmap)
    (k: the exaggeration of the drawn deformation)."""
    d = read_csv(shape_csv)
    ni, nj = int(max(d["i"])) + 1, int(max(d["j"])) + 1
    theta = [d["theta"][i * nj] for i in range(ni)]
    phi = d["phi"][:nj]
    k = exaggeration(d["rho"])
    X, Y, Z, R = grid_from_rho(theta, phi, d["rho"], k)
    flat = d["rho"]
    norm = mcolors.Normalize(vmin=min(flat), vmax=max(flat))
    cmap = plt.get_cmap("viridis")
    draw_surface(ax, X, Y, Z, R, norm, cmap, elev, azim, axes_labels=axes_labels)
    return k, norm, cmap


def plot_shape(shape_csv, out, size_px=(750, 750), title=None, elev=25.0, azim=-60.0):
    """The 3-D shape rho(theta, phi) coloured by the distance from the origin (Fig. 6 insets)."""
    w, h = size_px
    fig = plt.figure(figsize=(w / DPI, h / DPI), dpi=DPI)
    ax = fig.add_axes([0.0, 0.04, 0.84, 0.9], projection="3d")
    k, norm, cmap = draw_shape(ax, shape_csv, elev, azim)
    cax = fig.add_axes([0.86, 0.2, 0.03, 0.6])
    cax.grid(False)
    sm = plt.cm.ScalarMappable(norm=norm, cmap=cmap)
    fig.colorbar(sm, cax=cax, label=r"$\rho$ (distance from the origin)")
    if k != 1:
        fig.text(0.02, 0.02, rf"drawn as $1 + {k:g}\,(\rho - 1)$: deformation exaggerated $\times{k:g}$", fontsize=10)
    if title:
        fig.suptitle(title, fontsize=11)
    return save(fig, out, size_px)


def plot_animation(animation_json, out_png, out_gif=None, size_px=(1500, 375), gif_size_px=(400, 400),
                   strip_frames=6, elev=90.0, azim=-90.0):
    """A strip of frames (PNG) and, when Pillow is available, an animated GIF of the shape along the run,
    seen from above the shear plane by default (x: flow to the right, y: gradient upwards)."""
    a = read_json(animation_json)
    t, theta, phi, rho = a["t"], a["theta"], a["phi"], a["rho"]
    allv = [v for fr in rho for v in fr]
    norm = mcolors.Normalize(vmin=min(allv), vmax=max(allv))
    gain = exaggeration(allv)
    lim = 1 + gain * (max(allv) - 1)  # every frame at the same scale
    cmap = plt.get_cmap("viridis")
    drawn = []
    n = len(t)
    picks = sorted({round(k * (n - 1) / max(1, strip_frames - 1)) for k in range(strip_frames)})
    w, h = size_px
    fig = plt.figure(figsize=(w / DPI, h / DPI), dpi=DPI)
    for k, idx in enumerate(picks):
        ax = fig.add_axes([k / len(picks), 0.06, 1.0 / len(picks), 0.84], projection="3d")
        X, Y, Z, R = grid_from_rho(theta, phi, rho[idx], gain)
        draw_surface(ax, X, Y, Z, R, norm, cmap, elev, azim, axes_labels=False, lim=lim)
        ax.set_title(f"$t = {t[idx]:.4g}$", fontsize=12, y=1.0)
    note = rf"; deformation exaggerated $\times{gain:g}$" if gain != 1 else ""
    fig.text(0.5, 0.01, rf"viewed from $+z$: flow $x$ to the right, gradient $y$ up; colour: $\rho$ from "
             rf"{norm.vmin:.3f} (dark) to {norm.vmax:.3f} (light){note}", ha="center", fontsize=10)
    drawn.append(save(fig, out_png, size_px))
    if out_gif:
        try:
            from matplotlib.animation import FuncAnimation, PillowWriter
            import PIL  # noqa: F401  (python3-pil)
        except ImportError:
            return drawn
        gw, gh = gif_size_px
        fig = plt.figure(figsize=(gw / DPI, gh / DPI), dpi=DPI)
        ax = fig.add_axes([0, 0, 1, 0.92], projection="3d")

        def frame(idx):
            ax.clear()
            X, Y, Z, R = grid_from_rho(theta, phi, rho[idx], gain)
            draw_surface(ax, X, Y, Z, R, norm, cmap, elev, azim, axes_labels=False, lim=lim)
            ax.set_title(f"$t = {t[idx]:.4g}$" + (f"  (shape $\\times{gain:g}$)" if gain != 1 else ""), fontsize=11)
            return []

        anim = FuncAnimation(fig, frame, frames=n, blit=False)
        anim.save(out_gif, writer=PillowWriter(fps=12), dpi=DPI)
        plt.close(fig)
        drawn.append({"file": os.path.basename(out_gif), "size_px": list(gif_size_px)})
    return drawn


# ----------------------------------------------------- hooks: phase diagrams, Fig. 6e, bifurcations
def _pick(cols, names, fallback_index=None):
    for n in names:
        if n in cols:
            return n
    keys = list(cols)
    return keys[fallback_index] if fallback_index is not None and fallback_index < len(keys) else None


def plot_phase_diagram(csv_path, out, overlay_json=None, size_px=(900, 750), x=None, y=None, title=None, svg=False):
    """Points (x, y) coloured by l_Delta (l_Delta = 2, stable, left white), with curves overlaid.

    CSV: the output of `rbcstab diagram` (index,i,j,<x>,<y>,verdict,l_Delta,...), or any CSV with two axis
    columns (default: ln_B and ln_C, else the first two columns) and l_Delta.
    Overlay JSON: {"curves": [{"label", "x": [...], "y": [...], "style": "solid|dashed|dotted", "color"}]}."""
    d = read_csv(csv_path)
    keys = list(d)
    if "j" in keys and keys.index("j") + 2 < len(keys):  # rbcstab diagram: index,i,j,<x>,<y>,verdict,l_Delta,...
        x = x or keys[keys.index("j") + 1]
        y = y or keys[keys.index("j") + 2]
    x = x or _pick(d, ["ln_B", "x"], 0)
    y = y or _pick(d, ["ln_C", "y"], 1)
    ld = [int(v) if math.isfinite(v) else 0 for v in d["l_Delta"]]
    fig, ax = new_figure(size_px)
    overlay = read_json(overlay_json) if overlay_json else {}
    draw_phase_diagram(ax, d[x], d[y], ld, x, y, overlay.get("curves", []), title=title, labels=overlay.get("axes"))
    finite = [(a, b, lv) for a, b, lv in zip(d[x], d[y], ld) if math.isfinite(a) and math.isfinite(b)]
    return save(fig, out, size_px, svg, hover=(ax, [x, y, "l_Delta"], finite))


def plot_delta2_comparison(csv_path, out, symbols, size_px=(750, 750), title=None, svg=False):
    """Fig. 6e: theoretical Delta~_2 against the simulated mean Delta-bar_2, a diagonal guide, and (when the
    CSV has an alpha column) an inset of the ratio theory/simulation against ln alpha.
    `symbols`: the parameters' TeX symbols by name (report.json "symbols": the parameter table's).
    CSV columns: Delta2_theory, Delta2_simulation[, alpha][, lambda], or the CSV of `rbcstab post --fig6e`
    (Delta2_tilde, Delta2_bar, alpha, lambda, ...; rows with n/a are skipped)."""
    d = read_csv(csv_path)
    th = d[_pick(d, ["Delta2_theory", "Delta2_tilde"])]  # `rbcstab post --fig6e` names: Delta2_tilde, Delta2_bar
    sim = d[_pick(d, ["Delta2_simulation", "Delta2_bar"])]
    fig, ax = new_figure(size_px)
    draw_delta2_comparison(ax, th, sim, symbols, d.get("lambda"), d.get("alpha"), title)
    return save(fig, out, size_px, svg)


def plot_bifurcation(spec_json, out, size_px=(900, 675), svg=False):
    """Renders the diagram a PlotSpec describes (`rbcstab plot`'s JSON, format "rbcstab-plot", decided by
    report/bifurcation_plot.cpp) into a PNG: bifurcation_draw.draw_bifurcation on a new figure."""
    from bifurcation_draw import draw_bifurcation  # beside this script, whose folder is on sys.path

    fig, ax = new_figure(size_px)
    spec = read_json(spec_json)
    draw_bifurcation(ax, spec, spec_json)
    return save(fig, out, size_px, svg, hover=(ax, *bifurcation_points(spec)))


def plot_physical_map(map_json, out, size_px=(900, 700), title=None, svg=False):
    """The physical phase diagram of a map JSON (the [physical_map] panel's physical_map.json, or
    PhysicalMap.to_dict()): physical_draw.draw_physical_map on a new figure, the boundaries' points on hover."""
    from physical_draw import draw_physical_map, drawn_points  # beside this script, whose folder is on sys.path

    fig, ax = new_figure(size_px)
    data = read_json(map_json)
    draw_physical_map(ax, data, title=title)
    return save(fig, out, size_px, svg, hover=(ax, *drawn_points(data)))


def bifurcation_points(spec):
    """The drawn vertices of a PlotSpec (x, y, branch, stability) and its marked points (x, y, branch, text)."""
    columns = [spec["x"]["name"], spec["y"]["name"], "branch", "point"]
    points = []
    for sr in spec["series"]:
        for seg in sr["segments"]:
            points += [[a, b, sr["name"], seg["stability"]] for a, b in zip(seg["x"], seg["y"])
                       if a is not None and b is not None]
    points += [[p["x"], p["y"], spec["series"][p["series"]]["name"], p["text"] or p["type"]] for p in spec["points"]
               if p["x"] is not None and p["y"] is not None]
    return columns, points


# ---------------------------------------------------------------------------------------- drivers
def draw_report(folder):
    m = read_json(os.path.join(folder, "report.json"))
    scene = m["scene"]
    tag = m["title"]  # the scene's name and parameters in the parameter table's symbols (report.cpp)
    path = lambda name: os.path.join(folder, name)  # noqa: E731
    drawn = []
    for f in m["figures"]:
        kind, size, data = f["kind"], tuple(f["size_px"]), f["data"]
        out = path(f["png"])
        if kind == "reduced_dynamics":
            red = path("reduced_trajectory.csv") if "reduced_trajectory.csv" in data else None
            level = m["summary"]["model"]
            label = ("reduced system ($l=2$ only)" if level == "reduced" else f"{level} run, $l=2$ block")
            drawn.append(plot_reduced_dynamics(red, path("trajectory.csv"), out, size, title=tag, full_label=label,
                                                svg=True))
        elif kind == "excess_areas":
            drawn.append(plot_excess_areas(path(data[0]), out, size, title=tag, svg=True))
        elif kind == "tension":
            red = path("reduced_trajectory.csv") if "reduced_trajectory.csv" in data else None
            drawn.append(plot_tension(path(data[0]), path(data[1]), out, red, size, title=tag, svg=True))
        elif kind == "shape":
            elev, azim = shape_view(m["shape"].get("in_plane", False))
            drawn.append(plot_shape(path(data[0]), out, size, title=f"{scene['name']}: shape at $t = {f['t']:.4g}$",
                                    elev=elev, azim=azim))
        elif kind == "animation":
            drawn.extend(plot_animation(path(data[0]), out, path(f["gif"]) if f.get("gif") else None, size,
                                        tuple(f.get("gif_size_px", (400, 400)))))
        elif kind == "phase_diagram":
            drawn.append(plot_phase_diagram(path(data[0]), out, path(data[1]) if len(data) > 1 else None, size,
                                            title=f.get("title"), svg=True))
        elif kind == "delta2_comparison":
            drawn.append(plot_delta2_comparison(path(data[0]), out, m["symbols"], size, title=f.get("title"),
                                                 svg=True))
        elif kind == "bifurcation":
            drawn.append(plot_bifurcation(path(data[0]), out, size, svg=True))
        elif kind == "physical_map":
            drawn.append(plot_physical_map(path(data[0]), out, size, title=f.get("title"), svg=True))
        else:
            raise ValueError(f"unknown figure kind {kind!r}")
    with open(path("figures.json"), "w") as f:
        json.dump(drawn, f, indent=2)


def selftest(folder):
    """Hook figures from small synthetic data (the data files are written beside them)."""
    os.makedirs(folder, exist_ok=True)
    p = lambda name: os.path.join(folder, name)  # noqa: E731
    with open(p("phase_diagram.csv"), "w") as f:
        f.write("index,i,j,ln_B,ln_C,verdict,l_Delta,status\n")  # the layout of `rbcstab diagram`
        for i in range(12):
            for j in range(10):
                lb, lc = -1 + 7 * i / 11, -5.5 + 7.5 * j / 9
                la = lb - lc  # ln alpha
                lv = 2 if la < 3 else (3 if la < 5 else (4 if la < 7 else 5))
                f.write(f"{i * 10 + j},{i},{j},{lb},{lc},{'stable' if lv == 2 else 'unstable'},{lv},success\n")
    with open(p("phase_diagram_overlay.json"), "w") as f:
        json.dump({"curves": [
            {"label": r"$l_* = 2.5$", "x": [-1, 6], "y": [-4, 3], "style": "solid"},
            {"label": r"$l = 3 \to 4$", "x": [-1, 6], "y": [-6, 1], "style": "dashed"},
            {"label": r"$\mathcal{C}_*$", "x": [-1, 6], "y": [1, 1], "style": "solid", "color": "tab:red"}]}, f)
    with open(p("delta2_comparison.csv"), "w") as f:
        # The layout of `rbcstab post --fig6e` (comment line, n/a where stable or outside the domain).
        f.write("# Fig. 6e: synthetic\nlambda,B,C,alpha,ln_alpha,l_s,l_Delta,Delta2_tilde,Delta2_bar,ratio\n")
        for k in range(8):
            a = math.exp(3 + 0.5 * k)
            s = 0.3 + 0.05 * k
            t = s * (1 + 0.3 / math.log(a))
            f.write(f"{1 if k % 2 else 5},1,{1 / a},{a},{math.log(a)},3,3,{t},{s},{t / s}\n")
        f.write("5,1,1,1,0,3,2,n/a,n/a,n/a\n")
    xs = [0.1 * k for k in range(21)]
    sw = [1.2 + 0.05 * k for k in range(11)]
    seg = lambda st, style, x, y: {"stability": st, "style": style, "x": x, "y": y}  # noqa: E731
    with open(p("bifurcation_plot.json"), "w") as f:  # a PlotSpec: a branch, its switched branch, a BP
        y0 = [0.5 + 0.2 * x for x in xs]
        y1 = [0.74 + 0.4 * math.sqrt(x - 1.2) for x in sw]
        json.dump({"format": "rbcstab-plot", "version": 1, "title": r"$\lambda = 1$, $\mathcal{B} = 1$",
                   "x": {"name": "C", "label": r"$\mathcal{C}$"}, "y": {"name": "r", "label": "$r$"},
                   "series": [{"name": "equilibria (modal model)", "kind": "equilibrium",
                               "segments": [seg("stable", "solid", xs[:13] + [1.2], y0[:13] + [0.74]),
                                            seg("unstable", "dashed", [1.2] + xs[13:], [0.74] + y0[13:])]},
                              {"name": "equilibria (modal model), switched branch", "kind": "equilibrium",
                               "segments": [seg("stable", "solid", sw[:8], y1[:8]),
                                            seg("uncertain", "dotted", sw[7:], y1[7:])]}],
                   "points": [{"x": 1.2, "y": 0.74, "type": "BP", "label": 3, "series": 0, "marker": "special",
                               "text": "BP 3"},
                              {"x": 2.0, "y": 0.9, "type": "EP", "label": 4, "series": 0, "marker": "end",
                               "text": "EP 4"}],
                   "styles": [{"stability": "stable", "style": "solid"}, {"stability": "unstable", "style": "dashed"},
                              {"stability": "uncertain", "style": "dotted"}]}, f)
    with open(p("curve_plot.json"), "w") as f:  # a PlotSpec: a two-parameter curve in its plane
        json.dump({"format": "rbcstab-plot", "version": 1, "title": "",
                   "x": {"name": "C", "label": r"$\mathcal{C}$"}, "y": {"name": "B", "label": r"$\mathcal{B}$"},
                   "series": [{"name": "BP curve (modal model)", "kind": "curve",
                               "segments": [seg("curve", "solid", xs, [0.5 + x * x for x in xs])]}],
                   "points": [], "styles": []}, f)
    with open(p("physical_map.json"), "w") as f:  # two viscosities: a boundary found, then one below the range
        found = {"found": True, "shear_rate": 30.0, "bracket": [29.9, 30.0],
                 "band": {"cells": 3, "found": 3, "lo": 20.0, "hi": 45.0}}
        below = {"found": False, "reason": "synthetic", "side": "below", "band": {"cells": 3, "found": 0}}
        json.dump({"shear_rate_range": [0.1, 1e5], "experiments": [
            {"source": "S", "observation": "swinging", "kind": "stress", "viscosity": None, "shear_rate_lo": None,
             "shear_rate_hi": None, "stress": 0.1, "precision": "order"},
            {"source": "P", "observation": "trilobes", "kind": "point", "viscosity": 1e-3, "shear_rate_lo": 1000,
             "shear_rate_hi": 1000, "stress": None, "precision": "order"}],
            "columns": [{"viscosity": v, "tumbling_to_swinging": found, "onset_out_of_plane": below,
                         "onset_in_plane": below} for v in (1e-3, 5e-2)]}, f)
    out = [plot_physical_map(p("physical_map.json"), p("fig_physical_map.png")),
           plot_bifurcation(p("curve_plot.json"), p("fig_bifurcation_continue.png")),
           plot_phase_diagram(p("phase_diagram.csv"), p("fig_phase_diagram.png"), p("phase_diagram_overlay.json")),
           plot_delta2_comparison(p("delta2_comparison.csv"), p("fig_delta2_theory.png"), {"lambda": r"\lambda"}),
           plot_bifurcation(p("bifurcation_plot.json"), p("fig_bifurcation.png"))]
    with open(p("figures.json"), "w") as f:
        json.dump(out, f, indent=2)


def main(argv):
    if len(argv) in (4, 6) and argv[1] == "plot":  # plot SPEC.json OUT.png [WIDTH HEIGHT]
        size = (int(argv[4]), int(argv[5])) if len(argv) == 6 else (900, 675)
        plot_bifurcation(argv[2], argv[3], size)
        return 0
    if len(argv) != 3 or argv[1] not in ("report", "selftest"):
        sys.stderr.write(__doc__)
        return 2
    (draw_report if argv[1] == "report" else selftest)(argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

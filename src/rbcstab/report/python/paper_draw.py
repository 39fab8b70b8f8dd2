#!/usr/bin/python3
"""The paper's figures as `rbcstab paper` composes them (report/paper*.cpp and report/detail/paper_* decide every
run, window, scale and line; this script only renders DIR/paper.json with matplotlib, Agg backend).

    paper_draw.py DIR     draw every figure of DIR/paper.json into DIR/<id>.png (and DIR/<id>.svg when the spec names it)

Panel kinds: "lines" (series of CSV columns against t or l, horizontal and vertical reference lines, an optional
right axis, optional 3-D shape insets), "phase" (a phase diagram: phase_draw.draw_phase_diagram with its overlay), "markers" (the unstable
points of several diagrams on one plane, Fig. 5) and "fig6e" (Delta~2 against Delta-bar2 with the ratio inset)."""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from phase_draw import MARKERS, draw_phase_diagram  # noqa: E402 (beside this script, on sys.path)
from rbcstab_report import DPI, draw_shape, read_csv, read_json, shape_view  # noqa: E402

LS = {"solid": "-", "dashed": "--", "dotted": ":", "dashdot": "-."}


def wrapped(x, y, period):
    """(x, y) with y modulo period in (-period/2, period/2], a NaN inserted where it wraps (no vertical line across
    the panel)."""
    ox, oy, prev = [], [], None
    for a, v in zip(x, y):
        w = v - period * math.floor(v / period + 0.5) if math.isfinite(v) else v
        if prev is not None and abs(w - prev) > period / 2:
            ox.append(a)
            oy.append(float("nan"))
        ox.append(a)
        oy.append(w)
        prev = w
    return ox, oy


def draw_lines(ax, p, folder):
    right = None
    top = []  # largest drawn value on the main axis: a log axis spans 10 decades below it
    seen = []  # main-axis values inside the drawn time window: a linear axis spans them only
    lo_x, hi_x = p["xlim"]
    for s in p["series"]:
        d = read_csv(os.path.join(folder, s["data"]))
        target = ax
        if s.get("right"):
            right = right or ax.twinx()
            target = right
        x, y = d[s["x"]], d[s["y"]]
        if s.get("wrap"):
            x, y = wrapped(x, y, s["wrap"])
        if p.get("yscale") == "log" and not s.get("right"):
            y = [v if v > 0 else float("nan") for v in y]
            top += [v for v in y if math.isfinite(v)]
        if not s.get("right"):
            seen += [v for a, v in zip(x, y) if lo_x <= a <= hi_x and math.isfinite(v)]
        target.plot(x, y, color=s["color"], ls=s["ls"], lw=s["lw"], marker=s.get("marker"), ms=4,
                    label=s["label"] or None)
    for h in p["hlines"]:
        ax.axhline(h["y"], color=h["color"], ls=h["ls"], lw=h["lw"], label=h["label"] or None, zorder=1)
    for v in p["vlines"]:
        if math.isfinite(v["x"]):
            ax.axvline(v["x"], color=v["color"], ls=v["ls"], lw=1.1, label=v["label"], zorder=1)
    ax.set_xscale(p["xscale"])
    ax.set_xlim(*p["xlim"])
    if p.get("yscale") == "log":
        ax.set_yscale("log")
        top += [h["y"] for h in p["hlines"] if h["y"] > 0]
        if top:  # decayed modes fall by hundreds of decades: keep 10 below the largest value
            ax.set_ylim(max(top) * 1e-10, max(top) * 3)
    elif seen and p["xlabel"] == "$t$":  # a time window: the samples before it do not stretch the axis
        span = max(seen) - min(seen)
        pad = 0.05 * span if span > 0 else 0.05 * max(abs(max(seen)), 1e-12)
        ax.set_ylim(min(seen) - pad, max(seen) + pad)
    if p.get("ylim"):
        ax.set_ylim(*p["ylim"])
    ax.set_xlabel(p["xlabel"])
    ax.set_ylabel(p["ylabel"])
    handles, labels = ax.get_legend_handles_labels()
    if right is not None:
        right.set_ylabel(r"$\mathcal{B}\Upsilon_l$", color="tab:green")
        h2, l2 = right.get_legend_handles_labels()
        handles, labels = handles + h2, labels + l2
    if handles:
        ax.legend(handles, labels, loc=p.get("legend_loc", "best"), fontsize=8)
    for inset in p.get("insets", []):
        draw_inset_shape(ax, inset, folder)


def draw_inset_shape(ax, inset, folder):
    """A shape (report's renderer, the report's view for its orientation) in a 3-D inset at inset["bounds"]."""
    ins = ax.inset_axes(inset["bounds"], projection="3d")
    ins.patch.set_alpha(0)
    elev, azim = shape_view(inset["in_plane"])
    k = draw_shape(ins, os.path.join(folder, inset["data"]), elev, azim, axes_labels=False)[0]
    ins.set_title(inset["label"] + (rf" (deformation $\times{k:g}$)" if k != 1 else ""), fontsize=8, pad=0)


def draw_phase(ax, p, folder):
    d = read_csv(os.path.join(folder, p["data"]))
    keys = list(d)
    x, y = keys[keys.index("j") + 1], keys[keys.index("j") + 2]
    ld = [int(v) if math.isfinite(v) else 0 for v in d["l_Delta"]]
    overlay = read_json(os.path.join(folder, p["overlay"]))
    draw_phase_diagram(ax, d[x], d[y], ld, x, y, overlay.get("curves", []), title=p["title"], labels=overlay.get("axes"))


def draw_markers(ax, p, folder):
    lims = None
    for k, s in enumerate(p["sets"]):
        d = read_csv(os.path.join(folder, s["data"]))
        keys = list(d)
        x, y = keys[keys.index("j") + 1], keys[keys.index("j") + 2]
        lims = ((min(d[x]), max(d[x])), (min(d[y]), max(d[y])))
        px = [a for a, v in zip(d[x], d["l_Delta"]) if math.isfinite(v) and v >= 3]
        py = [b for b, v in zip(d[y], d["l_Delta"]) if math.isfinite(v) and v >= 3]
        # Larger markers first, so the later (smaller) ones stay visible on top.
        ax.scatter(px, py, s=60 - 15 * k, marker=s["marker"], facecolors="none", edgecolors=s["color"],
                   label=s["label"], zorder=2 + k)
    for c in read_json(os.path.join(folder, p["overlay"])).get("curves", []):
        xs = [a for a, b in zip(c["x"], c["y"]) if a is not None and b is not None]
        ys = [b for a, b in zip(c["x"], c["y"]) if a is not None and b is not None]
        ax.plot(xs, ys, color=c["color"], ls=LS.get(c["style"], "-"), lw=1.5, label=c["label"], zorder=1)
    if lims:
        ax.set_xlim(*lims[0])
        ax.set_ylim(*lims[1])
    ax.set_xlabel(p["xlabel"])
    ax.set_ylabel(p["ylabel"])
    ax.legend(loc="best", fontsize=8)


def draw_fig6e(ax, p, folder):
    d = read_csv(os.path.join(folder, p["data"]))
    keep = [k for k in range(len(d["Delta2_tilde"])) if math.isfinite(d["Delta2_tilde"][k])
            and math.isfinite(d["Delta2_bar"][k])]
    lams = sorted({d["lambda"][k] for k in keep})
    for n, lam in enumerate(lams):
        idx = [k for k in keep if d["lambda"][k] == lam]
        ax.scatter([d["Delta2_bar"][k] for k in idx], [d["Delta2_tilde"][k] for k in idx], marker=MARKERS[n],
                   facecolors="none" if n else "0.3", edgecolors="black", s=36, label=rf"${p['lambda_symbol']} = {lam:g}$")
    vals = [d[c][k] for k in keep for c in ("Delta2_tilde", "Delta2_bar")]
    if vals:
        ax.plot([min(vals), max(vals)], [min(vals), max(vals)], color="0.5", ls="--", lw=1, label="diagonal")
        ins = ax.inset_axes([0.58, 0.1, 0.38, 0.32])
        for n, lam in enumerate(lams):
            idx = [k for k in keep if d["lambda"][k] == lam]
            ins.plot([d["ln_alpha"][k] for k in idx], [d["ratio"][k] for k in idx], MARKERS[n], ms=3.5,
                     color="black", mfc="none" if n else "black")
        ins.set_xlabel(r"$\ln\alpha$", fontsize=8)
        ins.set_ylabel(r"$\tilde\Delta_2/\bar\Delta_2$", fontsize=8)
        ins.tick_params(labelsize=7)
    ax.set_xlabel(r"simulation $\bar\Delta_2$")
    ax.set_ylabel(r"theory $\tilde\Delta_2$")
    ax.legend(loc="upper left", fontsize=8)


DRAW = {"lines": draw_lines, "phase": draw_phase, "markers": draw_markers, "fig6e": draw_fig6e}


def draw_paper(folder):
    spec = read_json(os.path.join(folder, "paper.json"))
    plt.rcParams.update({"font.size": 10, "axes.grid": True, "grid.alpha": 0.3})
    for f in spec["figures"]:
        w, h = f["size_px"]
        fig, axes = plt.subplots(f["nrows"], f["ncols"], figsize=(w / DPI, h / DPI), dpi=DPI, layout="constrained",
                                 squeeze=False)
        flat = [a for row in axes for a in row]
        for ax, p in zip(flat, f["panels"]):
            DRAW[p["kind"]](ax, p, folder)
            if p["kind"] != "phase":  # draw_phase_diagram titles its own panel
                ax.set_title(p["title"], loc="left", fontsize=10)
        for ax in flat[len(f["panels"]):]:
            ax.set_visible(False)
        fig.suptitle(f["title"], fontsize=12)
        fig.savefig(os.path.join(folder, f["png"]), dpi=DPI)
        if f.get("svg"):  # no date inside: the same figure, the same file
            fig.savefig(os.path.join(folder, f["svg"]), dpi=DPI, metadata={"Date": None})
        plt.close(fig)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    draw_paper(argv[1])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

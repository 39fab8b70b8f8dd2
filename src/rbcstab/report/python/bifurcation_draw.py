"""Draws a bifurcation diagram that a PlotSpec describes (`rbcstab plot`'s JSON of what was drawn, format
"rbcstab-plot", decided by report/bifurcation_plot.cpp) into a matplotlib Axes. Shared by rbcstab_report.py
(`rbcstab plot`, the report) and the Python package (Branch.plot), so both draw by the same rules. No
backend or rcParams are set here: the caller owns the figure."""
from matplotlib.lines import Line2D

# Okabe-Ito colours (distinct for colour-blind readers), black first; stability is the line style.
SERIES_COLOURS = ["black", "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9"]
LINE_STYLES = {"solid": "-", "dashed": (0, (6, 3)), "dotted": (0, (1, 2))}
STABILITY_TEXT = {"stable": "stable", "unstable": "unstable", "uncertain": "uncertain (margin within its error)"}


def _nan(values):
    return [float("nan") if v is None else v for v in values]


def _renderer(fig):
    """The figure's renderer, to measure texts (Agg canvases have one; other backends draw once to get one)."""
    get = getattr(fig.canvas, "get_renderer", None)
    return get() if get is not None else fig._get_renderer()


def draw_bifurcation(ax, s, source="plot spec"):
    """Renders the PlotSpec s (a dict) into ax: each series in its colour, its segments in their line styles
    (stable solid, unstable dashed, uncertain dotted), the points' markers (a normal form's supercritical point
    filled, subcritical a diamond) and texts ("BP 3 super"), the axes' labels and the title. Nothing is decided
    here. Returns ax."""
    if s.get("format") != "rbcstab-plot":
        raise ValueError(f"{source}: not a plot spec (format {s.get('format')!r}, expected 'rbcstab-plot')")
    fig = ax.figure
    handles = []
    colour = lambda n: SERIES_COLOURS[n % len(SERIES_COLOURS)]  # noqa: E731
    for n, sr in enumerate(s["series"]):
        for seg in sr["segments"]:
            solid = seg["style"] == "solid"
            ax.plot(_nan(seg["x"]), _nan(seg["y"]), color=colour(n), ls=LINE_STYLES[seg["style"]],
                    lw=2.0 if solid else 1.6, zorder=2)
        handles.append(Line2D([], [], color=colour(n), lw=2.2, label=sr["name"]))
    for st in s.get("styles", []):
        handles.append(Line2D([], [], color="0.4", ls=LINE_STYLES[st["style"]], lw=1.6,
                              label=STABILITY_TEXT.get(st["stability"], st["stability"])))
    marker = {"special": dict(marker="o", ms=7, mfc="white", mew=1.6),
              "end": dict(marker="s", ms=5, mew=1.2, mfc="white"),
              "regular": dict(marker=".", ms=6)}
    # A special point's normal form (the spec's "criticality"): supercritical filled, subcritical a diamond.
    critical = {"supercritical": dict(marker="o", ms=7, mew=1.6), "subcritical": dict(marker="D", ms=6.5, mfc="white",
                                                                                      mew=1.6)}
    shown = [p for p in s["points"] if p["x"] is not None and p["y"] is not None]
    for p in shown:
        c = colour(p["series"])
        style = critical.get(p.get("criticality", ""), marker.get(p["marker"], marker["special"]))
        ax.plot([p["x"]], [p["y"]], ls="none", color=c, mec=c, zorder=4, **style)
    for name in ("supercritical", "subcritical"):
        if any(p.get("criticality") == name for p in shown):
            handles.append(Line2D([], [], ls="none", color="0.4", mec="0.4", label=name, **critical[name]))
    ax.margins(x=0.04, y=0.06)
    x0, x1 = ax.get_xlim()
    renderer = _renderer(fig)
    placed = []
    # Special points' texts first; each goes to the first of a few spots around its marker that overlaps
    # no text placed before it (turned inwards in the last eighth of the width, so it stays inside).
    for p in sorted((p for p in shown if p["text"]), key=lambda p: p["marker"] != "special"):
        inward = -1 if (p["x"] - x0) > 0.875 * (x1 - x0) else 1
        spots = [(7 * inward, 7), (7 * inward, -16), (-7 * inward, 7), (-7 * inward, -16), (7 * inward, 20)]
        for k, (dx, dy) in enumerate(spots):
            ann = ax.annotate(p["text"], (p["x"], p["y"]), xytext=(dx, dy), textcoords="offset points",
                              ha="left" if dx > 0 else "right", zorder=5,
                              fontsize=11 if p["marker"] == "special" else 9, color=colour(p["series"]),
                              bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))
            box = ann.get_window_extent(renderer)
            if k == len(spots) - 1 or not any(box.overlaps(q) for q in placed):
                placed.append(box)
                break
            ann.remove()
    ax.set_xlabel(s["x"]["label"])
    ax.set_ylabel(s["y"]["label"])
    if handles:
        ax.legend(handles=handles, loc="best", framealpha=0.9, fontsize=10)
    if s.get("title"):
        ax.set_title(s["title"], fontsize=11)
    return ax

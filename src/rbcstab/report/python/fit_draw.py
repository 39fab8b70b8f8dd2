"""Draws a fit's page figure from its JSON (report/fit_page.hpp: fit_page_json) and nothing else: per observable,
the observations against shear rate (log axis) with their error bars, one colour per outer viscosity, and the model
curve at the estimate drawn only over the span the model computed (the JSON's curve.span; grid points without a
prediction are gaps); below, the normalised residuals (predicted - observed)/sigma against shear rate with the
+-2 band. Each computed profile (the JSON's "profiles") gets its own figure beside it, fig_profile_<parameter>.png:
Delta chi^2 against the parameter (log axis for a ln-fitted one spanning more than a decade), the 3.84 line and the Fisher parabola, all drawn
over the profile's computed grid only; a flat profile says so on the figure. The parameter table and the
identifiability statements are text on the page, not drawn here.

    python3 fit_draw.py fit_page.json fig_fit.png [drawn.json]

prints what was drawn as JSON (and writes it to drawn.json when given): {"figures": n, "panels": [{"observable",
"viscosity", "points", "curve_span"}],
"profiles": [{"parameter", "file", "points", "span", "fisher_span", "threshold_span", "xlim", "xscale", "title",
"flat"}]}: the spans
are read back from the lines matplotlib holds."""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LABELS = {"inclination_angle": "inclination angle", "swinging_amplitude": "swinging amplitude",
          "swinging_frequency": "swinging frequency", "tank_treading_frequency": "tank-treading frequency"}


def draw_fit(data):
    """The figure of `data` (fit_page_json) and the record of what was drawn."""
    observables = []
    for p in data["panels"]:
        if p["observable"] not in observables:
            observables.append(p["observable"])
    fig, axes = plt.subplots(2, len(observables), figsize=(5.5 * len(observables), 7), squeeze=False,
                             gridspec_kw={"height_ratios": [3, 1.3]}, sharex="col")
    viscosities = sorted({p["viscosity"] for p in data["panels"]})
    colour = {v: f"C{i % 10}" for i, v in enumerate(viscosities)}
    drawn = []
    for col, name in enumerate(observables):
        ax, res = axes[0][col], axes[1][col]
        for p in (q for q in data["panels"] if q["observable"] == name):
            c = colour[p["viscosity"]]
            label = f"$\\eta$ = {p['viscosity'] * 1e3:.3g} mPa s"
            x = [q["shear_rate"] for q in p["points"]]
            ax.errorbar(x, [q["value"] for q in p["points"]], yerr=[q["uncertainty"] for q in p["points"]],
                        fmt="o", ms=4, color=c, capsize=2, label=label)
            span = p["curve"]["span"]
            if span is not None:
                lo, hi = span
                cx, cy = [], []
                for r, v in zip(p["curve"]["shear_rate"], p["curve"]["value"]):
                    inside = lo <= r <= hi
                    cx.append(r if inside else math.nan)
                    cy.append(v if inside and v is not None else math.nan)
                ax.plot(cx, cy, "-", color=c, lw=1.5)
            rx = [q["shear_rate"] for q in p["points"] if q["residual"] is not None]
            ry = [q["residual"] for q in p["points"] if q["residual"] is not None]
            res.plot(rx, ry, "o", ms=4, color=c)
            drawn.append({"observable": name, "viscosity": p["viscosity"], "points": len(x), "curve_span": span})
        unit = next(p["unit"] for p in data["panels"] if p["observable"] == name)
        ax.set_ylabel(f"{LABELS.get(name, name)} [{unit}]")
        ax.set_xscale("log")
        ax.legend(fontsize=8)
        res.axhspan(-2, 2, color="0.9", lw=0)
        res.axhline(0, color="0.4", lw=0.8)
        res.set_xscale("log")
        res.set_xlabel("shear rate [1/s]")
        res.set_ylabel("(predicted $-$ observed)/$\\sigma$")
    chi2 = data.get("chi2")
    fig.suptitle(f"fit: {data['status']}, $\\chi^2$ = {chi2:.4g} over {data['rows']} rows ({data['dof']} dof)"
                 if chi2 is not None else f"fit: {data['status']}")
    fig.tight_layout()
    return fig, drawn


def _span(xs):
    """[first, last] of the x values a line was drawn over (the grid is ascending)."""
    xs = [float(x) for x in xs]
    return [min(xs), max(xs)]


def draw_profile(p):
    """The figure of one profile (an entry of the JSON's "profiles") and the record of what was drawn."""
    fig, ax = plt.subplots(figsize=(6, 4.5))
    pts = [(x, d) for x, d in zip(p["x"], p["delta_chi2"]) if d is not None]
    (line,) = ax.plot([x for x, _ in pts], [d for _, d in pts], "o-", ms=4, color="C0", label="profile")
    lo, hi = p["span"]
    threshold = ax.hlines(p["threshold"], lo, hi, colors="C3", linestyles=":",
                          label=f"$\\Delta\\chi^2$ = {p['threshold']:.2f} (95 %)")
    fisher_span = None
    if p["fisher"] is not None:
        fx, fd = p["fisher"]["x"], p["fisher"]["delta_chi2"]
        (parabola,) = ax.plot(fx, fd, "--", color="0.4", label="Fisher parabola")
        fisher_span = _span(parabola.get_xdata())
    if p["value"] is not None:
        ax.axvline(p["value"], color="0.6", lw=0.8)
    if p["scale"] == "log" and hi > 10 * lo:  # a narrower span reads better on a linear axis
        ax.set_xscale("log")
    ax.set_xlim(lo, hi)
    # The parabola can rise far above the profile where the grid doubles its steps: the profile sets the scale.
    top = max([d for _, d in pts] + [2 * p["threshold"]])
    ax.set_ylim(min([0.0] + [d for _, d in pts]) - 0.05 * top, 1.1 * top)
    unit = f" [{p['unit']}]" if p["unit"] else ""
    ax.set_xlabel(f"{p['parameter']}{unit}")
    ax.set_ylabel("$\\Delta\\chi^2$ (profile $-$ minimum)")
    title = f"profile of {p['parameter']}"
    if p["flat"]:
        title += ": flat, $\\Delta\\chi^2$ < 3.84 over the whole range (not identifiable)"
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    segment = threshold.get_segments()[0]
    drawn = {"parameter": p["parameter"], "points": len(pts), "span": _span(line.get_xdata()),
             "fisher_span": fisher_span, "threshold_span": _span([segment[0][0], segment[-1][0]]),
             "xlim": list(ax.get_xlim()), "xscale": ax.get_xscale(), "title": ax.get_title(), "flat": p["flat"]}
    return fig, drawn


def main(argv):
    if len(argv) not in (3, 4):
        raise SystemExit(__doc__)
    with open(argv[1], encoding="utf-8") as f:
        data = json.load(f)
    fig, drawn = draw_fit(data)
    fig.savefig(argv[2], dpi=100)
    plt.close(fig)
    profiles = []
    for p in data.get("profiles", []):
        fig, record = draw_profile(p)
        record["file"] = f"fig_profile_{p['parameter']}.png"
        fig.savefig(os.path.join(os.path.dirname(os.path.abspath(argv[2])), record["file"]), dpi=100)
        plt.close(fig)
        profiles.append(record)
    record = json.dumps({"figures": 1 + len(profiles), "panels": drawn, "profiles": profiles})
    if len(argv) == 4:
        with open(argv[3], "w", encoding="utf-8") as f:
            f.write(record + "\n")
    print(record)


if __name__ == "__main__":
    main(sys.argv)

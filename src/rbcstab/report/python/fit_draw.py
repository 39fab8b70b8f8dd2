"""Draws a fit's page figure from its JSON (report/fit_page.hpp: fit_page_json) and nothing else: per observable,
the observations against shear rate (log axis) with their error bars, one colour per outer viscosity, and the model
curve at the estimate drawn only over the span the model computed (the JSON's curve.span; grid points without a
prediction are gaps); below, the normalised residuals (predicted - observed)/sigma against shear rate with the
+-2 band. The parameter table and the identifiability statements are text on the page, not drawn here.

    python3 fit_draw.py fit_page.json fig_fit.png

prints what was drawn as JSON: {"figures": 1, "panels": [{"observable", "viscosity", "points", "curve_span"}]}."""
import json
import math
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


def main(argv):
    if len(argv) != 3:
        raise SystemExit(__doc__)
    with open(argv[1], encoding="utf-8") as f:
        data = json.load(f)
    fig, drawn = draw_fit(data)
    fig.savefig(argv[2], dpi=100)
    plt.close(fig)
    print(json.dumps({"figures": 1, "panels": drawn}))


if __name__ == "__main__":
    main(sys.argv)

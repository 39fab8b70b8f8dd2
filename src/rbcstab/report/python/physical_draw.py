"""Draws the physical phase diagram (verdict/physical_map.hpp) into a matplotlib Axes from its JSON (verdict_io's
to_json with the observations): outer viscosity (mPa s) against shear rate (1/s), both logarithmic, each boundary
where it was found, its band, the boundaries outside the searched range hatched, the published observations over
it. Shared by rbcstab_report.py (the [physical_map] panel's figure) and the Python package (PhysicalMap.plot), so
both draw by the same rules. No backend or rcParams are set here: the caller owns the figure."""
import math

import numpy as np

BOUNDARIES = {"tumbling_to_swinging": ("C0", "tumbling \u2192 swinging (in plane)"),
              "onset_out_of_plane": ("C3", "l \u2265 3 onset, out of plane"),
              "onset_in_plane": ("C1", "l \u2265 3 onset, in plane")}


def rates(data, name):
    """Per viscosity, the boundary's shear rate (1/s; NaN where not found) and its band (lo, hi; NaN where no cell
    found it)."""
    cols = data["columns"]
    rate = np.array([c[name]["shear_rate"] if c[name]["found"] else math.nan for c in cols])
    lo = np.array([c[name]["band"]["lo"] if c[name]["band"]["found"] else math.nan for c in cols])
    hi = np.array([c[name]["band"]["hi"] if c[name]["band"]["found"] else math.nan for c in cols])
    return rate, lo, hi


def drawn_points(data):
    """The boundaries' drawn points (eta_ex [mPa s], shear rate [1/s], boundary), for the page's hover values."""
    eta = [c["viscosity"] * 1e3 for c in data["columns"]]
    points = []
    for name, (_, label) in BOUNDARIES.items():
        rate = rates(data, name)[0]
        points += [[e, r, label] for e, r in zip(eta, rate) if math.isfinite(r)]
    return ["eta_ex [mPa s]", "shear rate [1/s]", "boundary"], points


def draw_physical_map(ax, data, experiments=True, bands=True, title=None):
    """The map `data` (its JSON) on ax; a boundary not found at a viscosity draws no line across it. The published
    observations (data["experiments"]): a stress as the line eta_ex gamma = stress, a point or a rate range at its
    viscosity; order-of-magnitude statements with a factor-3 band. Returns ax."""
    eta = np.array([c["viscosity"] for c in data["columns"]]) * 1e3
    for name, (color, label) in BOUNDARIES.items():
        rate, lo, hi = rates(data, name)
        if not np.any(np.isfinite(rate)) and not np.any(np.isfinite(lo)):
            continue
        ax.plot(eta, rate, "-o", color=color, ms=3, label=label)
        if bands:
            ax.fill_between(eta, lo, hi, color=color, alpha=0.15, lw=0)
    # A boundary below the searched range: its upper regime holds at every rate searched there (hatched).
    rmin, rmax = data["shear_rate_range"]
    for name, (color, label) in BOUNDARIES.items():
        below = np.array([c[name].get("side") == "below" for c in data["columns"]])
        if below.any():
            what = ("swinging at every rate searched" if name == "tumbling_to_swinging" else
                    f"l \u2265 3 unstable at every rate searched ({label.split(', ')[-1]})")
            ax.fill_between(eta, rmin, rmax, where=below, color=color, alpha=0.08, hatch="//", lw=0, label=what)
    if experiments:
        markers = iter("sD^v<>")
        for e in data.get("experiments", []):
            label = f"{e['source']}: {e['observation']}"
            if e["kind"] == "stress":
                x = np.geomspace(eta.min(), eta.max(), 50)
                y = e["stress"] / (x * 1e-3)
                ax.plot(x, y, "k--", lw=1, label=label)
                if e["precision"] == "order":
                    ax.fill_between(x, y / 3, y * 3, color="k", alpha=0.06, lw=0)
            else:
                x = e["viscosity"] * 1e3
                lo, hi = e["shear_rate_lo"], e["shear_rate_hi"]
                if e["precision"] == "order":
                    lo, hi = lo / 3, hi * 3
                mid = math.sqrt(lo * hi) if e["kind"] == "rate_range" else e["shear_rate_lo"]
                ax.errorbar([x], [mid], yerr=[[mid - lo], [hi - mid]], fmt=next(markers, "o"), color="k",
                            capsize=3, ms=5, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("outer viscosity \u03b7_ex [mPa s]")
    ax.set_ylabel("shear rate \u03b3\u0307 [1/s]")
    ax.set_title(title or "Physical phase diagram (bands: published ranges of the cell's properties)", fontsize=9)
    ax.legend(fontsize=7, loc="best")
    return ax

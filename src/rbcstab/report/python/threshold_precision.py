#!/usr/bin/env python3
"""Threshold-precision figure: error of the located critical ln C against cost (verdict evaluations and
wall time), one line per (predictor, method, rtol). Usage: threshold_precision.py TABLE.csv OUT.png [TITLE]"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from png_output import save_png  # noqa: E402


def main():
    path, out = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) > 3 else "threshold precision"
    # Rows without an error (an empty field: the predictor's reference failed) have nothing to draw.
    rows = [r for r in csv.DictReader(open(path)) if r["status"] == "ok" and r["error"] != ""]
    series = {}
    for r in rows:
        rtol = float(r["rtol"])
        label = f'{r["predictor"]} / {r["method"]}' + (f" rtol {rtol:.0e}" if rtol > 0 else "")
        series.setdefault(label, []).append(r)
    fig, axes = plt.subplots(1, 2, figsize=(12, 5), constrained_layout=True)
    colors = {"asymptotic": "tab:blue", "finite_horizon": "tab:green", "simulation": "tab:red"}
    styles = {"bisection": "-", "grid": "--", "continuation": ":", "closed_form": ""}
    markers = ["o", "s", "^", "D", "v", "P"]
    for i, (label, pts) in enumerate(sorted(series.items())):
        pts.sort(key=lambda r: float(r["evaluations"]))
        err = [max(float(r["error"]), 1e-16) for r in pts]
        for ax, key in zip(axes, ["evaluations", "seconds"]):
            cost = [max(float(r[key]), 1e-6) for r in pts]
            ax.loglog(cost, err, linestyle=styles[pts[0]["method"]], marker=markers[i % len(markers)],
                      color=colors.get(pts[0]["predictor"], "black"), label=label, markersize=4)
    axes[0].set_xlabel("verdict evaluations")
    axes[1].set_xlabel("wall time [s]")
    for ax in axes:
        ax.set_ylabel(r"|ln C located $-$ ln C reference|")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7, ncol=2)
    fig.suptitle(title)
    save_png(fig, out, 100)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Work-precision figure: achieved error against cost (RHS evaluations and wall time), one line per
(level, stepper). Usage: work_precision.py TABLE.csv OUT.png [TITLE]"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from png_output import save_png  # noqa: E402


def main():
    path, out = sys.argv[1], sys.argv[2]
    title = sys.argv[3] if len(sys.argv) > 3 else "work-precision"
    rows = list(csv.DictReader(open(path)))
    series = {}
    for r in rows:
        if r["status"] != "success":
            continue
        series.setdefault((r["level"], r["stepper"]), []).append(r)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), constrained_layout=True)
    styles = ["-", "--", "-.", ":"]
    markers = ["o", "s", "^", "D", "v", "P", "X", "*"]
    for i, ((level, stepper), pts) in enumerate(sorted(series.items())):
        pts.sort(key=lambda r: float(r["rtol"]), reverse=True)
        err = [max(float(r["error_Delta"]), 1e-17) for r in pts]
        for ax, key in zip(axes, ["rhs_evaluations", "seconds"]):
            cost = [max(float(r[key]), 1e-7) for r in pts]
            ax.loglog(cost, err, linestyle=styles[i % len(styles)], marker=markers[i % len(markers)],
                      color=str(0.15 + 0.6 * (i % 4) / 3), label=f"{level} / {stepper}")
            bad = [(c, e) for c, e, r in zip(cost, err, pts) if r["verdict_changed"] == "1"]
            if bad:
                ax.scatter(*zip(*bad), s=90, facecolors="none", edgecolors="black", zorder=5)
    axes[0].set_xlabel("right-hand-side evaluations")
    axes[1].set_xlabel("wall time per run [s]")
    for ax in axes:
        ax.set_ylabel(r"max$_l$ relative error of $\Delta_l(T)$")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=8, title="level / stepper (circled: $l_\\Delta$ changed)", title_fontsize=8)
    fig.suptitle(title)
    save_png(fig, out, 110)


if __name__ == "__main__":
    main()

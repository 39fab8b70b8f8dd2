"""Draws docs/figures/physical_map.png: the physical phase diagram of a healthy cell (docs/units.md) with the
published observations. Run from the build tree:
    PYTHONPATH=build/release/python /usr/bin/python3 python/tools/physical_map_figure.py docs/figures/physical_map.png
It prints the map's columns and assumption checks as JSON to stdout. The figure shows the nominal cell only: the
bands (spreads="healthy", 13 cells per viscosity) cost about an hour of CPU with the onset searches, so the docs
figure leaves them out and says so in its title; rbcstab.physical_map computes them when asked."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import rbcstab  # noqa: E402


def main(out):
    cell = rbcstab.Scene(shear_rate="10/s", viscosity="25 mPa s", area="134 um^2", volume="94 um^3",
                         bending_modulus="2e-19 J", shear_modulus="6 uN/m", inner_viscosity="6 mPa s", Delta0=0.5)
    m = rbcstab.physical_map(cell, viscosity=(1e-3, 5e-2), viscosities=5, shear_rate=(1e-1, 1e5),
                             samples_per_decade=3, rtol=1e-2, onset=True, spreads=None, threads=0, progress=True)
    fig, ax = plt.subplots(figsize=(7.2, 5.2))
    m.plot(ax=ax, title="Physical phase diagram of a healthy cell (nominal cell; no bands computed for this figure)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    d = m.to_dict()
    print(json.dumps({"columns": d["columns"], "assumptions": d["assumptions"]}, indent=1))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "physical_map.png")

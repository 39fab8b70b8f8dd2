"""Draws docs/figures/physical_map.png: the physical phase diagram of a healthy cell (docs/units.md) with the
healthy-cell bands and the published observations. Run from the build tree:
    PYTHONPATH=build/release/python /usr/bin/python3 python/tools/physical_map_figure.py docs/figures/physical_map.png
It prints the map's JSON summary (per viscosity the nominal boundaries and bands) to stdout."""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import rbcstab  # noqa: E402


def main(out):
    cell = rbcstab.Scene(shear_rate="10/s", viscosity="25 mPa s", area="134 um^2", volume="94 um^3",
                         bending_modulus="2e-19 J", shear_modulus="6 uN/m", inner_viscosity="6 mPa s", Delta0=0.5)
    m = rbcstab.physical_map(cell, viscosity=(1e-3, 5e-2), viscosities=7, shear_rate=(1e-2, 1e5),
                             samples_per_decade=4, rtol=1e-2, onset=True, progress=True)
    fig, ax = plt.subplots(figsize=(7.2, 5.2))
    m.plot(ax=ax)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    d = m.to_dict()
    print(json.dumps({"columns": d["columns"], "assumptions": d["assumptions"]}, indent=1))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "physical_map.png")

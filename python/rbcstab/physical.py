"""The physical phase diagram: a cell given by its measured properties, its regimes in the plane of the outer
viscosity (mPa s) and the shear rate (1/s), with bands from the published ranges of its properties and the
published observations drawn over it (library: verdict/physical_map.hpp; docs/units.md)."""

import json

import numpy as np

from . import _args, _rbcstab
from ._drawing import drawing_module, keep_legends_inside
from .progress import progress_bar

__all__ = ["PhysicalMap", "physical_map"]


def _range(name, v):
    try:
        lo, hi = (float(x) for x in v)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a pair (min, max) of numbers, not {v!r}") from None
    return lo, hi


def physical_map(scene, viscosity=(1e-3, 5e-2), viscosities=9, shear_rate=(1e-1, 1e5), samples_per_decade=6,
                 rtol=1e-3, onset=True, spreads="healthy", threads=0, experiments=None, progress=False):
    """The regimes of a physical scene's cell over outer viscosity x shear rate.

    scene: a Scene with a complete [physical] cell including inner_viscosity (lambda follows eta_ex).
    viscosity: (min, max) outer viscosity eta_ex in Pa s, > 0; viscosities: how many, log-spaced, an integer in
    [1, 1000]. shear_rate: (min, max) in 1/s, 0 < min < max: the range both searches scan, samples_per_decade (an
    integer in [1, 100]) log-spaced samples, then bisection in ln(shear rate) to hi/lo - 1 <= rtol (dimensionless,
    in [1e-12, 0.1]). The reduced regime is stiff at small capillary number, so the cost grows as 1/min: the
    default starts at 0.1/s.
    Per viscosity: the tumbling -> swinging shear rate of the in-plane cell (reduced dynamics) and, with
    onset=True, the l >= 3 onset for each rest orientation (the summary's search). spreads: "healthy" (the
    healthy-cell ranges of docs/units.md for the inputs the cell has), None, or a list of (key, lo, hi[, source])
    with key a [physical] key (SI) or "Delta"/"Delta0": each boundary's band is its min and max over the cell at
    each range's ends, one key at a time. experiments: a CSV of observations (default: the shipped
    data/experiments.csv). threads: an integer in [0, 4096], 0 = all cores (the result does not depend on it).
    progress: True, a callable f(done, total, eta) or a tqdm bar, counting cells x viscosities. Ctrl-C raises
    KeyboardInterrupt. Cost: about 0.1-1 s of CPU per cell and viscosity for the tumbling search; the onset search
    costs more."""
    _args.scene(scene)
    lo_v, hi_v = _range("viscosity", viscosity)
    lo_r, hi_r = _range("shear_rate", shear_rate)
    healthy = False
    extra = []
    if isinstance(spreads, str):
        if spreads != "healthy":
            raise ValueError(f"spreads = {spreads!r}: must be 'healthy', None or a list of (key, lo, hi[, source])")
        healthy = True
    elif spreads is not None:
        for s in spreads:
            if not isinstance(s, (tuple, list)) or len(s) not in (3, 4):
                raise TypeError(f"spreads: each item must be (key, lo, hi[, source]), not {s!r}")
            extra.append((str(s[0]), float(s[1]), float(s[2]), str(s[3]) if len(s) == 4 else ""))
    args = dict(min_viscosity=lo_v, max_viscosity=hi_v, viscosities=int(viscosities), min_rate=lo_r, max_rate=hi_r,
                samples_per_decade=int(samples_per_decade), rtol=float(rtol), onset=bool(onset),
                healthy_spreads=healthy, spreads=extra, threads=int(threads),
                experiments="" if experiments is None else str(experiments))
    bar = progress_bar(progress, "rbcstab physical_map", "cells")
    if bar is None:
        data = _rbcstab.physical_map(scene, **args)
    else:
        with bar:
            data = _rbcstab.physical_map(scene, progress=bar, **args)
    return PhysicalMap(data)


class PhysicalMap:
    """The physical phase diagram (``rbcstab.physical_map``). ``viscosity`` (Pa s) and, per boundary name
    (tumbling_to_swinging, onset_out_of_plane, onset_in_plane), ``rate(name)`` in 1/s (NaN where not found) and
    ``band(name)`` (lo, hi; NaN where no cell found it); ``assumptions``: where the model's assumptions fail
    (value, bound, holds, meaning); ``experiments``: the observations drawn over it. ``to_dict()`` is the JSON."""

    def __init__(self, data):
        self._data = data

    def to_dict(self):
        """The map's JSON: cell (SI), spreads, columns (per viscosity: lambda, Lambda and each boundary with its
        bracket and band), assumptions, experiments, experiments_file, evaluations."""
        return json.loads(json.dumps(self._data))

    @property
    def viscosity(self):
        """The outer viscosities eta_ex of the columns, in Pa s (increasing)."""
        return np.array([c["viscosity"] for c in self._data["columns"]])

    def _check(self, name):
        names = drawing_module("physical_draw").BOUNDARIES
        if name not in names:
            raise ValueError(f"boundary {name!r}: must be one of {', '.join(names)}")

    def rate(self, name):
        """Per viscosity, the nominal cell's shear rate (1/s) at boundary `name` (tumbling_to_swinging,
        onset_out_of_plane, onset_in_plane): the bracket's upper end; NaN where it was not found."""
        self._check(name)
        return drawing_module("physical_draw").rates(self._data, name)[0]

    def band(self, name):
        """Per viscosity, (lo, hi) in 1/s: the boundary's min and max over the cells at the spreads' ends; NaN
        where no cell found it."""
        self._check(name)
        return drawing_module("physical_draw").rates(self._data, name)[1:]

    @property
    def assumptions(self):
        """Where the model's assumptions fail: dicts with assumption, quantity, value, bound, holds, meaning."""
        return [dict(a) for a in self._data["assumptions"]]

    @property
    def experiments(self):
        """The published observations drawn over the map (data/experiments.csv rows: source, reference,
        observation, kind, viscosity [Pa s], shear_rate_lo/hi [1/s], stress [Pa], precision, basis)."""
        return [dict(e) for e in self._data["experiments"]]

    def __repr__(self):
        v = self.viscosity * 1e3
        found = int(np.sum(np.isfinite(self.rate("tumbling_to_swinging"))))
        failing = [a["assumption"] for a in self._data["assumptions"] if not a["holds"]]
        return (f"<rbcstab PhysicalMap: {len(v)} viscosities in [{v.min():.3g}, {v.max():.3g}] mPa s, "
                f"tumbling->swinging found at {found}; assumptions failing: {', '.join(failing) or 'none'}>")

    def plot(self, ax=None, experiments=True, bands=True, title=None):
        """Outer viscosity (mPa s) against shear rate (1/s), both logarithmic: each boundary where it was found
        (no line across a viscosity where it was not), its band shaded, the published observations over it
        (order-of-magnitude statements as a factor-3 band). Returns the Axes."""
        import matplotlib.pyplot as plt

        if ax is None:
            _, ax = plt.subplots(figsize=(6.4, 4.8))
        drawing_module("physical_draw").draw_physical_map(ax, self._data, experiments, bands, title)
        keep_legends_inside(ax)
        return ax

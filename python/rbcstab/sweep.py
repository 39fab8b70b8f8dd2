"""Parameter-plane sweeps: phase diagrams by direct simulation (``rbcstab diagram``), stability boundaries traced
by continuation (``rbcstab trace``) and the Fig. 6e table (``rbcstab post --fig6e``).

Each result's ``to_dict()`` is the document the CLI writes for the same call (``diagram``: its PREFIX.json;
``trace``: its PREFIX.json; ``fig6e``: ``post --fig6e --json``), ``save(prefix)`` writes the CLI's two files, and
``plot(ax=None)`` draws with the report's drawing code (the report's phase-diagram colouring and lines, its Fig. 6(e)).
"""
import html
import json
import os

import numpy as np

from . import _args, _rbcstab, _tables
from ._drawing import drawing_module, keep_legends_inside
from .progress import progress_bar

__all__ = ["Diagram", "Trace", "Fig6eTable", "diagram", "trace", "fig6e"]


# ------------------------------------------------------------------------------------------- arguments
_scene = _args.scene
_integer = _args.integer
_number = _args.number
_flag = _args.flag
_sequence = _args.sequence
_names = _args.names
_numbers = _args.numbers_
_integers = _args.integers
_path = _args.path


def _text(name, value, default=""):
    return _args.text(name, value, default)


def _shard(shard):
    """'k/n' from (k, n) or 'k/n' (the library checks 0 <= k < n)."""
    if shard is None:
        return "0/1"
    if isinstance(shard, str):
        return shard
    k_n = _integers("shard", shard)
    if len(k_n) != 2:
        raise ValueError(f"shard takes two integers k, n (or 'k/n'), got {shard!r}")
    return f"{k_n[0]}/{k_n[1]}"


# ------------------------------------------------------------------------------------------- drawing
def phase_draw():
    return drawing_module("phase_draw")


def _axes(ax):
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt
    return plt.gca()


def _numbers_repr(values):
    return "[" + ", ".join(f"{v:.6g}" for v in values) + "]"


# ------------------------------------------------------------------------------------------- results
class _Document:
    """A result whose document (self._doc) and files (self._data: the compiled result) are the CLI's."""

    def to_dict(self):
        """Exactly the JSON the CLI writes to PREFIX.json for the same call."""
        return json.loads(json.dumps(self._doc))

    def to_csv(self):
        """The CLI's PREFIX.csv text."""
        return self._data.csv()

    def save(self, prefix):
        """Writes PREFIX.csv and PREFIX.json as the CLI's ``--out PREFIX`` does (both or neither)."""
        self._data.save(_path("prefix", prefix))


# ------------------------------------------------------------------------------------------- diagram
class Diagram(_Document):
    """A phase diagram by direct simulation (``rbcstab diagram``).

    ``axes`` names the grid's two axes (x, y); ``x`` and ``y`` are their values (also as attributes named by
    the axes, e.g. ``d.lnB``, ``d.lnC``). Per-point results are 2-D arrays of shape ``(len(y), len(x))``
    (row j, column i is the point (x[i], y[j]); ``imshow(..., origin="lower")`` orientation): ``l_Delta``,
    ``verdict`` ('stable', 'unstable', 'failed'), ``status``, ``reason``, ``growth``, ``oscillating``,
    ``sigma_final``, ``t_reached``, ``steps``, ``failed_steps``, ``rhs_evaluations`` and ``seconds`` (unless
    include_seconds=False). Points another shard computes hold -1, NaN or ''.
    ``to_dict()`` is the CLI's PREFIX.json for the same diagram; ``save(prefix)`` writes PREFIX.csv and
    PREFIX.json as the CLI does."""

    _ARRAYS = ("l_Delta", "verdict", "status", "reason", "growth", "oscillating", "sigma_final", "t_reached", "steps",
               "failed_steps", "rhs_evaluations", "seconds")

    def __init__(self, data):
        self._data = data
        self._doc = data.document()
        self.axes = tuple(data.axes)
        arrays = data.arrays()
        self.x = arrays.pop("x")
        self.y = arrays.pop("y")
        self._arrays = arrays
        for name, a in arrays.items():
            a.flags.writeable = False  # shared with to_dict()'s numbers: read-only keeps them equal
        self.x.flags.writeable = False
        self.y.flags.writeable = False

    def __getattr__(self, name):
        d = self.__dict__
        if name in d.get("_arrays", {}):
            return d["_arrays"][name]
        axes = d.get("axes", ())
        if name in axes:
            return d["x"] if name == axes[0] else d["y"]
        raise AttributeError(f"Diagram has no attribute {name!r}")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._arrays) | set(self.axes))

    def to_pandas(self):
        """A tidy DataFrame, one row per grid point: the two axes' values, then every per-point array."""
        return _tables.diagram_frame(self)

    def to_xarray(self):
        """An xarray Dataset over dimensions (y-axis, x-axis): the axes as coordinates (units and descriptions
        from the parameter table in attrs), every per-point array as a data variable."""
        return _tables.diagram_dataset(self)

    @property
    def shape(self):
        """(len(y), len(x)): the shape of the per-point arrays."""
        return (len(self.y), len(self.x))

    @property
    def complete(self):
        """Whether every grid point is held (a shard holds only its own)."""
        return self._doc["complete"]

    @property
    def config_hash(self):
        """FNV-1a 64 hash (hex) of what decides the points: a journal or shard with another hash is not merged."""
        return self._doc["config_hash"]

    @property
    def classifier(self):
        """The l_Delta rule: 'final' (Fig. 4), 'tail' (App. E) or 'auto' (tail mean if the run oscillates)."""
        return self._doc["diagram"]["classifier"]

    @property
    def summary(self):
        """The document's summary: point counts by verdict and by l_Delta, failed indices, cost."""
        return self._doc["summary"]

    @property
    def agreement(self):
        """Every predictor's agreement with the simulated points (None for a shard)."""
        return self._doc.get("agreement")

    @property
    def computed(self):
        """Points simulated in this call (the others came back from the journal)."""
        return self._data.computed

    @property
    def resumed(self):
        """How many points came back from the journal instead of being simulated in this call."""
        return self._data.resumed

    @property
    def rejected(self):
        """Journal records dropped and recomputed ('journal:line: why')."""
        return list(self._data.rejected)

    def point_scene(self, i, j):
        """The scene of grid point (x[i], y[j]) as the diagram ran it (its L and integrator included):
        ``rbcstab.simulate(d.point_scene(i, j), model="modal")`` repeats that point's run."""
        i, j = _integer("i", i), _integer("j", j)
        if not (0 <= i < len(self.x) and 0 <= j < len(self.y)):
            raise ValueError(f"(i, j) = ({i}, {j}) is outside the grid: must be in [0, {len(self.x)}) x "
                             f"[0, {len(self.y)})")
        return self._data.point_scene(j * len(self.x) + i)

    def __repr__(self):
        s = self.summary
        v = s["verdicts"]
        modes = ", ".join(f"l_Delta={k}: {n}" for k, n in sorted(s["l_Delta"].items(), key=lambda kv: int(kv[0])))
        shard = self._doc.get("shard")
        part = f", shard {shard['k']}/{shard['n']}" if shard else ""
        return (f"<rbcstab Diagram {self.axes[0]} x {self.axes[1]}: {len(self.x)} x {len(self.y)} points{part}, "
                f"{v.get('stable', 0)} stable, {v.get('unstable', 0)} unstable, {v.get('failed', 0)} failed"
                f"{' (' + modes + ')' if modes else ''}>")

    def _repr_html_(self):
        d = self._doc["diagram"]
        rows = [("axes", f"{self.axes[0]} in [{d['x']['min']:g}, {d['x']['max']:g}] ({d['x']['count']}), "
                         f"{self.axes[1]} in [{d['y']['min']:g}, {d['y']['max']:g}] ({d['y']['count']})"),
                ("scene", self._doc["scene"].get("name", "")), ("L", self._doc.get("L")),
                ("classifier", d["classifier"]), ("points", self.summary["points"]),
                ("verdicts", self.summary["verdicts"]), ("l_Delta", self.summary["l_Delta"])]
        a = self.agreement
        if isinstance(a, dict) and a.get("verdict_fraction") is not None:
            rows.append(("asymptotic criterion agrees (verdict / mode)",
                         f"{100 * a['verdict_fraction']:.1f}% / {100 * a['mode_fraction']:.1f}%"))
        body = "".join(f"<tr><th style='text-align:left'>{html.escape(str(k))}</th>"
                       f"<td style='text-align:left'>{html.escape(str(v))}</td></tr>" for k, v in rows)
        return f"<b>rbcstab Diagram</b><table>{body}</table>"

    def plot(self, ax=None, trace=None, analytic_lines=True, title=None):
        """The report's phase diagram on ax (default: the current axes): cells coloured by l_Delta (white:
        stable), the paper's analytic lines on top (analytic_lines=False: none) and, given a Trace of the same
        plane, its traced boundary. Returns ax."""
        ax = _axes(ax)
        if trace is not None:
            if not isinstance(trace, Trace):
                raise TypeError(f"trace must be a rbcstab.Trace, got {type(trace).__name__}")
            if trace.axes != self.axes:
                raise ValueError(f"trace is of the plane {trace.axes}, the diagram of {self.axes}")
            curves, labels = trace._overlay["curves"], trace._overlay.get("axes")
            if not analytic_lines:
                curves = [c for c in curves if c.get("color") == "black"]  # the traced pieces alone
        else:
            curves = self._overlay()["curves"] if analytic_lines else []
            labels = self._overlay().get("axes")
        xs, ys = np.meshgrid(self.x, self.y)
        phase_draw().draw_phase_diagram(ax, xs.ravel().tolist(), ys.ravel().tolist(),
                                            self.l_Delta.ravel().tolist(), self.axes[0], self.axes[1], curves,
                                            title=title, labels=labels)
        return keep_legends_inside(ax)

    def _overlay(self):
        if "_overlay_cache" not in self.__dict__:
            self.__dict__["_overlay_cache"] = self._data.overlay()
        return self.__dict__["_overlay_cache"]


def diagram(scene, axes=None, counts=None, threads=0, progress=True, *, x_range=None, y_range=None,
            classifier=None, alpha_fixed=None, schedule="dynamic", shard=None, journal=None, sync_interval=1.0,
            include_seconds=True, finite_horizon_agreement=True):
    """A phase diagram by direct simulation over two parameter axes (``rbcstab diagram``): every grid point is
    one modal-level run of the scene classified by l_Delta.

    axes      two axis names (x, y) from the parameter table (lambda, Delta, Delta0, alpha, lnB, lnC, beta, shear_rate);
              default: the scene's [diagram] table, else ("lnB", "lnC")
    counts    grid values (nx, ny), integers in [1, 1000000]; default: the table's, else (64, 64)
    threads   worker threads, an integer in [0, 4096] (0: all cores); the result does not depend on it
    progress  True: a progress bar (tqdm if importable, else text on stderr); False: none; or a callable
              f(done, total, eta)
    x_range, y_range   (min, max) of each axis, finite (default: the table's, else (-1, 6) and (-5.5, 2))
    classifier         'auto' | 'final' | 'tail' (l_Delta from Delta_l(T) or the tail mean; default 'auto')
    alpha_fixed        hold alpha = B/C at this value over the plane (>= 0; 0: off)
    schedule           'dynamic' | 'static' point scheduling over the threads
    shard              (k, n) or 'k/n': compute only the points with index % n == k (combine with rbcstab merge)
    journal            a checkpoint file (the CLI's PREFIX.journal): finished points are appended as they
                       complete, and a later call with the same journal and configuration resumes from them
    sync_interval      fdatasync the journal at most this often [s], finite and >= 0
    include_seconds    False: no per-point wall-clock seconds (the CLI's --no-seconds)
    finite_horizon_agreement  False: skip the finite-horizon predictor in the agreement block

    Ctrl-C raises KeyboardInterrupt within about a second; the journal, if any, keeps every finished point and
    stays resumable. The GIL is released while the points run."""
    scene = _scene(scene)
    args = dict(
        axes=_names("axes", axes), x_range=_numbers("x_range", x_range), y_range=_numbers("y_range", y_range),
        counts=_integers("counts", counts), classifier=_text("classifier", classifier),
        alpha_fixed=None if alpha_fixed is None else _number("alpha_fixed", alpha_fixed),
        threads=_integer("threads", threads), schedule=_text("schedule", schedule), shard=_shard(shard),
        journal=_path("journal", journal), sync_interval=_number("sync_interval", sync_interval),
        include_seconds=_flag("include_seconds", include_seconds),
        finite_horizon_agreement=_flag("finite_horizon_agreement", finite_horizon_agreement))
    bar = progress_bar(progress, "rbcstab diagram", "points")
    if bar is None:
        return Diagram(_rbcstab.diagram(scene, progress=None, **args))
    with bar:
        return Diagram(_rbcstab.diagram(scene, progress=bar, **args))


# ------------------------------------------------------------------------------------------- trace
class TraceCurve:
    """One piece of a traced boundary: mode ``l``, its ``chain`` (pieces of one connected curve share it), the
    ``criterion``, and numpy arrays ``x``, ``y`` (ordered along the chain), ``mu`` (the residual), ``sigma_R``,
    ``sigma_c``."""

    def __init__(self, d):
        self.l = d["l"]
        self.chain = d["chain"]
        self.criterion = d["criterion"]
        self.x, self.y, self.mu, self.sigma_R, self.sigma_c = d["x"], d["y"], d["mu"], d["sigma_R"], d["sigma_c"]

    def __len__(self):
        return len(self.x)

    def __repr__(self):
        return f"<TraceCurve l={self.l} chain={self.chain}: {len(self.x)} points>"


class Trace(_Document):
    """A stability boundary traced as curves (``rbcstab trace``): ``curves`` (TraceCurve pieces with numpy
    arrays x, y, mu, sigma_R, sigma_c), ``corners`` (numpy arrays x, y, l_from, l_to: where the active mode
    changes), ``analytic_lines`` (the paper's lines on the plane), ``method`` (how it was traced: "by
    continuation" or "in closed form in B"). ``to_dict()`` is the CLI's PREFIX.json."""

    def __init__(self, data):
        self._data = data
        self._doc = data.document()
        self._overlay = data.overlay()
        self.axes = tuple(data.axes)
        self.x_range = tuple(data.x_range)
        self.y_range = tuple(data.y_range)
        self.curves = [TraceCurve(c) for c in data.curves()]
        self.corners = data.corners()
        self.analytic_lines = [{"name": o["name"], "x": np.asarray(o["x"], dtype=float),
                                "y": np.asarray(o["y"], dtype=float)} for o in self._doc["analytic_lines"]]

    def to_pandas(self):
        """A DataFrame, one row per traced point: l, chain, piece (the index in ``curves``), x, y (named after the
        axes), mu, sigma_R, sigma_c."""
        pieces = [(k, c) for k, c in enumerate(self.curves)]
        def column(f):
            return np.concatenate([f(k, c) for k, c in pieces]) if pieces else np.array([])
        return _tables.frame([("l", column(lambda k, c: np.full(len(c), c.l))),
                              ("chain", column(lambda k, c: np.full(len(c), c.chain))),
                              ("piece", column(lambda k, c: np.full(len(c), k))),
                              (self.axes[0], column(lambda k, c: c.x)), (self.axes[1], column(lambda k, c: c.y)),
                              ("mu", column(lambda k, c: c.mu)), ("sigma_R", column(lambda k, c: c.sigma_R)),
                              ("sigma_c", column(lambda k, c: c.sigma_c))],
                             {"axes": self.axes, "criterion": self.criterion})

    @property
    def criterion(self):
        """The criterion traced: 'asymptotic' or 'finite-horizon' (the ``criterion`` keyword of :func:`trace`)."""
        return self._doc["criterion"]

    @property
    def evaluations(self):
        """How many times the criterion was evaluated (the unit of the progress count)."""
        return self._doc["evaluations"]

    @property
    def method(self):
        """How the boundary was traced: "by continuation" or "in closed form in B" (the ``method`` keyword)."""
        return self._doc["method"]

    @property
    def notes(self):
        """What the tracer says about its result (a list of lines, as the CLI's JSON "notes")."""
        return list(self._doc["notes"])

    @property
    def agreement(self):
        """The predictors' agreement with a diagram (given diagram=...), else None."""
        return self._doc.get("agreement")

    def __repr__(self):
        modes = sorted({c.l for c in self.curves})
        return (f"<rbcstab Trace ({self.criterion}) {self.axes[0]} x {self.axes[1]}: {len(self.curves)} pieces"
                f"{' (l = ' + ', '.join(map(str, modes)) + ')' if modes else ''}, {len(self.corners['x'])} corners, "
                f"{self.evaluations} criterion evaluations>")

    def _repr_html_(self):
        rows = [("plane", f"{self.axes[0]} in [{self.x_range[0]:g}, {self.x_range[1]:g}], {self.axes[1]} in "
                          f"[{self.y_range[0]:g}, {self.y_range[1]:g}]"),
                ("criterion", self.criterion), ("pieces", ", ".join(f"l={c.l}: {len(c)} points" for c in self.curves)),
                ("corners", ", ".join(f"({x:.4g}, {y:.4g}) {a}->{b}" for x, y, a, b in
                                      zip(*(self.corners[k] for k in ("x", "y", "l_from", "l_to"))))),
                ("method", self.method), ("evaluations", self.evaluations)] + [("note", n) for n in self.notes]
        body = "".join(f"<tr><th style='text-align:left'>{html.escape(str(k))}</th>"
                       f"<td style='text-align:left'>{html.escape(str(v))}</td></tr>" for k, v in rows)
        return f"<b>rbcstab Trace</b><table>{body}</table>"

    def plot(self, ax=None, analytic_lines=True, corners=True, title=None):
        """The traced boundary with the report's line rules (solid black; the paper's analytic lines dashed or
        dotted unless analytic_lines=False) and the corners as markers, on ax (default: the current axes)."""
        ax = _axes(ax)
        curves = self._overlay["curves"]
        if not analytic_lines:
            curves = [c for c in curves if c.get("color") == "black"]
        phase_draw().draw_phase_diagram(ax, [], [], [], self.axes[0], self.axes[1], curves,
                                            limits=(self.x_range, self.y_range), labels=self._overlay.get("axes"),
                                            title=title or f"boundary ({self.criterion} criterion)")
        if corners and len(self.corners["x"]):
            ax.plot(self.corners["x"], self.corners["y"], "o", color="black", mfc="white", ms=6, zorder=5,
                    label="mode corners")
        return keep_legends_inside(ax)


def trace(scene, criterion="asymptotic", *, axes=None, x_range=None, y_range=None, alpha_fixed=None, horizon=0.0,
          lines=4, samples=128, max_step=0.02, method="auto", diagram=None, threads=1, progress=False):
    """The stability boundary of a parameter plane traced as curves (``rbcstab trace``).

    criterion  'asymptotic' (mu_l = Upsilon_l(<sigma_R>) = 0) or 'finite-horizon' (G_l(T) = 0)
    axes, x_range, y_range, alpha_fixed   the plane, as for diagram() (default: the scene's [diagram] table)
    horizon    the finite horizon T in the time unit 1/shear rate, in [0, 1e7] (0: the scene's T)
    lines      interior lines searched for starting points, an integer in [0, 10000]
    samples    brackets per edge or line when searching for starts, an integer in [2, 1000000]
    max_step   continuation step cap in the unit square, dimensionless and > 0 (the curve's resolution)
    method     'auto' (on ln B planes the finite-horizon and in-plane asymptotic boundaries in closed form in B,
               one reduced transient or periodic orbit per value of the other axis; the rest by continuation) or
               'continuation' (every plane); the result's ``method`` says which was used
    diagram    a Diagram of the same plane (or its to_dict(), or the path of a diagram JSON file): measures
               every predictor's agreement with its simulations (the CLI's --diagram)
    threads    threads for the agreement's per-point verdicts, an integer in [0, 4096] (0: all cores)
    progress   True: a bar of the criterion evaluations (tqdm if importable, else text on stderr; the total is
               not known in advance); a callable f(done, total, eta) or a tqdm bar; False: none

    Ctrl-C raises KeyboardInterrupt (the criteria's reduced runs poll it). The GIL is released meanwhile."""
    scene = _scene(scene)
    text, source = None, "diagram"
    if isinstance(diagram, Diagram):
        text = diagram._data.json_text()
    elif isinstance(diagram, dict):
        text = json.dumps(diagram)
    elif isinstance(diagram, (str, os.PathLike)):
        source = os.fspath(diagram)
        with open(source) as f:
            text = f.read()
    elif diagram is not None:
        raise TypeError(f"diagram must be a rbcstab.Diagram, its to_dict() or a path, got {type(diagram).__name__}")
    args = dict(axes=_names("axes", axes), x_range=_numbers("x_range", x_range), y_range=_numbers("y_range", y_range),
                alpha_fixed=None if alpha_fixed is None else _number("alpha_fixed", alpha_fixed),
                criterion=_text("criterion", criterion), method=_text("method", method),
                horizon=_number("horizon", horizon), lines=_integer("lines", lines),
                samples=_integer("samples", samples), max_step=_number("max_step", max_step),
                threads=_integer("threads", threads), diagram=text, diagram_source=source)
    bar = progress_bar(progress, "rbcstab trace", "criterion evaluations")
    if bar is None:
        return Trace(_rbcstab.trace(scene, **args))
    with bar:
        return Trace(_rbcstab.trace(scene, progress=bar, **args))


# ------------------------------------------------------------------------------------------- Fig. 6e
class Fig6eTable(_args.Columns):
    """The Fig. 6e table (``rbcstab post --fig6e``): one row per (lambda, B, C), numpy columns by name
    (``table["Delta2_tilde"]``; NaN where a quantity is outside its domain, e.g. a stable run):
    lambda, B, C, alpha, ln_alpha, surviving_mode, l_Delta, Delta2_tilde, Delta2_tilde_integer_mode,
    Delta2_simulated, ratio, ratio_integer_mode. ``to_dict()`` is ``post --fig6e --json``; ``to_csv()`` the
    CSV ``post --fig6e`` prints."""

    _what = "the Fig. 6e table"

    def __init__(self, data, columns, csv):
        self._data = data
        self._columns = columns
        self._csv = csv
        for a in columns.values():
            a.flags.writeable = False


    def __len__(self):
        return len(self._columns["lambda"])

    def to_dict(self):
        """Exactly ``rbcstab post --fig6e --json``."""
        return json.loads(json.dumps(self._data))

    def to_csv(self):
        """The CSV ``rbcstab post --fig6e`` prints (text)."""
        return self._csv

    def __repr__(self):
        compared = int(np.sum(np.isfinite(self._columns["ratio"])))
        lams = sorted(set(self._columns["lambda"].tolist()))
        return (f"<rbcstab Fig6eTable: {len(self)} rows (lambda in {_numbers_repr(lams)}), {compared} compared, "
                f"L={self._data.get('L')}>")

    def _repr_html_(self):
        head = "".join(f"<th>{html.escape(c)}</th>" for c in self._columns)
        body = "".join("<tr>" + "".join(f"<td>{v:.6g}</td>" if isinstance(v, float) else f"<td>{v}</td>"
                                         for v in (self._columns[c][k].item() for c in self._columns)) + "</tr>"
                       for k in range(len(self)))
        return f"<b>rbcstab Fig. 6e table</b><table><tr>{head}</tr>{body}</table>"

    def plot(self, ax=None, ratio_inset=True, title=None):
        """The report's Fig. 6(e) on ax (default: the current axes): Delta2_tilde (theory) against
        Delta2_simulated as markers, one marker per lambda, a diagonal guide, and (ratio_inset=False: none) an
        inset of their ratio against ln alpha. Rows where either is NaN (a stable run, outside the domain) are
        not drawn, and no line joins the rows. Returns ax."""
        ax = _axes(ax)
        c = self._columns
        symbols = {row["name"]: row["symbol"] for row in _rbcstab.parameter_table()}
        phase_draw().draw_delta2_comparison(ax, c["Delta2_tilde"], c["Delta2_simulated"], symbols, c["lambda"],
                                            c["alpha"] if _flag("ratio_inset", ratio_inset) else None, title=title)
        return keep_legends_inside(ax)


def fig6e(scene, lambdas=None, B=None, C=None, progress=False):
    """The Fig. 6e table (``rbcstab post --fig6e``): the post-instability Delta~2 (Eq. ss) against the simulated
    long-time mean, one run per (lambda, B, C). Delta, Delta0, beta, delta, L, T and the integrator come from
    the scene; lambdas, B, C (dimensionless, each > 0; default: the scene's [fig6e] table, else the paper's 1, 5 / 1..10 /
    0.01..0.08) choose the grid. progress: True, a callable f(done, total, eta) or a tqdm bar, counting the runs
    of the grid. Ctrl-C raises KeyboardInterrupt; the GIL is released meanwhile."""
    scene = _scene(scene)
    grid = {name: None if v is None else _numbers(name, v) for name, v in (("lambdas", lambdas), ("B", B), ("C", C))}
    bar = progress_bar(progress, "rbcstab fig6e", "runs")
    if bar is None:
        data, columns, csv = _rbcstab.fig6e(scene, **grid)
    else:
        with bar:
            data, columns, csv = _rbcstab.fig6e(scene, progress=bar, **grid)
    return Fig6eTable(data, columns, csv)


"""One scene's runs: simulate, thresholds, post, summary (the CLI subcommands of the same names)."""
import html

from . import _args, _rbcstab, _tables
from ._drawing import drawing_module
from .progress import progress_bar

_UNSET = object()


def _scene_with(scene, **overrides):
    """The scene with the non-None overrides applied (TypeError if scene is not a Scene)."""
    _args.scene(scene)
    changes = {k: v for k, v in overrides.items() if v is not None}
    return scene.replace(**changes) if changes else scene


def _number(v, spec):
    """v formatted with spec, or "n/a" for a value that is not a number (JSON null: the run says why)."""
    return "n/a" if v is None or v != v else format(v, spec)


class Report(dict):
    """A result as the CLI's --json object (a dict: equal to json.loads of the CLI's output), with the CLI's
    text in ``.text``; prints as one line and renders in Jupyter as the text."""

    def __init__(self, kind, data, text):
        super().__init__(data)
        self.kind = kind
        self.text = text

    def to_dict(self):
        """The CLI's --json object as a plain dict."""
        return dict(self)

    def __repr__(self):
        keys = [k for k in ("l_Delta", "model", "status", "l_star", "sigma_star", "regime") if k in self]
        fields = ", ".join(f"{k}={self[k]!r}" for k in keys)
        return f"<rbcstab {self.kind} of scene {self.get('scene', '?')!r}" + (f": {fields}>" if fields else ">")

    def _repr_html_(self):
        return "<pre>" + html.escape(self.text) + "</pre>"


class _DenseSolution:
    """``run.sol(t)``: the run's observables at any time t in [0, T] (a number or an array), as a dict of numpy
    arrays ``Delta`` (shape t.shape + (L - 1,), column l - 2), ``sigma``, ``r``, ``Psi``: a polynomial of degree 7
    through the nearest accepted steps of the integrator, NaN in a span a certified early stop skipped."""

    def __init__(self, dense):
        self._dense = dense

    def __call__(self, t):
        values = self._dense(_args.times("t", t))
        return {"Delta": values[..., :-3], "sigma": values[..., -3], "r": values[..., -2], "Psi": values[..., -1]}


class Simulation:
    """One run (rbcstab simulate): numpy arrays ``t``, ``Delta`` (shape (len(t), L - 1), column l - 2),
    ``sigma``, ``r``, ``Psi`` on the sampling grid, ``integrated`` (bool per sample: False where a certified
    early stop skipped it, whose values are NaN), and every scalar of ``rbcstab simulate --json`` as an
    attribute (``model``, ``status``, ``l_Delta``, ``excess_area_drift``, ``rhs_evaluations``, ``seconds``, ...)."""

    def __init__(self, data, arrays, text):
        self._data = data
        self.t = arrays["t"]
        self.Delta = arrays["Delta"]
        self.sigma = arrays["sigma"]
        self.r = arrays["r"]
        self.Psi = arrays["Psi"]
        self.integrated = arrays["integrated"]
        dense = arrays.get("dense")
        self.sol = _DenseSolution(dense) if dense is not None else None
        self.y_final = arrays["y_final"]
        self.text = text

    def __getattr__(self, name):
        data = self.__dict__.get("_data", {})
        if name in data:
            return data[name]
        raise AttributeError(f"Simulation has no attribute {name!r}")

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._data))

    def to_dict(self):
        """Exactly the CLI's ``rbcstab simulate --json`` object."""
        return dict(self._data)

    @property
    def ls(self):
        """The modes l = 2..L of the columns of Delta."""
        return list(range(2, self.Delta.shape[1] + 2))

    def to_pandas(self):
        """A DataFrame, one row per sample: t, Delta_2 .. Delta_L, sigma, r, Psi, integrated (False: a sample a
        certified early stop skipped, NaN in the other columns); attrs: scene, model, L, status."""
        return _tables.frame([("t", self.t), (("Delta", [f"Delta_{l}" for l in self.ls]), self.Delta),
                              ("sigma", self.sigma), ("r", self.r), ("Psi", self.Psi),
                              ("integrated", self.integrated)],
                             {k: self._data[k] for k in ("scene", "model", "L", "status")})

    def __repr__(self):
        d = self._data
        return (f"<rbcstab Simulation of {d['scene']!r}: {d['model']} L={d['L']}, {d['status']}, "
                f"l_Delta={d['l_Delta']}, sigma(T)={_number(d['sigma_final'], '.6g')}, {d['rhs_evaluations']} rhs evaluations, "
                f"{d['seconds'] * 1e3:.3g} ms>")

    def _repr_html_(self):
        return "<pre>" + html.escape(self.text) + "</pre>"

    def plot(self, ax=None, modes=None, sigma=False):
        """Delta_l(t) for the given modes (default all), log scale; sigma=True draws sigma(t) instead. The lines
        break over samples a certified early stop skipped (NaN): no line across a span that was not computed. As in
        the report, a transient that is over in the first tenth of a run spanning decades of t gets a symlog time
        axis (linear below the first sample, logarithmic above)."""
        import matplotlib.pyplot as plt
        ax = ax if ax is not None else plt.gca()
        if sigma:
            ax.plot(self.t, self.sigma, label=r"$\sigma$")
            ax.set_ylabel(r"$\sigma$")
        else:
            shown = list(modes if modes is not None else self.ls)
            for l in shown:
                ax.semilogy(self.t, self.Delta[:, l - 2], label=rf"$\Delta_{{{l}}}$")
            rules = drawing_module("axis_rules")
            limits = rules.excess_area_limits([self.Delta[:, l - 2] for l in shown])
            if limits:  # the report's rule: decayed modes leave the axis instead of stretching it to 1e-100
                ax.set_ylim(*limits)
            scale, t1 = rules.transient_time_scale(self.t, [self.Delta[:, l - 2] for l in shown], limits)
            if scale == "symlog":  # the report's rule too: a transient over decades of t is not squeezed
                ax.set_xscale("symlog", linthresh=t1, linscale=0.25)
            ax.set_ylabel(r"$\Delta_l$")
        ax.set_xlabel(r"$t\dot\gamma$")
        ax.set_title(self._data["scene"])
        ax.legend()
        return ax


def simulate(scene, model=None, stepper=None, rtol=None, atol=None, t_eval=None, dense_output=False, progress=False):
    """Integrates the scene (rbcstab simulate). model ('auto', 'full', 'modal', 'reduced') and stepper override
    the scene's (defaults 'auto', 'rk8pd'); rtol: the relative tolerance (dimensionless), in [1e-15, 0.1]; atol:
    the absolute tolerance (in the state's dimensionless units), in [0, 1] (None: the scene's, default 1e-8 and
    1e-12). t_eval: the sample times in the time unit 1/shear rate (finite, increasing, in [0, T]; default the
    scene's grid 0, dt, ..., T), at which the integrator stops.
    dense_output=True: ``run.sol(t)`` gives the observables at any t (else ``run.sol`` is None). The run may stop early on a
    certified attractor (``terminated_at``, ``early_termination``; the skipped samples are NaN with
    ``integrated`` False);
    ``Scene(full_horizon=True)`` integrates to T. progress: True (a bar of the time integrated, t of T, in the
    time unit 1/shear rate), a callable f(done, total, eta) or a tqdm bar. Ctrl-C stops it (KeyboardInterrupt);
    the GIL is released while it runs."""
    scene = _scene_with(scene, model=model, stepper=stepper, rtol=rtol, atol=atol)
    times = [] if t_eval is None else _args.times("t_eval", t_eval, ndim=1).tolist()
    if t_eval is not None and not times:
        raise ValueError("t_eval is empty: give at least one time in [0, T], or None for the scene's grid")
    bar = progress_bar(progress, "rbcstab simulate", "time units")
    if bar is None:
        data, arrays, text = _rbcstab.simulate(scene, times, _args.flag("dense_output", dense_output))
    else:
        with bar:
            data, arrays, text = _rbcstab.simulate(scene, times, _args.flag("dense_output", dense_output), bar)
    return Simulation(data, arrays, text)


def thresholds(scene, exact_C_star=False):
    """The paper's instability thresholds and the predicted unstable modes, no simulation (rbcstab thresholds)."""
    data, text = _rbcstab.thresholds(_scene_with(scene), _args.flag("exact_C_star", exact_C_star))
    return Report("thresholds", data, text)


def post(scene):
    """The post-instability excess area Delta~2, predicted against simulated (rbcstab post)."""
    data, text = _rbcstab.post(_scene_with(scene))
    return Report("post", data, text)


def summary(scene):
    """The main job: the run and its analysis (rbcstab summary)."""
    data, text = _rbcstab.summary(_scene_with(scene))
    return Report("summary", data, text)

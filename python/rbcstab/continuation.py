"""Continuation: branches of equilibria and periodic orbits in one parameter, their special points (LP, BP, HB,
LPC, PD, NS, UZ), switched branches and two-parameter curves -- ``rbcstab continue`` from Python.

Every call is the CLI's library call, so ``Branch.to_dict()`` equals ``rbcstab continue ... --json`` on the same
arguments, ``Branch.save(path)`` writes the CLI's branch file (``--save``; ``--restart`` reads it, as
:func:`load_branch` reads the CLI's) and ``Branch.plot()`` draws by the rules of ``rbcstab plot``.

    >>> scene = rbcstab.Scene.from_toml("scenes/rest_l3_op.toml")
    >>> b = rbcstab.continuation(scene, kind="full", parameter="C", min=0.012, max=0.08, direction="backward")
    >>> b["C"], b["sigma"], b.stable, b.special_points[0]["type"]
    >>> s = b.switch(b.labels("BP")[0])                    # the branch bifurcating at the BP
    >>> c = b.curve(b.labels("BP")[0], parameter2="B", min2=0.8, max2=1.25)   # the BP in (C, B)
    >>> b.plot()
"""
import html
import os
import warnings


from . import _args, _rbcstab, _tables
from ._drawing import drawing_module
from .progress import progress_bar
from ._rbcstab import Scene

__all__ = ["continuation", "load_branch", "plot_branches", "Branch", "Curve", "ContinuationError",
           "ContinuationWarning", "TUNABLE_OPTIONS", "bifurcation_diagram", "load_diagram", "BifurcationDiagram"]


class ContinuationError(RuntimeError):
    """A run that produced nothing: its start failed (no solution near the start state) or was refused (an
    orbit certified unstable without allow_unstable_start). The CLI exits 1 there."""


class ContinuationWarning(UserWarning):
    """A run that ended early (a branch or curve stopped before a normal end, a switch that failed: the CLI's
    exit 1 with output) or a note on its start (an unstable or uncertain start)."""


# ------------------------------------------------------------------------------------------- arguments
_number = _args.number
_integer = _args.integer
_flag = _args.flag
_name = _args.text


# The tunable options (steps, Newton, location, the orbits' shooting) as the library declares them: keyword,
# whether an integer, range, default, help (``rbcstab continue --help`` lists the same).
TUNABLE_OPTIONS = tuple(_rbcstab.tunable_options())

_KINDS = {"min": _number, "max": _number, "relax_T": _number,
          "min2": _number, "max2": _number, "max_points": _integer, "label_every": _integer,
          "point": _integer, "switch_at_bp": _flag, "allow_unstable_start": _flag, "direction": _name,
          "curve": _name, "parameter2": _name, "kind": _name, "parameter": _name, "amplitude": _number,
          "duplicate_tol": _number, "max_branches": _integer, "journal": _args.path,
          **{k: _integer if integer else _number for k, integer, *_ in TUNABLE_OPTIONS}}


# The numeric keywords of continuation, restart, switch and curve as their docstrings list them: the tunable options
# from the library's declaration (TUNABLE_OPTIONS), the others with the library's limits
# (continuation/tunable_options.hpp, branch_spec.cpp).
_KEYWORD_DOCS = (
    (("min", "max"), "min, max: the free parameter's bounds (the branch ends there exactly), finite and within its "
                     "domain (parameter_table()'s 'domain'), in its unit (dimensionless; shear_rate in 1/s)"),
    (("min2", "max2"), "min2, max2: parameter2's bounds, finite and within its domain, in its unit (dimensionless; "
                       "shear_rate in 1/s)"),
    (("max_points",), "max_points: points per direction, an integer in [2, 100000000]"),
    (("relax_T",), "relax_T: the relaxation giving the start state, in the time unit 1/shear rate, finite and >= 0 "
                   "(orbits: rounded up to whole periods 2 pi)"),
    (("label_every",), "label_every: label every N-th point, an integer in [0, 100000000] (0: the ends and special "
                       "points only)"),
    (("point",), "point: the point-th special point of the curve's type along the branch, an integer in [1, 1000000]"),
) + tuple(((k,), f"{k} ({limits}{'' if integer else ', dimensionless'}; default {default:g}): {text}")
          for k, integer, limits, default, text in TUNABLE_OPTIONS)


def _with_keyword_docs(fn):
    """fn with the _KEYWORD_DOCS of its keywords appended to its docstring (one place for their ranges and units)."""
    import inspect
    params = inspect.signature(fn).parameters
    lines = [text for names, text in _KEYWORD_DOCS if any(n in params for n in names)]
    fn.__doc__ = (inspect.cleandoc(fn.__doc__) + "\n\nNumeric keywords (None: the library's default; arclength steps "
                  "are measured in the dimensionless (state, parameter) space):\n\n" +
                  "\n".join(f"- {line}" for line in lines))
    return fn


def _monitors(monitor, stop_at):
    """monitor={name: value, [values] or callable(point) -> float}, stop_at={name: value or callable} as the
    library's (name, values, stop, callable or None) list; None when neither is given (a restart keeps the run's)."""
    if monitor is None and stop_at is None:
        return None
    out = []
    for stop, key, given in ((False, "monitor", monitor), (True, "stop_at", stop_at)):
        if given is None:
            continue
        if not isinstance(given, dict):
            raise TypeError(f"{key} must be a dict {{name: value(s) or callable}}, got {type(given).__name__}")
        for name, v in given.items():
            _name(key, name)
            if callable(v):
                out.append((name, [], stop, v))
            elif isinstance(v, (list, tuple)):
                out.append((name, _args.numbers_(key, v), stop, None))
            else:
                out.append((name, [_number(key, v)], stop, None))
    return out


def _options(monitor=None, stop_at=None, **given):
    """The given options (None: not given, the library's default) checked for their types, as a dict; monitor and
    stop_at as the library's "monitors" list when either is given (an empty dict: none)."""
    options = {k: _KINDS[k](k, v) for k, v in given.items() if v is not None}
    monitors = _monitors(monitor, stop_at)
    if monitors is not None:
        options["monitors"] = monitors
    return options


def _run(call, what, progress, *args):
    """call(*args, progress=callable or None) with the bar shown and closed, and the run's outcome applied: a
    run without output raises ContinuationError, a note or an early end is a ContinuationWarning."""
    bar = progress_bar(progress, what, "points")
    try:
        # The library reports (points, 0, 0) as it goes and the final count at the end: no known end.
        run = call(*args, progress=bar)
    finally:
        if bar is not None:
            bar.close()
    has_output, note, failure = run.outcome()
    if not has_output:
        raise ContinuationError(failure)
    for message in (note, failure):
        if message:
            warnings.warn(message, ContinuationWarning, stacklevel=3)
    return _wrap(run)


def _wrap(run):
    return Curve(run) if run.has_part("one_parameter") else Branch(run)


# ------------------------------------------------------------------------------------------- entry points
@_with_keyword_docs
def continuation(scene, kind="equilibrium", parameter="lambda", min=None, max=None, *, direction=None, step=None,
                 max_step=None, max_points=None, relax_T=None, segments=None, switch_at_bp=False,
                 allow_unstable_start=False, label_every=None, curve=None, parameter2=None, min2=None, max2=None,
                 point=None, min_step=None, newton_tol=None, max_newton=None, location_tol=None, orbit_rtol=None,
                 orbit_atol=None, orbit_samples=None, monitor=None, stop_at=None, progress=False):
    """Continues a branch from the scene's state (``rbcstab continue``; each keyword is the CLI's flag of the
    same name in snake_case, None its default; docs/continuation.md).

    kind: 'equilibrium' (reduced system), 'modal', 'full', 'orbit' or 'modal-orbit'; parameter: the free
    parameter ('lambda', 'Delta', 'Delta0', 'B', 'C', 'Lambda', 'S', 'beta', 'shear_rate' on a physical scene);
    direction: 'forward', 'backward' or 'both' (default); switch_at_bp: also continue the branch bifurcating at the
    first BP met; allow_unstable_start: orbits, continue from an unstable start. curve ('LP', 'BP', 'HB', 'LPC',
    'PD', 'NS', 'UZ') with parameter2, min2, max2 and point: the curve of the point-th special point of that type
    in (parameter, parameter2) instead (a :class:`Curve`). The numeric keywords (bounds, steps, the numerical
    options of :data:`TUNABLE_OPTIONS`) are listed below with their ranges and units. monitor: {name: value, [values] or
    callable}: a UZ point named 'name=value' where a parameter or a numeric measure of the branch reaches each
    value; a callable f(point) -> float (point: a dict of the point's parameters and numeric measures) gives
    UZ points named 'name' at its zeros. stop_at: {name: value or callable}: end the branch (each direction)
    where it is reached (message 'stopped at name=value'). With curve, the monitors read the curve (its two
    parameters and measures). A callable is not kept with the run (restarts, save, pickle go without it).
    progress: True shows the points computed (tqdm if importable, else a line on stderr every second); a callable
    f(done, total, eta) is called with the points so far (total 0: a branch's end is not known in advance); a
    tqdm bar of yours is updated. Ctrl-C stops it (KeyboardInterrupt); the GIL is released.

    Returns a :class:`Branch` (or a :class:`Curve`). Raises ValueError for bad input (naming the parameter, its
    value and the allowed range), TypeError for a value of the wrong type, ContinuationError when the start
    fails; a run that ends early is returned with a ContinuationWarning."""
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a rbcstab.Scene, got {type(scene).__name__}")
    options = _options(min=min, max=max, direction=direction, step=step, max_step=max_step, max_points=max_points,
                       relax_T=relax_T, segments=segments, switch_at_bp=switch_at_bp,
                       allow_unstable_start=allow_unstable_start, label_every=label_every, curve=curve,
                       parameter2=parameter2, min2=min2, max2=max2, point=point, min_step=min_step,
                       newton_tol=newton_tol, max_newton=max_newton, location_tol=location_tol, orbit_rtol=orbit_rtol,
                       orbit_atol=orbit_atol, orbit_samples=orbit_samples, monitor=monitor, stop_at=stop_at)
    what = f"continuation in {parameter}" if isinstance(parameter, str) else "continuation"
    return _run(_rbcstab.continue_scene, what, progress, scene, _name("kind", kind), _name("parameter", parameter),
                options)


@_with_keyword_docs
def bifurcation_diagram(scene, depth=1, kind="equilibrium", parameter="lambda", min=None, max=None, *,
                        direction=None, step=None, max_step=None, max_points=None, relax_T=None, segments=None,
                        allow_unstable_start=False, label_every=None, min_step=None, newton_tol=None, max_newton=None,
                        location_tol=None, orbit_rtol=None, orbit_atol=None, orbit_samples=None, monitor=None,
                        stop_at=None, amplitude=None, duplicate_tol=None, max_branches=None, journal=None,
                        progress=False):
    """The whole bifurcation diagram to `depth` (``rbcstab continue --diagram DEPTH``; docs/continuation.md): the
    start branch as :func:`continuation` follows it (the same keywords), then at every located BP both halves of
    the branch bifurcating there, recursively to `depth` (an integer in [0, 20]; 0: the start branch only), each
    with the start branch's options. A branch reached twice is marked a duplicate, not followed again; a BP met
    again is not switched at again; HB, PD and NS points are listed as not followed (switching not available), the
    reason in their message (an HB of the model: a problem kind without an orbit switch or a multiple Hopf point; a
    PD: the doubled orbit has no scene kind yet; NS: tori are not continued), except an HB of the full model's
    l >= 3 onset: outcome rotating_wave, its orbits the states of the BP's branch (branch_to; label_to the BP) with
    the l-block turned into mode m, rotating at m/2.
    amplitude: the predictor step off a BP, finite and > 0 (dimensionless, in the (state, parameter) space; default
    1e-3); duplicate_tol: two points are the same within it, in (0, amplitude / 10] (dimensionless; default 1e-7);
    max_branches: at most this many branches, an integer in [1, 10000] (default 200). progress and Ctrl-C as
    :func:`continuation`. journal: a checkpoint file (the CLI's ``--save F``: F.journal): each branch continued to
    its end is appended as it ends, and a later call with the same journal and options resumes from it (the
    recorded branches are read back, not continued again) to the same diagram; a journal of other options is a
    ValueError, a torn or edited record is reported (:attr:`BifurcationDiagram.rejected`) and its branch continued
    again.

    Returns a :class:`BifurcationDiagram`. Raises ValueError / TypeError for bad input, ContinuationError when the start
    fails; an incomplete diagram, a branch that ended early or a failed switch gives a ContinuationWarning."""
    if not isinstance(scene, Scene):
        raise TypeError(f"scene must be a rbcstab.Scene, got {type(scene).__name__}")
    options = _options(min=min, max=max, direction=direction, step=step, max_step=max_step, max_points=max_points,
                       relax_T=relax_T, segments=segments, allow_unstable_start=allow_unstable_start,
                       label_every=label_every, min_step=min_step, newton_tol=newton_tol, max_newton=max_newton,
                       location_tol=location_tol, orbit_rtol=orbit_rtol, orbit_atol=orbit_atol,
                       orbit_samples=orbit_samples, monitor=monitor, stop_at=stop_at, amplitude=amplitude,
                       duplicate_tol=duplicate_tol, max_branches=max_branches, journal=journal)
    bar = progress_bar(progress, f"diagram in {parameter}", "points")
    try:
        d = _rbcstab.bifurcation_diagram(scene, _name("kind", kind), _name("parameter", parameter),
                                         _integer("depth", depth), options, progress=bar)
    finally:
        if bar is not None:
            bar.close()
    has_output, note, failure = d.outcome()
    if not has_output:
        raise ContinuationError(failure)
    for message in (note, failure):
        if message:
            warnings.warn(message, ContinuationWarning, stacklevel=2)
    return BifurcationDiagram(d)


def load_diagram(path):
    """The diagram ``rbcstab continue --diagram N --save path`` (or :meth:`BifurcationDiagram.save`) wrote: the tree and its
    branch files beside it, each checked."""
    return BifurcationDiagram(_rbcstab.load_diagram(os.fspath(path)))


def load_branch(path):
    """The run a branch file holds (``rbcstab continue --save``, :meth:`Branch.save`), checked key by key."""
    return _wrap(_rbcstab.load_branch(os.fspath(path)))


def _drawing():
    return drawing_module("bifurcation_draw")


def _text(name, value):
    return "" if value is None else _name(name, value)


def plot_branches(branches, ax=None, x=None, y=None, title=None, all_labels=False, names=None):
    """Draws branches overlaid (``rbcstab plot F1.json F2.json ...``): stable parts solid, unstable dashed,
    uncertain dotted, special points marked and labelled ("BP 3"), a branch's switched branch as its own series.
    x, y: a parameter or measure (default: the free parameter; y: Psi for reduced equilibria, r_max for orbits,
    r otherwise; a curve: its plane); names: the legend's names of the runs when several of the same kind are
    drawn. Returns the Axes (a new figure's when ax is None)."""
    branches = list(branches)
    for b in branches:
        if not isinstance(b, Branch):
            raise TypeError(f"branches must be rbcstab.Branch objects, got {type(b).__name__}")
    names = [f"branch {k + 1}" for k in range(len(branches))] if names is None else [_name("names", n) for n in names]
    spec = _rbcstab.plot_spec([b._run for b in branches], names, _text("x", x), _text("y", y), _text("title", title),
                              _flag("all_labels", all_labels))
    drawing = _drawing()  # before the figure: a missing file leaves no empty figure behind
    if ax is None:
        import matplotlib.pyplot as plt
        ax = plt.figure(layout="constrained").add_subplot()
    for note in spec["notes"]:
        warnings.warn(note, ContinuationWarning, stacklevel=2)
    return drawing.draw_bifurcation(ax, spec)


# ------------------------------------------------------------------------------------------- results
class Branch(_args.Columns):
    """A continuation run: a one-parameter branch (with its switched branch, if any), as ``rbcstab continue``.

    ``branch[name]`` is a numpy column over the branch's points: the free parameter and every measure of the
    CLI's JSON and CSV (r, Psi, sigma, Delta_2, ..., r_min, winding, kind, ...), stable, n_unstable, stability,
    margin, margin_error, label (0: unlabelled), type ('EP' at the ends), arclength, max_Re_eig (or
    max_abs_multiplier) and eigenvalues (or multipliers; points x dimension, complex). ``columns`` lists the
    names, ``len(branch)`` counts the points, ``special_points`` are the JSON's special points (type, label,
    parameters, precision, stability certificate, ...). ``switched`` is the switched branch (a Branch over the
    same run) or None. restart, switch, curve and save act on the whole run (labels are unique over a run)."""

    _role = "branch"
    _what = "this branch"

    def __init__(self, run, role=None):
        self._run = run
        if role is not None:
            self._role = role
        self._columns = run.columns(self._role)
        self._json = None

    # ---- the run's JSON and the part of it this object shows
    def _run_json(self):
        if self._json is None:
            self._json = self._run.json()
        return self._json

    def _part(self):
        j = self._run_json()
        return {"branch": j, "switched": j.get("switched_branch"), "one_parameter": j.get("one_parameter_branch")}[
            self._role]

    def to_dict(self):
        """The run as ``rbcstab continue ... --json`` prints it (a part -- switched, one_parameter_branch -- its
        object in that JSON)."""
        import copy
        return copy.deepcopy(self._part())

    # ---- columns: Columns gives columns and branch["name"]

    def __contains__(self, name):
        return name in self._columns

    def __len__(self):
        return len(self._part()["branch"])

    def to_pandas(self):
        """The branch as a DataFrame: the rows and columns of its CSV (:meth:`to_csv`: every computed point and, in
        their place along the branch, the located special points), ``type`` and ``label`` naming the special
        points, ``mode_l``/``mode_m`` the mode a BP's eigenvalue crosses with; attrs: kind, free_parameter,
        status."""
        return _tables.branch_frame(self)

    @property
    def stable(self):
        """Per point: no unstable eigenvalue (multiplier)."""
        return self._columns["stable"]

    @property
    def special_points(self):
        """The special points along the branch, as dicts of the CLI's JSON (type, name, label, the parameters,
        the measures, precision, status, unstable_before/after, stability, margin, margin_error, ...); an LP, BP or
        HB of an equilibrium branch (and an LPC, PD or NS of a forced orbit branch, where the model has one) also
        has ``normal_form``: kind (fold, pitchfork, transcritical, hopf, period_doubling, fold_of_cycles,
        neimark_sacker, ...), criticality (supercritical, subcritical, degenerate, not_applicable, not_computed),
        coefficients by name (l1 of a Hopf, c of a period doubling, d of a Neimark-Sacker point, p2 of a fold or
        pitchfork, ...), the amplitude law |x - x*| ~ amplitude |p - p*|^exponent on
        the side sign(p - p*) = side, and a note."""
        import copy
        return copy.deepcopy(self._part()["special_points"])

    def labels(self, type=None, l=None, m=None):
        """The labels of the special points (of one type: 'BP', 'LP', ...), in order along the branch; l, m: only
        the BPs and HBs of that mode (``mode_l``, ``mode_m`` of the special points: the mode l, and m where the
        model resolves it, whose eigenvalue (a BP) or pair (an HB, at frequency m/2 in the full model) crosses the
        imaginary axis there), as ``--label BP:l=3`` selects on the command line."""
        return [sp["label"] for sp in self._part()["special_points"]
                if sp["label"] is not None and (type is None or sp["type"] == type)
                and (l is None or sp.get("mode_l") == l) and (m is None or sp.get("mode_m") == m)]

    @property
    def status(self):
        """How the run ended: 'completed' (a bound, max_points or a stop_at monitor was reached), 'step_too_small'
        (the corrector failed down to min_step), 'outside_domain' (a parameter value the model refuses),
        'start_failed' (Newton did not converge at the start) or 'branch_lost' (every step down to min_step left
        the branch: :attr:`message` says after which point)."""
        return self._part()["status"]

    @property
    def message(self):
        """The status in words: where the run stopped and why (the CLI's summary line)."""
        return self._part()["message"]

    @property
    def free_parameter(self):
        """The parameter the points were continued in (a curve's: its second, as in the CLI's JSON)."""
        j = self._run_json()
        return j["curve"]["parameters"][0] if self._role == "one_parameter" else j["free_parameter"]

    @property
    def kind(self):
        """The problem continued: 'equilibrium' or 'orbit' (reduced), 'modal', 'modal-orbit' or 'full' (the
        ``kind`` keyword; the CLI's JSON "kind")."""
        return self._run_json()["kind"]

    @property
    def switched(self):
        """The branch bifurcating at the BP it switched at (switch_at_bp, :meth:`switch`), or None."""
        if self._role != "branch" or not self._run.has_part("switched"):
            return None
        return Branch(self._run, "switched")

    # ---- more runs from labelled points
    @_with_keyword_docs
    def restart(self, label, parameter=None, *, kind=None, min=None, max=None, direction=None, step=None,
                max_step=None, max_points=None, label_every=None, switch_at_bp=False, min_step=None, newton_tol=None,
                max_newton=None, location_tol=None, segments=None, orbit_rtol=None, orbit_atol=None,
                orbit_samples=None, monitor=None, stop_at=None, progress=False):
        """Continues again from the point labelled `label` (``continue --restart FILE --label N``): in
        `parameter` (default: the run's) with the run's scene, kind and options, those given here changed (the
        bounds: the run's when the parameter is the run's, none otherwise). The numerical options are those of
        :func:`continuation` (segments: only the run's own for orbits, the labelled state is on its mesh: any
        other value is refused);
        monitor, stop_at (as :func:`continuation`'s) replace the run's monitors and stops, {} drops them."""
        options = _options(parameter=parameter, kind=kind, min=min, max=max, direction=direction, step=step,
                           max_step=max_step, max_points=max_points, label_every=label_every,
                           switch_at_bp=switch_at_bp, min_step=min_step, newton_tol=newton_tol,
                           max_newton=max_newton, location_tol=location_tol, segments=segments,
                           orbit_rtol=orbit_rtol, orbit_atol=orbit_atol, orbit_samples=orbit_samples,
                           monitor=monitor, stop_at=stop_at)
        return _run(_rbcstab.restart, f"restart from label {label}", progress, self._run,
                    _integer("label", label), options)

    @_with_keyword_docs
    def switch(self, label, *, min=None, max=None, direction=None, step=None, max_step=None, max_points=None,
               label_every=None, min_step=None, newton_tol=None, max_newton=None, location_tol=None, segments=None,
               orbit_rtol=None, orbit_atol=None, orbit_samples=None, monitor=None, stop_at=None, progress=False):
        """Switches onto the branch bifurcating at the BP labelled `label` (``continue --restart FILE --switch-at
        N``): the returned run holds this run's branch with the new branch as its ``switched``. The numerical
        options, monitor and stop_at as :meth:`restart` (the monitors label the new branch). An HB label raises
        ValueError with the reason (at the full model's l >= 3 onset: its orbits are rotating waves of the BP's
        branch, the BP's label named)."""
        options = _options(min=min, max=max, direction=direction, step=step, max_step=max_step,
                           max_points=max_points, label_every=label_every, min_step=min_step, newton_tol=newton_tol,
                           max_newton=max_newton, location_tol=location_tol, segments=segments,
                           orbit_rtol=orbit_rtol, orbit_atol=orbit_atol, orbit_samples=orbit_samples,
                           monitor=monitor, stop_at=stop_at)
        return _run(_rbcstab.switch, f"switch at label {label}", progress, self._run, _integer("label", label),
                    options)

    @_with_keyword_docs
    def curve(self, label, parameter2, min2=None, max2=None, *, type=None, step=None, max_step=None,
              max_points=None, label_every=None, min_step=None, newton_tol=None, max_newton=None, location_tol=None,
              segments=None, orbit_rtol=None, orbit_atol=None, orbit_samples=None, monitor=None, stop_at=None,
              progress=False):
        """The curve of the special point labelled `label` (LP, BP, HB; LPC, PD, NS, BP, UZ of orbits) in (the
        run's parameter, parameter2), bounded by [min2, max2] (``continue --restart FILE --label N --curve TYPE
        --parameter2 P2``). type: the point's type, checked when given. The numerical options, monitor and
        stop_at as :meth:`restart` (the monitors read the curve's two parameters and measures). Returns a
        :class:`Curve`."""
        options = _options(step=step, max_step=max_step, max_points=max_points, label_every=label_every,
                           min_step=min_step, newton_tol=newton_tol, max_newton=max_newton,
                           location_tol=location_tol, segments=segments, orbit_rtol=orbit_rtol,
                           orbit_atol=orbit_atol, orbit_samples=orbit_samples, monitor=monitor, stop_at=stop_at)
        lo = -float("inf") if min2 is None else _number("min2", min2)
        hi = float("inf") if max2 is None else _number("max2", max2)
        return _run(_rbcstab.curve, f"curve from label {label}", progress, self._run, _integer("label", label),
                    None if type is None else _name("type", type), _name("parameter2", parameter2), lo, hi, options)

    # ---- files and text
    def save(self, path):
        """Writes the run as the CLI's branch file (``continue --save``), atomically: ``rbcstab continue
        --restart path`` and :func:`load_branch` read it."""
        self._run.save(os.fspath(path))

    def to_csv(self, path=None):
        """The run as ``continue --csv`` writes it; written to path (atomically replaced) when given."""
        if path is not None:
            self._run.save_csv(os.fspath(path))
        return self._run.csv()

    def text(self, measures=None):
        """The CLI's text output: the summary and the table of labelled points (measures: its columns)."""
        if isinstance(measures, str):
            measures = [m for m in measures.split(",") if m]
        return self._run.text([_name("measures", m) for m in (measures or [])])

    def __str__(self):
        return self.text()

    # ---- plots
    def plot_spec(self, x=None, y=None, title=None, all_labels=False):
        """What :meth:`plot` draws (``rbcstab plot``'s JSON of what was drawn, format rbcstab-plot)."""
        return _rbcstab.plot_spec([self._run], ["branch"], _text("x", x), _text("y", y), _text("title", title),
                                  _flag("all_labels", all_labels))

    def plot(self, ax=None, y=None, x=None, title=None, all_labels=False):
        """Draws the run as ``rbcstab plot`` does (the whole run: a branch with its switched branch, a curve in
        its plane); y, x: a parameter or measure (defaults as the CLI's). Returns the Axes."""
        return plot_branches([self], ax=ax, x=x, y=y, title=title, all_labels=all_labels)

    # ---- display
    def _parameters(self):
        """The parameter(s) of this part's points: a curve's two, else the free parameter."""
        j = self._run_json()
        if "curve" not in j:
            return [j["free_parameter"]]
        return list(j["curve"]["parameters"]) if self._role == "branch" else [j["curve"]["parameters"][0]]

    def _summary(self):
        j, part = self._run_json(), self._part()
        pts = part["branch"]
        what = {"branch": f"{j['curve']['type']} curve" if "curve" in j else "branch",
                "switched": "switched branch", "one_parameter": "one-parameter branch"}[self._role]
        ends = "".join(f", {n} {pts[0][n]:.6g} -> {pts[-1][n]:.6g}" for n in self._parameters()
                       if pts and pts[0].get(n) is not None and pts[-1].get(n) is not None)
        specials = ", ".join(f"{sp['type']} {sp['label']}" for sp in part["special_points"])
        return f"{j['kind']} {what}: {len(pts)} points{ends}, {part['status']}" + (f"; {specials}" if specials else "")

    def __repr__(self):
        sw, extra = self.switched, ""
        if sw is not None:
            extra = (f"; switched branch: {len(sw)} points, {sw.status}" if sw._part()["switched"]
                     else "; the switch failed")
        return f"<rbcstab.{type(self).__name__} {self._summary()}{extra}>"

    def _repr_html_(self):
        """The summary and a table of the special points."""
        names = self._parameters()
        cell = lambda v: f"<td>{html.escape(f'{v:.10g}' if isinstance(v, float) else str(v))}</td>"  # noqa: E731
        head = "".join(f"<th>{html.escape(h)}</th>" for h in ("type", "label", *names, "stability", "precision"))
        rows = "".join("<tr>" + "".join(cell(sp.get(k)) for k in ("type", "label", *names, "stability", "precision"))
                       + "</tr>" for sp in self._part()["special_points"])
        table = f"<table><tr>{head}</tr>{rows}</table>" if rows else ""
        return f"<p><b>rbcstab.{type(self).__name__}</b> {html.escape(self._summary())}</p>{table}"

    def __reduce__(self):
        return (_rebuild, (type(self), self._run, self._role))


def _rebuild(cls, run, role):
    return cls(run, role)


class Curve(Branch):
    """A two-parameter curve of a special point (``continue --curve``): columns over the curve's points (both
    parameters and the measures), its own special points, and ``one_parameter_branch``, the branch it started
    from (a Branch over the same run)."""

    @property
    def parameters(self):
        """The curve's two parameters (the branch's, then parameter2)."""
        return list(self._run_json()["curve"]["parameters"])

    @property
    def one_parameter_branch(self):
        """The branch the curve started from (a Branch over the same run: its special point is the curve's start)."""
        return Branch(self._run, "one_parameter")


class BifurcationDiagram:
    """A bifurcation diagram (:func:`bifurcation_diagram`, ``rbcstab continue --diagram``): its branches and the
    tree that joins them.

    ``branches`` are :class:`Branch` objects (``branches[0]`` the start branch; labels are unique over the
    diagram, so each restarts, switches and draws as any run); ``tree`` lists each branch's number, parent,
    parent_label (the label of the BP it emanates from), side, depth, status and points; ``special_points`` the
    branching points (BP, HB, PD, NS) with what was done at each (outcome: followed, duplicate, symmetric,
    already_switched, not_available, rotating_wave, not_located, depth_limit, failed, interrupted, branch_limit)."""

    def __init__(self, diagram):
        self._d = diagram
        self._json = None

    def _tree_json(self):
        if self._json is None:
            self._json = self._d.json()
        return self._json

    def to_dict(self):
        """The tree as ``rbcstab continue --diagram N --json`` prints it (each branch's JSON under "data")."""
        import copy
        return copy.deepcopy(self._tree_json())

    @property
    def branches(self):
        """Every branch of the diagram as a :class:`Branch`, in the order they were followed (the start branch first)."""
        return [Branch(self._d.branch(k)) for k in range(self._d.size())]

    @property
    def tree(self):
        """Per branch: its number, parent branch and the parent's label it bifurcates at, depth, side, labels,
        points, range, status and message (the JSON's "branches" without their data)."""
        return [{k: v for k, v in b.items() if k != "data"} for b in self._tree_json()["branches"]]

    @property
    def special_points(self):
        """The diagram's special points (the JSON's "special_points": each with its branch, label, type and what the
        diagram did at it)."""
        import copy
        return copy.deepcopy(self._tree_json()["special_points"])

    @property
    def complete(self):
        """No branching point was left for want of time (interrupted) or room (max_branches)."""
        return self._tree_json()["complete"]

    @property
    def resumed(self):
        """How many branches this call read back from its journal instead of continuing them (0 without one)."""
        return self._d.resumed()

    @property
    def rejected(self):
        """Journal records dropped and their branches continued again ('journal:line: why')."""
        return self._d.rejected()

    def __len__(self):
        return self._d.size()

    def save(self, path):
        """Writes the tree to path and each branch's file beside it (path's stem + .b1.json, .b2.json, ...),
        atomically, as ``--diagram N --save path``; returns the branch files' paths."""
        return self._d.save(os.fspath(path))

    def text(self):
        """The CLI's summary: one line per branch and per branching point."""
        return self._d.text()

    def __str__(self):
        return self.text()

    def __repr__(self):
        j = self._tree_json()
        return (f"<rbcstab.BifurcationDiagram {j['kind']} in {j['free_parameter']} to depth {j['depth']}: {len(self)} branches"
                + ("" if j["complete"] else ", incomplete") + ">")

    def plot(self, ax=None, y=None, x=None, title=None, all_labels=False):
        """Every branch overlaid as ``rbcstab plot`` draws branch files (stable solid, unstable dashed, special
        points marked with type and label), each named in the legend by its number and where it comes from."""
        names = [f"BR {b['branch']}" + ("" if b["parent"] is None else f" (from label {b['parent_label']})")
                 for b in self.tree]
        return plot_branches(self.branches, ax=ax, x=x, y=y, title=title, all_labels=all_labels, names=names)

    def __reduce__(self):
        return (BifurcationDiagram, (self._d,))

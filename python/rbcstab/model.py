"""The model itself as an ODE y' = F(t, y), for scipy.integrate.solve_ivp or your own code.

``Model(scene, level)`` builds, once, the system that ``rbcstab.simulate`` integrates for the scene (the same C++
object, with its analytic Jacobian) and evaluates it from Python::

    >>> import rbcstab, scipy.integrate
    >>> model = rbcstab.Model(rbcstab.Scene(), "modal")
    >>> sol = scipy.integrate.solve_ivp(model.rhs, (0, 500), model.y0, method="Radau", jac=model.jacobian,
    ...                                 rtol=1e-10, atol=1e-12)
    >>> model.observables(sol.t, sol.y)["sigma"][-1]

``initial_state``, ``rhs`` and ``jacobian`` are one-off shortcuts that build a Model on each call: hand a solver
the Model's methods instead.
"""
import html
import warnings

from . import _rbcstab
from .runs import _scene_with

__all__ = ["Model", "ModelWarning", "initial_state", "rhs", "jacobian"]


class ModelWarning(UserWarning):
    """The chosen model level approximates the scene (e.g. ``reduced`` on a scene with l >= 3 perturbations or
    m = +-1 content): it runs, as ``rbcstab simulate --model reduced`` does, with this warning."""


class Model(_rbcstab.Model):
    """The system of a scene at a model level: ``y' = F(t, y)`` on a real state of dimension ``n``.

    ``level``: ``"full"`` (every f_{l,m}), ``"modal"`` (the l = 2 amplitudes and ln Delta_l of the l >= 3 modes that
    hold area), ``"reduced"`` (z = r e^{-i Psi} and w on the unit sphere), or ``"auto"`` (the smallest exact level,
    as simulate chooses it); ``None`` takes the scene's ``model`` key. ``level`` reports the level used and
    ``level_reason`` why. A level that cannot hold the scene raises ValueError (``modal`` with an l >= 3 stress-free
    shape); a level that approximates it (``reduced`` with l >= 3 perturbations) emits a ``ModelWarning`` and
    has ``exact == False``, as simulate runs it with a warning.

    The truncation ``L`` is the scene's if it sets one, else the one simulate would choose (``L_reason`` says which).

    Attributes: ``n``, ``level``, ``exact``, ``level_reason``, ``L``, ``L_reason``, ``warnings``, ``y0`` (the initial
    state), ``state_names`` (one name per component: ``"Re f[l,m]"``, ``"Im f[l,m]"``, ``"f[2,0]"``,
    ``"ln Delta_l"``, ``"Re z"``, ``"Im z"``, ``"w"``), ``scene``.

    Methods (``y``: a 1-D float array of length ``n``; the caller's float64 C-contiguous array is read in place,
    anything else convertible is converted; a wrong shape or a non-finite value is a ValueError, a non-numeric
    value a TypeError):

    - ``rhs(t, y)``: F(t, y), shape (n,); with ``y`` of shape (n, k) (k states as columns) F of each column,
      shape (n, k): pass ``vectorized=True`` to ``solve_ivp``.
    - ``jacobian_p(parameter, t, y)``: dF/dq for a continuation parameter q (``"lambda"``, ``"C"``, ``"B"``,
      ``"Delta"``, ``"Lambda"``, ...; a composite moves as in continuation: Lambda through Delta), shape (n,): a
      central difference of the systems the library builds at q +- h, same level and L (relative error about
      eps^(2/3): 4e-11..4e-10 of its scale measured; one-sided at the edge of q's domain).
    - ``jacobian_sparsity()``: a bool array (n, n), True where dF/dy can be nonzero (for ``solve_ivp``'s
      ``jac_sparsity``): the 1x1/2x2 blocks of J = M + v w^T and the rank-one tension coupling's rows x columns.
      The tension couples every mode that holds area, so at the modal and full levels it is mostly dense; a zero
      it shows is zero at the initial state and at a perturbed one (structural, not a coincidence of y0).
    - ``jacobian(t, y)``: dF/dy, dense, shape (n, n) (the library's analytic Jacobian; n^2 doubles, so mind the full
      level at large L).
    - ``observables(t, y)``: dict with ``Delta`` (Delta_l at index l - 2), ``sigma``, ``r``, ``Psi``, as simulate
      reports them; with ``y`` of shape (n, k) and ``t`` of shape (k,) (``sol.y``, ``sol.t``) arrays over the
      columns, ``Delta`` of shape (k, L - 1) and ``Psi`` unwrapped along the columns.
    """

    def __init__(self, scene, level=None):
        scene = _scene_with(scene, model=level)
        super().__init__(scene)
        self.scene = scene
        if not self.exact:
            warnings.warn(f"model level {self.level} {self.level_reason}", ModelWarning, stacklevel=2)

    @property
    def ls(self):
        """The modes l = 2..L (the index of observables' Delta is l - 2)."""
        return list(range(2, self.L + 1))

    def __reduce__(self):
        # Rebuilt from its scene (which holds the level asked for): the same system, without a second warning.
        return (_rebuilt, (self.scene,))

    def __repr__(self):
        exact = "exact" if self.exact else "approximate"
        return f"<rbcstab Model of {self.scene.label}: {self.level} ({exact}), n={self.n}, L={self.L}>"

    def _repr_html_(self):
        names = self.state_names
        shown = ", ".join(names[:12]) + (f", ... ({len(names)} in all)" if len(names) > 12 else "")
        rows = [("scene", self.scene.label), ("level", f"{self.level}: {self.level_reason}"),
                ("L", f"{self.L}: {self.L_reason}"), ("n", str(self.n)), ("state", shown)]
        rows += [("warning", w) for w in self.warnings]
        body = "".join(f"<tr><th style='text-align:left'>{html.escape(k)}</th><td style='text-align:left'>"
                       f"{html.escape(v)}</td></tr>" for k, v in rows)
        return f"<table>{body}</table>"


def _rebuilt(scene):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ModelWarning)
        return Model(scene)


def initial_state(scene, level=None):
    """The initial state of the scene at the level (``Model(scene, level).y0``)."""
    return Model(scene, level).y0


def rhs(scene, level, t, y):
    """F(t, y) of the scene at the level (``Model(scene, level).rhs(t, y)``; builds the Model on each call); t: the
    time in the unit 1/shear rate, finite."""
    return Model(scene, level).rhs(t, y)


def jacobian(scene, level, t, y):
    """dF/dy at (t, y), dense (n, n) (``Model(scene, level).jacobian(t, y)``; builds the Model on each call); t: the
    time in the unit 1/shear rate, finite."""
    return Model(scene, level).jacobian(t, y)

"""The inverse problem: membrane properties from observed motion (rbcstab fit; docs/inverse.md)."""
import numbers

from . import _args, _rbcstab
from .progress import progress_bar
from .runs import Report

__all__ = ["FitResult", "fit"]


class FitResult(Report):
    """A fit (rbcstab fit --json as a dict): ``status`` (converged, infeasible, maximum_iterations, failed,
    interrupted),
    ``estimates`` (per free parameter: value in SI units, 95 % interval ``lo95``/``hi95``, ``identifiable``),
    ``chi2``, ``residuals`` per row, each estimate's ``profile`` (with profiles=True), ``covariance`` and ``correlation`` of the fitted coordinates, and the
    statements of what the data cannot identify (``unidentifiable``); ``report``, the page's folder, when
    fit(report=...) wrote one; the CLI's text in ``.text``."""

    def estimate(self, name):
        """The estimate of parameter `name` (a key such as "shear_modulus") as a dict; KeyError if not free."""
        for e in self["estimates"]:
            if e["name"] == name:
                return e
        raise KeyError(name)

    def __repr__(self):
        values = ", ".join(f"{e['name']}={e['value']:.4g}" for e in self["estimates"] if e["value"] is not None)
        return f"<rbcstab fit: {self['status']}, chi2={self['chi2']}, {values}>"


def _fixed_text(fixed):
    """{name: value} as the CLI's --fixed list: numbers in SI units, strings as given (with their units)."""
    if fixed is None:
        return ""
    if not isinstance(fixed, dict):
        raise TypeError(f"fixed must be a dict of name: value, got {type(fixed).__name__} {fixed!r}")
    items = []
    for name, value in fixed.items():
        _args.text("fixed key", name)
        if isinstance(value, str):
            items.append(f"{name}={value}")
        elif isinstance(value, numbers.Real) and not isinstance(value, bool):
            items.append(f"{name}={float(value)!r}")
        else:
            raise TypeError(f"fixed[{name!r}] must be a number or a string with a unit, got "
                            f"{type(value).__name__} {value!r}")
    return ",".join(items)


def fit(data, free, fixed=None, starts=4, max_iterations=100, seed=1, profiles=False, profile_points=4,
        profile_span=4.0, report=None, overwrite=False, jacobian="variational", regime_constraints=True,
        profile_method="gauss_newton", progress=False):
    """Fits the free parameters to the observations in the CSV file `data` (rbcstab fit).

    data: path of the observations CSV (docs/inverse.md "Data format"). free: names of the parameters to fit
    (bending_modulus or kappa, shear_modulus or mu, radius, inner_viscosity or eta_in, lambda, Delta, Delta0).
    fixed: dict of fixed values and starts, numbers in SI units (bending_modulus [J], shear_modulus [N/m],
    radius [m], inner_viscosity in Pa s) or strings with a unit ("6uN/m"); lambda, Delta and Delta0 are
    dimensionless. starts: Ipopt starts, an integer in [1, 64]. max_iterations: Ipopt iterations per start, an
    integer in [1, 10000]. seed: seed of the spread starts, an integer in [0, 4294967295]. profiles: True adds each free parameter's profile likelihood
    (``estimate(name)["profile"]``: the grid, Delta chi^2, the 95 % profile interval, ``flat``, ``nonlinear`` and a
    plain ``statement``; docs/inverse.md "Profile likelihoods"). profile_points: profile grid points on each side
    of the estimate, an integer in [1, 50]. profile_span: reach of that grid in Fisher standard errors (of the
    fitted coordinate, dimensionless), in (0, 50]. report: a folder to write the fit's page to (rbcstab fit
    --report: index.html, the figures, parameters.csv, fit.json; docs/report.md "A fit's page"), written only when
    the fit has an estimate; an existing folder is refused (ValueError) unless overwrite=True. jacobian: the in-plane
    rows' sensitivities, "variational" (the orbit's variational equations) or "finite_difference" (rbcstab fit
    --jacobian; docs/inverse.md "Sensitivities"). regime_constraints: True makes the in-plane regime rows Ipopt
    constraints on the model's transition shear rate (the result's ``constraints``), False only compares them.
    profile_method: how the profiles re-fit the other parameters, "gauss_newton" (projected Gauss-Newton with an
    Ipopt fallback) or "ipopt" (rbcstab fit --profile-method; docs/inverse.md "Profile likelihoods").
    progress: True (a bar
    of the starts, then of the profile points), False, a callable f(done, total, eta) or a tqdm bar.
    Ctrl-C stops the fit within an Ipopt iteration (KeyboardInterrupt).
    Returns a FitResult; ValueError for bad data (naming the file line and column) or a bad parameter; RuntimeError
    when python3 with matplotlib or the drawing script is missing for the page (checked before the fit runs)."""
    path = _args.text("data", data)
    names = _args.names("free", free)
    folder = "" if report is None else _args.text("report", report)
    args = (path, names, _fixed_text(fixed), _args.integer("starts", starts),
            _args.integer("max_iterations", max_iterations), _args.integer("seed", seed),
            _args.flag("profiles", profiles), _args.integer("profile_points", profile_points),
            _args.number("profile_span", profile_span), folder, _args.flag("overwrite", overwrite),
            _args.text("jacobian", jacobian), _args.flag("regime_constraints", regime_constraints),
            _args.text("profile_method", profile_method))
    bar = progress_bar(progress, "rbcstab fit", "starts and profile points")
    if bar is None:
        doc, text = _rbcstab.fit(*args, progress=None)
    else:
        with bar:
            doc, text = _rbcstab.fit(*args, progress=bar)
    return FitResult("fit", doc, text)

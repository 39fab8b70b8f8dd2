"""rbcstab: shape dynamics and shape instabilities of a quasi-spherical red blood cell in shear flow.

The perturbative model of Moriel, Stone and Mendez, from Python: every function here calls rbcstab's C++
library (the same calls as the ``rbcstab`` command line), so a result's ``to_dict()`` equals the CLI's
``--json`` output on the same scene. See docs/python.md.

    >>> import rbcstab
    >>> scene = rbcstab.Scene(lambda_=5, B=2, C=0.04)       # the paper's Fig. 3 case
    >>> run = rbcstab.simulate(scene)
    >>> run.l_Delta, run.Delta[-1], run.sigma[-1]
"""
from ._rbcstab import __version__, Scene, parameter_table, scene_keys
from .runs import Report, Simulation, simulate, thresholds, post, summary
from .model import *  # noqa: F401,F403 (initial_state, rhs, jacobian)
from .continuation import *  # noqa: F401,F403 (continuation, Branch, load_branch)
from .continuation import __all__ as _continuation_all  # rbcstab.continuation is the function, not the module
from .sweep import *  # noqa: F401,F403 (diagram, trace)
from .physical import *  # noqa: F401,F403 (physical_map)
from .inverse import *  # noqa: F401,F403 (fit, FitResult)
from . import model as _model, physical as _physical, sweep as _sweep, inverse as _inverse


def _scene_signature():
    """Scene(**keywords): every keyword with its default, from the library's key table (Scene._keywords())."""
    import inspect
    return inspect.Signature([inspect.Parameter(keyword, inspect.Parameter.KEYWORD_ONLY, default=default)
                              for keyword, default in Scene._keywords()])


setattr(Scene, "__signature__", _scene_signature())  # inspect.signature reads it (not a declared attribute)

__all__ = (["__version__", "Scene", "parameter_table", "scene_keys", "Report", "Simulation", "simulate", "thresholds", "post",
            "summary"] + _model.__all__ + _continuation_all + _sweep.__all__ + _physical.__all__
           + _inverse.__all__)

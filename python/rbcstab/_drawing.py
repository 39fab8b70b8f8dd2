"""The report's drawing code (src/rbcstab/report/python: phase_draw.py, bifurcation_draw.py), shared with the CLI's
report and plot so that a figure drawn from Python follows the same rules. Found as the CLI finds it:
$RBCSTAB_DATA_DIR, the installed share folder, or the source tree."""
import importlib.util
import os
import sys

from . import _rbcstab


def drawing_module(name):
    """The report's module `name` (e.g. "phase_draw"), imported once."""
    key = "rbcstab._" + name
    module = sys.modules.get(key)
    if module is None:
        folder = _rbcstab.report_script_dir()
        path = os.path.join(folder, name + ".py") if folder else ""
        if not path or not os.path.isfile(path):
            raise OSError(f"{name}.py (the report's drawing code) not found; set RBCSTAB_DATA_DIR to the folder "
                          "holding rbcstab_report.py")
        spec = importlib.util.spec_from_file_location(key, path)
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        sys.modules[key] = module
    return module

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


def keep_legends_inside(ax):
    """Makes room for a legend drawn outside the axes (the phase diagram's, right of the plane): when one would
    fall outside the figure and the figure has no layout engine of its own, constrained layout takes over (it
    places legends too). A figure the user laid out (a layout engine set) is left as it is. Returns ax."""
    figure = ax.figure
    legend = ax.get_legend()
    if legend is None or figure.get_layout_engine() is not None:
        return ax
    get_renderer = getattr(figure.canvas, "get_renderer", None)  # Agg-based canvases (inline, Qt, Tk, files)
    if get_renderer is None:
        return ax
    box, page = legend.get_window_extent(get_renderer()), figure.bbox
    if box.x0 < page.x0 or box.y0 < page.y0 or box.x1 > page.x1 or box.y1 > page.y1:
        figure.set_layout_engine("constrained")
    return ax

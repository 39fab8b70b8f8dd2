"""Axis rules shared by the report's figures and the Python package's plots. It chooses no matplotlib backend (the
package imports it into the user's session)."""
import math


def excess_area_limits(series):
    """y limits of a log axis of Delta_l(t) curves: from 1e-4 below the smallest start (but at most 12 decades
    below the top) to 3x the top. Decayed modes fall by hundreds of decades and would squeeze the others into a
    few pixels; what falls below is off the axis, not drawn at 1e-100. None when no series starts positive."""
    start = [s[0] for s in series if len(s) and math.isfinite(s[0]) and s[0] > 0]
    values = [v for s in series for v in s if math.isfinite(v) and v > 0]
    if not start or not values:
        return None
    top = max(values)
    return max(min(start) * 1e-4, top * 1e-12), top * 3

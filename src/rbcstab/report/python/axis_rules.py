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


def transient_time_scale(t, series, limits=None, settled=0.95, share=0.1, decades=2.0):
    """Time-axis scale of Delta_l(t) curves: ("symlog", t1) when the transient spans decades, else ("linear", None).
    The change of the curves is measured in log10 (clipped to `limits`, the y axis): when `settled` of it is done
    within the first `share` of the span and the positive samples span at least `decades` decades, a linear axis
    would squeeze the transient into a few pixels; symlog (linear below the first positive sample t1, so t = 0 stays
    on the axis, logarithmic above) spreads it out."""
    times = [x for x in t if math.isfinite(x)]
    positive = [x for x in times if x > 0]
    if len(times) < 3 or not positive or max(times) / min(positive) < 10 ** decades:
        return "linear", None
    lo, hi = limits if limits else (1e-300, math.inf)
    change = [0.0] * len(t)
    for s in series:
        prev = None
        for k, v in enumerate(s):
            if not (math.isfinite(v) and v > 0):
                continue  # a skipped sample (NaN) or a mode that left the axis at 0
            y = math.log10(min(max(v, lo), hi))
            if prev is not None:
                change[k] += abs(y - prev)
            prev = y
    total = sum(change)
    if total <= 0:
        return "linear", None
    done, t_settled = 0.0, times[-1]
    for x, c in zip(t, change):
        done += c
        if done >= settled * total:
            t_settled = x
            break
    if t_settled - times[0] > share * (times[-1] - times[0]):
        return "linear", None
    return "symlog", min(positive)

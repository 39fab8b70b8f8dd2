"""The time-axis rule of the Delta_l(t) figures (axis_rules.transient_time_scale, shared by the report and
Simulation.plot): symlog when the change happens in the first tenth of a span of decades, linear otherwise."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "src", "rbcstab", "report", "python"))
import axis_rules  # noqa: E402 (math only: no matplotlib needed)

T = [float(k) for k in range(501)]  # the default scene's grid: 0, 1, ..., 500


def relaxing(tau):
    """Delta_2 relaxing from 1 to 0.3 and a decaying Delta_3 from 1e-3, both on the time scale tau."""
    return [[0.3 + 0.7 * math.exp(-t / tau) for t in T], [1e-3 * math.exp(-t / tau) for t in T]]


def test_fast_transient_gets_a_log_time_axis_from_the_first_sample():
    s = relaxing(2.0)
    assert axis_rules.transient_time_scale(T, s, axis_rules.excess_area_limits(s)) == ("symlog", 1.0)


def test_slow_transient_oscillation_and_short_spans_stay_linear():
    # The same curves on a time scale of the whole run: the rule must not fire (a wrong input for it).
    s = relaxing(100.0)
    assert axis_rules.transient_time_scale(T, s, axis_rules.excess_area_limits(s)) == ("linear", None)
    swinging = [[0.1 * (1.5 + math.sin(t / 10)) for t in T]]
    assert axis_rules.transient_time_scale(T, swinging) == ("linear", None)
    # A fast transient but samples over less than two decades of t: nothing to gain from a log axis.
    short = [0.0] + [0.1 * k for k in range(1, 11)]
    assert axis_rules.transient_time_scale(short, [[math.exp(-t) for t in short]]) == ("linear", None)
    assert axis_rules.transient_time_scale(T, [[0.5] * len(T)]) == ("linear", None)  # nothing changes


def test_skipped_samples_and_modes_below_the_axis_do_not_count():
    s = relaxing(2.0)
    s[1][200:] = [float("nan")] * (len(T) - 200)  # a certified early stop: NaN after it
    s.append([1e-200] * len(T))  # below the axis: clipped, no change
    assert axis_rules.transient_time_scale(T, s, axis_rules.excess_area_limits(s)) == ("symlog", 1.0)

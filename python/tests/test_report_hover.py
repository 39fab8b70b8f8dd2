"""The report's hover data (rbcstab_report.hover_data): the page's script places each point by the axes box and
limits it records; checked against where matplotlib really drew a marker in the PNG (its pixels)."""
import math
import os
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "src", "rbcstab", "report", "python"))
report = pytest.importorskip("rbcstab_report")  # needs matplotlib, as the report does
image = pytest.importorskip("matplotlib.image")


def placed(hover, x, y, flip=False):
    """Where the page's script puts (x, y): the same arithmetic as hover_script() in report/detail/html_text.cpp."""
    def frac(v, a):
        lo, hi = a["lim"]
        if a["scale"] == "log":
            v, lo, hi = math.log(v), math.log(lo), math.log(hi)
        return (v - lo) / (hi - lo)
    left, top, right, bottom = hover["axes_px"]
    fy = frac(y, hover["y"])
    return left + frac(x, hover["x"]) * (right - left), (top + fy * (bottom - top)) if flip else (
        bottom - fy * (bottom - top))


def red_centre(png):
    """Centre of the pure red pixels of an RGBA image (the marker drawn for the test)."""
    img = image.imread(png)
    mask = (img[..., 0] > 0.9) & (img[..., 1] < 0.1) & (img[..., 2] < 0.1)
    rows, cols = mask.nonzero()
    assert len(rows) > 10
    return cols.mean() + 0.5, rows.mean() + 0.5  # pixel centres


@pytest.mark.parametrize("xscale", ["linear", "log"])
def test_hover_places_points_where_matplotlib_drew_them(tmp_path, xscale):
    fig, ax = report.new_figure((500, 400))
    xs, ys = [1.0, 10.0, 100.0], [0.2, 0.7, 0.4]
    ax.plot(xs, ys, color="0.5")
    ax.plot([10.0], [0.7], "s", color=(1, 0, 0), ms=12, mew=0)
    ax.set_xscale(xscale)
    ax.set_xlabel("x")
    out = str(tmp_path / "f.png")
    entry = report.save(fig, out, (500, 400), hover=(ax, ["x", "y"], list(zip(xs, ys))))
    hover = entry["hover"]
    assert hover["points"][1] == [10.0, 0.7]
    cx, cy = red_centre(out)
    px, py = placed(hover, 10.0, 0.7)
    # Within a pixel: the marker is rasterised on the pixel grid, the box edges are rounded to 0.01 px.
    assert abs(px - cx) < 1.0 and abs(py - cy) < 1.0, (px, py, cx, cy)
    # The check fails on a wrong mapping: y measured from the top instead of the bottom.
    fx, fy = placed(hover, 10.0, 0.7, flip=True)
    assert abs(fy - cy) > 20


def test_phase_diagram_and_bifurcation_carry_their_points(tmp_path):
    csv = tmp_path / "phase.csv"
    csv.write_text("index,i,j,ln_B,ln_C,verdict,l_Delta\n" + "".join(
        f"{3 * i + j},{i},{j},{i},{j - 2},x,{2 + (i > j)}\n" for i in range(3) for j in range(3)))
    phase = report.plot_phase_diagram(str(csv), str(tmp_path / "p.png"), size_px=(400, 300))["hover"]
    assert phase["columns"] == ["ln_B", "ln_C", "l_Delta"]
    assert sorted(map(tuple, phase["points"])) == sorted((i, j - 2, 2 + (i > j)) for i in range(3) for j in range(3))
    spec = {"x": {"name": "C"}, "y": {"name": "r"},
            "series": [{"name": "eq", "segments": [{"stability": "stable", "x": [0, 1, None], "y": [0.5, 0.6, 0.7]}]}],
            "points": [{"x": 1, "y": 0.6, "series": 0, "text": "BP 3", "type": "BP"}]}
    columns, points = report.bifurcation_points(spec)
    assert columns == ["C", "r", "branch", "point"]
    assert points == [[0, 0.5, "eq", "stable"], [1, 0.6, "eq", "stable"], [1, 0.6, "eq", "BP 3"]]  # no None vertex

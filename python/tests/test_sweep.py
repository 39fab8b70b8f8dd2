"""diagram, trace, fig6e: the CLI's documents on the same scenes (bitwise: the same code runs), the arrays'
orientation against single runs, determinism over threads, progress, Ctrl-C and bad input."""
import json
import math
import os
import signal
import subprocess
import threading
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import rbcstab  # noqa: E402
import rbcstab.progress  # noqa: E402
from conftest import _cli_path, without_timing  # noqa: E402

# A quick plane around the paper's Fig. 3 case (4 modes, short horizon): stable and unstable points.
SCENE = dict(L=5, T=40.0, dt=40.0)
PLANE = dict(axes=("lnB", "lnC"), x_range=(-1.0, 5.0), y_range=(-5.0, 1.0))
PLANE_FLAGS = ["--L", 5, "--T", 40, "--dt", 40, "--axes", "lnB,lnC", "--x-range=-1,5", "--y-range=-5,1"]


def run_cli(*args):
    out = subprocess.run([_cli_path(), *map(str, args)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return out


def read(path):
    with open(path) as f:
        return f.read()


@pytest.fixture(scope="module")
def diagram_8x8():
    return rbcstab.diagram(rbcstab.Scene(**SCENE), counts=(8, 8), threads=2, progress=False, **PLANE)


def test_diagram_equals_the_cli_files(diagram_8x8, tmp_path):
    run_cli("diagram", *PLANE_FLAGS, "--counts", "8,8", "--threads", 2, "--out", tmp_path / "cli", "--no-journal",
            "--quiet")
    assert without_timing(diagram_8x8.to_dict()) == without_timing(json.loads(read(tmp_path / "cli.json")))
    # without per-point seconds both write the same bytes
    quiet = rbcstab.diagram(rbcstab.Scene(**SCENE), counts=(8, 8), threads=2, progress=False, include_seconds=False,
                            **PLANE)
    run_cli("diagram", *PLANE_FLAGS, "--counts", "8,8", "--out", tmp_path / "bare", "--no-journal", "--quiet",
            "--no-seconds")
    quiet.save(tmp_path / "py")
    assert read(tmp_path / "py.json") == read(tmp_path / "bare.json")
    assert read(tmp_path / "py.csv") == read(tmp_path / "bare.csv") == quiet.to_csv()
    assert "seconds" not in quiet.__dir__() and not hasattr(quiet, "seconds")


def test_a_shard_equals_the_cli_shard_file(tmp_path):
    d = rbcstab.diagram(rbcstab.Scene(**SCENE), counts=(3, 2), shard=(1, 2), progress=False, **PLANE)
    run_cli("diagram", *PLANE_FLAGS, "--counts", "3,2", "--shard", "1/2", "--out", tmp_path / "cli", "--no-journal",
            "--quiet")
    assert without_timing(d.to_dict()) == without_timing(json.loads(read(tmp_path / "cli.shard1of2.json")))
    assert d.agreement is None and "shard 1/2" in repr(d)
    # the other shard's points are -1 / '' / NaN
    assert d.l_Delta.ravel().tolist()[0::2] == [-1, -1, -1] and min(d.l_Delta.ravel()[1::2]) >= 2
    assert d.verdict[0, 0] == "" and math.isnan(d.growth[0, 0])


def test_diagram_is_the_same_on_one_and_two_threads(diagram_8x8):
    one = rbcstab.diagram(rbcstab.Scene(**SCENE), counts=(8, 8), threads=1, progress=False, schedule="static",
                          **PLANE)
    assert without_timing(one.to_dict()) == without_timing(diagram_8x8.to_dict())
    for name in rbcstab.Diagram._ARRAYS:
        if name != "seconds":
            assert np.array_equal(getattr(one, name), getattr(diagram_8x8, name)), name
    assert np.array_equal(one.x, diagram_8x8.x) and np.array_equal(one.y, diagram_8x8.y)


def test_arrays_are_rows_of_y_and_columns_of_x():
    # nx != ny: a transposed array could not pass
    d = rbcstab.diagram(rbcstab.Scene(**SCENE), counts=(5, 3), threads=2, progress=False, **PLANE)
    assert d.axes == ("lnB", "lnC") and d.lnB is d.x and d.lnC is d.y
    assert d.x.tolist() == [-1.0, 0.5, 2.0, 3.5, 5.0] and d.y.tolist() == [-5.0, -2.0, 1.0]
    assert d.shape == (3, 5) and d.l_Delta.shape == (3, 5) and d.verdict.shape == (3, 5)
    assert d.l_Delta.dtype == np.int64 and d.growth.dtype == np.float64 and d.oscillating.dtype == bool
    for p in d.to_dict()["points"]:
        i, j = p["i"], p["j"]
        assert (d.x[i], d.y[j]) == (p["x"], p["y"])
        assert d.l_Delta[j, i] == p["l_Delta"] and d.verdict[j, i] == p["verdict"] and d.status[j, i] == p["status"]
        assert d.sigma_final[j, i] == p["sigma_final"] and d.rhs_evaluations[j, i] == p["rhs_evaluations"]
    assert len(set(d.l_Delta.ravel().tolist())) > 1, "the plane should hold stable and unstable points"
    # one unstable point against a single run of its scene (an independent call: rbcstab.simulate)
    j, i = map(int, np.argwhere(d.l_Delta >= 3)[0])
    scene = d.point_scene(i, j)
    assert math.isclose(math.log(scene.B), d.x[i], rel_tol=0, abs_tol=1e-15)
    assert math.isclose(math.log(scene.C), d.y[j], rel_tol=0, abs_tol=1e-15)
    run = rbcstab.simulate(scene, model="modal")
    assert run.L == 5 and run.l_Delta == d.l_Delta[j, i] and run.sigma_final == d.sigma_final[j, i]
    assert run.status == d.status[j, i]


def test_diagram_result_prints_plots_and_renders(diagram_8x8):
    r = repr(diagram_8x8)
    assert "\n" not in r and "lnB x lnC" in r and "8 x 8" in r
    assert "<table>" in diagram_8x8._repr_html_()
    fig, ax = plt.subplots()
    assert diagram_8x8.plot(ax=ax) is ax
    half_step = 6.0 / 7 / 2  # cells centred on the points
    assert len(ax.images) == 1 and ax.get_xlim() == pytest.approx((-1 - half_step, 5 + half_step))
    assert len(ax.lines) > 0  # the paper's analytic lines on the lnB - lnC plane
    plt.close(fig)
    fig, ax = plt.subplots()
    diagram_8x8.plot(ax=ax, analytic_lines=False)
    assert len(ax.images) == 1 and len(ax.lines) == 0
    plt.close(fig)
    assert diagram_8x8.summary["points"] == 64 and diagram_8x8.complete
    assert diagram_8x8.agreement["predictor"] == "asymptotic"


def test_trace_equals_the_cli(tmp_path):
    t = rbcstab.trace(rbcstab.Scene(**SCENE), **PLANE)
    run_cli("trace", *PLANE_FLAGS, "--out", tmp_path / "cli")
    cli = json.loads(read(tmp_path / "cli.json"))
    assert without_timing(t.to_dict()) == without_timing(cli)
    assert t.axes == ("lnB", "lnC") and len(t.curves) == len(cli["curves"]) > 0
    for curve, c in zip(t.curves, cli["curves"]):
        assert curve.l == c["l"] and curve.x.tolist() == c["x"] and curve.y.tolist() == c["y"]
        assert curve.mu.tolist() == c["mu"]
    assert t.corners["x"].tolist() == [k["x"] for k in cli["corners"]]
    assert t.corners["l_to"].tolist() == [k["l_to"] for k in cli["corners"]]
    assert t.to_csv() == read(tmp_path / "cli.csv")
    assert "\n" not in repr(t) and "<table>" in t._repr_html_()
    fig, ax = plt.subplots()
    assert t.plot(ax=ax) is ax and len(ax.lines) >= len(t.curves)
    plt.close(fig)


def test_trace_method_in_plane_closed_form_and_continuation_agree(tmp_path):
    # In plane (beta = pi/2) on a ln B x ln C plane, method="auto" traces in closed form in B; "continuation" traces
    # the same zero set by continuation: same pieces and corners (both located to ~1e-11), and the CLI's --method
    # gives the same document.
    scene = rbcstab.Scene(**SCENE, beta=math.pi / 2)
    opts = dict(PLANE, samples=32, max_step=0.05)
    auto, cont = rbcstab.trace(scene, **opts), rbcstab.trace(scene, method="continuation", **opts)
    assert auto.method == "in closed form in B" and cont.method == "by continuation"
    assert auto.evaluations < cont.evaluations
    assert [c.l for c in auto.curves] == [c.l for c in cont.curves] and len(auto.curves) > 0
    assert auto.corners["l_to"].tolist() == cont.corners["l_to"].tolist()
    np.testing.assert_allclose(auto.corners["x"], cont.corners["x"], atol=1e-8)
    np.testing.assert_allclose(auto.corners["y"], cont.corners["y"], atol=1e-8)
    run_cli("trace", *PLANE_FLAGS, "--beta", math.pi / 2, "--samples", 32, "--max-step", 0.05, "--method",
            "continuation", "--out", tmp_path / "cli")
    cli = json.loads(read(tmp_path / "cli.json"))
    assert without_timing(cont.to_dict()) == without_timing(cli)
    assert cli["method"] == "by continuation" and cli["options"]["method"] == "continuation"


def test_trace_agreement_with_a_diagram_equals_the_cli(diagram_8x8, tmp_path):
    diagram_8x8.save(tmp_path / "d")
    # coarse tracing options: the finite-horizon boundary is traced too (one reduced run per evaluation)
    coarse = dict(lines=0, samples=16, max_step=0.1)
    t = rbcstab.trace(rbcstab.Scene(**SCENE), diagram=diagram_8x8, **coarse, **PLANE)
    run_cli("trace", *PLANE_FLAGS, "--out", tmp_path / "cli", "--diagram", tmp_path / "d.json", "--lines", 0,
            "--samples", 16, "--max-step", 0.1)
    assert without_timing(t.to_dict()) == without_timing(json.loads(read(tmp_path / "cli.json")))
    assert t.agreement["predictor"] == "asymptotic"
    with pytest.raises(ValueError, match="plane"):
        rbcstab.trace(rbcstab.Scene(**SCENE), diagram=diagram_8x8, axes=("lnC", "lnB"))


def _legends_inside(figure):
    figure.canvas.draw()
    renderer, page = figure.canvas.get_renderer(), figure.bbox
    boxes = [a.get_legend().get_window_extent(renderer) for a in figure.axes if a.get_legend() is not None]
    return boxes and all(b.x0 >= page.x0 and b.y0 >= page.y0 and b.x1 <= page.x1 and b.y1 <= page.y1 for b in boxes)


def test_plots_keep_their_legends_inside_the_figure(diagram_8x8):
    # The phase diagram's legend sits right of the plane: on pyplot's default figure it used to fall off the page.
    figure = plt.figure(figsize=(6.4, 4.8))
    diagram_8x8.plot()
    assert _legends_inside(figure)
    plt.close(figure)
    figure = plt.figure(figsize=(6.4, 4.8))  # the oracle: the same drawing without the fit does fall off
    rbcstab.sweep.phase_draw().draw_phase_diagram(plt.gca(), [], [], [], "lnB", "lnC", diagram_8x8._overlay()["curves"],
                                                  limits=((-1.0, 5.0), (-5.0, 1.0)))
    assert not _legends_inside(figure)
    plt.close(figure)
    figure, ax = plt.subplots(layout="tight")  # a figure laid out by its user is left alone
    diagram_8x8.plot(ax=ax)
    assert figure.get_layout_engine().__class__.__name__ == "TightLayoutEngine"
    plt.close(figure)


def test_trace_and_fig6e_progress_count_their_unit_of_work():
    # The final report equals the count each document states: the trace's criterion evaluations, the table's runs.
    calls = []
    t = rbcstab.trace(rbcstab.Scene(**SCENE), progress=lambda d, n, eta: calls.append((d, n)), **PLANE)
    assert calls and [d for d, _ in calls] == sorted(d for d, _ in calls)
    assert calls[-1][0] == t.evaluations and all(n == 0 for _, n in calls)  # its total is not known in advance
    calls.clear()
    table = rbcstab.fig6e(rbcstab.Scene(T=20.0, L=5), lambdas=[5.0], B=[2.0, 8.0], C=[0.04],
                          progress=lambda d, n, eta: calls.append((d, n)))
    assert calls[-1] == (len(table), len(table)) == (2, 2)
    with pytest.raises(TypeError, match="progress"):
        rbcstab.fig6e(rbcstab.Scene(T=20.0, L=5), lambdas=[5.0], B=[2.0], C=[0.04], progress="yes")


def test_fig6e_equals_the_cli():
    scene = rbcstab.Scene(T=100.0, L=6)
    table = rbcstab.fig6e(scene, lambdas=[5.0], B=[2.0, 8.0], C=[0.04])
    out = run_cli("post", "--fig6e", "--json", "--T", 100, "--L", 6, "--fig6e-lambda", 5, "--fig6e-B", 2, 8,
                  "--fig6e-C", 0.04)
    cli = json.loads(out.stdout)
    assert table.to_dict() == cli
    assert len(table) == len(cli["rows"]) == 2
    for name in table.columns:
        expected = [math.nan if r[name] is None else r[name] for r in cli["rows"]]
        np.testing.assert_array_equal(table[name], np.array(expected))
    csv = run_cli("post", "--fig6e", "--T", 100, "--L", 6, "--fig6e-lambda", 5, "--fig6e-B", 2, 8, "--fig6e-C", 0.04)
    assert table.to_csv() == csv.stdout
    assert "\n" not in repr(table) and "<table>" in table._repr_html_()


def test_fig6e_plot_draws_the_table_on_the_given_axes():
    # One row per (lambda, B, C); B = 0.5 is stable at both lambdas (l_Delta = 2): NaN, not drawn.
    table = rbcstab.fig6e(rbcstab.Scene(T=60.0, L=4), lambdas=[1.0, 5.0], B=[0.5, 8.0], C=[0.04])
    compared = np.isfinite(table["Delta2_tilde"]) & np.isfinite(table["Delta2_simulated"])
    assert 0 < compared.sum() < len(table)  # the oracle: some rows have a value to draw, some do not
    fig, (ax, other, bare) = plt.subplots(1, 3)
    assert table.plot(ax=ax) is ax and not other.collections and not other.lines
    drawn = np.concatenate([c.get_offsets() for c in ax.collections])
    expected = np.column_stack([table["Delta2_simulated"][compared], table["Delta2_tilde"][compared]])
    np.testing.assert_array_equal(np.sort(drawn, axis=0), np.sort(expected, axis=0))
    assert len(ax.collections) == len(set(table["lambda"][compared]))  # one marker set per lambda
    assert [line.get_label() for line in ax.lines] == ["diagonal"]  # no line joins the rows
    assert len(ax.child_axes) == 1  # the ratio inset
    table.plot(ax=bare, ratio_inset=False)
    assert not bare.child_axes
    with pytest.raises(TypeError, match="ratio_inset"):
        table.plot(ax=bare, ratio_inset="no")
    plt.close(fig)


def test_every_result_plot_takes_ax_first():
    import inspect
    for f in (rbcstab.Simulation.plot, rbcstab.Branch.plot, rbcstab.Curve.plot, rbcstab.Diagram.plot,
              rbcstab.Trace.plot, rbcstab.Fig6eTable.plot, rbcstab.plot_branches):
        first = list(inspect.signature(f).parameters)[1]  # after self, or plot_branches' branches
        assert first == "ax" and inspect.signature(f).parameters["ax"].default is None, f.__qualname__


def test_progress_plain_text_goes_to_stderr(capsys, monkeypatch):
    monkeypatch.setattr(rbcstab.progress, "_tqdm", lambda: None)
    rbcstab.diagram(rbcstab.Scene(**SCENE), counts=(3, 2), threads=1, progress=True, **PLANE)
    err = capsys.readouterr().err
    assert "rbcstab diagram: 6/6 points (100%)" in err
    # one line per interval, then the final state once
    bar = rbcstab.progress.TextProgress("job", "steps", interval=0.0)
    with bar:
        bar(1, 4, 2.0)
        bar(2, 4, 1.0)
        bar(4, 4, 0.0)
    assert capsys.readouterr().err.splitlines() == ["job: 2/4 steps (50%), ETA 1.0 s", "job: 4/4 steps (100%)"]


def test_progress_callable_and_tqdm(capsys):
    seen = []
    rbcstab.diagram(rbcstab.Scene(**SCENE), counts=(3, 2), progress=lambda *a: seen.append(a), **PLANE)
    assert seen and seen[-1][:2] == (6, 6) and all(total == 6 for _, total, _ in seen)
    with pytest.raises(ZeroDivisionError):  # what the callable raises stops the run and comes out of it
        rbcstab.diagram(rbcstab.Scene(**SCENE), counts=(3, 2), progress=lambda *a: 1 / 0, **PLANE)
    pytest.importorskip("tqdm")
    rbcstab.diagram(rbcstab.Scene(**SCENE), counts=(3, 2), progress=True, **PLANE)
    err = capsys.readouterr().err
    assert "rbcstab diagram" in err and "6/6" in err


def test_ctrl_c_stops_a_diagram_within_a_second_and_the_journal_resumes(tmp_path):
    journal = tmp_path / "big.journal"
    # 16 x 16 points at L = 8 integrated to T = 4000: about two seconds of work (~16 ms a point on one core). With
    # early termination, or at T = 500 (0.27 s in all, measured), the grid can finish before the interrupt is seen:
    # the signal is handled at the progress calls, 0.1 s apart
    big = dict(axes=("lnB", "lnC"), counts=(16, 16), threads=2, journal=journal, finite_horizon_agreement=False)
    scene = rbcstab.Scene(L=8, T=4000.0, full_horizon=True)
    sent = []

    def interrupt_after_some_points(done, total, eta):
        # SIGINT from another thread once some points are in the journal, as a user's Ctrl-C
        if done >= 20 and not sent:
            sent.append(time.monotonic())
            threading.Timer(0.01, lambda: os.kill(os.getpid(), signal.SIGINT)).start()

    with pytest.raises(KeyboardInterrupt):
        rbcstab.diagram(scene, progress=interrupt_after_some_points, **big)
    elapsed = time.monotonic() - sent[0]
    assert elapsed < 1.0, elapsed
    # every record in the journal is whole: the same call resumes from them and computes only the rest
    d = rbcstab.diagram(scene, progress=False, **big)
    assert d.complete and d.rejected == []
    assert 20 <= d.resumed < 256 and d.resumed + d.computed == 256
    # a journal of another configuration is refused, not misread
    with pytest.raises(ValueError, match="journal"):
        rbcstab.diagram(scene.replace(T=100.0), progress=False, **big)


def test_ctrl_c_stops_a_finite_horizon_trace_within_a_second():
    # by continuation, one reduced run over T = 400 per criterion evaluation, thousands of them: about 3 s of work
    # unless interrupted (at T = 40 an idle machine needs about 1 s, too close to the timer; method="auto" traces
    # this plane in closed form in B, one run per ln C, in well under the timer)
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        rbcstab.trace(rbcstab.Scene(**dict(SCENE, T=400.0, dt=400.0)), criterion="finite-horizon",
                      method="continuation", **PLANE)
    elapsed = time.monotonic() - start
    timer.join()
    assert elapsed < 0.5 + 1.0, elapsed


def test_the_gil_is_released_while_a_diagram_runs():
    # the diagram runs on another thread; this one keeps executing Python meanwhile
    done = []
    worker = threading.Thread(target=lambda: done.append(rbcstab.diagram(rbcstab.Scene(L=8, T=200.0), counts=(4, 4),
                                                                        threads=1, progress=False)))
    worker.start()
    spins = 0
    while worker.is_alive():
        spins += 1
        time.sleep(0.001)
    worker.join()
    assert done and done[0].complete and spins >= 10, spins


@pytest.mark.parametrize("kwargs, error, match", [
    (dict(axes=("lnB", "lnD")), ValueError, "lnD"),
    (dict(axes=("lnB",)), ValueError, "axes"),
    (dict(axes="lnB"), TypeError, "axes"),
    (dict(axes=("lnB", "lnB")), ValueError, "axes"),
    (dict(counts=(4, 4, 4)), ValueError, "counts"),
    (dict(counts=(4, -1)), ValueError, "counts"),
    (dict(counts=(0, 4)), ValueError, "counts"),
    (dict(counts=(4.0, 4)), TypeError, "counts"),
    (dict(counts=4), TypeError, "counts"),
    (dict(threads=1.5), TypeError, "threads"),
    (dict(threads="2"), TypeError, "threads"),
    (dict(threads=-1), ValueError, "threads"),
    (dict(x_range=(float("nan"), 1.0)), ValueError, "x_range"),
    (dict(y_range=(0.0, float("inf"))), ValueError, "y_range"),
    (dict(x_range=(0.0,)), ValueError, "x_range"),
    (dict(classifier="mean"), ValueError, "classifier"),
    (dict(alpha_fixed=-2.0), ValueError, "alpha_fixed"),
    (dict(schedule="random"), ValueError, "schedule"),
    (dict(shard="2/2"), ValueError, "shard"),
    (dict(shard=(0, 1, 2)), ValueError, "shard"),
    (dict(progress="yes"), TypeError, "progress"),
    (dict(journal=""), ValueError, "journal"),
])
def test_bad_diagram_input_raises_naming_it(kwargs, error, match):
    args = dict(counts=(2, 2), progress=False)
    args.update(kwargs)
    with pytest.raises(error, match=match):
        rbcstab.diagram(rbcstab.Scene(**SCENE), **args)


def test_bad_trace_and_fig6e_input_raises_naming_it():
    scene = rbcstab.Scene(**SCENE)
    with pytest.raises(TypeError, match="scene"):
        rbcstab.diagram({"L": 5})
    with pytest.raises(ValueError, match="criterion"):
        rbcstab.trace(scene, criterion="eventual")
    with pytest.raises(ValueError, match="lines"):
        rbcstab.trace(scene, lines=-1)
    with pytest.raises(ValueError, match="method"):
        rbcstab.trace(scene, method="closed")
    with pytest.raises(TypeError, match="samples"):
        rbcstab.trace(scene, samples=2.5)
    with pytest.raises(ValueError, match="x_range"):
        rbcstab.trace(scene, x_range=(0.0, float("nan")))
    with pytest.raises(TypeError, match="diagram"):
        rbcstab.trace(scene, diagram=42)
    with pytest.raises(ValueError, match="B"):
        rbcstab.fig6e(scene, B=[-1.0])
    with pytest.raises(TypeError, match="lambdas"):
        rbcstab.fig6e(scene, lambdas=5.0)


def test_phase_drawing_puts_a_geometric_axis_on_a_log_scale():
    # A shear_rate axis is spaced evenly in ln: its cells are drawn on a log axis with edges at the geometric
    # midpoints, so a point's cell contains it; an evenly spaced axis keeps the linear scale.
    from rbcstab.sweep import phase_draw
    pd = phase_draw()
    xs_g = [10.0, 100.0, 1000.0]
    ys = [1.0, 3.0]
    X, Y = np.meshgrid(xs_g, ys)
    ld = [2, 4, 4, 2, 2, 4]
    fig, ax = plt.subplots()
    label = {r["name"]: r["label"] for r in rbcstab.parameter_table()}
    pd.draw_phase_diagram(ax, X.ravel().tolist(), Y.ravel().tolist(), ld, "shear_rate", "lambda",
                          labels={"x": label["shear_rate"], "y": label["lambda"]})
    assert ax.get_xscale() == "log" and ax.get_yscale() == "linear"
    assert ax.get_xlabel() == r"$\dot\gamma$ [1/s]" and ax.get_ylabel() == r"$\lambda$"
    lo, hi = ax.get_xlim()
    assert lo == pytest.approx(10 / math.sqrt(10)) and hi == pytest.approx(1000 * math.sqrt(10))
    plt.close(fig)
    fig, ax = plt.subplots()
    X, Y = np.meshgrid([1.0, 2.0, 3.0], ys)
    pd.draw_phase_diagram(ax, X.ravel().tolist(), Y.ravel().tolist(), ld, "lnB", "lambda")
    assert ax.get_xscale() == "linear" and ax.get_xlim() == pytest.approx((0.5, 3.5))
    plt.close(fig)

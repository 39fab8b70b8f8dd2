"""simulate, thresholds, post, summary: the CLI's JSON on the same scenes (bitwise: the same code runs)."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import rbcstab
from conftest import without_timing

SHORT = dict(T=20.0, dt=0.5)


def test_simulate_equals_the_cli_json(cli):
    run = rbcstab.simulate(rbcstab.Scene(**SHORT))
    assert without_timing(run.to_dict()) == without_timing(cli("simulate", "--T", 20, "--dt", 0.5))


def test_simulate_in_plane_full_level_equals_the_cli(cli):
    scene = rbcstab.Scene(beta=np.pi / 2, L=5, T=10.0, model="full")
    run = rbcstab.simulate(scene, stepper="rkf45", rtol=1e-7)
    expected = cli("simulate", "--beta", repr(np.pi / 2), "--L", 5, "--T", 10, "--model", "full",
                   "--stepper", "rkf45", "--rtol", 1e-7)
    assert without_timing(run.to_dict()) == without_timing(expected)


def test_simulate_arrays_match_the_scalars():
    run = rbcstab.simulate(rbcstab.Scene(**SHORT))
    n = len(run.t)
    assert run.t[0] == 0.0 and run.t[-1] == 20.0 and n == 41
    assert run.Delta.shape == (n, run.L - 1)
    for a in (run.sigma, run.r, run.Psi):
        assert a.shape == (n,) and a.dtype == np.float64
    # the last sample is the state at T, which the JSON reports
    for l in run.ls:
        assert run.Delta[-1, l - 2] == run.excess_area_final[str(l)]
    assert run.sigma[-1] == run.sigma_final
    # the excess area is conserved along the trajectory to the reported drift
    assert np.max(np.abs(run.Delta.sum(axis=1) - run.excess_area_total)) <= run.excess_area_drift + 1e-15
    assert run.status == "success" and run.rhs_evaluations > 0 and "\n" not in repr(run)


def test_thresholds_post_summary_equal_the_cli(cli):
    scene = rbcstab.Scene(**SHORT)
    assert rbcstab.thresholds(scene) == cli("thresholds", "--T", 20, "--dt", 0.5)
    assert without_timing(rbcstab.post(scene)) == without_timing(cli("post", "--T", 20, "--dt", 0.5))
    s = rbcstab.summary(scene)
    assert without_timing(s) == without_timing(cli("summary", "--T", 20, "--dt", 0.5))
    assert s.text.startswith("rbcstab ") and "\n" not in repr(s)


def test_an_overflowing_run_prints_without_nan():
    # lambda = 1e308 is in range but overflows at t = 0: sigma(T) is null in the JSON, with its reason
    run = rbcstab.simulate(rbcstab.Scene(T=5.0, **{"lambda": 1e308}))
    assert run.status == "non_finite_state" and run.sigma_final is None and "lambda = 1e+308" in run.reason
    assert "sigma(T)=n/a" in repr(run) and "nan" not in repr(run).lower() and "nan" not in run.text.lower()
    for report in (rbcstab.thresholds, rbcstab.post, rbcstab.summary):
        r = report(rbcstab.Scene(T=5.0, **{"lambda": 1e308}))
        assert r["scene"] == "fig3_op" and "nan" not in r.text.lower() and "nan" not in repr(r).lower()


def test_bad_arguments_raise():
    with pytest.raises(TypeError):
        rbcstab.simulate({"lambda": 5})
    with pytest.raises(ValueError, match="rtol"):
        rbcstab.simulate(rbcstab.Scene(), rtol=-1.0)
    with pytest.raises(ValueError, match="stepper"):
        rbcstab.simulate(rbcstab.Scene(), stepper="euler9")
    with pytest.raises(TypeError):
        rbcstab.thresholds(rbcstab.Scene(), exact_C_star="yes")


def test_ctrl_c_stops_a_long_simulation_within_a_second():
    # full level at L = 30 over a long horizon: minutes of work unless interrupted
    scene = rbcstab.Scene(L=30, model="full", T=1e6, dt=1e3)
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        rbcstab.simulate(scene)
    elapsed = time.monotonic() - start
    timer.join()
    assert elapsed < 0.5 + 1.0, elapsed


def test_the_gil_is_released_while_simulating():
    # a Python thread keeps running while another thread simulates
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.005)

    t = threading.Thread(target=tick)
    t.start()
    start = time.monotonic()
    # ~0.35 s here: long against the 5 ms ticks and the 0.05 s floor below on any machine
    rbcstab.simulate(rbcstab.Scene(L=12, model="full", T=1000.0))
    end = time.monotonic()
    stop.set()
    t.join()
    during = [x for x in ticks if start < x < end]
    assert end - start > 0.05 and len(during) >= 3


def test_early_stop_samples_are_masked_not_joined():
    """A certified early stop keeps every grid time: the skipped samples are NaN with integrated False, as the
    JSON counts them; every integrated sample is finite (no silent jump from the stop to the last period)."""
    run = rbcstab.simulate(rbcstab.Scene(T=500.0, dt=1.0))
    assert run.terminated_at is not None
    assert len(run.t) == 501 and run.samples == 501
    assert run.samples_integrated == int(run.integrated.sum()) < 501
    skipped = ~run.integrated
    assert np.all((run.t[skipped] > run.terminated_at) & (run.t[skipped] < run.early_termination["resumed_at"]))
    assert np.all(np.isnan(run.sigma[skipped])) and np.all(np.isnan(run.Delta[skipped]))
    assert np.all(np.isfinite(run.sigma[run.integrated])) and np.all(np.isfinite(run.Delta[run.integrated]))
    np.testing.assert_array_equal(run.t, np.arange(501.0))  # the grid's times, skipped rows included


def test_early_stop_arrays_equal_the_cli_csv(tmp_path):
    """The arrays and the CLI's --trajectory CSV walk the same rows: equal bit for bit (round-trip digits), NaN
    (empty fields) on the same skipped rows, the same integrated column."""
    from conftest import _cli_path
    import subprocess
    run = rbcstab.simulate(rbcstab.Scene(T=500.0, dt=1.0, L=6))
    assert not run.integrated.all()
    csv = tmp_path / "t.csv"
    subprocess.run([_cli_path(), "simulate", "--T", "500", "--dt", "1", "--L", "6", "--trajectory", str(csv)],
                   check=True, capture_output=True)
    rows = np.genfromtxt(csv, delimiter=",", names=True)
    np.testing.assert_array_equal(rows["t"], run.t)
    np.testing.assert_array_equal(rows["integrated"].astype(bool), run.integrated)
    for name in ("sigma", "r", "Psi"):
        np.testing.assert_array_equal(rows[name], getattr(run, name))
    for l in run.ls:
        np.testing.assert_array_equal(rows[f"Delta_{l}"], run.Delta[:, l - 2])


def test_plot_draws_on_the_given_axes_and_breaks_at_the_skip():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    run = rbcstab.simulate(rbcstab.Scene(T=500.0, dt=1.0, L=4))
    skipped = ~run.integrated
    assert skipped.any()
    fig, (ax, other) = plt.subplots(1, 2)
    for sigma in (False, True):
        ax.clear()
        assert run.plot(ax=ax, sigma=sigma) is ax and not other.lines
        assert ax.lines
        for line in ax.lines:  # a NaN on every skipped row: matplotlib draws no segment across the span
            assert np.all(np.isnan(np.asarray(line.get_ydata(), dtype=float)[skipped]))
    plt.close(fig)


def test_t_eval_and_dense_output():
    times = [0.0, 0.3, 7.25, 19.9]
    run = rbcstab.simulate(rbcstab.Scene(**SHORT), t_eval=np.array(times), dense_output=True)
    assert run.t.tolist() == times and run.integrated.all()
    # The dense output through the accepted steps agrees with the samples the integrator stopped at, to its
    # error (rtol 1e-8 of O(1) values: 1e-6 leaves room for both runs' global errors).
    at = run.sol(np.array(times))
    assert at["Delta"].shape == (4, run.L - 1) and at["sigma"].shape == (4,)
    assert np.allclose(at["sigma"], run.sigma, rtol=1e-6, atol=0)
    assert np.allclose(at["Delta"], run.Delta, rtol=1e-6, atol=1e-12)
    assert np.isclose(run.sol(20.0)["sigma"], run.sigma_final, rtol=1e-14)
    assert rbcstab.simulate(rbcstab.Scene(**SHORT)).sol is None
    import pickle
    assert np.array_equal(pickle.loads(pickle.dumps(run)).sol(3.0)["Delta"], run.sol(3.0)["Delta"])


def test_t_eval_bad_values_name_it():
    scene = rbcstab.Scene(**SHORT)
    for bad, error in (([0.0, 2.0, 1.0], ValueError), ([0.0, 21.0], ValueError), ([np.nan], ValueError),
                       ([], ValueError), ([[0.0, 1.0]], ValueError), ("0 1", TypeError), ([0.0, "x"], TypeError)):
        with pytest.raises(error, match="t_eval"):
            rbcstab.simulate(scene, t_eval=bad)
    run = rbcstab.simulate(scene, dense_output=True)
    with pytest.raises(ValueError, match="t = 25"):
        run.sol(25.0)


def test_simulate_progress_counts_time_to_T():
    # t of T after the accepted steps, throttled; the final report is the end of the run: T.
    for scene in (rbcstab.Scene(T=60.0), rbcstab.Scene(T=60.0, full_horizon=True)):
        calls = []
        run = rbcstab.simulate(scene, progress=lambda done, total, eta: calls.append((done, total)))
        assert calls and calls[-1] == (scene.T, scene.T) and run.t[-1] == scene.T
        assert all(0 <= d <= scene.T for d, _ in calls)
    with pytest.raises(TypeError, match="progress"):
        rbcstab.simulate(rbcstab.Scene(T=1.0), progress="yes")


def test_plot_keeps_the_log_axis_to_the_data_that_matter():
    # The Fig. 3 run's l >= 4 modes decay by dozens of decades: autoscaled, the axis would reach their floor and
    # squeeze Delta_2, Delta_3 into a few pixels. The report's rule (axis_rules.py) keeps 12 decades below the top.
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    run = rbcstab.simulate(rbcstab.Scene(L=6))
    finite = run.Delta[np.isfinite(run.Delta) & (run.Delta > 0)]
    assert finite.min() < 1e-12 * finite.max()  # the oracle: the data do span more than the axis will
    fig, ax = plt.subplots()
    run.plot(ax=ax)
    bottom, top = ax.get_ylim()
    assert bottom >= 1e-12 * finite.max() * (1 - 1e-12) and top == pytest.approx(3 * finite.max())
    plt.close(fig)

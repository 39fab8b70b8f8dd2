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

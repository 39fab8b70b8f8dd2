"""rbcstab.continuation: the CLI's JSON on the same arguments (bitwise), branches against closed forms, a switched
branch, a BP curve, branch files shared with the CLI, bad input, Ctrl-C and the plot.

Oracle (docs/theory.md, "Full-model equilibria with a constant drive"; the C++ tests' full_fixtures.hpp): with
beta = 0 the drive S_{l,m} = C_{l,m} - Gamma3^l/C g_{l,m} is constant, an equilibrium is
f_{l,m} = -S_{l,m} / (i m/2 + Upsilon_l(sigma)) and sigma is the root of
sum_{l,m} a_l |S_{l,m}|^2 / (m^2/4 + Upsilon_l(sigma)^2) = Delta above every forced sigma_l^c. It is written here
from the paper's coefficients (Eq. gammas), not from rbcstab.
"""
import io
import math
import os
import pathlib
import pickle
import signal
import subprocess
import threading
import time
import warnings

import numpy as np
import pytest

import rbcstab
from conftest import without_timing

REPO = pathlib.Path(__file__).resolve().parents[2]
REST_L3 = str(REPO / "scenes" / "rest_l3_op.toml")  # lambda = B = Delta = 1, Delta0 = 0.01, beta = 0, rest l = 3
FULL_C = dict(kind="full", parameter="C", min=0.012, max=0.08, direction="backward")
FULL_C_FLAGS = ["--kind", "full", "--scene", REST_L3, "--parameter", "C", "--min", 0.012, "--max", 0.08,
                "--direction", "backward"]


# ------------------------------------------------------------------------------------- the closed form
def d_lambda(lam, l):
    return (2 * l**3 + 3 * l**2 + 4) + lam * (2 * l**3 + 3 * l**2 - 5)


def gamma2(lam, l):
    return -(l + 2) * (l + 1) * l * (l - 1) / d_lambda(lam, l)


def gamma3(lam, l):
    return -4 * (l + 2) * (l - 1) / d_lambda(lam, l)


def a_l(l):
    return (l + 2) * (l - 1) / 2


def sigma_c(l, alpha):
    Pi = l * (l + 1)
    return -(Pi + 4 * alpha / Pi)


def upsilon(l, sigma, lam, B, C):
    Pi = l * (l + 1)
    return gamma2(lam, l) / B * (Pi + sigma + 4 * (B / C) / Pi)


def drive(l, m, lam, C, Delta0, rest):
    """S_{l,m} at beta = 0: the shear C_{2,+-2} = -+4 i sqrt(30 pi)/(32 + 23 lambda) and the stress-free shape's
    m = 0 content g_{2,0} = -sqrt(Delta0/a_2), g_{l,0} = sqrt(rest_l/a_l)."""
    shear = (-1 if m == 2 else 1) * 4j * math.sqrt(30 * math.pi) / (32 + 23 * lam) if l == 2 and abs(m) == 2 else 0
    g = 0.0
    if m == 0:
        g = -math.sqrt(Delta0 / a_l(2)) if l == 2 else math.sqrt(rest.get(l, 0.0) / a_l(l))
    return shear - gamma3(lam, l) / C * g


def closed_form(lam=1.0, B=1.0, C=0.08, Delta=1.0, Delta0=0.01, L=5, rest=None):
    """(sigma, [Delta_2, ..., Delta_L]) of the equilibrium connected to the stable ellipsoid."""
    rest = rest or {}
    S = {(l, m): drive(l, m, lam, C, Delta0, rest) for l in range(2, L + 1) for m in range(-l, l + 1)}

    def areas(sigma):
        out = []
        for l in range(2, L + 1):
            Y = upsilon(l, sigma, lam, B, C)
            out.append(sum(a_l(l) * abs(S[l, m]) ** 2 / (m * m / 4 + Y * Y) for m in range(-l, l + 1) if S[l, m]))
        return out

    lo = max(sigma_c(l, B / C) for l in range(2, L + 1) if abs(S[l, 0]) > 0)
    hi = lo + 1
    while sum(areas(hi)) > Delta:
        hi = lo + 2 * (hi - lo)
    for _ in range(400):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if sum(areas(mid)) > Delta:
            lo = mid
        else:
            hi = mid
    sigma = 0.5 * (lo + hi)
    return sigma, areas(sigma)


def l4_threshold(B=1.0, lo=0.014, hi=0.017):
    """C where the closed-form sigma(C) of the rest-l3 scene reaches sigma_4^c(B/C) (the unforced l = 4 turns
    neutral), by bisection to the last bit."""
    def margin(C):
        return closed_form(B=B, C=C, rest={3: 1e-3})[0] - sigma_c(4, B / C)
    m_lo = margin(lo)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if (margin(mid) > 0) == (m_lo > 0):
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


# ------------------------------------------------------------------------------------- fixtures
@pytest.fixture(scope="module")
def rest_scene():
    return rbcstab.Scene.from_toml(REST_L3)


@pytest.fixture(scope="module")
def full_branch(rest_scene):
    """The full-model branch in C from 0.08 down to 0.012 of the rest-l3 scene (the CLI test's FULL_ARGS)."""
    return rbcstab.continuation(rest_scene, **FULL_C)


def cli_run(*args):
    out = subprocess.run([os.environ["RBCSTAB_CLI"], *map(str, args)], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    return out.stdout


# ------------------------------------------------------------------------------------- the CLI's JSON
def test_to_dict_equals_the_cli_json(cli, full_branch):
    assert without_timing(full_branch.to_dict()) == without_timing(cli("continue", *FULL_C_FLAGS))


def test_to_dict_equals_the_cli_json_for_scene_keywords_and_options(cli):
    # scene keywords as flags, the reduced system, options given
    scene = rbcstab.Scene(lambda_=2.0, B=1.5, C=0.05)
    b = rbcstab.continuation(scene, parameter="lambda", min=0.5, max=4, step=0.02, max_step=0.2, label_every=3)
    expected = cli("continue", "--lambda", 2, "--B", 1.5, "--C", 0.05, "--parameter", "lambda", "--min", 0.5,
                   "--max", 4, "--step", 0.02, "--max-step", 0.2, "--label-every", 3)
    assert without_timing(b.to_dict()) == without_timing(expected)
    assert b.kind == "equilibrium" and b.free_parameter == "lambda"


def test_curve_from_continuation_equals_the_cli(cli, rest_scene):
    c = rbcstab.continuation(rest_scene, **dict(FULL_C, min=0.014), curve="BP", parameter2="B", min2=0.9,
                             max2=1.1, point=1, max_step=0.05)
    expected = cli("continue", *FULL_C_FLAGS[:-6], "--min", 0.014, "--max", 0.08, "--direction", "backward",
                   "--curve", "BP", "--parameter2", "B", "--min2", 0.9, "--max2", 1.1, "--point", 1, "--max-step", 0.05)
    assert isinstance(c, rbcstab.Curve)
    assert without_timing(c.to_dict()) == without_timing(expected)


def test_orbit_options_equal_the_cli(cli):
    # every option a fresh orbit run maps (segments, relax_T, allow_unstable_start, max_points, label_every)
    scene = rbcstab.Scene(lambda_=5.0, Delta=0.3, Delta0=0.01, B=2.0, C=0.04, L=2)
    b = rbcstab.continuation(scene, kind="orbit", parameter="Delta", min=0.3, max=0.4, segments=4, relax_T=100.0,
                             allow_unstable_start=True, max_points=4, label_every=2, direction="forward")
    expected = cli("continue", "--kind", "orbit", "--lambda", 5, "--Delta", 0.3, "--Delta0", 0.01, "--B", 2,
                   "--C", 0.04, "--L", 2, "--parameter", "Delta", "--min", 0.3, "--max", 0.4, "--segments", 4,
                   "--relax-T", 100, "--allow-unstable-start", "--max-points", 4, "--label-every", 2,
                   "--direction", "forward")
    assert without_timing(b.to_dict()) == without_timing(expected)
    assert b.to_dict()["segments"] == 4 and len(b) == 4
    for name in ("r_min", "r_max", "winding", "kind", "max_abs_multiplier", "multipliers"):
        assert name in b.columns, name
    assert b["kind"].dtype.kind == "U" and b["winding"].dtype.kind == "i"


def test_tunables_and_monitors_equal_the_cli_and_a_callable_monitor_finds_the_same_point(cli):
    scene = rbcstab.Scene(lambda_=2.0, B=1.5, C=0.05)
    b = rbcstab.continuation(scene, parameter="lambda", min=0.5, max=4, direction="forward", newton_tol=1e-11,
                             max_newton=10, min_step=1e-9, location_tol=1e-10, monitor={"lambda": [2.5, 3.2]},
                             stop_at={"lambda": 3.5})
    expected = cli("continue", "--lambda", 2, "--B", 1.5, "--C", 0.05, "--parameter", "lambda", "--min", 0.5,
                   "--max", 4, "--direction", "forward", "--newton-tol", 1e-11, "--max-newton", 10, "--min-step",
                   1e-9, "--location-tol", 1e-10, "--monitor", "lambda=2.5,3.2", "--stop-at", "lambda=3.5")
    assert without_timing(b.to_dict()) == without_timing(expected)
    uz = {p["name"]: p["lambda"] for p in b.special_points if p["type"] == "UZ"}
    assert set(uz) == {"lambda=2.5", "lambda=3.2", "lambda=3.5"}
    assert b.to_dict()["message"] == "stopped at lambda=3.5" and b.to_dict()["status"] == "completed"
    assert abs(b["lambda"][-1] - 3.5) <= 1e-9  # located to location_tol = 1e-10 in (x, p)
    # A callable of the point's parameters and measures: its zero is the same point as the value monitor's.
    c = rbcstab.continuation(scene, parameter="lambda", min=0.5, max=4, direction="forward",
                             monitor={"g": lambda point: point["lambda"] - 3.2})
    g = [p for p in c.special_points if p["type"] == "UZ" and p["name"] == "g"]
    assert len(g) == 1 and abs(g[0]["lambda"] - uz["lambda=3.2"]) <= 1e-9
    names = {k for k, *_ in rbcstab.TUNABLE_OPTIONS}
    assert {"step", "min_step", "max_step", "newton_tol", "max_newton", "location_tol", "segments", "orbit_rtol",
            "orbit_atol", "orbit_samples"} == names
    with pytest.raises(ValueError, match=r"newton_tol = 0.5 is out of range: must be in \(0, 0.01\)"):
        rbcstab.continuation(scene, newton_tol=0.5)
    with pytest.raises(ValueError, match=r"orbit_samples = 2 is out of range"):
        rbcstab.continuation(scene, kind="orbit", orbit_samples=2)
    with pytest.raises(TypeError, match="max_newton"):
        rbcstab.continuation(scene, max_newton=2.5)
    with pytest.raises(TypeError, match="monitor"):
        rbcstab.continuation(scene, monitor="lambda=1")
    with pytest.raises(ValueError, match="unknown monitor 'sigma'"):
        rbcstab.continuation(scene, monitor={"sigma": 1.0})


def test_restart_switch_and_curve_take_the_tunables_and_monitors(cli, tmp_path):
    # The branch file keeps the run's monitors; a restart's monitor/stop_at replace them ({} drops them), as
    # --restart's --monitor (the CLI's JSON on the same flags); a callable's zero is the value monitor's point
    # (located to location_tol = 1e-10 in (x, p): 1e-9).
    scene = rbcstab.Scene(lambda_=2.0, B=1.5, C=0.05)
    b = rbcstab.continuation(scene, parameter="lambda", min=0.5, max=4, direction="forward", monitor={"lambda": 2.5})
    path = tmp_path / "b.json"
    b.save(path)

    def uz(run):
        return {p["name"]: p["lambda"] for p in run.special_points if p["type"] == "UZ"}

    assert set(uz(b.restart(1))) == {"lambda=2.5"}
    assert set(uz(rbcstab.load_branch(path).restart(1))) == {"lambda=2.5"}
    r = b.restart(1, newton_tol=1e-11, max_newton=10, location_tol=1e-10, max_step=0.2, monitor={"lambda": 3.2})
    expected = cli("continue", "--restart", path, "--label", 1, "--newton-tol", 1e-11, "--max-newton", 10,
                   "--location-tol", 1e-10, "--max-step", 0.2, "--monitor", "lambda=3.2")
    assert without_timing(r.to_dict()) == without_timing(expected)
    assert set(uz(r)) == {"lambda=3.2"}
    assert uz(b.restart(1, monitor={})) == {}
    g = b.restart(1, location_tol=1e-10, monitor={"g": lambda point: point["lambda"] - 3.2})
    assert set(uz(g)) == {"g"} and abs(uz(g)["g"] - uz(r)["lambda=3.2"]) <= 1e-9
    assert uz(g.restart(1)) == {}  # a callable is not kept with the run
    s = b.restart(1, stop_at={"lambda": 3.0})
    assert s.to_dict()["message"] == "stopped at lambda=3" and abs(s["lambda"][-1] - 3.0) <= 1e-9
    with pytest.raises(ValueError, match=r"newton_tol = 0.5 is out of range: must be in \(0, 0.01\)"):
        b.restart(1, newton_tol=0.5)
    with pytest.raises(ValueError, match=r"segments = 4 cannot change on a restart \(the run's: 8\)"):
        b.restart(1, segments=4)
    with pytest.raises(TypeError, match="max_newton"):
        b.restart(1, max_newton=2.5)
    # A curve from a labelled BP with a callable monitor of its second parameter: B = 1.1 where it is zero.
    m = rbcstab.continuation(rbcstab.Scene(lambda_=1.0, B=1.0, C=0.08, Delta=1.0, Delta0=0.01, L=4), kind="modal",
                             parameter="C", min=0.015, max=0.08, direction="backward")
    c = m.curve(m.labels("BP")[0], "B", 0.8, 1.2, location_tol=1e-10, monitor={"f": lambda point: point["B"] - 1.1})
    f = [p for p in c.special_points if p["type"] == "UZ" and p["name"] == "f"]
    assert len(f) >= 1 and all(abs(p["B"] - 1.1) <= 1e-9 for p in f), f
    sw = m.switch(m.labels("BP")[0], newton_tol=1e-11, monitor={"C": 0.03})
    assert sw.switched is not None


# ------------------------------------------------------------------------------------- closed forms
def test_modal_branch_in_lambda_equals_the_closed_form(cli):
    scene = rbcstab.Scene(lambda_=1.0, B=1.0, Delta=1.0, Delta0=0.01, C=0.08, beta=0.0, L=4)
    b = rbcstab.continuation(scene, kind="modal", parameter="lambda", min=0.2, max=8)
    assert b["lambda"][0] == 0.2 and b["lambda"][-1] == 8 and len(b) >= 10
    assert np.all(np.diff(b["lambda"]) > 0)
    for k, lam in enumerate(b["lambda"]):
        sigma, Delta_l = closed_form(lam=lam, C=0.08, L=2)
        # Newton stops at 1e-12 on the state; sigma ~ 60 is an O(|J|) function of it: 1e-10 relative.
        assert b["sigma"][k] == pytest.approx(sigma, rel=1e-10, abs=0)
        assert b["Delta_2"][k] == pytest.approx(Delta_l[0], abs=1e-10)
        assert b["Delta_3"][k] == 0 and b["Delta_4"][k] == 0  # the ellipsoidal branch: an invariant subspace
    assert b.stable.dtype == bool and b.stable.all()


def test_full_branch_in_lambda_equals_the_closed_form(rest_scene):
    b = rbcstab.continuation(rest_scene, kind="full", parameter="lambda", min=0.5, max=3)
    assert b["lambda"][0] == 0.5 and b["lambda"][-1] == 3 and len(b) >= 5
    for k, lam in enumerate(b["lambda"]):
        sigma, Delta_l = closed_form(lam=lam, C=0.08, L=5, rest={3: 1e-3})
        assert b["sigma"][k] == pytest.approx(sigma, rel=1e-10, abs=0)
        for l in range(2, 6):
            assert b[f"Delta_{l}"][k] == pytest.approx(Delta_l[l - 2], abs=1e-10)
    assert b["Delta_3"].max() > 1e-3  # the rest content is forced: not vacuous


def test_the_l4_branch_point_lies_at_the_closed_form_threshold(full_branch):
    C4 = l4_threshold()
    assert C4 == pytest.approx(0.015272344752, abs=1e-12)
    bps = [sp for sp in full_branch.special_points if sp["type"] == "BP"]
    assert len(bps) == 1
    bp = bps[0]
    # located to a bracket < 1e-11; 1e-8 as the C++ test (the closed form's root is exact to the last bit)
    assert bp["status"] == "located" and bp["C"] == pytest.approx(C4, abs=1e-8)
    assert bp["label"] in full_branch.labels("BP")
    # its mode: l = 4, m = 0 (the full model's real mode crossing 0), carrying that one mode. The m != 0 modes
    # cross at the same C as pairs +- i m / 2: one HB each, at the BP's C, with its mode l = 4 and m, carrying
    # two; the count chained through the five points (before: the BP carried no change, one HB all nine).
    assert (bp["mode_l"], bp["mode_m"]) == (4, 0) and bp["mode_direction"] in ("stable", "unstable")
    assert abs(bp["unstable_after"] - bp["unstable_before"]) == 1
    hb = [sp for sp in full_branch.special_points if sp["type"] == "HB"]
    assert sorted(h["mode_m"] for h in hb) == [1, 2, 3, 4] and all(h["mode_l"] == 4 for h in hb)
    assert all(h["C"] == bp["C"] and abs(h["unstable_after"] - h["unstable_before"]) == 2 for h in hb)
    crossing = [sp for sp in full_branch.special_points if sp["C"] == bp["C"]]
    assert len(crossing) == 5
    assert all(a["unstable_after"] == b["unstable_before"] for a, b in zip(crossing, crossing[1:]))
    assert {crossing[0]["unstable_before"], crossing[-1]["unstable_after"]} == {0, 9}
    assert full_branch.labels("BP", l=4) == [bp["label"]] == full_branch.labels("BP", l=4, m=0)
    assert full_branch.labels("BP", l=3) == [] and full_branch.labels("BP", l=4, m=1) == []
    assert set(bp) >= {"type", "label", "C", "precision", "stability", "margin", "margin_error"}
    # the branch itself against the closed form: sigma and Delta_l at every point, 1e-10
    for k, C in enumerate(full_branch["C"]):
        sigma, Delta_l = closed_form(C=C, rest={3: 1e-3})
        assert full_branch["sigma"][k] == pytest.approx(sigma, rel=1e-10, abs=0)
        assert full_branch["Delta_3"][k] == pytest.approx(Delta_l[1], abs=1e-10)
    # stable above the crossing, unstable below it
    assert full_branch.stable[full_branch["C"] > C4 + 1e-6].all()
    assert not full_branch.stable[full_branch["C"] < C4 - 1e-6].any()


def test_the_bp_curve_in_C_B_pins_sigma_at_sigma4c(full_branch):
    label = full_branch.labels("BP")[0]
    c = full_branch.curve(label, parameter2="B", min2=0.8, max2=1.25, max_step=0.05)
    assert isinstance(c, rbcstab.Curve) and c.parameters == ["C", "B"]
    assert c.status == "completed" and len(c) >= 5
    B, C = c["B"], c["C"]
    assert B.min() == 0.8 and B.max() == 1.25
    for k in range(len(c)):
        s4 = sigma_c(4, B[k] / C[k])
        # every curve point has the closed form's sigma(C, B) = sigma_4^c(B/C): 1e-9 relative (Newton's 1e-12 on
        # C times d(sigma - sigma_4^c)/dC ~ 1e3), and the state's sigma is that value
        assert closed_form(B=B[k], C=C[k], rest={3: 1e-3})[0] == pytest.approx(s4, rel=1e-9)
        assert c["sigma"][k] == pytest.approx(s4, rel=1e-9)
    ends = dict(zip(B, C))
    assert ends[0.8] == pytest.approx(0.0122260, abs=1e-7) and ends[1.25] == pytest.approx(0.0190704, abs=1e-7)
    assert c.one_parameter_branch.free_parameter == "C"


def test_the_switched_branch_has_sigma_pinned_at_sigma4c(full_branch, tmp_path, cli):
    label = full_branch.labels("BP")[0]
    s = full_branch.switch(label)
    sw = s.switched
    assert sw is not None and sw.status == "completed" and len(sw) >= 5
    for k, C in enumerate(sw["C"]):
        assert sw["sigma"][k] == pytest.approx(sigma_c(4, 1.0 / C), rel=1e-10)
    assert sw["Delta_4"].max() > 0.05  # the l = 4 mode takes area on the new branch
    # the run keeps the branch it switched from, its labels kept
    assert np.array_equal(s["C"], full_branch["C"]) and s.labels("BP") == full_branch.labels("BP")
    # the CLI does the same from the branch file
    full_branch.save(tmp_path / "b.json")
    expected = cli("continue", "--restart", tmp_path / "b.json", "--switch-at", label)
    assert without_timing(s.to_dict()) == without_timing(expected)


def test_switch_at_an_hb_of_the_onset_names_its_rotating_waves_and_the_bp(full_branch):
    # The l = 4 onset: a BP and four Hopf pairs at once. The orbits born at each pair are the BP branch's states with
    # the l = 4 block turned into mode m, rotating at m/2: no branch of their own (ValueError), the BP's label named.
    hb = full_branch.labels("HB")
    assert len(hb) == 4
    bp = full_branch.labels("BP", l=4, m=0)
    assert len(bp) == 1
    for label, m in zip(full_branch.labels("HB", l=4, m=1) + full_branch.labels("HB", l=4, m=3), (1, 3)):
        with pytest.raises(ValueError, match="exact rotating waves") as e:
            full_branch.switch(label)
        assert f"turned into mode m = {m}" in str(e.value)
        assert f"switch at label {bp[0]} (the BP)" in str(e.value)


def test_switch_at_bp_continues_the_switched_branch_in_the_same_run(rest_scene):
    b = rbcstab.continuation(rest_scene, **dict(FULL_C, min=0.014), switch_at_bp=True)
    assert b.switched is not None and len(b.switched) > 2
    assert b.to_dict()["switched_branch"]["switched"] is True


# ------------------------------------------------------------------------------------- branch files
def test_python_save_restarts_from_the_cli_and_cli_save_loads_in_python(full_branch, tmp_path, cli):
    py_file, cli_file = tmp_path / "py.json", tmp_path / "cli.json"
    full_branch.save(py_file)
    label = full_branch["label"][len(full_branch) // 2]
    assert label > 0
    # Python's file restarts from the CLI, as the same restart from Python
    expected = cli("continue", "--restart", py_file, "--label", label, "--max-points", 5)
    again = full_branch.restart(label, max_points=5)
    assert without_timing(again.to_dict()) == without_timing(expected)
    assert without_timing(rbcstab.load_branch(py_file).restart(label, max_points=5).to_dict()) == \
        without_timing(expected)
    # the CLI's file loads in Python: the same run
    cli_run("continue", *FULL_C_FLAGS, "--save", cli_file, "--csv", tmp_path / "cli.csv")
    full_branch.to_csv(tmp_path / "py.csv")
    assert (tmp_path / "py.csv").read_bytes() == (tmp_path / "cli.csv").read_bytes()
    with pytest.raises(OSError):
        full_branch.save(tmp_path / "no_such_folder" / "b.json")
    with pytest.raises(OSError):
        full_branch.to_csv(tmp_path / "no_such_folder" / "b.csv")
    loaded = rbcstab.load_branch(cli_file)
    mine = without_timing(full_branch.to_dict())
    theirs = without_timing(loaded.to_dict())
    assert theirs.pop("L_reason").endswith("the branch file's scene (--restart)")
    mine.pop("L_reason")
    assert theirs == mine
    for name in full_branch.columns:
        assert np.array_equal(loaded[name], full_branch[name], equal_nan=name not in ("stability", "type")), name
    # the files themselves hold the same run
    import json
    assert without_timing(json.loads(py_file.read_text())) == without_timing(json.loads(cli_file.read_text()))
    # and a pickle is a branch file
    assert without_timing(pickle.loads(pickle.dumps(full_branch)).to_dict()) == without_timing(full_branch.to_dict())


def test_restart_in_another_parameter(full_branch):
    start = int(full_branch["label"][0])  # the end point at C = 0.08
    r = full_branch.restart(start, parameter="B", min=0.9, max=1.1, direction="both")
    assert r.free_parameter == "B" and r["B"].min() == 0.9 and r["B"].max() == 1.1
    assert r.to_dict()["start"]["method"] == "restart"


# ------------------------------------------------------------------------------------- columns and display
def test_columns_text_csv_and_repr(full_branch):
    b = full_branch
    n = len(b)
    for name in ("C", "r", "Psi", "sigma", "Delta_2", "Delta_5", "stable", "n_unstable", "stability", "margin",
                 "margin_error", "label", "type", "arclength", "max_Re_eig"):
        assert name in b.columns and b[name].shape == (n,), name
    assert b["eigenvalues"].shape[0] == n and b["eigenvalues"].dtype == complex
    assert np.array_equal(b["max_Re_eig"], b["eigenvalues"].real.max(axis=1))
    assert b["type"][0] == "EP" and b["type"][-1] == "EP"
    assert np.array_equal(b["n_unstable"] == 0, b.stable)
    with pytest.raises(KeyError, match="sigma"):
        b["no_such_measure"]
    # the CSV's header is the CLI's
    assert b.to_csv().splitlines()[0] == \
        "C,branch,r,Psi,sigma,Delta_2,Delta_3,Delta_4,Delta_5,stable,n_unstable,max_Re_eig,label,type"
    assert "BP" in b.text() and "LAB" in b.text(measures="r,sigma")
    assert "\n" not in repr(b) and "BP" in repr(b) and repr(b).startswith("<rbcstab.Branch")
    assert "<table>" in b._repr_html_()


def test_progress_runs_with_the_bar():
    b = rbcstab.continuation(rbcstab.Scene(), parameter="lambda", min=4, max=6, progress=True)
    assert len(b) > 2


def test_progress_callable_and_tqdm_bar_count_every_point():
    # The library reports at most every 0.1 s; the final count is reported at the end whatever the throttle held
    # back: one per point computed (the branch's points but its start, which is solved, not stepped to).
    calls = []
    b = rbcstab.continuation(rbcstab.Scene(), parameter="lambda", min=4, max=6,
                             progress=lambda done, total, eta: calls.append((done, total, eta)))
    assert calls and all(total == 0 for _, total, _ in calls)
    counts = [done for done, _, _ in calls]
    assert counts == sorted(counts) and counts[-1] == len(b) - 1, (counts, len(b))
    tqdm = pytest.importorskip("tqdm")
    with tqdm.tqdm(file=io.StringIO()) as bar:
        end = int(b["label"][b["label"] != 0][-1])  # the EP at lambda = 6
        b2 = b.restart(end, max=7, progress=bar)
        assert bar.n == len(b2) - 1
    with pytest.raises(TypeError, match="a tqdm bar"):
        rbcstab.continuation(rbcstab.Scene(), progress=object())


# ------------------------------------------------------------------------------------- bad input
def test_bad_input_raises(full_branch):
    scene = rbcstab.Scene()
    with pytest.raises(ValueError, match="kind"):
        rbcstab.continuation(scene, kind="spiral")
    with pytest.raises(ValueError, match="parameter"):
        rbcstab.continuation(scene, parameter="viscosity")
    with pytest.raises(ValueError, match="direction"):
        rbcstab.continuation(scene, direction="sideways")
    with pytest.raises(ValueError, match="p_min|min"):
        rbcstab.continuation(scene, min=6.0, max=4.0)
    with pytest.raises(ValueError, match="min"):
        rbcstab.continuation(scene, min=float("nan"))
    with pytest.raises(ValueError, match="max"):
        rbcstab.continuation(scene, parameter="C", max=float("nan"))
    with pytest.raises(ValueError, match="min"):
        rbcstab.continuation(scene, min=-1.0)  # below lambda's closed domain edge 0
    with pytest.raises(ValueError, match="max_points"):
        rbcstab.continuation(scene, max_points=1)
    with pytest.raises(ValueError, match="curve"):
        rbcstab.continuation(scene, curve="XX", parameter2="B")
    with pytest.raises(ValueError, match="parameter2"):
        rbcstab.continuation(scene, curve="LP", parameter2="nope")
    with pytest.raises(ValueError, match="parameter2"):
        rbcstab.continuation(scene, parameter2="B")
    with pytest.raises(TypeError, match="scene"):
        rbcstab.continuation({"lambda": 5})
    with pytest.raises(TypeError, match="kind"):
        rbcstab.continuation(scene, kind=3)
    with pytest.raises(TypeError, match="min"):
        rbcstab.continuation(scene, min="0")
    with pytest.raises(TypeError, match="max_points"):
        rbcstab.continuation(scene, max_points=10.5)
    with pytest.raises(TypeError, match="switch_at_bp"):
        rbcstab.continuation(scene, switch_at_bp=1)
    with pytest.raises(TypeError, match="progress"):
        rbcstab.continuation(scene, progress="yes")
    with pytest.raises(TypeError):
        rbcstab.continuation(scene, no_such_option=1)
    with pytest.raises(ValueError, match="label"):
        full_branch.restart(99999)
    with pytest.raises(TypeError, match="label"):
        full_branch.restart("3")
    with pytest.raises(ValueError, match="label"):
        full_branch.curve(int(full_branch["label"][0]), parameter2="B")  # an end point: not a special point
    with pytest.raises(ValueError, match="switch_at|BP"):
        full_branch.switch(int(full_branch["label"][0]))
    with pytest.raises(ValueError, match="min2"):
        full_branch.curve(full_branch.labels("BP")[0], parameter2="B", min2=2.0, max2=1.0)
    with pytest.raises(ValueError, match="path"):
        rbcstab.load_branch("/nonexistent/branch.json")
    with pytest.raises(ValueError):
        rbcstab.load_branch(REST_L3)  # not a branch file
    with pytest.raises(ValueError, match="'y'|y ="):
        full_branch.plot_spec(y="no_such_measure")


def test_a_run_without_output_raises_and_an_early_end_warns():
    # No NS point on the in-plane orbit branch (its multipliers stay inside the unit circle): the CLI's exit 1
    # without output (cli.continue's curve_ns_none)
    scene = rbcstab.Scene(lambda_=5.0, Delta=0.3, Delta0=0.01, B=2.0, C=0.04, L=2)
    with pytest.raises(rbcstab.ContinuationError, match="no located NS point"):
        rbcstab.continuation(scene, kind="orbit", parameter="Delta", min=0.3, max=0.45, curve="NS", parameter2="C")
    # a branch that stops at max_points ends normally: no warning
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        b = rbcstab.continuation(rbcstab.Scene(), parameter="lambda", min=4, max=6, max_points=3)
    assert len(b) == 5 and b.status == "completed"  # 3 per direction, the start shared
    # a switch that finds no BP: the branch with a ContinuationWarning (the CLI's exit 1 with output)
    with pytest.warns(rbcstab.ContinuationWarning, match="no BP"):
        b = rbcstab.continuation(rbcstab.Scene(), parameter="lambda", min=4, max=6, switch_at_bp=True)
    assert len(b) > 2 and "the switch failed" in repr(b)


# ------------------------------------------------------------------------------------- Ctrl-C, GIL
@pytest.mark.parametrize("options", [
    # shootings: in-plane orbits with a tiny step and no bound, minutes of work unless interrupted
    dict(step=1e-5, max_step=1e-5, max_points=10**7, direction="forward"),
    # the start's relaxation over 1e8 time units (the integrator's poll)
    dict(relax_T=1e8),
], ids=["shootings", "relaxation"])
def test_ctrl_c_stops_a_long_orbit_continuation_within_a_second(options):
    # The timer thread runs only if the GIL is released.
    scene = rbcstab.Scene(lambda_=5.0, beta=math.pi / 2)
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        rbcstab.continuation(scene, kind="orbit", parameter="lambda", **options)
    elapsed = time.monotonic() - start
    timer.join()
    assert elapsed < 1.0 + 1.0, elapsed


# ------------------------------------------------------------------------------------- plots
def test_plot_draws_the_cli_plot_spec_on_agg(full_branch, tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    s = full_branch.switch(full_branch.labels("BP")[0])
    ax = s.plot(y="sigma")
    texts = [t.get_text() for t in ax.texts]
    assert any(t.startswith("BP") for t in texts)
    styles = {line.get_linestyle() for line in ax.lines}
    assert "-" in styles and "--" in styles  # stable solid, unstable dashed
    assert ax.get_xlabel() and ax.get_ylabel()
    plt.close(ax.figure)
    # the spec is the CLI's for the same input (apart from the input's name)
    s.save(tmp_path / "in.json")
    cli_run("plot", tmp_path / "in.json", "--y", "sigma", "-o", tmp_path / "fig.png")
    import json
    theirs = json.loads((tmp_path / "fig.json").read_text())
    mine = s.plot_spec(y="sigma")
    for spec in (mine, theirs):
        for series in spec["series"]:
            series.pop("source")
    assert mine == theirs
    fig, ax2 = plt.subplots()
    c = full_branch.curve(full_branch.labels("BP")[0], parameter2="B", min2=0.9, max2=1.1)
    assert c.plot(ax=ax2) is ax2 and ax2.get_xlabel()
    plt.close(fig)


def test_special_points_carry_their_normal_form_and_the_plot_marks_it():
    """The l = 3 onset of the modal model in C: a supercritical pitchfork whose law |x - x*| ~ A |C - C*|^(1/2) holds
    on the unstable side (C < C*); docs/continuation.md "Normal forms" has the C++ checks (closed forms, the
    post-instability quadratic). Here: the JSON reaches Python and the plot spec, and a subcritical point would not be
    drawn as a supercritical one."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    m = rbcstab.continuation(rbcstab.Scene(lambda_=1.0, B=1.0, C=0.08, Delta=1.0, Delta0=0.01, L=4), kind="modal",
                             parameter="C", min=0.03, max=0.08, direction="backward")
    (bp,) = [sp for sp in m.special_points if sp["type"] == "BP"]
    nf = bp["normal_form"]
    assert nf["kind"] == "pitchfork" and nf["criticality"] == "supercritical" and nf["side"] == -1
    assert nf["exponent"] == 0.5 and nf["amplitude"] == pytest.approx(10.2206, rel=1e-5)
    assert nf["coefficients"]["a"] == 0 and nf["coefficients"]["p2"] < 0
    spec = m.plot_spec(y="Delta_2")
    (point,) = [p for p in spec["points"] if p["type"] == "BP"]
    assert point["criticality"] == "supercritical" and point["text"].endswith(" super")
    ax = m.plot(y="Delta_2")
    assert "supercritical" in [t.get_text() for t in ax.get_legend().get_texts()]
    assert any(t.get_text().endswith(" super") for t in ax.texts)
    plt.close(ax.figure)


# ------------------------------------------------------------------------------------- shear_rate as a parameter
def test_shear_rate_continuation_needs_a_physical_scene_and_matches_the_converted_scene():
    """shear_rate comes from the parameter table: on a physical scene the branch runs in 1/s and each point is
    the closed-form equilibrium at the converted (B, C) (C = eta gamma R/mu); a plain scene is refused naming it."""
    with pytest.raises(ValueError, match="shear_rate.*physical scene"):
        rbcstab.continuation(rbcstab.Scene(beta=0.0), parameter="shear_rate", min=10, max=100)
    cell = dict(shear_rate=100, viscosity=1e-3, radius=3e-6, bending_modulus=2e-19, shear_modulus=2.5e-6)
    scene = rbcstab.Scene(**{"Delta": 1.0, "Delta0": 0.01, "lambda": 5.0, "beta": 0.0, **cell})
    b = rbcstab.continuation(scene, parameter="shear_rate", min=10, max=1000, max_step=20)
    rates = np.asarray(b["shear_rate"])
    assert rates.min() == 10 and rates.max() == 1000
    Lam = math.sqrt(1.0) * (23 * 5 + 32) / (8 * math.sqrt(30 * math.pi))
    for g, r in zip(rates, np.asarray(b["r"])):
        S = (1e-3 * g * 3e-6 / 2.5e-6) * math.sqrt(15 * math.pi / (2 * 0.01))
        bq = 1 + Lam**2 + S**-2
        u = 2 / (bq + math.sqrt(bq * bq - 4 * Lam**2))
        assert r == pytest.approx(math.sqrt(u), abs=1e-10)


def test_the_quickstart_switches_at_the_onset():
    # docs/python.md's quickstart: labels("BP", l=3) is the onset at C = 0.0362, where sigma = sigma_3^c(B / C)
    # (closed form; located to ~1e-11 in C, d sigma / dC ~ 1e3: 1e-8), not the l = 6 BP at C = 0.0137.
    scene = rbcstab.Scene(lambda_=5, B=2, C=0.04, Delta=1, Delta0=0.01)
    branch = rbcstab.continuation(scene.replace(lambda_=1, B=1, L=6), kind="modal", parameter="C", min=0.01, max=0.1)
    assert [sp["mode_l"] for sp in branch.special_points] == [6, 5, 4, 3]
    bp = branch.labels("BP", l=3)[0]
    sp = next(sp for sp in branch.special_points if sp["label"] == bp)
    assert sp["C"] == pytest.approx(0.0361689, abs=1e-6)
    assert sp["sigma"] == pytest.approx(sigma_c(3, 1 / sp["C"]), abs=1e-8)
    post = branch.switch(bp).switched
    for C, sigma in zip(post["C"], post["sigma"]):
        assert sigma == pytest.approx(sigma_c(3, 1 / C), abs=1e-10)


# ------------------------------------------------------------------------------------- the whole diagram
def test_bifurcation_diagram_equals_the_cli_and_pickles(cli, tmp_path):
    # docs/continuation.md's diagram: the walk-through's scene to depth 1 (start branch + both halves at its 4 BPs).
    scene = rbcstab.Scene(lambda_=1, B=1, L=6)
    d = rbcstab.bifurcation_diagram(scene, depth=1, kind="modal", parameter="C", min=0.01, max=0.1)
    expected = cli("continue", "--kind", "modal", "--parameter", "C", "--min", 0.01, "--max", 0.1, "--lambda", 1,
                   "--B", 1, "--L", 6, "--diagram", 1)
    assert without_timing(d.to_dict()) == without_timing(expected)
    assert len(d) == 9 and d.complete
    assert [b["parent"] for b in d.tree] == [None] + [1] * 8
    onset = [b for b, t in zip(d.branches, d.tree) if t["parent_label"] == 6]
    assert len(onset) == 2
    for b in onset:  # the post-instability state: sigma = sigma_3^c = -(12 + 4 alpha / 12), alpha = B / C
        np.testing.assert_allclose(b["sigma"], -(12 + 4 * (1 / b["C"]) / 12), rtol=1e-10)
    copy = pickle.loads(pickle.dumps(d))
    assert copy.to_dict() == d.to_dict() and repr(copy) == repr(d)
    files = d.save(tmp_path / "d.json")
    assert len(files) == 9 and rbcstab.load_diagram(tmp_path / "d.json").to_dict() == d.to_dict()
    # the set bifurcating at the l = 4 BP is vertical (C = 1/60): a few points
    assert rbcstab.load_branch(files[7]).switch(onset[0].labels("BP", l=4)[0], max_points=5).switched is not None
    with pytest.raises(ValueError, match="depth"):
        rbcstab.bifurcation_diagram(scene, depth=21, kind="modal", parameter="C", min=0.01, max=0.1)
    with pytest.raises(TypeError):
        rbcstab.bifurcation_diagram(scene, depth=1.5, kind="modal", parameter="C")


def test_bifurcation_diagram_resumes_from_its_journal(cli, tmp_path):
    # The walk-through's diagram with a journal: a run cut after 4 branches (the journal's header and 4 records,
    # then a torn record) resumes to the uninterrupted diagram; the CLI's journal (--save F: F.journal) of the same
    # options is the same configuration (everything resumed); other options' journal is refused.
    scene = rbcstab.Scene(lambda_=1, B=1, L=6)
    options = dict(depth=1, kind="modal", parameter="C", min=0.01, max=0.1)
    clean = rbcstab.bifurcation_diagram(scene, **options)
    assert clean.resumed == 0 and clean.rejected == []
    journal = tmp_path / "d.journal"
    first = rbcstab.bifurcation_diagram(scene, journal=journal, **options)
    assert first.to_dict() == clean.to_dict() and first.resumed == 0
    lines = journal.read_text().splitlines(keepends=True)
    assert len(lines) == 10
    journal.write_text("".join(lines[:5]) + lines[5][:100])
    d = rbcstab.bifurcation_diagram(scene, journal=str(journal), **options)
    assert d.resumed == 4
    assert len(d.rejected) == 1 and d.rejected[0].startswith(f"{journal}:6: torn last record")
    assert d.to_dict() == clean.to_dict()
    cli("continue", "--kind", "modal", "--parameter", "C", "--min", 0.01, "--max", 0.1, "--lambda", 1, "--B", 1,
        "--L", 6, "--diagram", 1, "--save", tmp_path / "c.json")
    from_cli = rbcstab.bifurcation_diagram(scene, journal=tmp_path / "c.json.journal", **options)
    assert from_cli.resumed == 9 and from_cli.to_dict() == clean.to_dict()
    with pytest.raises(ValueError, match="another configuration"):
        rbcstab.bifurcation_diagram(scene, journal=journal, **dict(options, depth=2))
    with pytest.raises(TypeError, match="journal"):
        rbcstab.bifurcation_diagram(scene, journal=5, **options)


def test_bifurcation_diagram_says_the_onset_hbs_are_rotating_waves_of_the_bp_branch():
    # The full model's l = 3 onset (L = 4): the BP's two halves are followed; its three HBs (m = 1, 2, 3 at the same
    # C) are listed as rotating waves of the BP's branch (branch_to, label_to: that branch and the BP), not failures.
    scene = rbcstab.Scene(lambda_=1, B=1, C=0.08, Delta=1, Delta0=0.01, L=4)
    d = rbcstab.bifurcation_diagram(scene, depth=1, kind="full", parameter="C", min=0.03, max=0.08,
                                    direction="backward")
    assert len(d) == 3 and d.complete
    hbs = [p for p in d.special_points if p["type"] == "HB"]
    assert sorted(p["mode_m"] for p in hbs) == [1, 2, 3]
    bp = [p for p in d.special_points if p["type"] == "BP" and p["outcome"] == "followed"]
    assert len(bp) == 2
    for p in hbs:
        assert p["outcome"] == "rotating_wave" and p["side"] == 0
        assert p["label_to"] == bp[0]["label"] and p["branch_to"] in (bp[0]["branch_to"], bp[1]["branch_to"])
        assert f"turned into mode m = {p['mode_m']}" in p["detail"] and "0.5i" in p["detail"]


def test_bifurcation_diagram_plot_labels_every_branch(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    scene = rbcstab.Scene(lambda_=1, B=1, L=6)
    with pytest.warns(rbcstab.ContinuationWarning, match="max_branches reached"):
        d = rbcstab.bifurcation_diagram(scene, depth=1, kind="modal", parameter="C", min=0.01, max=0.1,
                                        max_branches=3)
    assert len(d) == 3 and not d.complete  # max_branches reached: said so
    ax = d.plot(y="sigma")
    assert len(ax.get_lines()) >= 3  # a series per branch (more where the stability changes along one)

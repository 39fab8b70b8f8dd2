"""rbcstab.fit against `rbcstab fit --json` on the same data, and bad data refused by both with the file line
and column named."""
import os
import signal
import subprocess
import threading
import time

import pytest

import rbcstab
from conftest import _cli_path

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EXAMPLE = os.path.join(ROOT, "data", "fit_synthetic.csv")


@pytest.fixture
def small(tmp_path):
    """The example's 1 mPa s angles at 150 and 600 1/s: four rows, a fit of a fraction of a second."""
    rows = [line for line in open(EXAMPLE) if line.startswith(("observable", "inclination_angle,150,1,",
                                                                "swinging_amplitude,150,1,", "inclination_angle,600,1,",
                                                                "swinging_amplitude,600,1,"))]
    path = tmp_path / "obs.csv"
    path.write_text("# four rows of data/fit_synthetic.csv\n" + "".join(rows))
    return str(path)


def test_fit_equals_the_cli(small, cli):
    fixed = {"Delta": 0.1, "Delta0": 0.05}
    r = rbcstab.fit(small, ["mu", "lambda"], fixed=fixed, starts=1)
    assert isinstance(r, rbcstab.FitResult)
    assert r["status"] == "converged"
    assert r.to_dict() == cli("fit", "--data", small, "--free", "mu,lambda", "--fixed", "Delta=0.1,Delta0=0.05",
                              "--starts", "1")
    mu = r.estimate("shear_modulus")
    assert mu["identifiable"] and mu["lo95"] < mu["value"] < mu["hi95"]
    # The example was made at mu = 6 uN/m, lambda = 5 with 0.5 deg noise.
    assert mu["lo95"] < 6e-6 < mu["hi95"]
    assert "shear_modulus" in r.text and "95 % interval" in r.text


def test_jacobian_methods_agree_and_a_bad_name_is_refused(small):
    """The variational and the finite-difference Jacobian lead Ipopt to the same estimate (docs/inverse.md
    "Sensitivities": the two Jacobians agree to ~1e-8 of their largest entry; the estimates to 1e-10 on the
    synthetic file), so 1e-7 relative is far from either's noise yet would catch a wrong derivative."""
    fixed = {"Delta": 0.1, "Delta0": 0.05}
    v = rbcstab.fit(small, ["mu", "lambda"], fixed=fixed, starts=1)
    d = rbcstab.fit(small, ["mu", "lambda"], fixed=fixed, starts=1, jacobian="finite_difference")
    for name in ("shear_modulus", "lambda"):
        assert v.estimate(name)["value"] == pytest.approx(d.estimate(name)["value"], rel=1e-7)
    with pytest.raises(ValueError, match="jacobian"):
        rbcstab.fit(small, ["mu"], jacobian="analytic")
    with pytest.raises(ValueError, match="profile_method"):
        rbcstab.fit(small, ["mu"], profile_method="newton")
    with pytest.raises(TypeError):
        rbcstab.fit(small, ["mu"], regime_constraints="yes")


def test_bad_data_names_line_and_column(tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("observable,shear_rate,viscosity,value,uncertainty,unit\ninclination_angle,100,1,10,-1,deg\n")
    with pytest.raises(ValueError, match=r"bad.csv:2: column 'uncertainty'"):
        rbcstab.fit(str(bad), ["mu"])
    out = subprocess.run([_cli_path(), "fit", "--data", str(bad), "--free", "mu"], capture_output=True, text=True)
    assert out.returncode == 2
    assert "bad.csv:2: column 'uncertainty'" in out.stderr


def test_wrong_types_are_type_errors(small):
    with pytest.raises(TypeError):
        rbcstab.fit(small, "mu")  # a string, not a list of names
    with pytest.raises(TypeError):
        rbcstab.fit(small, ["mu"], fixed={"Delta": [0.1]})
    with pytest.raises(ValueError, match="starts"):
        rbcstab.fit(small, ["mu"], starts=0)
    with pytest.raises(ValueError, match="not a fit parameter"):
        rbcstab.fit(small, ["stiffness"])


def test_report_folder_progress_and_refusal(small, tmp_path):
    """fit(report=DIR) writes the page (its parameters.csv holds the result's numbers), progress counts the starts,
    and an existing folder is refused before the fit runs. (The profile figures: report_tests and cli.fit.report.)"""
    calls = []
    page = tmp_path / "page"
    r = rbcstab.fit(small, ["lambda"], fixed={"Delta": 0.1, "Delta0": 0.05}, starts=1, report=str(page),
                    progress=lambda done, total, eta: calls.append((done, total)))
    assert r["status"] == "converged"
    assert r["report"] == str(page)
    for name in ("index.html", "README.md", "fit.json", "parameters.csv", "fig_fit.png", "observations.csv"):
        assert (page / name).exists(), name
    header, row = (page / "parameters.csv").read_text().splitlines()
    table = dict(zip(header.split(","), row.split(",")))
    e = r.estimate("lambda")
    assert float(table["value"]) == e["value"] and float(table["lo95"]) == e["lo95"]
    assert float(table["hi95"]) == e["hi95"] and table["identifiable"] == "true"
    assert calls[-1] == (1, 1) and all(total == 1 for _, total in calls)
    with pytest.raises(ValueError, match="exists; pass overwrite"):
        rbcstab.fit(small, ["lambda"], fixed={"Delta": 0.1, "Delta0": 0.05}, starts=1, report=str(page))
    with pytest.raises(TypeError):
        rbcstab.fit(small, ["lambda"], report=3)


def test_progress_that_raises_stops_the_fit(small):
    """What the progress callable raises (Ctrl-C's KeyboardInterrupt included) stops the fit and is raised."""
    def interrupt(done, total, eta):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        rbcstab.fit(small, ["lambda"], fixed={"Delta": 0.1, "Delta0": 0.05}, starts=4, progress=interrupt)


def test_ctrl_c_stops_a_fit_within_a_second(small):
    """64 starts: many seconds of work unless interrupted; SIGINT after 0.5 s raises KeyboardInterrupt promptly."""
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        rbcstab.fit(small, ["mu", "lambda"], fixed={"Delta": 0.1, "Delta0": 0.05}, starts=64)
    elapsed = time.monotonic() - start
    timer.join()
    assert elapsed < 0.5 + 1.0, elapsed

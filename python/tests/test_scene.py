"""rbcstab.Scene: keywords from the scene keys, validation as the CLI's, immutability, round trips."""
import math
import pickle

import pytest

import rbcstab


def test_version_is_the_cli_version(cli):
    import subprocess, os
    out = subprocess.run([os.environ["RBCSTAB_CLI"], "--version"], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["rbcstab", rbcstab.__version__]


def test_defaults_are_the_paper_fig3_case():
    s = rbcstab.Scene()
    assert (s.lambda_, s.Delta, s.Delta0, s.B, s.C, s.beta, s.delta) == (5.0, 1.0, 0.01, 2.0, 0.04, 0.001, 1e-3)
    assert s.L is None and s.T == 500.0 and s.dt == 1.0
    assert s.model == "automatic" or s.model == "auto"


def test_every_scene_key_is_a_keyword_and_an_attribute():
    keys = rbcstab.scene_keys()
    assert {k["path"] for k in keys} >= {"parameters.lambda", "parameters.B", "run.L", "integrator.rtol"}
    s = rbcstab.Scene()
    for k in keys:
        assert hasattr(s, k["keyword"]), k


def test_parameter_table_drives_every_python_interface():
    # The library's table is the one list: Scene keywords and properties, continuation parameters, diagram axes
    # and figure labels all follow it; the drawing code keeps no symbol table of its own.
    rows = rbcstab.parameter_table()
    keywords = {k["keyword"] for k in rbcstab.scene_keys() if k["table"] in ("parameters", "initial")}
    s = rbcstab.Scene()
    stored = [r for r in rows if r["table"] in ("parameters", "initial")]
    assert {r["keyword"] for r in stored} == {k for k in keywords if k not in ("delta_l", "rest_delta_l")}
    for r in rows:
        if r["table"] or r["definition"]:
            assert isinstance(getattr(s, r["keyword"]), float), r
        unit = f" [{r['unit']}]" if r["unit"] else ""
        assert r["label"] == f"${r['symbol']}${unit}", r
        assert set(r["levels"]) <= {"reduced", "modal", "full"} and r["levels"], r
    with pytest.raises(ValueError) as e:
        rbcstab.continuation(s, parameter="kappa")
    assert str(e.value).endswith("must be one of " + ", ".join(r["name"] for r in rows if r["continuation"]))
    with pytest.raises(ValueError) as e:
        rbcstab.diagram(s, axes=("kappa", "lambda"), counts=(2, 2), progress=False)
    assert "must be one of " + ", ".join(r["name"] for r in rows if r["axis"]) in str(e.value)
    from rbcstab.sweep import phase_draw
    assert not hasattr(phase_draw(), "SYMBOLS")
    # B never reaches the reduced (l = 2) system, whose multiplier is Upsilon_2 itself (the levels' own test).
    assert {r["name"]: r["levels"] for r in rows}["B"] == ["modal", "full"]


def test_derived_numbers_follow_their_definitions():
    s = rbcstab.Scene(lambda_=5.0, Delta=1.0, Delta0=0.01, B=2.0, C=0.04)
    # Eq. Lambda_S: Lambda = sqrt(Delta)(23 lambda + 32)/(8 sqrt(30 pi)), S = C sqrt(15 pi/(2 Delta0)), alpha = B/C
    assert s.Lambda == pytest.approx(math.sqrt(1.0) * (23 * 5 + 32) / (8 * math.sqrt(30 * math.pi)), rel=1e-14)
    assert s.S == pytest.approx(0.04 * math.sqrt(15 * math.pi / (2 * 0.01)), rel=1e-14)
    assert s.alpha == pytest.approx(50.0, rel=1e-15)
    with pytest.raises(AttributeError):
        s.alpha = 3


def test_replace_returns_a_new_scene_and_keeps_the_old():
    a = rbcstab.Scene()
    b = a.replace(lambda_=1.0, L=6)
    assert a.lambda_ == 5.0 and a.L is None
    assert b.lambda_ == 1.0 and b.L == 6
    assert b.replace(L=None).L is None
    assert b != a and b == rbcstab.Scene(lambda_=1.0, L=6)


def test_to_dict_round_trips_and_pickles():
    s = rbcstab.Scene(B=3.5, delta_l={3: 2e-3}, name="mine")
    d = s.to_dict()
    assert d["lambda"] == 5.0 and d["B"] == 3.5 and d["L"] is None and d["delta_l"] == {3: 2e-3}
    assert rbcstab.Scene(**d) == s
    assert pickle.loads(pickle.dumps(s)) == s


def test_from_toml_reads_the_scene_files(tmp_path):
    p = tmp_path / "s.toml"
    p.write_text(rbcstab.Scene(C=0.08, L=5, name="x").to_toml())
    s = rbcstab.Scene.from_toml(str(p))
    assert s.C == 0.08 and s.L == 5 and s.name == "x"


@pytest.mark.parametrize("kwargs, words", [
    ({"lambda_": -1.0}, ["lambda", "-1", ">= 0"]),
    ({"Delta": float("nan")}, ["Delta", "nan"]),
    ({"L": -3}, ["L", "-3"]),
    ({"L": 1000}, ["L", "1000"]),
    ({"rtol": 2.0}, ["rtol", "2"]),
    ({"model": "bogus"}, ["model", "bogus"]),
    ({"dt": 600.0}, ["dt", "600"]),
])
def test_bad_values_raise_value_error_naming_parameter_value_and_range(kwargs, words):
    with pytest.raises(ValueError) as e:
        rbcstab.Scene(**kwargs)
    for w in words:
        assert w in str(e.value), (w, str(e.value))


@pytest.mark.parametrize("kwargs", [
    {"lambda_": "5"}, {"B": None}, {"L": 4.0}, {"L": True}, {"delta_l": [3, 1e-3]}, {"delta_l": {"3": 1e-3}},
    {"model": 3}, {"nonsense": 1},
])
def test_wrong_types_raise_type_error(kwargs):
    with pytest.raises(TypeError):
        rbcstab.Scene(**kwargs)


def test_from_toml_errors_name_the_key(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text("[parameters]\nlambda = -2\n")
    with pytest.raises(ValueError, match="parameters.lambda"):
        rbcstab.Scene.from_toml(str(p))
    with pytest.raises(ValueError):
        rbcstab.Scene.from_toml(str(tmp_path / "missing.toml"))


def test_repr_is_one_line():
    r = repr(rbcstab.Scene())
    assert "\n" not in r and "lambda=5" in r and "L=auto" in r

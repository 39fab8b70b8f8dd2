"""rbcstab.Scene: keywords from the scene keys, validation as the CLI's, immutability, round trips."""
import copy
import inspect
import math
import os
import pickle
import warnings

import numpy as np

import pytest

import rbcstab


def test_version_is_the_cli_version(cli):
    import subprocess, os
    out = subprocess.run([os.environ["RBCSTAB_CLI"], "--version"], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["rbcstab", rbcstab.__version__]


def test_defaults_are_the_paper_fig3_case():
    s = rbcstab.Scene()
    # beta not given: runs use 0.001, a continuation its kind's own (None shows that it was not given)
    assert (s.lambda_, s.Delta, s.Delta0, s.B, s.C, s.beta, s.delta) == (5.0, 1.0, 0.01, 2.0, 0.04, None, 1e-3)
    assert s.replace(beta=0.001).beta == 0.001
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
        if r["table"] or r["definition"]:  # beta: None until given (each computation chooses)
            assert isinstance(getattr(s.replace(beta=0.001), r["keyword"]), float), r
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
    with pytest.raises(FileNotFoundError):
        rbcstab.Scene.from_toml(str(tmp_path / "missing.toml"))


def test_repr_is_one_line():
    r = repr(rbcstab.Scene())
    assert "\n" not in r and "lambda_=5.0" in r and "L=None" in r and "beta=None" in r


# ---- state you can see (issue 30, point 2) ----

SCENES = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))), "scenes")
SCENE_FILES = sorted(f for f in os.listdir(SCENES) if f.endswith(".toml"))


def _copies(s):
    """The four ways a scene travels: copy, deepcopy, pickle, to_dict/from_dict."""
    return {"copy": copy.copy(s), "deepcopy": copy.deepcopy(s), "pickle": pickle.loads(pickle.dumps(s)),
            "from_dict": rbcstab.Scene.from_dict(s.to_dict())}


@pytest.mark.parametrize("name", SCENE_FILES)
def test_every_scene_file_survives_copy_pickle_and_to_dict(name):
    s = rbcstab.Scene.from_toml(os.path.join(SCENES, name))

    def short_run(scene):  # a cheap call that reads the whole scene (its L_reason: whether and where L was given)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", rbcstab.ModelWarning)
            run = rbcstab.simulate(scene.replace(T=min(scene.T, 2.0), dt=min(scene.dt, 1.0)))
        return {k: v for k, v in run.to_dict().items() if k != "seconds"}, run.Delta

    expected, Delta = short_run(s)
    for how, c in _copies(s).items():
        assert c.to_dict() == s.to_dict() and c == s and hash(c) == hash(s) and repr(c) == repr(s), how
        assert eval(repr(s), {"rbcstab": rbcstab, "inf": math.inf}) == s, how  # repr shows all of it
        got, got_Delta = short_run(c)
        assert got == expected and np.array_equal(got_Delta, Delta), how
        # What each computation reads beside the values: which keys were given, the panel tables, the file.
        for key in ("L", "beta", "diagram", "fig6e", "continuation", "source"):
            assert getattr(c, key) == getattr(s, key), (how, key)


def test_a_short_run_is_the_same_from_every_copy():
    s = rbcstab.Scene.from_toml(os.path.join(SCENES, "fig3_b_op.toml")).replace(T=20.0, dt=1.0)
    run = rbcstab.simulate(s)
    for how, c in _copies(s).items():
        other = rbcstab.simulate(c)
        assert np.array_equal(other.Delta, run.Delta) and np.array_equal(other.t, run.t), how


def test_beta_given_or_not_is_state_that_travels():
    # Continuation at lambda = 1 starts from beta = 0 (the equilibrium kind's default) when beta is not given;
    # the run's 0.001 would put an in-plane rest-shape component in and leave no equilibrium. A copy that lost
    # "not given" (as to_dict, pickle and copy did) failed where the scene ran.
    s = rbcstab.Scene(lambda_=1, B=1, L=6)
    assert s.beta is None and s.to_dict()["beta"] is None and "beta=None" in repr(s)
    assert s != s.replace(beta=0.001) and hash(s) != hash(s.replace(beta=0.001))
    b = rbcstab.continuation(s, parameter="lambda", min=0.5, max=3, max_points=40)
    for how, c in _copies(s).items():
        assert rbcstab.continuation(c, parameter="lambda", min=0.5, max=3, max_points=40).to_dict() == b.to_dict(), how
    with pytest.raises(ValueError, match="beta = 0.001"):
        rbcstab.continuation(s.replace(beta=0.001), parameter="lambda", min=0.5, max=3, max_points=40)
    assert s.replace(beta=0.001).replace(beta=None) == s


def test_panel_tables_and_the_source_are_part_of_the_scene(tmp_path):
    s = rbcstab.Scene.from_toml(os.path.join(SCENES, "fig4b_op.toml"))
    assert s.diagram is not None and s.to_dict()["diagram"] == s.diagram and s.source.endswith("fig4b_op.toml")
    bare = s.replace(diagram=None)
    assert bare != s and bare.diagram is None and "diagram=" in repr(s) and "diagram=" not in repr(bare)
    # A diagram without axes takes them from the table: the same plane from every copy.
    plane = rbcstab.diagram(s, counts=(1, 1), progress=False).to_dict()["diagram"]
    for how, c in _copies(s).items():
        assert rbcstab.diagram(c, counts=(1, 1), progress=False).to_dict()["diagram"] == plane, how
    assert rbcstab.Scene(diagram={"axes": ["lnB", "lnC"], "counts": [3, 4]}).diagram == {"axes": ["lnB", "lnC"],
                                                                                          "counts": [3, 4]}
    with pytest.raises(TypeError, match="diagram"):
        rbcstab.Scene(diagram=[1, 2])


def test_scenes_are_immutable_and_hashable():
    s = rbcstab.Scene(B=3.0)
    for name in ("B", "lambda_", "beta", "L", "diagram", "source", "Lambda"):
        with pytest.raises(AttributeError):
            setattr(s, name, 1.0)
    with pytest.raises(AttributeError):
        s.anything_new = 1
    assert len({s, rbcstab.Scene(B=3.0), rbcstab.Scene(B=3.0, name="fig3_op")}) == 1
    assert {s: 1}[rbcstab.Scene(B=3.0)] == 1 and hash(s) != hash(rbcstab.Scene(B=3.5))
    assert s != rbcstab.Scene(B=3.0, source="x.toml") and s != "not a scene"


def test_the_signature_lists_every_keyword_with_its_default():
    sig = inspect.signature(rbcstab.Scene)
    params = sig.parameters
    keys = rbcstab.scene_keys()
    assert {k["keyword"] for k in keys} <= set(params) and {"diagram", "fig6e", "continuation", "source"} <= set(params)
    d = rbcstab.Scene().to_dict()
    for k in keys:
        p = params[k["keyword"]]
        assert p.kind is inspect.Parameter.KEYWORD_ONLY and p.default == k["default"], k["keyword"]
        assert d.get(k["key"], p.default) == p.default, k["keyword"]
    assert params["L"].default is None and params["beta"].default is None and params["lambda_"].default == 5.0
    assert rbcstab.Scene(**{n: p.default for n, p in params.items()}) == rbcstab.Scene()


# ---- Python words in Python errors (issue 30, point 6) ----

def test_huge_integers_are_value_errors_with_the_range():
    with pytest.raises(ValueError) as e:
        rbcstab.Scene(L=2**63)
    assert str(e.value).startswith("L = 9223372036854775808 is out of range: must be an integer in [2, 100]")
    with pytest.raises(ValueError, match=r"L = -1180591620717411303424 is out of range: must be an integer in \[2, 100\]"):
        rbcstab.Scene().replace(L=-2**70)
    with pytest.raises(ValueError, match="max_steps = 18446744073709551616 is out of range"):
        rbcstab.Scene(max_steps=2**64)
    with pytest.raises(ValueError, match="B = inf"):
        rbcstab.Scene(B=10**400)
    with pytest.raises(ValueError, match="delta_l"):
        rbcstab.Scene(delta_l={2**70: 1e-3})


def test_the_ranges_are_the_clis(cli):
    import subprocess
    scene = rbcstab.Scene(lambda_=1, B=1, L=6)
    for keyword, value, words in (("max_points", 10**12, "[2, 100000000]"), ("label_every", 10**9, "[0, 100000000]")):
        with pytest.raises(ValueError) as e:
            rbcstab.continuation(scene, parameter="lambda", min=0.5, max=3, **{keyword: value})
        assert keyword in str(e.value) and words in str(e.value), str(e.value)
        flag = "--" + keyword.replace("_", "-")
        out = subprocess.run([os.environ["RBCSTAB_CLI"], "continue", "--lambda", "1", "--B", "1", "--L", "6",
                              flag, str(value)], capture_output=True, text=True)
        assert out.returncode != 0 and words in out.stderr, out.stderr
    with pytest.raises(ValueError, match=r"point = 1000001 is out of range: must be an integer in \[1, 1000000\]"):
        rbcstab.continuation(scene, parameter="lambda", min=0.5, max=3, curve="LP", parameter2="B", point=10**6 + 1)


@pytest.mark.parametrize("call, words", [
    (lambda s: rbcstab.continuation(s, parameter="C", min=0.05, max=0.1), "outside [min, max] = [0.05, 0.1]"),
    (lambda s: rbcstab.continuation(s.replace(model="full"), kind="modal", parameter="C", min=0.01, max=0.1),
     "not available for kind modal"),
    (lambda s: rbcstab.continuation(s, kind="modal", parameter="C", min=0.01, max=0.1, curve="BP"),
     "curve needs parameter2"),
])
def test_messages_name_keywords_not_flags(call, words):
    with pytest.raises(ValueError) as e:
        call(rbcstab.Scene(lambda_=1, B=1, L=6))
    assert words in str(e.value) and "--" not in str(e.value), str(e.value)


def test_from_toml_takes_paths_and_raises_pythons_errors(tmp_path):
    import pathlib
    p = pathlib.Path(SCENES) / "fig4b_op.toml"
    assert rbcstab.Scene.from_toml(p) == rbcstab.Scene.from_toml(str(p))
    with pytest.raises(FileNotFoundError) as e:
        rbcstab.Scene.from_toml(tmp_path / "missing.toml")
    assert e.value.filename == str(tmp_path / "missing.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("[parameters]\nB = 2\nC = = 3\n")
    with pytest.raises(ValueError, match=r"bad.toml:3:"):
        rbcstab.Scene.from_toml(bad)
    with pytest.raises(TypeError):
        rbcstab.Scene.from_toml(3)


def test_messages_name_the_scene_by_its_file_or_the_scene():
    assert rbcstab.Scene().label == "the scene"
    assert rbcstab.Scene(name="mine").label == "scene 'mine'"
    assert rbcstab.Scene(source="x.toml").label == "the scene of x.toml"
    assert "fig3_op" not in repr(rbcstab.Model(rbcstab.Scene(), "modal"))


def test_implausible_bare_physical_numbers_are_refused_and_units_are_kept():
    # A bare number is SI (the path the CLI flags and the [physical] table share): 2.8 is no radius in metres.
    cell = dict(shear_rate=100, viscosity=1e-3, bending_modulus=2e-19, shear_modulus=2.5e-6)
    for radius in (2.8, "2.8"):
        with pytest.raises(ValueError, match=r"radius = 2\.8 \(a bare number, read as 2\.8 m\).*did you mean 2\.8 um\?"):
            rbcstab.Scene(radius=radius, **cell)
    assert rbcstab.Scene(radius=2.8e-6, **cell).radius == 2.8e-6
    assert rbcstab.Scene(radius="2.8 um", **cell).radius == 2.8e-6
    # With its unit it is taken as given; to_dict and pickle keep the unit, so the value reads back as itself.
    big = rbcstab.Scene(radius="2.8 m", **cell)
    assert big.radius == 2.8
    assert big.to_dict()["radius"] == "2.8 m"
    assert rbcstab.Scene.from_dict(big.to_dict()) == big
    assert pickle.loads(pickle.dumps(big)) == big

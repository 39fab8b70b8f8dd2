"""Every result type pickles (issue 30, point 3): a copy holds the same data and does the same (its to_dict(), its
arrays, its CSV and its methods), so results travel through multiprocessing and caches."""
import multiprocessing
import pickle
import warnings

import numpy as np
import pytest

import rbcstab

SCENE = rbcstab.Scene(T=40.0)


def _same_arrays(a, b):
    assert a.keys() == b.keys()
    for k in a:
        assert np.array_equal(a[k], b[k], equal_nan=a[k].dtype.kind == "f"), k


def roundtrip(obj):
    copy = pickle.loads(pickle.dumps(obj))
    assert type(copy) is type(obj) and repr(copy) == repr(obj)
    return copy


def test_simulation_and_reports():
    run = rbcstab.simulate(SCENE)
    c = roundtrip(run)
    assert c.to_dict() == run.to_dict() and c.text == run.text
    for name in ("t", "Delta", "sigma", "r", "Psi", "y_final"):
        assert np.array_equal(getattr(c, name), getattr(run, name)), name
    for report in (rbcstab.thresholds(SCENE), rbcstab.summary(SCENE)):
        c = roundtrip(report)
        assert c == report and c.kind == report.kind and c.text == report.text


def test_branch_and_curve():
    scene = rbcstab.Scene(lambda_=1, B=1, L=6)
    branch = rbcstab.continuation(scene, kind="modal", parameter="C", min=0.01, max=0.1)
    c = roundtrip(branch)
    assert c.to_dict() == branch.to_dict() and c.to_csv() == branch.to_csv()
    bp = branch.labels("BP", l=3)[0]
    assert c.labels("BP", l=3) == [bp]
    curve = branch.curve(bp, parameter2="B", min2=0.5, max2=2, max_points=12)
    cc = roundtrip(curve)
    assert cc.to_dict() == curve.to_dict() and np.array_equal(cc["B"], curve["B"])


def test_model():
    model = rbcstab.Model(SCENE, "modal")
    c = roundtrip(model)
    y = model.y0 * 1.01
    assert c.n == model.n and c.level == model.level and c.scene == model.scene
    assert np.array_equal(c.rhs(0.3, y), model.rhs(0.3, y)) and np.array_equal(c.jacobian(0.3, y), model.jacobian(0.3, y))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rbcstab.ModelWarning)
        approx = rbcstab.Model(SCENE, "reduced")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the copy does not warn again: its warnings attribute keeps the text
        c = roundtrip(approx)
    assert not c.exact and c.warnings == approx.warnings


def test_diagram(tmp_path):
    d = rbcstab.diagram(SCENE, counts=(3, 2), progress=False, include_seconds=False)
    c = roundtrip(d)
    assert c.to_dict() == d.to_dict() and c.to_csv() == d.to_csv() and c.axes == d.axes and c.shape == d.shape
    _same_arrays(c._arrays, d._arrays)
    assert np.array_equal(c.x, d.x) and np.array_equal(c.y, d.y)
    assert c.point_scene(2, 1) == d.point_scene(2, 1) and c.computed == d.computed and c.summary == d.summary
    c.save(tmp_path / "c")
    d.save(tmp_path / "d")
    assert (tmp_path / "c.csv").read_text() == (tmp_path / "d.csv").read_text()


def test_trace_and_fig6e():
    t = rbcstab.trace(SCENE, lines=0, samples=8)
    c = roundtrip(t)
    assert c.to_dict() == t.to_dict() and c.to_csv() == t.to_csv() and c.axes == t.axes
    assert c.x_range == t.x_range and c._overlay == t._overlay and len(c.curves) == len(t.curves)
    for a, b in zip(c.curves, t.curves):
        assert (a.l, a.chain, a.criterion) == (b.l, b.chain, b.criterion) and np.array_equal(a.mu, b.mu)
    _same_arrays(c.corners, t.corners)
    table = rbcstab.fig6e(SCENE.replace(L=4, T=20.0), lambdas=[1], B=[1], C=[0.05])
    ct = roundtrip(table)
    assert ct.to_dict() == table.to_dict() and ct.to_csv() == table.to_csv()
    _same_arrays(ct._columns, table._columns)


def _run(scene):
    return rbcstab.simulate(scene), rbcstab.Model(scene, "modal")


def test_a_pool_of_two_over_two_scenes():
    scenes = [rbcstab.Scene(T=30.0), rbcstab.Scene(T=30.0, C=0.08)]
    with multiprocessing.get_context("fork").Pool(2) as pool:
        results = pool.map(_run, scenes)
    for scene, (run, model) in zip(scenes, results):
        assert run.to_dict()["sigma_final"] == rbcstab.simulate(scene).to_dict()["sigma_final"]
        assert model.scene == scene.replace(model="modal")

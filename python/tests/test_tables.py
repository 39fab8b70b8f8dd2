"""pandas and xarray views (issue 30, point 4): each frame against the CLI's own CSV of the same result (another
serialiser, in C++) or the result's arrays, tidy (one row per sample, point or grid point), units from the
parameter table; without pandas the view says what to install."""
import io
import sys

import numpy as np
import pytest

import rbcstab

pd = pytest.importorskip("pandas")
xr = pytest.importorskip("xarray")

PLANE = dict(axes=("lnB", "lnC"), x_range=(-1.0, 5.0), y_range=(-5.0, 1.0))


def _csv_frame(text):
    return pd.read_csv(io.StringIO(text), comment="#")


def test_simulation_one_row_per_sample():
    run = rbcstab.simulate(rbcstab.Scene(T=200.0, L=5))  # stops early: some samples are skipped
    df = run.to_pandas()
    assert not run.integrated.all()
    assert list(df.columns[:1]) == ["t"] and len(df) == len(run.t)
    assert [f"Delta_{l}" for l in run.ls] == [c for c in df.columns if c.startswith("Delta_")]
    for l in run.ls:
        assert np.array_equal(df[f"Delta_{l}"].to_numpy(), run.Delta[:, l - 2], equal_nan=True)
    for name in ("t", "sigma", "r", "Psi"):
        assert np.array_equal(df[name].to_numpy(), getattr(run, name), equal_nan=True), name
    assert np.array_equal(df["integrated"].to_numpy(), run.integrated)
    assert df["sigma"][~df["integrated"]].isna().all()  # skipped samples: no number where none was computed
    assert df.attrs["model"] == run.model and df.attrs["L"] == run.L


def test_branch_points_and_special_points_in_one_table():
    branch = rbcstab.continuation(rbcstab.Scene(lambda_=1, B=1, L=6), kind="modal", parameter="C", min=0.01,
                                  max=0.1)
    df = branch.to_pandas()
    specials = [sp for sp in branch.special_points if sp["label"] is not None]
    # The computed points (their stability is known) are the Branch's own columns, in order and exactly (the CSV
    # prints 17 significant digits); the other rows are the located special points, one each.
    computed = df[df["stable"].notna()]
    assert len(computed) == len(branch) and len(df) == len(branch) + sum(sp["type"] != "EP" for sp in specials)
    for c in ("C", "r", "Psi", "sigma", "Delta_3", "max_Re_eig"):
        assert np.array_equal(computed[c].to_numpy(float), branch[c].astype(float), equal_nan=True), c
    for sp in specials:
        row = df[df["label"] == sp["label"]]
        assert len(row) == 1 and row["type"].iloc[0] == sp["type"], sp["label"]
        assert row["C"].iloc[0] == sp["C"] and row["sigma"].iloc[0] == sp["sigma"]
        if sp["type"] == "BP":
            assert row["mode_l"].iloc[0] == sp["mode_l"]
    assert (df["type"] == "").sum() == len(branch) - 2  # the two ends are EP
    onset = df[(df["type"] == "BP") & (df["mode_l"] == 3)]
    assert list(onset["label"]) == branch.labels("BP", l=3)
    assert df.attrs["free_parameter"] == "C" and df.attrs["kind"] == "modal"


@pytest.fixture(scope="module")
def diagram():
    return rbcstab.diagram(rbcstab.Scene(L=5, T=40.0, dt=40.0), counts=(4, 3), threads=2, progress=False,
                           include_seconds=False, **PLANE)


def test_diagram_tidy_rows_match_the_clis_csv(diagram):
    df = diagram.to_pandas()
    assert len(df) == len(diagram.x) * len(diagram.y)
    csv = _csv_frame(diagram.to_csv())
    assert len(csv) == len(df)
    # Row by row the same grid point: the axes' values and the mode, whatever order each writer chose.
    key = ["lnB", "lnC"]
    a = df.sort_values(key).reset_index(drop=True)
    b = csv.sort_values(key).reset_index(drop=True)
    for c in key + ["l_Delta", "sigma_final"]:
        assert np.allclose(a[c].to_numpy(float), b[c].to_numpy(float), rtol=1e-15, atol=0, equal_nan=True), c
    i, j = 2, 1
    row = df[(df["lnB"] == diagram.x[i]) & (df["lnC"] == diagram.y[j])]
    assert len(row) == 1 and row["l_Delta"].iloc[0] == diagram.l_Delta[j, i]


def test_diagram_as_xarray(diagram):
    ds = diagram.to_xarray()
    assert ds["l_Delta"].dims == ("lnC", "lnB")
    assert np.array_equal(ds["lnB"].values, diagram.x) and np.array_equal(ds["lnC"].values, diagram.y)
    i, j = 3, 2
    assert ds["l_Delta"].sel(lnB=diagram.x[i], lnC=diagram.y[j]).item() == diagram.l_Delta[j, i]
    rows = {r["name"]: r for r in rbcstab.parameter_table()}
    for axis in ("lnB", "lnC"):
        assert ds[axis].attrs["long_name"] == rows[axis]["description"]
        assert ds[axis].attrs["units"] == (rows[axis]["unit"] or "1")


def test_trace_one_row_per_traced_point():
    t = rbcstab.trace(rbcstab.Scene(L=5, T=40.0, dt=40.0), **PLANE)
    df = t.to_pandas()
    assert len(df) == sum(len(c) for c in t.curves)
    for k, c in enumerate(t.curves):
        piece = df[df["piece"] == k]
        assert np.array_equal(piece["lnB"].to_numpy(), c.x) and np.array_equal(piece["lnC"].to_numpy(), c.y)
        assert (piece["l"] == c.l).all()


def test_without_pandas_the_view_says_what_to_install(monkeypatch):
    run = rbcstab.simulate(rbcstab.Scene(T=10.0, L=4))
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas now raises ImportError
    with pytest.raises(ImportError, match="python3-pandas"):
        run.to_pandas()

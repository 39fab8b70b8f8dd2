"""The physical phase diagram from Python (issue 31, point 2): the same library call as the C++ tests, its bands
scale as the model says (the tumbling boundary sits at one capillary number, so its rate is proportional to the
shear modulus), the published observations come with it, the plot draws only what was computed, and bad input
raises ValueError/TypeError naming the keyword."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import rbcstab  # noqa: E402

CELL = dict(shear_rate="10/s", viscosity="25 mPa s", radius="2.8 um", bending_modulus="2e-19 J",
            shear_modulus="6 uN/m", inner_viscosity="6 mPa s", Delta=1.0, Delta0=0.5)
FAST = dict(shear_rate=(0.1, 1e3), samples_per_decade=3, rtol=1e-4, onset=False, threads=2)


@pytest.fixture(scope="module")
def small_map():
    return rbcstab.physical_map(rbcstab.Scene(**CELL), viscosity=(25e-3, 50e-3), viscosities=2,
                                spreads=[("shear_modulus", 3e-6, 12e-6, "test")], **FAST)


def test_band_scales_with_the_shear_modulus(small_map):
    rate = small_map.rate("tumbling_to_swinging")
    lo, hi = small_map.band("tumbling_to_swinging")
    assert np.all(np.isfinite(rate))
    np.testing.assert_allclose(lo / rate, 0.5, rtol=2e-4)
    np.testing.assert_allclose(hi / rate, 2.0, rtol=2e-4)
    # Doubling the outer viscosity at a fixed inner one lowers lambda: the boundary moves, and lambda is reported.
    lam = [c["lambda"] for c in small_map.to_dict()["columns"]]
    assert lam == pytest.approx([0.24, 0.12])


def test_observations_and_assumptions_come_with_it(small_map):
    d = small_map.to_dict()
    assert d["experiments_file"].endswith("experiments.csv")
    assert {e["source"] for e in small_map.experiments} >= {"Abkarian2007", "Lanotte2016"}
    names = [a["assumption"] for a in small_map.assumptions]
    assert names == ["quasi-spherical expansion", "Stokes flow", "linear shear elasticity"]
    assert "PhysicalMap" in repr(small_map)


def test_plot_draws_only_what_was_computed(small_map):
    fig, ax = plt.subplots()
    assert small_map.plot(ax=ax) is ax
    line = ax.get_lines()[0]
    assert line.get_label().startswith("tumbling")
    np.testing.assert_allclose(line.get_ydata(), small_map.rate("tumbling_to_swinging"))
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log"
    plt.close(fig)


def test_bad_input_names_the_keyword():
    s = rbcstab.Scene(**CELL)
    with pytest.raises(ValueError, match="max_viscosity"):
        rbcstab.physical_map(s, viscosity=(5e-2, 1e-3), **FAST)
    with pytest.raises(ValueError, match="spreads"):
        rbcstab.physical_map(s, spreads="sick", **FAST)
    with pytest.raises(TypeError, match="viscosity"):
        rbcstab.physical_map(s, viscosity=3, **FAST)
    with pytest.raises(TypeError, match="Scene"):
        rbcstab.physical_map("cell.toml", **FAST)
    with pytest.raises(ValueError, match="inner_viscosity"):
        rbcstab.physical_map(rbcstab.Scene(**{k: v for k, v in CELL.items() if k != "inner_viscosity"}, lambda_=5.0),
                             **FAST)
    with pytest.raises(ValueError, match="stiffness"):
        rbcstab.physical_map(s, spreads=[("stiffness", 1, 2)], **FAST)
    with pytest.raises(ValueError, match="experiments"):
        rbcstab.physical_map(s, experiments="/nonexistent/obs.csv", **FAST)

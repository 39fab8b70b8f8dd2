"""The model from Python: rbcstab.Model (rhs, jacobian, y0, observables) and initial_state / rhs / jacobian.

Oracles: central finite differences of rhs for the Jacobian; rbcstab.simulate (the library's own integrator and
observables) for the initial observables and for a SciPy Radau solution; the three levels against each other on
the scenes where each is exact.
"""
import warnings

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import rbcstab

LEVELS = ("full", "modal", "reduced")


def quiet_model(scene, level):
    """A Model without the ModelWarning of a level that approximates the scene (the tests that want it ask)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rbcstab.ModelWarning)
        return rbcstab.Model(scene, level)


# --- the Jacobian against central differences -------------------------------------------------------------------

def central_differences(model, t, y, rel_step):
    """dF/dy by central differences, column j with step h_j = rel_step * max(|y_j|, 1)."""
    J = np.empty((model.n, model.n))
    for j in range(model.n):
        h = rel_step * max(abs(y[j]), 1.0)
        yp, ym = y.copy(), y.copy()
        yp[j] += h
        ym[j] -= h
        J[:, j] = (model.rhs(t, yp) - model.rhs(t, ym)) / (yp[j] - ym[j])
    return J


# Scenes whose levels are all defined: the Fig. 3 scene (the modal level is its exact one; reduced approximates it)
# at L = 4 so that the full level stays small, and an in-plane scene with a stress-free l = 3 content (full only).
JACOBIAN_CASES = [(rbcstab.Scene(L=4), level) for level in LEVELS] + [
    (rbcstab.Scene(L=5, beta=np.pi / 2, delta=1e-2, rest_delta_l={3: 1e-3}), "full"),
    (rbcstab.Scene(L=6, lambda_=1.0, B=0.5, C=0.5, delta_l={4: 0.05}), "modal"),
]


@pytest.mark.parametrize("scene,level", JACOBIAN_CASES, ids=lambda v: v if isinstance(v, str) else v.name)
def test_jacobian_equals_central_differences_of_rhs(scene, level):
    # Error of a central difference with step h: truncation h^2 |F'''| / 6 plus rounding. F = M(sigma) y + s(t)
    # sums terms of size |J| |y| that cancel to |F|, so its rounding is ~eps (|J| |y| + |F|) and a difference
    # quotient's ~eps (|J| |y| + |F|) / h. With h = 1e-6 (relative, on states of order one) and |F'''| of order
    # |J| (F is rational in y with order-one denominators near y0) the sum is 1e-10..1e-9 |J| (|y| reaches 7 for
    # ln Delta_l); the measured error is at most this estimate, and the test allows ten times it. A wrong entry of
    # the analytic Jacobian is off by the order of the entries around it (the smallest, rank-one terms of the
    # l >= 3 modes, are ~1e-3 |J|): far above.
    model = quiet_model(scene, level)
    rng = np.random.default_rng(20240614)
    eps, h = np.finfo(float).eps, 1e-6
    for _ in range(3):
        t = rng.uniform(0.0, 20.0)
        y = model.y0 * (1 + 0.05 * rng.standard_normal(model.n)) + 0.01 * rng.standard_normal(model.n)
        J = model.jacobian(t, y)
        assert J.shape == (model.n, model.n) and J.dtype == np.float64
        fd = central_differences(model, t, y, h)
        Jmax, Fmax = np.max(np.abs(J)), np.max(np.abs(model.rhs(t, y)))
        estimate = eps * (Jmax * np.max(np.abs(y)) + Fmax) / h + h ** 2 * Jmax
        assert np.max(np.abs(J - fd)) <= 10 * estimate, (level, np.max(np.abs(J - fd)) / estimate)
        assert np.max(np.abs(J - fd)) <= 1e-8 * Jmax  # and so to 1e-8 of the Jacobian's scale (measured: 1e-9)


# --- the Model against simulate --------------------------------------------------------------------------------

@pytest.mark.parametrize("level", LEVELS + ("auto",))
def test_model_reports_what_simulate_reports_at_t0(level):
    scene = rbcstab.Scene(T=2.0)
    model = quiet_model(scene, level)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rbcstab.ModelWarning)
        run = rbcstab.simulate(scene, model=level)
    assert model.level == run.model and model.exact == run.model_exact and model.level_reason == run.model_reason
    assert model.L == run.L and model.L_reason == run.L_reason and model.warnings == run.warnings
    o = model.observables(0.0, model.y0)
    # the same library calls on the same state: equal to the last bit
    assert list(o["Delta"]) == [run.excess_area_initial[str(l)] for l in model.ls]
    assert o["sigma"] == run.sigma_initial
    assert o["r"] == run.r[0] and o["Psi"] == run.Psi[0]
    assert len(model.state_names) == model.n == len(model.y0)


def test_auto_is_the_level_simulate_chooses():
    assert rbcstab.Model(rbcstab.Scene()).level == "modal"  # beta = 0.001: m = +-1 content and l >= 3 seeds
    assert rbcstab.Model(rbcstab.Scene(beta=0.0, delta=0.0), "auto").level == "reduced"
    assert rbcstab.Model(rbcstab.Scene(rest_delta_l={3: 1e-3}), "auto").level == "full"
    # the scene's own model key is the default level
    assert rbcstab.Model(rbcstab.Scene(model="full", L=3)).level == "full"


def test_truncation_is_the_scenes_or_the_one_simulate_chooses():
    given = rbcstab.Model(rbcstab.Scene(L=7), "modal")
    assert given.L == 7 and given.ls == list(range(2, 8))
    # no L: the truncation simulate chooses for the scene's horizon (the Fig. 3 test compares it with simulate's)
    automatic = rbcstab.Model(rbcstab.Scene(T=50.0), "modal")
    assert automatic.L == rbcstab.simulate(rbcstab.Scene(T=50.0)).L
    assert automatic.L_reason.startswith(f"L = {automatic.L}") and automatic.L_reason != given.L_reason


def test_state_names_follow_each_levels_layout():
    scene = rbcstab.Scene(L=4)
    for level in LEVELS:
        model = quiet_model(scene, level)
        y = dict(zip(model.state_names, model.y0))
        o = model.observables(0.0, model.y0)
        if level == "full":  # Delta_l = a_l sum_m |f_{l,m}|^2, a_l = (l - 1)(l + 2) / 2
            for l in model.ls:
                norm2 = sum(y[f"Re f[{l},{m}]"] ** 2 + y[f"Im f[{l},{m}]"] ** 2 for m in range(-l, l + 1))
                assert o["Delta"][l - 2] == pytest.approx((l - 1) * (l + 2) / 2 * norm2, rel=1e-14)
        elif level == "modal":  # ln Delta_l for l >= 3; f_{2,-m} = (-1)^m conj f_{2,m}
            for l in model.ls[1:]:
                assert o["Delta"][l - 2] == pytest.approx(np.exp(y[f"ln Delta_{l}"]), rel=1e-14)
            norm2 = y["f[2,0]"] ** 2 + 2 * sum(y[f"{p} f[2,{m}]"] ** 2 for p in ("Re", "Im") for m in (1, 2))
            assert o["Delta"][0] == pytest.approx(2 * norm2, rel=1e-14)
        else:  # z = r e^{-i Psi}, |z|^2 + w^2 = 1 at the start
            z = y["Re z"] + 1j * y["Im z"]
            assert abs(z) == pytest.approx(o["r"], rel=1e-14, abs=1e-15)
            assert abs(z) ** 2 + y["w"] ** 2 == pytest.approx(1.0, rel=1e-14)
    # the l = 2 amplitudes by name are the same numbers at the full and modal levels, in the m order of each
    tilted = rbcstab.Scene(L=3, beta=1.0)
    full, modal = (dict(zip(m.state_names, m.y0)) for m in (quiet_model(tilted, lv) for lv in ("full", "modal")))
    assert full["Re f[2,0]"] == modal["f[2,0]"] and full["Im f[2,0]"] == 0.0
    for m in (1, 2):
        for part in ("Re", "Im"):
            assert full[f"{part} f[2,{m}]"] == modal[f"{part} f[2,{m}]"]
        # reality: f_{2,-m} = (-1)^m conj f_{2,m}
        assert full[f"Re f[2,{-m}]"] == (-1) ** m * full[f"Re f[2,{m}]"] != 0.0
        assert full[f"Im f[2,{-m}]"] == -((-1) ** m) * full[f"Im f[2,{m}]"]


def test_solve_ivp_radau_reproduces_simulate_on_the_fig3_scene():
    # The default scene is the paper's Fig. 3 case (modal is its exact level). simulate runs rk8pd at rtol 1e-8,
    # atol 1e-12; Radau runs at rtol 1e-10 with the library's Jacobian. The modal state holds f_{2,m} (|f| ~ 1) and
    # ln Delta_l for l >= 3, so both tolerances act relatively on every Delta_l, even on the modes that decay to
    # 1e-100, and the difference is bounded by simulate's error, a modest multiple of its rtol 1e-8: 1e-7 relative
    # allows ten times rtol for the error's growth through the instability (Delta_3 rises from 1e-3 to most of the
    # excess area; measured: 5e-10). sigma, r and Psi likewise on their scales (|sigma| ~ 30, r, Psi ~ 1).
    # Integrated to T: an early-terminated run advances its decayed modes to first order, within rtol of ln Delta_l
    # (about 1e-6 of Delta_l ~ 1e-100), which this per-element comparison would not allow; that agreement is tested
    # against full-horizon runs in C++ (certified_run_test).
    scene = rbcstab.Scene(full_horizon=True)
    run = rbcstab.simulate(scene)
    model = rbcstab.Model(scene)
    assert model.level == run.model == "modal" and model.L == run.L
    sol = solve_ivp(model.rhs, (0.0, scene.T), model.y0, method="Radau", jac=model.jacobian, t_eval=run.t,
                    rtol=1e-10, atol=1e-12)
    assert sol.status == 0, sol.message
    o = model.observables(sol.t, sol.y)
    assert o["Delta"].shape == run.Delta.shape
    np.testing.assert_allclose(o["Delta"], run.Delta, rtol=1e-7, atol=0)
    assert np.max(np.abs(o["sigma"] - run.sigma)) <= 1e-7 * np.max(np.abs(run.sigma))
    # at T, the quantities simulate's JSON reports
    for l in model.ls:
        assert o["Delta"][-1, l - 2] == pytest.approx(run.excess_area_final[str(l)], rel=1e-7)
    assert o["sigma"][-1] == pytest.approx(run.sigma_final, rel=1e-7)
    assert o["Psi"][-1] == pytest.approx(run.Psi_final, abs=1e-7)
    assert np.max(np.abs(o["r"] - run.r)) <= 1e-7
    assert np.max(np.abs(o["Psi"] - run.Psi)) <= 1e-7  # unwrapped alike
    assert run.l_Delta == 3 and np.argmax(o["Delta"][-1] - o["Delta"][0]) + 2 == 3


@pytest.mark.parametrize("beta", [0.0, np.pi / 2], ids=["out_of_plane", "in_plane"])
def test_the_three_levels_agree_where_all_are_exact(beta):
    # delta = 0 and beta in {0, pi/2}: only l = 2, m in {0, +-2} hold area, so reduced, modal and full are the same
    # dynamics in different coordinates. Each is solved by Radau at rtol 1e-10, atol 1e-12: the observables differ
    # by the three solutions' errors, a modest multiple of rtol; 1e-8 (relative to each quantity's scale: Delta,
    # max |sigma| ~ 40, r ~ 1, Psi, which grows to ~30 while the in-plane cell tumbles) allows a hundred times rtol
    # (measured: 1e-10).
    scene = rbcstab.Scene(beta=beta, delta=0.0, L=3, T=30.0)
    models = [rbcstab.Model(scene, level) for level in LEVELS]
    assert all(m.exact for m in models)
    t_eval = np.linspace(0.0, scene.T, 61)
    obs = {}
    for m in models:
        sol = solve_ivp(m.rhs, (0.0, scene.T), m.y0, method="Radau", jac=m.jacobian, t_eval=t_eval, rtol=1e-10,
                        atol=1e-12)
        assert sol.status == 0, (m.level, sol.message)
        obs[m.level] = m.observables(sol.t, sol.y)
    ref = obs["full"]
    for level in ("modal", "reduced"):
        o = obs[level]
        np.testing.assert_allclose(o["Delta"], ref["Delta"], rtol=0, atol=1e-8 * scene.Delta)
        for key in ("sigma", "r", "Psi"):
            assert np.max(np.abs(o[key] - ref[key])) <= 1e-8 * max(1.0, np.max(np.abs(ref[key]))), (level, key)
    # and at t = 0 they are the same state: equal observables to rounding
    o0 = [m.observables(0.0, m.y0) for m in models]
    for o in o0[1:]:
        assert o["sigma"] == pytest.approx(o0[0]["sigma"], rel=1e-12)
        assert o["Psi"] == pytest.approx(o0[0]["Psi"], abs=1e-12)


def test_vectorised_observables_equal_the_per_state_ones():
    model = rbcstab.Model(rbcstab.Scene(L=5), "modal")
    sol = solve_ivp(model.rhs, (0.0, 30.0), model.y0, method="Radau", jac=model.jacobian, rtol=1e-8,
                    t_eval=np.linspace(0, 30, 31))
    many = model.observables(sol.t, sol.y)
    assert many["Delta"].shape == (31, model.L - 1)
    for k in (0, 7, 30):
        one = model.observables(sol.t[k], sol.y[:, k])
        assert np.array_equal(one["Delta"], many["Delta"][k])
        assert one["sigma"] == many["sigma"][k] and one["r"] == many["r"][k]
        assert np.isclose(np.exp(1j * one["Psi"]), np.exp(1j * many["Psi"][k]), rtol=0, atol=1e-14)
    assert np.all(np.abs(np.diff(many["Psi"])) < np.pi)  # unwrapped


# --- the one-off functions and the inputs ----------------------------------------------------------------------

def test_functions_equal_the_model_methods():
    scene = rbcstab.Scene(L=4)
    model = rbcstab.Model(scene, "modal")
    y = model.y0 * 1.01
    assert np.array_equal(rbcstab.initial_state(scene, "modal"), model.y0)
    assert np.array_equal(rbcstab.rhs(scene, "modal", 3.0, y), model.rhs(3.0, y))
    assert np.array_equal(rbcstab.jacobian(scene, "modal", 3.0, y), model.jacobian(3.0, y))


def test_outputs_are_new_numpy_arrays_and_inputs_convert():
    model = rbcstab.Model(rbcstab.Scene(L=4), "full")
    y = model.y0
    f = model.rhs(1.0, y)
    J = model.jacobian(1.0, y)
    assert f.flags.owndata and f.flags.writeable and J.flags.owndata and J.flags.c_contiguous
    assert not np.shares_memory(model.y0, model.y0)  # y0 is a new array on each access
    # lists, float32, integer and strided arrays convert; the result is that of the float64 array
    wide = np.zeros(2 * model.n)
    wide[::2] = y
    assert np.array_equal(model.rhs(1.0, wide[::2]), f)
    assert np.array_equal(model.rhs(1, list(y)), f)
    assert np.array_equal(model.rhs(np.float32(1.0), y), f)
    assert model.rhs(0.0, np.zeros(model.n, dtype=np.int64)).shape == (model.n,)
    assert model.rhs(0.0, y.astype(np.float32)).dtype == np.float64


def test_a_level_that_approximates_the_scene_warns():
    with pytest.warns(rbcstab.ModelWarning, match="reduced"):
        model = rbcstab.Model(rbcstab.Scene(), "reduced")
    assert not model.exact and model.n == 3
    assert "approximate" in repr(model) and "\n" not in repr(model) and "<table>" in model._repr_html_()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert rbcstab.Model(rbcstab.Scene(beta=0.0, delta=0.0), "reduced").exact


def test_bad_inputs_raise():
    scene = rbcstab.Scene(L=4)
    model = rbcstab.Model(scene, "modal")
    n, y = model.n, model.y0
    with pytest.raises(ValueError, match=rf"shape \({n},\).*got shape \({n - 1},\)"):
        model.rhs(0.0, y[:-1])
    with pytest.raises(ValueError, match=rf"got shape \(1, {n}\)"):
        model.jacobian(0.0, y[None, :])
    with pytest.raises(ValueError, match=r"got shape \(\)"):
        model.rhs(0.0, 1.0)
    for bad in ("abc", [str(v) for v in y], None, {"y": 1}, y.astype(complex), y > 0):
        with pytest.raises(TypeError):
            model.rhs(0.0, bad)
    for bad_t in ("0", None, [0.0], True):
        with pytest.raises(TypeError):
            model.rhs(bad_t, y)
    for bad_value in (np.nan, np.inf, -np.inf):
        z = y.copy()
        z[2] = bad_value
        with pytest.raises(ValueError, match="finite"):
            model.rhs(0.0, z)
        with pytest.raises(ValueError, match="finite"):
            model.jacobian(0.0, z)
        with pytest.raises(ValueError, match="t must be finite"):
            model.rhs(bad_value, y)
    with pytest.raises(ValueError, match="model"):
        rbcstab.Model(scene, "exact")
    with pytest.raises(ValueError, match="model"):
        rbcstab.rhs(scene, "ful", 0.0, y)
    with pytest.raises(TypeError):
        rbcstab.Model(scene, 3)
    with pytest.raises(TypeError):
        rbcstab.Model({"lambda": 5}, "full")
    with pytest.raises(ValueError, match="modal"):  # a stress-free l >= 3 shape: only full holds it
        rbcstab.Model(rbcstab.Scene(rest_delta_l={3: 1e-3}), "modal")
    # observables: one state, or columns with one time each
    with pytest.raises(ValueError, match="shape"):
        model.observables(0.0, np.zeros((n + 1, 2)))
    with pytest.raises(ValueError, match=r"t must have shape \(3,\)"):
        model.observables(np.zeros(2), np.tile(y[:, None], (1, 3)))
    with pytest.raises(ValueError, match="finite"):
        model.observables(np.array([0.0, np.nan]), np.tile(y[:, None], (1, 2)))


# --- more of the model for users' own tools: batches, dF/dq, the sparsity pattern ------------------------------

@pytest.mark.parametrize("level", LEVELS)
def test_rhs_over_a_batch_of_states_is_rhs_of_each(level):
    model = quiet_model(rbcstab.Scene(L=4), level)
    rng = np.random.default_rng(7)
    Y = model.y0[:, None] * (1 + 0.05 * rng.standard_normal((model.n, 5)))
    F = model.rhs(1.5, Y)
    assert F.shape == (model.n, 5)
    for j in range(5):  # the same library call per column: bitwise
        assert np.array_equal(F[:, j], model.rhs(1.5, np.ascontiguousarray(Y[:, j])))
    # SciPy's vectorized=True (its finite-difference Jacobian calls rhs on a batch) gives the same solution as
    # the column-by-column calls: the same numbers in the same order.
    a = solve_ivp(model.rhs, (0.0, 5.0), model.y0, method="Radau", vectorized=True, rtol=1e-8, atol=1e-10)
    b = solve_ivp(lambda t, y: model.rhs(t, y), (0.0, 5.0), model.y0, method="Radau", vectorized=False,
                  rtol=1e-8, atol=1e-10)
    assert a.status == b.status == 0 and np.array_equal(a.y, b.y)
    with pytest.raises(ValueError, match=r"shape \(" + str(model.n) + r",\) \(one state\) or"):
        model.rhs(0.0, np.zeros((model.n + 1, 2)))


def five_point(models, t, y, h):
    """dF/dq from the Models at q - 2h, q - h, q + h, q + 2h: error O(h^4)."""
    fm2, fm1, fp1, fp2 = (m.rhs(t, y) for m in models)
    return (fm2 - 8 * fm1 + 8 * fp1 - fp2) / (12 * h)


@pytest.mark.parametrize("level,keyword,parameter", [("modal", "C", "C"), ("modal", "lambda_", "lambda"),
                                                     ("modal", "B", "B"), ("full", "C", "C"),
                                                     ("reduced", "lambda_", "lambda")])
def test_jacobian_p_against_models_built_at_shifted_parameters(level, keyword, parameter):
    # The oracle builds four Models from Scenes with the parameter shifted (Python's Scene.replace, a path apart
    # from the library's with_parameter) and takes a five-point difference: error ~ h^4 |F^(5)| ~ 1e-12 at
    # h = 1e-3 q, rounding ~ eps |F| / h ~ 1e-13 |F| / q. The library's central difference errs by ~ eps^(2/3) ~
    # 4e-11 of F's scale (measured 4e-11..4e-10). 1e-8 of max |dF/dq| allows that; a step not scaled with q (the
    # 1 + |q| of the continuation's own differences) measured 2.5e-8 at C = 0.04, and a wrong factor or sign O(1).
    scene = rbcstab.Scene(L=4, model=level)
    model = quiet_model(scene, level)
    q = getattr(scene, keyword)
    h = 1e-3 * q
    models = [quiet_model(scene.replace(**{keyword: q + k * h}), level) for k in (-2, -1, 1, 2)]
    rng = np.random.default_rng(11)
    y = model.y0 * (1 + 0.05 * rng.standard_normal(model.n))
    dq = model.jacobian_p(parameter, 2.0, y)
    ref = five_point(models, 2.0, y, h)
    assert dq.shape == (model.n,) and np.max(np.abs(ref)) > 0
    assert np.max(np.abs(dq - ref)) <= 1e-8 * np.max(np.abs(ref)), np.max(np.abs(dq - ref)) / np.max(np.abs(ref))


def test_jacobian_p_of_a_parameter_the_level_leaves_alone_is_zero():
    # B does not enter the reduced model: the systems at B +- h are the same, and the difference is exactly 0.
    model = quiet_model(rbcstab.Scene(L=4), "reduced")
    assert np.array_equal(model.jacobian_p("B", 0.0, model.y0), np.zeros(model.n))
    with pytest.raises(ValueError, match="parameter"):
        model.jacobian_p("nonsense", 0.0, model.y0)


@pytest.mark.parametrize("level", LEVELS)
def test_jacobian_sparsity_covers_every_nonzero_of_the_jacobian(level):
    model = quiet_model(rbcstab.Scene(L=4, beta=0.7), level)
    P = model.jacobian_sparsity()
    assert P.shape == (model.n, model.n) and P.dtype == np.bool_ and P.diagonal().all()
    rng = np.random.default_rng(3)
    for _ in range(3):
        y = model.y0 * (1 + 0.1 * rng.standard_normal(model.n)) + 1e-3 * rng.standard_normal(model.n)
        J = model.jacobian(rng.uniform(0, 10), y)
        assert not np.any((J != 0) & ~P), np.argwhere((J != 0) & ~P)[:5]
    sol = solve_ivp(model.rhs, (0.0, 3.0), model.y0, method="BDF", jac_sparsity=P, rtol=1e-9, atol=1e-12)
    ref = solve_ivp(model.rhs, (0.0, 3.0), model.y0, method="BDF", jac=model.jacobian, rtol=1e-9, atol=1e-12)
    assert sol.status == ref.status == 0
    assert np.max(np.abs(sol.y[:, -1] - ref.y[:, -1])) <= 1e-6 * max(1.0, np.max(np.abs(ref.y[:, -1])))

"""Numerics of obslib.pair_form: the bound on grids, the maximising alpha, the Weyl slacks."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import minimize_scalar

import obslib as ob
from obslib import pair_form as pf
from obslib import symbolic as sy
from obslib.studies.pair_closed_form import paper_grid


def test_fine_grid_contains_the_special_points_exactly():
    a, t = pf.fine_grid(5.0, 100, 180)
    assert a.size == 501 and t.size == 721
    assert 1.0 in a
    assert all(x in t for x in (np.pi / 2, -np.pi / 2, 0.0, np.pi, -np.pi))


def test_grid_validation():
    with pytest.raises(ValueError, match="theta_quarter"):
        pf.fine_grid(5.0, 10, 0)
    with pytest.raises(ValueError, match="alpha_per_unit"):
        pf.fine_grid(5.0, 2.5, 10)


def test_bound_surface_is_pair_bound_polar_on_the_mesh():
    a, t = paper_grid()
    Z = pf.bound_surface(a, t, 2.0, 4.0)
    assert Z.shape == (t.size, a.size)
    k, l = 17, 23
    assert Z[k, l] == ob.pair_bound_polar(a[l], t[k], 0.5)
    with pytest.raises(ValueError, match="d_io"):
        pf.bound_surface(a, t, 1.0, 0.0)
    with pytest.raises(ValueError, match="u_max"):
        pf.bound_surface(a, t, -1.0, 1.0)
    with pytest.raises(ValueError, match="1-D"):
        pf.bound_surface(a[:, None], t)


def test_grid_maximum_reports_all_ties():
    a, t = pf.fine_grid(5.0, 20, 30)
    m = pf.grid_maximum(a, t, pf.bound_surface(a, t))
    assert m.value == pytest.approx(1 / np.sqrt(2), abs=1e-12)
    assert m.points == ((1.0, -np.pi / 2), (1.0, np.pi / 2))
    with pytest.raises(ValueError, match="shape"):
        pf.grid_maximum(a, t, np.zeros((2, 2)))


# --- maximising alpha ----------------------------------------------------------------------------
@pytest.mark.parametrize("q", [0.1, 0.5, 1.0, 3.0])
@pytest.mark.parametrize("theta", [0.2, 0.8, 1.3, 2.0, 2.9, -1.0])
def test_maximising_alpha_agrees_with_closed_form_and_brute_force(theta, q):
    num = pf.maximising_alpha(theta, q)
    clo = pf.maximising_alpha_closed(theta, q)
    assert num == pytest.approx(clo, abs=1e-12)
    res = minimize_scalar(lambda x: -ob.pair_bound_polar(x, theta, q), bounds=(0.0, 20.0),
                          method="bounded", options={"xatol": 1e-10})
    assert num == pytest.approx(res.x, abs=1e-5)
    assert num > 1.0


def test_maximising_alpha_is_one_for_stationary_target_and_at_half_pi():
    t = np.linspace(0.1, 3.0, 30)
    assert np.all(pf.maximising_alpha(t, 0.0) == 1.0)
    assert np.allclose(pf.maximising_alpha_closed(t, 0.0), 1.0, atol=1e-15)
    assert pf.maximising_alpha(np.pi / 2, 2.0) == pytest.approx(1.0, abs=1e-12)


def test_maximising_alpha_vectorises_and_validates():
    out = pf.maximising_alpha(np.array([0.5, 1.0]), np.array([1.0, 2.0]))
    assert out.shape == (2,)
    for bad_theta in (0.0, np.pi, -np.pi):
        with pytest.raises(ValueError, match="no maximiser"):
            pf.maximising_alpha(bad_theta, 1.0)
        with pytest.raises(ValueError, match="no maximiser"):
            pf.maximising_alpha_closed(bad_theta, 1.0)
    with pytest.raises(ValueError, match="u_over_d"):
        pf.maximising_alpha(1.0, -1.0)
    with pytest.raises(ValueError, match="finite"):
        pf.maximising_alpha(np.nan, 1.0)


def test_bisection_root_agrees_with_scipy_brentq():
    # an independent root finder on the same equation (Eq. (34)), one theta at a time
    from scipy.optimize import brentq

    rng = np.random.default_rng(6)
    theta, q = rng.uniform(0.01, 3.13, 300), rng.uniform(0.01, 3, 300)
    ours = pf.maximising_alpha(theta, q)
    for t_, q_, a in zip(theta, q, ours):
        g = lambda x: float(pf.stationarity_alpha(x, t_, q_))  # noqa: E731
        if g(1.0) <= 0:
            assert a == 1.0
            continue
        hi = 2.0
        while g(hi) > 0:
            hi *= 2
        assert a == pytest.approx(
            brentq(g, 1.0, hi, xtol=1e-14, rtol=4 * np.finfo(float).eps), abs=3e-14
        )
        assert g(a - 1e-9) > 0 > g(a + 1e-9)


def test_stationarity_alpha_matches_symbolic_and_has_the_sign_of_the_derivative():
    g = sy.lambdify_expr(sy.stationarity_alpha(), sy.RATIO_ARGS)
    rng = np.random.default_rng(4)
    a, t, q = rng.uniform(0.05, 5, 500), rng.uniform(-3, 3, 500), rng.uniform(0, 3, 500)
    np.testing.assert_allclose(pf.stationarity_alpha(a, t, q), g(a, t, q), atol=1e-9)
    theta, qq = 0.9, 1.5
    star = pf.maximising_alpha(theta, qq)
    assert pf.stationarity_alpha(0.5 * star, theta, qq) > 0
    assert pf.stationarity_alpha(1.5 * star, theta, qq) < 0
    with pytest.raises(ValueError, match="non-negative"):
        pf.stationarity_alpha(-1.0, 0.3, 1.0)


# --- Weyl ----------------------------------------------------------------------------------------
entry = st.one_of(st.integers(-3, 3).map(float),
                  st.floats(-1e3, 1e3, allow_nan=False).map(lambda v: v if abs(v) > 1e-6 else 0.0))


@settings(derandomize=True, deadline=None, max_examples=300)
@given(st.lists(entry, min_size=6, max_size=6), st.booleans())
def test_weyl_slacks_are_non_negative(v, psd):
    X = np.array([[v[0], v[1]], [v[1], v[2]]])
    Y = np.array([[v[3], v[4]], [v[4], v[5]]])
    if psd:
        X, Y = X.T @ X, Y.T @ Y
    sl = pf.weyl_2x2_slacks(X, Y)
    scale = np.abs(np.linalg.eigvalsh(X)).max() + np.abs(np.linalg.eigvalsh(Y)).max()
    names = [k for k in sl if k != "ratio"]
    assert len(names) == 6  # the six inequalities of Eq. (18)
    for name in names:
        assert sl[name] >= -1e-12 * scale, name
    if psd and np.linalg.eigvalsh(X)[1] + np.linalg.eigvalsh(Y)[1] > 1e-9 * max(scale, 1e-300):
        assert sl["ratio"] >= -1e-9


def test_weyl_slacks_batch_and_validation():
    X = pf.random_symmetric_2x2(500, 0)
    Y = pf.random_symmetric_2x2(500, 1)
    sl = pf.weyl_2x2_slacks(X, Y)
    assert all(sl[k].shape == (500,) for k in sl)
    assert np.isnan(sl["ratio"]).any()  # not PSD
    P = pf.random_symmetric_2x2(200, 2, psd=True)
    assert (np.linalg.eigvalsh(P)[:, 0] >= -1e-9 * np.abs(P).max()).all()
    with pytest.raises(ValueError, match="symmetric"):
        pf.weyl_2x2_slacks(np.array([[1.0, 2.0], [0.0, 1.0]]), np.eye(2))
    with pytest.raises(ValueError, match="shape"):
        pf.weyl_2x2_slacks(np.eye(2), np.eye(3))
    with pytest.raises(ValueError, match="finite"):
        pf.weyl_2x2_slacks(np.full((2, 2), np.nan), np.eye(2))


def test_dbound_dalpha_equals_differences_and_sympy():
    exact = sy.lambdify_expr(sy.dbound_dalpha_closed(), sy.RATIO_ARGS)
    rng = np.random.default_rng(2)
    a, t, q = rng.uniform(0.05, 4, 200), rng.uniform(0.05, 3.1, 200), rng.uniform(0, 3, 200)
    d = pf.dbound_dalpha(a, t, q)
    h = 1e-6
    fd = (ob.pair_bound_polar(a + h, t, q) - ob.pair_bound_polar(a - h, t, q)) / (2 * h)
    np.testing.assert_allclose(d, fd, atol=1e-7)
    np.testing.assert_allclose(d, exact(a, t, q), rtol=1e-9, atol=1e-12)
    # at alpha = 0 the slope from the right, |sin theta| / sqrt(1 + q^2)
    np.testing.assert_allclose(pf.dbound_dalpha(0.0, t, q), np.abs(np.sin(t)) / np.sqrt(1 + q * q),
                               rtol=1e-14)
    with pytest.raises(ValueError, match="non-negative"):
        pf.dbound_dalpha(-1.0, 0.5, 1.0)
    with pytest.raises(ValueError, match="finite"):
        pf.dbound_dalpha(1.0, np.nan, 1.0)

"""Theorem 1's bound and Theorem 4's closed form, each against an independent computation."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from strategies import scenes

import obslib as ob
from obslib._validate import check_scene_batch
from obslib.bounds import lower_bounds, worst_case_controls
from obslib.observability import relative_rows
from obslib.scenes import SCENE_KINDS, random_scene_batch, random_scenes


def svd_bound(rows, u_max):
    """Theorem 1 straight from numpy's SVD of the rows o - p_i (Eq. (21))."""
    sv = np.linalg.svd(np.asarray(rows, dtype=float), compute_uv=False)
    return sv[-1] / np.sqrt(sv[0] ** 2 + u_max**2)


@pytest.mark.parametrize("kind", SCENE_KINDS)
def test_closed_form_equals_svd_on_thousands_of_scenes(kind):
    """pair_bounds (Gram-matrix closed form) vs SVD, every pair, 1000 scenes per kind, 1e-3..1e4."""
    worst = 0.0
    for sc in random_scenes(1000, seed=11, n_sensors=(2, 5), kinds=(kind,)):
        W = ob.pair_bounds(sc.sensors, sc.target[None], sc.u_max)[:, :, 0]
        n = len(sc.sensors)
        for i in range(n):
            for j in range(i + 1, n):
                ref = svd_bound(sc.target - sc.sensors[[i, j]], sc.u_max)
                worst = max(worst, abs(W[i, j] - ref))
    assert worst < 1e-10


def test_closed_form_is_accurate_for_nearly_parallel_sensors():
    """Sensors at angle 1e-7 rad apart: the bound is ~5e-8 and must keep its relative accuracy."""
    o = np.zeros(2)
    eps = 1e-7
    s = np.array([[1.0, 0.0], [2.0 * np.cos(eps), 2.0 * np.sin(eps)]])
    W = ob.pair_bounds(s, o[None], 0.0)[0, 1, 0]
    # exact value from Theorem 4 with alpha = 2, theta = eps, u = 0, in extended precision
    import mpmath as mp

    mp.mp.dps = 50
    a, th = mp.mpf(2), mp.mpf(eps)
    root = mp.sqrt(1 + a**4 + 2 * a**2 * mp.cos(2 * th))
    exact = mp.sqrt((1 + a**2 - root) / (1 + a**2 + root))
    assert W == pytest.approx(float(exact), rel=1e-8)


def test_polar_form_equals_cartesian_form():
    rng = np.random.default_rng(5)
    for _ in range(2000):
        s = rng.uniform(-10, 10, size=(2, 2))
        o = rng.uniform(-10, 10, size=2)
        u = rng.uniform(0, 5)
        vi, vj = s[0] - o, s[1] - o
        di, dj = np.linalg.norm(vi), np.linalg.norm(vj)
        theta = np.arctan2(vj[1], vj[0]) - np.arctan2(vi[1], vi[0])
        polar = ob.pair_bound_polar(dj / di, theta, u / di)
        assert polar == pytest.approx(svd_bound([o - s[0], o - s[1]], u), abs=1e-12)


def test_polar_maximum_is_theorem5_value():
    q = np.linspace(0, 3, 7)
    np.testing.assert_allclose(ob.pair_bound_polar(1.0, np.pi / 2, q), np.sqrt(1 / (1 + q**2)))
    np.testing.assert_allclose(ob.pair_bound_polar(1.0, -np.pi / 2, q), np.sqrt(1 / (1 + q**2)))
    assert ob.pair_bound_polar(2.0, 0.0, 0.3) == 0.0
    assert ob.pair_bound_polar(0.0, 1.0, 0.3) == 0.0


@given(scenes(), st.floats(0, 1), st.floats(0, 2 * np.pi))
def test_bound_never_exceeds_exact_inside_the_disc(scene, frac, phi):
    sensors, target, u_max = scene
    u = frac * u_max * np.array([np.cos(phi), np.sin(phi)])
    exact = ob.inverse_condition_number(sensors, target, u)
    assert ob.lower_bound(sensors, target, u_max) <= exact + 1e-12


@given(scenes(min_sensors=1, max_sensors=1))
def test_single_sensor_bound_is_zero(scene):
    sensors, target, u_max = scene
    assert ob.lower_bound(sensors, target, u_max) == 0.0
    assert ob.pair_bounds(sensors, target[None], u_max).shape == (1, 1, 1)
    assert ob.pair_bounds(sensors, target[None], u_max)[0, 0, 0] == 0.0


@given(scenes(), st.floats(0, 2 * np.pi), st.tuples(st.floats(-1, 1), st.floats(-1, 1)))
def test_invariant_under_rotation_and_translation(scene, angle, shift):
    sensors, target, u_max = scene
    scale = np.abs(np.vstack([sensors, target])).max()
    R = np.array([[np.cos(angle), -np.sin(angle)], [np.sin(angle), np.cos(angle)]])
    t = scale * np.array(shift)
    moved_s, moved_o = sensors @ R.T + t, R @ target + t
    a = ob.pair_bounds(sensors, target[None], u_max)
    b = ob.pair_bounds(moved_s, moved_o[None], u_max)
    np.testing.assert_allclose(a, b, rtol=0, atol=1e-9)
    assert ob.lower_bound(sensors, target, u_max) == pytest.approx(
        ob.lower_bound(moved_s, moved_o, u_max), abs=1e-9
    )


@given(scenes(max_sensors=7))
def test_pair_bounds_symmetric_zero_diagonal_and_equal_to_lower_bound(scene):
    sensors, target, u_max = scene
    targets = np.vstack([target, target[::-1] + 0.5])
    if np.linalg.norm(targets[1] - sensors, axis=1).min() == 0:
        targets = targets[:1]
    W = ob.pair_bounds(sensors, targets, u_max)
    n, L = len(sensors), len(targets)
    assert W.shape == (n, n, L)
    # exact: W[i, j] and W[j, i] come from the same elementwise ufunc calls with the roles
    # swapped (products and sums commute exactly in IEEE arithmetic; no BLAS is involved)
    assert np.array_equal(W, W.transpose(1, 0, 2))
    assert np.all(W[np.arange(n), np.arange(n)] == 0)
    for l in range(L):
        for i in range(n):
            for j in range(i + 1, n):
                assert W[i, j, l] == pytest.approx(
                    ob.lower_bound(sensors[[i, j]], targets[l], u_max), abs=1e-10
                )


def test_u_max_per_target():
    rng = np.random.default_rng(1)
    s = rng.uniform(0, 10, size=(5, 2))
    t = rng.uniform(0, 10, size=(3, 2))
    u = np.array([0.0, 1.0, 4.0])
    W = ob.pair_bounds(s, t, u)
    for l in range(3):
        # elementwise arithmetic only (no BLAS); the per-target norms come from einsum, whose
        # loop may differ with the array's shape, so allow a few ulps of values in [0, 1]
        np.testing.assert_allclose(W[:, :, l], ob.pair_bounds(s, t[[l]], u[l])[:, :, 0],
                                   rtol=0, atol=4 * np.finfo(float).eps)


def test_mahalanobis_identity_covariance_is_euclidean():
    rng = np.random.default_rng(2)
    s = rng.uniform(0, 10, size=(6, 2))
    t = rng.uniform(0, 10, size=(4, 2))
    np.testing.assert_allclose(
        ob.pair_bounds(s, t, 1.0, cov=np.eye(2)), ob.pair_bounds(s, t, 1.0), atol=1e-14
    )


def test_mahalanobis_isotropic_covariance_rescales_speed():
    """cov = c I divides every distance by sqrt(c): alpha and theta unchanged, u/d times sqrt(c)."""
    rng = np.random.default_rng(4)
    s = rng.uniform(0, 10, size=(6, 2))
    t = rng.uniform(0, 10, size=(2, 2))
    c = 0.3
    np.testing.assert_allclose(
        ob.pair_bounds(s, t, 2.0, cov=c * np.eye(2)),
        ob.pair_bounds(s, t, 2.0 * np.sqrt(c)),
        atol=1e-13,
    )


def test_mahalanobis_matches_experiments_definition():
    """The experiments' evaluation: Theorem 4's form with Mahalanobis d_i, d_j and the Euclidean
    angle theta."""
    rng = np.random.default_rng(6)
    for _ in range(300):
        s = rng.uniform(-5, 5, size=(2, 2))
        xhat = rng.uniform(-5, 5, size=2)
        A = rng.normal(size=(2, 2))
        cov = A @ A.T + 0.1 * np.eye(2)
        u = rng.uniform(0, 3)
        vi, vj = s[0] - xhat, s[1] - xhat
        prec = np.linalg.inv(cov)
        di, dj = np.sqrt(vi @ prec @ vi), np.sqrt(vj @ prec @ vj)
        cos_t = vi @ vj / (np.linalg.norm(vi) * np.linalg.norm(vj))
        theta = np.arccos(np.clip(cos_t, -1, 1))
        expected = ob.pair_bound_polar(dj / di, theta, u / di)
        got = ob.pair_bounds(s, xhat[None], u, cov=cov)[0, 1, 0]
        assert got == pytest.approx(expected, abs=1e-9)


@given(scenes())
def test_worst_case_control_attains_the_bound(scene):
    sensors, target, u_max = scene
    u = ob.worst_case_control(sensors, target, u_max)
    assert np.linalg.norm(u) == pytest.approx(u_max, rel=1e-12)
    exact = ob.inverse_condition_number(sensors, target, u)
    assert exact == pytest.approx(ob.lower_bound(sensors, target, u_max), abs=1e-10)


def test_fewer_than_two_sensors_give_zero():
    assert ob.lower_bound(np.zeros((0, 2)), [1.0, 1.0], 1.0) == 0.0
    assert ob.lower_bound([[0.0, 0.0]], [1.0, 1.0], 1.0) == 0.0
    assert ob.pair_bounds(np.zeros((0, 2)), [[1.0, 1.0]], 1.0).shape == (0, 0, 1)


def test_stationary_target_bound_is_exact():
    """Remark 1: with u_max = 0 the bound is C^-1(O(o))."""
    rng = np.random.default_rng(8)
    for _ in range(200):
        s = rng.uniform(-5, 5, size=(rng.integers(2, 6), 2))
        o = rng.uniform(-5, 5, size=2)
        assert ob.lower_bound(s, o, 0.0) == pytest.approx(
            ob.inverse_condition_number(s, o, [0, 0]), abs=1e-14
        )


# --------------------------------------------------------------------------- batched forms and
# audits


def test_scene_batch_is_seeded_legal_and_of_every_kind():
    a, b = random_scene_batch(300, 8), random_scene_batch(300, 8)
    assert np.array_equal(a.sensors, b.sensors, equal_nan=True) and np.array_equal(a.u_max, b.u_max)
    assert a.kinds == tuple(SCENE_KINDS[k % 4] for k in range(300))
    assert a.counts.min() == 2 and a.counts.max() == 6
    assert np.isnan(a.sensors[~a.valid]).all() and (a.rows[~a.valid] == 0).all()
    for k in range(300):
        sc = a.scene(k)
        rows = relative_rows(sc.sensors, sc.target)  # distinct, none on the target
        assert np.array_equal(rows, a.rows[k, : a.counts[k]])
        cross = rows[:, 0, None] * rows[None, :, 1] - rows[:, 1, None] * rows[None, :, 0]
        rel = np.abs(cross).max() / (rows**2).sum(axis=1).max()
        if sc.kind == "collinear":
            assert rel < 1e-14
        elif sc.kind == "near-parallel":
            assert rel < 1e-7
    one = random_scene_batch(50, 1, n_sensors=(1, 1), kinds=("spread",))
    assert (one.counts == 1).all() and set(one.kinds) == {"spread"}


def test_check_scene_batch_names_the_offending_scene():
    b = random_scene_batch(6, 2, n_sensors=(3, 3))
    s = b.sensors.copy()
    s[4, 2] = s[4, 0]
    with pytest.raises(ValueError, match="scene 4: sensors 0 and 2 coincide"):
        check_scene_batch(s, b.targets, b.counts)
    s = b.sensors.copy()
    s[1, 1] = b.targets[1]
    with pytest.raises(ValueError, match="scene 1: sensor 1 is on the target"):
        check_scene_batch(s, b.targets, b.counts)
    s = b.sensors.copy()
    s[3, 0, 1] = np.inf
    with pytest.raises(ValueError, match="scene 3 has a non-finite"):
        check_scene_batch(s, b.targets, b.counts)
    with pytest.raises(ValueError, match="kind"):
        random_scene_batch(5, 0, kinds=("round",))


def test_batched_bound_and_worst_case_control_equal_the_per_scene_functions():
    batch = random_scene_batch(600, 6)
    bounds = lower_bounds(batch.rows, batch.u_max)
    controls = worst_case_controls(batch.rows, batch.u_max)
    for k in range(600):
        sc = batch.scene(k)
        assert bounds[k] == pytest.approx(
            ob.lower_bound(sc.sensors, sc.target, sc.u_max), rel=1e-12, abs=1e-14
        )
        np.testing.assert_allclose(
            controls[k],
            ob.worst_case_control(sc.sensors, sc.target, sc.u_max),
            rtol=0,
            atol=1e-12 * sc.u_max,
        )
    assert lower_bounds(batch.rows[:, :1], batch.u_max).max() == 0.0  # one sensor: Theorem 2
    with pytest.raises(ValueError, match="u_max"):
        lower_bounds(batch.rows, -1.0)

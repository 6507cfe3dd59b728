"""One run of Section V (tracking.simulate, the engine's pass of one run): the EKF step, noise
replay, named errors."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from obslib import tracking as tr
from obslib._validate import ArgumentTypeError

from .filterpy_reference import simulate as filterpy_simulate

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


def test_first_step_logs_prior_values(runs):
    for s in tr.STRATEGIES:
        r = runs[(s, "mahalanobis")]
        assert r.error[0] == pytest.approx(np.sqrt(0.5), abs=1e-15)  # (5.5, 3.5) vs (5, 3)
        assert r.trace_cov[0] == pytest.approx(1.0, abs=1e-15)
        np.testing.assert_array_equal(r.truth[0], [5.0, 3.0])
        np.testing.assert_array_equal(r.estimate[0], [5.5, 3.5])


def hand_ekf_step(x, P, sensors, pair, o, noise, Q, R):
    """One EKF step written out: random-walk predict, half-squared-range update, Joseph form."""
    Pp = P + Q
    p = sensors[list(pair)]
    H = np.array([x - p[0], x - p[1]])  # Jacobian rows (xhat - p_i)^T
    z = np.array([0.5 * np.sum((p[0] - o) ** 2), 0.5 * np.sum((p[1] - o) ** 2)]) + noise
    h = np.array([0.5 * np.sum((p[0] - x) ** 2), 0.5 * np.sum((p[1] - x) ** 2)])
    S = H @ Pp @ H.T + R
    K = Pp @ H.T @ np.linalg.inv(S)
    x_new = x + K @ (z - h)
    A = np.eye(2) - K @ H
    P_new = A @ Pp @ A.T + K @ R @ K.T
    return x_new, P_new


@pytest.mark.parametrize("strategy", tr.STRATEGIES)
def test_one_filter_step_matches_hand_derived_update(strategy):
    setup = CIRCLE.replace(steps=3)
    noise = np.random.default_rng(7).normal(0, 0.5, (3, 6))
    r = tr.simulate(setup, strategy, noise=noise)
    s = setup.sensor_array
    Q, R = np.array(setup.Q), np.array(setup.R)
    for k in range(2):
        x_new, P_new = hand_ekf_step(
            r.estimate[k], r.cov[k], s, r.pairs[k], r.truth[k], noise[k, r.pairs[k]], Q, R
        )
        np.testing.assert_allclose(r.estimate[k + 1], x_new, rtol=0, atol=1e-13)
        np.testing.assert_allclose(r.cov[k + 1], P_new, rtol=0, atol=1e-14)


def test_filterpy_update_is_joseph_form():
    """filterpy 2.0.0's EKF update is P = (I-KH) P (I-KH)^T + K R K^T (Joseph form).

    For the optimal gain the Joseph and the simple form (I-KH) P agree analytically; they part in
    floating point when the measurement is far more precise than the prior (here R = 1e-6 I
    against P ~ 1e6). There the simple form is off by ~1e-4 relative and loses symmetry, while
    filterpy's P equals the Joseph expression to rounding.
    """
    from filterpy.kalman import ExtendedKalmanFilter

    ekf = ExtendedKalmanFilter(2, 2)
    ekf.x = np.array([[0.3], [0.4]])
    P = np.array([[1e6, 3e5], [3e5, 2e5]])
    ekf.P = P.copy()
    ps = np.array([[2.0, 0.0], [0.0, 3.0]])
    R = 1e-6 * np.eye(2)
    H = tr.range_jacobian(ekf.x, ps)
    K = P @ H.T @ np.linalg.inv(H @ P @ H.T + R)
    A = np.eye(2) - K @ H
    joseph = A @ P @ A.T + K @ R @ K.T
    simple = A @ P
    ekf.update(np.array([[1.0], [2.0]]), tr.range_jacobian, tr.half_squared_range, R=R,
               args=(ps,), hx_args=(ps,))
    scale = np.abs(joseph).max()
    assert np.abs(ekf.P - joseph).max() < 1e-9 * scale
    assert np.abs(ekf.P - simple).max() > 1e-7 * scale
    np.testing.assert_allclose(ekf.K, K, rtol=1e-9)


def assert_same_run(a, b):
    for name in ("pairs", "bound", "error", "trace_cov", "truth", "estimate", "cov"):
        np.testing.assert_array_equal(getattr(a, name), getattr(b, name), err_msg=name)


@pytest.mark.parametrize("setup", [CIRCLE, ADV], ids=["circle", "adversarial"])
def test_same_noise_table_gives_identical_runs(setup):
    table = tr.noise_table(setup, 11)
    a = tr.simulate(setup, "best-pair", noise=table)
    b = tr.simulate(setup, "best-pair", noise=table.copy())
    c = tr.simulate(setup, "best-pair", seed=11)
    assert_same_run(a, b)
    assert_same_run(a, c)
    assert a.seed is None and c.seed == 11


def test_noise_is_common_to_strategies(runs):
    tables = [runs[(s, "mahalanobis")].noise for s in tr.STRATEGIES]
    for t in tables[1:]:
        np.testing.assert_array_equal(t, tables[0])
    assert tables[0].shape == (315, 6)
    np.testing.assert_array_equal(tables[0], np.random.default_rng(0).normal(0, 0.5, (315, 6)))


def test_noise_entry_is_keyed_by_step_and_sensor():
    """Changing the noise of a sensor the run never uses at a step leaves the run unchanged."""
    setup = CIRCLE.replace(steps=30)
    table = tr.noise_table(setup, 3)
    r = tr.simulate(setup, "fixed-pair", noise=table)
    t2 = table.copy()
    t2[:, [2, 3, 4, 5]] += 10.0  # sensors outside the fixed pair (s1, s2)
    assert_same_run(r, tr.simulate(setup, "fixed-pair", noise=t2))
    t3 = table.copy()
    t3[10, 0] += 1.0  # s1 at step 11
    r3 = tr.simulate(setup, "fixed-pair", noise=t3)
    np.testing.assert_array_equal(r3.estimate[:11], r.estimate[:11])
    assert not np.array_equal(r3.estimate[11], r.estimate[11])


def test_published_ordering_of_mean_trace_at_default_seed(runs):
    """Strategy 1 < 2 < 3 in mean trace(Sigma), as in the published run (0.073 / 0.140 / 0.217).

    What we find at seed 0: 0.0753 < 0.1376 < 0.2100 (asserted as found, not tuned)."""
    t = [runs[(s, "mahalanobis")].trace_cov.mean() for s in tr.STRATEGIES]
    assert t[0] < t[1] < t[2]
    assert runs[("best-pair", "mahalanobis")].switches == 148  # published: 148


def test_never_the_same_sensor_twice(runs):
    adv = tr.simulate(ADV, "best-pair")
    for r in list(runs.values()) + [adv]:
        assert (r.pairs[:, 0] < r.pairs[:, 1]).all()
        assert r.pairs.min() >= 0 and r.pairs.max() < r.setup.n_sensors
    assert (runs[("best-partner", "mahalanobis")].pairs == 1).any(axis=1).all()  # s2 always in
    assert (runs[("fixed-pair", "mahalanobis")].pairs == [0, 1]).all()


@settings(max_examples=15, deadline=None)
@given(
    seed=st.integers(0, 2**32 - 1),
    strategy=st.sampled_from(tr.STRATEGIES),
    metric=st.sampled_from(tr.METRICS),
    u_max=st.floats(0.0, 5.0),
)
def test_runs_stay_well_formed(seed, strategy, metric, u_max):
    setup = CIRCLE.replace(steps=25, metric=metric, u_max=u_max)
    r = tr.simulate(setup, strategy, seed=seed)
    assert np.isfinite(r.estimate).all() and np.isfinite(r.cov).all()
    assert ((0 <= r.bound) & (r.bound <= 1)).all()
    assert (r.trace_cov > 0).all()
    assert (np.linalg.eigvalsh(r.cov) > 0).all()
    assert (r.pairs[:, 0] != r.pairs[:, 1]).all()


def test_bad_run_arguments_raise():
    with pytest.raises(ValueError, match="unknown strategy"):
        tr.simulate(CIRCLE, "random-pair")
    with pytest.raises(ValueError, match="shape"):
        tr.simulate(CIRCLE, "best-pair", noise=np.zeros((10, 6)))
    bad = np.zeros((315, 6))
    bad[4, 2] = np.nan
    with pytest.raises(ValueError, match="sensor 2 at step 5"):
        tr.simulate(CIRCLE, "best-pair", noise=bad)
    with pytest.raises(ValueError, match="TrackingSetup"):
        tr.simulate({"steps": 3}, "best-pair")
    with pytest.raises(ValueError, match="either seeds or noise"):
        tr.simulate_batch(CIRCLE, "best-pair")
    with pytest.raises(ValueError, match="n_seeds"):
        tr.monte_carlo(CIRCLE, 0)


# --------------------------------------------------------------------------------------------
# Inputs at the edge: named errors, or a correct run
# --------------------------------------------------------------------------------------------


def test_seed_and_strategy_of_the_wrong_kind_raise():
    with pytest.raises(ArgumentTypeError, match="seed must be an integer, got None"):
        tr.simulate(CIRCLE, "best-pair", seed=None)
    with pytest.raises(ArgumentTypeError, match="seed must be an integer, got True"):
        tr.simulate(CIRCLE, "best-pair", seed=True)
    with pytest.raises(ArgumentTypeError, match="strategy must be a string"):
        tr.simulate(CIRCLE, 3)


@pytest.mark.parametrize("engine", ["simulate", "batch"])
def test_an_estimate_far_from_the_target_gives_a_named_error(engine):
    """At 1e10 from the sensors the two Jacobian rows are parallel to rounding and the
    innovation covariance is singular (filterpy raises LinAlgError from inside its update)."""
    setup = CIRCLE.replace(estimate0=(1e10, 7e9), steps=20)
    with pytest.raises(ValueError, match="innovation covariance H P H\\^T \\+ R is singular"):
        if engine == "simulate":
            tr.simulate(setup, "best-pair")
        else:
            tr.simulate_batch(setup, "best-pair", seeds=[0])


def test_a_far_but_representable_estimate_still_runs():
    setup = CIRCLE.replace(estimate0=(1e3, 7e2), steps=40)
    r = tr.simulate(setup, "best-pair")
    ref = filterpy_simulate(setup, "best-pair")
    assert np.isfinite(r.estimate).all()
    np.testing.assert_array_equal(ref["pairs"], r.pairs)


def test_a_tiny_initial_covariance_runs_with_the_right_first_pick():
    """cov0 of scale 1e-170 (determinant underflows): the first pick and bound equal the
    Mahalanobis bound evaluated with numpy.linalg.inv, and the engine agrees with filterpy."""
    from obslib import pair_bound_polar

    c = 1e-170 * np.array([[2.0, 0.5], [0.5, 1.0]])
    setup = CIRCLE.replace(cov0=c, steps=6)
    r = tr.simulate(setup, "best-pair")
    b = filterpy_simulate(setup, "best-pair")
    s, x = setup.sensor_array, np.array(setup.estimate0)
    prec = np.linalg.inv(c)
    vals = {}
    for i in range(6):
        for j in range(i + 1, 6):
            vi, vj = s[i] - x, s[j] - x
            di, dj = np.sqrt(vi @ prec @ vi), np.sqrt(vj @ prec @ vj)
            theta = np.arccos(np.clip(vi @ vj / np.hypot(*vi) / np.hypot(*vj), -1, 1))
            vals[(i, j)] = pair_bound_polar(dj / di, theta, setup.u_max / di)
    best = max(vals, key=vals.get)
    assert tuple(r.pairs[0]) == best
    assert r.bound[0] == pytest.approx(vals[best], rel=1e-9)
    np.testing.assert_array_equal(b["pairs"], r.pairs)
    assert np.isfinite(r.estimate).all() and np.isfinite(b["estimate"]).all()

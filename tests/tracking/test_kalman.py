"""The extended Kalman filter (obslib.tracking.kalman) against filterpy's ExtendedKalmanFilter,
one filter at a time, for both measurement models and any number of sensors, and its test of a
singular innovation covariance."""

from __future__ import annotations

import numpy as np
import pytest
from filterpy.kalman import ExtendedKalmanFilter

from obslib import tracking as tr
from obslib.tracking import kalman

MODELS = {"half-squared-range": (tr.range_jacobian, tr.half_squared_range),
          "range": (tr.euclidean_range_jacobian, tr.euclidean_range)}


def _spd(rng, shape, scale=1.0):
    A = rng.normal(size=shape + (2, 2))
    return scale * (A @ np.swapaxes(A, -1, -2) + 0.2 * np.eye(2))


def _filterpy(x, P, Q, R, m):
    f = ExtendedKalmanFilter(dim_x=2, dim_z=m)
    f.x, f.P, f.F, f.Q, f.R = x[:, None].copy(), P.copy(), np.eye(2), Q, R
    return f


@pytest.mark.parametrize("diagonal", [True, False])
def test_batched_pair_steps_equal_filterpy_on_random_problems(diagonal):
    """Random states, covariances, pairs and measurements, B filters over several steps, with
    diagonal noise matrices (the zero entries skipped) and full ones: the engine's closed form
    of two half squared ranges (``predict_entries``, ``update_pair_entries`` on component
    arrays) and the public
    ``predict``/``update``. filterpy computes K = P H^T inv(S) with matrix products; the closed
    form writes the 2 x 2 products out, so the two agree to rounding (1e-9 relative: the
    covariances shrink by up to 1e4 over the steps)."""
    rng = np.random.default_rng(1 if diagonal else 2)
    B = 40
    x = rng.uniform(0, 10, size=(B, 2))
    P = _spd(rng, (B,))
    Q = np.diag([0.3, 0.1]) if diagonal else _spd(rng, (), 0.2)
    R = np.diag([0.25, 0.5]) if diagonal else _spd(rng, (), 0.3)
    filters = [_filterpy(x[b], P[b], Q, R, 2) for b in range(B)]
    state = (x[:, 0], x[:, 1])
    cov = (P[:, 0, 0], P[:, 0, 1], P[:, 1, 0], P[:, 1, 1])
    xm, Pm = x.copy(), P.copy()
    for _ in range(6):
        ps = rng.uniform(-5, 15, size=(B, 2, 2))
        z = rng.normal(20, 5, size=(B, 2))
        cov = kalman.predict_entries(cov, Q.tolist())
        state, cov = kalman.update_pair_entries(state, cov, (ps[:, 0, 0], ps[:, 0, 1]),
                                    (ps[:, 1, 0], ps[:, 1, 1]), (z[:, 0], z[:, 1]), R.tolist())
        xm, Pm = kalman.update(xm, kalman.predict(Pm, Q), ps, z, R)
        for b, f in enumerate(filters):
            f.predict()
            f.update(z[b][:, None], tr.range_jacobian, tr.half_squared_range, args=(ps[b],),
                     hx_args=(ps[b],))
            got_P = np.array([[cov[0][b], cov[1][b]], [cov[2][b], cov[3][b]]])
            tol = 1e-9 * np.abs(f.P).max()
            np.testing.assert_allclose([state[0][b], state[1][b]], f.x[:, 0], rtol=1e-9,
                                       atol=1e-9)
            np.testing.assert_allclose(got_P, f.P, rtol=1e-9, atol=tol)
            np.testing.assert_allclose(xm[b], f.x[:, 0], rtol=1e-9, atol=1e-9)
            np.testing.assert_allclose(Pm[b], f.P, rtol=1e-9, atol=tol)


@pytest.mark.parametrize("measurement", kalman.MEASUREMENTS)
@pytest.mark.parametrize("m", [1, 2, 3, 5, 12])
def test_teams_of_any_size_equal_filterpy(measurement, m):
    """m sensors per filter, either measurement model: the stacked update the engine uses for
    teams (``update_stacked``, through the public ``update``; the gain in its information form
    for m = 12) against filterpy over several steps, to 1e-9 relative."""
    rng = np.random.default_rng(10 * m + len(measurement))
    B = 12
    x = rng.uniform(0, 10, size=(B, 2))
    P = _spd(rng, (B,))
    Q, r = 0.2 * np.eye(2), 0.04
    jac, hx = MODELS[measurement]
    filters = [_filterpy(x[b], P[b], Q, r * np.eye(m), m) for b in range(B)]
    for _ in range(5):
        ps = rng.uniform(-5, 15, size=(B, m, 2))
        z = hx(rng.uniform(0, 10, size=(B, 2)), ps) + rng.normal(0, 0.2, size=(B, m))
        x, P = kalman.update(x, kalman.predict(P, Q), ps, z, r, measurement=measurement)
        for b, f in enumerate(filters):
            f.predict()
            f.update(z[b][:, None], jac, hx, args=(ps[b],), hx_args=(ps[b],))
            np.testing.assert_allclose(x[b], f.x[:, 0], rtol=1e-9, atol=1e-9)
            np.testing.assert_allclose(P[b], f.P, rtol=1e-9, atol=1e-9 * np.abs(f.P).max())


def test_a_singular_innovation_is_reported_per_filter():
    """Two sensors on one line through the estimate give parallel Jacobian rows: with R = 0,
    S = H P H^T has rank 1. The other filters' updates are regular."""
    x = (np.array([0.0, 0.0]), np.array([0.0, 0.0]))
    P = (np.ones(2), np.zeros(2), np.zeros(2), np.ones(2))
    s0 = (np.array([1.0, 1.0]), np.array([0.0, 0.0]))
    s1 = (np.array([2.0, 0.0]), np.array([0.0, 2.0]))  # filter 0: collinear; filter 1: not
    with pytest.raises(kalman.SingularInnovation) as err:
        kalman.update_pair_entries(x, P, s0, s1, (np.ones(2), np.ones(2)), [[0.0, 0.0], [0.0, 0.0]])
    assert err.value.ok.tolist() == [False, True]
    assert isinstance(err.value, ValueError)
    ps = np.array([[[1.0, 0.0], [2.0, 0.0]], [[1.0, 0.0], [0.0, 2.0]]])
    with pytest.raises(kalman.SingularInnovation) as err:
        kalman.update(np.zeros((2, 2)), np.eye(2), ps, np.ones((2, 2)), 0.0, "range")
    assert err.value.ok.tolist() == [False, True]


def test_bad_filter_arguments_are_named():
    with pytest.raises(ValueError, match="P must have shape"):
        kalman.predict([1.0, 2.0], 0.1)
    with pytest.raises(ValueError, match="Q must be symmetric"):
        kalman.predict(np.eye(2), [[1.0, 0.5], [0.0, 1.0]])
    with pytest.raises(ValueError, match="z must have shape"):
        kalman.update([0.0, 0.0], np.eye(2), [[1.0, 0.0], [0.0, 1.0]], [1.0], 1.0)
    with pytest.raises(ValueError, match="unknown measurement"):
        kalman.update([0.0, 0.0], np.eye(2), [[1.0, 0.0]], [1.0], 1.0, "bearing")
    with pytest.raises(ValueError, match="sensor sits on an estimate"):
        kalman.update([1.0, 0.0], np.eye(2), [[1.0, 0.0]], [1.0], 1.0, "range")


def test_the_assignment_study_names_a_singular_update():
    """Initial estimates some 1e8 away from the sensors (p0 = 1e17): the two rows are parallel
    to about 1e-7, so S is singular to the engine's precision, and the error says where."""
    from obslib.studies import assignment_tracking as at

    setup = at.AssignmentTrackingSetup(n_targets=2, steps=2, p0=1e17)
    with pytest.raises(ValueError, match=r"update at step 1 of run 0 \(target \d\) failed"):
        at.run(setup, "random", [0])

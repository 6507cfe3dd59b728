"""The measurement model (obslib.tracking.model) against finite differences, pair_bounds and
the exact C^-1."""

from __future__ import annotations

import numpy as np
import pytest

import obslib as ob
from obslib import tracking as tr
from obslib.bound_checks import disc_controls

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


def test_measurement_function_and_jacobian():
    ps = np.array([[1.0, 2.0], [-3.0, 0.5]])
    x = np.array([0.2, -0.4])
    h = tr.half_squared_range(x, ps)
    J = tr.range_jacobian(x, ps)
    eps = 1e-6
    num = np.column_stack([
        (tr.half_squared_range(x + eps * e, ps) - tr.half_squared_range(x - eps * e, ps))
        / (2 * eps)
        for e in np.eye(2)
    ])
    np.testing.assert_allclose(J, num, atol=1e-8)
    np.testing.assert_allclose(h, 0.5 * ((ps - x) ** 2).sum(1))
    np.testing.assert_allclose(tr.half_squared_range(x.reshape(2, 1), ps)[:, 0], h)


def test_pair_bound_series_equals_pair_bounds(random_states):
    rng = np.random.default_rng(5)
    x, cov = random_states(rng, 50)
    pairs = np.array([sorted(rng.choice(6, 2, replace=False)) for _ in range(50)])
    s = CIRCLE.sensor_array
    for c in (None, cov):
        W = ob.pair_bounds(s, x, CIRCLE.u_max, cov=c)
        want = W[pairs[:, 0], pairs[:, 1], np.arange(50)]
        got = tr.pair_bound_series(CIRCLE, x, pairs, cov=c)
        np.testing.assert_allclose(got, want, rtol=1e-14, atol=0)
    with pytest.raises(ValueError, match="pairs must be"):
        tr.pair_bound_series(CIRCLE, x, pairs[:-1])


def test_target_objective_is_exact_inverse_condition_number():
    ps = np.array([[0.0, 0.0], [4.0, 0.0]])
    o = np.array([2.0, 2.0])
    ctrl = disc_controls(0.5, 3, 12)
    got = tr.target_objective(ps, o, ctrl)
    want = [ob.inverse_condition_number(ps, o + u, u) for u in ctrl]
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-15)

"""The independent reference the tracking engine is held to: runs written step by step with
filterpy's ``ExtendedKalmanFilter`` (one filter per target) and the library's public choosers,
one run at a time, as plainly as possible."""

from __future__ import annotations

import numpy as np
from filterpy.kalman import ExtendedKalmanFilter

from obslib import tracking as tr
from obslib.tracking.choosers import pair_draws
from obslib.tracking.model import pair_index


def _filter(x0, P0, Q, R):
    ekf = ExtendedKalmanFilter(dim_x=2, dim_z=2)
    ekf.x = np.array(x0, dtype=float).reshape(2, 1)
    ekf.P = np.array(P0, dtype=float)
    ekf.F = np.eye(2)
    ekf.Q = np.array(Q, dtype=float)
    ekf.R = np.array(R, dtype=float)
    return ekf


def simulate(setup, strategy, noise=None, seed=0):
    """One Section V run (the fields of ``TrackingResult`` it logs, as a dict): filterpy's EKF,
    the pairs of ``tracking.choose_pairs`` (``pair_draws`` for ``"random"``), the adversary's
    control the first ``argmin`` of ``tracking.target_objective`` over its whole set."""
    table = tr.noise_table(setup, seed) if noise is None else np.asarray(noise, dtype=float)
    s = setup.sensor_array
    steps = setup.steps
    ekf = _filter(setup.estimate0, setup.cov0, setup.Q, setup.R)
    circle = setup.motion == "circle"
    truth = np.empty((steps + 1, 2))
    if circle:
        truth[:] = tr.circle_truth(setup)
    else:
        truth[0] = setup.start
        controls = setup.control_array
    ii, jj = pair_index(setup.n_sensors)
    draws = pair_draws(seed, steps, ii.size) if strategy == "random" else None
    oracle = strategy == "exact-icn"

    def choose(k, control=None):
        x, P = ekf.x[:, 0].copy(), ekf.P.copy()
        if draws is not None:
            pair = np.array([ii[draws[k]], jj[draws[k]]])
            cov = P[None] if setup.metric == "mahalanobis" else None
            return pair, float(tr.pair_bound_series(setup, x[None], pair[None], cov)[0])
        u = None if control is None else np.asarray(control)[None]
        if oracle and u is None:
            u = np.zeros((1, 2))
        pairs, bound = tr.choose_pairs(setup, strategy, x[None], P[None], u)
        return pairs[0], float(bound[0])

    def move(ps, o):
        return o + controls[int(np.argmin(tr.target_objective(ps, o, controls)))]

    pairs = np.empty((steps, 2), dtype=int)
    bound, est, cov = np.empty(steps), np.empty((steps, 2)), np.empty((steps, 2, 2))
    pair, b = choose(0)
    for k in range(steps):
        pairs[k], bound[k] = pair, b
        est[k], cov[k] = ekf.x[:, 0], ekf.P
        ps = s[pairs[k]]
        o = truth[k]
        z = tr.half_squared_range(o.reshape(2, 1), ps) + table[k, pairs[k]][:, None]
        ekf.predict()
        ekf.update(z, tr.range_jacobian, tr.half_squared_range, args=(ps,), hx_args=(ps,))
        if oracle:
            if not circle:
                truth[k + 1] = move(ps, o)
            pair, b = choose(k + 1, truth[k + 1] - truth[k])
            continue
        pair, b = choose(k + 1)
        if not circle:
            truth[k + 1] = move(ps if setup.adversary == "current-pair" else s[pair], o)
    return {"pairs": pairs, "bound": bound, "estimate": est, "cov": cov, "truth": truth[:-1],
            "next_pair": pair, "estimate_end": ekf.x[:, 0].copy(), "cov_end": ekf.P.copy()}

"""The reference engine: one tracking run of Section V driven step by step through filterpy's
extended Kalman filter (:func:`simulate`).

The filter
----------
Static (random-walk) prediction :math:`x \\leftarrow x`, :math:`P \\leftarrow P + Q`; measurement
Jacobian rows :math:`H_i = (\\hat x - p_i)^T`. The update is
``filterpy.kalman.ExtendedKalmanFilter.update``, which in filterpy 2.0.0 already uses the
Joseph form

.. math::

    P \\leftarrow (I - K H) P (I - K H)^T + K R K^T

(the tests compare one step with a hand-written Joseph update), so no correction of filterpy's
:math:`P` is needed.

Order within step :math:`k`: (1) choose the pair from the current estimate and covariance and
log its bound; (2) log the error :math:`\\lVert \\hat x_k - o_k \\rVert` and
:math:`\\operatorname{tr} \\Sigma_k`, the values *before* this step's update (step 1 logs 0.7071
and 1.0 for the paper's circle); (3) predict, measure the true :math:`o_k` with the chosen pair
and update; (4) choose the next pair from the posterior and move the target to :math:`o_{k+1}`.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_choice, as_instance, as_int, as_noise_table
from .choosers import CRITERIA, NAMES, PairChooser, candidates, pair_draws
from .kalman import innovation_is_regular
from .model import circle_truth, half_squared_range, range_jacobian, target_objective
from .results import TrackingResult, derived_arrays
from .setup import TrackingSetup, noise_table

__all__ = ["simulate"]


def singular_update_message(x, ps, k: int, run: int | None = None) -> str:
    """The error of an update whose innovation covariance is singular (see
    :data:`~obslib.tracking.kalman.SINGULAR_RTOL`): estimate ``x``, pair sensors ``ps``, step
    ``k`` (0-based)."""
    where = f"step {k + 1}" + ("" if run is None else f" of run {run}")
    return (
        f"the filter's update at {where} failed: the innovation covariance H P H^T + R is "
        f"singular in floating point (estimate {np.round(x, 6).tolist()}, pair sensors "
        f"{np.asarray(ps).tolist()}); the estimate is so far from the sensors, or its covariance "
        "so large, that the two Jacobian rows are parallel to rounding. Start the estimate "
        "nearer the target or with a smaller cov0."
    )


def _update(ekf, z, ps, k: int) -> None:
    """filterpy's EKF update (after its predict), with a ValueError naming the cause where the
    innovation covariance is singular (``kalman.innovation_is_regular``)
    instead of filterpy's LinAlgError or a silently wrong gain."""
    x = ekf.x[:, 0]
    H = range_jacobian(ekf.x, ps)
    S = H @ ekf.P @ H.T + ekf.R
    if not innovation_is_regular(S[0, 0], S[0, 1], S[1, 0], S[1, 1]):
        raise ValueError(singular_update_message(x, ps, k))
    try:
        ekf.update(z, range_jacobian, half_squared_range, args=(ps,), hx_args=(ps,))
    except np.linalg.LinAlgError:
        raise ValueError(singular_update_message(x, ps, k)) from None
    if not (np.isfinite(ekf.x).all() and np.isfinite(ekf.P).all()):
        raise ValueError(singular_update_message(x, ps, k))


def simulate(setup: TrackingSetup, strategy: str, noise=None, seed: int = 0) -> TrackingResult:
    """One tracking run of Section V with filterpy's EKF (Figs. 4-7).

    Parameters
    ----------
    setup : TrackingSetup
        E.g. :data:`~obslib.tracking.PAPER_CIRCLE` (Figs. 4-6) or
        :data:`~obslib.tracking.PAPER_ADVERSARIAL` (Fig. 7).
    strategy : str
        ``"best-pair"``, ``"best-partner"``, ``"fixed-pair"``: strategies (1), (2), (3) of
        Section V-A (:data:`~obslib.tracking.STRATEGIES`); or a criterion beyond the paper,
        ``"d-optimal"``, ``"a-optimal"``, ``"e-optimal"``, ``"exact-icn"``, ``"random"``
        (:data:`~obslib.tracking.CRITERIA`, see :mod:`~obslib.tracking.choosers`). The logged
        ``bound`` is always the paper's pair bound of the chosen pair.
    noise : array_like, shape (steps, N), optional
        Explicit measurement noise, entry ``[k-1, i]`` for sensor ``i`` at step ``k`` (exact
        replay). Default: :func:`~obslib.tracking.noise_table` of ``seed``.
    seed : int
        Seed of the noise table when ``noise`` is not given, and of the ``"random"`` chooser's
        draws (``choosers.pair_draws``, a separate stream) in any case.

    Returns
    -------
    TrackingResult

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=20)
    >>> r = tracking.simulate(setup, "best-pair", seed=0)
    >>> r.pairs[:2].tolist(), round(float(r.bound[0]), 4), r.error.shape
    ([[3, 5], [3, 5]], 0.8736, (20,))
    """
    from filterpy.kalman import ExtendedKalmanFilter

    as_instance(setup, TrackingSetup, "setup")
    as_choice(strategy, NAMES, "strategy")
    if noise is None or strategy == "random":
        seed = as_int(seed, "seed", 0)
    if noise is None:
        table, used_seed = noise_table(setup, seed), seed
    else:
        table, used_seed = as_noise_table(noise, (setup.steps, setup.n_sensors)), None
    oracle = strategy == "exact-icn"
    if oracle and setup.motion == "adversarial" and setup.adversary == "next-pair":
        raise ValueError("an exact-icn run cannot face a next-pair adversary: each needs the "
                         "other's next move first")

    s = setup.sensor_array
    steps = setup.steps
    ekf = ExtendedKalmanFilter(dim_x=2, dim_z=2)
    ekf.x = np.array(setup.estimate0, dtype=float).reshape(2, 1)
    ekf.P = np.array(setup.cov0, dtype=float)
    ekf.F = np.eye(2)
    ekf.Q = np.array(setup.Q, dtype=float)
    ekf.R = np.array(setup.R, dtype=float)

    circle = setup.motion == "circle"
    truth = np.empty((steps + 1, 2))
    if circle:
        truth[:] = circle_truth(setup)
    else:
        truth[0] = setup.start
        controls = setup.control_array
    pairs = np.empty((steps, 2), dtype=int)
    bound = np.empty(steps)
    est = np.empty((steps, 2))
    cov = np.empty((steps, 2, 2))

    cand = candidates(setup, strategy)[None]
    kind = strategy if strategy in CRITERIA else "bound"
    draws = pair_draws(seed, steps, cand.shape[1])[None] if strategy == "random" else None
    chooser = PairChooser(s, cand, [setup.metric == "mahalanobis"], setup.u_max**2, [kind],
                          setup.Q, setup.R, draws)

    no_control = np.zeros((1, 2))

    def choose(k, control=no_control):
        x, P = ekf.x[:, 0], ekf.P
        best, b = chooser(x[:1].copy(), x[1:].copy(), *(P[a, e, None] for a in (0, 1)
                                                        for e in (0, 1)), control, k)
        if chooser.deferred.size:
            b = chooser.deferred_bounds(best[:, None], x[None, None, :], P[None, None])[:, 0]
        return np.array([chooser.ii[best[0]], chooser.jj[best[0]]]), float(b[0])

    pair, b = choose(0)
    for k in range(steps):
        # (1) the pair chosen from the current estimate and covariance, and its bound
        pairs[k], bound[k] = pair, b
        # (2) the estimate and covariance before this step's update
        est[k] = ekf.x[:, 0]
        cov[k] = ekf.P
        # (3) predict (random walk), measure the true o_k with the pair, Joseph-form update
        ps = s[pairs[k]]
        o = truth[k]
        z = half_squared_range(o.reshape(2, 1), ps) + table[k, pairs[k]][:, None]
        ekf.predict()
        _update(ekf, z, ps, k)
        if oracle:  # (4) move the target first: the oracle knows the control u_k
            if not circle:
                u = controls[int(np.argmin(target_objective(ps, o, controls)))]
                truth[k + 1] = o + u
            pair, b = choose(k + 1, (truth[k + 1] - truth[k])[None])
            continue
        # The next choice depends only on the posterior, so a "next-pair" adversary can know it.
        pair, b = choose(k + 1)
        # (4) move the target
        if not circle:
            eval_pair = ps if setup.adversary == "current-pair" else s[pair]
            u = controls[int(np.argmin(target_objective(eval_pair, o, controls)))]
            truth[k + 1] = o + u
    return TrackingResult(
        setup=setup,
        strategy=strategy,
        seed=used_seed,
        noise=table,
        pairs=pairs,
        bound=bound,
        estimate=est,
        cov=cov,
        next_pair=pair.copy(),
        **derived_arrays(est, cov, truth),
    )

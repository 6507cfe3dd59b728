"""Tracking simulations of Section V: two sensors track a target (Figs. 4-6) or an adversary
(Fig. 7).

Six stationary range sensors; at each step a *strategy* picks two of them, which measure the
half squared range ``z_i = 1/2 ||p_i - o||^2 + n_i`` to the target, and an extended Kalman filter
on the target's 2-D position fuses the two measurements. The strategies of Section V-A are

``"best-pair"``
    strategy (1), flexible best pair: the pair with the highest pair bound (Theorem 4) at the
    current estimate;
``"best-partner"``
    strategy (2), the best partner of a fixed sensor (``setup.anchor``, the paper's ``s_2``);
``"fixed-pair"``
    strategy (3), always the same pair (``setup.fixed_pair``, the paper's ``(s_2, s_1)``).

Every parameter of the published runs is in ``../shared/EXPERIMENTS.md`` and in the two parameter
records :data:`PAPER_CIRCLE` (Figs. 4-6) and :data:`PAPER_ADVERSARIAL` (Fig. 7).

The filter
----------
Static (random-walk) prediction ``x <- x``, ``P <- P + Q``; measurement Jacobian rows
``H_i = (xhat - p_i)^T``. The update is :meth:`filterpy.kalman.ExtendedKalmanFilter.update`,
which in filterpy 2.0.0 already uses the Joseph form
``P = (I - K H) P (I - K H)^T + K R K^T`` (we checked its source; the tests compare one step with
a hand-written Joseph update), so no correction of filterpy's ``P`` is needed.

Order within step ``k`` (EXPERIMENTS.md): (1) choose the pair from the current estimate and
covariance and log its bound; (2) log the error ``||xhat_k - o_k||`` and ``trace(Sigma_k)``, the
values *before* this step's update (step 1 logs 0.7071 and 1.0); (3) predict, measure the true
``o_k`` with the chosen pair and update; (4) move the target to ``o_{k+1}``.

Noise is common to all strategies: entry ``[k-1, i]`` of a ``(steps, N)`` table is sensor ``i``'s
noise at step ``k``, whichever strategy asks for it. :func:`simulate` takes an explicit table
(exact replay) or draws it once from ``numpy.random.default_rng(seed)``.

The pair bound is :func:`obslib.pair_bounds` at the estimate with ``u_max`` of the setup, with
Mahalanobis distances in the estimate's covariance as in the published runs (``metric=
"mahalanobis"``) or Euclidean ones (``metric="euclidean"``); ties keep the first maximum in
``(i, j)`` order.

The adversarial target of Section V-B (``motion="adversarial"``) moves after the update: knowing
its position ``o`` and the pair that just measured it, it takes the control ``u`` of its set that
minimises the exact ``C^{-1}([o + u - p_i; o + u - p_j; u])`` (:func:`target_objective`); the
``"next-pair"`` variant evaluates the pair the sensors will use next instead.

Two engines compute the same runs: :func:`simulate` drives filterpy's EKF step by step (the
reference), and the batch engine (:func:`simulate_many`, :func:`simulate_batch`,
:func:`monte_carlo`) runs many noise seeds, strategies and setups at once with the same equations
written as NumPy array operations over runs, without per-step validation. The tests check that
they pick the same pairs and controls and agree to rounding.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from functools import cached_property
from typing import Iterable

import numpy as np

from ._validate import as_point, as_points, check_distinct, check_spd2
from .controls import disc_controls
from .bounds import _pair_kernel, pair_bounds, relative_vectors
from .observability import _inverse_condition

__all__ = [
    "STRATEGIES",
    "METRICS",
    "ADVERSARIES",
    "MOTIONS",
    "PARAM_FIELDS",
    "PAPER_SENSORS",
    "TrackingSetup",
    "PAPER_CIRCLE",
    "PAPER_ADVERSARIAL",
    "TIE_RTOL",
    "clearly_lower",
    "TrackingResult",
    "BatchResult",
    "paper_controls",
    "disc_controls",
    "noise_table",
    "setup_from_params",
    "circle_truth",
    "half_squared_range",
    "range_jacobian",
    "choose_pairs",
    "pair_bound_series",
    "target_objective",
    "simulate",
    "simulate_batch",
    "simulate_many",
    "monte_carlo",
    "compare_strategies",
    "spearman",
    "Entrapment",
    "entrapment",
    "switch_mechanism",
    "ENTRAPMENT_CRITERIA",
    "is_entrapped",
    "entrapment_summary",
    "adversary_variants",
    "switch_rate",
    "switch_back_fraction",
    "bound_correlation",
    "mirror_point",
    "track_loss",
    "partner_study",
    "partner_arms",
    "partner_summary",
    "PUBLISHED_CIRCLE",
    "PUBLISHED_ADVERSARIAL",
    "cov_ellipse",
    "CHI2_2DOF_9973",
    "sensor_label",
    "draw_sensors",
    "draw_snapshot",
    "RunAnimation",
    "animate",
    "animation_html",
]

STRATEGIES = ("best-pair", "best-partner", "fixed-pair")
METRICS = ("mahalanobis", "euclidean")
ADVERSARIES = ("current-pair", "next-pair")
MOTIONS = ("circle", "adversarial")

#: The six sensors s1..s6 of Section V (EXPERIMENTS.md, Figs. 4-7).
PAPER_SENSORS = ((-3.0, 2.0), (0.0, 0.0), (1.0, -1.0), (4.0, 0.0), (4.0, 4.0), (2.0, 5.0))

#: Numbers of the published Figs. 4-6 run, for orientation (EXPERIMENTS.md): pair changes over
#: 314 transitions and run means, per strategy.
PUBLISHED_CIRCLE = {
    "best-pair": {"switches": 148, "mean_bound": 0.73, "mean_error": 0.16, "mean_trace": 0.073},
    "best-partner": {"switches": 102, "mean_bound": 0.49, "mean_error": 0.19, "mean_trace": 0.140},
    "fixed-pair": {"switches": 0, "mean_bound": 0.27, "mean_error": 0.22, "mean_trace": 0.217},
}

#: The published Fig. 7 run (EXPERIMENTS.md): mean bound and pair changes over 314 transitions.
PUBLISHED_ADVERSARIAL = {"mean_bound": 0.79, "switches": 306, "transitions": 314}

#: Chi-square quantile, 2 degrees of freedom, 99.73 % (the "3 sigma" ellipse of Fig. 4).
CHI2_2DOF_9973 = 11.82


def paper_controls(u_max: float, n_angles: int = 63, dphi: float = 0.1) -> np.ndarray:
    """The adversary's control set of the published Fig. 7 run.

    ``u = 0`` followed by ``n_angles`` controls of norm ``u_max`` at angles ``0, dphi, ...,
    (n_angles - 1) dphi`` (default 0, 0.1, ..., 6.2 rad; EXPERIMENTS.md, Fig. 7). The paper's text
    says "all the possible control inputs within a ball"; :func:`disc_controls` gives that.

    Returns
    -------
    ndarray, shape (n_angles + 1, 2)
    """
    phi = dphi * np.arange(n_angles)
    ring = float(u_max) * np.column_stack([np.cos(phi), np.sin(phi)])
    return np.vstack([np.zeros((1, 2)), ring])


# --------------------------------------------------------------------------------------------
# The parameter record
# --------------------------------------------------------------------------------------------


def _matrix(value, name: str) -> tuple:
    """A symmetric positive-definite 2x2 matrix as a tuple of tuples, or ValueError."""
    try:
        m = np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} must be a numeric 2x2 matrix: {exc}") from None
    if m.ndim == 0:
        m = m * np.eye(2)
    if m.shape != (2, 2):
        raise ValueError(f"{name} must be a 2x2 matrix (or a scalar times I), got shape {m.shape}")
    check_spd2(m, name)
    return tuple(map(tuple, m.tolist()))


def _point(value, name: str) -> tuple:
    return tuple(as_point(value, name).tolist())


def _scalar(value, name: str, *, positive=False, nonneg=False) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} must be a number: {exc}") from None
    if not np.isfinite(v):
        raise ValueError(f"{name} must be finite, got {v}")
    if positive and v <= 0:
        raise ValueError(f"{name} must be positive, got {v}")
    if nonneg and v < 0:
        raise ValueError(f"{name} must be non-negative, got {v}")
    return v


@dataclass(frozen=True)
class TrackingSetup:
    """Parameters of one tracking experiment of Section V (a frozen parameter record).

    Build variants with :func:`dataclasses.replace`, e.g.
    ``replace(PAPER_CIRCLE, metric="euclidean")``; every construction is validated and bad
    values raise :class:`ValueError`.

    Attributes
    ----------
    sensors : tuple of (x, y)
        Stationary sensor positions ``p_i`` (at least two, pairwise distinct).
    steps : int
        Number of time steps (at least 1).
    u_max : float
        Speed bound entering the pair bound (and the adversary's default control set).
    estimate0, cov0 : (x, y), 2x2
        Initial estimate and covariance of the filter.
    Q, R : 2x2
        Process noise of the random-walk prediction and measurement-noise covariance of the
        filter for the pair's two measurements (a scalar means that multiple of ``I``).
    noise_std : float
        Standard deviation of the true measurement noise ``n_i`` (may differ from ``R``).
    motion : {"circle", "adversarial"}
        The true target's motion: the circle of Section V-A or the adversary of Section V-B.
    center, radius, rate : circle parameters
        ``o_k = center + radius (cos(rate (k-1)), sin(rate (k-1)))``.
    start : (x, y) or None
        True start of the adversarial target (``None`` for the circle).
    controls : tuple of (ux, uy) or None
        The adversary's control set, each of norm ``<= u_max``; ``None`` means
        :func:`paper_controls` of ``u_max``.
    adversary : {"current-pair", "next-pair"}
        What the adversary minimises: the exact ``C^{-1}`` of ``[o' - p_i; o' - p_j; u]`` at its
        next position ``o' = o + u`` with the pair that just measured it (``"current-pair"``, the
        paper) or with the pair the sensors will use next (``"next-pair"``, a stronger target that
        knows the sensors' next choice).
    metric : {"mahalanobis", "euclidean"}
        Distances in the pair bound: Mahalanobis in the estimate's covariance (the published runs)
        or Euclidean.
    anchor : int
        The fixed sensor of strategy (2), 0-based (``1`` is the paper's ``s_2``).
    fixed_pair : (int, int)
        The pair of strategy (3), 0-based (``(1, 0)`` is the paper's ``(s_2, s_1)``).
    """

    sensors: tuple = PAPER_SENSORS
    steps: int = 315
    u_max: float = 3.0
    estimate0: tuple = (5.5, 3.5)
    cov0: tuple = ((0.5, 0.0), (0.0, 0.5))
    Q: tuple = ((0.5, 0.0), (0.0, 0.5))
    R: tuple = ((0.5, 0.0), (0.0, 0.5))
    noise_std: float = 0.5
    motion: str = "circle"
    center: tuple = (2.0, 3.0)
    radius: float = 3.0
    rate: float = 0.02
    start: tuple | None = None
    controls: tuple | None = None
    adversary: str = "current-pair"
    metric: str = "mahalanobis"
    anchor: int = 1
    fixed_pair: tuple = (1, 0)

    def __post_init__(self):
        put = lambda name, value: object.__setattr__(self, name, value)  # noqa: E731
        if self.sensors is None or np.size(np.asarray(self.sensors, dtype=object)) == 0:
            raise ValueError("setup has no sensors; the strategies need at least 2")
        s = as_points(self.sensors, "sensors")
        if s.shape[0] == 0:
            raise ValueError("setup has no sensors; the strategies need at least 2")
        if s.shape[0] < 2:
            raise ValueError(f"setup has {s.shape[0]} sensor; the strategies need at least 2")
        check_distinct(s)
        put("sensors", tuple(map(tuple, s.tolist())))
        n = s.shape[0]
        if isinstance(self.steps, bool) or not isinstance(self.steps, (int, np.integer)):
            raise ValueError(f"steps must be an integer, got {self.steps!r}")
        if self.steps < 1:
            raise ValueError(f"steps must be at least 1, got {self.steps}")
        put("steps", int(self.steps))
        put("u_max", _scalar(self.u_max, "u_max", nonneg=True))
        put("estimate0", _point(self.estimate0, "estimate0"))
        put("cov0", _matrix(self.cov0, "cov0"))
        put("Q", _matrix(self.Q, "Q"))
        put("R", _matrix(self.R, "R"))
        put("noise_std", _scalar(self.noise_std, "noise_std", nonneg=True))
        if self.motion not in MOTIONS:
            raise ValueError(f"motion must be one of {MOTIONS}, got {self.motion!r}")
        put("center", _point(self.center, "center"))
        put("radius", _scalar(self.radius, "radius", nonneg=True))
        put("rate", _scalar(self.rate, "rate"))
        if self.motion == "adversarial":
            if self.start is None:
                raise ValueError("an adversarial target needs a start position")
            put("start", _point(self.start, "start"))
        elif self.start is not None:
            raise ValueError("start is for the adversarial target; the circle starts on the circle")
        if self.controls is not None:
            c = as_points(self.controls, "controls", min_count=1)
            norms = np.hypot(c[:, 0], c[:, 1])
            over = norms > self.u_max * (1 + 1e-12)
            if over.any():
                k = int(np.flatnonzero(over)[0])
                raise ValueError(
                    f"control {k} has norm {norms[k]:.6g} > u_max = {self.u_max:g}"
                )
            put("controls", tuple(map(tuple, c.tolist())))
        if self.adversary not in ADVERSARIES:
            raise ValueError(f"adversary must be one of {ADVERSARIES}, got {self.adversary!r}")
        if self.metric not in METRICS:
            raise ValueError(f"metric must be one of {METRICS}, got {self.metric!r}")
        if not isinstance(self.anchor, (int, np.integer)) or not 0 <= self.anchor < n:
            raise ValueError(f"anchor must be a sensor index in 0..{n - 1}, got {self.anchor!r}")
        put("anchor", int(self.anchor))
        fp = tuple(self.fixed_pair)
        if len(fp) != 2 or not all(isinstance(i, (int, np.integer)) and 0 <= i < n for i in fp):
            raise ValueError(f"fixed_pair must be two sensor indices in 0..{n - 1}, got {fp!r}")
        if fp[0] == fp[1]:
            raise ValueError(f"fixed_pair names sensor {fp[0]} twice")
        put("fixed_pair", (int(fp[0]), int(fp[1])))

    # Convenience arrays (fresh copies, so the record stays immutable).
    @property
    def sensor_array(self) -> np.ndarray:
        """Sensors as an ``(N, 2)`` array."""
        return np.array(self.sensors, dtype=float)

    @property
    def n_sensors(self) -> int:
        return len(self.sensors)

    @property
    def control_array(self) -> np.ndarray:
        """The adversary's controls, ``(K, 2)`` (the paper's set when ``controls`` is None)."""
        if self.controls is None:
            return paper_controls(self.u_max)
        return np.array(self.controls, dtype=float)

    def replace(self, **changes) -> "TrackingSetup":
        """A validated copy with some fields changed (:func:`dataclasses.replace`)."""
        return dataclasses.replace(self, **changes)


#: Figs. 4-6: the circle of radius 3 about (2, 3), 0.02 rad per step, u_max = 3 (EXPERIMENTS.md).
PAPER_CIRCLE = TrackingSetup()

#: Fig. 7: the adversarial target, u_max = 0.1, true start (2, 2), estimate (2.5, 1.5).
PAPER_ADVERSARIAL = TrackingSetup(
    u_max=0.1, estimate0=(2.5, 1.5), motion="adversarial", start=(2.0, 2.0)
)


#: Notebook parameter names and the setup fields they set (see :func:`setup_from_params`).
PARAM_FIELDS = {
    "steps": "steps",
    "u_max": "u_max",
    "noise_std": "noise_std",
    "q": "Q",
    "r": "R",
    "p0": "cov0",
    "metric": "metric",
}


def setup_from_params(base: TrackingSetup, params: dict) -> TrackingSetup:
    """``base`` with the notebook parameters of :data:`PARAM_FIELDS` applied (others ignored).

    The notebooks and the claims ledger build their setups with this, so both run the same
    experiment for the same parameters (``q``, ``r``, ``p0`` are multiples of ``I``).
    """
    changes = {PARAM_FIELDS[k]: v for k, v in params.items() if k in PARAM_FIELDS}
    return base.replace(**changes)


# --------------------------------------------------------------------------------------------
# Building blocks
# --------------------------------------------------------------------------------------------


def noise_table(setup: TrackingSetup, seed: int = 0) -> np.ndarray:
    """The measurement noise of one run, ``(steps, N)``: ``[k-1, i]`` is sensor ``i`` at step ``k``.

    Drawn once from ``numpy.random.default_rng(seed)`` as ``normal(0, noise_std)``, so every
    strategy sees the same realisation (EXPERIMENTS.md: noise common to all strategies).
    """
    rng = np.random.default_rng(seed)
    return rng.normal(0.0, setup.noise_std, size=(setup.steps, setup.n_sensors))


def _check_noise(setup: TrackingSetup, noise) -> np.ndarray:
    try:
        t = np.asarray(noise, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"noise must be a numeric (steps, sensors) table: {exc}") from None
    want = (setup.steps, setup.n_sensors)
    if t.shape != want:
        raise ValueError(f"noise table must have shape {want} (steps, sensors), got {t.shape}")
    bad = ~np.isfinite(t)
    if bad.any():
        k, i = (int(v) for v in np.argwhere(bad)[0])
        raise ValueError(f"noise of sensor {i} at step {k + 1} is not finite")
    return t


def circle_truth(setup: TrackingSetup) -> np.ndarray:
    """True positions ``o_k``, ``k = 1..steps + 1``, on the circle of Section V-A, ``(steps+1, 2)``.

    ``o_k = center + radius (cos(rate (k - 1)), sin(rate (k - 1)))``; the extra last row is the
    position the target moves to after the last step.
    """
    a = setup.rate * np.arange(setup.steps + 1)
    return np.asarray(setup.center) + setup.radius * np.column_stack([np.cos(a), np.sin(a)])


def half_squared_range(x, pair_sensors) -> np.ndarray:
    """Measurement function ``h(x) = 1/2 ||p_i - x||^2`` for the rows ``p_i`` of ``pair_sensors``.

    ``x`` may be a filterpy column ``(2, 1)`` (returns ``(m, 1)``) or a batch ``(..., 2)`` with
    ``pair_sensors`` ``(..., m, 2)`` (returns ``(..., m)``).
    """
    x = np.asarray(x, dtype=float)
    ps = np.asarray(pair_sensors, dtype=float)
    if x.shape == (2, 1):
        d = ps - x[:, 0]
        return (0.5 * (d[:, 0] ** 2 + d[:, 1] ** 2))[:, None]
    d = ps - x[..., None, :]
    return 0.5 * (d[..., 0] ** 2 + d[..., 1] ** 2)


def range_jacobian(x, pair_sensors) -> np.ndarray:
    """Jacobian of :func:`half_squared_range`: rows ``H_i = (x - p_i)^T``, shape ``(..., m, 2)``."""
    x = np.asarray(x, dtype=float)
    ps = np.asarray(pair_sensors, dtype=float)
    if x.shape == (2, 1):
        return x[:, 0][None, :] - ps
    return x[..., None, :] - ps


def _pair_index(n: int):
    """Row and column of the pairs ``i < j`` in ``(i, j)`` order."""
    return np.triu_indices(n, 1)


def choose_pairs(setup: TrackingSetup, strategy: str, xhat, cov):
    """The pair each strategy picks at estimates ``xhat`` (B, 2) with covariances ``cov`` (B, 2, 2).

    Scores are :func:`obslib.pair_bounds` (Theorem 4) at the estimate with ``u_max`` of the
    setup, distances Mahalanobis in ``cov`` (``metric="mahalanobis"``, the published runs) or
    Euclidean. Ties keep the first maximum in ``(i, j)`` order (EXPERIMENTS.md).

    Returns
    -------
    pairs : ndarray of int, shape (B, 2)
        0-based sensor indices, ``pairs[:, 0] < pairs[:, 1]``.
    bound : ndarray, shape (B,)
        The chosen pair's bound.
    """
    if strategy not in STRATEGIES:
        raise ValueError(f"unknown strategy {strategy!r}; known: {STRATEGIES}")
    xhat = np.atleast_2d(np.asarray(xhat, dtype=float))
    b = xhat.shape[0]
    n = setup.n_sensors
    W = pair_bounds(
        setup.sensors, xhat, setup.u_max, cov=cov if setup.metric == "mahalanobis" else None
    )  # (N, N, B)
    if strategy == "fixed-pair":
        i, j = sorted(setup.fixed_pair)
        pairs = np.broadcast_to(np.array([i, j]), (b, 2)).copy()
        return pairs, W[i, j, :].copy()
    if strategy == "best-pair":
        ii, jj = _pair_index(n)
        scores = W[ii, jj, :]  # (P, B), pairs in (i, j) order
        best = np.argmax(scores, axis=0)  # first maximum
        pairs = np.column_stack([ii[best], jj[best]])
        return pairs, scores[best, np.arange(b)]
    # best-partner: the anchor with its best partner; candidates in index order.
    a = setup.anchor
    others = np.array([j for j in range(n) if j != a])
    scores = W[a, others, :]  # (N - 1, B)
    best = np.argmax(scores, axis=0)
    partner = others[best]
    pairs = np.sort(np.column_stack([np.full(b, a), partner]), axis=1)
    return pairs, scores[best, np.arange(b)]


def pair_bound_series(setup: TrackingSetup, points, pairs, cov=None) -> np.ndarray:
    """Theorem 4's bound of the given pair at each point: ``W[pairs[k, 0], pairs[k, 1], k]``.

    Equals indexing :func:`obslib.pair_bounds` (tests check it) but evaluates only the given
    pair at each point, so whole Monte Carlo batches can be passed at once.

    Parameters
    ----------
    points : array_like, shape (K, 2)
        Where to evaluate (e.g. a run's ``estimate`` or ``truth``).
    pairs : array_like of int, shape (K, 2)
    cov : array_like, shape (K, 2, 2), optional
        Mahalanobis distances in these covariances; Euclidean when omitted.
    """
    v = relative_vectors(setup.sensors, points, cov)  # validated, (N, K, 2)
    K = v.shape[1]
    pr = np.asarray(pairs)
    n = setup.n_sensors
    if pr.shape != (K, 2) or not np.issubdtype(pr.dtype, np.integer):
        raise ValueError(f"pairs must be integers of shape ({K}, 2), got {pr.dtype} {pr.shape}")
    if K and (pr.min() < 0 or pr.max() >= n):
        raise ValueError(f"pairs must be sensor indices in 0..{n - 1}")
    # each point's vectors scaled by their largest length, as in pair_bounds
    scale = np.sqrt(np.einsum("nlk,nlk->nl", v, v).max(axis=0)) if n else np.ones(K)
    v = v / scale[None, :, None]
    u2 = np.broadcast_to(setup.u_max**2, (K,)) / scale**2
    k = np.arange(K)
    vi, vj = v[pr[:, 0], k], v[pr[:, 1], k]
    return _pair_kernel(vi[:, 0], vi[:, 1], vj[:, 0], vj[:, 1], u2)


def target_objective(pair_sensors, position, controls) -> np.ndarray:
    """Exact ``C^{-1}`` of ``[o' - p_i; o' - p_j; u]`` at ``o' = o + u`` for each control ``u``.

    The adversary of Section V-B minimises this over its control set.

    Parameters
    ----------
    pair_sensors : array_like, shape (..., 2, 2)
        The two sensors' positions (rows).
    position : array_like, shape (..., 2)
        The target's current position ``o``.
    controls : array_like, shape (K, 2)

    Returns
    -------
    ndarray, shape (..., K)
    """
    ps = np.asarray(pair_sensors, dtype=float)
    o = np.asarray(position, dtype=float)
    u = np.asarray(controls, dtype=float)
    nxt = o[..., None, :] + u  # (..., K, 2)
    rows = nxt[..., :, None, :] - ps[..., None, :, :]  # (..., K, 2, 2)
    uu = np.broadcast_to(u, nxt.shape)[..., None, :]  # (..., K, 1, 2)
    return _inverse_condition(np.concatenate([rows, uu], axis=-2))


# --------------------------------------------------------------------------------------------
# Results
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class TrackingResult:
    """One tracking run (:func:`simulate`); per-step arrays, step ``k`` at index ``k - 1``.

    Attributes
    ----------
    setup, strategy, seed :
        What was run (``seed`` is None when an explicit noise table was given).
    noise : (steps, N)
        The noise table used.
    pairs : (steps, 2) int
        The chosen pair, 0-based, ``pairs[:, 0] < pairs[:, 1]``.
    bound : (steps,)
        The chosen pair's bound at the estimate (the setup's metric).
    error, trace_cov : (steps,)
        ``||xhat_k - o_k||`` and ``trace(Sigma_k)`` before the step's update.
    truth, estimate : (steps, 2)
        ``o_k`` and ``xhat_k`` (before the update).
    cov : (steps, 2, 2)
        ``Sigma_k`` before the update.
    control : (steps, 2)
        The target's move after step ``k``: ``u_k = o_{k+1} - o_k``.
    truth_end : (2,)
        ``o_{steps+1}``, where the target is after its last move.
    next_pair : (2,) int
        The pair the sensors would choose after the last step.
    objective : (steps,)
        ``C^{-1}([o_{k+1} - p_i; o_{k+1} - p_j; u_k])`` with the pair of step ``k``: the value the
        adversary of Section V-B minimises (computed on first access).
    true_icn : (steps,)
        The exact ``C^{-1}([o_k - p_i; o_k - p_j; u_{k-1}])`` the sensors face at step ``k``
        with the pair they chose (``u_0 = 0``; computed on first access).
    """

    setup: TrackingSetup
    strategy: str
    seed: int | None
    noise: np.ndarray
    pairs: np.ndarray
    bound: np.ndarray
    error: np.ndarray
    trace_cov: np.ndarray
    truth: np.ndarray
    estimate: np.ndarray
    cov: np.ndarray
    control: np.ndarray
    truth_end: np.ndarray
    next_pair: np.ndarray

    @cached_property
    def objective(self) -> np.ndarray:
        ps = self.setup.sensor_array[self.pairs]  # (..., steps, 2, 2)
        nxt = np.concatenate([self.truth[..., 1:, :], self.truth_end[..., None, :]], axis=-2)
        return _inverse_condition(
            np.concatenate([nxt[..., None, :] - ps, self.control[..., None, :]], axis=-2)
        )

    @cached_property
    def true_icn(self) -> np.ndarray:
        ps = self.setup.sensor_array[self.pairs]
        c = self.control
        prev = np.concatenate([np.zeros_like(c[..., :1, :]), c[..., :-1, :]], axis=-2)
        return _inverse_condition(
            np.concatenate([self.truth[..., None, :] - ps, prev[..., None, :]], axis=-2)
        )

    @property
    def steps(self) -> int:
        return self.pairs.shape[-2]

    @property
    def switched(self) -> np.ndarray:
        """``(steps - 1,)`` bool: the pair at step ``k + 1`` differs from the pair at step ``k``."""
        return (self.pairs[..., 1:, :] != self.pairs[..., :-1, :]).any(axis=-1)

    @property
    def switches(self):
        """Number of pair changes over the ``steps - 1`` transitions."""
        return int(self.switched.sum())

    def summary(self) -> dict:
        """The run's headline numbers (as in EXPERIMENTS.md): switches, mean bound, error, trace."""
        return {
            "switches": self.switches,
            "transitions": self.steps - 1,
            "mean_bound": float(self.bound.mean()),
            "mean_error": float(self.error.mean()),
            "mean_trace": float(self.trace_cov.mean()),
        }


@dataclass(frozen=True, eq=False)
class BatchResult(TrackingResult):
    """Many runs of one strategy (:func:`simulate_batch`): the arrays of :class:`TrackingResult`
    with a leading run axis ``(B, ...)``; ``seeds`` replaces ``seed``. ``run(b)`` gives one run."""

    seeds: tuple = ()

    @property
    def n_runs(self) -> int:
        return self.pairs.shape[0]

    @property
    def switches(self) -> np.ndarray:
        """Pair changes per run, ``(B,)``."""
        return self.switched.sum(axis=-1)

    def run(self, b: int) -> TrackingResult:
        """Run ``b`` as a :class:`TrackingResult`."""
        arrays = {
            f.name: getattr(self, f.name)[b]
            for f in dataclasses.fields(TrackingResult)
            if f.name not in ("setup", "strategy", "seed")
        }
        seed = self.seeds[b] if self.seeds else None
        r = TrackingResult(setup=self.setup, strategy=self.strategy, seed=seed, **arrays)
        for name in ("objective", "true_icn"):  # if already computed for the whole batch
            if name in self.__dict__:
                r.__dict__[name] = self.__dict__[name][b]
        return r


# --------------------------------------------------------------------------------------------
# The reference engine: filterpy, one run
# --------------------------------------------------------------------------------------------


def _derived(est, cov, truth_ext) -> dict:
    """Arrays shared by both engines, for any leading shape: errors, traces, truth, controls.

    ``truth_ext`` holds ``o_1 .. o_{steps+1}`` (the last is where the target moves after the
    last step).
    """
    control = truth_ext[..., 1:, :] - truth_ext[..., :-1, :]
    cur = truth_ext[..., :-1, :]
    diff = est - cur
    return {
        "error": np.hypot(diff[..., 0], diff[..., 1]),
        "trace_cov": cov[..., 0, 0] + cov[..., 1, 1],
        "truth": cur,
        "control": control,
        "truth_end": truth_ext[..., -1, :].copy(),
    }


def simulate(setup: TrackingSetup, strategy: str, noise=None, seed: int = 0) -> TrackingResult:
    """One tracking run of Section V with filterpy's EKF (Figs. 4-7).

    Parameters
    ----------
    setup : TrackingSetup
        E.g. :data:`PAPER_CIRCLE` (Figs. 4-6) or :data:`PAPER_ADVERSARIAL` (Fig. 7).
    strategy : {"best-pair", "best-partner", "fixed-pair"}
        Strategies (1), (2), (3) of Section V-A.
    noise : array_like, shape (steps, N), optional
        Explicit measurement noise, entry ``[k-1, i]`` for sensor ``i`` at step ``k`` (exact
        replay). Default: :func:`noise_table` of ``seed``.
    seed : int
        Seed of the noise table when ``noise`` is not given.

    Returns
    -------
    TrackingResult
    """
    from filterpy.kalman import ExtendedKalmanFilter

    if not isinstance(setup, TrackingSetup):
        raise ValueError(f"setup must be a TrackingSetup, got {type(setup).__name__}")
    if strategy not in STRATEGIES:
        raise ValueError(f"unknown strategy {strategy!r}; known: {STRATEGIES}")
    if noise is None:
        table, used_seed = noise_table(setup, seed), int(seed)
    else:
        table, used_seed = _check_noise(setup, noise), None

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

    pair, b = choose_pairs(setup, strategy, ekf.x[:, 0], ekf.P)
    for k in range(steps):
        # (1) the pair chosen from the current estimate and covariance, and its bound
        pairs[k], bound[k] = pair[0], b[0]
        # (2) the estimate and covariance before this step's update
        est[k] = ekf.x[:, 0]
        cov[k] = ekf.P
        # (3) predict (random walk), measure the true o_k with the pair, Joseph-form update
        ps = s[pairs[k]]
        o = truth[k]
        z = half_squared_range(o.reshape(2, 1), ps) + table[k, pairs[k]][:, None]
        ekf.predict()
        ekf.update(z, range_jacobian, half_squared_range, args=(ps,), hx_args=(ps,))
        # The next choice depends only on the posterior, so a "next-pair" adversary can know it.
        pair, b = choose_pairs(setup, strategy, ekf.x[:, 0], ekf.P)
        # (4) move the target
        if not circle:
            eval_pair = ps if setup.adversary == "current-pair" else s[pair[0]]
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
        next_pair=pair[0].copy(),
        **_derived(est, cov, truth),
    )


# --------------------------------------------------------------------------------------------
# The batch engine: many runs at once, same equations in NumPy
# --------------------------------------------------------------------------------------------

#: Setup fields that may differ between the rows of one batched pass (see :func:`simulate_many`).
_ROW_FIELDS = ("metric", "anchor", "fixed_pair", "adversary", "controls")


def _candidates(setup: TrackingSetup, strategy: str) -> np.ndarray:
    """Which pairs (in ``(i, j)`` order, :func:`_pair_index`) a strategy chooses among, ``(P,)``.

    Best pair: all; best partner: the pairs containing the anchor (in the order of the partner's
    index, as in :func:`choose_pairs`); fixed pair: that pair alone.
    """
    ii, jj = _pair_index(setup.n_sensors)
    if strategy == "best-pair":
        return np.ones(ii.size, dtype=bool)
    if strategy == "best-partner":
        return (ii == setup.anchor) | (jj == setup.anchor)
    i, j = sorted(setup.fixed_pair)
    return (ii == i) & (jj == j)


def _mahalanobis_sq(vx, vy, p00, p01, p10, p11):
    """``v^T Sigma^-1 v`` for ``Sigma = [[p00, p01], [p10, p11]]`` (broadcasting), from the
    adjugate: ``(p11 vx^2 - (p01 + p10) vx vy + p00 vy^2) / det Sigma``."""
    dm2 = p11 * (vx * vx)
    dm2 -= (p01 + p10) * (vx * vy)
    dm2 += p00 * (vy * vy)
    dm2 /= p00 * p11 - p01 * p10
    return dm2


class _PairChooser:
    """The strategies' picks for ``R`` runs at once, without per-step validation.

    Built once per batched pass from each run's candidate pairs ``cand`` (``(R, P)`` bool,
    :func:`_candidates`) and metric (``maha``, ``(R,)`` bool). Calling it with the runs'
    estimates and covariance entries returns the chosen pair's index (in :func:`_pair_index`
    order) and bound. The bound is :func:`obslib.pair_bounds`'s (the tests hold the two to
    rounding): vectors ``xhat - p_i`` (the sign does not matter) rescaled to the Mahalanobis
    length ``d_i^2 = v^T Sigma^-1 v`` where ``maha`` is set, each run's vectors divided by the
    longest, then the kernel of :func:`obslib.pair_bounds` for the run's candidate pairs only.
    The pick is the first maximum among the candidates in ``(i, j)`` order.

    Runs with a single candidate (the fixed pair) need no scores to choose, so the call leaves
    their bound out (NaN); :meth:`fixed_bounds` evaluates it afterwards over whole runs at once.
    """

    def __init__(self, sensors, cand, maha, u2):
        self.sx = sensors[:, 0].copy()
        self.sy = sensors[:, 1].copy()
        self.n = n = sensors.shape[0]
        self.ii, self.jj = _pair_index(n)
        self.maha = np.asarray(maha, dtype=bool)
        self.u2 = float(u2)
        R_ = cand.shape[0]
        counts = cand.sum(axis=1)
        if (counts == 0).any():
            raise ValueError("a run has no candidate pair")
        self.best = np.empty(R_, dtype=int)
        self.bound = np.full(R_, np.nan)
        self.single = np.flatnonzero(counts == 1)
        self.best[self.single] = np.nonzero(cand[self.single])[1]
        self.multi = np.flatnonzero(counts > 1)
        self.groups = []
        for c in np.unique(counts[self.multi]):
            rows = np.flatnonzero(counts == c)
            cidx = np.nonzero(cand[rows])[1].reshape(rows.size, int(c))  # ascending pair index
            loc = np.searchsorted(self.multi, rows)  # rows within the multi-candidate block
            fi = loc[:, None] * n + self.ii[cidx]
            fj = loc[:, None] * n + self.jj[cidx]
            self.groups.append((rows, loc, cidx, fi, fj, np.arange(rows.size)))
        self.maha_multi = self.maha[self.multi]

    def _vectors(self, xx, xy, p00, p01, p10, p11, maha):
        """Normalised (Mahalanobis) vectors ``(M, N)`` of ``M`` estimates and ``u2`` scaled."""
        vx = xx[:, None] - self.sx
        vy = xy[:, None] - self.sy
        e2 = vx * vx + vy * vy
        if not (e2 > 0).all():
            raise ValueError("an estimate is not finite or sits on a sensor")
        if maha.any():
            dm2 = _mahalanobis_sq(vx, vy, *(c[:, None] for c in (p00, p01, p10, p11)))
            n2 = np.where(maha[:, None], dm2, e2)
            f = np.sqrt(n2 / e2)
            vx *= f
            vy *= f
        else:
            n2 = e2
        inv = 1.0 / n2.max(axis=1)  # 1 / scale^2
        sc = np.sqrt(inv)[:, None]
        vx *= sc
        vy *= sc
        return vx, vy, self.u2 * inv

    def __call__(self, xx, xy, p00, p01, p10, p11):
        if self.groups:
            m = self.multi
            vx, vy, u2s = self._vectors(xx[m], xy[m], p00[m], p01[m], p10[m], p11[m],
                                        self.maha_multi)
            for rows, loc, cidx, fi, fj, ar in self.groups:
                w = _pair_kernel(vx.take(fi), vy.take(fi), vx.take(fj), vy.take(fj), u2s[loc, None])
                pick = w.argmax(axis=1)
                self.best[rows] = cidx[ar, pick]
                self.bound[rows] = w[ar, pick]
        elif not (np.isfinite(xx).all() and np.isfinite(xy).all()):
            raise ValueError("an estimate is not finite")
        return self.best.copy(), self.bound.copy()

    def fixed_bounds(self, est, cov) -> np.ndarray:
        """The bound of the single-candidate runs' pair over whole runs: ``est`` ``(R, T, 2)``
        and ``cov`` ``(R, T, 2, 2)`` of all runs in; ``(len(single), T)`` out."""
        r = self.single
        T = est.shape[1]
        k = np.repeat(self.best[r], T)
        val = _fixed_pair_bound(self.sx, self.sy, self.ii[k], self.jj[k], self.u2,
                                est[r].reshape(-1, 2), cov[r].reshape(-1, 2, 2),
                                np.repeat(self.maha[r], T))
        return val.reshape(r.size, T)


def _fixed_pair_bound(sx, sy, i, j, u2, x, c, maha) -> np.ndarray:
    """Theorem 4's bound of the pair ``(i[m], j[m])`` at estimate ``x[m]`` (covariance ``c[m]``,
    Mahalanobis where ``maha[m]``), ``(M,)``: as :class:`_PairChooser` but only the pair's two
    vectors (normalised by the longer of the two), in chunks that stay in cache."""
    out = np.empty(x.shape[0])
    step = 1 << 14
    for a in range(0, x.shape[0], step):
        sl = slice(a, a + step)
        vs = []
        for e in (i[sl], j[sl]):
            vx = x[sl, 0] - sx[e]
            vy = x[sl, 1] - sy[e]
            e2 = vx * vx + vy * vy
            if not (e2 > 0).all():
                raise ValueError("an estimate is not finite or sits on a sensor")
            m = maha[sl]
            if m.any():
                dm2 = _mahalanobis_sq(vx, vy, c[sl, 0, 0], c[sl, 0, 1], c[sl, 1, 0], c[sl, 1, 1])
                n2 = np.where(m, dm2, e2)
                f = np.sqrt(n2 / e2)
                vx, vy = vx * f, vy * f
            else:
                n2 = e2
            vs.append((vx, vy, n2))
        inv = 1.0 / np.maximum(vs[0][2], vs[1][2])
        sc = np.sqrt(inv)
        (xi, yi, _), (xj, yj, _) = vs
        out[sl] = _pair_kernel(xi * sc, yi * sc, xj * sc, yj * sc, u2 * inv)
    return out


def _control_basis(controls) -> np.ndarray:
    """Monomials ``1, ux, uy, ux^2, ux uy, uy^2`` of each control, ``(6, K)``."""
    ux, uy = controls[:, 0], controls[:, 1]
    return np.stack([np.ones_like(ux), ux, uy, ux * ux, ux * uy, uy * uy])


def _adversary_moves(eval_ps, o, controls, basis=None, barred=None) -> np.ndarray:
    """Index of the control each run's adversary takes: the first minimiser of
    :func:`target_objective` (its exact values, bit for bit), ``(R,)``.

    With ``a = o - p_i``, ``b = o - p_j`` and the rows ``a + u``, ``b + u``, ``u`` of the matrix
    ``M``, the three 2 x 2 minors of ``M`` are affine in ``u`` (``a x b + (a - b) x u``,
    ``a x u``, ``b x u``), so ``det(M^T M)`` (their sum of squares, Cauchy-Binet) and
    ``tr(M^T M)`` are quadratics in ``u``: one matrix product with the monomials of the controls
    (:func:`_control_basis`) gives both for all runs and controls. ``C^{-1}(M)`` is an
    increasing function of ``t = 4 det / tr^2`` (``C^{-2} = l_min / l_max`` and
    ``t = 4 l_min l_max / (l_min + l_max)^2``), so the controls whose ``det / tr^2`` is within
    ``1e-11`` of the run's minimum contain the exact minimiser (the screen's rounding error is
    some 1e-15). Those few candidates (usually one) are evaluated with
    :func:`target_objective`'s own arithmetic and the first exact minimiser is taken, so the
    pick equals ``argmin`` of :func:`target_objective` over the whole set (tests check it).

    ``barred`` (``(R, K)``, 0 or inf, optional) removes controls from a run's set: runs with
    different control sets share one call with the union of the sets, each run's own set a
    contiguous block of it in its own order.
    """
    if basis is None:
        basis = _control_basis(controls)
    R_ = o.shape[0]
    ax, ay = o[:, 0] - eval_ps[:, 0, 0], o[:, 1] - eval_ps[:, 0, 1]
    bx, by = o[:, 0] - eval_ps[:, 1, 0], o[:, 1] - eval_ps[:, 1, 1]
    # minors as w0 + wx ux + wy uy: (a x b + (a - b) x u), (a x u), (b x u)
    w0 = np.stack([ax * by - ay * bx, np.zeros(R_), np.zeros(R_)])
    wx = np.stack([by - ay, -ay, -by])
    wy = np.stack([ax - bx, ax, bx])
    coef = np.empty((2 * R_, 6))
    coef[:R_, 0] = (w0 * w0).sum(axis=0)
    coef[:R_, 1] = 2 * (w0 * wx).sum(axis=0)
    coef[:R_, 2] = 2 * (w0 * wy).sum(axis=0)
    coef[:R_, 3] = (wx * wx).sum(axis=0)
    coef[:R_, 4] = 2 * (wx * wy).sum(axis=0)
    coef[:R_, 5] = (wy * wy).sum(axis=0)
    coef[R_:, 0] = ax * ax + ay * ay + bx * bx + by * by
    coef[R_:, 1] = 2 * (ax + bx)
    coef[R_:, 2] = 2 * (ay + by)
    coef[R_:, 3] = 3.0
    coef[R_:, 4] = 0.0
    coef[R_:, 5] = 3.0
    dt = coef @ basis  # (2R, K): det and trace
    q = dt[:R_]
    q /= dt[R_:] * dt[R_:]
    if barred is not None:
        q += barred  # 0 or inf
    ar = np.arange(R_)
    ks = q.argmin(axis=1)  # the first screened minimum
    m = q[ar, ks]
    q[ar, ks] = np.inf
    near = q.min(axis=1) <= m + 1e-11  # another control within the screen's margin
    if not near.any():
        return ks
    q[ar, ks] = m
    amb = np.flatnonzero(near)
    rows, kk = np.nonzero(q[amb] <= m[amb, None] + 1e-11)
    rows = amb[rows]
    nxt = o[rows] + controls[kk]
    stack = np.concatenate([nxt[:, None, :] - eval_ps[rows], controls[kk][:, None, :]], axis=1)
    exact = _inverse_condition(stack)
    order = np.lexsort((kk, exact, rows))  # by run, then value, then control index
    first = np.ones(order.size, dtype=bool)
    first[1:] = rows[order][1:] != rows[order][:-1]
    ks[rows[order[first]]] = kk[order[first]]
    return ks


def _run_rows(setup: TrackingSetup, cand, maha, nextpair, tables, controls=None,
              barred=None) -> dict:
    """The batch engine: ``R`` runs of one shared setup, each with its own pair candidates
    (``cand``, ``(R, P)``), metric (``maha``) and adversary (``nextpair``), and noise table.
    An adversary's controls are ``controls`` (default: the setup's) less each run's ``barred``
    ones (see :func:`_adversary_moves`).

    Run ``r`` uses the noise table ``tables[r % B]``. Per step, in the order of
    :func:`simulate`: choose and log, predict ``P + Q``, measure the true position with the
    chosen pair, update with the EKF's gain and the Joseph form
    ``P = (I - K H) P (I - K H)^T + K R K^T`` (filterpy's equations, written out for 2 x 2
    matrices), choose the next pair, move the target.
    """
    R_ = cand.shape[0]
    B, steps, n = tables.shape  # run r uses table r % B
    s = setup.sensor_array
    sx, sy = s[:, 0].copy(), s[:, 1].copy()
    ii, jj = _pair_index(n)
    (q00, q01), (q10, q11) = setup.Q
    (r00, r01), (r10, r11) = setup.R
    q_diag = q01 == 0 and q10 == 0
    r_diag = r01 == 0 and r10 == 0
    # the logs are kept step-major ((steps, R) rows written contiguously), transposed at the end
    noise = np.ascontiguousarray(tables.transpose(1, 0, 2)).reshape(steps, B * n)
    rows_n = (np.arange(R_) % B) * n

    xx = np.full(R_, float(setup.estimate0[0]))
    xy = np.full(R_, float(setup.estimate0[1]))
    (c00, c01), (c10, c11) = setup.cov0
    p00, p01, p10, p11 = (np.full(R_, float(c)) for c in (c00, c01, c10, c11))
    circle = setup.motion == "circle"
    if circle:
        path = circle_truth(setup)  # (steps + 1, 2), the same for every run
    else:
        truth = np.empty((steps + 1, R_, 2))
        truth[0] = setup.start
        if controls is None:
            controls = setup.control_array
        basis = _control_basis(controls)
        anynext = bool(nextpair.any())

    best_log = np.empty((steps, R_), dtype=int)
    bound = np.empty((steps, R_))
    est = np.empty((steps, 2, R_))
    cov = np.empty((steps, 4, R_))

    chooser = _PairChooser(s, cand, maha, setup.u_max**2)
    best, b = chooser(xx, xy, p00, p01, p10, p11)
    for k in range(steps):
        best_log[k] = best
        bound[k] = b
        est[k, 0], est[k, 1] = xx, xy
        cov[k, 0], cov[k, 1], cov[k, 2], cov[k, 3] = p00, p01, p10, p11
        i0, i1 = ii[best], jj[best]
        # measure the true o_k with the pair: z = 1/2 ||p - o||^2 + n
        if circle:
            ox, oy = path[k]
        else:
            ox, oy = truth[k, :, 0], truth[k, :, 1]
        s0x, s0y, s1x, s1y = sx[i0], sy[i0], sx[i1], sy[i1]
        d0x, d0y, d1x, d1y = s0x - ox, s0y - oy, s1x - ox, s1y - oy
        z0 = 0.5 * (d0x * d0x + d0y * d0y) + noise[k].take(rows_n + i0)
        z1 = 0.5 * (d1x * d1x + d1y * d1y) + noise[k].take(rows_n + i1)
        # predict: F = I (adding a zero entry of Q is skipped: x + 0 = x)
        pp00, pp11 = p00 + q00, p11 + q11
        pp01, pp10 = (p01, p10) if q_diag else (p01 + q01, p10 + q10)
        # Jacobian rows H_m = (xhat - p_m)^T and the predicted measurement
        h0x, h0y, h1x, h1y = xx - s0x, xy - s0y, xx - s1x, xy - s1y
        y0 = z0 - 0.5 * (h0x * h0x + h0y * h0y)
        y1 = z1 - 0.5 * (h1x * h1x + h1y * h1y)
        # P H^T, S = H P H^T + R, K = P H^T S^-1
        a00, a10 = pp00 * h0x + pp01 * h0y, pp10 * h0x + pp11 * h0y
        a01, a11 = pp00 * h1x + pp01 * h1y, pp10 * h1x + pp11 * h1y
        s00 = h0x * a00 + h0y * a10 + r00
        s01 = h0x * a01 + h0y * a11
        s10 = h1x * a00 + h1y * a10
        s11 = h1x * a01 + h1y * a11 + r11
        if not r_diag:
            s01, s10 = s01 + r01, s10 + r10
        det = s00 * s11 - s01 * s10
        i00, i01, i10, i11 = s11 / det, -s01 / det, -s10 / det, s00 / det
        k00, k01 = a00 * i00 + a01 * i10, a00 * i01 + a01 * i11
        k10, k11 = a10 * i00 + a11 * i10, a10 * i01 + a11 * i11
        xx = xx + (k00 * y0 + k01 * y1)
        xy = xy + (k10 * y0 + k11 * y1)
        # Joseph form with A = I - K H
        A00 = 1.0 - (k00 * h0x + k01 * h1x)
        A01 = -(k00 * h0y + k01 * h1y)
        A10 = -(k10 * h0x + k11 * h1x)
        A11 = 1.0 - (k10 * h0y + k11 * h1y)
        b00, b01 = A00 * pp00 + A01 * pp10, A00 * pp01 + A01 * pp11
        b10, b11 = A10 * pp00 + A11 * pp10, A10 * pp01 + A11 * pp11
        if r_diag:  # K R with R diagonal (the zero products are exact zeros)
            e00, e01, e10, e11 = k00 * r00, k01 * r11, k10 * r00, k11 * r11
        else:
            e00, e01 = k00 * r00 + k01 * r10, k00 * r01 + k01 * r11
            e10, e11 = k10 * r00 + k11 * r10, k10 * r01 + k11 * r11
        p00 = (b00 * A00 + b01 * A01) + (e00 * k00 + e01 * k01)
        p01 = (b00 * A10 + b01 * A11) + (e00 * k10 + e01 * k11)
        p10 = (b10 * A00 + b11 * A01) + (e10 * k00 + e11 * k01)
        p11 = (b10 * A10 + b11 * A11) + (e10 * k10 + e11 * k11)
        # the next choice depends only on the posterior (a "next-pair" adversary may know it)
        best, b = chooser(xx, xy, p00, p01, p10, p11)
        if not circle:
            eval_ps = s[np.stack([i0, i1], axis=1)]
            if anynext:
                nxt_ps = s[np.stack([ii[best], jj[best]], axis=1)]
                eval_ps = np.where(nextpair[:, None, None], nxt_ps, eval_ps)
            o = truth[k]
            truth[k + 1] = o + controls[_adversary_moves(eval_ps, o, controls, basis, barred)]
    pairs = np.stack([ii, jj], axis=1)[best_log.T]  # (R, steps, 2)
    est = np.ascontiguousarray(est.transpose(2, 0, 1))
    cov = np.ascontiguousarray(cov.transpose(2, 0, 1)).reshape(R_, steps, 2, 2)
    bound = np.ascontiguousarray(bound.T)
    if chooser.single.size:
        bound[chooser.single] = chooser.fixed_bounds(est, cov)
    next_pair = np.stack([ii[best], jj[best]], axis=1)
    if circle:  # the same path for every run: read-only broadcast views
        d = _derived(est, cov, path[None])
        for name in ("truth", "control", "truth_end"):
            d[name] = np.broadcast_to(d[name], (R_,) + d[name].shape[1:])
    else:
        d = _derived(est, cov, np.ascontiguousarray(truth.transpose(1, 0, 2)))
    return dict(pairs=pairs, bound=bound, estimate=est, cov=cov, next_pair=next_pair, **d)


def simulate_many(arms, seeds=None, noise=None) -> dict:
    """Several (setup, strategy) arms over the same noise realisations, batched together.

    Every arm runs once per seed (or noise table), with common noise: run ``b`` of every arm
    uses ``noise_table(setup, seeds[b])``, so it equals ``simulate(setup, strategy,
    seed=seeds[b])`` (the tests check this to rounding). Arms whose setups differ only in
    ``metric``, ``anchor``, ``fixed_pair``, ``adversary`` and ``controls`` share one pass of the
    batch engine (the filter's equations of :func:`simulate` written as NumPy array operations
    over runs); a run does not depend on the other runs of its pass (bit for bit). Identical
    arms are run once and share their result; so are fixed-pair arms that differ only in the
    metric, whose runs are the same (only the logged bound is evaluated with each metric).

    Parameters
    ----------
    arms : mapping
        ``{name: (setup, strategy)}``.
    seeds : iterable of int, optional
    noise : array_like, shape (B, steps, N), optional
        Explicit noise tables instead of seeds.

    Returns
    -------
    dict
        ``{name: BatchResult}`` in the order of ``arms``.
    """
    arms = dict(arms)
    if not arms:
        raise ValueError("no arms to run")
    for name, arm in arms.items():
        try:
            setup, strategy = arm
        except (TypeError, ValueError):
            raise ValueError(f"arm {name!r} must be a (setup, strategy) pair") from None
        if not isinstance(setup, TrackingSetup):
            raise ValueError(
                f"arm {name!r}: setup must be a TrackingSetup, got {type(setup).__name__}"
            )
        if strategy not in STRATEGIES:
            raise ValueError(f"unknown strategy {strategy!r}; known: {STRATEGIES}")
    if (seeds is None) == (noise is None):
        raise ValueError("give either seeds or noise tables")
    if noise is None:
        seeds = tuple(int(x) for x in seeds)
        if not seeds:
            raise ValueError("seeds is empty")
    else:
        given = np.asarray(noise, dtype=float)
        if given.ndim != 3:
            raise ValueError(f"noise must have shape (B, steps, N), got {given.shape}")
        seeds = ()

    # identical runs are computed once (a fixed pair's run does not depend on the metric, only
    # its logged bound does); arms differing only in _ROW_FIELDS share a pass
    def run_key(arm):
        setup, strategy = arm
        if strategy == "fixed-pair" and setup.metric != "mahalanobis":
            return setup.replace(metric="mahalanobis"), strategy
        return arm

    first: dict = {}
    for name, arm in arms.items():
        first.setdefault(run_key(arm), name)
    groups: dict = {}
    for name in first.values():
        setup = arms[name][0]
        key = tuple(getattr(setup, f.name) for f in dataclasses.fields(setup)
                    if f.name not in _ROW_FIELDS)
        groups.setdefault(key, []).append(name)
    drawn: dict = {}
    out = {}
    for names in groups.values():
        base = arms[names[0]][0]
        if seeds:
            tkey = (base.steps, base.n_sensors, base.noise_std)
            if tkey not in drawn:
                drawn[tkey] = np.stack([noise_table(base, x) for x in seeds])
            tables = drawn[tkey]
        else:
            tables = np.stack([_check_noise(base, t) for t in given])
        B = tables.shape[0]
        cand = np.concatenate([np.tile(_candidates(*arms[n]), (B, 1)) for n in names])
        maha = np.repeat([arms[n][0].metric == "mahalanobis" for n in names], B)
        nxt = np.repeat([arms[n][0].adversary == "next-pair" for n in names], B)
        controls = barred = None
        if base.motion == "adversarial":
            # the union of the arms' control sets, one contiguous block per distinct set
            sets, block = [], []
            for n in names:
                c = arms[n][0].control_array
                hit = [b for b, x in enumerate(sets) if np.array_equal(x, c)]
                if not hit:
                    sets.append(c)
                block.append(hit[0] if hit else len(sets) - 1)
            if len(sets) > 1:
                controls = np.concatenate(sets)
                edges = np.cumsum([0] + [len(x) for x in sets])
                barred = np.full((len(names) * B, len(controls)), np.inf)
                for g, b in enumerate(block):
                    barred[g * B : (g + 1) * B, edges[b] : edges[b + 1]] = 0.0
        res = _run_rows(base, cand, maha, nxt, tables, controls, barred)
        for g, n in enumerate(names):
            sl = slice(g * B, (g + 1) * B)
            setup, strategy = arms[n]
            out[n] = BatchResult(
                setup=setup, strategy=strategy, seed=None, seeds=seeds, noise=tables,
                **{k: v[sl] for k, v in res.items()},
            )
    result = {}
    for n, arm in arms.items():
        ref = first[run_key(arm)]
        if arm == arms[ref]:
            result[n] = out[ref]
            continue
        # the same run as arm `ref` with the other metric: only the logged bound differs
        setup, r = arm[0], out[ref]
        i, j = sorted(setup.fixed_pair)
        M = r.bound.size
        s = setup.sensor_array
        bound = _fixed_pair_bound(
            s[:, 0].copy(), s[:, 1].copy(), np.full(M, i), np.full(M, j), setup.u_max**2,
            r.estimate.reshape(-1, 2), r.cov.reshape(-1, 2, 2),
            np.full(M, setup.metric == "mahalanobis"),
        ).reshape(r.bound.shape)
        result[n] = dataclasses.replace(r, setup=setup, bound=bound)
    return result


def simulate_batch(setup: TrackingSetup, strategy: str, seeds=None, noise=None) -> BatchResult:
    """Many runs of one strategy at once: :func:`simulate` vectorised over noise realisations.

    The same equations as filterpy's ``predict`` and ``update`` (Joseph form) in the same order,
    written as NumPy array operations over runs (:func:`simulate_many`), so a run equals
    ``simulate(setup, strategy, seed=s)`` to rounding (checked in the tests).

    Parameters
    ----------
    seeds : iterable of int, optional
        One run per seed with ``noise_table(setup, seed)``.
    noise : array_like, shape (B, steps, N), optional
        Explicit noise tables instead of seeds.
    """
    if strategy not in STRATEGIES:
        raise ValueError(f"unknown strategy {strategy!r}; known: {STRATEGIES}")
    return simulate_many({strategy: (setup, strategy)}, seeds=seeds, noise=noise)[strategy]


def monte_carlo(
    setup: TrackingSetup,
    n_seeds: int = 100,
    strategies: Iterable[str] = STRATEGIES,
    first_seed: int = 0,
    batch: int = 1000,
) -> dict[str, BatchResult]:
    """The strategies over ``n_seeds`` noise realisations, seeds ``first_seed, first_seed + 1, ..``.

    Trial ``t`` uses ``noise_table(setup, first_seed + t)`` for every strategy (common noise),
    so trial ``t`` of a strategy equals ``simulate(setup, strategy, seed=first_seed + t)``.
    All strategies run together (:func:`simulate_many`), ``batch`` seeds at a time.

    Returns
    -------
    dict
        ``{strategy: BatchResult}`` with arrays of leading size ``n_seeds``.
    """
    if int(n_seeds) < 1:
        raise ValueError(f"n_seeds must be at least 1, got {n_seeds}")
    if int(batch) < 1:
        raise ValueError(f"batch must be at least 1, got {batch}")
    strategies = list(strategies)
    if not strategies:
        return {}
    seeds = list(range(int(first_seed), int(first_seed) + int(n_seeds)))
    arms = {s: (setup, s) for s in strategies}
    parts = [simulate_many(arms, seeds=seeds[i : i + batch]) for i in range(0, len(seeds), batch)]
    if len(parts) == 1:
        return parts[0]
    return {
        s: BatchResult(
            setup=setup,
            strategy=s,
            seed=None,
            seeds=tuple(seeds),
            **{
                f.name: np.concatenate([getattr(p[s], f.name) for p in parts])
                for f in dataclasses.fields(TrackingResult)
                if f.name not in ("setup", "strategy", "seed")
            },
        )
        for s in strategies
    }


# --------------------------------------------------------------------------------------------
# Statistics
# --------------------------------------------------------------------------------------------


#: Relative difference below which two logged values count as equal when strategies are compared.
TIE_RTOL = 1e-9


def clearly_lower(a, b, rtol: float = TIE_RTOL) -> np.ndarray:
    """``a < b`` by more than ``rtol`` times the larger magnitude, elementwise.

    Two strategies that pick the same pairs for long enough drive their filters to the same
    state, equal up to rounding; whether such values compare as exactly equal then depends on the
    order of floating-point operations (and could differ between engines or machines). Counting
    only clear differences makes the win fractions independent of that: a tie wins for neither.
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a < b - rtol * np.maximum(np.abs(a), np.abs(b))


def compare_strategies(mc: dict, reference: str = "best-pair", skip_first: bool = True) -> dict:
    """Monte Carlo statistics of Fig. 6: means, spreads and how often ``reference`` wins.

    Step 1 logs the values before any update, identical for all strategies by construction;
    ``skip_first`` leaves it out of the win fractions and overall means.

    Returns
    -------
    dict
        ``{"strategies": {name: {...}}, "wins": {other: {...}}}``. Per strategy: overall
        ``mean_error``, ``mean_trace``, ``mean_bound`` (over seeds and steps), their spread
        ``sd_*`` (standard deviation over seeds of the per-run means), ``switches`` (mean pair
        changes per run) and per-step arrays ``step_mean_*`` and ``step_sd_*`` (over seeds).
        Per other strategy: ``error_pointwise`` / ``trace_pointwise``, the fraction of
        (seed, step) with the reference lower; ``error_stepmean`` / ``trace_stepmean``,
        the fraction of steps where the reference's Monte Carlo mean is lower;
        ``bound_pointwise``, the fraction with the reference's bound higher; ``run_error`` /
        ``run_trace``, the fraction of runs with the reference's run mean lower. Lower and higher
        mean by more than :data:`TIE_RTOL` relatively (:func:`clearly_lower`): ties count for
        neither.
    """
    steps = next(iter(mc.values())).error.shape[1]
    sl = slice(1, None) if skip_first and steps > 1 else slice(None)
    stats = {}
    for name, r in mc.items():
        d = {}
        for key, arr in (("error", r.error), ("trace", r.trace_cov), ("bound", r.bound)):
            a = arr[:, sl]
            d[f"mean_{key}"] = float(a.mean())
            d[f"sd_{key}"] = float(a.mean(axis=1).std(ddof=1)) if a.shape[0] > 1 else 0.0
            d[f"step_mean_{key}"] = arr.mean(axis=0)
            d[f"step_sd_{key}"] = arr.std(axis=0, ddof=1) if arr.shape[0] > 1 else 0 * arr[0]
        d["switches"] = float(r.switches.mean())
        stats[name] = d
    ref = mc[reference]
    wins = {}
    for name, r in mc.items():
        if name == reference:
            continue
        e1, e2 = ref.error[:, sl], r.error[:, sl]
        t1, t2 = ref.trace_cov[:, sl], r.trace_cov[:, sl]
        wins[name] = {
            "error_pointwise": float(clearly_lower(e1, e2).mean()),
            "trace_pointwise": float(clearly_lower(t1, t2).mean()),
            "error_stepmean": float(clearly_lower(e1.mean(0), e2.mean(0)).mean()),
            "trace_stepmean": float(clearly_lower(t1.mean(0), t2.mean(0)).mean()),
            "bound_pointwise": float(clearly_lower(r.bound[:, sl], ref.bound[:, sl]).mean()),
            "run_error": float(clearly_lower(e1.mean(1), e2.mean(1)).mean()),
            "run_trace": float(clearly_lower(t1.mean(1), t2.mean(1)).mean()),
        }
    return {"strategies": stats, "wins": wins}


def _rank(a: np.ndarray) -> np.ndarray:
    """Ranks ``1..n`` along the last axis, ties by their average rank (``scipy.stats.rankdata``'s
    ``"average"`` method; the tests compare the two). A slice with a NaN gets NaN ranks."""
    a = np.asarray(a, dtype=float)
    shape = a.shape
    n = shape[-1] if a.ndim else 1
    flat = a.reshape(-1, n)
    m = flat.shape[0]
    order = np.argsort(flat, axis=1)  # tie order does not matter: ties share one rank
    srt = np.take_along_axis(flat, order, axis=1)
    new = np.ones((m, n), dtype=bool)
    new[:, 1:] = srt[:, 1:] != srt[:, :-1]  # a tie group starts here
    starts = np.flatnonzero(new.ravel())
    sizes = np.diff(np.append(starts, m * n))
    avg = (starts % n) + (sizes + 1) / 2.0  # 1-based average position of each group
    ranks_sorted = np.repeat(avg, sizes).reshape(m, n)
    ranks = np.empty_like(ranks_sorted)
    np.put_along_axis(ranks, order, ranks_sorted, axis=1)
    ranks[np.isnan(flat).any(axis=1)] = np.nan
    return ranks.reshape(shape)


def spearman(a, b, axis: int = -1) -> np.ndarray:
    """Spearman rank correlation of ``a`` and ``b`` along ``axis`` (ties by average rank)."""
    ra = np.moveaxis(_rank(np.moveaxis(np.asarray(a, dtype=float), axis, -1)), -1, axis)
    rb = np.moveaxis(_rank(np.moveaxis(np.asarray(b, dtype=float), axis, -1)), -1, axis)
    ra = ra - ra.mean(axis=axis, keepdims=True)
    rb = rb - rb.mean(axis=axis, keepdims=True)
    num = (ra * rb).sum(axis=axis)
    den = np.sqrt((ra * ra).sum(axis=axis) * (rb * rb).sum(axis=axis))
    with np.errstate(invalid="ignore", divide="ignore"):
        return num / den  # NaN where one series is constant


@dataclass(frozen=True)
class Entrapment:
    """Measures of how "entrapped" an adversarial target is (Fig. 7).

    Attributes
    ----------
    reach : float
        How far the target could go: ``steps * max ||u||`` of its control set.
    net_displacement : float
        ``||o_end - o_start||``.
    max_from_start : float
        Largest distance from the start over the run.
    radius : float
        Radius of the smallest disc about the path's centroid containing the whole path.
    path_length : float
        Total distance travelled.
    bound_mean, bound_min : float
        The sensors' pair bound over the run.
    icn_mean, icn_min : float
        The exact ``C^{-1}`` the sensors face (``true_icn``), steps 2.. (step 1 has no control).
    objective_mean : float
        Mean of the value the target aimed at (its minimised ``C^{-1}``).
    switches : int
        Pair changes over ``steps - 1`` transitions.
    switch_gain : float
        Mean of ``true_icn[k+1] - objective[k]`` over transitions where the pair switched: what
        the switch gave back to the sensors.
    mean_error, mean_trace : float
        Tracking quality over the run.
    """

    reach: float
    net_displacement: float
    max_from_start: float
    radius: float
    path_length: float
    bound_mean: float
    bound_min: float
    icn_mean: float
    icn_min: float
    objective_mean: float
    switches: int
    transitions: int
    switch_gain: float
    mean_error: float
    mean_trace: float


def entrapment(result: TrackingResult) -> Entrapment:
    """Measure how well the adversarial target of Fig. 7 escapes (:class:`Entrapment`)."""
    path = np.vstack([result.truth, result.truth[-1] + result.control[-1]])
    c = path.mean(axis=0)
    ctrl = result.setup.control_array
    reach = result.steps * float(np.hypot(ctrl[:, 0], ctrl[:, 1]).max())
    sw = result.switched
    gain = result.true_icn[1:][sw] - result.objective[:-1][sw]
    return Entrapment(
        reach=reach,
        net_displacement=float(np.hypot(*(path[-1] - path[0]))),
        max_from_start=float(np.hypot(*(path - path[0]).T).max()),
        radius=float(np.hypot(*(path - c).T).max()),
        path_length=float(np.hypot(*np.diff(path, axis=0).T).sum()),
        bound_mean=float(result.bound.mean()),
        bound_min=float(result.bound.min()),
        icn_mean=float(result.true_icn[1:].mean()) if result.steps > 1 else float("nan"),
        icn_min=float(result.true_icn[1:].min()) if result.steps > 1 else float("nan"),
        objective_mean=float(result.objective.mean()),
        switches=int(sw.sum()),
        transitions=int(sw.size),
        switch_gain=float(gain.mean()) if gain.size else 0.0,
        mean_error=float(result.error.mean()),
        mean_trace=float(result.trace_cov.mean()),
    )


#: What "entrapped" means in this book (fixed before looking at the runs): the target stays
#: within ``reach_fraction`` of its reach (``steps * max ||u||``) from its start, the sensors'
#: bound averages at least ``bound_mean`` and the exact C^-1 they face never drops below
#: ``icn_min``.
ENTRAPMENT_CRITERIA = {"reach_fraction": 0.2, "bound_mean": 0.5, "icn_min": 0.1}


def is_entrapped(e: Entrapment, reach_fraction=None, bound_mean=None, icn_min=None) -> bool:
    """Whether one adversarial run meets :data:`ENTRAPMENT_CRITERIA` (or the values given)."""
    c = dict(ENTRAPMENT_CRITERIA)
    given = {"reach_fraction": reach_fraction, "bound_mean": bound_mean, "icn_min": icn_min}
    c.update({k: v for k, v in given.items() if v is not None})
    return bool(
        e.max_from_start <= c["reach_fraction"] * e.reach
        and e.bound_mean >= c["bound_mean"]
        and e.icn_min >= c["icn_min"]
    )


def entrapment_summary(batch: BatchResult) -> dict:
    """:func:`entrapment` of every run of a batch, summarised.

    Returns
    -------
    dict
        ``entrapped`` (fraction of runs meeting :data:`ENTRAPMENT_CRITERIA`), the largest
        ``max_from_start``, ``reach``, the mean and range of the per-run mean bound, the
        smallest ``icn_min``, the mean ``icn_mean``, mean ``switches`` and ``mean_error``, and
        ``runs`` (the list of :class:`Entrapment`).
    """
    batch.true_icn, batch.objective  # computed once for all runs
    es = [entrapment(batch.run(b)) for b in range(batch.n_runs)]
    return {
        "entrapped": float(np.mean([is_entrapped(e) for e in es])),
        "max_from_start": max(e.max_from_start for e in es),
        "reach": es[0].reach,
        "bound_mean": float(np.mean([e.bound_mean for e in es])),
        "bound_mean_range": (min(e.bound_mean for e in es), max(e.bound_mean for e in es)),
        "icn_min": min(e.icn_min for e in es),
        "icn_mean": float(np.mean([e.icn_mean for e in es])),
        "switches": float(np.mean([e.switches for e in es])),
        "mean_error": float(np.mean([e.mean_error for e in es])),
        "runs": es,
    }


def adversary_variants(setup: TrackingSetup, n_radii: int, n_angles: int) -> dict:
    """The paper's adversary and stronger ones (Section V-B), as setups.

    ``"paper"``: the setup as given; ``"next-pair"``: the target knows the pair the sensors
    will use next; ``"disc"``: controls on a polar grid of the whole disc ``||u|| <= u_max``
    (``1 + n_radii * n_angles`` controls, :func:`disc_controls`); ``"disc, next-pair"``: both.
    """
    disc = disc_controls(setup.u_max, n_radii, n_angles)
    return {
        "paper": setup,
        "next-pair": setup.replace(adversary="next-pair"),
        "disc": setup.replace(controls=disc),
        "disc, next-pair": setup.replace(controls=disc, adversary="next-pair"),
    }


def switch_mechanism(result: TrackingResult) -> dict:
    """How the pair reacts when the adversary closes in on a sensor (Fig. 7 caption).

    For each transition ``k -> k + 1``: did the target move closer to one of the two sensors of
    step ``k``'s pair, did the pair switch, and did the switch give the sensors a larger exact
    ``C^{-1}`` (``true_icn[k+1]``) than the value the target aimed at with the old pair
    (``objective[k]``)?

    Returns
    -------
    dict
        ``closer`` (transitions where the target got closer to a sensor of the pair),
        ``switch_if_closer`` and ``switch_if_not`` (switch rates), ``switches``,
        ``raised`` (fraction of switches with ``true_icn[k+1] > objective[k]``) and
        ``mean_gain`` (mean of ``true_icn[k+1] - objective[k]`` over switches).
    """
    s = result.setup.sensor_array
    ps = s[result.pairs]
    before = np.hypot(*(result.truth[:, None, :] - ps).transpose(2, 0, 1)).min(axis=1)
    after_pos = result.truth + result.control
    after = np.hypot(*(after_pos[:, None, :] - ps).transpose(2, 0, 1)).min(axis=1)
    closer = (after < before)[:-1]
    sw = result.switched
    gain = result.true_icn[1:] - result.objective[:-1]
    return {
        "transitions": int(sw.size),
        "closer": int(closer.sum()),
        "switch_if_closer": float(sw[closer].mean()) if closer.any() else float("nan"),
        "switch_if_not": float(sw[~closer].mean()) if (~closer).any() else float("nan"),
        "switches": int(sw.sum()),
        "raised": float((gain[sw] > 0).mean()) if sw.any() else float("nan"),
        "mean_gain": float(gain[sw].mean()) if sw.any() else float("nan"),
    }


def switch_back_fraction(batch: BatchResult) -> float:
    """Fraction of the pair switches that return at once to the pair of the step before.

    Over all runs of ``batch`` and the transitions ``k -> k + 1`` with ``k >= 2``: a switch
    (``pairs[k + 1] != pairs[k]``) counts as going back when ``pairs[k + 1] == pairs[k - 1]``.
    Chattering between two nearly equal pairs shows as a high fraction.
    """
    sw = batch.switched[:, 1:]
    back = (batch.pairs[:, 2:] == batch.pairs[:, :-2]).all(axis=2) & sw
    return float(back.sum() / max(sw.sum(), 1))


def switch_rate(batch: BatchResult) -> np.ndarray:
    """Fraction of runs whose pair changes at each transition ``k -> k + 1``, ``(steps - 1,)``."""
    return batch.switched.mean(axis=0)


def bound_correlation(batch: BatchResult, bound: str = "own", skip_first: bool = True) -> dict:
    """Spearman correlation, within each run and over time, of the bound with error and trace.

    Section V-A: "higher C^-1 correlates with lower epsilon and trace(Sigma)". ``bound="own"``
    uses the logged bound (the setup's metric, Mahalanobis in the published runs, which itself
    shrinks as ``Sigma`` grows); ``bound="euclidean"`` re-evaluates the chosen pairs at the
    estimates with Euclidean distances, i.e. the geometry alone.

    Returns
    -------
    dict
        ``error`` and ``trace``: per-run correlations ``(B,)``.
    """
    sl = slice(1, None) if skip_first else slice(None)
    if bound == "own":
        b = batch.bound
    elif bound == "euclidean":
        shape = batch.bound.shape
        b = pair_bound_series(
            batch.setup, batch.estimate.reshape(-1, 2), batch.pairs.reshape(-1, 2)
        ).reshape(shape)
    else:
        raise ValueError(f"bound must be 'own' or 'euclidean', got {bound!r}")
    return {
        "error": spearman(b[:, sl], batch.error[:, sl]),
        "trace": spearman(b[:, sl], batch.trace_cov[:, sl]),
    }


def mirror_point(points, a, b) -> np.ndarray:
    """Reflection of ``points`` (..., 2) across the line through ``a`` and ``b``.

    Two range measurements cannot tell ``o`` from its mirror image across the baseline of the
    two sensors; a filter fed by one fixed pair can lock onto the mirror image.
    """
    a = np.asarray(a, dtype=float)
    d = np.asarray(b, dtype=float) - a
    d = d / np.hypot(*d)
    v = np.asarray(points, dtype=float) - a
    return a + 2 * (v @ d)[..., None] * d - v


def track_loss(batch: BatchResult, threshold: float = 0.5) -> dict:
    """Runs of a fixed pair whose estimate ends at the mirror image of the target.

    A run is *lost* when its mean error exceeds ``threshold``. For each run, also whether the
    last estimate is closer to the target's mirror image across the pair's baseline than to the
    target, and the first step from which it stays so.

    Returns
    -------
    dict
        ``lost`` (B,) bool, ``mirrored`` (B,) bool, ``flip_step`` (B,) int (1-based; 0 if never).
    """
    s = batch.setup.sensor_array
    i, j = batch.pairs[0, 0]
    m = mirror_point(batch.truth, s[i], s[j])
    dm = np.hypot(*(batch.estimate - m).transpose(2, 0, 1))
    closer = dm < batch.error
    # first step from which the estimate stays closer to the mirror image
    stays = np.flip(np.logical_and.accumulate(np.flip(closer, axis=1), axis=1), axis=1)
    flip = np.where(stays.any(axis=1), stays.argmax(axis=1) + 1, 0)
    return {
        "lost": batch.error.mean(axis=1) > threshold,
        "mirrored": closer[:, -1],
        "flip_step": flip,
    }


def partner_arms(setup: TrackingSetup) -> dict:
    """Strategy (3) with each partner ``j`` of the anchor: ``{j: (setup, "fixed-pair")}``, for
    :func:`simulate_many` (the arms of :func:`partner_study`)."""
    return {
        j: (setup.replace(fixed_pair=(setup.anchor, j)), "fixed-pair")
        for j in range(setup.n_sensors)
        if j != setup.anchor
    }


def partner_summary(runs: dict) -> dict:
    """Monte Carlo means per partner from the runs of :func:`partner_arms` (see
    :func:`partner_study`)."""
    out = {}
    for j, r in runs.items():
        run_err = r.error[:, 1:].mean(axis=1)
        out[j] = {
            "mean_bound": float(r.bound[:, 1:].mean()),
            "mean_error": float(run_err.mean()),
            "median_error": float(np.median(run_err)),
            "mean_trace": float(r.trace_cov[:, 1:].mean()),
            "lost": float(track_loss(r)["lost"].mean()),
        }
    return out


def partner_study(setup: TrackingSetup, n_seeds: int, first_seed: int = 0) -> dict:
    """Strategy (3) with every partner of the anchor: Monte Carlo means per partner.

    Checks the paper's choice of ``s_1`` as ``s_2``'s fixed partner ("it gives the best
    performance amongst all other sensors, on an average, for the circular trajectory"). All
    partners run over the same seeds in one batched pass (:func:`partner_arms`,
    :func:`simulate_many`); partner ``j`` equals ``monte_carlo(setup.replace(fixed_pair=(anchor,
    j)), n_seeds, ["fixed-pair"], first_seed)``.

    Returns
    -------
    dict
        ``{partner: {"mean_bound", "mean_error", "median_error", "mean_trace", "lost"}}`` with
        ``partner`` 0-based and ``lost`` the fraction of runs of :func:`track_loss`.
    """
    if int(n_seeds) < 1:
        raise ValueError(f"n_seeds must be at least 1, got {n_seeds}")
    seeds = range(int(first_seed), int(first_seed) + int(n_seeds))
    return partner_summary(simulate_many(partner_arms(setup), seeds=seeds))


# --------------------------------------------------------------------------------------------
# Pictures (Fig. 4 snapshots and the animation)
# --------------------------------------------------------------------------------------------


def cov_ellipse(mean, cov, chi2: float = CHI2_2DOF_9973, n: int = 100) -> np.ndarray:
    """Boundary of ``{x : (x - mean)^T cov^-1 (x - mean) <= chi2}``, ``(n, 2)`` points.

    The default ``chi2 = 11.82`` is the 99.73 % ellipse of Fig. 4.
    """
    w, v = np.linalg.eigh(np.asarray(cov, dtype=float))
    t = np.linspace(0, 2 * np.pi, n)
    circle = np.column_stack([np.cos(t), np.sin(t)])
    return np.asarray(mean, dtype=float) + (circle * np.sqrt(chi2 * np.clip(w, 0, None))) @ v.T


_SUBSCRIPT = str.maketrans("0123456789", "".join(chr(0x2080 + d) for d in range(10)))


def sensor_label(i: int) -> str:
    """``"s"`` with the 1-based index of sensor ``i`` (0-based) as Unicode subscript digits:
    the figures' sensor names, plain text (no mathtext to parse)."""
    return "s" + str(int(i) + 1).translate(_SUBSCRIPT)


def draw_sensors(ax, sensors, *, ms: float = 8, label: str | None = None):
    """Sensors as blue triangles named ``s1..sN`` (:func:`sensor_label`) on ``ax``."""
    s = np.asarray(sensors, dtype=float)
    ax.plot(*s.T, "^", color="tab:blue", ms=ms, **({} if label is None else {"label": label}))
    for n, p in enumerate(s):
        ax.annotate(sensor_label(n), p, textcoords="offset points", xytext=(4, 4), fontsize=8)


def draw_snapshot(ax, result: TrackingResult, k: int, *, legend: bool = True, ellipse_scale=1.0):
    """Draw step ``k`` (1-based) of a run as in Fig. 4 on ``ax``.

    Sensors (labelled ``s1..sN``), the true path so far and the target, the estimate with its
    99.73 % covariance ellipse (scaled by ``ellipse_scale`` if wanted for visibility) and lines
    from the chosen pair to the estimate. Returns the artists.
    """
    i = k - 1
    s = result.setup.sensor_array
    draw_sensors(ax, s, label="sensors")
    for j in result.pairs[i]:
        ax.plot(*np.array([s[j], result.estimate[i]]).T, "-", color="tab:green", lw=1)
    ax.plot(*result.truth[: i + 1].T, "-", color="0.6", lw=1, label="true path")
    ax.plot(*result.truth[i], "o", color="k", ms=5, label="target o\u2096")
    ax.plot(*result.estimate[i], "x", color="tab:red", ms=7, label="estimate \u00f4\u2096")
    e = cov_ellipse(result.estimate[i], ellipse_scale**2 * result.cov[i])
    ax.plot(*e.T, "-", color="tab:red", lw=1, label="99.73 % ellipse")
    ax.set_aspect("equal")
    i0, j0 = result.pairs[i]
    ax.set_title(f"k = {k}, pair ({sensor_label(i0)}, {sensor_label(j0)})", fontsize=9)
    if legend:
        ax.legend(fontsize=6, loc="lower left")
    return ax


class RunAnimation:
    """An animation of a tracking run (:func:`animate`), rendered by blitting.

    The static part (axes, sensors, labels) is drawn once; each frame restores it and draws only
    the moving artists (chosen pair, true path, target, estimate, ellipse, caption), then keeps
    the canvas as a PNG. :meth:`to_jshtml` wraps the frames in matplotlib's JavaScript player
    (:class:`matplotlib.animation.HTMLWriter`), like ``FuncAnimation.to_jshtml``;
    :meth:`func_animation` gives a :class:`matplotlib.animation.FuncAnimation` of the same frames
    for other writers.

    Attributes
    ----------
    fig : matplotlib.figure.Figure
        The (closed) figure.
    frames : list of int
        The steps shown (1-based).
    interval : float
        Milliseconds per frame.
    """

    def __init__(self, fig, update, artists, frames, interval):
        self.fig = fig
        self.frames = list(frames)
        self.interval = float(interval)
        self._update = update
        self._artists = tuple(artists)
        self._html = None

    def draw(self, k: int):
        """Set the moving artists to step ``k``; returns them."""
        self._update(k)
        return self._artists

    def png_frames(self) -> list:
        """Every frame as PNG bytes (blitting on an Agg canvas)."""
        from io import BytesIO

        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from PIL import Image

        canvas = FigureCanvasAgg(self.fig)
        for a in self._artists:
            a.set_animated(True)
        canvas.draw()  # everything but the moving artists
        background = canvas.copy_from_bbox(self.fig.bbox)
        out = []
        for k in self.frames:
            self.draw(k)
            canvas.restore_region(background)
            for a in self._artists:
                self.fig.draw_artist(a)
            w, h = canvas.get_width_height(physical=True)
            img = Image.frombuffer("RGBA", (w, h), canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
            f = BytesIO()
            img.convert("RGB").save(f, format="png", compress_level=3)  # the figure is opaque
            out.append(f.getvalue())
        return out

    def to_jshtml(self, default_mode: str = "loop") -> str:
        """HTML/JS player with the frames embedded (matplotlib's ``HTMLWriter`` template)."""
        if self._html is None:
            import base64
            import tempfile
            from pathlib import Path

            from matplotlib.animation import HTMLWriter

            frames = self.png_frames()

            class _Writer(HTMLWriter):
                def grab_frame(self, **kwargs):
                    self._saved_frames.append(base64.encodebytes(frames.pop(0)).decode("ascii"))

            with tempfile.TemporaryDirectory() as tmp:
                path = Path(tmp, "anim.html")
                writer = _Writer(fps=1000.0 / self.interval, embed_frames=True,
                                 default_mode=default_mode)
                writer.setup(self.fig, path, dpi=self.fig.dpi)
                for _ in self.frames:
                    writer.grab_frame()
                writer.finish()
                self._html = path.read_text()
        return self._html

    def _repr_html_(self):
        return self.to_jshtml()

    def func_animation(self):
        """The same frames as a :class:`matplotlib.animation.FuncAnimation` (blitted)."""
        from matplotlib.animation import FuncAnimation

        return FuncAnimation(self.fig, self.draw, frames=self.frames, interval=self.interval,
                             blit=True)


def animate(result: TrackingResult, every: int = 3, dpi: int = 50, figsize=(4.0, 4.0), interval=80):
    """An animation of a run (:class:`RunAnimation`): every ``every``-th step and the last.

    Each frame shows what :func:`draw_snapshot` draws (Fig. 4): sensors, the chosen pair's lines
    to the estimate, the true path so far and the target, the estimate and its 99.73 %
    covariance ellipse, and the step and pair as a caption. Show it in a notebook with
    ``IPython.display.HTML(animation_html(anim))``; the figure is closed so that it is not also
    shown as a still.
    """
    import matplotlib.pyplot as plt

    if int(every) < 1:
        raise ValueError(f"every must be at least 1, got {every}")
    s = result.setup.sensor_array
    fig, ax = plt.subplots(figsize=figsize, dpi=dpi)
    pts = np.vstack([s, result.truth, result.estimate])
    lo, hi = pts.min(axis=0) - 1.0, pts.max(axis=0) + 1.0
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    draw_sensors(ax, s, ms=7)
    (links,) = ax.plot([], [], "-", color="tab:green", lw=1)
    (path,) = ax.plot([], [], "-", color="0.6", lw=1)
    (target,) = ax.plot([], [], "o", color="k", ms=4)
    (est,) = ax.plot([], [], "x", color="tab:red", ms=6)
    (ell,) = ax.plot([], [], "-", color="tab:red", lw=1)
    title = ax.set_title(" ", fontsize=9)
    frames = list(range(1, result.steps + 1, int(every)))
    if frames[-1] != result.steps:
        frames.append(result.steps)

    def frame(k):
        i = k - 1
        e = result.estimate[i]
        a, b = s[result.pairs[i]]
        links.set_data([a[0], e[0], b[0]], [a[1], e[1], b[1]])
        path.set_data(*result.truth[: i + 1].T)
        target.set_data([result.truth[i, 0]], [result.truth[i, 1]])
        est.set_data([e[0]], [e[1]])
        ell.set_data(*cov_ellipse(e, result.cov[i]).T)
        i0, j0 = result.pairs[i]
        title.set_text(f"k = {k}, pair ({sensor_label(i0)}, {sensor_label(j0)})")

    plt.close(fig)
    return RunAnimation(fig, frame, (links, path, target, est, ell, title), frames, interval)


def animation_html(anim, uid: str = "anim") -> str:
    """Self-contained, stable HTML/JS for an animation (``anim.to_jshtml()``): a
    :class:`RunAnimation` or a matplotlib animation.

    ``to_jshtml`` names its elements with a random id and links Font Awesome from a CDN for its
    buttons. The id is replaced by ``uid`` so the stored notebook does not change from run to
    run, and the external stylesheet is dropped so the page fetches nothing at view time (the
    book's theme ships Font Awesome itself).
    """
    import re

    html = anim.to_jshtml()
    m = re.search(r'id="_anim_img([0-9a-f]+)"', html)
    if m is None:
        raise ValueError("not the HTML of matplotlib's to_jshtml: no _anim_img element")
    html = html.replace(m.group(1), uid)
    return re.sub(r'<link[^>]*href="(?:https?:)?//[^"]*"[^>]*>\s*', "", html)

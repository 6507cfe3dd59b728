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
reference), and :func:`simulate_batch` runs many noise seeds at once with the same equations in
vectorised NumPy (for the Monte Carlo, :func:`monte_carlo`). The tests check they agree.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Iterable

import numpy as np

from ._validate import as_point, as_points, check_distinct, check_spd2
from .bound_checks import disc_controls
from .bounds import pair_bounds
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
    "bound_correlation",
    "mirror_point",
    "track_loss",
    "partner_study",
    "PUBLISHED_CIRCLE",
    "PUBLISHED_ADVERSARIAL",
    "cov_ellipse",
    "CHI2_2DOF_9973",
    "draw_snapshot",
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

    Parameters
    ----------
    points : array_like, shape (K, 2)
        Where to evaluate (e.g. a run's ``estimate`` or ``truth``).
    pairs : array_like of int, shape (K, 2)
    cov : array_like, shape (K, 2, 2), optional
        Mahalanobis distances in these covariances; Euclidean when omitted.
    """
    pts = np.asarray(points, dtype=float)
    pr = np.asarray(pairs)
    W = pair_bounds(setup.sensors, pts, setup.u_max, cov=cov)
    return W[pr[:, 0], pr[:, 1], np.arange(pts.shape[0])]


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
    objective : (steps,)
        ``C^{-1}([o_{k+1} - p_i; o_{k+1} - p_j; u_k])`` with the pair of step ``k``: the value the
        adversary of Section V-B minimises.
    true_icn : (steps,)
        The exact ``C^{-1}([o_k - p_i; o_k - p_j; u_{k-1}])`` the sensors face at step ``k``
        with the pair they chose (``u_0 = 0``).
    next_pair : (2,) int
        The pair the sensors would choose after the last step.
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
    objective: np.ndarray
    true_icn: np.ndarray
    next_pair: np.ndarray

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
        return TrackingResult(setup=self.setup, strategy=self.strategy, seed=seed, **arrays)


# --------------------------------------------------------------------------------------------
# The reference engine: filterpy, one run
# --------------------------------------------------------------------------------------------


def _derived(sensors, pairs, est, cov, truth_ext) -> dict:
    """Arrays shared by both engines, for any leading shape: errors, traces, controls, C^{-1}.

    ``truth_ext`` holds ``o_1 .. o_{steps+1}`` (the last is where the target moves after the
    last step).
    """
    ps = sensors[pairs]  # (..., steps, 2, 2)
    control = truth_ext[..., 1:, :] - truth_ext[..., :-1, :]
    prev = np.concatenate([np.zeros_like(control[..., :1, :]), control[..., :-1, :]], axis=-2)
    cur, nxt = truth_ext[..., :-1, :], truth_ext[..., 1:, :]
    obj = _inverse_condition(
        np.concatenate([nxt[..., None, :] - ps, control[..., None, :]], axis=-2)
    )
    icn = _inverse_condition(np.concatenate([cur[..., None, :] - ps, prev[..., None, :]], axis=-2))
    diff = est - cur
    return {
        "error": np.hypot(diff[..., 0], diff[..., 1]),
        "trace_cov": cov[..., 0, 0] + cov[..., 1, 1],
        "truth": cur,
        "control": control,
        "objective": obj,
        "true_icn": icn,
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
        **_derived(s, pairs, est, cov, truth),
    )


# --------------------------------------------------------------------------------------------
# The batch engine: many seeds at once, same equations in NumPy
# --------------------------------------------------------------------------------------------


def simulate_batch(setup: TrackingSetup, strategy: str, seeds=None, noise=None) -> BatchResult:
    """Many runs of one strategy at once: :func:`simulate` vectorised over noise realisations.

    The same equations as filterpy's ``predict`` and ``update`` (Joseph form) in the same order,
    written with batched matrix products, so a run equals ``simulate(setup, strategy, seed=s)``
    to rounding (checked in the tests).

    Parameters
    ----------
    seeds : iterable of int, optional
        One run per seed with ``noise_table(setup, seed)``.
    noise : array_like, shape (B, steps, N), optional
        Explicit noise tables instead of seeds.
    """
    if strategy not in STRATEGIES:
        raise ValueError(f"unknown strategy {strategy!r}; known: {STRATEGIES}")
    if (seeds is None) == (noise is None):
        raise ValueError("give either seeds or noise tables")
    if noise is None:
        seeds = tuple(int(x) for x in seeds)
        if not seeds:
            raise ValueError("seeds is empty")
        tables = np.stack([noise_table(setup, x) for x in seeds])
    else:
        tables = np.asarray(noise, dtype=float)
        if tables.ndim != 3:
            raise ValueError(f"noise must have shape (B, steps, N), got {tables.shape}")
        tables = np.stack([_check_noise(setup, t) for t in tables])
        seeds = ()
    B = tables.shape[0]
    steps = setup.steps
    s = setup.sensor_array
    Q = np.array(setup.Q)
    R = np.array(setup.R)
    eye = np.eye(2)
    rows = np.arange(B)

    x = np.broadcast_to(np.array(setup.estimate0), (B, 2)).copy()
    P = np.broadcast_to(np.array(setup.cov0), (B, 2, 2)).copy()
    circle = setup.motion == "circle"
    truth = np.empty((B, steps + 1, 2))
    if circle:
        truth[:] = circle_truth(setup)[None]
    else:
        truth[:, 0] = setup.start
        controls = setup.control_array

    pairs = np.empty((B, steps, 2), dtype=int)
    bound = np.empty((B, steps))
    est = np.empty((B, steps, 2))
    cov = np.empty((B, steps, 2, 2))
    pair, b = choose_pairs(setup, strategy, x, P)
    for k in range(steps):
        pairs[:, k], bound[:, k] = pair, b
        est[:, k], cov[:, k] = x, P
        ps = s[pair]  # (B, 2, 2)
        o = truth[:, k]
        z = half_squared_range(o, ps) + tables[rows[:, None], k, pair]
        Pp = P + Q  # predict: F = I
        H = range_jacobian(x, ps)
        HT = np.swapaxes(H, 1, 2)
        PHT = Pp @ HT
        S = H @ PHT + R
        K = PHT @ np.linalg.inv(S)
        x = x + (K @ (z - half_squared_range(x, ps))[..., None])[..., 0]
        IKH = eye - K @ H
        P = IKH @ Pp @ np.swapaxes(IKH, 1, 2) + K @ R @ np.swapaxes(K, 1, 2)
        pair, b = choose_pairs(setup, strategy, x, P)
        if not circle:
            eval_ps = ps if setup.adversary == "current-pair" else s[pair]
            best = np.argmin(target_objective(eval_ps, o, controls), axis=1)
            truth[:, k + 1] = o + controls[best]
    return BatchResult(
        setup=setup,
        strategy=strategy,
        seed=None,
        seeds=seeds,
        noise=tables,
        pairs=pairs,
        bound=bound,
        estimate=est,
        cov=cov,
        next_pair=pair,
        **_derived(s, pairs, est, cov, truth),
    )


def monte_carlo(
    setup: TrackingSetup,
    n_seeds: int = 100,
    strategies: Iterable[str] = STRATEGIES,
    first_seed: int = 0,
    batch: int = 100,
) -> dict[str, BatchResult]:
    """The strategies over ``n_seeds`` noise realisations, seeds ``first_seed, first_seed + 1, ..``.

    Trial ``t`` uses ``noise_table(setup, first_seed + t)`` for every strategy (common noise),
    so trial ``t`` of a strategy equals ``simulate(setup, strategy, seed=first_seed + t)``.
    Runs are batched ``batch`` seeds at a time (:func:`simulate_batch`).

    Returns
    -------
    dict
        ``{strategy: BatchResult}`` with arrays of leading size ``n_seeds``.
    """
    if int(n_seeds) < 1:
        raise ValueError(f"n_seeds must be at least 1, got {n_seeds}")
    seeds = list(range(int(first_seed), int(first_seed) + int(n_seeds)))
    out = {}
    for strategy in strategies:
        parts = [
            simulate_batch(setup, strategy, seeds=seeds[i : i + batch])
            for i in range(0, len(seeds), batch)
        ]
        out[strategy] = BatchResult(
            setup=setup,
            strategy=strategy,
            seed=None,
            seeds=tuple(seeds),
            **{
                f.name: np.concatenate([getattr(p, f.name) for p in parts])
                for f in dataclasses.fields(TrackingResult)
                if f.name not in ("setup", "strategy", "seed")
            },
        )
    return out


# --------------------------------------------------------------------------------------------
# Statistics
# --------------------------------------------------------------------------------------------


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
        (seed, step) with the reference strictly lower; ``error_stepmean`` / ``trace_stepmean``,
        the fraction of steps where the reference's Monte Carlo mean is lower; and
        ``bound_pointwise``, the fraction with the reference's bound strictly higher.
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
            "error_pointwise": float((e1 < e2).mean()),
            "trace_pointwise": float((t1 < t2).mean()),
            "error_stepmean": float((e1.mean(0) < e2.mean(0)).mean()),
            "trace_stepmean": float((t1.mean(0) < t2.mean(0)).mean()),
            "bound_pointwise": float((ref.bound[:, sl] > r.bound[:, sl]).mean()),
            "run_error": float((e1.mean(1) < e2.mean(1)).mean()),
            "run_trace": float((t1.mean(1) < t2.mean(1)).mean()),
        }
    return {"strategies": stats, "wins": wins}


def spearman(a, b, axis: int = -1) -> np.ndarray:
    """Spearman rank correlation of ``a`` and ``b`` along ``axis`` (ties by average rank)."""
    from scipy.stats import rankdata

    ra = rankdata(a, axis=axis)
    rb = rankdata(b, axis=axis)
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
        b = np.stack([
            pair_bound_series(batch.setup, batch.estimate[i], batch.pairs[i])
            for i in range(batch.n_runs)
        ])
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


def partner_study(setup: TrackingSetup, n_seeds: int, first_seed: int = 0) -> dict:
    """Strategy (3) with every partner of the anchor: Monte Carlo means per partner.

    Checks the paper's choice of ``s_1`` as ``s_2``'s fixed partner ("it gives the best
    performance amongst all other sensors, on an average, for the circular trajectory").

    Returns
    -------
    dict
        ``{partner: {"mean_bound", "mean_error", "median_error", "mean_trace", "lost"}}`` with
        ``partner`` 0-based and ``lost`` the fraction of runs of :func:`track_loss`.
    """
    out = {}
    for j in range(setup.n_sensors):
        if j == setup.anchor:
            continue
        r = monte_carlo(
            setup.replace(fixed_pair=(setup.anchor, j)), n_seeds, ["fixed-pair"], first_seed
        )["fixed-pair"]
        run_err = r.error[:, 1:].mean(axis=1)
        out[j] = {
            "mean_bound": float(r.bound[:, 1:].mean()),
            "mean_error": float(run_err.mean()),
            "median_error": float(np.median(run_err)),
            "mean_trace": float(r.trace_cov[:, 1:].mean()),
            "lost": float(track_loss(r)["lost"].mean()),
        }
    return out


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


def draw_snapshot(ax, result: TrackingResult, k: int, *, legend: bool = True, ellipse_scale=1.0):
    """Draw step ``k`` (1-based) of a run as in Fig. 4 on ``ax``.

    Sensors (labelled ``s1..sN``), the true path so far and the target, the estimate with its
    99.73 % covariance ellipse (scaled by ``ellipse_scale`` if wanted for visibility) and lines
    from the chosen pair to the estimate. Returns the artists.
    """
    i = k - 1
    s = result.setup.sensor_array
    ax.plot(*s.T, "^", color="tab:blue", ms=8, label="sensors")
    for n, p in enumerate(s):
        ax.annotate(f"$s_{{{n + 1}}}$", p, textcoords="offset points", xytext=(4, 4), fontsize=8)
    for j in result.pairs[i]:
        ax.plot(*np.array([s[j], result.estimate[i]]).T, "-", color="tab:green", lw=1)
    ax.plot(*result.truth[: i + 1].T, "-", color="0.6", lw=1, label="true path")
    ax.plot(*result.truth[i], "o", color="k", ms=5, label="target $o_k$")
    ax.plot(*result.estimate[i], "x", color="tab:red", ms=7, label=r"estimate $\hat o_k$")
    e = cov_ellipse(result.estimate[i], ellipse_scale**2 * result.cov[i])
    ax.plot(*e.T, "-", color="tab:red", lw=1, label="99.73 % ellipse")
    ax.set_aspect("equal")
    i0, j0 = result.pairs[i] + 1
    ax.set_title(f"k = {k}, pair ($s_{{{i0}}}$, $s_{{{j0}}}$)", fontsize=9)
    if legend:
        ax.legend(fontsize=6, loc="lower left")
    return ax


def animate(result: TrackingResult, every: int = 3, dpi: int = 50, figsize=(4.0, 4.0), interval=80):
    """A :class:`matplotlib.animation.FuncAnimation` of a run: every ``every``-th step and the last.

    Each frame shows what :func:`draw_snapshot` draws (Fig. 4), updating persistent artists.
    Show it in a notebook with ``IPython.display.HTML(anim.to_jshtml())``; the figure is closed
    so that it is not also shown as a still.
    """
    import matplotlib.pyplot as plt
    from matplotlib.animation import FuncAnimation

    if int(every) < 1:
        raise ValueError(f"every must be at least 1, got {every}")
    s = result.setup.sensor_array
    fig, ax = plt.subplots(figsize=figsize, dpi=dpi)
    pts = np.vstack([s, result.truth, result.estimate])
    lo, hi = pts.min(axis=0) - 1.0, pts.max(axis=0) + 1.0
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.plot(*s.T, "^", color="tab:blue", ms=7)
    for n, p in enumerate(s):
        ax.annotate(f"$s_{{{n + 1}}}$", p, textcoords="offset points", xytext=(4, 4), fontsize=8)
    (links,) = ax.plot([], [], "-", color="tab:green", lw=1)
    (path,) = ax.plot([], [], "-", color="0.6", lw=1)
    (target,) = ax.plot([], [], "o", color="k", ms=4)
    (est,) = ax.plot([], [], "x", color="tab:red", ms=6)
    (ell,) = ax.plot([], [], "-", color="tab:red", lw=1)
    title = ax.set_title("", fontsize=9)
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
        i0, j0 = result.pairs[i] + 1
        # plain text: a mathtext title differs every frame, and parsing it dominated rendering
        title.set_text(f"k = {k}, pair (s{i0}, s{j0})")
        return links, path, target, est, ell, title

    anim = FuncAnimation(fig, frame, frames=frames, interval=interval, blit=False)
    plt.close(fig)
    return anim


def animation_html(anim, uid: str = "anim") -> str:
    """Self-contained, stable HTML/JS for a matplotlib animation (``anim.to_jshtml()``).

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

"""The parameter record of a Section V tracking experiment, the paper's two records, and the
measurement-noise tables every strategy shares.

A :class:`TrackingSetup` is frozen and validated on construction; :data:`PAPER_CIRCLE` holds the
parameters of Figs. 4-6 and :data:`PAPER_ADVERSARIAL` those of Fig. 7. A noise table is a
``(steps, N)`` array whose entry ``[k - 1, i]`` is sensor ``i``'s noise at step ``k``, whichever
strategy asks for it (:func:`noise_table`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np

from .._validate import (
    ArgumentTypeError,
    as_choice,
    as_float_array,
    as_instance,
    as_int,
    as_mapping,
    as_noise_table,
    as_nonnegative,
    as_point,
    as_points,
    as_positive,
    as_real_array,
    check_distinct,
    check_spd_any_scale,
)
from .kalman import MEASUREMENTS

__all__ = [
    "TargetsSetup",
    "LATER_SENSORS",
    "LATER_MULTI_TARGET",
    "circle_paths",
    "network_scene",
    "METRICS",
    "ADVERSARIES",
    "MOTIONS",
    "PARAM_FIELDS",
    "PAPER_SENSORS",
    "TrackingSetup",
    "PAPER_CIRCLE",
    "PAPER_ADVERSARIAL",
    "paper_controls",
    "noise_table",
    "setup_from_params",
]

METRICS = ("mahalanobis", "euclidean")
ADVERSARIES = ("current-pair", "next-pair")
MOTIONS = ("circle", "adversarial")

#: Largest entry of ``cov0``, ``Q`` and ``R`` the filter can carry: the determinant of the
#: innovation covariance ``S = H P H^T + R`` is of the order of the square of ``P``'s entries.
MAX_COV_SCALE = 1e100

#: The six sensors s1..s6 of Section V (Figs. 4-7).
PAPER_SENSORS = ((-3.0, 2.0), (0.0, 0.0), (1.0, -1.0), (4.0, 0.0), (4.0, 4.0), (2.0, 5.0))


def paper_controls(u_max: float, n_angles: int = 63, dphi: float = 0.1) -> np.ndarray:
    """The adversary's control set of the published Fig. 7 run.

    ``u = 0`` followed by ``n_angles`` controls of norm ``u_max`` at angles ``0, dphi, ...,
    (n_angles - 1) dphi`` (default 0, 0.1, ..., 6.2 rad). The paper's text says "all the
    possible control inputs within a ball"; :func:`obslib.controls.disc_controls` gives that.

    Returns
    -------
    ndarray, shape (n_angles + 1, 2)

    Examples
    --------
    >>> paper_controls(0.1).shape
    (64, 2)
    """
    u_max = as_nonnegative(u_max, "u_max")
    phi = as_positive(dphi, "dphi") * np.arange(as_int(n_angles, "n_angles", 1))
    ring = u_max * np.column_stack([np.cos(phi), np.sin(phi)])
    return np.vstack([np.zeros((1, 2)), ring])


# --------------------------------------------------------------------------------------------
# Validators of the record's fields
# --------------------------------------------------------------------------------------------


def _matrix(value, name: str) -> tuple:
    """A symmetric positive-definite 2x2 matrix as a tuple of tuples, or ValueError."""
    m = as_real_array(value, name, "a real 2x2 matrix or a real number")
    if m.ndim == 0:
        m = m * np.eye(2)
    if m.shape != (2, 2):
        raise ValueError(f"{name} must be a 2x2 matrix (or a scalar times I), got shape {m.shape}")
    check_spd_any_scale(m, name, MAX_COV_SCALE)
    return tuple(map(tuple, m.tolist()))


def _point(value, name: str) -> tuple:
    return tuple(as_point(as_real_array(value, name, "a real point (x, y)"), name).tolist())


def _scalar(value, name: str, *, positive=False, nonneg=False) -> float:
    arr = as_real_array(value, name, "a real number")
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a number, got shape {arr.shape}")
    v = float(arr)
    if not np.isfinite(v):
        raise ValueError(f"{name} must be finite, got {v}")
    if positive and v <= 0:
        raise ValueError(f"{name} must be positive, got {v}")
    if nonneg and v < 0:
        raise ValueError(f"{name} must be non-negative, got {v}")
    return v


def _index(value, name: str, n: int) -> int:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise ValueError(f"{name} must be a sensor index in 0..{n - 1}, got {value!r}")
    if not 0 <= value < n:
        raise ValueError(f"{name} must be a sensor index in 0..{n - 1}, got {value!r}")
    return int(value)


@dataclass(frozen=True)
class TrackingSetup:
    """Parameters of one tracking experiment of Section V (a frozen parameter record).

    Build variants with :meth:`replace` (:func:`dataclasses.replace`), e.g.
    ``PAPER_CIRCLE.replace(metric="euclidean")``; every construction is validated and bad
    values raise :class:`ValueError` (or :class:`TypeError` for a value of the wrong kind, such
    as a bool or a complex number where a real number belongs).

    Attributes
    ----------
    sensors : tuple of (x, y)
        Stationary sensor positions :math:`p_i` (at least two, pairwise distinct).
    steps : int
        Number of time steps (at least 1).
    u_max : float
        Speed bound entering the pair bound (and the adversary's default control set).
    estimate0 : (x, y)
        Initial estimate of the filter.
    cov0 : 2x2
        Initial covariance of the filter.
    Q : 2x2
        Process noise of the random-walk prediction (a scalar means that multiple of :math:`I`).
    R : 2x2
        Measurement-noise covariance of the filter for the pair's two measurements (a scalar
        means that multiple of :math:`I`).
    noise_std : float
        Standard deviation of the true measurement noise :math:`n_i` (may differ from ``R``).
    motion : {"circle", "adversarial"}
        The true target's motion: the circle of Section V-A or the adversary of Section V-B.
    center : (x, y)
        Centre :math:`c` of the circle :math:`o_k = c + r\\,(\\cos(\\omega (k-1)),
        \\sin(\\omega (k-1)))`.
    radius : float
        Its radius :math:`r`.
    rate : float
        Its angular rate :math:`\\omega` (rad per step).
    start : (x, y) or None
        True start of the adversarial target (``None`` for the circle).
    controls : tuple of (ux, uy) or None
        The adversary's control set, each of norm at most ``u_max``; ``None`` means
        :func:`paper_controls` of ``u_max``.
    adversary : {"current-pair", "next-pair"}
        What the adversary minimises: the exact :math:`C^{-1}` of
        :math:`[o' - p_i; o' - p_j; u]` at its next position :math:`o' = o + u` with the pair
        that just measured it (``"current-pair"``, the paper) or with the pair the sensors will
        use next (``"next-pair"``, a stronger target that knows the sensors' next choice).
    metric : {"mahalanobis", "euclidean"}
        Distances in the pair bound: Mahalanobis in the estimate's covariance (the published
        runs) or Euclidean.
    anchor : int
        The fixed sensor of strategy (2), 0-based (``1`` is the paper's :math:`s_2`).
    fixed_pair : (int, int)
        The pair of strategy (3), 0-based (``(1, 0)`` is the paper's :math:`(s_2, s_1)`).
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
        s = as_points(as_real_array(self.sensors, "sensors", "real points (x, y)"), "sensors")
        if s.shape[0] == 0:
            raise ValueError("setup has no sensors; the strategies need at least 2")
        if s.shape[0] < 2:
            raise ValueError(f"setup has {s.shape[0]} sensor; the strategies need at least 2")
        check_distinct(s)
        put("sensors", tuple(map(tuple, s.tolist())))
        n = s.shape[0]
        if isinstance(self.steps, (bool, np.bool_)) or not isinstance(self.steps, np.integer | int):
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
            c = as_real_array(self.controls, "controls", "real points (ux, uy)")
            c = as_points(c, "controls", min_count=1)
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
        put("anchor", _index(self.anchor, "anchor", n))
        try:
            fp = tuple(self.fixed_pair)
        except TypeError:
            raise ValueError(f"fixed_pair must be two sensor indices in 0..{n - 1}, "
                             f"got {self.fixed_pair!r}") from None
        if len(fp) != 2 or not all(
            isinstance(i, (int, np.integer)) and not isinstance(i, (bool, np.bool_)) and 0 <= i < n
            for i in fp
        ):
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
        """Number of sensors ``N``."""
        return len(self.sensors)

    @property
    def control_array(self) -> np.ndarray:
        """The adversary's controls, ``(K, 2)`` (the paper's set when ``controls`` is None)."""
        if self.controls is None:
            return paper_controls(self.u_max)
        return np.array(self.controls, dtype=float)

    def replace(self, **changes) -> TrackingSetup:
        """A validated copy with some fields changed (:func:`dataclasses.replace`)."""
        return dataclasses.replace(self, **changes)


#: The setup of Figs. 4-6, the circle of radius 3 about (2, 3), 0.02 rad per step, u_max = 3.
PAPER_CIRCLE = TrackingSetup()

#: The setup of Fig. 7, the adversarial target, u_max = 0.1, true start (2, 2), estimate (2.5, 1.5).
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
    experiment for the same parameters (``q``, ``r``, ``p0`` are multiples of :math:`I`).

    Examples
    --------
    >>> setup_from_params(PAPER_CIRCLE, {"q": 0.2, "n_seeds": 5}).Q
    ((0.2, 0.0), (0.0, 0.2))
    """
    as_instance(base, TrackingSetup, "base")
    params = as_mapping(params, "params")
    changes = {PARAM_FIELDS[k]: v for k, v in params.items() if k in PARAM_FIELDS}
    return base.replace(**changes)


# --------------------------------------------------------------------------------------------
# Many targets: the record, the authors' later experiment, larger scenes
# --------------------------------------------------------------------------------------------


#: The eight sensors of the authors' later experiment.
LATER_SENSORS = ((-3.0, 0.0), (-3.0, 4.0), (0.0, 0.0), (2.0, -1.0), (5.0, 0.0), (4.0, 6.0),
                 (2.0, 7.0), (1.0, 3.0))


def _array_field(value, name: str, ndim_tail: tuple, what: str) -> np.ndarray:
    a = as_float_array(value, name)
    if a.ndim != len(ndim_tail) or any(t is not None and s != t
                                       for s, t in zip(a.shape, ndim_tail)):
        raise ValueError(f"{name} must have shape {what}, got {a.shape}")
    if not np.isfinite(a).all():
        raise ValueError(f"{name} must be finite")
    return a


def _nested(a: np.ndarray) -> tuple:
    if a.ndim == 1:
        return tuple(float(v) for v in a)
    return tuple(_nested(b) for b in a)


@dataclass(frozen=True)
class TargetsSetup:
    """Parameters of a multi-target tracking experiment (a frozen, validated record).

    Attributes
    ----------
    sensors : tuple of (x, y)
        The ``N`` stationary sensors, distinct.
    truth : nested tuple, shape (steps + 1, L, 2)
        The targets' true positions :math:`o_{l,k}`, ``k = 1 .. steps + 1`` (the last is where
        they move after the last step); ``steps`` and ``L`` are read from it.
    estimate0 : nested tuple, shape (L, 2)
        The filters' initial estimates.
    cov0 : 2 x 2 matrix or number
        Their initial covariance (a number means that multiple of :math:`I`), shared.
    Q : 2 x 2 matrix or number
        The filters' process noise (random-walk prediction).
    R : float
        The filters' measurement-noise variance, per measurement.
    noise_std : float
        Standard deviation of the true measurement noise (the noise tables).
    u_max : float
        The targets' speed bound in Theorem 4's pair bound.
    measurement : {"range", "half-squared-range"}
        What a sensor measures (:data:`~obslib.tracking.kalman.MEASUREMENTS`): the range, as
        the later experiment, or Section V's half squared range.
    metric : {"euclidean", "mahalanobis"}
        Distances of the pair bound: Euclidean to the estimates (the later experiment) or
        Mahalanobis in the estimates' covariances.
    eps : float
        The prior :math:`\\varepsilon I` of ``"logdet-teams-prior"``.
    """

    sensors: tuple
    truth: tuple
    estimate0: tuple
    cov0: tuple = ((0.5, 0.0), (0.0, 0.5))
    Q: tuple = ((0.2, 0.0), (0.0, 0.2))
    R: float = 0.04
    noise_std: float = 0.2
    u_max: float = 0.1
    measurement: str = "range"
    metric: str = "euclidean"
    eps: float = 1.0

    def __post_init__(self):
        put = lambda name, value: object.__setattr__(self, name, value)  # noqa: E731
        s = as_points(as_float_array(self.sensors, "sensors"), "sensors", min_count=1)
        if not np.isfinite(s).all():
            raise ValueError("sensors must be finite")
        check_distinct(s)
        put("sensors", _nested(s))
        t = _array_field(self.truth, "truth", (None, None, 2), "(steps + 1, L, 2)")
        if t.shape[0] < 2 or t.shape[1] < 1:
            raise ValueError(f"truth must hold at least 2 positions of at least 1 target, shape "
                             f"(steps + 1, L, 2), got {t.shape}")
        put("truth", _nested(t))
        x0 = _array_field(self.estimate0, "estimate0", (t.shape[1], 2),
                          f"({t.shape[1]}, 2), one per target")
        put("estimate0", _nested(x0))
        put("cov0", _matrix(self.cov0, "cov0"))
        put("Q", _matrix(self.Q, "Q"))
        put("R", as_positive(self.R, "R"))
        put("noise_std", as_nonnegative(self.noise_std, "noise_std"))
        put("u_max", as_nonnegative(self.u_max, "u_max"))
        as_choice(self.measurement, MEASUREMENTS, "measurement")
        as_choice(self.metric, METRICS, "metric")
        put("eps", as_positive(self.eps, "eps"))

    @property
    def sensor_array(self) -> np.ndarray:
        """The sensors, ``(N, 2)``."""
        return np.array(self.sensors, dtype=float)

    @property
    def truth_array(self) -> np.ndarray:
        """The true positions, ``(steps + 1, L, 2)``."""
        return np.array(self.truth, dtype=float)

    @property
    def n_sensors(self) -> int:
        return len(self.sensors)

    @property
    def n_targets(self) -> int:
        return len(self.estimate0)

    @property
    def steps(self) -> int:
        return len(self.truth) - 1

    def replace(self, **changes) -> TargetsSetup:
        """A validated copy with some fields changed (:func:`dataclasses.replace`)."""
        return dataclasses.replace(self, **changes)

    def first(self, steps: int) -> TargetsSetup:
        """The same experiment cut to its first ``steps`` steps.

        Examples
        --------
        >>> LATER_MULTI_TARGET.first(10).steps
        10
        """
        steps = as_int(steps, "steps", 1)
        if steps > self.steps:
            raise ValueError(f"steps must be at most the setup's {self.steps}, got {steps}")
        return self.replace(truth=self.truth[: steps + 1])


def circle_paths(centers, periods, steps: int, radius: float = 1.0) -> np.ndarray:
    """The later experiment's targets: at step 1 each stands at its centre :math:`c_l`, at step
    :math:`k + 1` at :math:`c_l + r\\,(\\cos(k / W_l), \\sin(k / W_l))`, ``(steps + 1, L, 2)``
    (so the first move jumps from the centre onto the circle).

    Examples
    --------
    >>> circle_paths([[2.0, 1.0]], [10.0], 2).round(4).tolist()
    [[[2.0, 1.0]], [[2.995, 1.0998]], [[2.9801, 1.1987]]]
    """
    c = as_float_array(centers, "centers")
    if not np.isfinite(c).all():
        raise ValueError("centers must be finite")
    c = as_points(c, "centers", min_count=1)
    w = as_float_array(periods, "periods")
    if w.shape != (c.shape[0],) or not np.isfinite(w).all() or (w == 0).any():
        raise ValueError(f"periods must be {c.shape[0]} finite non-zero numbers, one per centre")
    steps = as_int(steps, "steps", 1)
    radius = as_nonnegative(radius, "radius")
    k = np.arange(1, steps + 1)[:, None]
    a = k / w
    out = np.empty((steps + 1, c.shape[0], 2))
    out[0] = c
    out[1:, :, 0] = radius * np.cos(a) + c[:, 0]
    out[1:, :, 1] = radius * np.sin(a) + c[:, 1]
    return out


#: The authors' later multi-target experiment as their code runs it: 8 range sensors, 3 targets
#: on unit circles about (2, 1), (-2, 2), (3, 4) (periods 10, 20, -30 steps per radian, each
#: starting at its centre), initial estimates (2.5, 1.5), (-0.5, 0.5), (3.5, 4.5) with
#: covariance 0.5 I, Q = 0.2 I, range noise of standard deviation 0.2 (R = 0.04), u_max = 0.1,
#: Euclidean distances in the pair bound, 100 steps.
LATER_MULTI_TARGET = TargetsSetup(
    sensors=LATER_SENSORS,
    truth=_nested(circle_paths([[2.0, 1.0], [-2.0, 2.0], [3.0, 4.0]], [10.0, 20.0, -30.0], 100)),
    estimate0=((2.5, 1.5), (-0.5, 0.5), (3.5, 4.5)),
)


def network_scene(n_sensors: int, n_targets: int, steps: int = 100, seed: int = 0,
                  side: float | None = None) -> TargetsSetup:
    """A larger network of the later experiment's kind: ``N`` sensors and ``L`` targets on
    random smooth paths, with the filter, noise and bound of :data:`LATER_MULTI_TARGET`.

    The sensors are uniform in the square ``[0, side]^2``; ``side`` defaults to
    :math:`10 \\sqrt{N / 8}`, so the sensors are as dense as the later experiment's eight in
    its 10 x 10 field. Each target starts uniform in the square's middle ``[0.2, 0.8]`` part and
    moves at a constant speed, uniform in ``[u_max / 3, u_max]`` (the later experiment's
    targets move 0.1, 0.05 and 0.033 per step, u_max = 0.1), with a heading that turns
    smoothly: :math:`\\theta_k = \\theta_0 + \\sum_{m=1}^{3} b_m \\sin(2 \\pi m k / K +
    \\phi_m)`, :math:`b_m` uniform in :math:`\\pm 1.5 / m`, ``K`` the steps. The initial
    estimates are the starts plus Gaussian errors of covariance ``cov0``. Everything is drawn
    from ``numpy.random.default_rng([3, seed])``.

    Examples
    --------
    >>> su = network_scene(200, 50, steps=20, seed=1)
    >>> su.n_sensors, su.n_targets, su.steps
    (200, 50, 20)
    >>> import numpy as np
    >>> step = np.diff(su.truth_array, axis=0)
    >>> speed = np.hypot(step[..., 0], step[..., 1])
    >>> bool((speed <= su.u_max * (1 + 1e-12)).all())
    True
    """
    n = as_int(n_sensors, "n_sensors", 1)
    L = as_int(n_targets, "n_targets", 1)
    steps = as_int(steps, "steps", 1)
    seed = as_int(seed, "seed", 0)
    side = 10.0 * np.sqrt(n / 8.0) if side is None else as_positive(side, "side")
    base = LATER_MULTI_TARGET
    rng = np.random.default_rng([3, seed])
    sensors = rng.uniform(0.0, side, size=(n, 2))
    start = rng.uniform(0.2 * side, 0.8 * side, size=(L, 2))
    speed = rng.uniform(base.u_max / 3, base.u_max, size=L)
    theta0 = rng.uniform(0.0, 2 * np.pi, size=L)
    m = np.arange(1, 4)
    b = rng.uniform(-1.5, 1.5, size=(L, 3)) / m
    phi = rng.uniform(0.0, 2 * np.pi, size=(L, 3))
    k = np.arange(steps)[:, None, None]
    theta = theta0 + (b * np.sin(2 * np.pi * m * k / steps + phi)).sum(axis=-1)  # (steps, L)
    moves = speed[:, None] * np.stack([np.cos(theta), np.sin(theta)], axis=-1)  # (steps, L, 2)
    truth = np.concatenate([start[None], start + np.cumsum(moves, axis=0)])
    chol = np.linalg.cholesky(np.array(base.cov0))
    estimate0 = start + rng.normal(size=(L, 2)) @ chol.T
    return base.replace(sensors=_nested(sensors), truth=_nested(truth),
                        estimate0=_nested(estimate0))


# --------------------------------------------------------------------------------------------
# Checks shared by the engines
# --------------------------------------------------------------------------------------------


def noise_table(setup, seed: int = 0) -> np.ndarray:
    """The measurement noise of one run, ``(steps, N)``: ``[k-1, i]`` is sensor ``i`` at step ``k``.

    Drawn once from ``numpy.random.default_rng(seed)`` as ``normal(0, noise_std)``, so every
    strategy (or assignment) sees the same realisation, whatever target a sensor serves.
    ``setup`` is a :class:`TrackingSetup` or a :class:`~obslib.tracking.TargetsSetup`.

    Examples
    --------
    >>> noise_table(PAPER_CIRCLE, 0).shape
    (315, 6)
    """
    _setup_iv(setup)
    rng = np.random.default_rng(as_int(seed, "seed", 0))
    return rng.normal(0.0, setup.noise_std, size=(setup.steps, setup.n_sensors))


def _setup_iv(setup):
    if not isinstance(setup, (TrackingSetup, TargetsSetup)):
        raise ValueError(f"setup must be a TrackingSetup or a TargetsSetup, got "
                         f"{type(setup).__name__}")
    return setup


def run_table(setup, noise, seed, seeded: bool):
    """The noise table of one run and the seed it records: ``noise`` checked against the
    setup's ``(steps, N)``, or :func:`noise_table` of ``seed`` (then recorded); ``seed`` is
    checked wherever it is used (``seeded``: it also draws the run's random choices).

    Examples
    --------
    >>> table, used = run_table(PAPER_CIRCLE.replace(steps=3), None, 4, False)
    >>> table.shape, used
    ((3, 6), 4)
    """
    _setup_iv(setup)
    if noise is None or seeded:
        seed = as_int(seed, "seed", 0)
    if noise is None:
        return noise_table(setup, seed), seed
    return as_noise_table(noise, (setup.steps, setup.n_sensors)), None


def seeds_or_noise(seeds, noise):
    """Either seeds (a non-empty iterable of integers, returned as a tuple with ``None``) or
    noise tables (an array ``(B, steps, N)``, returned as ``()`` and the array), not both.

    Examples
    --------
    >>> seeds_or_noise(range(3), None)
    ((0, 1, 2), None)
    """
    if (seeds is None) == (noise is None):
        raise ValueError("give either seeds or noise tables")
    if noise is not None:
        given = as_float_array(noise, "noise")
        if given.ndim != 3:
            raise ValueError(f"noise must have shape (B, steps, N), got {given.shape}")
        return (), given
    if isinstance(seeds, (str, bytes)) or not isinstance(seeds, Iterable):
        raise ArgumentTypeError(
            f"seeds must be an iterable of non-negative integers, got {seeds!r}")
    seeds = tuple(as_int(x, "each seed", 0) for x in seeds)
    if not seeds:
        raise ValueError("seeds is empty")
    return seeds, None

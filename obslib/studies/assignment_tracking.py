"""Assignments judged by tracking: Fig. 8's setting with moving targets and one EKF per target.

Section V-C of the paper compares pair assignments only by the value of their own objective
(the sum of Theorem 4's pair bounds). This module asks how well the targets are then *tracked*.
``L`` targets move in the square ``[0, side]^2`` among ``N`` stationary range sensors (Fig. 8:
``N = 2 L``); at every step each target gets its own pair of sensors, no sensor serving two
targets, and its own extended Kalman filter fuses the pair's two measurements. Three rules make
the assignment, re-made at every step from the current estimates:

``"bound"``
    Algorithm 1 (greedy unique pairs) on Theorem 4's pair bound at each estimate, with
    Mahalanobis distances in the estimate's covariance ``Sigma_l`` (as the tracking experiments
    of Section V evaluate it) or Euclidean ones;
``"d-optimal"``
    the same greedy on the information gain of the pair,
    :math:`\\log\\det J_l(i, j) - \\log\\det (\\Sigma_l^-)^{-1}` with
    :math:`J_l(i, j) = (\\Sigma_l^-)^{-1} + H^T R^{-1} H`, :math:`\\Sigma_l^- = \\Sigma_l + Q` and
    ``H`` the rows :math:`(\\hat x_l - p_i)^T, (\\hat x_l - p_j)^T` (D-optimal design);
``"random"``
    a uniformly random valid assignment (a random permutation of the sensors, paired in order).

The model
---------
Target ``l`` moves by a control drawn uniformly from the disc of radius ``u_max`` (the paper's
bounded unknown control): :math:`o_{k+1} = o_k + u_k`. Each filter predicts with the random walk
:math:`\\hat x^- = \\hat x`, :math:`\\Sigma^- = \\Sigma + Q`, :math:`Q = (u_{max}^2 / 4) I`
(the covariance of the uniform disc), and updates with the half squared ranges
:math:`z_i = \\tfrac12 \\|p_i - o\\|^2 + n_i` (Section II;
:func:`obslib.tracking.half_squared_range`) of its two sensors, :math:`n_i \\sim N(0, \\sigma^2)`,
``R = sigma^2 I``: the batched EKF of :mod:`obslib.tracking.kalman` (filterpy's equations, Joseph
form), which stops with a ``ValueError`` naming the target, step and seed where the innovation
covariance is singular.

Order within step ``k``, as in :mod:`obslib.tracking`: (1) assign from the current estimates and
covariances; (2) log each target's error :math:`\\|\\hat x - o\\|` and :math:`\\operatorname{tr}
\\Sigma` before the update; (3) predict, measure, update; (4) move the targets.

Common random numbers: seed ``s`` fixes the sensors, the targets' starts and controls, the
initial estimates and the measurement noise (``numpy.random.default_rng([s, 0])``; entry
``[k, i]`` of the noise table is sensor ``i``'s at step ``k``, whichever target it serves) and
the random assignments (``default_rng([s, 1])``), identically for every rule. All runs and
targets advance together as NumPy array operations.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from .. import tracking as tr
from .._kernels import pair_kernel
from .._validate import (
    as_choice,
    as_float_array,
    as_instance,
    as_int,
    as_names,
    as_positive,
    as_sequence,
    as_str,
)
from ..assignment import greedy_pairs_batch
from ..tracking import kalman

__all__ = [
    "RULES",
    "AssignmentTrackingSetup",
    "Scenario",
    "AssignmentRuns",
    "scenario",
    "run",
    "run_all",
]

#: The assignment rules, in the order the studies report them.
RULES = ("bound", "d-optimal", "random")
METRICS = ("mahalanobis", "euclidean")


@dataclass(frozen=True)
class AssignmentTrackingSetup:
    """Parameters of the assignment-by-tracking experiment (validated, frozen).

    Attributes
    ----------
    n_targets : int
        ``L``, the number of moving targets (at least 1).
    n_sensors : int or None
        ``N >= 2 L``; ``None`` means ``2 L`` as in Fig. 8.
    steps : int
        Time steps per run.
    side : float
        Sensors and starting targets are uniform in ``[0, side]^2`` (Fig. 8: 100).
    u_max : float
        Radius of the targets' control disc and the bound's control bound (Fig. 8: 1).
    noise_std : float
        Standard deviation of each half-squared-range measurement; the filters use
        ``R = noise_std^2 I``.
    p0 : float
        Initial covariance ``p0 I``; the initial estimate is the start plus ``N(0, p0 I)``.
    metric : {"mahalanobis", "euclidean"}
        Distances in the bound (Mahalanobis in the estimate's covariance, or Euclidean).
    """

    n_targets: int = 5
    n_sensors: int | None = None
    steps: int = 100
    side: float = 100.0
    u_max: float = 1.0
    noise_std: float = 0.5
    p0: float = 1.0
    metric: str = "mahalanobis"

    def __post_init__(self):
        put = lambda k, v: object.__setattr__(self, k, v)  # noqa: E731
        L = as_int(self.n_targets, "n_targets", 1)
        put("n_targets", L)
        n = 2 * L if self.n_sensors is None else as_int(self.n_sensors, "n_sensors", 2)
        if n < 2 * L:
            raise ValueError(f"n_sensors must be at least 2 n_targets = {2 * L}, got {n}")
        put("n_sensors", n)
        put("steps", as_int(self.steps, "steps", 1))
        put("side", as_positive(self.side, "side"))
        put("u_max", as_positive(self.u_max, "u_max"))
        put("noise_std", as_positive(self.noise_std, "noise_std"))
        put("p0", as_positive(self.p0, "p0"))
        if as_str(self.metric, "metric") not in METRICS:
            raise ValueError(f"metric must be one of {METRICS}, got {self.metric!r}")

    @property
    def Q(self) -> float:
        """Process-noise variance per axis, ``u_max^2 / 4`` (the uniform disc's covariance)."""
        return self.u_max**2 / 4.0

    @property
    def R(self) -> float:
        """Measurement-noise variance, ``noise_std^2``."""
        return self.noise_std**2

    def replace(self, **changes) -> AssignmentTrackingSetup:
        """A validated copy with some fields changed."""
        return replace(self, **changes)


@dataclass(frozen=True, eq=False)
class Scenario:
    """The random draws of a batch of runs (common to every rule), leading axis = run.

    ``sensors`` (B, N, 2); ``start`` (B, L, 2); ``estimate0`` (B, L, 2); ``controls``
    (B, steps, L, 2); ``noise`` (B, steps, N); ``perm`` (B, steps, N), the random rule's sensor
    permutations; ``seeds`` the seeds.
    """

    setup: AssignmentTrackingSetup
    seeds: tuple
    sensors: np.ndarray
    start: np.ndarray
    estimate0: np.ndarray
    controls: np.ndarray
    noise: np.ndarray
    perm: np.ndarray

    @property
    def truth(self) -> np.ndarray:
        """True positions ``o_k``, ``k = 1..steps + 1``, shape (B, steps + 1, L, 2)."""
        return np.concatenate(
            [self.start[:, None], self.start[:, None] + np.cumsum(self.controls, axis=1)], axis=1
        )


def _seeds(seeds) -> tuple:
    if isinstance(seeds, range):
        seeds = list(seeds)
    if isinstance(seeds, (int, np.integer)) and not isinstance(seeds, bool):
        seeds = [seeds]
    out = tuple(as_int(s, "seeds", 0) for s in as_sequence(seeds, "seeds"))
    if not out:
        raise ValueError("seeds must name at least one seed")
    return out


def scenario(setup: AssignmentTrackingSetup, seeds) -> Scenario:
    """Draw the runs ``seeds`` of ``setup`` (see the module's note on common random numbers).

    Examples
    --------
    >>> setup = AssignmentTrackingSetup(n_targets=2, steps=3)
    >>> sc = scenario(setup, [0, 1])
    >>> sc.sensors.shape, sc.controls.shape, sc.noise.shape, sc.perm.shape
    ((2, 4, 2), (2, 3, 2, 2), (2, 3, 4), (2, 3, 4))
    >>> one = scenario(setup, [1])  # run b depends on seeds[b] only
    >>> bool((one.sensors[0] == sc.sensors[1]).all())
    True
    >>> bool((np.linalg.norm(sc.controls, axis=-1) <= setup.u_max).all())
    True
    >>> bool((np.sort(sc.perm, axis=-1) == np.arange(4)).all())
    True
    """
    as_instance(setup, AssignmentTrackingSetup, "setup")
    seeds = _seeds(seeds)
    L, n, T = setup.n_targets, setup.n_sensors, setup.steps
    parts = {k: [] for k in ("sensors", "start", "estimate0", "controls", "noise", "perm")}
    for s in seeds:
        rng = np.random.default_rng([s, 0])
        parts["sensors"].append(rng.uniform(0, setup.side, size=(n, 2)))
        start = rng.uniform(0, setup.side, size=(L, 2))
        parts["start"].append(start)
        parts["estimate0"].append(start + rng.normal(0, np.sqrt(setup.p0), size=(L, 2)))
        rad = setup.u_max * np.sqrt(rng.uniform(size=(T, L)))
        ang = rng.uniform(0, 2 * np.pi, size=(T, L))
        parts["controls"].append(np.stack([rad * np.cos(ang), rad * np.sin(ang)], axis=-1))
        parts["noise"].append(rng.normal(0, setup.noise_std, size=(T, n)))
        rng_a = np.random.default_rng([s, 1])
        parts["perm"].append(rng_a.permuted(np.tile(np.arange(n), (T, 1)), axis=1))
    return Scenario(setup, seeds, **{k: np.stack(v) for k, v in parts.items()})


# --------------------------------------------------------------------------------------------
# Pair weights, batched over runs (validation-free workers; the public entry is run())
# --------------------------------------------------------------------------------------------


def bound_weights(sensors, xhat, cov, u_max, metric="mahalanobis") -> np.ndarray:
    """Theorem 4's pair bound for a batch: ``W[b, i, j, l]``, shape (B, N, N, L).

    Equals :func:`obslib.pair_bounds` ``(sensors[b], xhat[b], u_max, cov=cov[b])`` (Mahalanobis)
    or without ``cov`` (Euclidean), up to rounding: the same rescaling and the same kernel.
    ``sensors`` (B, N, 2), ``xhat`` (B, L, 2), ``cov`` (B, L, 2, 2).

    Examples
    --------
    >>> import obslib as ob
    >>> rng = np.random.default_rng(0)
    >>> S, x = rng.uniform(0, 10, (1, 4, 2)), rng.uniform(0, 10, (1, 2, 2))
    >>> cov = np.array([[[[1.0, 0.2], [0.2, 0.5]], [[0.3, 0.0], [0.0, 2.0]]]])
    >>> W = bound_weights(S, x, cov, 1.0)
    >>> W.shape
    (1, 4, 4, 2)
    >>> bool(np.allclose(W[0], ob.pair_bounds(S[0], x[0], 1.0, cov=cov[0])))
    True
    >>> We = bound_weights(S, x, cov, 1.0, "euclidean")
    >>> bool(np.allclose(We[0], ob.pair_bounds(S[0], x[0], 1.0)))
    True
    """
    x, y, u2 = _bound_rows(sensors, xhat, cov, u_max, metric)
    return pair_kernel(
        x[:, :, None, :], y[:, :, None, :], x[:, None, :, :], y[:, None, :, :], u2[:, None, None, :]
    )


def _bound_rows(sensors, xhat, cov, u_max, metric):
    """The scaled rows ``x, y`` ``(B, N, L)`` of ``bound_weights`` and their ``u_max^2``
    ``(B, L)``."""
    B, N, L = sensors.shape[0], sensors.shape[1], xhat.shape[1]
    v = xhat[:, :, None, :] - sensors[:, None, :, :]  # (B, L, N, 2)
    x, y, inv = _scaled(v.reshape(B * L, N, 2), cov.reshape(B * L, 2, 2), metric)
    x = x.reshape(B, L, N).transpose(0, 2, 1)  # (B, N, L)
    y = y.reshape(B, L, N).transpose(0, 2, 1)
    return x, y, (u_max**2 * inv).reshape(B, L)


def _scaled(v, cov, metric):
    """Rows ``v`` ``(M, K, 2)`` scaled as the tracking engine scales the bound's rows
    (``choosers.scaled_rows``): Mahalanobis lengths in ``cov`` ``(M, 2, 2)``
    when ``metric`` says so, divided by each estimate's longest row."""
    c = (cov[:, 0, 0], cov[:, 0, 1], cov[:, 1, 0], cov[:, 1, 1])
    maha = np.full(v.shape[0], metric == "mahalanobis")
    return tr.choosers.scaled_rows(v[..., 0].copy(), v[..., 1].copy(), c, maha)


def info_gain_weights(sensors, xhat, cov_pred, r) -> np.ndarray:
    """Information gain of every pair, ``log det J(i, j) - log det (Sigma^-)^{-1}``, (B, N, N, L).

    With ``H`` the rows ``h_i = (xhat - p_i)^T``, ``h_j`` and ``R = r I``, the gain is
    :math:`\\log\\det(I_2 + H \\Sigma^- H^T / r) = \\log((1 + a_i/r)(1 + a_j/r) - c_{ij}^2/r^2)`
    with :math:`a_i = h_i^T \\Sigma^- h_i`, :math:`c_{ij} = h_i^T \\Sigma^- h_j` (Sylvester's
    determinant identity). Symmetric in ``i, j``; the diagonal is the gain of measuring one sensor
    twice and is never used.

    Examples
    --------
    Against :math:`\\log\\det J - \\log\\det (\\Sigma^-)^{-1}` computed directly:

    >>> rng = np.random.default_rng(0)
    >>> S, x = rng.uniform(0, 10, (1, 4, 2)), rng.uniform(0, 10, (1, 1, 2))
    >>> Pm = np.array([[[[1.0, 0.2], [0.2, 0.5]]]])  # (B, L, 2, 2)
    >>> G = info_gain_weights(S, x, Pm, 0.25)
    >>> H = x[0, 0] - S[0, [0, 2]]  # rows of the pair (0, 2)
    >>> J = np.linalg.inv(Pm[0, 0]) + H.T @ H / 0.25
    >>> gain = np.log(np.linalg.det(J) * np.linalg.det(Pm[0, 0]))
    >>> bool(np.isclose(G[0, 0, 2, 0], gain, rtol=1e-10))
    True
    >>> bool((G == G.transpose(0, 2, 1, 3)).all())
    True
    """
    h = xhat[:, None, :, :] - sensors[:, :, None, :]  # (B, N, L, 2)
    hx, hy = h[..., 0] / np.sqrt(r), h[..., 1] / np.sqrt(r)  # (B, N, L)
    p00, p01, p11 = (cov_pred[:, None, None, :, a, b] for a, b in ((0, 0), (0, 1), (1, 1)))
    xi, yi, xj, yj = hx[:, :, None], hy[:, :, None], hx[:, None], hy[:, None]
    # c_ij = h_i^T Sigma^- h_j / r, written symmetrically so that c_ij == c_ji exactly
    c = p00 * (xi * xj) + p01 * (xi * yj + yi * xj) + p11 * (yi * yj)  # (B, N, N, L)
    a = np.einsum("biil->bil", c)
    det = (1 + a[:, :, None, :]) * (1 + a[:, None, :, :]) - c * c
    return np.log(det)


def batch_greedy(W) -> np.ndarray:
    """Algorithm 1 on a batch of weights ``W`` (B, N, N, L): each target's pair, (B, L, 2).

    The picks of :func:`obslib.assignment.greedy_pairs_batch` on the pairs ``i < j`` (ties to the
    smallest ``(i, j, l)``, as :func:`obslib.greedy_pair_assignment`), arranged by target.

    Examples
    --------
    >>> import obslib as ob
    >>> rng = np.random.default_rng(1)
    >>> W = rng.uniform(size=(2, 6, 6, 3))
    >>> W = W + W.transpose(0, 2, 1, 3)  # symmetric in i, j
    >>> pairs = batch_greedy(W)
    >>> pairs.shape
    (2, 3, 2)
    >>> for b in range(2):
    ...     t = ob.greedy_pair_assignment(W[b]).triples
    ...     print(all(list(pairs[b, l]) == [i, j] for i, j, l in t))
    True
    True
    """
    W = as_float_array(W, "W")
    ii, jj = np.triu_indices(W.shape[1], 1)
    return _greedy_upper(W[:, ii, jj], W.shape[1])


def _upper_bound_weights(sensors, xhat, cov, u_max, metric, ii, jj) -> np.ndarray:
    """The entries ``W[b, ii[p], jj[p], l]`` of ``bound_weights``, ``(B, P, L)``: the same
    rows and kernel for the pairs ``i < j`` only (half the kernel's work)."""
    x, y, u2 = _bound_rows(sensors, xhat, cov, u_max, metric)
    return pair_kernel(x[:, ii], y[:, ii], x[:, jj], y[:, jj], u2[:, None, :])


def _upper_gain_weights(sensors, xhat, cov_pred, r, ii, jj) -> np.ndarray:
    """The entries ``G[b, ii[p], jj[p], l]`` of ``info_gain_weights``, ``(B, P, L)``, with
    its arithmetic, for the pairs ``i < j`` only."""
    h = xhat[:, None, :, :] - sensors[:, :, None, :]  # (B, N, L, 2)
    hx, hy = h[..., 0] / np.sqrt(r), h[..., 1] / np.sqrt(r)  # (B, N, L)
    p00, p01, p11 = (cov_pred[:, None, :, a, b] for a, b in ((0, 0), (0, 1), (1, 1)))
    a = p00 * (hx * hx) + p01 * (hx * hy + hy * hx) + p11 * (hy * hy)  # c_ii, (B, N, L)
    xi, yi, xj, yj = hx[:, ii], hy[:, ii], hx[:, jj], hy[:, jj]
    c = p00 * (xi * xj) + p01 * (xi * yj + yi * xj) + p11 * (yi * yj)  # (B, P, L)
    det = (1 + a[:, ii]) * (1 + a[:, jj]) - c * c
    return np.log(det)


def _greedy_upper(w, n) -> np.ndarray:
    """Each target's pair ``(B, L, 2)`` picked by Algorithm 1
    (:func:`obslib.assignment.greedy_pairs_batch`) from the weights ``w`` ``(B, P, L)`` of the
    pairs ``i < j`` of ``n`` sensors."""
    picks, _ = greedy_pairs_batch(w, n)
    out = np.empty(picks.shape[:2] + (2,), dtype=np.int64)
    rows = np.arange(picks.shape[0])[:, None]
    out[rows, picks[..., 2]] = picks[..., :2]
    return out


def random_assignments(perm, n_targets) -> np.ndarray:
    """Pairs from sensor permutations ``perm`` (B, N): target ``l`` gets ``perm[2l], perm[2l+1]``
    (sorted), shape (B, L, 2).

    Examples
    --------
    >>> random_assignments([[3, 0, 1, 2, 5, 4]], 2).tolist()
    [[[0, 3], [1, 2]]]
    """
    p = np.asarray(perm)[:, : 2 * n_targets].reshape(-1, n_targets, 2)
    return np.sort(p, axis=-1)


def _filter_step(x, P, ps, z, q, r):
    """Predict and update every target's filter at once (:mod:`obslib.tracking.kalman`):
    estimates ``x`` (..., 2), covariances ``P`` (..., 2, 2), pair sensors ``ps`` (..., 2, 2)
    (rows the two sensors), measurements ``z`` (..., 2), noise variances ``q``, ``r`` per axis.
    Returns the new ``x, P`` (new arrays); raises
    :class:`~obslib.tracking.kalman.SingularInnovation` as the update does."""
    Pm = kalman._predict((P[..., 0, 0], P[..., 0, 1], P[..., 1, 0], P[..., 1, 1]),
                        ((q, 0.0), (0.0, q)))
    xn, Pn = kalman._update((x[..., 0], x[..., 1]), Pm, (ps[..., 0, 0], ps[..., 0, 1]),
                           (ps[..., 1, 0], ps[..., 1, 1]), (z[..., 0], z[..., 1]),
                           ((r, 0.0), (0.0, r)))
    return np.stack(xn, axis=-1), np.stack(Pn, axis=-1).reshape(P.shape)


# --------------------------------------------------------------------------------------------
# Runs
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class AssignmentRuns:
    """The runs of one rule: per-step arrays, step ``k`` at index ``k - 1``, leading axis = run.

    ``pairs`` (B, steps, L, 2) each target's pair; ``error`` (B, steps, L) ``||xhat - o_k||``
    before the step's update (the convention of :mod:`obslib.tracking`; it includes the target's
    last move); ``post_error`` (B, steps, L) ``||xhat - o_k||`` after it, the error the
    assignment of step ``k`` controls; ``trace`` (B, steps, L) ``tr Sigma`` before the update;
    ``bound`` (B, steps, L) the chosen pair's bound as the ``"bound"`` rule scores it; ``gain``
    (B, steps, L) its information gain as the ``"d-optimal"`` rule scores it.
    """

    setup: AssignmentTrackingSetup
    rule: str
    seeds: tuple
    pairs: np.ndarray
    error: np.ndarray
    post_error: np.ndarray
    estimate: np.ndarray
    truth: np.ndarray
    trace: np.ndarray
    bound: np.ndarray
    gain: np.ndarray
    extras: dict = field(default_factory=dict)

    def total_error(self, which: str = "post") -> np.ndarray:
        """Error summed over targets, (B, steps): after the update (``"post"``) or before it
        (``"prior"``)."""
        if which not in ("post", "prior"):
            raise ValueError(f"which must be 'post' or 'prior', got {which!r}")
        return (self.post_error if which == "post" else self.error).sum(axis=-1)

    def lost(self, threshold: float, skip_first: bool = True) -> np.ndarray:
        """(B, L) bool: targets whose mean error after the update exceeds ``threshold``."""
        e = (
            self.post_error[:, 1:]
            if skip_first and self.post_error.shape[1] > 1
            else self.post_error
        )
        return e.mean(axis=1) > threshold

    def mirrored(self) -> np.ndarray:
        """(B, L) bool: the last estimate is closer to the target's mirror image across the
        baseline of its last pair than to the target (the two-range ambiguity)."""
        S = self.extras["sensors"]
        b = np.arange(S.shape[0])[:, None]
        a, c = S[b, self.pairs[:, -1, :, 0]], S[b, self.pairs[:, -1, :, 1]]  # (B, L, 2)
        o, x = self.truth[:, -1], self.estimate[:, -1]
        d = (c - a) / np.hypot(*(c - a).transpose(2, 0, 1))[..., None]
        v = o - a
        m = a + 2 * (v * d).sum(-1)[..., None] * d - v  # o reflected across the baseline
        return np.hypot(*(x - m).transpose(2, 0, 1)) < np.hypot(*(x - o).transpose(2, 0, 1))

    def run_mean_error(self, which: str = "post", skip_first: bool = True) -> np.ndarray:
        """Per-run mean over steps of the error summed over targets, (B,).

        ``skip_first`` leaves out step 1, whose prior error is the same for every rule.
        """
        e = self.total_error(which)
        return (e[:, 1:] if skip_first and e.shape[1] > 1 else e).mean(axis=1)


def _chosen_values(S, x, P, pr, u_max, metric, q, r):
    """The bound and the information gain of the chosen pairs ``pr`` (B, L, 2), each (B, L):
    the entries of ``bound_weights`` and ``info_gain_weights`` at the chosen pairs, up
    to rounding, without scoring the other pairs."""
    bb = np.arange(S.shape[0])[:, None]
    ps = S[bb[..., None], pr]  # (B, L, 2, 2)
    h = x[..., None, :] - ps  # rows x - p_i, x - p_j
    B, L = h.shape[0], h.shape[1]
    x, y, inv = _scaled(h.reshape(B * L, 2, 2), P.reshape(B * L, 2, 2), metric)
    bound = pair_kernel(x[:, 0], y[:, 0], x[:, 1], y[:, 1], u_max**2 * inv).reshape(B, L)
    G = h @ (P + q * np.eye(2)) @ np.swapaxes(h, -1, -2) / r  # H Sigma^- H^T / r
    gain = np.log((1 + G[..., 0, 0]) * (1 + G[..., 1, 1]) - G[..., 0, 1] * G[..., 1, 0])
    return bound, gain


def _run(sc: Scenario, rules) -> dict:
    """All ``rules`` on the scenario ``sc`` in one batch (rule-major rows), step by step."""
    st = sc.setup
    nb, L, T = len(sc.seeds), st.n_targets, st.steps
    nr = len(rules)
    B = nr * nb
    q, r = st.Q, st.R
    S = np.tile(sc.sensors, (nr, 1, 1))
    truth = np.tile(sc.truth, (nr, 1, 1, 1))
    noise = np.tile(sc.noise, (nr, 1, 1))
    rows = {rule: slice(a * nb, (a + 1) * nb) for a, rule in enumerate(rules)}
    x = np.tile(sc.estimate0, (nr, 1, 1))
    P = np.broadcast_to(st.p0 * np.eye(2), (B, L, 2, 2)).copy()
    pairs = np.empty((B, T, L, 2), dtype=np.int64)
    err, post, tr, bnd, gain = (np.empty((B, T, L)) for _ in range(5))
    est = np.empty((B, T, L, 2))
    bb = np.arange(B)[:, None]
    pr = np.empty((B, L, 2), dtype=np.int64)
    # the rules score the pairs i < j only: the greedy never looks at the others (the picks of
    # bound_weights and info_gain_weights with batch_greedy; 0.25 s against 0.5 s per study)
    ii, jj = np.triu_indices(S.shape[1], 1)
    for k in range(T):
        for rule, sl in rows.items():
            if rule == "bound":
                w = _upper_bound_weights(S[sl], x[sl], P[sl], st.u_max, st.metric, ii, jj)
                pr[sl] = _greedy_upper(w, S.shape[1])
            elif rule == "d-optimal":
                w = _upper_gain_weights(S[sl], x[sl], P[sl] + q * np.eye(2), r, ii, jj)
                pr[sl] = _greedy_upper(w, S.shape[1])
            else:
                pr[sl] = random_assignments(sc.perm[:, k], L)
        pairs[:, k] = pr
        bnd[:, k], gain[:, k] = _chosen_values(S, x, P, pr, st.u_max, st.metric, q, r)
        o = truth[:, k]
        dx = x - o
        err[:, k] = np.hypot(dx[..., 0], dx[..., 1])
        tr[:, k] = P[..., 0, 0] + P[..., 1, 1]
        ps = S[bb[..., None], pr]  # (B, L, 2, 2)
        d = ps - o[..., None, :]
        z = 0.5 * (d[..., 0] ** 2 + d[..., 1] ** 2) + noise[:, k][bb[..., None], pr]
        try:
            x, P = _filter_step(x, P, ps, z, q, r)
        except kalman.SingularInnovation as e:
            b, l = (int(v) for v in np.argwhere(~e.ok)[0])
            raise ValueError(
                f"the filter of target {l} failed at step {k + 1} of seed {sc.seeds[b % nb]} "
                f"(rule {rules[b // nb]!r}): the innovation covariance H P H^T + R is singular in "
                f"floating point (estimate {np.round(x[b, l], 6).tolist()}, pair sensors "
                f"{ps[b, l].tolist()}); the estimate is too far from the sensors or its "
                "covariance too large for the two ranges to tell it apart") from None
        dx = x - o
        post[:, k] = np.hypot(dx[..., 0], dx[..., 1])
        est[:, k] = x
    return {
        rule: AssignmentRuns(st, rule, sc.seeds, pairs[sl], err[sl], post[sl], est[sl],
                             sc.truth[:, :T], tr[sl], bnd[sl], gain[sl], {"sensors": sc.sensors})
        for rule, sl in rows.items()
    }


def run(setup: AssignmentTrackingSetup, rule: str, seeds) -> AssignmentRuns:
    """Runs ``seeds`` of ``setup`` with the assignment ``rule`` (one of :data:`RULES`).

    Run ``b`` depends only on ``(setup, rule, seeds[b])``: the same seed gives the same run in
    any batch, and every rule sees the same draws (common random numbers).

    Examples
    --------
    >>> import obslib as ob
    >>> setup = AssignmentTrackingSetup(n_targets=2, steps=4)
    >>> r = run(setup, "bound", [0, 1])
    >>> r.pairs.shape, r.error.shape
    ((2, 4, 2, 2), (2, 4, 2))
    >>> one = run(setup, "bound", [1])
    >>> bool(np.allclose(one.post_error[0], r.post_error[1], rtol=1e-12))
    True

    Step 1 is Algorithm 1 on the bound at the initial estimates (covariance
    ``p0 I``):

    >>> sc = scenario(setup, [0])
    >>> W = ob.pair_bounds(sc.sensors[0], sc.estimate0[0], 1.0, cov=np.eye(2))
    >>> t = ob.greedy_pair_assignment(W).triples
    >>> sorted(t) == sorted((i, j, l) for l, (i, j) in enumerate(r.pairs[0, 0]))
    True
    """
    as_choice(rule, RULES, "rule")
    return _run(scenario(setup, seeds), [rule])[rule]


def run_all(setup: AssignmentTrackingSetup, seeds, rules=RULES) -> dict:
    """:func:`run` for several rules on one shared draw: ``{rule: AssignmentRuns}``.

    Examples
    --------
    >>> setup = AssignmentTrackingSetup(n_targets=2, steps=4)
    >>> runs = run_all(setup, [0, 1], rules=("bound", "random"))
    >>> list(runs)
    ['bound', 'random']
    >>> alone = run(setup, "random", [0, 1])
    >>> e = runs["random"].post_error
    >>> bool(np.allclose(e, alone.post_error, rtol=1e-12))
    True
    >>> # step 1's prior error does not depend on the rule
    >>> bool((runs["bound"].error[:, 0] == runs["random"].error[:, 0]).all())
    True
    """
    rules = list(as_names(rules, "rules", RULES))
    return _run(scenario(setup, seeds), rules)

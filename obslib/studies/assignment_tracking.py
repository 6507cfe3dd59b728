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
    of Section V evaluate it) or Euclidean ones (the assignment ``"unique-pairs"`` of
    :mod:`obslib.tracking.assigners`);
``"d-optimal"``
    the same greedy on the information gain of the pair,
    :math:`\\log\\det J_l(i, j) - \\log\\det (\\Sigma_l^-)^{-1}` with
    :math:`J_l(i, j) = (\\Sigma_l^-)^{-1} + H^T R^{-1} H`, :math:`\\Sigma_l^- = \\Sigma_l + Q` and
    ``H`` the rows :math:`(\\hat x_l - p_i)^T, (\\hat x_l - p_j)^T` (D-optimal design;
    ``"d-optimal-pairs"``);
``"random"``
    a uniformly random valid assignment (a random permutation of the sensors, paired in order;
    ``"random"`` with the scenario's permutations).

The model
---------
Target ``l`` moves by a control drawn uniformly from the disc of radius ``u_max`` (the paper's
bounded unknown control): :math:`o_{k+1} = o_k + u_k`. Each filter predicts with the random walk
:math:`\\hat x^- = \\hat x`, :math:`\\Sigma^- = \\Sigma + Q`, :math:`Q = (u_{max}^2 / 4) I`
(the covariance of the uniform disc), and updates with the half squared ranges
:math:`z_i = \\tfrac12 \\|p_i - o\\|^2 + n_i` (Section II;
:func:`obslib.tracking.half_squared_range`) of its two sensors, :math:`n_i \\sim N(0, \\sigma^2)`,
``R = sigma^2 I``: the tracking engine's extended Kalman filters (:mod:`obslib.tracking.engine`,
filterpy's equations, Joseph form; the runs are :func:`obslib.tracking.simulate_targets_scenes`,
one scene per seed), which stop with a ``ValueError`` naming the run, target and step where the
innovation covariance is singular.

Order within step ``k``, as in :mod:`obslib.tracking`: (1) assign from the current estimates and
covariances; (2) log each target's error :math:`\\|\\hat x - o\\|` and :math:`\\operatorname{tr}
\\Sigma` before the update; (3) predict, measure, update; (4) move the targets.

Common random numbers: seed ``s`` fixes the sensors, the targets' starts and controls, the
initial estimates and the measurement noise (``numpy.random.default_rng([s, 0])``; entry
``[k, i]`` of the noise table is sensor ``i``'s at step ``k``, whichever target it serves) and
the random assignments (``default_rng([s, 1])``), identically for every rule. All runs and
targets advance together on the engine.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from .. import tracking
from .._kernels import pair_kernel
from .._validate import (
    as_choice,
    as_instance,
    as_int,
    as_names,
    as_positive,
    as_sequence,
    as_str,
)

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
        if as_str(self.metric, "metric") not in tracking.METRICS:
            raise ValueError(f"metric must be one of {tracking.METRICS}, got {self.metric!r}")

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
# The logged pairs' values (validation-free workers; the public entry is run())
# --------------------------------------------------------------------------------------------


def _scaled(v, cov, metric):
    """Rows ``v`` ``(M, K, 2)`` scaled as Section V's choosers scale the bound's rows
    (``choosers.scaled_rows``): Mahalanobis lengths in ``cov`` ``(M, 2, 2)``
    when ``metric`` says so, divided by each estimate's longest row."""
    c = (cov[:, 0, 0], cov[:, 0, 1], cov[:, 1, 0], cov[:, 1, 1])
    maha = np.full(v.shape[0], metric == "mahalanobis")
    return tracking.choosers.scaled_rows(v[..., 0].copy(), v[..., 1].copy(), c, maha)


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


#: The assignments of :mod:`obslib.tracking.assigners` that make each rule's choice.
_ASSIGNMENT = {"bound": "unique-pairs", "d-optimal": "d-optimal-pairs", "random": "random"}


def _scene_setups(sc: Scenario) -> list:
    """One :class:`obslib.tracking.TargetsSetup` per run of the scenario: its sensors, the
    targets' paths and initial estimates, and the filter of the study."""
    st = sc.setup
    common = dict(cov0=st.p0, Q=st.Q, R=st.R, noise_std=st.noise_std, u_max=st.u_max,
                  measurement="half-squared-range", metric=st.metric)
    return [tracking.TargetsSetup(sensors=sc.sensors[b], truth=sc.truth[b],
                                  estimate0=sc.estimate0[b], **common)
            for b in range(len(sc.seeds))]


def _run(sc: Scenario, rules) -> dict:
    """All ``rules`` on the scenario ``sc`` in one pass of the tracking engine
    (:func:`obslib.tracking.simulate_targets_scenes` with the scenario's noise and random
    permutations), then each chosen pair's bound and gain from the logged states."""
    st = sc.setup
    T, L = st.steps, st.n_targets
    runs = tracking.simulate_targets_scenes(_scene_setups(sc), [_ASSIGNMENT[r] for r in rules],
                                            noise=sc.noise, draws=sc.perm)
    nb, n = len(sc.seeds), st.n_sensors
    out = {}
    for rule in rules:
        b = runs[_ASSIGNMENT[rule]]
        # each target's two sensors, in increasing order: sort by (target, sensor)
        key = np.where(b.labels >= 0, b.labels, L).astype(np.int64) * n + np.arange(n)
        pairs = np.sort(key, axis=-1)[..., : 2 * L] % n
        pairs = pairs.reshape(nb, T, L, 2)
        post = np.concatenate([b.estimate[:, 1:], b.estimate_end[:, None]], axis=1)
        dx = post - sc.truth[:, :T]
        S = np.repeat(sc.sensors, T, axis=0)
        bound, gain = _chosen_values(S, b.estimate.reshape(nb * T, L, 2),
                                     b.cov.reshape(nb * T, L, 2, 2), pairs.reshape(nb * T, L, 2),
                                     st.u_max, st.metric, st.Q, st.R)
        out[rule] = AssignmentRuns(st, rule, sc.seeds, pairs, b.error,
                                   np.hypot(dx[..., 0], dx[..., 1]), post, sc.truth[:, :T],
                                   b.trace_cov, bound.reshape(nb, T, L), gain.reshape(nb, T, L),
                                   {"sensors": sc.sensors})
    return out


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

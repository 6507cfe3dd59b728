"""Studies of the greedy team assignment of Problem 2: Fig. 9's evenness and the greedy against the
exact optimum (Sections IV-B and V-D; notebook 08, claims of
:mod:`obslib.claims.general_assignment`).

Fig. 9 of the paper plots, for ``L = 5`` targets and ``N = 20..50`` sensors in ``[0, 100]^2``,
the mean and spread of the number of sensors the greedy (log det measure) gives to a target.
Targets are exchangeable, so for any rule that does not favour target indices the *mean* count
of every target is ``N / L`` by symmetry; evenness is a property of each trial, measured here by
the spread of the counts within a trial and compared with a uniformly random assignment.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .._validate import (
    as_eps,
    as_float_array,
    as_int,
    as_int_range,
    as_ints,
    as_positive,
    as_str,
    check_maximisable,
)
from ..bounds import relative_vectors
from ..measures import MEASURES, measure_from_vectors, subset_masks
from ..sweep import run_sweep
from ..teams import (
    MAXIMISABLE,
    best_team_labelling,
    greedy_team_assignment,
    greedy_team_counts,
    greedy_team_picks,
)

__all__ = [
    "NOTEBOOK",
    "fig9_geometry",
    "fig9_trial",
    "fig9_trials",
    "fig9_sweep",
    "random_spread",
    "Evenness",
    "evenness",
    "greedy_vs_optimal_teams",
]

#: The chapter of these studies.
NOTEBOOK = "08_general_assignment"


def fig9_geometry(n_sensors, trial, seed, n_targets, side):
    """Sensors and targets of one Fig. 9 trial, uniform in the square of ``side``, seeded by
    ``(seed, n_sensors, trial)`` so every study of Fig. 9 sees the same geometry.

    Examples
    --------
    >>> S, T = fig9_geometry(10, trial=0, seed=0, n_targets=3, side=100.0)
    >>> S.shape, T.shape, bool(((S >= 0) & (S <= 100)).all())
    ((10, 2), (3, 2), True)
    >>> rng = np.random.default_rng([0, 10, 0])  # sensors first, then targets
    >>> bool((S == rng.uniform(0, 100, (10, 2))).all())
    True
    >>> S1, _ = fig9_geometry(10, trial=1, seed=0, n_targets=3, side=100.0)
    >>> bool((S1 != S).any())
    True
    """
    n_sensors, trial = as_int(n_sensors, "n_sensors", 0), as_int(trial, "trial", 0)
    seed, n_targets = as_int(seed, "seed", 0), as_int(n_targets, "n_targets", 0)
    side = as_positive(side, "side")
    rng = np.random.default_rng([seed, n_sensors, trial])
    return rng.uniform(0, side, size=(n_sensors, 2)), rng.uniform(0, side, size=(n_targets, 2))


def fig9_trial(n_sensors: int, trial: int, seed: int, n_targets: int = 5, measure: str = "logdet",
               eps: float = 1.0, side: float = 100.0) -> np.ndarray:
    r"""Sensors per target (shape ``(L,)``) of one greedy team assignment.

    The draw depends only on ``(seed, N, trial)`` (``default_rng([seed, N, trial])``): sensors
    first, then targets, uniform in :math:`[0, \mathrm{side}]^2`.

    Examples
    --------
    >>> counts = fig9_trial(n_sensors=20, trial=0, seed=0)
    >>> counts.size, int(counts.sum())
    (5, 20)
    """
    S, T = fig9_geometry(n_sensors, trial, seed, n_targets, side)
    teams = greedy_team_assignment(S, T, measure=measure, eps=eps)
    return np.array([len(t) for t in teams])


def fig9_trials(n_sensors: int, trials, seed: int, n_targets: int = 5, measure: str = "logdet",
                eps: float = 1.0, side: float = 100.0) -> np.ndarray:
    """:func:`fig9_trial` for several trials of one ``N`` at once (one batch), shape ``(len(trials),
    L)``.

    Examples
    --------
    >>> fig9_trials(20, [0, 1], seed=0).sum(axis=1)
    array([20, 20])
    """
    trials = as_ints(trials, "trials", 0)
    geoms = [fig9_geometry(n_sensors, t, seed, n_targets, side) for t in trials]
    return greedy_team_counts(
        np.array([g[0] for g in geoms]).reshape(-1, n_sensors, 2),
        np.array([g[1] for g in geoms]).reshape(-1, n_targets, 2),
        measure,
        eps,
    )


def fig9_sweep(N_values, trials: int, seed: int, n_targets: int = 5, measure: str = "logdet",
               eps: float = 1.0, side: float = 100.0, backend: str = "serial", n_jobs=None,
               scheduler=None, progress: bool = False) -> np.ndarray:
    """Counts of shape ``(len(N_values), trials, L)`` for the Fig. 9 sweep.

    One task per ``N`` runs its trials as a batch (:func:`fig9_trials`); every trial keeps its own
    seed, so ``backend``, ``n_jobs`` and ``scheduler`` (for :func:`obslib.sweep.run_sweep`) do
    not change the counts; ``progress`` shows a bar of the finished sizes on standard error.

    Examples
    --------
    >>> fig9_sweep([20, 25], trials=2, seed=0).shape
    (2, 2, 5)
    """
    N_values = as_ints(N_values, "N_values", 0)
    trials, seed = as_int(trials, "trials", 1), as_int(seed, "seed", 0)
    # every argument of the trials is checked here, before the tasks go to joblib or Dask
    n_targets, eps = as_int(n_targets, "n_targets", 0), as_eps(eps)
    check_maximisable(as_str(measure, "measure"), eps, MEASURES, MAXIMISABLE)
    side = as_positive(side, "side")
    tasks = [
        dict(
            n_sensors=n,
            trials=list(range(trials)),
            seed=seed,
            n_targets=n_targets,
            measure=measure,
            eps=eps,
            side=side,
        )
        for n in N_values
    ]
    counts = run_sweep(fig9_trials, tasks, backend, n_jobs, scheduler, progress)
    return np.array(counts).reshape(len(N_values), trials, n_targets)


def random_spread(n_sensors: int, n_targets: int) -> float:
    """Expected within-trial standard deviation scale of a uniformly random assignment.

    Each count is Binomial(N, 1/L): standard deviation ``sqrt(N (1/L)(1 - 1/L))``.

    Examples
    --------
    >>> round(random_spread(20, 5), 4)
    1.7889
    """
    n_sensors, n_targets = as_int(n_sensors, "n_sensors", 0), as_int(n_targets, "n_targets", 1)
    p = 1.0 / n_targets
    return float(np.sqrt(n_sensors * p * (1 - p)))


@dataclass(frozen=True)
class Evenness:
    """How evenly a sweep's counts (shape ``(len(N), trials, L)``) share the sensors out, per ``N``.

    ``within`` is the mean over trials of the standard deviation of the ``L`` counts of a trial,
    ``baseline`` the same for a uniformly random assignment (:func:`random_spread`) and
    ``relative = within / baseline``. ``mean_deviation`` is the largest ``|mean count - N/L|``
    over ``N`` and targets, and ``z`` those deviations over their standard errors: the means are
    ``N/L`` by symmetry, so they say nothing about evenness by themselves.
    """

    fair: np.ndarray
    within: np.ndarray
    baseline: np.ndarray
    relative: np.ndarray
    mean_deviation: float
    z: np.ndarray


def evenness(counts, N_values, n_targets: int) -> Evenness:
    """Evenness statistics of Fig. 9 sweep counts (see :class:`Evenness`).

    Examples
    --------
    >>> e = evenness(fig9_sweep([20, 25], trials=3, seed=0), [20, 25], n_targets=5)
    >>> e.fair, bool((e.relative < 1).all())
    (array([4., 5.]), True)
    """
    C = as_float_array(counts, "counts")
    N = as_float_array(N_values, "N_values")
    n_targets = as_int(n_targets, "n_targets", 1)
    if C.ndim != 3 or N.shape != (C.shape[0],) or C.shape[1] < 1:
        raise ValueError(f"counts (len(N_values), trials, n_targets) and N_values must match, "
                         f"got {C.shape} and {N.shape}")
    fair = N / n_targets
    dev = np.abs(C.mean(axis=1) - fair[:, None])
    se = C.std(axis=1, ddof=1) / np.sqrt(C.shape[1]) if C.shape[1] > 1 else np.zeros(dev.shape)
    z = dev / np.where(se > 0, se, np.inf)
    within = C.std(axis=2).mean(axis=1)
    baseline = np.array([random_spread(int(n), n_targets) for n in N_values])
    return Evenness(fair, within, baseline, within / baseline, float(dev.max()), z)


def greedy_vs_optimal_teams(
    n_instances: int,
    seed: int,
    sensors=(3, 7),
    targets=(1, 3),
    measure: str = "logdet",
    eps: float = 1.0,
    side: float = 100.0,
) -> np.ndarray:
    """Greedy / exact optimum of Problem 2 on tiny random instances (array of ratios).

    Instances are drawn one after the other (``N``, then ``L``, then sensors and targets); those of
    the same ``(N, L)`` are then solved together: a measure table over all ``2^N`` teams per
    target (:func:`obslib.measures.measure_from_vectors`), the greedy's teams looked up in it and
    the optimum found over all ``L^N`` assignments, as :func:`obslib.optimal_team_assignment` does.

    The ratios are computed once per arguments (cached) and returned as a fresh array.

    Examples
    --------
    >>> ratios = greedy_vs_optimal_teams(5, seed=0)
    >>> ratios.shape, bool(ratios.min() >= 0.5)
    ((5,), True)
    """
    e = as_eps(eps)
    check_maximisable(measure, e, MEASURES, MAXIMISABLE)
    n_instances, seed = as_int(n_instances, "n_instances", 1), as_int(seed, "seed", 0)
    sensors, targets = as_int_range(sensors, "sensors", 1), as_int_range(targets, "targets", 1)
    side = as_positive(side, "side")
    return _greedy_vs_optimal_teams(n_instances, seed, tuple(sensors), tuple(targets), measure, e,
                                    side).copy()


@lru_cache(maxsize=4)
def _greedy_vs_optimal_teams(n_instances, seed, sensors, targets, measure, e, side) -> np.ndarray:
    """:func:`greedy_vs_optimal_teams` on validated arguments, computed once per arguments (the
    chapter and the ledger share it; the public function returns a copy)."""
    rng = np.random.default_rng(seed)
    draws = []
    for _ in range(n_instances):
        n = int(rng.integers(sensors[0], sensors[1] + 1))
        L = int(rng.integers(targets[0], targets[1] + 1))
        draws.append((n, L, rng.uniform(0, side, (n, 2)), rng.uniform(0, side, (L, 2))))
    out = np.ones(n_instances)
    for n, L in sorted({(d[0], d[1]) for d in draws}):
        idx = [k for k, d in enumerate(draws) if d[:2] == (n, L)]
        V = np.stack(
            [relative_vectors(draws[k][2], draws[k][3]) for k in idx]
        )  # (K, N, L, 2), validated
        tables = [
            measure_from_vectors(V[:, :, l, :], subset_masks(n), measure, e) for l in range(L)
        ]  # (K, 2^N)
        bits = 1 << np.arange(n, dtype=np.int64)
        opt = best_team_labelling(np.stack(tables))[1]
        picks_i, picks_l = greedy_team_picks(np.stack([draws[k][2] for k in idx]),
                                             np.stack([draws[k][3] for k in idx]), measure, e)
        g = np.zeros(len(idx))
        for l in range(L):
            g += np.take_along_axis(
                tables[l], (np.where(picks_l == l, bits[picks_i], 0)).sum(axis=1)[:, None], 1
            )[:, 0]
        with np.errstate(divide="ignore", invalid="ignore"):
            out[idx] = np.where(opt > 0, g / opt, 1.0)
    return out

"""Fig. 8's experiment: greedy unique pairs against the relaxed matching and the exact optimum as
the number of targets grows (Section V-C; notebook 07, claims of
:mod:`obslib.claims.greedy_vs_relaxed`)."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .._validate import (
    as_bool,
    as_int,
    as_ints,
    as_mapping,
    as_nonnegative,
    as_positive,
    as_weights,
)
from ..assignment import (
    greedy_pair_assignment,
    optimal_pair_assignment,
    relaxed_from_geometry,
    relaxed_pair_assignment,
)
from ..bounds import pair_bounds
from ..sweep import run_sweep
from .batch_optimum import MAX_DP_SENSORS, batch_pair_bounds, greedy_values, optimal_values

__all__ = [
    "NOTEBOOK",
    "FIG8_KEYS",
    "FIG8_DENSE_WEIGHTS",
    "fig8_instance",
    "fig8_trial",
    "fig8_sweep",
    "Fig8Summary",
    "fig8_summary",
    "Problem3Audit",
    "problem3_milp",
    "problem3_audit",
]

#: The chapter of these studies.
NOTEBOOK = "07_greedy_vs_relaxed"

#: The values each trial reports.
FIG8_KEYS = ("greedy", "relaxed", "relaxed_ordered", "optimum")
#: Up to this many pair weights a Fig. 8 trial computes them all and shares them between the
#: algorithms; beyond, the greedy and the relaxations prune (the values are the same either way).
FIG8_DENSE_WEIGHTS = 1 << 17
#: A task of :func:`fig8_sweep` batches the trials of one ``L`` whose weight arrays ``(N, N, L)``
#: hold together at most this many weights (16 MiB; at least one trial per task).
_BLOCK_WEIGHTS = 1 << 21


def _is_dense(n_targets: int) -> bool:
    """Whether a Fig. 8 trial with ``L`` targets computes all its pair weights at once."""
    n = 2 * n_targets
    return n * (n - 1) // 2 * n_targets <= FIG8_DENSE_WEIGHTS


def fig8_instance(n_targets: int, trial: int, seed: int, side: float = 100.0) -> tuple:
    """The instance of one Fig. 8 trial: ``N = 2L`` sensors ``(2L, 2)`` and ``L`` targets
    ``(L, 2)`` uniform in ``[0, side]^2``, drawn in that order from
    ``numpy.random.default_rng([seed, L, trial])``.

    Examples
    --------
    >>> S, T = fig8_instance(n_targets=3, trial=0, seed=0)
    >>> S.shape, T.shape
    ((6, 2), (3, 2))
    """
    return _draw(as_int(n_targets, "n_targets", 1), as_int(trial, "trial", 0),
                 as_int(seed, "seed", 0), as_positive(side, "side"))


def _draw(n_targets, trial, seed, side) -> tuple:
    rng = np.random.default_rng([seed, n_targets, trial])
    S = rng.uniform(0, side, size=(2 * n_targets, 2))
    T = rng.uniform(0, side, size=(n_targets, 2))
    return S, T


def _dense_values(W, with_optimum: bool) -> dict:
    """Key of :data:`FIG8_KEYS` -> values of the instances with all their weights ``W``
    ``(K, N, N, L)`` at hand: the greedy in one batched call (each instance's rounds are
    independent of the others'), each relaxed matching from its ``W``, the optimum (NaN unless
    ``with_optimum``) by the dynamic program in one batched call up to
    :data:`~obslib.studies.batch_optimum.MAX_DP_SENSORS` sensors, else by the exact solver."""
    relaxed = {key: np.array([relaxed_pair_assignment(w, ordered).value for w in W])
               for key, ordered in (("relaxed", False), ("relaxed_ordered", True))}
    out = {"greedy": greedy_values(W), **relaxed, "optimum": np.full(len(W), np.nan)}
    if with_optimum:
        out["optimum"] = (optimal_values(W) if W.shape[1] <= MAX_DP_SENSORS
                          else np.array([optimal_pair_assignment(w).value for w in W]))
    return out


def fig8_trial(n_targets: int, trial: int, seed: int, u_max: float = 1.0, side: float = 100.0,
               with_optimum: bool = False) -> dict:
    """One trial of Fig. 8, on the instance :func:`fig8_instance` draws.

    The draw depends only on ``(seed, L, trial)``, so a sweep gives the same numbers in any
    order, serially or in parallel. Returns the greedy,
    relaxed (Problem 3), ordered-pair relaxed (the original code's) values, and the exact optimum
    when ``with_optimum`` (NaN otherwise).

    Examples
    --------
    >>> t = fig8_trial(n_targets=3, trial=0, seed=0, with_optimum=True)
    >>> t["greedy"] <= t["optimum"] <= t["relaxed"] <= t["relaxed_ordered"]
    True
    """
    n_targets, trial = as_int(n_targets, "n_targets", 1), as_int(trial, "trial", 0)
    seed, with_optimum = as_int(seed, "seed", 0), as_bool(with_optimum, "with_optimum")
    u_max, side = as_nonnegative(u_max, "u_max"), as_positive(side, "side")
    S, T = _draw(n_targets, trial, seed, side)
    if _is_dense(n_targets):  # small: every weight, computed once
        values = _dense_values(pair_bounds(S, T, u_max)[None], with_optimum)
        return {k: float(v[0]) for k, v in values.items()}
    # large: each algorithm evaluates only the pairs that can matter
    relaxed = relaxed_from_geometry(S, T, u_max)
    return {
        "greedy": greedy_pair_assignment(sensors=S, targets=T, u_max=u_max).value,
        "relaxed": relaxed[0].value,
        "relaxed_ordered": relaxed[1].value,
        "optimum": (optimal_pair_assignment(pair_bounds(S, T, u_max)).value if with_optimum
                    else np.nan),
    }


def _fig8_block(n_targets: int, first: int, stop: int, seed: int, u_max: float, side: float,
                with_optimum: bool) -> dict:
    """Trials ``first .. stop - 1`` of Fig. 8 at ``L = n_targets``: key of :data:`FIG8_KEYS` ->
    array of their values, each equal bit for bit to :func:`fig8_trial`'s.

    Small instances are solved together: the weights by
    :func:`obslib.studies.batch_optimum.batch_pair_bounds` (bit for bit :func:`obslib.pair_bounds`),
    then the values as one trial computes them, for the whole block at once. The 600 trials of the
    notebook's sweep (``L = 1 .. 20``, 30 trials, optimum up to ``L = 6``) took 1.2 to 1.7 s one
    trial per task and take 0.5 to 0.7 s this way, measured side by side (the greedy had run 600
    times on a batch of one). Large
    instances, and a degenerate draw (which :func:`obslib.pair_bounds` refuses), go through
    :func:`fig8_trial`.
    """
    trials = range(first, stop)
    W = None
    if _is_dense(n_targets):
        S, T = (np.stack(a) for a in zip(*(_draw(n_targets, t, seed, side) for t in trials)))
        W, valid = batch_pair_bounds(S, T, u_max)  # (K, N, N, L)
        if not valid.all():  # a draw of probability zero: fig8_trial raises pair_bounds's error
            W = None
    if W is None:
        rows = [fig8_trial(n_targets, t, seed, u_max, side, with_optimum) for t in trials]
        return {k: np.array([r[k] for r in rows], dtype=float) for k in FIG8_KEYS}
    return _dense_values(W, with_optimum)


def fig8_sweep(L_values, trials: int, seed: int, u_max: float = 1.0, side: float = 100.0,
               optimum_max_L: int = 0, backend: str = "serial", n_jobs=None, scheduler=None,
               progress: bool = False) -> dict:
    """Fig. 8's sweep: arrays of shape ``(len(L_values), trials)`` for each of :data:`FIG8_KEYS`.

    Entry ``[a, t]`` is :func:`fig8_trial` ``(L_values[a], t, seed, u_max, side,
    L_values[a] <= optimum_max_L)``, bit for bit. Each task of the sweep solves a block of
    trials of one ``L`` together (one trial per task for the large instances);
    ``backend``, ``n_jobs``, ``scheduler`` and ``progress`` (a bar of the finished tasks on
    standard error) go to :func:`obslib.sweep.run_sweep`; the numbers do not depend on them, so
    the result is cached on the other arguments (its arrays are read-only): a chapter and the
    ledger asking for the same sweep share one computation.

    Examples
    --------
    >>> r = fig8_sweep([1, 2], trials=2, seed=0)
    >>> r["L"].tolist(), r["greedy"].shape
    ([1, 2], (2, 2))
    """
    key = (tuple(as_ints(L_values, "L_values", 1)), as_int(trials, "trials", 1),
           as_int(seed, "seed", 0), float(as_nonnegative(u_max, "u_max")),
           float(as_positive(side, "side")), as_int(optimum_max_L, "optimum_max_L", 0))
    if key not in _SWEEPS:
        out = _fig8_sweep(*key, backend, n_jobs, scheduler, progress)
        for arr in out.values():
            arr.setflags(write=False)
        if len(_SWEEPS) >= _MAX_SWEEPS:  # forget the oldest
            del _SWEEPS[next(iter(_SWEEPS))]
        _SWEEPS[key] = out
    return dict(_SWEEPS[key])


#: The sweeps computed so far, by their arguments (at most :data:`_MAX_SWEEPS`, oldest first).
_SWEEPS: dict = {}
_MAX_SWEEPS = 8
fig8_sweep.cache_clear = _SWEEPS.clear  # as functools.lru_cache names it


def _fig8_sweep(L_values, trials, seed, u_max, side, optimum_max_L, backend, n_jobs, scheduler,
                progress) -> dict:
    tasks, where = [], []
    for a, L in enumerate(L_values):
        n = 2 * L
        block = max(1, _BLOCK_WEIGHTS // (n * n * L)) if _is_dense(L) else 1
        for first in range(0, trials, block):
            stop = min(first + block, trials)
            tasks.append(dict(n_targets=L, first=first, stop=stop, seed=seed, u_max=u_max,
                              side=side, with_optimum=L <= optimum_max_L))
            where.append((a, slice(first, stop)))
    results = run_sweep(_fig8_block, tasks, backend, n_jobs, scheduler, progress)
    out = {k: np.empty((len(L_values), trials)) for k in FIG8_KEYS}
    for (a, cols), r in zip(where, results):
        for k in FIG8_KEYS:
            out[k][a, cols] = r[k]
    out["L"] = np.array(L_values)
    return out


@dataclass(frozen=True)
class Problem3Audit:
    """Problem 3 (the relaxed matching) on Fig. 8's instances, against a 0-1 program and
    against Problem 1's optimum (:func:`problem3_audit`); arrays ``(len(L), trials)``."""

    L: np.ndarray  #: the numbers of targets (``N = 2L``)
    matching: np.ndarray  #: the maximum weight matching of pairs to targets
    milp: np.ndarray  #: Problem 3 solved as a 0-1 program
    optimum: np.ndarray  #: Problem 1's optimum on the same instances

    @property
    def largest_difference(self) -> float:
        """Largest ``|matching - milp|`` relative to the value (0 without instances)."""
        if not self.milp.size:
            return 0.0
        return float(np.max(np.abs(self.matching - self.milp) / np.maximum(self.milp, 1e-300)))

    @property
    def below_optimum(self) -> np.ndarray:
        """Instances where the relaxed value falls below Problem 1's optimum (beyond rounding)."""
        return self.matching < self.optimum * (1 - 1e-12)


def problem3_milp(W) -> float:
    r"""Problem 3 (Sec. V-C) solved as a 0-1 program, independently of the matching.

    Variables :math:`x_{pl} \in \{0, 1\}` for the unordered pairs :math:`p = (i, j)`,
    :math:`i < j`, and targets :math:`l`: every target takes exactly one pair, every pair serves
    at most one target (sensors may serve several), maximise :math:`\sum \omega_{pl} x_{pl}`
    (``scipy.optimize.milp``, HiGHS).

    Parameters
    ----------
    W : array_like, shape (N, N, L)
        Pair weights, finite and symmetric in ``i, j``, ``N (N - 1) / 2 >= L``.

    Examples
    --------
    Three sensors, two targets, the pair (0, 1) best for both; it can serve only one:

    >>> W = np.zeros((3, 3, 2)); W[0, 1] = W[1, 0] = 1.0; W[0, 2] = W[2, 0] = 0.25
    >>> problem3_milp(W)
    1.25
    """
    from scipy.optimize import Bounds, LinearConstraint, milp
    from scipy.sparse import coo_array

    arr = as_weights(W)
    n, _, n_targets = arr.shape
    ii, jj = np.triu_indices(n, 1)
    n_pairs = ii.size
    if n_pairs < n_targets:
        raise ValueError(f"{n_targets} targets need as many pairs, {n} sensors give {n_pairs}")
    c = -arr[ii, jj, :].reshape(-1)  # variable p * L + l
    var = np.arange(n_pairs * n_targets)
    per_target = coo_array((np.ones(var.size), (var % n_targets, var)),
                           shape=(n_targets, var.size))
    per_pair = coo_array((np.ones(var.size), (var // n_targets, var)), shape=(n_pairs, var.size))
    res = milp(c, integrality=np.ones(var.size), bounds=Bounds(0, 1),
               constraints=[LinearConstraint(per_target, 1, 1),
                            LinearConstraint(per_pair, 0, 1)],
               options={"mip_rel_gap": 0.0})
    if not res.success:
        raise RuntimeError(f"the 0-1 program of Problem 3 failed: {res.message}")
    x = np.round(res.x).astype(bool)
    return float(arr[ii, jj, :].reshape(-1)[x].sum())


def problem3_audit(L_max: int, trials: int, seed: int, u_max: float = 1.0, side: float = 100.0,
                   optimum_max_L: int = 0) -> Problem3Audit:
    """Problem 3 on the instances of the sweep :func:`fig8_sweep` ``(range(1, L_max + 1),
    trials, seed, u_max, side, optimum_max_L)`` where that sweep solves Problem 1 exactly
    (``L <= optimum_max_L``): the matching (:func:`obslib.relaxed_pair_assignment`, from the
    sweep) against the 0-1 program :func:`problem3_milp`, and against Problem 1's optimum.
    Cached on the arguments; the sweep is the chapter's, computed once.

    Examples
    --------
    >>> a = problem3_audit(4, trials=2, seed=0, optimum_max_L=3)
    >>> a.L.tolist(), a.largest_difference < 1e-12, bool(a.below_optimum.any())
    ([1, 2, 3], True, False)
    """
    return _problem3_audit(as_int(L_max, "L_max", 1), as_int(trials, "trials", 1),
                           as_int(seed, "seed", 0), float(as_nonnegative(u_max, "u_max")),
                           float(as_positive(side, "side")),
                           as_int(optimum_max_L, "optimum_max_L", 0))


@lru_cache(maxsize=4)
def _problem3_audit(L_max, trials, seed, u_max, side, optimum_max_L):
    sweep = fig8_sweep(range(1, L_max + 1), trials, seed, u_max, side, optimum_max_L)
    rows = np.flatnonzero(sweep["L"] <= optimum_max_L)
    Ls = sweep["L"][rows]
    milps = np.array([[problem3_milp(pair_bounds(*_draw(int(L), t, seed, side), u_max))
                       for t in range(trials)] for L in Ls]).reshape(len(Ls), trials)
    out = Problem3Audit(Ls, sweep["relaxed"][rows], milps, sweep["optimum"][rows])
    for arr in (out.L, out.matching, out.milp, out.optimum):
        arr.setflags(write=False)
    return out


@dataclass(frozen=True)
class Fig8Summary:
    """What Fig. 8 plots and the ledger judges, per number of targets ``L``."""

    L: np.ndarray  #: the numbers of targets
    mean: dict  #: key of :data:`FIG8_KEYS` -> mean over trials, shape ``(len(L),)``
    std: dict  #: key -> standard deviation over trials (``ddof = 0``)
    ratio: np.ndarray  #: mean greedy / mean relaxed


def fig8_summary(sweep: dict) -> Fig8Summary:
    """Means, spreads and the greedy / relaxed ratio of a :func:`fig8_sweep` result.

    Examples
    --------
    >>> s = fig8_summary(fig8_sweep([1, 2], trials=3, seed=0))
    >>> (s.L.tolist(), round(float(s.ratio[0]), 12),
    ...  bool((s.mean["greedy"] <= s.mean["relaxed"]).all()))
    ([1, 2], 1.0, True)
    """
    sweep = as_mapping(sweep, "sweep")
    missing = [k for k in (*FIG8_KEYS, "L") if k not in sweep]
    if missing:
        raise ValueError(f"sweep lacks {missing}: pass the result of fig8_sweep")
    mean = {k: np.asarray(sweep[k]).mean(axis=1) for k in FIG8_KEYS}
    std = {k: np.asarray(sweep[k]).std(axis=1) for k in FIG8_KEYS}
    return Fig8Summary(np.asarray(sweep["L"]), mean, std, mean["greedy"] / mean["relaxed"])

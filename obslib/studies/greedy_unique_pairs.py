"""Studies of Algorithm 1 against the exact optimum of Problem 1 (Section IV-A, Theorem 6; notebook
03, claims of :mod:`obslib.claims.greedy_unique_pairs`).

On batches of small instances, whose optimum :mod:`obslib.studies.batch_optimum` computes
exactly, this module holds the random greedy-versus-optimum study, a local search for instances
where the greedy does worst, the charging argument of Theorem 6's proof made explicit, Algorithm 1
on weights of both signs, and the classic weights on which the 1/3 of Theorem 6 is tight.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .._validate import (
    as_float_array,
    as_int,
    as_int_range,
    as_nonnegative,
    as_positive,
    as_triples,
    check_distinct,
    check_not_on_targets,
)
from ..assignment import greedy_pairs_batch
from .batch_optimum import (
    batch_pair_bounds,
    greedy_values,
    optimal_assignments,
    optimal_values,
    pair_assignments,
)

__all__ = [
    "NOTEBOOK",
    "GreedyStudy",
    "pair_instances",
    "greedy_vs_optimal",
    "worst_instance_search",
    "charging",
    "ChargingAudit",
    "charging_audit",
    "SignedStudy",
    "signed_weights_study",
    "tight_weights",
]

#: The chapter of these studies.
NOTEBOOK = "03_greedy_unique_pairs"


@dataclass(frozen=True)
class GreedyStudy:
    """Greedy, optimum and relaxed values over random instances (arrays, one entry per instance)."""

    n_sensors: np.ndarray
    n_targets: np.ndarray
    greedy: np.ndarray
    optimum: np.ndarray

    @property
    def ratio(self) -> np.ndarray:
        """``greedy / optimum`` (1 where the optimum is 0)."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(self.optimum > 0, self.greedy / self.optimum, 1.0)


def _random_geometry(rng, n, n_targets, side):
    while True:
        S = rng.uniform(0, side, size=(n, 2))
        T = rng.uniform(0, side, size=(n_targets, 2))
        try:  # what pair_bounds would reject
            check_distinct(S)
            check_not_on_targets(T[None, :, :] - S[:, None, :])
            return S, T
        except ValueError:  # a coincidence of zero probability; draw again
            continue


def _ratios(S, T, u_max) -> np.ndarray:
    """Greedy / optimum for a batch of geometries; ``inf`` where the geometry or optimum is
    degenerate."""
    W, valid = batch_pair_bounds(S, T, u_max)
    W[~valid] = 0.0
    opt = optimal_values(W)
    ok = valid & (opt > 0)
    out = np.full(opt.shape, np.inf)
    out[ok] = greedy_values(W[ok]) / opt[ok]
    return out


def _frozen(*arrays):
    """The arrays, made read-only: a cached result is shared by every caller."""
    for arr in arrays:
        arr.setflags(write=False)
    return arrays if len(arrays) > 1 else arrays[0]


def greedy_vs_optimal(n_instances: int, seed: int, targets=(2, 4), extra=(0, 2), u_max=1.0,
                      side=100.0) -> GreedyStudy:
    r"""Algorithm 1 against the exact optimum on random instances of the Fig. 8 kind.

    Each instance draws ``L`` uniformly from ``targets`` and :math:`N = 2L + e` with :math:`e` from
    ``extra`` (both inclusive), positions uniform in :math:`[0, \mathrm{side}]^2`, weights the pair
    bounds with ``u_max`` (Euclidean). Instances are drawn one after the other from one generator
    (:func:`pair_instances`), then solved in batches per ``(N, L)`` (:func:`greedy_values`,
    :func:`optimal_values`). The result is cached on the arguments (its arrays are read-only), so
    a chapter and the ledger that ask for the same study share one computation.

    Examples
    --------
    >>> study = greedy_vs_optimal(n_instances=20, seed=0)
    >>> study.ratio.shape, bool(study.ratio.min() >= 1 / 3)
    ((20,), True)
    """
    return _greedy_vs_optimal(*_instances_iv(n_instances, seed, targets, extra, side),
                              float(as_nonnegative(u_max, "u_max")))


def _instances_iv(n_instances, seed, targets, extra, side) -> tuple:
    """The validated, hashable arguments of :func:`pair_instances`."""
    return (as_int(n_instances, "n_instances", 1), as_int(seed, "seed", 0),
            as_int_range(targets, "targets", 1), as_int_range(extra, "extra", 0),
            float(as_positive(side, "side")))


def pair_instances(n_instances: int, seed: int, targets=(2, 4), extra=(0, 2),
                     side=100.0) -> list:
    """The random instances of :func:`greedy_vs_optimal`, grouped by size.

    Returns
    -------
    list of (int, int, ndarray, ndarray, ndarray)
        Per size ``(N, L)``, in increasing order: ``N``, ``L``, the indices of its instances in
        draw order, their sensors ``(K, N, 2)`` and their targets ``(K, L, 2)`` (read-only).

    Examples
    --------
    >>> groups = pair_instances(5, seed=0)
    >>> sum(len(idx) for _, _, idx, _, _ in groups)
    5
    """
    return _pair_instances(*_instances_iv(n_instances, seed, targets, extra, side))


@lru_cache(maxsize=8)
def _pair_instances(n_instances, seed, targets, extra, side):
    rng = np.random.default_rng(seed)
    sizes, geoms = [], []
    for _ in range(n_instances):
        L = int(rng.integers(targets[0], targets[1] + 1))
        n = 2 * L + int(rng.integers(extra[0], extra[1] + 1))
        sizes.append((n, L))
        geoms.append(_random_geometry(rng, n, L, side))
    sizes_arr = np.array(sizes).reshape(-1, 2)
    out = []
    for n, L in sorted(set(sizes)):
        idx = np.flatnonzero((sizes_arr[:, 0] == n) & (sizes_arr[:, 1] == L))
        S = np.stack([geoms[i][0] for i in idx])
        T = np.stack([geoms[i][1] for i in idx])
        out.append((n, L, *_frozen(idx, S, T)))
    return out


@lru_cache(maxsize=8)
def _solved(n_instances, seed, targets, extra, side, u_max):
    """Per size of :func:`pair_instances`: ``N``, ``L``, the indices, the weights ``W``, the
    greedy's picks and picked weights (:func:`obslib.assignment.greedy_pairs_batch`), and the
    optimum with one optimal assignment (:func:`optimal_assignments`); arrays read-only."""
    out = []
    for n, L, idx, S, T in _pair_instances(n_instances, seed, targets, extra, side):
        W, _ = batch_pair_bounds(S, T, u_max)
        ii, jj = np.triu_indices(n, 1)
        picks, weights = greedy_pairs_batch(W[:, ii, jj, :], n)
        values, triples = optimal_assignments(W)
        out.append((n, L, idx, *_frozen(W, picks, weights, values, triples)))
    return out


@lru_cache(maxsize=8)
def _greedy_vs_optimal(n_instances, seed, targets, extra, side, u_max):
    greedy, optimum = np.zeros(n_instances), np.zeros(n_instances)
    n_sensors = np.zeros(n_instances, dtype=np.int64)
    n_targets = np.zeros(n_instances, dtype=np.int64)
    for n, L, idx, _, _, weights, values, _ in _solved(n_instances, seed, targets, extra, side,
                                                       u_max):
        greedy[idx] = np.cumsum(weights, axis=1)[:, -1]  # summed in pick order, as greedy_values
        optimum[idx] = values
        n_sensors[idx], n_targets[idx] = n, L
    return GreedyStudy(*_frozen(n_sensors, n_targets, greedy, optimum))


def worst_instance_search(n_sensors: int, n_targets: int, seed: int, n_starts: int = 20,
                          n_steps: int = 300, u_max: float = 1.0, side: float = 100.0):
    """Local search for the geometry where the greedy's ratio to the optimum is smallest.

    From ``n_starts`` random instances, repeatedly moves one random point (sensor or target) by a
    Gaussian step (shrinking over time) and keeps the move when the ratio does not increase.
    Each start's draws (its instance, then per step the point and the step) come from one
    generator, start after start; the starts are then advanced together, as a batch. Cached on
    the arguments (the arrays returned are read-only).

    Returns
    -------
    (float, ndarray, ndarray)
        The smallest ratio found (the first start reaching it), and its sensors and targets.

    Examples
    --------
    >>> ratio, sensors, targets = worst_instance_search(4, 2, seed=0, n_starts=2,
    ...                                                 n_steps=10)
    >>> 1 / 3 <= ratio <= 1, sensors.shape, targets.shape
    (True, (4, 2), (2, 2))
    """
    n_sensors, n_targets = as_int(n_sensors, "n_sensors", 2), as_int(n_targets, "n_targets", 1)
    n_starts, n_steps = as_int(n_starts, "n_starts", 1), as_int(n_steps, "n_steps", 0)
    u_max, side = as_nonnegative(u_max, "u_max"), as_positive(side, "side")
    return _worst_instance_search(n_sensors, n_targets, as_int(seed, "seed", 0), n_starts,
                                  n_steps, float(u_max), float(side))


@lru_cache(maxsize=8)
def _worst_instance_search(n_sensors, n_targets, seed, n_starts, n_steps, u_max, side):
    rng = np.random.default_rng(seed)
    m = n_sensors + n_targets
    P = np.empty((n_starts, m, 2))  # sensors then targets, per start
    moved = np.empty((n_starts, n_steps), dtype=np.int64)
    delta = np.empty((n_starts, n_steps, 2))
    for c in range(n_starts):
        S, T = _random_geometry(rng, n_sensors, n_targets, side)
        P[c] = np.vstack([S, T])
        for step in range(n_steps):
            scale = side * 0.2 * (1 - step / n_steps) + 0.01
            moved[c, step] = int(rng.integers(m))
            delta[c, step] = rng.normal(0, scale, 2)
    rows = np.arange(n_starts)
    r = _ratios(P[:, :n_sensors], P[:, n_sensors:], u_max)
    for step in range(n_steps):
        P2 = P.copy()
        P2[rows, moved[:, step]] += delta[:, step]
        r2 = _ratios(P2[:, :n_sensors], P2[:, n_sensors:], u_max)
        keep = r2 <= r
        P[keep], r[keep] = P2[keep], r2[keep]
    c = int(np.argmin(r))
    return (float(r[c]), *_frozen(P[c, :n_sensors].copy(), P[c, n_sensors:].copy()))


def charging(W, greedy_triples, optimal_triples) -> list[dict]:
    """The charging argument of Theorem 6's proof, round by round.

    In round ``k`` the greedy's pick ``g = (i, j, l)`` is charged with every optimal triple not
    charged before that shares a sensor or the target with ``g`` (at most three: one through
    each of ``i``, ``j``, ``l``). Such a triple was still available in round ``k``, so its weight
    is at most ``w(g)``; hence ``OPT <= 3 GREEDY`` once every optimal triple is charged.

    Returns
    -------
    list of dict
        Per round: ``pick``, ``w`` (its weight), ``charged`` (the optimal triples) and their
        weights ``charged_w``.

    Examples
    --------
    On :func:`tight_weights` the greedy's first pick is charged with all three optimal triples:

    >>> import obslib as ob
    >>> W = tight_weights()
    >>> greedy = ob.greedy_pair_assignment(W).triples
    >>> optimal = ob.optimal_pair_assignment(W).triples
    >>> rounds = charging(W, greedy, optimal)
    >>> [(r["pick"], len(r["charged"])) for r in rounds]
    [((0, 1, 0), 3), ((2, 3, 1), 0), ((4, 5, 2), 0)]
    """
    W = as_float_array(W, "W")
    greedy_triples = as_triples(greedy_triples, W, "greedy_triples")
    left = as_triples(optimal_triples, W, "optimal_triples")
    rounds = []
    for i, j, l in greedy_triples:
        hit = [t for t in left if {t[0], t[1]} & {i, j} or t[2] == l]
        left = [t for t in left if t not in hit]
        rounds.append({
            "pick": (i, j, l),
            "w": float(W[i, j, l]),
            "charged": hit,
            "charged_w": [float(W[t]) for t in hit],
        })
    if left:
        raise ValueError(
            f"optimal triples never charged: {left} (greedy did not assign every target?)"
        )
    return rounds


@dataclass(frozen=True)
class ChargingAudit:
    """The charging argument of Theorem 6's proof checked on the instances of
    :func:`greedy_vs_optimal` (:func:`charging_audit`)."""

    n_instances: int
    n_picks: int
    #: how many picks are charged with 0, 1, 2, 3 and more than 3 optimal triples
    charges_per_pick: tuple
    n_not_once: int  #: instances where an optimal triple is charged other than exactly once
    n_heavier: int  #: charged optimal triples heavier than the pick they are charged to
    n_over_three: int  #: picks charged with more than three triples
    #: instances where OPT exceeds the sum over picks of (triples charged) x (pick's weight),
    #: or that sum exceeds three times the greedy's total
    n_chain_broken: int
    largest_slack: float  #: largest (charged triple's weight - its pick's weight), at most 0
    smallest_ratio: float  #: smallest greedy / optimum


def charging_audit(n_instances: int, seed: int, targets=(2, 4), extra=(0, 2), u_max=1.0,
                   side=100.0) -> ChargingAudit:
    r"""Theorem 6's charging argument, checked step by step on random instances.

    On each instance of :func:`greedy_vs_optimal` (the same draws and the same solutions), the
    greedy's picks are charged in order with the optimal triples not charged before that share a
    sensor or the target with them (:func:`charging`). The proof needs: every optimal triple
    charged exactly once, to a pick at least as heavy, at most three per pick; then
    :math:`\mathrm{OPT} \le \sum_k n_k w_k \le 3\,\omega(\mathrm{GREEDY})` for picks of
    weight :math:`w_k \ge 0` charged with :math:`n_k` triples. Each step is counted where it
    fails. Cached on the arguments.

    Examples
    --------
    >>> a = charging_audit(50, seed=0)
    >>> a.n_not_once, a.n_heavier, a.n_over_three, a.n_chain_broken
    (0, 0, 0, 0)
    """
    return _charging_audit(*_instances_iv(n_instances, seed, targets, extra, side),
                           float(as_nonnegative(u_max, "u_max")))


@lru_cache(maxsize=8)
def _charging_audit(n_instances, seed, targets, extra, side, u_max):
    per_pick = np.zeros(5, dtype=np.int64)
    not_once = heavier = over = broken = 0
    slack, ratio = -np.inf, np.inf
    for _, _, _, W, picks, weights, values, triples in _solved(n_instances, seed, targets, extra,
                                                               side, u_max):
        for k in range(W.shape[0]):
            opt = [tuple(t) for t in triples[k].tolist()]
            try:
                rounds = charging(W[k], [tuple(t) for t in picks[k].tolist()], opt)
            except ValueError:  # an optimal triple never charged
                not_once += 1
                continue
            charged = [t for r in rounds for t in r["charged"]]
            not_once += sorted(charged) != sorted(opt)
            total = 0.0
            for r in rounds:
                n_k = len(r["charged"])
                per_pick[min(n_k, 4)] += 1
                over += n_k > 3
                heavier += sum(w > r["w"] for w in r["charged_w"])
                slack = max([slack] + [w - r["w"] for w in r["charged_w"]])
                total += n_k * r["w"]
            greedy = float(sum(weights[k].tolist()))
            tol = 1e-12 * max(1.0, abs(values[k]))
            broken += values[k] > total + tol or total > 3 * greedy + tol
            if values[k] > 0:
                ratio = min(ratio, greedy / values[k])
    return ChargingAudit(n_instances, int(per_pick.sum()), tuple(int(c) for c in per_pick),
                         int(not_once), int(heavier), int(over), int(broken), float(slack),
                         float(ratio))


@dataclass(frozen=True)
class SignedStudy:
    """Algorithm 1 against the optimum on random weights of both signs, and on the same weights
    made non-negative (their absolute values): arrays, one entry per instance
    (:func:`signed_weights_study`)."""

    n_targets: np.ndarray
    greedy: np.ndarray
    optimum: np.ndarray
    greedy_abs: np.ndarray
    optimum_abs: np.ndarray
    #: the instance where the greedy falls furthest below a third of the optimum: its weights
    #: ``W`` (nested lists), the greedy's and an optimal assignment, their totals
    witness: dict

    @property
    def below_third(self) -> np.ndarray:
        """Instances where ``greedy < optimum / 3`` (beyond rounding)."""
        return self.greedy < self.optimum / 3 - 1e-12

    @property
    def below_third_abs(self) -> np.ndarray:
        """The same with the non-negative weights."""
        return self.greedy_abs < self.optimum_abs / 3 - 1e-12


def signed_weights_study(n_instances: int, seed: int, targets=(2, 4)) -> SignedStudy:
    """Theorem 6 "for any omega": Algorithm 1 on random weights of both signs.

    Each instance draws ``L`` uniformly from ``targets`` (inclusive), ``N = 2L`` sensors and
    weights ``omega(s_i, s_j, t_l)`` uniform in ``[-1, 1]`` (symmetric in ``i, j``). The
    optimum of Problem 1 (every target gets a pair, as Algorithm 1 gives one) is found by brute
    force over all assignments (:func:`pair_assignments`); the same is done with the absolute
    values of the weights. Cached on the arguments.

    Examples
    --------
    >>> st = signed_weights_study(200, seed=0)
    >>> bool(st.below_third.any()), bool(st.below_third_abs.any())
    (True, False)
    """
    return _signed_weights_study(as_int(n_instances, "n_instances", 1), as_int(seed, "seed", 0),
                                 as_int_range(targets, "targets", 1))


def _brute_force(W: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Problem 1 by enumeration on a batch ``W`` ``(K, N, N, L)``: values and the index of the
    first best assignment of :func:`pair_assignments`."""
    _, n, _, n_targets = W.shape
    P, Q = pair_assignments(n, n_targets)
    totals = np.zeros((W.shape[0], P.shape[0]))
    for l in range(n_targets):  # summed in target order
        totals += W[:, P[:, l], Q[:, l], l]
    best = totals.argmax(axis=1)
    return totals[np.arange(W.shape[0]), best], best


@lru_cache(maxsize=4)
def _signed_weights_study(n_instances, seed, targets):
    rng = np.random.default_rng(seed)
    Ls = rng.integers(targets[0], targets[1] + 1, size=n_instances)
    draws = []
    for L in Ls.tolist():
        n = 2 * L
        ii, jj = np.triu_indices(n, 1)
        w = np.zeros((n, n, L))
        w[ii, jj] = rng.uniform(-1.0, 1.0, size=(ii.size, L))
        draws.append(w + w.transpose(1, 0, 2))  # symmetric, 0 on the diagonal
    out = {k: np.zeros(n_instances) for k in ("greedy", "optimum", "greedy_abs", "optimum_abs")}
    worst, worst_gap = None, -np.inf
    for L in sorted(set(Ls.tolist())):
        idx = np.flatnonzero(Ls == L)
        W = np.stack([draws[i] for i in idx])
        for suffix, V in (("", W), ("_abs", np.abs(W))):
            out["greedy" + suffix][idx] = greedy_values(V)
            out["optimum" + suffix][idx], best = _brute_force(V)
            if not suffix:
                gap = out["optimum"][idx] / 3 - out["greedy"][idx]
                k = int(np.argmax(gap))
                if gap[k] > worst_gap:
                    worst_gap, worst = gap[k], (idx[k], W[k], best[k])
    i, W, best = worst
    n, L = W.shape[0], W.shape[2]
    P, Q = pair_assignments(n, L)
    ii, jj = np.triu_indices(n, 1)
    picks, _ = greedy_pairs_batch(W[None, ii, jj, :], n)
    witness = {"instance": int(i), "W": W.tolist(), "greedy": float(out["greedy"][i]),
               "optimum": float(out["optimum"][i]),
               "greedy_triples": [tuple(t) for t in picks[0].tolist()],
               "optimal_triples": [(int(P[best, l]), int(Q[best, l]), l) for l in range(L)]}
    return SignedStudy(*_frozen(Ls, out["greedy"], out["optimum"], out["greedy_abs"],
                                out["optimum_abs"]), witness)


def tight_weights(eps: float = 1e-3) -> np.ndarray:
    r"""Weights (not from geometry) on which Algorithm 1 gets :math:`(1 + \varepsilon) / 3` of the
    optimum.

    Six sensors and three targets: the triple ``(0, 1, t0)`` weighs :math:`1 + \varepsilon` and
    blocks the optimal ``(0, 2, t1)``, ``(1, 3, t2)``, ``(4, 5, t0)`` of weight 1 each; every other
    weight is 0. Theorem 6 holds for any :math:`\omega`, and this shows its 1/3 cannot be improved.

    Examples
    --------
    >>> W = tight_weights(eps=1e-3)
    >>> round(float(greedy_values(W[None])[0] / optimal_values(W[None])[0]), 6)
    0.333667
    """
    eps = as_nonnegative(eps, "eps")
    W = np.zeros((6, 6, 3))
    for (i, j, l), w in {
        (0, 1, 0): 1 + eps,
        (0, 2, 1): 1.0,
        (1, 3, 2): 1.0,
        (4, 5, 0): 1.0,
    }.items():
        W[i, j, l] = W[j, i, l] = w
    return W

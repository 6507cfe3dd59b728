"""Studies of Algorithm 1 against the exact optimum (Section IV-A, Theorem 6).

The paper could not compute the optimum of Problem 1; for small instances we can, by enumerating
every assignment of disjoint sensor pairs to targets once per ``(N, L)`` and evaluating all of
them for a whole batch of instances with NumPy. This module holds that batch optimum, the random
greedy-versus-optimum study, a local search for instances where the greedy does worst, the
charging argument of Theorem 6's proof made explicit, and the classic weights on which the 1/3
of Theorem 6 is tight.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from itertools import combinations

import numpy as np

from .assignment import greedy_pair_assignment
from .bounds import pair_bounds

__all__ = [
    "pair_assignments",
    "optimal_values",
    "GreedyStudy",
    "greedy_vs_optimal",
    "worst_instance_search",
    "charging",
    "tight_weights",
    "FIG8_KEYS",
    "fig8_trial",
    "fig8_sweep",
]

#: Largest number of assignments :func:`pair_assignments` enumerates.
MAX_ASSIGNMENTS = 200_000


@lru_cache(maxsize=32)
def pair_assignments(n: int, n_targets: int) -> tuple[np.ndarray, np.ndarray]:
    """All ways to give each of ``L`` targets its own pair out of ``N`` sensors, no sensor twice.

    Returns ``(P, Q)``, each of shape ``(A, L)``: assignment ``a`` gives target ``l`` the pair
    ``(P[a, l], Q[a, l])`` with ``P < Q``. With non-negative weights an optimum of Problem 1
    assigns every target (``N >= 2L``), so these are all the candidates.
    """
    if n < 2 * n_targets or n_targets < 1:
        raise ValueError(f"need L >= 1 and N >= 2L, got N = {n}, L = {n_targets}")
    out = []
    pairs = list(combinations(range(n), 2))

    def rec(l, used, chosen):
        if l == n_targets:
            out.append(tuple(chosen))
            if len(out) > MAX_ASSIGNMENTS:
                raise ValueError(f"more than {MAX_ASSIGNMENTS} assignments for N = {n}, L = {n_targets}")
            return
        for p in pairs:
            if p[0] not in used and p[1] not in used:
                rec(l + 1, used | set(p), chosen + [p])

    rec(0, frozenset(), [])
    arr = np.array(out, dtype=np.int64)  # (A, L, 2)
    return arr[:, :, 0], arr[:, :, 1]


def optimal_values(W: np.ndarray) -> np.ndarray:
    """Problem 1's optimum for a batch of weight arrays ``W`` of shape ``(K, N, N, L)``."""
    W = np.asarray(W, dtype=float)
    k, n, _, n_targets = W.shape
    P, Q = pair_assignments(n, n_targets)
    lidx = np.arange(n_targets)[None, :]
    return W[:, P, Q, lidx].sum(axis=2).max(axis=1)


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


def _random_weights(rng, n, n_targets, u_max, side):
    while True:
        S = rng.uniform(0, side, size=(n, 2))
        T = rng.uniform(0, side, size=(n_targets, 2))
        try:
            return S, T, pair_bounds(S, T, u_max)
        except ValueError:  # a coincidence of zero probability; draw again
            continue


def greedy_vs_optimal(n_instances: int, seed: int, targets=(2, 4), extra=(0, 2), u_max=1.0,
                      side=100.0) -> GreedyStudy:
    """Algorithm 1 against the exact optimum on random instances of the Fig. 8 kind.

    Each instance draws ``L`` uniformly from ``targets`` and ``N = 2L + e`` with ``e`` from
    ``extra`` (both inclusive), positions uniform in ``[0, side]^2``, weights the pair bounds
    with ``u_max`` (Euclidean). Optima are computed in batches per ``(N, L)``.
    """
    rng = np.random.default_rng(seed)
    sizes, Ws, greedy = [], [], []
    for _ in range(n_instances):
        L = int(rng.integers(targets[0], targets[1] + 1))
        n = 2 * L + int(rng.integers(extra[0], extra[1] + 1))
        _, _, W = _random_weights(rng, n, L, u_max, side)
        sizes.append((n, L))
        Ws.append(W)
        greedy.append(greedy_pair_assignment(W).value)
    sizes_arr = np.array(sizes)
    optimum = np.zeros(n_instances)
    for n, L in sorted(set(sizes)):
        idx = np.flatnonzero((sizes_arr[:, 0] == n) & (sizes_arr[:, 1] == L))
        optimum[idx] = optimal_values(np.stack([Ws[i] for i in idx]))
    return GreedyStudy(sizes_arr[:, 0], sizes_arr[:, 1], np.array(greedy), optimum)


def worst_instance_search(n_sensors: int, n_targets: int, seed: int, n_starts: int = 20,
                          n_steps: int = 300, u_max: float = 1.0, side: float = 100.0):
    """Local search for the geometry where the greedy's ratio to the optimum is smallest.

    From ``n_starts`` random instances, repeatedly moves one random point (sensor or target) by a
    Gaussian step (shrinking over time) and keeps the move when the ratio does not increase.

    Returns
    -------
    (float, ndarray, ndarray)
        The smallest ratio found, and its sensors and targets.
    """
    rng = np.random.default_rng(seed)
    best = (np.inf, None, None)

    def ratio(S, T):
        try:
            W = pair_bounds(S, T, u_max)
        except ValueError:
            return np.inf
        opt = optimal_values(W[None])[0]
        return greedy_pair_assignment(W).value / opt if opt > 0 else np.inf

    for _ in range(n_starts):
        S, T, _ = _random_weights(rng, n_sensors, n_targets, u_max, side)
        r = ratio(S, T)
        for step in range(n_steps):
            scale = side * 0.2 * (1 - step / n_steps) + 0.01
            S2, T2 = S.copy(), T.copy()
            k = int(rng.integers(n_sensors + n_targets))
            if k < n_sensors:
                S2[k] += rng.normal(0, scale, 2)
            else:
                T2[k - n_sensors] += rng.normal(0, scale, 2)
            r2 = ratio(S2, T2)
            if r2 <= r:
                S, T, r = S2, T2, r2
        if r < best[0]:
            best = (r, S, T)
    return best


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
    """
    W = np.asarray(W, dtype=float)
    left = list(optimal_triples)
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
        raise ValueError(f"optimal triples never charged: {left} (greedy did not assign every target?)")
    return rounds


def tight_weights(eps: float = 1e-3) -> np.ndarray:
    """Weights (not from geometry) on which Algorithm 1 gets ``(1 + eps) / 3`` of the optimum.

    Six sensors and three targets: the triple ``(0, 1, t0)`` weighs ``1 + eps`` and blocks the
    optimal ``(0, 2, t1)``, ``(1, 3, t2)``, ``(4, 5, t0)`` of weight 1 each; every other weight
    is 0. Theorem 6 holds for any ``omega``, and this shows its 1/3 cannot be improved.
    """
    W = np.zeros((6, 6, 3))
    for (i, j, l), w in {(0, 1, 0): 1 + eps, (0, 2, 1): 1.0, (1, 3, 2): 1.0, (4, 5, 0): 1.0}.items():
        W[i, j, l] = W[j, i, l] = w
    return W


FIG8_KEYS = ("greedy", "relaxed", "relaxed_ordered", "optimum")


def fig8_trial(n_targets: int, trial: int, seed: int, u_max: float = 1.0, side: float = 100.0,
               with_optimum: bool = False) -> dict:
    """One trial of Fig. 8: ``N = 2L`` sensors and ``L`` targets uniform in ``[0, side]^2``.

    The draw depends only on ``(seed, L, trial)`` (``numpy.random.default_rng([seed, L, trial])``),
    so a sweep gives the same numbers in any order, serially or in parallel. Returns the greedy,
    relaxed (Problem 3), ordered-pair relaxed (the original code's) values, and the exact optimum
    when ``with_optimum`` (NaN otherwise).
    """
    from .assignment import _relaxed_from_cost, optimal_pair_assignment, upper_pair_weights

    rng = np.random.default_rng([seed, n_targets, trial])
    S = rng.uniform(0, side, size=(2 * n_targets, 2))
    T = rng.uniform(0, side, size=(n_targets, 2))
    ii, jj, cost = upper_pair_weights(S, T, u_max)  # shared by both relaxations
    out = {
        "greedy": greedy_pair_assignment(sensors=S, targets=T, u_max=u_max).value,
        "relaxed": _relaxed_from_cost(2 * n_targets, ii, jj, cost, False, None).value,
        "relaxed_ordered": _relaxed_from_cost(2 * n_targets, ii, jj, cost, True, None).value,
        "optimum": np.nan,
    }
    if with_optimum:
        W = pair_bounds(S, T, u_max)
        out["optimum"] = float(optimal_values(W[None])[0]) if n_targets <= 4 else optimal_pair_assignment(W).value
    return out


def fig8_sweep(L_values, trials: int, seed: int, u_max: float = 1.0, side: float = 100.0,
               optimum_max_L: int = 0, backend: str = "serial", n_jobs=None, scheduler=None) -> dict:
    """Fig. 8's sweep: arrays of shape ``(len(L_values), trials)`` for each of :data:`FIG8_KEYS`.

    ``backend``, ``n_jobs`` and ``scheduler`` go to :func:`obslib.sweep.run_sweep`; the numbers do
    not depend on them.
    """
    from .sweep import run_sweep

    L_values = [int(L) for L in L_values]
    tasks = [
        dict(n_targets=L, trial=t, seed=seed, u_max=u_max, side=side, with_optimum=L <= optimum_max_L)
        for L in L_values for t in range(trials)
    ]
    results = run_sweep(fig8_trial, tasks, backend, n_jobs, scheduler)
    out = {k: np.array([r[k] for r in results]).reshape(len(L_values), trials) for k in FIG8_KEYS}
    out["L"] = np.array(L_values)
    return out

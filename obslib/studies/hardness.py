"""Is Unique Pair Assignment (Problem 1) NP-complete, and how far does the exact optimum get?

Sec. V-C states "The Unique Pair Assignment problem is NP-Complete" and Sec. I that "the optimal
solution cannot be computed", both without proof. For *arbitrary* weights the statement holds,
by a reduction from 3-dimensional matching (3DM, NP-complete; Karp 1972):

    A 3DM instance has disjoint sets ``X, Y, Z`` of ``q`` elements each and triples
    ``T`` subset of ``X x Y x Z``; it asks whether ``q`` pairwise disjoint triples of ``T``
    exist (a perfect matching). Build ``N = 2q`` sensors ``X u Y`` and ``L = q`` targets ``Z``
    with ``omega(x, y, z) = 1`` for ``(x, y, z)`` in ``T`` and 0 for every other triple
    (pairs inside ``X`` or inside ``Y`` included). An assignment reaches value ``q`` iff its
    ``q`` triples all weigh 1, i.e. lie in ``T``, use every target once and no sensor twice,
    i.e. form a perfect matching.

So deciding "is there an assignment of value ``>= K``" is NP-hard, and it is in NP (check a
given assignment), hence NP-complete. For the *geometric* weights of the paper (Theorem 4's
bound of points in the plane) this reduction does not apply: those weights are not free to take
the values 0 and 1 at will, and we know of no hardness proof for them (nor does the paper give
one). Either way NP-hardness is about the worst case as instances grow; it does not mean the
optimum "cannot be computed" at the sizes of the paper: :func:`exact_solver_reach` times the
exact 0-1 program (:func:`obslib.optimal_pair_assignment`) at growing sizes.
"""

from __future__ import annotations

import itertools
import time
from functools import lru_cache

import numpy as np

from .._validate import ArgumentTypeError, as_int, as_ints, as_nonnegative, as_positive
from ..assignment import greedy_pair_assignment, optimal_pair_assignment, relaxed_pair_assignment
from ..bounds import pair_bounds
from .greedy_vs_relaxed import fig8_instance

__all__ = [
    "three_dm_weights",
    "has_perfect_matching",
    "random_3dm",
    "reduction_check",
    "exact_solver_reach",
    "exact_ratio_spread",
    "exact_optimum_study",
]


def _three_dm_iv(q, triples) -> tuple[int, list]:
    q = as_int(q, "q", 1)
    out = []
    if isinstance(triples, (str, bytes)) or not isinstance(triples, (list, tuple)):
        raise ArgumentTypeError(f"triples must be a list of (x, y, z), got {triples!r}")
    for t in triples:
        if not isinstance(t, (tuple, list)) or len(t) != 3 or not all(
                isinstance(a, (int, np.integer)) and not isinstance(a, bool) and 0 <= a < q
                for a in t):
            raise ValueError(
                f"each triple must be (x, y, z) with elements in 0..{q - 1}, got {t!r}"
            )
        out.append(tuple(int(a) for a in t))
    return int(q), out


def three_dm_weights(q: int, triples) -> np.ndarray:
    """Problem 1 weights ``W`` of shape ``(2q, 2q, q)`` built from a 3DM instance.

    Sensors ``0..q-1`` are ``X``, sensors ``q..2q-1`` are ``Y``, targets are ``Z``;
    ``W[x, q + y, z] = W[q + y, x, z] = 1`` for each triple ``(x, y, z)``, 0 elsewhere.

    Examples
    --------
    >>> from obslib.studies.hardness import three_dm_weights
    >>> W = three_dm_weights(2, [(0, 1, 1)])
    >>> W.shape, float(W[0, 3, 1]), float(W[3, 0, 1]), float(W.sum())
    ((4, 4, 2), 1.0, 1.0, 2.0)
    """
    q, ts = _three_dm_iv(q, triples)
    W = np.zeros((2 * q, 2 * q, q))
    for x, y, z in ts:
        W[x, q + y, z] = W[q + y, x, z] = 1.0
    return W


def has_perfect_matching(q: int, triples) -> bool:
    """Whether ``q`` pairwise disjoint triples exist (brute force over ``q``-subsets).

    Examples
    --------
    >>> from obslib.studies.hardness import has_perfect_matching
    >>> has_perfect_matching(2, [(0, 0, 0), (1, 1, 1)])
    True
    >>> has_perfect_matching(2, [(0, 0, 0), (1, 1, 0)])  # both use z = 0
    False
    """
    q, ts = _three_dm_iv(q, triples)
    ts = sorted(set(ts))
    for combo in itertools.combinations(ts, q):
        if all(len({t[k] for t in combo}) == q for k in range(3)):
            return True
    return False


def random_3dm(q: int, n_triples: int, rng) -> list:
    """``n_triples`` distinct random triples over ``q``-element sets (a random 3DM instance).

    Examples
    --------
    >>> import numpy as np
    >>> from obslib.studies.hardness import random_3dm
    >>> t = random_3dm(2, 5, np.random.default_rng(0))
    >>> len(t), len(set(t)), all(0 <= v < 2 for triple in t for v in triple)
    (5, 5, True)
    """
    q, _ = _three_dm_iv(q, [])
    total = q**3
    if (isinstance(n_triples, bool) or not isinstance(n_triples, (int, np.integer))
            or not 0 <= n_triples <= total):
        raise ValueError(f"n_triples must be an integer in 0..{total}, got {n_triples!r}")
    idx = rng.choice(total, size=int(n_triples), replace=False)
    return [(int(i // (q * q)), int(i // q % q), int(i % q)) for i in idx]


def reduction_check(n_instances: int, seed: int = 0, q_values=(2, 3, 4)) -> dict:
    """The reduction on random 3DM instances: matching exists iff the optimum equals ``q``.

    Each instance draws ``q`` from ``q_values`` and between ``q`` and ``3 q`` triples (so both
    answers occur). The optimum is the exact 0-1 program of :func:`obslib.optimal_pair_assignment`.

    Returns
    -------
    dict
        ``n``, ``agree`` (instances where both sides agree), ``with_matching``. Computed once
        per arguments (cached).

    Examples
    --------
    >>> from obslib.studies.hardness import reduction_check
    >>> r = reduction_check(6, q_values=(2,))
    >>> r["n"], r["agree"]
    (6, 6)
    """
    if (isinstance(n_instances, bool) or not isinstance(n_instances, (int, np.integer))
            or n_instances < 1):
        raise ValueError(f"n_instances must be a positive integer, got {n_instances!r}")
    q_values = tuple(as_ints(q_values, "q_values", 1))
    return _reduction_check(int(n_instances), as_int(seed, "seed", 0), q_values)


@lru_cache(maxsize=4)
def _reduction_check(n_instances: int, seed: int, q_values: tuple) -> dict:
    rng = np.random.default_rng(seed)
    agree = with_m = 0
    for _ in range(int(n_instances)):
        q = int(rng.choice(list(q_values)))
        ts = random_3dm(q, int(rng.integers(q, 3 * q + 1)), rng)
        m = has_perfect_matching(q, ts)
        opt = optimal_pair_assignment(three_dm_weights(q, ts)).value
        agree += int(m == (opt >= q - 1e-9))
        with_m += int(m)
    return {"n": int(n_instances), "agree": agree, "with_matching": with_m}


def _budget(time_budget) -> float:
    """The solver's time limit in seconds, a positive number, or a ValueError naming it."""
    return as_positive(time_budget, "time_budget")


def exact_solver_reach(L_values, time_budget: float, seed: int = 0, u_max: float = 1.0,
                       side: float = 100.0) -> list[dict]:
    """Time the exact optimum of Problem 1 on random Fig. 8 instances (``N = 2L``).

    Sizes are tried in the given order until one does not finish within ``time_budget``
    seconds (the solver's ``time_limit``); that size is reported as not solved and larger ones
    skipped.

    Returns
    -------
    list of dict
        Per size tried: ``L``, ``N``, ``solved``, ``seconds``, and when solved ``optimum``,
        ``greedy`` and ``relaxed`` (Problem 3) values.

    Examples
    --------
    >>> from obslib.studies.hardness import exact_solver_reach
    >>> rows = exact_solver_reach([2, 3], time_budget=30.0)
    >>> [(r["L"], r["N"], r["solved"]) for r in rows]
    [(2, 4, True), (3, 6, True)]
    >>> all(r["greedy"] <= r["optimum"] + 1e-12 for r in rows)
    True
    """
    budget = _budget(time_budget)
    Ls = as_ints(L_values, "L_values", 1)
    seed = as_int(seed, "seed", 0)
    u_max, side = as_nonnegative(u_max, "u_max"), as_positive(side, "side")
    rows = []
    for L in Ls:
        rng = np.random.default_rng([seed, L])
        S, T = rng.uniform(0, side, (2 * L, 2)), rng.uniform(0, side, (L, 2))
        W = pair_bounds(S, T, u_max)
        t0 = time.perf_counter()
        try:
            opt = optimal_pair_assignment(W, time_limit=budget)
        except RuntimeError:
            rows.append({"L": L, "N": 2 * L, "solved": False, "seconds": time.perf_counter() - t0})
            break
        rows.append({
            "L": L, "N": 2 * L, "solved": True, "seconds": time.perf_counter() - t0,
            "optimum": opt.value,
            "greedy": greedy_pair_assignment(W).value,
            "relaxed": relaxed_pair_assignment(W).value,
        })
    return rows


def exact_optimum_study(L_values, n_spread: int, time_budget: float, seed: int = 0,
                        u_max: float = 1.0) -> dict:
    """How far the exact optimum of Problem 1 reaches (:func:`exact_solver_reach`), and greedy
    over optimum on ``n_spread`` instances of the largest size solved
    (:func:`exact_ratio_spread`).

    Returns
    -------
    dict
        ``reach`` (the rows of :func:`exact_solver_reach`), ``largest_solved`` (``L``, or
        ``None`` when no size was solved within ``time_budget``) and ``spread`` (the ratios,
        empty when no size was solved). Computed once per arguments (cached), so that the
        chapter and the ledger report the same solver run.

    Examples
    --------
    >>> from obslib.studies.hardness import exact_optimum_study
    >>> s = exact_optimum_study([2, 3], 2, time_budget=30.0)
    >>> s["largest_solved"], s["spread"].shape
    (3, (2,))
    """
    n_spread = as_int(n_spread, "n_spread", 1)
    L_values = tuple(as_ints(L_values, "L_values", 1))
    return _exact_optimum_study(L_values, n_spread, _budget(time_budget), as_int(seed, "seed", 0),
                                as_nonnegative(u_max, "u_max"))


@lru_cache(maxsize=4)
def _exact_optimum_study(L_values, n_spread, time_budget, seed, u_max) -> dict:
    reach = exact_solver_reach(list(L_values), time_budget, seed, u_max)
    top = max((r["L"] for r in reach if r["solved"]), default=None)
    spread = (exact_ratio_spread(top, n_spread, time_budget, seed, u_max) if top is not None
              else np.array([]))
    return {"reach": reach, "largest_solved": top, "spread": spread}


def exact_ratio_spread(L: int, n_instances: int, time_budget: float, seed: int = 0,
                       u_max: float = 1.0, side: float = 100.0) -> np.ndarray:
    """Greedy over the exact optimum of Problem 1 on ``n_instances`` random Fig. 8 instances of
    one size: instance ``k`` is trial ``k`` of Fig. 8
    (:func:`~obslib.studies.greedy_vs_relaxed.fig8_instance`).

    Returns
    -------
    ndarray, shape (n_instances,)
        The ratios; NaN where the exact solver did not finish within ``time_budget`` seconds.

    Examples
    --------
    >>> from obslib.studies.hardness import exact_ratio_spread
    >>> r = exact_ratio_spread(3, 4, time_budget=30.0)
    >>> r.shape, bool(((r >= 1 / 3) & (r <= 1 + 1e-12)).all())
    ((4,), True)
    """
    L, n_instances = as_int(L, "L", 1), as_int(n_instances, "n_instances", 1)
    budget = _budget(time_budget)
    seed = as_int(seed, "seed", 0)
    u_max, side = as_nonnegative(u_max, "u_max"), as_positive(side, "side")
    out = np.full(n_instances, np.nan)
    for k in range(n_instances):
        W = pair_bounds(*fig8_instance(L, k, seed, side), u_max)
        try:
            opt = optimal_pair_assignment(W, time_limit=budget)
        except RuntimeError:
            continue
        out[k] = greedy_pair_assignment(W).value / opt.value
    return out

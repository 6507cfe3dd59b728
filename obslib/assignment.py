"""Assigning unique pairs of sensors to targets (Section IV-A, Problems 1 and 3).

Weights are ``W[i, j, l]`` = the pair bound of sensors ``i, j`` for target ``l``
(:func:`obslib.pair_bounds`), symmetric in ``i, j`` and zero on the diagonal.

``greedy_pair_assignment``
    Algorithm 1: repeatedly take the heaviest triple whose sensors and target are all unused.
``greedy_pairs_batch``
    Algorithm 1 on many instances at once: the one kernel behind the greedy here and the
    studies' batched greedy.
``greedy_pair_assignment_literal``
    The same algorithm as printed, re-evaluating every remaining triple each round; kept for
    tests and benchmarks.
``relaxed_pair_assignment``
    Problem 3 (each unordered pair serves at most one target, sensors may be reused), solved
    exactly as a bipartite matching (:mod:`obslib._relaxed_pairs`); an upper bound on Problem 1.
``optimal_pair_assignment``
    Problem 1 solved exactly: branch and bound on its LP relaxation (HiGHS), within a time and
    a memory limit (:class:`OptimumNotProven`).

Ties
----
Among triples of equal weight every algorithm here takes the lexicographically smallest
``(i, j, l)`` with ``i < j`` (greedy); the matching and the exact solver return one optimum.
"""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass

import numpy as np

from . import _exact_pairs, _relaxed_pairs
from ._kernels import pair_kernel
from ._memory import check_geometry_memory, check_upper_weights_memory, check_weight_memory
from ._pair_search import GeometryHeads, PairSearch, WeightHeads, geometry_iv, rows_of
from ._validate import (
    ArgumentTypeError,
    as_bool,
    as_float_array,
    as_int,
    as_positive,
    as_triples,
    as_weights,
    check_pair_sizes,
)

__all__ = ["PairAssignment", "greedy_pair_assignment", "greedy_pair_assignment_literal",
           "greedy_pairs_batch", "relaxed_pair_assignment", "optimal_pair_assignment",
           "OptimumNotProven", "MAX_EXACT_BYTES", "assignment_value", "upper_pair_weights",
           "upper_pair_weight_blocks", "relaxed_from_geometry"]


@dataclass(frozen=True)
class PairAssignment:
    """Result of a pair assignment: ``triples`` ``(i, j, l)`` with ``i < j`` and their total
    ``value``.

    For the greedy algorithms the triples are in pick order; otherwise sorted by target.
    ``n_evaluations`` counts the pair weights the call computed from geometry (``None`` when it
    was given ``W``): a machine-independent measure of work.

    Examples
    --------
    >>> PairAssignment(triples=[(0, 1, 0)], value=0.5)
    PairAssignment(triples=[(0, 1, 0)], value=0.5, n_evaluations=None)
    """

    triples: list
    value: float
    n_evaluations: int | None = None


def assignment_value(W, triples) -> float:
    """Total weight ``sum W[i, j, l]`` of an assignment (no feasibility check).

    Examples
    --------
    >>> W = np.zeros((2, 2, 1)); W[0, 1, 0] = W[1, 0, 0] = 0.25
    >>> assignment_value(W, [(0, 1, 0)])
    0.25
    """
    W, triples = _assignment_value_iv(W, triples)
    return float(sum(W[i, j, l] for i, j, l in triples))


def _assignment_value_iv(W, triples) -> tuple:
    """Weights as a float array ``(N, N, L)`` and triples that index it."""
    W = as_float_array(W, "W")
    return W, as_triples(triples, W)


# --------------------------------------------------------------------------------------------
# Algorithm 1: one kernel for one instance or a batch, from weights or from geometry
# --------------------------------------------------------------------------------------------


def _rounds(source, free, n_targets: int, bar=None):
    """Algorithm 1 on ``B`` instances at once: their picks ``(B, L, 3)`` in pick order and the
    picked weights ``(B, L)``.

    ``free`` ``(B, N)`` marks each instance's free sensors (updated in place) and
    ``source.heads(b, l, free)`` gives the heaviest free pair ``(w, i, j)`` of targets ``l`` of
    instances ``b`` (ties: smallest ``(i, j)``; ``w = -inf`` when none). Each target's head is
    kept until a sensor of it is taken; a stale head keeps its old weight, an upper bound of its
    target's best, and is refreshed only when it reaches the top (weights never change and
    sensors only leave). Every round takes, in each instance, the heaviest head, ties to the
    smallest ``(i, j, l)``.
    """
    B, n = free.shape
    rows = np.arange(B)
    lidx = np.arange(n_targets)
    w, i, j = source.heads(np.repeat(rows, n_targets), np.tile(lidx, B), free)
    hw, hi, hj = w.reshape(B, n_targets), i.reshape(B, n_targets), j.reshape(B, n_targets)
    picks = np.empty((B, n_targets, 3), dtype=np.int64)
    weights = np.empty((B, n_targets))
    col = rows[:, None]
    for r in range(n_targets):
        while True:  # refresh the stale heads that could be the top (twice at most)
            valid = free[col, hi] & free[col, hj]
            top = np.where(valid, hw, -np.inf).max(axis=1)
            need = ~valid & (hw >= top[:, None]) & (hw > -np.inf)
            if not need.any():
                break
            b, l = np.nonzero(need)
            hw[b, l], hi[b, l], hj[b, l] = source.heads(b, l, free)
        if not (top > -np.inf).all():  # N >= 2L is checked at the boundary
            raise RuntimeError(f"no free pair left in round {r + 1}")
        key = np.where(hw == top[:, None], (hi * n + hj) * n_targets + lidx, np.iinfo(np.int64).max)
        l = key.argmin(axis=1)
        i, j = hi[rows, l], hj[rows, l]
        picks[:, r, 0], picks[:, r, 1], picks[:, r, 2] = i, j, l
        weights[:, r] = top
        free[rows, i] = free[rows, j] = False
        hw[rows, l] = -np.inf
        if bar is not None:
            bar.update()
    return picks, weights


def _progress(progress: bool, total, what):
    """A tqdm bar on stderr over ``total`` steps when ``progress`` (validated) is true, else
    None."""
    if not progress:
        return None
    from tqdm import tqdm

    return tqdm(total=total, desc=what, file=sys.stderr, leave=False, mininterval=0.5)


def greedy_pairs_batch(w, n_sensors: int, progress=False):
    """Algorithm 1 on a batch of instances given by the weights of their pairs ``i < j``.

    ``w[b, p, l]`` is the weight in instance ``b`` of pair ``p`` (``numpy.triu_indices(N, 1)``
    order) for target ``l``. Every round takes, in each instance at once, the heaviest triple
    ``(i, j, l)`` whose sensors and target are unused, ties to the smallest ``(i, j, l)``; it
    is the kernel of :func:`greedy_pair_assignment` and of the studies' batched greedy.

    Parameters
    ----------
    w : array_like, shape (B, N (N - 1) / 2, L)
        Finite weights (any sign).
    n_sensors : int
        ``N``, at least ``2 L``.
    progress : bool
        Show a progress bar (tqdm, on stderr) over the rounds.

    Returns
    -------
    picks : ndarray, shape (B, L, 3)
        ``(i, j, l)`` of each round, in pick order.
    weights : ndarray, shape (B, L)
        The picked weights, in pick order.

    Examples
    --------
    >>> W = np.zeros((4, 4, 2))
    >>> W[0, 1, 0] = W[1, 0, 0] = 2.0  # pair (0, 1) for target 0
    >>> W[2, 3, 1] = W[3, 2, 1] = 1.0  # pair (2, 3) for target 1
    >>> ii, jj = np.triu_indices(4, 1)
    >>> picks, weights = greedy_pairs_batch(W[ii, jj][None], 4)
    >>> picks[0].tolist(), weights[0].tolist()
    ([[0, 1, 0], [2, 3, 1]], [2.0, 1.0])
    """
    w, n, progress = _greedy_pairs_batch_iv(w, n_sensors, progress)
    ii, jj = np.triu_indices(n, 1)
    free = np.ones((w.shape[0], n), dtype=bool)
    bar = _progress(progress, w.shape[2], "Algorithm 1")
    try:
        return _rounds(WeightHeads(w, ii, jj), free, w.shape[2], bar)
    finally:
        if bar is not None:
            bar.close()


def _greedy_pairs_batch_iv(w, n_sensors, progress) -> tuple:
    """Finite weights ``(B, N (N - 1) / 2, L)`` with ``N >= 2L``, ``N``, the progress flag."""
    n = as_int(n_sensors, "n_sensors", 2)
    w = as_float_array(w, "w")
    pairs = n * (n - 1) // 2
    if w.ndim != 3 or w.shape[1] != pairs:
        raise ValueError(f"w must have shape (B, N (N - 1) / 2, L) = (B, {pairs}, L), "
                         f"got {w.shape}")
    check_pair_sizes(n, w.shape[2])
    if not np.isfinite(w).all():
        raise ValueError("w must be finite")
    return w, n, as_bool(progress, "progress")


def _assignment(picks, weights, n_evaluations=None) -> PairAssignment:
    """The :class:`PairAssignment` of one instance's picks; the value summed in pick order."""
    return PairAssignment(triples=[tuple(t) for t in picks.tolist()],
                          value=float(sum(weights.tolist())), n_evaluations=n_evaluations)


def _pairs_iv(W, sensors, targets, u_max, cov):
    """Validated weights ``W`` ``(N, N, L)`` or the validated geometry
    (:class:`obslib._pair_search.Geometry`), the other ``None``: never both, never part of the
    geometry."""
    geometry = (sensors, targets, u_max)
    if W is not None:
        if any(g is not None for g in (*geometry, cov)):
            raise ValueError("give either W or sensors/targets, not both")
        return as_weights(W), None
    if any(g is None for g in geometry):
        raise ValueError("give W, or sensors=, targets= and u_max=" +
                         (" (cov= goes with them)" if cov is not None else ""))
    return None, geometry_iv(sensors, targets, u_max, cov)


def _sizes(arr, geometry) -> tuple:
    """``(N, L)`` of validated weights or geometry."""
    return (arr.shape[0], arr.shape[2]) if arr is not None else geometry.sizes


def greedy_pair_assignment(W=None, *, sensors=None, targets=None, u_max=None, cov=None, k=None,
                           progress=False):
    """Algorithm 1 (greedy unique pair assignment), without re-evaluating triples.

    Each round takes the heaviest triple ``(i, j, l)`` whose sensors and target are unused
    (ties: smallest ``(i, j, l)``), then removes them. Because the weights do not change between
    rounds, each target keeps its best free pair (its *head*) until a sensor of it is taken, and
    a stale head is recomputed only when it could be the round's maximum (:func:`_rounds`, the
    kernel of :func:`greedy_pairs_batch`). From geometry, each target keeps a sorted list of its
    heaviest pairs, found without evaluating most pairs (:mod:`obslib._pair_search`: a pair
    heavier than ``tau`` has nearly orthogonal rows of nearly equal length, so an angular window
    around each row turned by 90 degrees holds its partners), and refilled with a lower
    threshold when every pair of it has lost a sensor. The picks equal those of
    :func:`greedy_pair_assignment_literal`.

    Parameters
    ----------
    W : array_like, shape (N, N, L), optional
        Pair weights: finite, non-negative, symmetric in ``i, j`` (the diagonal is ignored).
    sensors, targets, u_max, cov : optional
        Instead of ``W``: the geometry, weighted as :func:`obslib.pair_bounds` does (Theorem 4,
        Mahalanobis with ``cov``), computed on demand so the ``(N, N, L)`` array is never
        materialised. Memory: the normalised rows, 16 bytes per sensor and target (0.8 GB at
        ``N = 10,000``, ``L = 5,000``), one target's search and the candidate lists
        (:func:`obslib._memory.geometry_bytes`); it is estimated before anything of size
        ``N x L`` is allocated, and a scene over
        :data:`obslib._memory.MAX_GEOMETRY_BYTES` (4 GiB) is refused with the size and what
        fits.
    k : int, optional
        From geometry, the least number of pairs a target's list holds after a fill (default
        16); affects speed only.
    progress : bool
        Show a progress bar (tqdm, on stderr) over the rounds (from geometry, first over the
        targets' first searches).

    Returns
    -------
    PairAssignment
        ``triples`` in pick order, ``value`` their total (Algorithm 1's ``omega(GREEDY)``).
        The 1/3 guarantee is Theorem 6.

    Examples
    --------
    Two clusters of two sensors, one target above each:

    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> greedy_pair_assignment(sensors=S, targets=T, u_max=1.0).triples
    [(2, 3, 1), (0, 1, 0)]
    >>> from obslib.bounds import pair_bounds
    >>> greedy_pair_assignment(pair_bounds(S, T, 1.0)).triples  # from weights
    [(2, 3, 1), (0, 1, 0)]
    """
    arr, geometry, k, progress = _greedy_iv(W, sensors, targets, u_max, cov, k, progress)
    n, n_targets = _sizes(arr, geometry)
    # the bar ticks once per round, and from geometry first once per target's first search
    bar = _progress(progress, n_targets * (1 if arr is not None else 2), "greedy")
    try:
        if arr is not None:
            source = WeightHeads.of(arr)
        else:
            search = PairSearch(*rows_of(geometry))
            source = GeometryHeads(search, n_targets, k, bar)
        picks, weights = _rounds(source, np.ones((1, n), dtype=bool), n_targets, bar)
    finally:
        if bar is not None:
            bar.close()
    counted = None if arr is not None else search.n_evaluations
    return _assignment(picks[0], weights[0], counted)


def _greedy_iv(W, sensors, targets, u_max, cov, k, progress) -> tuple:
    """:func:`greedy_pair_assignment`'s arguments: weights or geometry (:func:`_pairs_iv`) with
    ``N >= 2L`` and, from geometry, within the memory limit; ``k`` (default 16); the flag."""
    k = 16 if k is None else as_int(k, "k", 1)
    progress = as_bool(progress, "progress")
    arr, geometry = _pairs_iv(W, sensors, targets, u_max, cov)
    n, n_targets = _sizes(arr, geometry)
    check_pair_sizes(n, n_targets)
    if geometry is not None:
        check_geometry_memory(n, n_targets, "greedy", "greedy_pair_assignment")
    return arr, geometry, k, progress


def greedy_pair_assignment_literal(W=None, *, sensors=None, targets=None, u_max=None, cov=None,
                                   progress=False) -> PairAssignment:
    """Algorithm 1 as printed: every round, evaluate all remaining triples and take the maximum.

    Vectorised per round (one ``argmax`` over the remaining ``(N', N', L')`` block); ties go to
    the smallest ``(i, j, l)`` with ``i < j``. From geometry it recomputes the weights of the
    remaining sensors and targets every round, as the algorithm's "compute all possible omega"
    says (with the kernel of :func:`obslib.pair_bounds`, so the weights are the same). Quadratic
    in the number of rounds; for tests and benchmarks. ``progress`` shows a tqdm bar over the
    rounds on stderr.

    Examples
    --------
    >>> from obslib.bounds import pair_bounds
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> greedy_pair_assignment_literal(pair_bounds(S, T, 1.0)).triples
    [(2, 3, 1), (0, 1, 0)]
    """
    arr, geometry, progress = _literal_iv(W, sensors, targets, u_max, cov, progress)
    n, n_targets = _sizes(arr, geometry)
    if arr is not None:
        def block(s_free, t_free):
            return arr[np.ix_(s_free, s_free, t_free)]
        counted = None
    else:
        X, Y, u2 = rows_of(geometry)

        def block(s_free, t_free):
            x, y = X[np.ix_(t_free, s_free)].T, Y[np.ix_(t_free, s_free)].T
            return pair_kernel(x[:, None, :], y[:, None, :], x[None, :, :], y[None, :, :],
                               u2[t_free])
        counted = 0
    s_free = np.arange(n)
    t_free = np.arange(n_targets)
    triples, value = [], 0.0
    bar = _progress(progress, n_targets, "literal Algorithm 1")
    while t_free.size and s_free.size >= 2:
        w = block(s_free, t_free)
        m = s_free.size
        if counted is not None:
            counted += m * (m - 1) // 2 * t_free.size  # distinct pairs; the block holds both orders
        upper = np.triu(np.ones((m, m), dtype=bool), 1)
        w = np.where(upper[:, :, None], w, -np.inf)
        a, b, c = np.unravel_index(int(np.argmax(w)), w.shape)  # C order = (i, j, l) order
        i, j, l = int(s_free[a]), int(s_free[b]), int(t_free[c])
        triples.append((i, j, l))
        value += float(w[a, b, c])
        s_free = s_free[(s_free != i) & (s_free != j)]
        t_free = t_free[t_free != l]
        if bar is not None:
            bar.update()
    if bar is not None:
        bar.close()
    return PairAssignment(triples=triples, value=float(value), n_evaluations=counted)


def _literal_iv(W, sensors, targets, u_max, cov, progress) -> tuple:
    """Weights or geometry (:func:`_pairs_iv`) with ``N >= 2L``, from geometry within the memory
    of the ``(N, N, L)`` block its first round evaluates; the progress flag."""
    progress = as_bool(progress, "progress")
    arr, geometry = _pairs_iv(W, sensors, targets, u_max, cov)
    n, n_targets = _sizes(arr, geometry)
    if geometry is not None:
        check_weight_memory(n, n_targets)
    check_pair_sizes(n, n_targets)
    return arr, geometry, progress


# --------------------------------------------------------------------------------------------
# Relaxed matching (Problem 3) and the exact optimum (Problem 1)
# --------------------------------------------------------------------------------------------


def upper_pair_weight_blocks(sensors, targets, u_max, cov=None, chunk: int = 1 << 20):
    """The weights of the pairs ``i < j`` (``numpy.triu_indices(N, 1)`` order), target block by
    block.

    Yields ``(l0, l1, block)`` with ``block[l - l0, p]`` the weight of pair ``p`` for target
    ``l``, ``l0 <= l < l1``; blocks hold about ``chunk`` weights (at least one target), so the
    whole ``(L, P)`` array never needs to exist. Same kernel as :func:`obslib.pair_bounds`. The
    arguments are checked when it is called, before the first block.

    Examples
    --------
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> blocks = upper_pair_weight_blocks(S, T, 1.0, chunk=6)
    >>> [(l0, l1, block.shape) for l0, l1, block in blocks]
    [(0, 1, (1, 6)), (1, 2, (1, 6))]
    """
    geometry, chunk = _blocks_iv(sensors, targets, u_max, cov, chunk)
    return _blocks(geometry, chunk)


def _blocks_iv(sensors, targets, u_max, cov, chunk) -> tuple:
    """The validated geometry, within the memory of its rows, and ``chunk`` (at least 1)."""
    chunk = as_int(chunk, "chunk", 1)
    geometry = geometry_iv(sensors, targets, u_max, cov)
    n, n_targets = geometry.sizes
    check_geometry_memory(n, n_targets, "greedy", "upper_pair_weight_blocks")
    return geometry, chunk


def _blocks(geometry, chunk: int):
    """The generator of :func:`upper_pair_weight_blocks`."""
    xt, yt, u2 = rows_of(geometry)  # (L, N)
    ii, jj = np.triu_indices(xt.shape[1], 1)
    step = max(1, chunk // max(ii.size, 1))
    for a in range(0, xt.shape[0], step):
        b = min(a + step, xt.shape[0])
        x, y = xt[a:b], yt[a:b]
        yield a, b, pair_kernel(x[:, ii], y[:, ii], x[:, jj], y[:, jj], u2[a:b, None])


def upper_pair_weights(sensors, targets, u_max, cov=None, chunk: int = 1 << 20):
    """Weights of the unordered pairs ``i < j`` for every target, as ``(ii, jj, C)``.

    ``C[l, p]`` is ``pair_bounds(...)[ii[p], jj[p], l]`` (one shared elementwise kernel on the same
    rows, so equal) with pairs in ``numpy.triu_indices(N, 1)`` order; shape ``(L, P)``, filled from
    :func:`upper_pair_weight_blocks`. An array ``C`` over
    :data:`obslib._memory.MAX_WEIGHT_BYTES` is refused before anything is allocated.

    Examples
    --------
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> ii, jj, C = upper_pair_weights(S, T, 1.0)
    >>> ii.tolist(), jj.tolist(), C.shape
    ([0, 0, 0, 1, 1, 2], [1, 2, 3, 2, 3, 3], (2, 6))
    """
    geometry, chunk = _upper_pair_weights_iv(sensors, targets, u_max, cov, chunk)
    n, n_targets = geometry.sizes
    ii, jj = np.triu_indices(n, 1)
    out = np.empty((n_targets, ii.size))
    for a, b, block in _blocks(geometry, chunk):
        out[a:b] = block
    return ii, jj, out


def _upper_pair_weights_iv(sensors, targets, u_max, cov, chunk) -> tuple:
    """:func:`_blocks_iv`, and the ``(L, P)`` array within
    :data:`obslib._memory.MAX_WEIGHT_BYTES`."""
    geometry, chunk = _blocks_iv(sensors, targets, u_max, cov, chunk)
    check_upper_weights_memory(*geometry.sizes)
    return geometry, chunk


def relaxed_pair_assignment(W=None, ordered: bool = False, *, sensors=None, targets=None,
                            u_max=None, cov=None, progress=False) -> PairAssignment:
    """Problem 3: maximum-weight matching of sensor pairs to targets.

    Each unordered pair serves at most one target and each target gets at most one pair, but a
    sensor may belong to several chosen pairs. Its value is an upper bound on Problem 1's
    optimum (Sec. V-C). Solved exactly as a sparse bipartite matching between targets and each
    target's ``L`` heaviest pairs (:mod:`obslib._relaxed_pairs`, the one solver of Problem 3).

    Parameters
    ----------
    W : array_like, shape (N, N, L), optional
    ordered : bool
        Match *ordered* pairs ``(i, j)``, ``i != j``, instead: the original code's relaxation, in
        which one unordered pair can serve two targets (as ``(i, j)`` and ``(j, i)``).
    sensors, targets, u_max, cov : optional
        Instead of ``W``: the geometry, most of whose weights are never computed. Memory is
        estimated first and a scene over :data:`obslib._memory.MAX_GEOMETRY_BYTES` refused,
        saying what fits.
    progress : bool
        Show a progress bar (tqdm, on stderr): from geometry over the targets' candidate
        searches, from ``W`` over the one matching.

    Examples
    --------
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> relaxed_pair_assignment(sensors=S, targets=T, u_max=1.0).triples
    [(0, 1, 0), (2, 3, 1)]
    >>> from obslib.bounds import pair_bounds
    >>> relaxed_pair_assignment(pair_bounds(S, T, 1.0)).triples  # from weights
    [(0, 1, 0), (2, 3, 1)]
    """
    arr, geometry, orders, progress = _relaxed_iv(W, sensors, targets, u_max, cov, [ordered],
                                                  progress, "ordered")
    return _relaxed(arr, geometry, orders, progress)[0]


def relaxed_from_geometry(sensors, targets, u_max, cov=None, orders=(False, True),
                          progress=False) -> list:
    """Problem 3 from geometry for each ``ordered`` flag of ``orders``, sharing one search of
    the candidate pairs: ``[relaxed_pair_assignment(ordered=o, sensors=..., ...) for o in
    orders]`` at the cost of one. ``n_evaluations`` counts the weights computed (once, for all
    of them).

    Examples
    --------
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> [r.triples for r in relaxed_from_geometry(S, T, 1.0)]  # unordered, ordered
    [[(0, 1, 0), (2, 3, 1)], [(0, 1, 0), (2, 3, 1)]]
    """
    arr, geometry, orders, progress = _relaxed_iv(None, sensors, targets, u_max, cov, orders,
                                                  progress)
    return _relaxed(arr, geometry, orders, progress)


def _relaxed_iv(W, sensors, targets, u_max, cov, orders, progress, name="orders") -> tuple:
    """Problem 3's arguments: weights or geometry (:func:`_pairs_iv`) with a target and two
    sensors, from geometry within the memory limit; the ``ordered`` flags ``orders`` (named
    ``name`` in errors); the progress flag."""
    if not (isinstance(orders, (tuple, list)) and orders):
        raise ArgumentTypeError(f"{name} must be a non-empty list of True/False, got {orders!r}")
    orders = tuple(as_bool(o, name) for o in orders)
    progress = as_bool(progress, "progress")
    arr, geometry = _pairs_iv(W, sensors, targets, u_max, cov)
    n, n_targets = _sizes(arr, geometry)
    if n_targets < 1:
        raise ValueError("there must be at least one target")
    if n < 2:
        raise ValueError(f"pairs need at least two sensors, got {n}")
    if geometry is not None:
        what = "relaxed" if len(orders) == 1 else "relaxed, both"
        check_geometry_memory(n, n_targets, what, "relaxed_pair_assignment")
    return arr, geometry, orders, progress


def _relaxed(arr, geometry, orders, progress) -> list:
    """Problem 3, the one solver (:mod:`obslib._relaxed_pairs`): each target's ``L`` heaviest
    pairs, from the weights ``arr`` or searched from the geometry, then a maximum-weight matching
    for each flag of ``orders``; one :class:`PairAssignment` per flag."""
    n, n_targets = _sizes(arr, geometry)
    if arr is not None:
        candidates = _relaxed_pairs.candidates_from_weights(arr)
        bar = _progress(progress, 1, "matching")
    else:
        bar = _progress(progress, n_targets, "candidate pairs")
        candidates = _relaxed_pairs.candidates_from_geometry(rows_of(geometry), bar)
    try:
        return [PairAssignment(*_relaxed_pairs.matching(*candidates[:3], n, n_targets, ordered),
                               n_evaluations=candidates[3]) for ordered in orders]
    finally:
        if bar is not None:
            if arr is not None:
                bar.update()
            bar.close()


class OptimumNotProven(RuntimeError):
    """:func:`optimal_pair_assignment` reached its ``time_limit`` before proving an optimum.

    ``best`` is the best assignment found by then (a :class:`PairAssignment`, one pair per
    target; at worst Algorithm 1's), ``bound`` an upper bound on the optimum (``None`` when the
    limit came before the linear relaxation gave one), so ``best.value / bound`` bounds how far
    from optimal ``best`` can be.
    """

    def __init__(self, message, best, bound):
        super().__init__(message)
        self.best, self.bound = best, bound


#: Largest memory :func:`optimal_pair_assignment` may use beyond ``W``: 2 GiB, at
#: :data:`obslib._exact_pairs.BYTES_PER_VARIABLE` bytes per pair-target variable.
MAX_EXACT_BYTES = _exact_pairs.MAX_BYTES


def optimal_pair_assignment(W, time_limit: float | None = None, progress=False) -> PairAssignment:
    """Problem 1 solved exactly: a 0-1 program over pair-target variables.

    Variables ``x[p, l]`` for unordered pairs ``p = (i, j)`` and targets ``l``; each target takes
    at most one pair and each sensor serves at most one target:

    .. math::

        \\max \\sum_{p, l} \\omega_{p l} x_{p l} \\quad\\text{s.t.}\\quad
        \\sum_p x_{p l} \\le 1,\\quad \\sum_{l} \\sum_{p \\ni i} x_{p l} \\le 1,\\quad
        x \\in \\{0, 1\\}.

    Solved by branch and bound with the bound of the linear relaxation (LP, HiGHS via
    ``scipy.optimize.linprog``): with its duals :math:`y \\ge 0`, every assignment :math:`x`
    satisfies :math:`\\omega^T x = \\mathbf{1}^T y - \\sum_{\\text{rows}} y_r s_r -
    \\sum_{v \\in x} \\ell_v`, with row slacks :math:`s_r \\in \\{0, 1\\}` and losses
    :math:`\\ell_v = a_v^T y - \\omega_v \\ge 0` (the negated reduced profits). The search starts
    from the better of Algorithm 1 and an LP-guided greedy, improved by re-pairing the sensors of
    two targets, drops every variable whose loss alone exceeds the gap to that incumbent
    (reduced-cost fixing), and explores the rest depth first, deciding at each node the open
    target or free sensor with the fewest options that fit, pruning with the smallest remaining
    loss per target and per sensor. It proves the optimum up to
    :math:`10^{-10}` of the bound (floating-point noise; HiGHS's default gap is :math:`10^{-4}`);
    if the search grows beyond a fixed node count it hands the reduced model to
    ``scipy.optimize.milp``. The LP is solved by column generation (each target's heaviest pairs
    first, then the pairs the duals price as profitable), so HiGHS never sees all
    ``N (N - 1) / 2 * L`` variables at once. Fig. 8's random instances at ``L = 20``, ``N = 2L``
    take 0.1 to 1 s (one HiGHS 0-1 program: about 4 s).

    Limits. Memory is estimated before any work, at
    :data:`obslib._exact_pairs.BYTES_PER_VARIABLE` bytes per pair-target variable beyond ``W``
    itself, and the branch and bound's lists at most
    :data:`obslib._exact_pairs.SEARCH_BYTES`; above :data:`MAX_EXACT_BYTES` (2 GiB: about 33
    million variables, ``N = 2L`` up to ``L = 254``) the call raises ``ValueError`` saying what
    fits. The HiGHS 0-1 program that takes over a search grown too large needs
    about :data:`obslib._exact_pairs.MILP_BYTES_PER_VARIABLE` bytes per variable left; it runs
    only when that fits the same limit, and otherwise the call raises :class:`OptimumNotProven`.
    ``time_limit`` bounds the whole call: every HiGHS call gets the time left, the local search
    and the branch and bound check the clock, and when it runs out the call raises
    :class:`OptimumNotProven` (a ``RuntimeError``) carrying the best assignment found and the LP
    bound, within a fraction of a second of the limit (0.2 s over at ``L = 100`` and
    ``L = 200``: one HiGHS call on a restricted LP, one sort, or a few search nodes). It stops
    earlier when the one step left, HiGHS's 0-1 program over the variables the bound could not
    fix (for more than :data:`obslib._exact_pairs.SEARCH_MAX_VARIABLES` of them, instead of the
    branch and bound), could not even read its model in the time left (about
    :data:`obslib._exact_pairs.HIGHS_SECONDS_PER_VARIABLE` seconds per variable).

    Parameters
    ----------
    W : array_like, shape (N, N, L)
        Pair weights: finite, non-negative, symmetric in ``i, j`` (the diagonal is ignored).
    time_limit : float, optional
        Seconds the call may take (from after the validation of ``W`` and the import of
        ``scipy.optimize``).
    progress : bool
        Show the phase (LP relaxation, incumbent, branch and bound) and the gap between the
        bound and the best assignment in a tqdm bar on stderr.

    Returns
    -------
    PairAssignment
        An optimal assignment, ``triples`` sorted by target; where several assignments are
        optimal (ties, zero weights), which one is returned is unspecified.

    Raises
    ------
    ValueError
        For bad ``W``, ``N < 2L``, or an instance over the memory limit.
    OptimumNotProven
        When ``time_limit`` passes before an optimum is proven.

    Examples
    --------
    >>> from obslib.bounds import pair_bounds
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> optimal_pair_assignment(pair_bounds(S, T, 1.0)).triples
    [(0, 1, 0), (2, 3, 1)]
    """
    arr, time_limit, progress = _optimal_iv(W, time_limit, progress)
    n, n_targets = arr.shape[0], arr.shape[2]
    import scipy.optimize  # noqa: F401  (1 s on a first call: imported before the clock starts)

    deadline = None if not time_limit else time.perf_counter() + float(time_limit)
    bar = _progress(progress, None, "exact optimum")
    try:
        # Algorithm 1 (one of the search's incumbents) on the weights validated above
        picks, _ = _rounds(WeightHeads.of(arr), np.ones((1, n), dtype=bool), n_targets)
        start = [tuple(t) for t in picks[0].tolist()]
        triples = _exact_pairs.solve(arr, deadline, start, bar)
    except _exact_pairs.Stopped as e:
        best = sorted(e.triples, key=lambda t: t[2])
        best = PairAssignment(triples=best, value=assignment_value(arr, best))
        gap = "" if e.bound is None else f", the bound {e.bound:.6g}"
        why = (f"within time_limit = {time_limit} s" if e.reason == "time" else
               f"within {MAX_EXACT_BYTES / 2**30:.0f} GiB: the search left more variables than "
               "the HiGHS 0-1 program it hands them to could hold")
        raise OptimumNotProven(
            f"no proven optimum {why}; the best assignment found is worth {best.value:.6g}{gap} "
            "(attributes best and bound)", best, e.bound) from None
    finally:
        if bar is not None:
            bar.close()
    triples = sorted(triples, key=lambda t: t[2])
    return PairAssignment(triples=triples, value=assignment_value(arr, triples))


def _optimal_iv(W, time_limit, progress) -> tuple:
    """Weights with ``N >= 2L`` within :data:`MAX_EXACT_BYTES`, a positive ``time_limit`` or
    ``None``, the progress flag."""
    arr = as_weights(W)
    n, n_targets = arr.shape[0], arr.shape[2]
    check_pair_sizes(n, n_targets)
    if time_limit is not None:
        time_limit = as_positive(time_limit, "time_limit")
    progress = as_bool(progress, "progress")
    _exact_pairs.check_memory(n, n_targets, MAX_EXACT_BYTES)
    return arr, time_limit, progress

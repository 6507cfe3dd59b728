"""Assigning unique pairs of sensors to targets (Section IV-A, Problems 1 and 3).

Weights are ``W[i, j, l]`` = the pair bound of sensors ``i, j`` for target ``l``
(:func:`obslib.pair_bounds`), symmetric in ``i, j`` and zero on the diagonal.

``greedy_pair_assignment``
    Algorithm 1: repeatedly take the heaviest triple whose sensors and target are all unused.
``greedy_pair_assignment_literal``
    The same algorithm as printed, re-evaluating every remaining triple each round; kept for
    tests and benchmarks.
``relaxed_pair_assignment``
    Problem 3 (each unordered pair serves at most one target, sensors may be reused), solved
    exactly as a bipartite matching between pairs and targets; an upper bound on Problem 1.
``optimal_pair_assignment``
    Problem 1 solved exactly as a 0-1 program (``scipy.optimize.milp``, HiGHS).

Ties
----
Among triples of equal weight every algorithm here takes the lexicographically smallest
``(i, j, l)`` with ``i < j`` (greedy); the matching and MILP solvers return one optimum.
"""

from __future__ import annotations

import heapq
import time
from dataclasses import dataclass

import numpy as np

from . import _exact_pairs as exact_pairs
from ._kernels import normalise, pair_kernel
from ._validate import ArgumentTypeError, as_bool, as_float_array, as_int, as_points, as_u_max, as_weights, check_pair_sizes, check_weight_memory, validated_vectors

__all__ = [
    "PairAssignment",
    "greedy_pair_assignment",
    "greedy_pair_assignment_literal",
    "relaxed_pair_assignment",
    "optimal_pair_assignment",
    "assignment_value",
    "upper_pair_weights",
    "upper_pair_weight_blocks",
    "relaxed_from_geometry",
]


@dataclass(frozen=True)
class PairAssignment:
    """Result of a pair assignment: ``triples`` ``(i, j, l)`` with ``i < j`` and their total ``value``.

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
    W = as_float_array(W, "W")
    return float(sum(W[i, j, l] for i, j, l in triples))


def _geometry(sensors, targets, u_max, cov):
    """Validated rows ``o_l - p_i`` ``(N, L, 2)`` normalised per target, and ``u_max^2`` ``(L,)``
    in the same unit: the input of :func:`obslib._kernels.pair_kernel` (as in ``pair_bounds``)."""
    v, unit = validated_vectors(sensors, targets, cov)
    with np.errstate(over="ignore"):
        u = as_u_max(u_max, v.shape[1]) / unit
    return normalise(v, u)


# --------------------------------------------------------------------------------------------
# Greedy (Algorithm 1) without re-evaluation
# --------------------------------------------------------------------------------------------


class _TargetQueue:
    """Candidate pairs of one target in greedy order ``(-w, i, j)``, refilled on demand.

    Holds at least the ``k`` best pairs over the sensors that were free when it was (re)filled,
    and every pair tied with the last of them. Since weights never change and sensors only
    leave, the first candidate whose sensors are both free is the target's best free pair as long
    as the list is not exhausted; when it is, the list is refilled over the free sensors.
    """

    def __init__(self, source, l: int, k: int):
        self.source, self.l, self.k = source, l, k
        self.cand: list = []
        self.pos = 0
        self.complete = False  # the list holds every pair over the sensors free at fill time

    def fill(self, free: np.ndarray) -> None:
        a, b, w, self.complete = self.source.top_pairs(self.l, np.flatnonzero(free), self.k)
        i, j = np.minimum(a, b), np.maximum(a, b)
        order = np.lexsort((j, i, -w))
        self.cand = list(zip(w[order].tolist(), i[order].tolist(), j[order].tolist()))
        self.pos = 0

    def head(self, free: np.ndarray):
        """The best candidate with both sensors free, or None if the target has no free pair.

        Terminates: a refill lists only pairs of free sensors, so after one refill the next
        candidate is free or the list is complete (weights are finite, checked at the boundary).
        """
        refilled = False
        while True:
            while self.pos < len(self.cand):
                w, i, j = self.cand[self.pos]
                if free[i] and free[j]:
                    return w, i, j
                self.pos += 1
            if self.complete:
                return None
            if refilled:  # cannot happen with finite weights; never spin
                raise RuntimeError(f"refilling the candidates of target {self.l} made no progress")
            self.fill(free)
            refilled = True


def _keep_top(a, b, w, k):
    """The pairs among ``(a, b, w)`` whose weight is at least the ``k``-th largest."""
    if w.size <= k:
        return a, b, w
    kth = np.partition(w, w.size - k)[w.size - k]
    keep = w >= kth
    return a[keep], b[keep], w[keep]


class _WeightSource:
    """Pair weights read from a materialised ``W``."""

    def __init__(self, W):
        self.W = W

    def top_pairs(self, l, idx, k):
        iu, ju = np.triu_indices(idx.size, 1)
        a, b = idx[iu], idx[ju]
        w = self.W[a, b, l]
        complete = w.size <= k
        return (*_keep_top(a, b, w, k), complete)


class _GeometrySource:
    """Pair weights computed on demand from geometry, pruned by a distance-only upper bound.

    For rows with squared lengths ``r_i <= r_j``, ``lambda_min <= r_i`` and ``lambda_max >= r_j``
    (the diagonal of the Gram matrix lies between its eigenvalues), so
    ``bound^2 <= r_i / (r_j + u^2)``. Given ``tau``, the ``k``-th largest weight of a sample of
    pairs (a lower bound on the ``k``-th largest weight overall), only pairs with
    ``r_j <= r_i / tau^2 - u^2`` can reach the top ``k``; with the sensors sorted by distance
    they form a band, found with ``searchsorted``. The pruning is exact: every pair of weight
    ``>= tau`` is evaluated.
    """

    def __init__(self, v, u2):
        # normalised rows as contiguous (L, N) coordinate arrays, and u_max^2 per target (L,)
        self.x = np.ascontiguousarray(v[..., 0].T)
        self.y = np.ascontiguousarray(v[..., 1].T)
        self.r = self.x * self.x + self.y * self.y
        self.u2 = u2
        self.n_evaluations = 0

    def _weights(self, l, a, b):
        x, y = self.x[l], self.y[l]
        self.n_evaluations += a.size
        w = pair_kernel(x[a], y[a], x[b], y[b], self.u2[l])
        if not np.isfinite(w).all():  # validation and normalisation exclude it; never feed a NaN on
            raise RuntimeError(f"a pair weight of target {l} is not finite")
        return w

    def top_pairs(self, l, idx, k):
        m = idx.size
        if m < 2:
            e = np.zeros(0, dtype=int)
            return e, e, np.zeros(0), True
        order = idx[np.argsort(self.r[l, idx], kind="stable")]
        rs = self.r[l, order]
        n_pairs = m * (m - 1) // 2
        if n_pairs <= 4 * k:
            hi = np.full(m, m)
        else:
            # sample: each sensor with its next few neighbours in distance order
            width = min(m - 1, -(-_SAMPLE * k // m) + 1)
            pa, pb = _band(np.minimum(np.arange(m) + width + 1, m))
            tau = np.partition(self._weights(l, order[pa], order[pb]), pa.size - k)[pa.size - k]
            if tau <= 0:
                hi = np.full(m, m)
            else:
                limit = rs / (tau * tau * (1 - 1e-9)) - self.u2[l]
                hi = np.searchsorted(rs, limit, side="right")
        pa, pb = _band(hi)
        a, b = order[pa], order[pb]
        w = self._weights(l, a, b)
        complete = pa.size == n_pairs and w.size <= k
        return (*_keep_top(a, b, w, k), complete)


#: Size of the sample that sets the pruning threshold, in multiples of ``k`` (speed only).
_SAMPLE = 16


def _band(hi):
    """Positions ``(p, q)``, ``p < q < hi[p]``, of the pairs in a band over a sorted order."""
    m = hi.size
    counts = np.maximum(hi - np.arange(m) - 1, 0)
    p = np.repeat(np.arange(m), counts)
    starts = np.cumsum(counts) - counts
    q = p + 1 + (np.arange(p.size) - np.repeat(starts, counts))
    return p, q


def _greedy(source, n: int, n_targets: int, k: int | None = None) -> PairAssignment:
    """Algorithm 1 with a lazily refilled candidate list per target and a global heap."""
    if k is None:
        k = 8
    free = np.ones(n, dtype=bool)
    queues = [_TargetQueue(source, l, k) for l in range(n_targets)]
    heap = []
    for q in queues:
        q.fill(free)
        h = q.head(free)
        if h is not None:
            heap.append((-h[0], h[1], h[2], q.l))
    heapq.heapify(heap)
    triples, value = [], 0.0
    while heap:
        negw, i, j, l = heapq.heappop(heap)
        if free[i] and free[j]:
            triples.append((i, j, l))
            value += -negw
            free[i] = free[j] = False
            continue
        h = queues[l].head(free)  # stale: this target's head lost a sensor; re-queue its next
        if h is not None:
            heapq.heappush(heap, (-h[0], h[1], h[2], l))
    return PairAssignment(triples=triples, value=float(value))


def greedy_pair_assignment(W=None, *, sensors=None, targets=None, u_max=None, cov=None, k=None):
    """Algorithm 1 (greedy unique pair assignment), without re-evaluating triples.

    Each round takes the heaviest triple ``(i, j, l)`` whose sensors and target are unused
    (ties: smallest ``(i, j, l)``), then removes them. Because the weights do not change between
    rounds, each target keeps a sorted list of its best pairs, computed once and refilled only
    when all of them have lost a sensor; a heap of the targets' current heads gives each round's
    maximum. From geometry, a target's list is found without evaluating most pairs (see
    ``_GeometrySource``). The picks equal those of :func:`greedy_pair_assignment_literal`.

    Parameters
    ----------
    W : array_like, shape (N, N, L), optional
        Pair weights: finite, non-negative, symmetric in ``i, j`` (the diagonal is ignored).
    sensors, targets, u_max, cov : optional
        Instead of ``W``: the geometry, weighted as :func:`obslib.pair_bounds` does (Theorem 4,
        Mahalanobis with ``cov``), computed on demand so the ``(N, N, L)`` array is never
        materialised.
    k : int, optional
        Candidates kept per target between refills (default 8); affects speed only.

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
    if k is not None:
        k = as_int(k, "k", 1)
    if W is not None:
        if sensors is not None or targets is not None:
            raise ValueError("give either W or sensors/targets, not both")
        arr = as_weights(W)
        n, n_targets = arr.shape[0], arr.shape[2]
        check_pair_sizes(n, n_targets)
        return _greedy(_WeightSource(arr), n, n_targets, k)
    if sensors is None or targets is None or u_max is None:
        raise ValueError("give W, or sensors=, targets= and u_max=")
    v, u2 = _geometry(sensors, targets, u_max, cov)  # (N, L, 2) validated and normalised
    n, n_targets = v.shape[0], v.shape[1]
    check_pair_sizes(n, n_targets)
    source = _GeometrySource(v, u2)
    result = _greedy(source, n, n_targets, k)
    return PairAssignment(result.triples, result.value, source.n_evaluations)


def greedy_pair_assignment_literal(W=None, *, sensors=None, targets=None, u_max=None, cov=None) -> PairAssignment:
    """Algorithm 1 as printed: every round, evaluate all remaining triples and take the maximum.

    Vectorised per round (one ``argmax`` over the remaining ``(N', N', L')`` block); ties go to
    the smallest ``(i, j, l)`` with ``i < j``. From geometry it recomputes the weights of the
    remaining sensors and targets every round, as the algorithm's "compute all possible omega"
    says (with the kernel of :func:`obslib.pair_bounds`, so the weights are the same). Quadratic
    in the number of rounds; for tests and benchmarks.

    Examples
    --------
    >>> from obslib.bounds import pair_bounds
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> greedy_pair_assignment_literal(pair_bounds(S, T, 1.0)).triples
    [(2, 3, 1), (0, 1, 0)]
    """
    if W is not None:
        arr = as_weights(W)
        n, n_targets = arr.shape[0], arr.shape[2]

        def block(s_free, t_free):
            return arr[np.ix_(s_free, s_free, t_free)]
        counted = None
    elif sensors is not None and targets is not None and u_max is not None:
        v, u2 = _geometry(sensors, targets, u_max, cov)
        n, n_targets = v.shape[0], v.shape[1]
        check_weight_memory(n, n_targets)  # the first round evaluates the whole (N, N, L) block

        def block(s_free, t_free):
            x, y = v[np.ix_(s_free, t_free, [0])][..., 0], v[np.ix_(s_free, t_free, [1])][..., 0]
            return pair_kernel(x[:, None, :], y[:, None, :], x[None, :, :], y[None, :, :], u2[t_free])
        counted = 0
    else:
        raise ValueError("give W, or sensors=, targets= and u_max=")
    check_pair_sizes(n, n_targets)
    s_free = np.arange(n)
    t_free = np.arange(n_targets)
    triples, value = [], 0.0
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
    return PairAssignment(triples=triples, value=float(value), n_evaluations=counted)


# --------------------------------------------------------------------------------------------
# Relaxed matching (Problem 3) and the exact optimum (Problem 1)
# --------------------------------------------------------------------------------------------


def upper_pair_weight_blocks(sensors, targets, u_max, cov=None, chunk: int = 1 << 20):
    """The weights of the pairs ``i < j`` (``numpy.triu_indices(N, 1)`` order), target block by block.

    Yields ``(l0, l1, block)`` with ``block[l - l0, p]`` the weight of pair ``p`` for target
    ``l``, ``l0 <= l < l1``; blocks hold about ``chunk`` weights (at least one target), so the
    whole ``(L, P)`` array never needs to exist. Same kernel as :func:`obslib.pair_bounds`.

    Examples
    --------
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> blocks = upper_pair_weight_blocks(S, T, 1.0, chunk=6)
    >>> [(l0, l1, block.shape) for l0, l1, block in blocks]
    [(0, 1, (1, 6)), (1, 2, (1, 6))]
    """
    v, u2 = _geometry(sensors, targets, u_max, cov)
    ii, jj = np.triu_indices(v.shape[0], 1)
    xt, yt = np.ascontiguousarray(v[..., 0].T), np.ascontiguousarray(v[..., 1].T)  # (L, N)
    step = max(1, chunk // max(ii.size, 1))
    for a in range(0, xt.shape[0], step):
        b = min(a + step, xt.shape[0])
        x, y = xt[a:b], yt[a:b]
        yield a, b, pair_kernel(x[:, ii], y[:, ii], x[:, jj], y[:, jj], u2[a:b, None])


def upper_pair_weights(sensors, targets, u_max, cov=None, chunk: int = 1 << 20):
    """Weights of the unordered pairs ``i < j`` for every target, as ``(ii, jj, C)``.

    ``C[l, p]`` is ``pair_bounds(...)[ii[p], jj[p], l]`` (one shared elementwise kernel on the same rows, so equal)
    with pairs in ``numpy.triu_indices(N, 1)`` order; shape ``(L, P)``, filled from
    :func:`upper_pair_weight_blocks`.

    Examples
    --------
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> ii, jj, C = upper_pair_weights(S, T, 1.0)
    >>> ii.tolist(), jj.tolist(), C.shape
    ([0, 0, 0, 1, 1, 2], [1, 2, 3, 2, 3, 3], (2, 6))
    """
    n, n_targets = as_points(sensors, "sensors").shape[0], as_points(targets, "targets").shape[0]
    ii, jj = np.triu_indices(n, 1)
    out = np.empty((n_targets, ii.size))
    for a, b, block in upper_pair_weight_blocks(sensors, targets, u_max, cov, chunk):
        out[a:b] = block
    return ii, jj, out


def relaxed_pair_assignment(W=None, ordered: bool = False, *, sensors=None, targets=None, u_max=None,
                            cov=None) -> PairAssignment:
    """Problem 3: maximum-weight matching of sensor pairs to targets.

    Each unordered pair serves at most one target and each target gets at most one pair, but a
    sensor may belong to several chosen pairs. Solved exactly with
    ``scipy.optimize.linear_sum_assignment`` on the ``(L, P)`` matrix of pair weights. Its value
    is an upper bound on Problem 1's optimum (Sec. V-C).

    Parameters
    ----------
    W : array_like, shape (N, N, L), optional
    ordered : bool
        Match *ordered* pairs ``(i, j)``, ``i != j``, instead: the original code's relaxation, in
        which one unordered pair can serve two targets (as ``(i, j)`` and ``(j, i)``).
    sensors, targets, u_max, cov : optional
        Instead of ``W``: the geometry (only the ``i < j`` weights are computed).

    Examples
    --------
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> relaxed_pair_assignment(sensors=S, targets=T, u_max=1.0).triples
    [(0, 1, 0), (2, 3, 1)]
    """
    ordered = as_bool(ordered, "ordered")
    if W is not None:
        arr = as_weights(W)
        n = arr.shape[0]
        ii, jj = np.triu_indices(n, 1)
        return _relaxed_from_cost(n, ii, jj, arr[ii, jj, :].T, ordered, counted=None)
    if sensors is not None and targets is not None and u_max is not None:
        return relaxed_from_geometry(sensors, targets, u_max, cov, orders=(ordered,))[0]
    raise ValueError("give W, or sensors=, targets= and u_max=")


def relaxed_from_geometry(sensors, targets, u_max, cov=None, orders=(False, True)) -> list:
    """Problem 3 from geometry, evaluating only each target's ``L`` best pairs.

    A target matched to a pair outside its ``L`` heaviest could move to one of them, since the
    other ``L - 1`` targets hold at most ``L - 1`` pairs; it would gain weight, so every optimum
    uses only those candidates (with ``(i, j)`` and ``(j, i)`` for the ordered variant, whose
    ``L``-th best ordered weight is at least the ``L``-th best unordered one). The candidates are
    found with the greedy's exact distance pruning (``_GeometrySource``), without computing most
    weights, and the sparse matching is solved with
    ``scipy.sparse.csgraph.min_weight_full_bipartite_matching``. Returns one
    :class:`PairAssignment` per entry of ``orders`` (``ordered`` flags), sharing the candidates;
    ``n_evaluations`` counts the weights computed (once, for all of them).

    Examples
    --------
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> [r.triples for r in relaxed_from_geometry(S, T, 1.0)]  # unordered, ordered
    [[(0, 1, 0), (2, 3, 1)], [(0, 1, 0), (2, 3, 1)]]
    """
    from scipy.sparse import csr_array
    from scipy.sparse.csgraph import min_weight_full_bipartite_matching

    v, u2 = _geometry(sensors, targets, u_max, cov)
    n, n_targets = v.shape[0], v.shape[1]
    if n_targets < 1:
        raise ValueError("there must be at least one target")
    if n < 2:
        raise ValueError(f"pairs need at least two sensors, got {n}")
    source = _GeometrySource(v, u2)
    every = np.arange(n)
    rows, ids, ws = [], [], []
    for l in range(n_targets):
        a, b, w, _ = source.top_pairs(l, every, n_targets)
        rows.append(np.full(w.size, l))
        ids.append(np.minimum(a, b) * n + np.maximum(a, b))
        ws.append(w)
    rows, ids, ws = np.concatenate(rows), np.concatenate(ids), np.concatenate(ws)
    pairs, col = np.unique(ids, return_inverse=True)
    ii, jj = pairs // n, pairs % n
    out = []
    for ordered in orders:
        r, c, w, m = rows, col, ws, pairs.size
        if ordered:  # the second copy of pair p is column m + p
            r, c, w, m = np.r_[rows, rows], np.r_[col, col + pairs.size], np.r_[ws, ws], 2 * pairs.size
        # every full matching has L edges, so the offset (edges must be nonzero) changes no choice
        graph = csr_array((w + 1.0, (r, c)), shape=(n_targets, m))
        mr, mc = min_weight_full_bipartite_matching(graph, maximize=True)
        key = r.astype(np.int64) * m + c  # each (target, column) edge once
        order = np.argsort(key)
        mr, mc = np.asarray(mr), np.asarray(mc)
        value = w[order[np.searchsorted(key[order], mr.astype(np.int64) * m + mc)]]
        p = mc % pairs.size
        triples = sorted(zip(ii[p].tolist(), jj[p].tolist(), np.asarray(mr).tolist()), key=lambda t: t[2])
        out.append(PairAssignment(triples=triples, value=float(value.sum()), n_evaluations=source.n_evaluations))
    return out


def _relaxed_from_cost(n, ii, jj, cost, ordered, counted) -> PairAssignment:
    """Problem 3 from the ``(L, P)`` weights ``cost`` of the pairs ``(ii, jj)``, ``ii < jj``."""
    from scipy.optimize import linear_sum_assignment

    n_targets = cost.shape[0]
    if n_targets < 1:
        raise ValueError("there must be at least one target")
    if n < 2:
        raise ValueError(f"pairs need at least two sensors, got {n}")
    if ordered:  # (i, j) and (j, i) carry the same weight
        ii, jj, cost = np.concatenate([ii, jj]), np.concatenate([jj, ii]), np.concatenate([cost, cost], axis=1)
    rows, cols = linear_sum_assignment(cost, maximize=True)
    triples = sorted(
        (min(int(ii[c]), int(jj[c])), max(int(ii[c]), int(jj[c])), int(r)) for r, c in zip(rows, cols)
    )
    triples.sort(key=lambda t: t[2])
    return PairAssignment(triples=triples, value=float(cost[rows, cols].sum()), n_evaluations=counted)


def optimal_pair_assignment(W, time_limit: float | None = None) -> PairAssignment:
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
    ``scipy.optimize.milp``. Fig. 8's random instances at ``L = 20``, ``N = 2L`` take 0.1 to 1 s
    (one HiGHS 0-1 program: about 4 s).

    Parameters
    ----------
    W : array_like, shape (N, N, L)
        Pair weights: finite, non-negative, symmetric in ``i, j`` (the diagonal is ignored).
    time_limit : float, optional
        Seconds after which the call gives up (RuntimeError).

    Returns
    -------
    PairAssignment
        An optimal assignment, ``triples`` sorted by target; where several assignments are
        optimal (ties, zero weights), which one is returned is unspecified.

    Raises
    ------
    ValueError
        For bad ``W`` or ``N < 2L``; RuntimeError if the solver stops without a proven optimum.

    Examples
    --------
    >>> from obslib.bounds import pair_bounds
    >>> S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    >>> optimal_pair_assignment(pair_bounds(S, T, 1.0)).triples
    [(0, 1, 0), (2, 3, 1)]
    """
    arr = as_weights(W)
    n, n_targets = arr.shape[0], arr.shape[2]
    check_pair_sizes(n, n_targets)
    if time_limit is not None:
        if isinstance(time_limit, bool) or not isinstance(time_limit, (int, float, np.integer, np.floating)):
            raise ArgumentTypeError(f"time_limit must be a number of seconds or None, got {time_limit!r}")
        if not (np.isfinite(time_limit) and time_limit > 0):
            raise ValueError(f"time_limit must be positive and finite, got {time_limit!r}")
    deadline = None if not time_limit else time.perf_counter() + float(time_limit)
    start = _greedy(_WeightSource(arr), n, n_targets).triples  # one of the search's incumbents
    triples = sorted(exact_pairs.solve(arr, deadline, start), key=lambda t: t[2])
    return PairAssignment(triples=triples, value=assignment_value(arr, triples))

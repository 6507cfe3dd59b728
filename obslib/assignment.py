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
    (reduced-cost fixing), and explores the rest target by target, pruning with the smallest
    remaining loss per target and per sensor. It proves the optimum up to :math:`10^{-10}` of the
    bound (floating-point noise); if the search grows beyond a fixed node count it hands the
    reduced model to ``scipy.optimize.milp``. Practical for the sizes of the paper (``L <= 20``,
    ``N = 2L``).

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
    return _optimal(arr, deadline)


def _hi_scale(top: float) -> float:
    """Divisor bringing weights of maximum ``top`` near 1 for HiGHS (1 when already in range).

    HiGHS treats ``|c| >= 1e20`` as infinite and has absolute tolerances near 1e-9: weights far
    outside ``[2**-20, 2**20]`` are divided by a power of two first (the optimum does not change).
    """
    return 1.0 if 2.0**-20 <= top <= 2.0**20 else 2.0 ** (np.frexp(top)[1] - 1)


def _pair_rows(n, n_targets, ii, jj, keep):
    """Constraint matrix (target rows, then sensor rows) of the variables ``keep`` (``p * L + l``)."""
    from scipy.sparse import coo_matrix, vstack

    p_of, l_of = keep // n_targets, keep % n_targets
    col = np.arange(keep.size)
    target_rows = coo_matrix((np.ones(keep.size), (l_of, col)), shape=(n_targets, keep.size))
    sensor_rows = coo_matrix(
        (np.ones(2 * keep.size), (np.concatenate([ii[p_of], jj[p_of]]), np.concatenate([col, col]))),
        shape=(n, keep.size),
    )
    return vstack([target_rows, sensor_rows]).tocsr()


def _milp(arr, time_limit=None, keep=None) -> PairAssignment:
    """Problem 1 as one HiGHS 0-1 program (``scipy.optimize.milp``) over the variables ``keep``
    (indices ``p * L + l``, default all); the plain formulation, also the reference of the tests."""
    from scipy.optimize import Bounds, LinearConstraint, milp

    n, n_targets = arr.shape[0], arr.shape[2]
    ii, jj = np.triu_indices(n, 1)
    w = arr[ii, jj, :].reshape(-1)  # variable index p * L + l
    if keep is None:
        keep = np.arange(w.size)
    c = -w[keep]
    top = float(-c.min(initial=0.0))
    if top == 0.0:  # every weight is 0: assigning nothing is optimal (HiGHS cannot rank zeros)
        return PairAssignment(triples=[], value=0.0)
    c = c / _hi_scale(top)
    options = {"mip_rel_gap": 0.0}  # proven optimum, not HiGHS's default 1e-4 relative gap
    if time_limit:
        options["time_limit"] = time_limit
    res = milp(
        c,
        constraints=LinearConstraint(_pair_rows(n, n_targets, ii, jj, keep), -np.inf, 1.0),
        integrality=np.ones(keep.size),
        bounds=Bounds(0, 1),
        options=options,
    )
    if res.status != 0:
        raise RuntimeError(f"MILP did not reach a proven optimum: {res.message}")
    chosen = keep[res.x > 0.5]
    p_of, l_of = chosen // n_targets, chosen % n_targets
    triples = sorted(zip(ii[p_of].tolist(), jj[p_of].tolist(), l_of.tolist()), key=lambda t: t[2])
    return PairAssignment(triples=triples, value=assignment_value(arr, triples))


def _lp_duals(wmat, n, ii, jj):
    """Duals ``y >= 0`` (target rows, then sensor rows) of Problem 1's LP relaxation and its
    solution ``x`` (indices ``p * L + l``), or ``(None, None)``.

    Any ``y >= 0`` gives valid bounds below; the LP optimum gives the tightest of this form.
    """
    from scipy.optimize import linprog

    n_targets = wmat.shape[1]
    w = wmat.reshape(-1)
    scale = _hi_scale(float(w.max()))
    res = linprog(-w / scale, A_ub=_pair_rows(n, n_targets, ii, jj, np.arange(w.size)),
                  b_ub=np.ones(n_targets + n), bounds=(0, None), method="highs")
    if res.status != 0:
        return None, None
    return np.maximum(-np.asarray(res.ineqlin.marginals), 0.0) * scale, res.x


def _repair(arr, assign, free, tol):
    """Local search on a full assignment ``assign`` (``(L, 2)`` sensors per target), in place.

    Moves: re-pair the four sensors of two targets (three pairings, two ways round) and swap one
    sensor of a target for an unused one; the best improving move is applied until none improves
    by more than ``tol``.
    """
    n_targets = assign.shape[0]
    la, lb = np.triu_indices(n_targets, 1)
    tl = np.arange(n_targets)
    while True:
        a, b = assign[:, 0], assign[:, 1]
        cur = arr[a, b, tl]
        best_gain, best_move = tol, None
        if la.size:
            s1, s2, s3, s4 = a[la], b[la], a[lb], b[lb]
            base = cur[la] + cur[lb]
            for k, (p, q, r, s) in enumerate(((s1, s3, s2, s4), (s1, s4, s2, s3))):
                for flip in (False, True):
                    x, y = ((r, s), (p, q)) if flip else ((p, q), (r, s))
                    gain = arr[x[0], x[1], la] + arr[y[0], y[1], lb] - base
                    m = int(np.argmax(gain))
                    if gain[m] > best_gain:
                        best_gain, best_move = float(gain[m]), ("pair", m, k, flip)
            # swapping whole pairs between the two targets
            gain = arr[s3, s4, la] + arr[s1, s2, lb] - base
            m = int(np.argmax(gain))
            if gain[m] > best_gain:
                best_gain, best_move = float(gain[m]), ("pair", m, 2, False)
        fr = np.flatnonzero(free)
        if fr.size:
            for side in (0, 1):
                keep = assign[:, 1 - side]
                gain = arr[fr[None, :], keep[:, None], tl[:, None]] - cur[:, None]
                m = int(np.argmax(gain))
                if gain.flat[m] > best_gain:
                    best_gain, best_move = float(gain.flat[m]), ("free", m, side, fr)
        if best_move is None:
            return
        kind, m, k, extra = best_move
        if kind == "pair":
            l1, l2 = la[m], lb[m]
            s1, s2, s3, s4 = assign[l1, 0], assign[l1, 1], assign[l2, 0], assign[l2, 1]
            if k == 2:
                new1, new2 = (s3, s4), (s1, s2)
            else:
                p1, p2 = ((s1, s3), (s2, s4)) if k == 0 else ((s1, s4), (s2, s3))
                new1, new2 = (p2, p1) if extra else (p1, p2)
            assign[l1], assign[l2] = new1, new2
        else:
            l, f = divmod(m, extra.size)
            free[assign[l, k]] = True
            assign[l, k] = extra[f]
            free[extra[f]] = False


def _complete(n, n_targets, triples):
    """A full assignment ``(L, 2)`` and the free-sensor mask from partial ``triples``."""
    assign = np.full((n_targets, 2), -1)
    free = np.ones(n, dtype=bool)
    for i, j, l in triples:
        assign[l] = i, j
        free[i] = free[j] = False
    for l in np.flatnonzero(assign[:, 0] < 0):
        i, j = np.flatnonzero(free)[:2]
        assign[l] = i, j
        free[i] = free[j] = False
    return assign, free


#: Nodes the search may visit before handing the reduced model to HiGHS (bounds the time on
#: adversarial instances; the paper's random instances need a few thousand).
_MAX_NODES = 200_000


def _optimal(arr, deadline) -> PairAssignment:
    """Branch and bound for Problem 1 (see :func:`optimal_pair_assignment`)."""
    n, n_targets = arr.shape[0], arr.shape[2]
    ii, jj = np.triu_indices(n, 1)
    wmat = arr[ii, jj, :]  # (P, L)
    if float(wmat.max(initial=0.0)) == 0.0:
        return PairAssignment(triples=[], value=0.0)
    y, x = _lp_duals(wmat, n, ii, jj)
    if y is None:
        return _milp(arr, _remaining(deadline))
    yt, ys = y[:n_targets], y[n_targets:]
    loss = yt[None, :] + ys[ii][:, None] + ys[jj][:, None] - wmat
    # LP duals are feasible up to HiGHS's tolerance: raise target duals so no loss is negative
    # (any y >= 0 keeps the identity and the bounds valid)
    yt = yt + np.maximum(-loss.min(axis=0), 0.0)
    loss = np.maximum(yt[None, :] + ys[ii][:, None] + ys[jj][:, None] - wmat, 0.0)
    bound = float(yt.sum() + ys.sum())
    tol = 1e-10 * bound

    # incumbent: Algorithm 1 and the LP's rounding completed in order of loss, each improved by
    # local search (entries above 1/2 share no row, so they form an assignment)
    starts = [_greedy(_WeightSource(arr), n, n_targets).triples]
    order = np.lexsort((-wmat.reshape(-1), loss.reshape(-1), x < 0.5))
    used_t, used_s, picks = np.zeros(n_targets, bool), np.zeros(n, bool), []
    for v in order.tolist():
        p, l = divmod(v, n_targets)
        i, j = int(ii[p]), int(jj[p])
        if not (used_t[l] or used_s[i] or used_s[j]):
            used_t[l] = used_s[i] = used_s[j] = True
            picks.append((i, j, l))
            if len(picks) == n_targets:
                break
    starts.append(picks)
    best_val, best = -1.0, None
    for triples in starts:
        assign, free = _complete(n, n_targets, triples)
        _repair(arr, assign, free, tol)
        val = float(arr[assign[:, 0], assign[:, 1], np.arange(n_targets)].sum())
        if val > best_val:
            best_val, best = val, assign.copy()
    best = [(int(min(a, b)), int(max(a, b)), l) for l, (a, b) in enumerate(best.tolist())]
    if bound - best_val <= tol:
        return _result(arr, best)

    # reduced-cost fixing: a variable whose loss reaches the gap is in no better assignment
    keep = np.flatnonzero(loss.reshape(-1) < bound - best_val - tol)
    keep = keep[np.lexsort((-wmat.reshape(-1)[keep], loss.reshape(-1)[keep]))]
    search = _Search(arr, ii, jj, yt, ys, loss, keep, bound, best_val, best, tol, deadline)
    # Search first for assignments within a small gap of the bound, widening it geometrically:
    # a tight floor prunes hard, and an assignment found above it is a near-optimal incumbent
    # for the rest of the search (L = 15: 0.07 s against 0.30 s from the local-search incumbent).
    gap = bound - best_val
    floor = bound - gap / 64
    _remaining(deadline)
    try:
        while True:
            search.run(max(floor, best_val))
            if search.value > floor or floor <= best_val:
                break
            floor = bound - 1.5 * (bound - floor)
    except _TooLarge:
        # the incumbent's gap (not the floor's) decides which variables may still matter
        keep = np.flatnonzero(loss.reshape(-1) < bound - search.value - tol)
        alt = _milp(arr, _remaining(deadline), keep)
        return alt if alt.value > search.value else _result(arr, search.best)
    return _result(arr, search.best)


def _remaining(deadline):
    if deadline is None:
        return None
    left = deadline - time.perf_counter()
    if left <= 0:
        raise RuntimeError("MILP did not reach a proven optimum: time limit reached")
    return left


def _result(arr, triples) -> PairAssignment:
    triples = sorted(triples, key=lambda t: t[2])
    return PairAssignment(triples=triples, value=assignment_value(arr, triples))


class _TooLarge(Exception):
    """The search passed :data:`_MAX_NODES`."""


class _Search:
    """Depth-first branch and bound over targets for :func:`_optimal`.

    With ``bound = 1^T y`` and losses ``loss[p, l] >= 0``, an assignment's value is ``bound``
    minus the losses of its triples, ``y_l`` of each unassigned target and ``y_i`` of each unused
    sensor. A node (some targets decided) is pruned when its losses so far plus a lower bound on
    the rest leave no room above the incumbent; the rest is bounded both by the smallest option
    of each open target and by half the smallest option of each free sensor (a triple's loss
    split between its two sensors, an unused sensor costing ``y_i``).
    """

    def __init__(self, arr, ii, jj, yt, ys, loss, keep, bound, best_val, best, tol, deadline):
        n, n_targets = arr.shape[0], arr.shape[2]
        self.arr, self.bound, self.tol, self.deadline = arr, bound, tol, deadline
        self.value, self.best = best_val, best  # the incumbent
        self.best_val = best_val  # the pruning floor: the incumbent's value or above
        self.yt, self.ys = yt.tolist(), ys.tolist()
        self.tops = [[] for _ in range(n_targets)]  # per target, options (loss, l, i, j) by loss
        self.sops = [[] for _ in range(n)]  # per sensor, the same options
        p_of, l_of = keep // n_targets, keep % n_targets
        for lo, l, i, j in zip(loss.reshape(-1)[keep].tolist(), l_of.tolist(), ii[p_of].tolist(),
                               jj[p_of].tolist()):
            opt = (lo, l, i, j)
            self.tops[l].append(opt)
            self.sops[i].append(opt)
            self.sops[j].append(opt)
        self.nodes = 0
        self.n, self.n_targets = n, n_targets

    def run(self, floor):
        """Search for assignments worth more than ``floor`` (at least the incumbent's value)."""
        _remaining(self.deadline)
        self.best_val = max(floor, self.value)
        self._node(frozenset(range(self.n)), frozenset(range(self.n_targets)), 0.0, [])

    def _node(self, sfree, tfree, spent, chosen):
        self.nodes += 1
        if self.nodes > _MAX_NODES:
            raise _TooLarge
        if self.nodes % 4096 == 0:
            _remaining(self.deadline)
        if not tfree:
            val = float(sum(self.arr[i, j, l] for i, j, l in chosen))
            if val > self.best_val + self.tol:
                self.best_val = self.value = val
                self.best = list(chosen)
            return
        limit = self.bound - self.best_val - self.tol - spent  # the rest must lose less
        yt, ys = self.yt, self.ys
        lbt, tmin = 0.0, {}
        for l in tfree:
            m = yt[l]
            for opt in self.tops[l]:
                if opt[0] >= m:
                    break
                if opt[2] in sfree and opt[3] in sfree:
                    m = opt[0]
                    break
            tmin[l] = m
            lbt += m
        if lbt >= limit:
            return
        lbs = 0.0
        for i in sfree:
            m = 2.0 * ys[i]
            for opt in self.sops[i]:
                if opt[0] >= m:
                    break
                if opt[1] in tfree and opt[2] in sfree and opt[3] in sfree:
                    m = opt[0]
                    break
            lbs += m
        if 0.5 * lbs >= limit:
            return
        # branch on the open target with the fewest options that fit
        pick, options = None, None
        for l in tfree:
            room = limit - (lbt - tmin[l])
            opts = [opt for opt in self._fitting(l, room, sfree)]
            if yt[l] < room:
                opts.append((yt[l], l, -1, -1))
                opts.sort()
            if options is None or len(opts) < len(options):
                pick, options = l, opts
                if len(opts) <= 1:
                    break
        rest = tfree - {pick}
        base = lbt - tmin[pick]
        for opt in options:
            if opt[0] + base >= self.bound - self.best_val - self.tol - spent:  # incumbent improved
                break
            if opt[2] < 0:
                self._node(sfree, rest, spent + opt[0], chosen)
            else:
                self._node(sfree - {opt[2], opt[3]}, rest, spent + opt[0], chosen + [(opt[2], opt[3], pick)])

    def _fitting(self, l, room, sfree):
        for opt in self.tops[l]:
            if opt[0] >= room:
                return
            if opt[2] in sfree and opt[3] in sfree:
                yield opt

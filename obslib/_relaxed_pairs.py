"""Problem 3, the relaxed pair assignment, solved exactly: the one solver behind
:func:`obslib.assignment.relaxed_pair_assignment` and
:func:`obslib.assignment.relaxed_from_geometry`.

Each unordered pair of sensors serves at most one target and each target gets at most one pair.
A target matched to a pair outside its ``L`` heaviest could move to one of them, since the other
``L - 1`` targets hold at most ``L - 1`` pairs, and would not lose weight; so every target keeps
only its ``L`` heaviest pairs and their ties (:func:`candidates_from_weights`, or
:func:`candidates_from_geometry` with the greedy's exact pruning, without computing most
weights), and :func:`matching` solves the sparse bipartite matching of targets to those pairs
with ``scipy.sparse.csgraph.min_weight_full_bipartite_matching``. With ``ordered``, each pair
``(i, j)`` is also a second column ``(j, i)``: the original code's relaxation.
"""

from __future__ import annotations

import numpy as np

from ._pair_search import PairSearch, keep_top

__all__ = ["candidates_from_weights", "candidates_from_geometry", "matching"]


def candidates_from_weights(arr) -> tuple:
    """Each target's ``L`` heaviest pairs ``i < j`` of the validated weights ``arr``
    ``(N, N, L)`` and their ties, as ``(target, i * N + j, weight)`` arrays, and ``None`` (no
    weight computed)."""
    n, n_targets = arr.shape[0], arr.shape[2]
    ii, jj = np.triu_indices(n, 1)
    cost = np.ascontiguousarray(arr[ii, jj, :].T)  # (L, P), each row contiguous
    keep = min(n_targets, ii.size)
    kth = np.partition(cost, ii.size - keep, axis=1)[:, ii.size - keep]
    rows, col = np.nonzero(cost >= kth[:, None])
    return rows, ii[col] * n + jj[col], cost[rows, col], None


def candidates_from_geometry(rows_of_targets, bar=None) -> tuple:
    """Each target's ``L`` heaviest pairs and their ties, from the normalised rows ``x, y``
    ``(L, N)`` and ``u^2`` ``(L,)`` (:func:`obslib._pair_search.rows_of`), found with the greedy's
    exact pruning (:class:`obslib._pair_search.PairSearch`); as ``(target, i * N + j, weight)``
    arrays and the number of weights computed. ``bar`` ticks once per target."""
    source = PairSearch(*rows_of_targets)
    n_targets, n = source.x.shape
    every = np.arange(n)
    rows, ids, ws = [], [], []
    for l in range(n_targets):
        a, b, w, _ = source.best(l, every, n_targets)
        a, b, w = keep_top(a, b, w, n_targets)
        rows.append(np.full(w.size, l))
        ids.append(np.minimum(a, b) * n + np.maximum(a, b))
        ws.append(w)
        if bar is not None:
            bar.update()
    return np.concatenate(rows), np.concatenate(ids), np.concatenate(ws), source.n_evaluations


def matching(rows, ids, ws, n: int, n_targets: int, ordered: bool) -> tuple:
    """The maximum-weight matching of the targets ``rows`` to their candidate pairs ``ids``
    (``i * N + j``) of weights ``ws``; with ``ordered``, each pair also as ``(j, i)``, a second
    column of its own. Returns the triples ``(i, j, l)``, ``i < j``, sorted by target, and
    their total weight summed in that order."""
    from scipy.sparse import csr_array
    from scipy.sparse.csgraph import min_weight_full_bipartite_matching

    pairs, col = np.unique(ids, return_inverse=True)
    ii, jj = pairs // n, pairs % n
    r, c, w, m = rows, col, ws, pairs.size
    if ordered:  # the second copy of pair p is column m + p
        r, c = np.r_[rows, rows], np.r_[col, col + pairs.size]
        w, m = np.r_[ws, ws], 2 * pairs.size
    # every full matching has min(L, m) edges, so the offset (edges must be nonzero) changes no
    # choice; weights are non-negative, so a heaviest matching may as well be a largest one
    graph = csr_array((w + 1.0, (r, c)), shape=(n_targets, m))
    mr, mc = min_weight_full_bipartite_matching(graph, maximize=True)
    mr, mc = np.asarray(mr, dtype=np.int64), np.asarray(mc, dtype=np.int64)
    by_target = np.argsort(mr)
    mr, mc = mr[by_target], mc[by_target]
    key = r.astype(np.int64) * m + c  # each (target, column) edge once
    order = np.argsort(key)
    value = w[order[np.searchsorted(key[order], mr * m + mc)]]
    p = mc % pairs.size
    triples = list(zip(ii[p].tolist(), jj[p].tolist(), mr.tolist()))
    return triples, float(value.sum())

"""Problem 1's exact optimum and Algorithm 1's value for whole batches of small instances, by
dynamic programming over the sets of used sensors (Section IV-A; notebooks 03, 07 and 11).

The paper could not compute the optimum of Problem 1; for small instances we can, exactly, for a
whole batch of instances at once with NumPy (:func:`optimal_values`, :func:`optimal_assignments`;
:func:`pair_assignments` enumerates every assignment instead, the brute force the tests compare
it with), beside Algorithm 1 on the same batch (:func:`greedy_values`) and Theorem 4's weights of
a batch of geometries (:func:`batch_pair_bounds`).
"""

from __future__ import annotations

from functools import lru_cache
from itertools import combinations

import numpy as np

from .._kernels import normalise, pair_kernel
from .._validate import as_float_array, as_int, as_u_max
from ..assignment import greedy_pairs_batch
from ..tracking.assigners import MAX_ENUMERATED, assignment_count

__all__ = ["MAX_DP_SENSORS", "pair_assignments", "optimal_values", "optimal_assignments",
           "greedy_values", "batch_pair_bounds"]

def pair_assignments(n: int, n_targets: int) -> tuple[np.ndarray, np.ndarray]:
    """All ways to give each of ``L`` targets its own pair out of ``N`` sensors, no sensor twice.

    Returns ``(P, Q)``, each of shape ``(A, L)``: assignment ``a`` gives target ``l`` the pair
    ``(P[a, l], Q[a, l])`` with ``P < Q``. With non-negative weights an optimum of Problem 1
    assigns every target (``N >= 2L``), so these are all the candidates; there may be at most
    :data:`~obslib.tracking.assigners.MAX_ENUMERATED` of them, the tracking engine's limit.

    Examples
    --------
    Two targets, four sensors: three ways to split the sensors into two pairs, each in two orders:

    >>> P, Q = pair_assignments(4, 2)
    >>> for p, q in zip(P.tolist(), Q.tolist()):
    ...     print(list(zip(p, q)))
    [(0, 1), (2, 3)]
    [(0, 2), (1, 3)]
    [(0, 3), (1, 2)]
    [(1, 2), (0, 3)]
    [(1, 3), (0, 2)]
    [(2, 3), (0, 1)]
    """
    return _pair_assignments(as_int(n, "n", 0), as_int(n_targets, "n_targets", 0))


@lru_cache(maxsize=32)
def _pair_assignments(n, n_targets):
    if n < 2 * n_targets or n_targets < 1:
        raise ValueError(f"need L >= 1 and N >= 2L, got N = {n}, L = {n_targets}")
    if assignment_count(n, n_targets) > MAX_ENUMERATED:
        raise ValueError(f"more than {MAX_ENUMERATED} assignments for N = {n}, L = {n_targets}")
    out = []
    pairs = list(combinations(range(n), 2))

    def rec(l, used, chosen):
        if l == n_targets:
            out.append(tuple(chosen))
            return
        for p in pairs:
            if p[0] not in used and p[1] not in used:
                rec(l + 1, used | set(p), chosen + [p])

    rec(0, frozenset(), [])
    arr = np.array(out, dtype=np.int64)  # (A, L, 2)
    return arr[:, :, 0], arr[:, :, 1]


#: Largest ``N`` :func:`optimal_values` accepts (its tables have up to ``2^N`` entries per
#: instance).
MAX_DP_SENSORS = 16


def _as_batch(W) -> np.ndarray:
    W = as_float_array(W, "W")
    if W.ndim != 4 or W.shape[1] != W.shape[2]:
        raise ValueError(f"W must be a batch of weight arrays of shape (K, N, N, L), got {W.shape}")
    k, n, _, n_targets = W.shape
    if n_targets < 1 or n < 2 * n_targets:
        raise ValueError(f"need L >= 1 and N >= 2L, got N = {n}, L = {n_targets}")
    if not np.isfinite(W).all():
        raise ValueError("W must be finite")
    return W


def optimal_values(W) -> np.ndarray:
    r"""Problem 1's optimum for a batch of weight arrays ``W`` of shape ``(K, N, N, L)``.

    Dynamic programming over targets in order: after target ``l``, ``best[mask]`` is the largest
    total weight of giving targets ``0..l`` disjoint pairs that use exactly the sensors in the
    bit set ``mask``; target ``l + 1`` extends each set by every pair disjoint from it. Every
    target gets a pair (as Algorithm 1 gives one), so the optimum is the largest entry after the
    last target; with non-negative weights that is also the optimum when a target may be left
    out. The sums are formed in target order, as a direct sum over an assignment would be, and
    rounding is monotone, so the result equals the maximum over :func:`pair_assignments` exactly
    (the tests compare them). Work grows like :math:`2^N N^2 L` per instance; ``N`` is limited to
    :data:`MAX_DP_SENSORS`.

    Examples
    --------
    On :func:`~obslib.studies.greedy_unique_pairs.tight_weights` the optimum is 3:

    >>> from obslib.studies.greedy_unique_pairs import tight_weights
    >>> optimal_values(tight_weights(eps=1e-3)[None])
    array([3.])
    """
    return _optimum(_as_dp_batch(W), False)[0]


def optimal_assignments(W) -> tuple[np.ndarray, np.ndarray]:
    """Problem 1's optimum and one optimal assignment, for a batch ``W`` ``(K, N, N, L)``.

    The dynamic program of :func:`optimal_values` (the same values, bit for bit), which also
    keeps, for every set of sensors it reaches, the first best way to reach it, and walks those
    choices back from the best final set.

    Returns
    -------
    values : ndarray, shape (K,)
    triples : ndarray, shape (K, L, 3)
        ``(i, j, l)`` with ``i < j`` for each target ``l`` in order.

    Examples
    --------
    >>> from obslib.studies.greedy_unique_pairs import tight_weights
    >>> values, triples = optimal_assignments(tight_weights(eps=1e-3)[None])
    >>> values.tolist(), triples[0].tolist()
    ([3.0], [[4, 5, 0], [0, 2, 1], [1, 3, 2]])
    """
    return _optimum(_as_dp_batch(W), True)


def _as_dp_batch(W) -> np.ndarray:
    W = _as_batch(W)
    if W.shape[1] > MAX_DP_SENSORS:
        raise ValueError(
            f"N = {W.shape[1]} sensors is too many for the exact optimum (at most {MAX_DP_SENSORS})"
        )
    return W


def _optimum(W: np.ndarray, with_triples: bool):
    """The dynamic program of :func:`optimal_values` on a validated batch; with
    ``with_triples``, also one optimal assignment per instance (else ``None``)."""
    k, n, _, n_targets = W.shape
    ii, jj = np.triu_indices(n, 1)
    pair_mask = (np.int64(1) << ii) | (np.int64(1) << jj)
    states = np.zeros(1, dtype=np.int64)  # sensor sets reachable after the targets so far
    best = np.zeros((k, 1))
    layers = []  # per target: the previous state and the pair of each candidate, and the choice
    for l in range(n_targets):
        s, p = np.nonzero((states[:, None] & pair_mask[None, :]) == 0)  # set s extended by pair p
        new = states[s] | pair_mask[p]
        order = np.argsort(new, kind="stable")
        new = new[order]
        starts = np.flatnonzero(np.r_[True, new[1:] != new[:-1]])
        vals = best[:, s[order]] + W[:, ii[p[order]], jj[p[order]], l]
        best = np.maximum.reduceat(vals, starts, axis=1)
        if with_triples:  # the first candidate of each new set that reaches its best
            sizes = np.diff(np.r_[starts, vals.shape[1]])
            hit = vals == np.repeat(best, sizes, axis=1)
            pos = np.where(hit, np.arange(vals.shape[1]), vals.shape[1])
            layers.append((s[order], p[order], np.minimum.reduceat(pos, starts, axis=1)))
        states = new[starts]
    values = best.max(axis=1)
    if not with_triples:
        return values, None
    rows = np.arange(k)
    at = best.argmax(axis=1)  # index of the final set, per instance
    triples = np.empty((k, n_targets, 3), dtype=np.int64)
    for l in range(n_targets - 1, -1, -1):
        prev, pair, choice = layers[l]
        c = choice[rows, at]
        triples[:, l] = np.column_stack([ii[pair[c]], jj[pair[c]], np.full(k, l)])
        at = prev[c]
    return values, triples


def greedy_values(W) -> np.ndarray:
    """Algorithm 1's value for a batch of weight arrays ``W`` of shape ``(K, N, N, L)``.

    The picks of :func:`obslib.assignment.greedy_pairs_batch` (ties to the smallest
    ``(i, j, l)``, as :func:`obslib.greedy_pair_assignment`), their weights summed in pick
    order, so the values equal its ``value`` exactly (the tests compare them).

    Examples
    --------
    On :func:`~obslib.studies.greedy_unique_pairs.tight_weights` the greedy takes the heavy pair
    and is stuck with :math:`1 + \\varepsilon`:

    >>> from obslib.studies.greedy_unique_pairs import tight_weights
    >>> greedy_values(tight_weights(eps=1e-3)[None])
    array([1.001])
    """
    W = _as_batch(W)
    n = W.shape[1]
    ii, jj = np.triu_indices(n, 1)
    _, weights = greedy_pairs_batch(W[:, ii, jj, :], n)
    return np.cumsum(weights, axis=1)[:, -1]  # summed in pick order


def batch_pair_bounds(sensors, targets, u_max) -> tuple[np.ndarray, np.ndarray]:
    """:func:`obslib.pair_bounds` (Theorem 4, Euclidean) for a batch of geometries.

    ``sensors`` ``(K, N, 2)`` and ``targets`` ``(K, L, 2)``; returns ``(W, valid)``: ``W`` of
    shape ``(K, N, N, L)``, equal bit for bit to ``pair_bounds(sensors[k], targets[k], u_max)``
    (same normalisation, same kernel), and ``valid[k]``, false where that call would raise
    because two sensors coincide or a sensor sits on a target (``W[k]`` is then meaningless).

    Examples
    --------
    >>> import obslib as ob
    >>> S = np.array([[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]])
    >>> T = np.array([[[0.5, 0.5], [2.0, 2.0]]])
    >>> W, valid = batch_pair_bounds(S, T, 1.0)
    >>> W.shape, valid, bool(np.array_equal(W[0], ob.pair_bounds(S[0], T[0], 1.0)))
    ((1, 4, 4, 2), array([ True]), True)
    """
    S = as_float_array(sensors, "sensors")
    T = as_float_array(targets, "targets")
    if S.ndim != 3 or T.ndim != 3 or S.shape[2] != 2 or T.shape[2] != 2 or S.shape[0] != T.shape[0]:
        raise ValueError(
            f"need sensors (K, N, 2) and targets (K, L, 2), got {S.shape} and {T.shape}"
        )
    if not (np.isfinite(S).all() and np.isfinite(T).all()):
        raise ValueError("sensor and target positions must be finite")
    u = float(as_u_max(u_max))
    n = S.shape[1]
    v = T[:, None, :, :] - S[:, :, None, :]  # (K, N, L, 2), as relative_vectors
    same = (S[:, :, None, :] == S[:, None, :, :]).all(axis=-1) & ~np.eye(n, dtype=bool)
    valid = ~same.any(axis=(1, 2)) & ~(v == 0).all(axis=-1).any(axis=(1, 2))
    k, n_targets = v.shape[0], v.shape[2]
    # the K instances' targets side by side, (N, K L, 2), normalised as pair_bounds does
    with np.errstate(divide="ignore", invalid="ignore"):
        v, u2 = normalise(v.transpose(1, 0, 2, 3).reshape(n, k * n_targets, 2), u)
        v = v.reshape(n, k, n_targets, 2).transpose(1, 0, 2, 3)  # (K, N, L, 2)
        u2 = u2.reshape(k, n_targets)
        x, y = v[..., 0], v[..., 1]  # (K, N, L)
        W = pair_kernel(
            x[:, :, None, :],
            y[:, :, None, :],
            x[:, None, :, :],
            y[:, None, :, :],
            u2[:, None, None, :],
        )
    return W, valid

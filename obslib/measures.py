"""Theorem 8's four measures of the symmetric observability matrix ``O^T O``.

Theorem 8 of the paper (Sec. IV-B) states that for the *symmetric observability matrix*
``OO(o, u_o) := O(o, u_o)^T O(o, u_o)`` "its trace, log determinant, rank and the trace of its
inverse are submodular and monotone increasing" as functions of the set of sensors. This module
evaluates those measures for one set of sensors (:func:`measure`, the form the greedy team
assignment of Problem 2 calls) and, vectorised, for many subsets and many instances at once
(:func:`measure_table`, :func:`measure_from_vectors`).

Conventions
-----------
Rows.
    ``O`` has the rows ``o - p_i`` of the chosen sensors (Eq. (4)), so
    ``O^T O = sum_i (o - p_i)(o - p_i)^T`` is a sum of one rank-one term per sensor.
The ``u`` row.
    ``u=None`` (default) leaves it out: the stationary target, and the matrix the paper's
    Fig. 9 experiment used. A given ``u`` (shape ``(2,)``, e.g. ``u_max`` times a unit
    direction) is a *fixed, known* control appended as the last row, so it adds the same
    ``u u^T`` to every subset. (The worst-case control of Theorem 1, ``u_max v_max``, is not
    used: its direction depends on the subset, which would make ``u u^T`` a different term for
    every set and is not what Theorem 8 is about.)
Prior information ``eps``.
    ``eps >= 0`` adds ``eps I`` (the information of a prior with covariance ``I / eps``):
    the measured matrix is ``G = O^T O + eps I``. With ``eps = 0`` and fewer than two
    independent rows, ``G`` is singular: ``logdet`` is ``-inf`` and the inverse does not exist,
    so ``trace_inverse`` is ``+inf`` (its limit as ``eps -> 0+``) and ``neg_trace_inverse`` is
    ``-inf``. These are returned as such, without warnings and never as NaN. A greedy that
    compares marginal gains needs finite values: pass ``eps > 0``.
Rank.
    ``rank`` is the rank of ``O^T O`` itself (``eps`` is ignored: ``O^T O + eps I`` always has
    rank 2). It is numerical: a 2 x 2 matrix has rank 2 when ``sigma_min / sigma_max`` of
    ``O`` exceeds ``rank_rtol`` (default ``1e-10``), rank 1 when it is nonzero, rank 0 when
    empty. The same test decides "singular" for ``eps = 0`` above.

Direction of monotonicity.
    ``trace``, ``logdet`` and ``rank`` can only increase when a sensor is added (each adds a
    positive semidefinite term). ``trace_inverse`` can only *decrease* (``G <= G'`` in the
    Loewner order implies ``G'^{-1} <= G^{-1}``), so "monotone increasing" as printed can only
    hold for its negative, ``neg_trace_inverse = -trace(G^{-1})``, the form to maximise.
    :data:`DIRECTION` records this.

Computation.
    For a 2 x 2 matrix everything follows from ``tr`` and ``det``: with the rows ``v_k`` of
    the subset (the sensors' ``o - p_i`` and ``u``), ``tr(O^T O) = sum ||v_k||^2`` and, by the
    Cauchy-Binet formula, ``det(O^T O) = sum_{k < l} (v_k x v_l)^2`` -- a sum of non-negative
    terms, so it is accurate even for nearly collinear rows. Then
    ``det(G) = det(O^T O) + eps tr(O^T O) + eps^2``, ``tr(G^{-1}) = tr(G) / det(G)``, and one
    matrix product over the membership matrix of the subsets evaluates all of them at once.
"""

from __future__ import annotations

from itertools import combinations

import numpy as np

from ._validate import as_point
from .observability import observability_matrix, relative_rows

__all__ = [
    "MEASURES",
    "DIRECTION",
    "RANK_RTOL",
    "measure",
    "measure_table",
    "measure_from_vectors",
    "measures_from_vectors",
    "subset_masks",
    "symmetric_observability_matrix",
]

#: Measure names accepted by :func:`measure`.
MEASURES = ("trace", "logdet", "rank", "trace_inverse", "neg_trace_inverse")

#: The only direction in which each measure can be monotone (see the module docstring).
DIRECTION = {
    "trace": "increasing",
    "logdet": "increasing",
    "rank": "increasing",
    "trace_inverse": "decreasing",
    "neg_trace_inverse": "increasing",
}

#: Default relative threshold on ``sigma_min / sigma_max`` below which ``O`` counts as rank-deficient.
RANK_RTOL = 1e-10

#: Largest ground set for which :func:`subset_masks` enumerates all subsets.
MAX_GROUND_SET = 16


def _check_name(name: str) -> str:
    if name not in MEASURES:
        raise ValueError(f"unknown measure {name!r}; known: {MEASURES}")
    return name


def _check_eps(eps) -> float:
    try:
        e = float(eps)
    except (TypeError, ValueError):
        raise ValueError(f"eps must be a non-negative number, got {eps!r}") from None
    if not np.isfinite(e) or e < 0:
        raise ValueError(f"eps must be finite and non-negative, got {eps!r}")
    return e


def _check_rtol(rank_rtol) -> float:
    r = float(rank_rtol)
    if not (np.isfinite(r) and 0 <= r < 1):
        raise ValueError(f"rank_rtol must be in [0, 1), got {rank_rtol!r}")
    return r


def subset_masks(n: int) -> np.ndarray:
    """Membership matrix of all ``2**n`` subsets of ``{0, ..., n-1}``, shape ``(2**n, n)``.

    Row ``k`` is the subset whose elements are the set bits of ``k`` (element ``i`` <-> bit
    ``i``): row 0 is the empty set, row ``2**n - 1`` the whole ground set.
    """
    if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 0:
        raise ValueError(f"n must be a non-negative integer, got {n!r}")
    if n > MAX_GROUND_SET:
        raise ValueError(f"ground set of {n} elements is too large to enumerate (max {MAX_GROUND_SET})")
    k = np.arange(2**n)[:, None]
    return ((k >> np.arange(n)[None, :]) & 1).astype(bool)


def _sensors_or_empty(sensors) -> np.ndarray:
    arr = np.asarray(sensors, dtype=float) if not isinstance(sensors, np.ndarray) else sensors
    if arr.size == 0:
        return np.zeros((0, 2))
    return arr


def symmetric_observability_matrix(sensors, target, u=None, eps: float = 0.0) -> np.ndarray:
    """``O(o, u)^T O(o, u) + eps I``, the symmetric observability matrix of Theorem 8.

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        Sensor positions (distinct, none on the target); ``N = 0`` is allowed.
    target : array_like, shape (2,)
        Target position ``o``.
    u : array_like, shape (2,), optional
        A fixed known control, appended as the last row of ``O`` (Eq. (4)).
    eps : float
        Prior information added on the diagonal (``>= 0``).

    Returns
    -------
    ndarray, shape (2, 2)
    """
    e = _check_eps(eps)
    O = observability_matrix(_sensors_or_empty(sensors), target, u)
    return O.T @ O + e * np.eye(2)


#: Largest ``rows * inner * columns`` of one matrix product in :func:`_matmul_rows`.
_GEMM_BLOCK = 1 << 18


def _matmul_rows(x: np.ndarray, w: np.ndarray) -> np.ndarray:
    """``x @ w`` for a 2-D ``x``, in blocks of rows.

    The products here are thin (a few dozen inner terms): a multi-threaded BLAS spends more on
    waking and spinning its threads than on the arithmetic, and steals the core the rest of the
    computation runs on. Blocks of at most :data:`_GEMM_BLOCK` multiply-adds stay below
    OpenBLAS's threading threshold. Measured on two cores with the default BLAS threads: a
    ``(2000, 15) @ (15, 64)`` product takes 0.4 ms blocked against 8 ms whole, ``(20000, 15) @
    (15, 64)`` 3 ms against 8 ms. The result equals ``x @ w`` to rounding, not bit for bit: BLAS
    chooses its summation order by CPU and block shape (a test bounds the difference).
    """
    if x.ndim != 2:
        return x @ w
    step = max(1, _GEMM_BLOCK // max(1, w.shape[0] * w.shape[1]))
    if x.shape[0] <= step:
        return x @ w
    out = np.empty((x.shape[0], w.shape[1]))
    for i in range(0, x.shape[0], step):
        np.matmul(x[i:i + step], w, out=out[i:i + step])
    return out


def _tr_det(vectors: np.ndarray, masks: np.ndarray):
    """``tr``, ``det``, ``lambda_max`` of ``sum_{k in S} v_k v_k^T`` for each row ``S`` of ``masks``.

    ``vectors`` has shape ``(..., M, 2)`` and ``masks`` ``(K, M)``; the results have shape
    ``(..., K)``. The determinant is the Cauchy-Binet sum of squared cross products.
    """
    m = masks.astype(float)
    sq = np.einsum("...mk,...mk->...m", vectors, vectors)
    tr = _matmul_rows(sq, m.T)
    n = vectors.shape[-2]
    if n >= 2:
        a, b = np.array(list(combinations(range(n), 2))).T
        cross = vectors[..., a, 0] * vectors[..., b, 1] - vectors[..., a, 1] * vectors[..., b, 0]
        det = _matmul_rows(cross * cross, (m[:, a] * m[:, b]).T)
    else:
        det = np.zeros_like(tr)
    half = 0.5 * tr
    lmax = half + np.sqrt(np.maximum(half * half - det, 0.0))
    return tr, det, lmax


def _from_tr_det(name: str, tr, det, lmax, eps: float, rank_rtol: float):
    """Measure ``name`` of ``G = A + eps I`` from ``tr``, ``det``, ``lambda_max`` of ``A = O^T O``."""
    if name == "trace":
        return tr + 2.0 * eps
    with np.errstate(divide="ignore", invalid="ignore"):
        full = det > (rank_rtol * lmax) ** 2  # sigma_min / sigma_max > rank_rtol, and A != 0
    if name == "rank":
        return np.where(full, 2.0, np.where(tr > 0, 1.0, 0.0))
    det_g = det + eps * tr + eps * eps
    tr_g = tr + 2.0 * eps
    if eps == 0.0:
        det_g = np.where(full, det_g, 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        if name == "logdet":
            return np.where(det_g > 0, np.log(np.where(det_g > 0, det_g, 1.0)), -np.inf)
        inv = np.where(det_g > 0, tr_g / np.where(det_g > 0, det_g, 1.0), np.inf)
    return inv if name == "trace_inverse" else -inv


def measure_from_vectors(vectors, masks, name: str, eps: float = 0.0, u=None,
                         rank_rtol: float = RANK_RTOL) -> np.ndarray:
    """Vectorised kernel: a measure for many subsets of many instances at once.

    Parameters
    ----------
    vectors : array_like, shape (..., N, 2)
        Rows ``o - p_i`` of each instance (already validated by the caller).
    masks : array_like of bool, shape (K, N)
        The subsets, one membership row each (see :func:`subset_masks`).
    name : str
        One of :data:`MEASURES`.
    eps : float
        Prior information ``eps I`` (``>= 0``); ignored by ``rank``.
    u : array_like, shape (2,) or (..., 2), optional
        Fixed control row(s), one per instance or shared.
    rank_rtol : float
        Threshold of the numerical rank (see the module docstring).

    Returns
    -------
    ndarray, shape (..., K)
    """
    _check_name(name)
    return measures_from_vectors(vectors, masks, (name,), eps, u, rank_rtol)[name]


def measures_from_vectors(vectors, masks, names=MEASURES, eps: float = 0.0, u=None,
                          rank_rtol: float = RANK_RTOL) -> dict:
    """Several measures of the same subsets at once: ``{name: table}``.

    ``tr``, ``det`` and ``lambda_max`` of ``O^T O`` are computed once and shared by all
    ``names``; each table is bitwise the one :func:`measure_from_vectors` returns for that name
    (it is the same code). Parameters as in :func:`measure_from_vectors`.
    """
    for name in names:
        _check_name(name)
    e = _check_eps(eps)
    r = _check_rtol(rank_rtol)
    v = np.asarray(vectors, dtype=float)
    m = np.asarray(masks, dtype=bool)
    if v.ndim < 2 or v.shape[-1] != 2:
        raise ValueError(f"vectors must have shape (..., N, 2), got {v.shape}")
    if m.ndim != 2 or m.shape[1] != v.shape[-2]:
        raise ValueError(f"masks must have shape (K, {v.shape[-2]}), got {m.shape}")
    if u is not None:
        uu = np.broadcast_to(np.asarray(u, dtype=float), v.shape[:-2] + (2,))
        v = np.concatenate([v, uu[..., None, :]], axis=-2)
        m = np.concatenate([m, np.ones((m.shape[0], 1), dtype=bool)], axis=1)
    tr, det, lmax = _tr_det(v, m)
    return {name: _from_tr_det(name, tr, det, lmax, e, r) for name in names}


def measure_table(sensors, target, name: str, eps: float = 0.0, u=None, masks=None,
                  rank_rtol: float = RANK_RTOL) -> np.ndarray:
    """A Theorem 8 measure for every subset of ``sensors`` (or the given ``masks``).

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        The ground set of sensors (distinct, none on the target).
    target : array_like, shape (2,)
        Target position ``o``.
    name, eps, u, rank_rtol
        As in :func:`measure`.
    masks : array_like of bool, shape (K, N), optional
        Subsets to evaluate; default all ``2**N`` in bitmask order (:func:`subset_masks`).

    Returns
    -------
    ndarray, shape (2**N,) or (K,)
    """
    rows = relative_rows(sensors, target)
    if masks is None:
        masks = subset_masks(rows.shape[0])
    uu = None if u is None else as_point(u, "u")
    return measure_from_vectors(rows, masks, name, eps, uu, rank_rtol)


def measure(sensors, target, name: str, eps: float = 0.0, u=None,
            rank_rtol: float = RANK_RTOL) -> float:
    """One Theorem 8 measure of ``O^T O + eps I`` for one set of sensors.

    This is the set function ``w_l(S)`` a greedy team assignment (Problem 2) maximises.

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        The sensors of the team (distinct, none on the target). ``N = 0`` (an empty list) is
        allowed: ``O^T O = 0``.
    target : array_like, shape (2,)
        Target position ``o`` (true or estimated).
    name : str
        ``"trace"``, ``"logdet"``, ``"rank"``, ``"trace_inverse"`` or ``"neg_trace_inverse"``.
    eps : float
        Prior information ``eps I`` added to ``O^T O`` (``>= 0``, default 0). With ``eps = 0`` a
        singular matrix gives ``logdet = -inf`` and ``trace_inverse = +inf``.
    u : array_like, shape (2,), optional
        A fixed known control appended as the last row of ``O`` (default: no ``u`` row).
    rank_rtol : float
        Relative threshold of the numerical rank.

    Returns
    -------
    float

    Examples
    --------
    >>> measure([[0, 0], [2, 0]], [1, 1], "logdet")  # rows (1, 1), (-1, 1): det = 4
    1.3862943611198906
    """
    rows = relative_rows(_sensors_or_empty(sensors), target)
    uu = None if u is None else as_point(u, "u")
    mask = np.ones((1, rows.shape[0]), dtype=bool)
    return float(measure_from_vectors(rows, mask, name, eps, uu, rank_rtol)[0])

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
    ``O`` has the rows ``o - p_i`` of the chosen sensors (Eq. (5)), so
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

import numpy as np

from ._kernels import measure_from_tr_det, pow2_scale, tr_det
from ._validate import (
    ArgumentTypeError,
    as_eps,
    as_float_array,
    as_int,
    as_measure_name,
    as_names,
    as_point,
    as_rank_rtol,
)
from .observability import relative_rows

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

#: Default relative threshold on ``sigma_min / sigma_max`` below which ``O`` counts as
#: rank-deficient.
RANK_RTOL = 1e-10

#: Largest ground set for which :func:`subset_masks` enumerates all subsets.
MAX_GROUND_SET = 16


def subset_masks(n: int) -> np.ndarray:
    """Membership matrix of all ``2**n`` subsets of ``{0, ..., n-1}``, shape ``(2**n, n)``.

    Row ``k`` is the subset whose elements are the set bits of ``k`` (element ``i`` <-> bit
    ``i``): row 0 is the empty set, row ``2**n - 1`` the whole ground set.

    Examples
    --------
    >>> subset_masks(2).astype(int)
    array([[0, 0],
           [1, 0],
           [0, 1],
           [1, 1]])
    """
    n = _subset_masks_iv(n)
    k = np.arange(2**n)[:, None]
    return ((k >> np.arange(n)[None, :]) & 1).astype(bool)


def _subset_masks_iv(n) -> int:
    """An integer ``0 <= n <= MAX_GROUND_SET``."""
    n = as_int(n, "n", 0)
    if n > MAX_GROUND_SET:
        raise ValueError(
            f"ground set of {n} elements is too large to enumerate (max {MAX_GROUND_SET})"
        )
    return n


def _sensors_or_empty(sensors) -> np.ndarray:
    arr = as_float_array(sensors, "sensors") if not isinstance(sensors, np.ndarray) else sensors
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
        A fixed known control, appended as the last row of ``O`` (Eq. (5)).
    eps : float
        Prior information added on the diagonal (``>= 0``).

    Returns
    -------
    ndarray, shape (2, 2)

    Examples
    --------
    >>> symmetric_observability_matrix([[0, 0], [2, 0]], [1, 1])
    array([[2., 0.],
           [0., 2.]])
    """
    rows, uu, e = _symmetric_observability_matrix_iv(sensors, target, u, eps)
    O = rows if uu is None else np.vstack([rows, uu])
    return O.T @ O + e * np.eye(2)


def _symmetric_observability_matrix_iv(sensors, target, u, eps) -> tuple:
    """``eps >= 0`` (checked first), the rows ``o - p_i`` (no sensor allowed) and the control
    ``(2,)`` or ``None``: ``(rows, u, eps)``."""
    e = as_eps(eps)
    rows = relative_rows(_sensors_or_empty(sensors), target)
    return rows, None if u is None else as_point(u, "u"), e


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

    Examples
    --------
    >>> measure_from_vectors([[1, 1], [-1, 1]], subset_masks(2), "trace")
    array([0., 2., 2., 4.])
    """
    args = _measure_from_vectors_iv(vectors, masks, name, eps, u, rank_rtol)
    return _measures(*args)[name]


def _measure_from_vectors_iv(vectors, masks, name, eps, u, rank_rtol) -> tuple:
    """One measure name, then :func:`_measures_from_vectors_iv` of it."""
    as_measure_name(name, MEASURES)
    return _measures_from_vectors_iv(vectors, masks, (name,), eps, u, rank_rtol)


def measures_from_vectors(vectors, masks, names=MEASURES, eps: float = 0.0, u=None,
                          rank_rtol: float = RANK_RTOL) -> dict:
    """Several measures of the same subsets at once: ``{name: table}``.

    ``tr``, ``det`` and ``lambda_max`` of ``O^T O`` are computed once and shared by all
    ``names``; each table is bitwise the one :func:`measure_from_vectors` returns for that name
    (it is the same code). Parameters as in :func:`measure_from_vectors`.

    Examples
    --------
    >>> t = measures_from_vectors([[1, 1], [-1, 1]], [[True, True]],
    ...                           ("trace", "rank"))
    >>> t["trace"], t["rank"]
    (array([4.]), array([2.]))
    """
    return _measures(*_measures_from_vectors_iv(vectors, masks, names, eps, u, rank_rtol))


def _measures_from_vectors_iv(vectors, masks, names, eps, u, rank_rtol) -> tuple:
    """The arguments of :func:`_measures`: finite vectors ``(..., N, 2)``, boolean masks
    ``(K, N)``, measure names, ``eps``, ``rank_rtol`` and the controls broadcast to
    ``(..., 2)`` or ``None``."""
    if isinstance(names, str):
        raise ArgumentTypeError(
            f"names must be a sequence of measure names, not the string {names!r}"
        )
    names = as_names(names, "names", MEASURES)
    e = as_eps(eps)
    r = as_rank_rtol(rank_rtol)
    v = as_float_array(vectors, "vectors")
    m = _mask_booleans(masks)
    if v.ndim < 2 or v.shape[-1] != 2:
        raise ValueError(f"vectors must have shape (..., N, 2), got {v.shape}")
    if not np.isfinite(v).all():
        raise ValueError("vectors have a non-finite coordinate")
    _check_mask_shape(m, v.shape[-2])
    uu = None
    if u is not None:
        uu = as_float_array(u, "u")
        if not np.isfinite(uu).all():
            raise ValueError("u has a non-finite coordinate")
        try:
            uu = np.broadcast_to(uu, v.shape[:-2] + (2,))
        except ValueError:
            raise ValueError(
                f"u must have shape (2,) or {v.shape[:-2] + (2,)}, got {uu.shape}"
            ) from None
    return v, m, names, e, r, uu


def _mask_booleans(masks) -> np.ndarray:
    """Subset memberships as booleans (0/1 accepted)."""
    m = np.asarray(masks)
    if m.dtype.kind not in "biuf":
        raise ArgumentTypeError(f"masks must be booleans (or 0/1), got dtype {m.dtype}")
    if m.dtype.kind != "b":
        if not np.isin(m, (0, 1)).all():
            raise ValueError("masks must hold only booleans or 0/1")
        m = m.astype(bool)
    return m


def _check_mask_shape(m: np.ndarray, n: int) -> None:
    if m.ndim != 2 or m.shape[1] != n:
        raise ValueError(f"masks must have shape (K, {n}), got {m.shape}")


def _measures(v: np.ndarray, m: np.ndarray, names, e: float, r: float, uu=None) -> dict:
    """:func:`measures_from_vectors` of validated input: vectors ``v`` ``(..., N, 2)``, boolean
    masks ``m`` ``(K, N)``, measure names, ``eps``, ``rank_rtol`` and the control rows ``uu``
    ``(..., 2)`` or ``None``."""
    if uu is not None:
        v = np.concatenate([v, uu[..., None, :]], axis=-2)
        m = np.concatenate([m, np.ones((m.shape[0], 1), dtype=bool)], axis=1)
    # Scenes outside the safe range are computed in a unit of a power of two (exact) and
    # converted back; the rest exactly as they are. The rank (a ratio) takes the unit from the
    # rows alone; the other measures from the rows and eps (a squared length) together.
    maxabs = np.abs(v).max(axis=(-2, -1), initial=0.0)
    units = {"rank": pow2_scale(maxabs), "other": pow2_scale(np.maximum(maxabs, np.sqrt(e)))}
    cache: dict = {}
    out = {}
    for name in names:
        p = units["rank" if name == "rank" else "other"]
        if (p == 1.0).all():
            if "plain" not in cache:
                cache["plain"] = tr_det(v, m)
            out[name] = measure_from_tr_det(name, *cache["plain"], e, r)
        else:
            key = "rank" if name == "rank" else "other"
            if key not in cache:
                cache[key] = tr_det(v / p[..., None, None], m)
            pp = p[..., None]
            # e / p / p, not e / (p * p): p * p underflows to 0 for p near 2**-1000
            out[name] = measure_from_tr_det(name, *cache[key], e / pp / pp, r, pp)
    return out


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

    Examples
    --------
    >>> measure_table([[0, 0], [2, 0]], [1, 1], "rank")  # {}, {0}, {1}, {0, 1}
    array([0., 1., 1., 2.])
    """
    args = _measure_table_iv(sensors, target, name, eps, u, masks, rank_rtol)
    return _measures(*args)[name]


def _measure_table_iv(sensors, target, name, eps, u, masks, rank_rtol) -> tuple:
    """The arguments of :func:`_measures` for :func:`measure_table`: the rows ``o - p_i``, the
    masks (all subsets by default), ``(name,)``, ``eps``, ``rank_rtol``, the control or
    ``None``."""
    rows = relative_rows(sensors, target)
    if masks is None:
        masks = subset_masks(rows.shape[0])
    uu = None if u is None else as_point(u, "u")
    as_measure_name(name, MEASURES)
    e, r = as_eps(eps), as_rank_rtol(rank_rtol)
    m = _mask_booleans(masks)
    _check_mask_shape(m, rows.shape[0])
    return rows, m, (name,), e, r, uu


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
    >>> measure([[0, 0], [2, 0]], [1, 1], "logdet")  # rows (1, 1), (-1, 1): det 4
    1.3862943611198906
    """
    args = _measure_iv(sensors, target, name, eps, u, rank_rtol)
    return float(_measures(*args)[name][0])


def _measure_iv(sensors, target, name, eps, u, rank_rtol) -> tuple:
    """The arguments of :func:`_measures` for :func:`measure`: the rows ``o - p_i`` (no sensor
    allowed), one mask of them all, ``(name,)``, ``eps``, ``rank_rtol``, the control or
    ``None``."""
    rows = relative_rows(_sensors_or_empty(sensors), target)
    uu = None if u is None else as_point(u, "u")
    as_measure_name(name, MEASURES)
    e, r = as_eps(eps), as_rank_rtol(rank_rtol)
    return rows, np.ones((1, rows.shape[0]), dtype=bool), (name,), e, r, uu

r"""Theorem 1's bound :math:`\omega(S)` for every subset :math:`S` of the sensors, as a table or as
a set function."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ._kernels import pow2_scale, rescale, tr_det
from ._validate import as_point, as_points, as_stack, as_u_max, as_u_max_stack
from .bounds import lower_bound
from .measures import subset_masks
from .observability import relative_rows

__all__ = ["lower_bound_table", "lower_bound_tables", "lower_bound_set_function"]


def _bound_from_tr_det(tr, det, lmax, u2):
    lmin = np.where(lmax > 0, det / np.where(lmax > 0, lmax, 1.0), 0.0)
    den = lmax + u2
    return np.where(den > 0, np.sqrt(np.maximum(lmin, 0.0) / np.where(den > 0, den, 1.0)), 0.0)


def lower_bound_tables(vectors, u_max) -> np.ndarray:
    r"""Theorem 1's bound for all subsets of many instances at once.

    :math:`\sqrt{\lambda_{\min} / (\lambda_{\max} + u_{\max}^2)}` with the eigenvalues of
    :math:`O(o)^T O(o)` from its trace and the Cauchy-Binet determinant (Eqs. (6), (25)); 0 for
    fewer than two sensors. The bound does not depend on the unit of length: each instance is
    first brought into the safe range by a power of two (exact; instances already inside it are
    computed as they are), with its ``u_max`` in the same unit.

    Parameters
    ----------
    vectors : array_like, shape (I, N, 2)
        Rows ``o - p_i`` of each instance.
    u_max : float or array_like, shape (I,)

    Returns
    -------
    ndarray, shape (I, 2**N)

    Examples
    --------
    >>> sensors = np.array([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]])
    >>> target = np.array([1.0, 1.0])
    >>> lower_bound_tables((target - sensors)[None], u_max=1.0).round(4)
    array([[0.    , 0.    , 0.    , 0.8165, 0.    , 0.8165, 0.    , 0.6325]])
    """
    return _lower_bound_tables(*_lower_bound_tables_iv(vectors, u_max))


def _lower_bound_tables_iv(vectors, u_max) -> tuple:
    """Finite rows ``(I, N, 2)`` and ``u_max`` (finite, non-negative) broadcast to ``(I,)``."""
    v = as_stack(vectors, "vectors", 2)
    if v.ndim != 3:
        raise ValueError(f"vectors must have shape (I, N, 2), got {v.shape}")
    return v, as_u_max_stack(u_max, v.shape[:1])


def _lower_bound_tables(v: np.ndarray, u: np.ndarray) -> np.ndarray:
    """:func:`lower_bound_tables` of validated rows ``(I, N, 2)`` and speed bounds ``(I,)``."""
    p = pow2_scale(np.abs(v).max(axis=(1, 2), initial=0.0))  # (I,)
    v, u = rescale(v, p[:, None, None]), rescale(u, p)
    tr, det, lmax = tr_det(v, subset_masks(v.shape[1]))
    with np.errstate(over="ignore"):  # u_max beyond the float range in the rows' unit: bound 0
        u2 = (u**2)[:, None]
    return _bound_from_tr_det(tr, det, lmax, u2)


def lower_bound_table(sensors, target, u_max) -> np.ndarray:
    r"""Theorem 1's bound :math:`\omega(S)` for every subset :math:`S` of ``sensors``, shape
    ``(2**N,)``.

    Vectorised; agrees with :func:`obslib.lower_bound` (SVD) to rounding.

    Examples
    --------
    Table entry ``k`` is the bound of the sensors at the bits of ``k``; adding the third sensor
    lowers it (Theorem 7: the bound is not monotone):

    >>> sensors = np.array([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]])
    >>> lower_bound_table(sensors, [1.0, 1.0], u_max=1.0).round(4)
    array([0.    , 0.    , 0.    , 0.8165, 0.    , 0.8165, 0.    , 0.6325])
    """
    rows, u = _lower_bound_table_iv(sensors, target, u_max)
    return _lower_bound_tables(rows[None], u[None])[0]


def _lower_bound_table_iv(sensors, target, u_max) -> tuple:
    """The rows ``o - p_i`` of the scene (:func:`obslib.observability.relative_rows`) and a
    finite non-negative ``u_max``."""
    return relative_rows(sensors, target), as_u_max(u_max)


def lower_bound_set_function(sensors, target, u_max) -> Callable[[tuple], float]:
    r"""Theorem 1's bound :math:`\omega` as a set function of index tuples, each value by
    :func:`obslib.lower_bound` (SVD).

    Examples
    --------
    >>> omega = lower_bound_set_function([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]],
    ...                                  [1.0, 1.0], 1.0)
    >>> round(omega((0, 1)), 4), round(omega((0, 1, 2)), 4)
    (0.8165, 0.6325)
    """
    s, o, u = _lower_bound_set_function_iv(sensors, target, u_max)

    def omega(idx: tuple) -> float:
        return lower_bound(s[list(idx)].reshape(-1, 2), o, u)

    return omega


def _lower_bound_set_function_iv(sensors, target, u_max) -> tuple:
    """The sensors ``(N, 2)``, the target ``(2,)`` and ``u_max`` of a valid scene (checked as
    :func:`obslib.lower_bound` checks it)."""
    s = as_points(sensors, "sensors")
    _, u = _lower_bound_table_iv(s, target, u_max)
    return s, as_point(target, "target"), float(u)

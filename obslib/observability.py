"""The observability matrix of Section III and its exact inverse condition number.

For ``N`` stationary range sensors at ``p_i`` and a target at ``o`` moving with control
``u_o`` (the system of Eq. (3), measurements ``z_i = 1/2 ||p_i - o||^2``), the local
nonlinear observability matrix reduces to the stacked matrix of Eq. (5)::

    O(o, u_o) = [o - p_1; o - p_2; ...; o - p_N; u_o]        shape (N + 1, 2)

Its inverse condition number ``C^{-1} = sigma_min / sigma_max`` (Eq. (6)) is the
observability measure the paper uses; it needs ``u_o``, which the sensors do not know.
"""

from __future__ import annotations

import numpy as np

from ._validate import as_point, as_points, check_distinct, check_not_on_targets

__all__ = ["observability_matrix", "inverse_condition_number", "relative_rows"]


def relative_rows(sensors, target) -> np.ndarray:
    """Validated rows ``o - p_i`` of the known part ``O(o)`` (appendix, Eq. (12)).

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        Sensor positions ``p_i``; pairwise distinct.
    target : array_like, shape (2,)
        Target position ``o``; no sensor may sit on it.

    Returns
    -------
    ndarray, shape (N, 2)
    """
    s = as_points(sensors, "sensors")
    o = as_point(target, "target")
    check_distinct(s)
    rows = o[None, :] - s
    check_not_on_targets(rows[:, None, :])
    return rows


def observability_matrix(sensors, target, u=None) -> np.ndarray:
    """Stacked observability matrix ``O(o, u_o)`` of Eq. (5).

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        Sensor positions ``p_i`` (distinct, none on the target).
    target : array_like, shape (2,)
        Target position ``o``.
    u : array_like, shape (2,), optional
        Target control input ``u_o``; when given it is the last row.

    Returns
    -------
    ndarray, shape (N, 2) or (N + 1, 2)
        Rows ``o - p_i`` followed by ``u_o``.
    """
    rows = relative_rows(sensors, target)
    if u is None:
        return rows
    return np.vstack([rows, as_point(u, "u")])


#: Up to this many rows the inverse condition number uses the closed form, beyond it the SVD.
CLOSED_FORM_MAX_ROWS = 8


def _inverse_condition(stack: np.ndarray) -> np.ndarray:
    """``sigma_min / sigma_max`` of each ``(m, 2)`` matrix in ``stack`` (..., m, 2).

    For ``G = O^T O`` (2 x 2), ``sigma_min / sigma_max = sqrt(lambda_min / lambda_max)
    = sqrt(det G) / lambda_max`` with ``det G = sum_{k < l} (r_k x r_l)^2`` (Cauchy-Binet: a sum
    of non-negative terms, accurate for nearly parallel rows) and
    ``lambda_max = tr/2 + sqrt((tr/2)^2 - det)`` (no cancellation). For more than
    :data:`CLOSED_FORM_MAX_ROWS` rows the pairs outnumber the SVD's work and the SVD is used.
    A matrix with fewer than two rows has rank < 2, so its ratio is 0.
    """
    m = stack.shape[-2]
    if m < 2:
        return np.zeros(stack.shape[:-2])
    if m > CLOSED_FORM_MAX_ROWS:
        sv = np.linalg.svd(stack, compute_uv=False)
        top = sv[..., 0]
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(top > 0, sv[..., -1] / np.where(top > 0, top, 1.0), 0.0)
    x, y = stack[..., 0], stack[..., 1]
    a, b = np.triu_indices(m, 1)
    cross = x[..., a] * y[..., b] - y[..., a] * x[..., b]
    det = np.einsum("...k,...k->...", cross, cross)
    half = 0.5 * np.einsum("...k,...k->...", x, x) + 0.5 * np.einsum("...k,...k->...", y, y)
    lmax = half + np.sqrt(np.maximum(half * half - det, 0.0))
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.where(lmax > 0, np.sqrt(det) / np.where(lmax > 0, lmax, 1.0), 0.0)


def inverse_condition_number(sensors, target, u=None):
    """Exact inverse condition number ``C^{-1}(O(o, u_o))`` of Eq. (6).

    Computed from the Gram matrix ``O^T O`` in closed form (see ``_inverse_condition``; by SVD
    for more than eight rows); tests hold both paths to ``numpy.linalg.svd``.

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        Sensor positions (distinct, none on the target). ``N = 1`` is allowed.
    target : array_like, shape (2,)
        Target position ``o``.
    u : array_like, shape (2,) or (K, 2), optional
        Control input(s) ``u_o``. A ``(K, 2)`` array evaluates ``K`` controls at once.
        ``None`` means the stationary target (no ``u`` row, the same as ``u = 0``).

    Returns
    -------
    float or ndarray, shape (K,)
        ``sigma_min / sigma_max`` in ``[0, 1]``; 0 when the matrix has rank < 2.
    """
    rows = relative_rows(sensors, target)
    if u is None:
        return float(_inverse_condition(rows))
    uu = np.asarray(u, dtype=float) if not isinstance(u, np.ndarray) else u.astype(float)
    if uu.ndim == 1:
        return float(_inverse_condition(np.vstack([rows, as_point(uu, "u")])))
    uu = as_points(uu, "u")
    stack = np.concatenate(
        [np.broadcast_to(rows, (uu.shape[0],) + rows.shape), uu[:, None, :]], axis=1
    )
    return _inverse_condition(stack)

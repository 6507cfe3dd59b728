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

from ._kernels import gram_parts, inverse_condition, pow2_scale, ratio_from_gram, rescale
from ._validate import (
    as_float_array,
    as_point,
    as_points,
    as_stack,
    check_differences,
    check_distinct,
    check_not_on_targets,
)

__all__ = [
    "observability_matrix",
    "inverse_condition_number",
    "inverse_condition_numbers",
    "inverse_condition_numbers_polar",
    "relative_rows",
]


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

    Examples
    --------
    >>> relative_rows([[0, 0], [2, 0]], [1, 1])
    array([[ 1.,  1.],
           [-1.,  1.]])
    """
    return _relative_rows_iv(sensors, target)


def _relative_rows_iv(sensors, target) -> np.ndarray:
    """The rows ``o - p_i`` of distinct finite sensors and a finite target, none on it, without
    overflow: the canonical form of ``(sensors, target)``."""
    s = as_points(sensors, "sensors")
    o = as_point(target, "target")
    check_distinct(s)
    with np.errstate(over="ignore", invalid="ignore"):
        rows = o[None, :] - s
    check_differences(rows[:, None, :])
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

    Examples
    --------
    >>> observability_matrix([[0, 0], [2, 0]], [1, 1], u=[1, 0])
    array([[ 1.,  1.],
           [-1.,  1.],
           [ 1.,  0.]])
    """
    rows, uu = _observability_matrix_iv(sensors, target, u)
    return rows if uu is None else np.vstack([rows, uu])


def _observability_matrix_iv(sensors, target, u) -> tuple:
    """The rows ``o - p_i`` (:func:`_relative_rows_iv`) and one finite control ``(2,)`` or
    ``None``."""
    return _relative_rows_iv(sensors, target), None if u is None else as_point(u, "u")


def inverse_condition_number(sensors, target, u=None):
    """Exact inverse condition number ``C^{-1}(O(o, u_o))`` of Eq. (6).

    Computed from the Gram matrix ``O^T O`` in closed form (see
    :func:`obslib._kernels.inverse_condition`; by SVD for more than eight rows); tests hold both
    paths to ``numpy.linalg.svd``.

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

    Examples
    --------
    Two orthogonal rows of equal length: ``C^{-1} = 1``; the row ``u = (1, 0)`` makes
    ``O^T O = diag(3, 2)``, so ``C^{-1} = sqrt(2 / 3)``.

    >>> inverse_condition_number([[0, 0], [2, 0]], [1, 1])
    1.0
    >>> round(inverse_condition_number([[0, 0], [2, 0]], [1, 1], u=[1, 0]), 6)
    0.816497

    The answer does not depend on the unit of length:

    >>> c = inverse_condition_number([[0, 0], [2e150, 0]], [1e150, 1e150],
    ...                              u=[1e150, 0])
    >>> round(c, 6)
    0.816497
    """
    rows, uu = _inverse_condition_number_iv(sensors, target, u)
    if uu is None:
        return float(inverse_condition(rows))
    if uu.ndim == 1:
        return float(inverse_condition(np.vstack([rows, uu])))
    stack = np.concatenate(
        [np.broadcast_to(rows, (uu.shape[0],) + rows.shape), uu[:, None, :]], axis=1
    )
    return inverse_condition(stack)


def _inverse_condition_number_iv(sensors, target, u) -> tuple:
    """The rows ``o - p_i`` and ``u``: ``None``, one finite control ``(2,)`` or ``K`` of them
    ``(K, 2)``."""
    rows = _relative_rows_iv(sensors, target)
    if u is None:
        return rows, None
    uu = as_float_array(u, "u")
    return rows, as_point(uu, "u") if uu.ndim == 1 else as_points(uu, "u")


def inverse_condition_numbers(rows, u=None) -> np.ndarray:
    """Batched exact ``C^{-1}(O(o, u_o))`` of Eq. (6) for many scenes and controls at once.

    The same closed form as :func:`inverse_condition_number` (``sqrt(det G) / lambda_max`` of
    ``G = O^T O``, ``det G`` by Cauchy-Binet as a sum of squared cross products, accurate for
    nearly parallel rows), organised for stacks: the sensor-sensor part of the Cauchy-Binet sum
    is computed once per scene and each control adds ``sum_k (r_k x u)^2`` and ``||u||^2``.

    Parameters
    ----------
    rows : array_like, shape (..., N, 2)
        Rows ``o - p_i`` of each scene (validated by the caller, e.g. with
        ``obslib._validate.check_scene_batch``). All-zero rows are allowed as padding: they leave
        ``O^T O`` unchanged, so scenes with different ``N`` can share one array.
    u : array_like, shape (..., K, 2) or (..., 2), optional
        Controls, ``K`` per scene (or one per scene); ``None``: the stationary target.

    Returns
    -------
    ndarray, shape (..., K) or (...)
        ``sigma_min / sigma_max`` in ``[0, 1]``; 0 when the matrix has rank < 2. Equal to
        :func:`inverse_condition_number` to rounding (a test compares them scene by scene).

    Examples
    --------
    >>> inverse_condition_numbers([[[1, 1], [-1, 1]]], [[[1, 0]]]).round(6)
    array([[0.816497]])
    """
    r, uu, single = _inverse_condition_numbers_iv(rows, u)
    p = pow2_scale(np.abs(r).max(axis=(-2, -1), initial=0.0))  # per scene, into the safe range
    if uu is not None:
        if single:
            uu = uu[..., None, :]
        p = np.maximum(p, pow2_scale(np.abs(uu).max(axis=(-2, -1), initial=0.0)))
        uu = rescale(uu, p[..., None, None])
    r = rescale(r, p[..., None, None])
    det, tr = gram_parts(r)
    if uu is not None:
        ux, uy = uu[..., 0][..., None], uu[..., 1][..., None]  # (..., K, 1)
        cu = r[..., None, :, 0] * uy - r[..., None, :, 1] * ux  # (..., K, N): r_k x u
        det = det[..., None] + np.einsum("...k,...k->...", cu, cu)
        tr = tr[..., None] + (uu[..., 0] ** 2 + uu[..., 1] ** 2)
        if single:
            det, tr = det[..., 0], tr[..., 0]
    return ratio_from_gram(det, tr)


def _inverse_condition_numbers_iv(rows, u) -> tuple:
    """Finite rows ``(..., N, 2)``; finite controls ``(..., K, 2)`` or one per scene
    ``(..., 2)`` (then ``single``), or ``None``; their scenes' shapes broadcast together."""
    r = as_stack(rows, "rows", 2)
    if u is None:
        return r, None, False
    uu = as_stack(u, "u", 1)
    single = uu.ndim == r.ndim - 1
    try:
        np.broadcast_shapes(r.shape[:-2], uu.shape[:-1] if single else uu.shape[:-2])
    except ValueError:
        raise ValueError(f"the scenes of rows {r.shape} and u {uu.shape} do not broadcast "
                         "together") from None
    return r, uu, single


def inverse_condition_numbers_polar(rows, radii, angles) -> np.ndarray:
    """Batched exact ``C^{-1}(O(o, u))`` on a polar grid of controls ``u = rho (cos phi, sin phi)``.

    The same closed form as :func:`inverse_condition_numbers`, with the control's Cauchy-Binet
    terms factored as ``sum_k (r_k x u)^2 = rho^2 sum_k (r_k x e_phi)^2``: the sum over sensors is
    done once per direction instead of once per control.

    Parameters
    ----------
    rows : array_like, shape (S, N, 2)
        Rows ``o - p_i`` of each scene, zero rows as padding (as in
        :func:`inverse_condition_numbers`).
    radii : array_like, shape (S, R)
        Control norms ``rho`` of each scene (non-negative).
    angles : array_like, shape (A,)
        Directions ``phi`` shared by all scenes.

    Returns
    -------
    ndarray, shape (S, R, A)

    Examples
    --------
    >>> c = inverse_condition_numbers_polar([[[1, 1], [-1, 1]]], [[0.0, 1.0]],
    ...                                     [0.0])
    >>> c.round(6)
    array([[[1.      ],
            [0.816497]]])
    """
    r, rho, phi = _polar_iv(rows, radii, angles)
    p = np.maximum(pow2_scale(np.abs(r).max(axis=(-2, -1), initial=0.0)),
                   pow2_scale(rho.max(axis=1, initial=0.0)))  # per scene, into the safe range
    r, rho = rescale(r, p[:, None, None]), rescale(rho, p[:, None])
    det0, tr0 = gram_parts(r)
    c = (
        r[:, None, :, 0] * np.sin(phi)[None, :, None]
        - r[:, None, :, 1] * np.cos(phi)[None, :, None]
    )
    q = np.einsum("sak,sak->sa", c, c)  # (S, A): sum_k (r_k x e_phi)^2
    rho2 = (rho * rho)[:, :, None]  # (S, R, 1)
    return ratio_from_gram(det0[:, None, None] + rho2 * q[:, None, :], tr0[:, None, None] + rho2)


def _polar_iv(rows, radii, angles) -> tuple:
    """Finite rows ``(S, N, 2)``, finite non-negative radii ``(S, R)``, finite angles ``(A,)``."""
    r = as_stack(rows, "rows", 2)
    if r.ndim != 3:
        raise ValueError(f"rows must have shape (S, N, 2), got {r.shape}")
    rho = as_float_array(radii, "radii")
    phi = as_float_array(angles, "angles")
    if rho.ndim != 2 or rho.shape[0] != r.shape[0] or phi.ndim != 1:
        raise ValueError(f"need radii (S, R) with S = {r.shape[0]} and angles (A,), got "
                         f"{rho.shape}, {phi.shape}")
    if not (np.isfinite(rho).all() and np.isfinite(phi).all()) or (rho < 0).any():
        raise ValueError("radii must be finite and non-negative, angles finite")
    return r, rho, phi

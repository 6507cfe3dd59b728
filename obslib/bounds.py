"""Theorem 1's lower bound, its two-sensor closed form (Theorem 4) and its worst case.

Theorem 1 bounds the unknown ``C^{-1}(O(o, u_o))`` using only the known part ``O(o)``
(the rows ``o - p_i``) and the speed bound ``u_max`` (Eqs. (21), (22)):

.. math::

    C^{-1}(O(o, u_o)) \\geq
    \\frac{\\sigma_{\\min}(O(o))}{\\sqrt{\\sigma_{\\max}(O(o))^2 + u_{\\max}^2}}
    = \\sqrt{\\frac{\\lambda_{\\min}}{\\lambda_{\\max} + u_{\\max}^2}},

with :math:`\\lambda` the eigenvalues of :math:`O(o)^T O(o)`. For two sensors these
eigenvalues have a closed form (Theorem 4); :func:`pair_bounds` evaluates it for all pairs and
all targets at once, and :func:`pair_bound_polar` is the paper's polar form in ``alpha`` and
``theta_ji``.
"""

from __future__ import annotations

import numpy as np

from ._kernels import normalise, pair_kernel, pow2_scale, rescale
from ._memory import check_weight_memory
from ._validate import (
    as_float_array,
    as_points,
    as_stack,
    as_u_max,
    as_u_max_stack,
    broadcast,
    validated_vectors,
    vectors_between,
)
from .observability import relative_rows

__all__ = [
    "lower_bound",
    "pair_bounds",
    "pair_bound_polar",
    "worst_case_control",
    "relative_vectors",
    "lower_bounds",
    "worst_case_controls",
]


def lower_bound(sensors, target, u_max) -> float:
    """Theorem 1's lower bound on ``C^{-1}(O(o, u_o))`` for any number of sensors.

    Computed by SVD of ``O(o)`` (Eq. (21)): ``sigma_min / sqrt(sigma_max^2 + u_max^2)``.

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        Sensor positions ``p_i`` (distinct, none on the target).
    target : array_like, shape (2,)
        Target position ``o``.
    u_max : float
        Bound on the target's control, ``||u_o|| <= u_max`` (non-negative).

    Returns
    -------
    float
        The bound, in ``[0, 1]``. With fewer than two sensors ``O(o)`` has rank < 2 and the
        bound is 0 (Theorem 2).

    Examples
    --------
    Rows ``(1, 1)`` and ``(-1, 1)``: both singular values are ``sqrt(2)``, so the bound is
    ``sqrt(2) / sqrt(2 + 1)``.

    >>> round(lower_bound([[0, 0], [2, 0]], [1, 1], u_max=1.0), 6)
    0.816497
    >>> lower_bound([[0, 0]], [1, 1], u_max=1.0)  # one sensor: rank 1 (Theorem 2)
    0.0
    """
    rows, u = _lower_bound_iv(sensors, target, u_max)
    return float(_lower_bounds(rows, u))


def _lower_bound_iv(sensors, target, u_max) -> tuple:
    """The rows ``o - p_i`` of the scene (:func:`obslib.observability.relative_rows`) and a
    finite non-negative ``u_max``: the arguments of :func:`lower_bound` and
    :func:`worst_case_control`."""
    return relative_rows(sensors, target), as_u_max(u_max)


def relative_vectors(sensors, targets, cov=None) -> np.ndarray:
    """Validated vectors ``o_l - p_i``, shape ``(N, L, 2)``, optionally rescaled to Mahalanobis
    length.

    With ``cov`` (the target estimate's covariance ``Sigma_l``), each vector keeps its Euclidean
    direction and gets the Mahalanobis length ``d_il = sqrt(v^T Sigma_l^{-1} v)``. Feeding these
    vectors to the Theorem 4 eigenvalues gives exactly the tracking experiments' evaluation:
    ``alpha = d_j / d_i`` and ``u_max^2 / d_i^2`` from Mahalanobis distances, ``theta_ji`` the
    Euclidean angle, as in the published tracking runs.

    Examples
    --------
    >>> relative_vectors([[0, 0], [2, 0]], [[1, 1]]).tolist()
    [[[1.0, 1.0]], [[-1.0, 1.0]]]
    >>> # lengths halved by cov = 4 I
    >>> relative_vectors([[0, 0], [2, 0]], [[1, 1]], cov=4 * np.eye(2)).tolist()
    [[[0.5, 0.5]], [[-0.5, 0.5]]]
    """
    v, unit = _relative_vectors_iv(sensors, targets, cov)
    if cov is None:
        return v
    with np.errstate(over="ignore"):
        out = v * unit[None, :, None]
    if not np.isfinite(out).all():
        l = int(np.flatnonzero(~np.isfinite(out).all(axis=(0, 2)))[0])
        raise ValueError(f"the Mahalanobis lengths to target {l} overflow (cov of target {l} is "
                         "tiny relative to the distances); pair_bounds handles such scales")
    return out


def _relative_vectors_iv(sensors, targets, cov) -> tuple:
    """The validated vectors ``o_l - p_i`` ``(N, L, 2)`` in their units ``(L,)``
    (:func:`obslib._validate.validated_vectors`)."""
    return validated_vectors(sensors, targets, cov)


def pair_bounds(sensors, targets, u_max, cov=None) -> np.ndarray:
    """Theorem 4's bound for every sensor pair and every target, ``W[i, j, l]``.

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        Sensor positions (pairwise distinct).
    targets : array_like, shape (L, 2)
        Target positions (true positions, or estimates ``o_hat`` when ``cov`` is given).
    u_max : float or array_like, shape (L,)
        Control bound, shared or one per target (``u_{o_l, max}``).
    cov : array_like, shape (2, 2) or (L, 2, 2), optional
        Covariance of each target estimate. When given, distances are Mahalanobis as in the
        tracking experiments (see :func:`relative_vectors`); otherwise Euclidean.

    Returns
    -------
    ndarray, shape (N, N, L)
        ``W[i, j, l] = sqrt(lambda_min / (lambda_max + u_max^2))`` for rows
        ``o_l - p_i, o_l - p_j`` (Eq. (9)); symmetric in ``i, j`` and zero on ``i == j``.
        The same for coordinates and ``u_max`` scaled together by any factor (each target's rows
        are normalised before anything is squared).

    Raises
    ------
    ValueError
        For bad input (naming the sensor, target or argument), and, before allocating, when the
        ``(N, N, L)`` array would exceed :data:`obslib._memory.MAX_WEIGHT_BYTES` (1 GiB): the
        message suggests ``greedy_pair_assignment(sensors=..., targets=..., u_max=...)``, which
        computes weights on demand.

    Examples
    --------
    >>> pair_bounds([[0, 0], [2, 0]], [[1, 1]], u_max=1.0).round(6)[:, :, 0]
    array([[0.      , 0.816497],
           [0.816497, 0.      ]])

    Units do not matter (lengths and ``u_max`` scaled together):

    >>> W = pair_bounds([[0, 0], [2e-150, 0]], [[1e-150, 1e-150]], u_max=1e-150)
    >>> W.round(6)[0, 1, 0]
    np.float64(0.816497)
    """
    v, u = _pair_bounds_iv(sensors, targets, u_max, cov)
    return _pair_bounds(v, u)


def _pair_bounds_iv(sensors, targets, u_max, cov) -> tuple:
    """The validated vectors ``(N, L, 2)`` (the ``(N, N, L)`` result within
    :data:`~obslib._memory.MAX_WEIGHT_BYTES`) and the speed bounds ``(L,)`` in their unit."""
    s = as_points(sensors, "sensors")
    t = as_points(targets, "targets")
    check_weight_memory(s.shape[0], t.shape[0])
    v, unit = vectors_between(s, t, cov)  # each input is checked once
    return v, as_u_max(u_max, t.shape[0]) / unit


def _pair_bounds(v: np.ndarray, u) -> np.ndarray:
    """:func:`pair_bounds` of validated vectors ``v`` ``(N, L, 2)`` and speed bounds ``u`` in
    their unit."""
    v, u2 = normalise(v, u)
    x, y = v[..., 0], v[..., 1]  # (N, L)
    return pair_kernel(x[:, None, :], y[:, None, :], x[None, :, :], y[None, :, :], u2)


def pair_bound_polar(alpha, theta, u_over_d):
    """Theorem 4's closed form in polar coordinates (Eq. (9)).

    ``sqrt((1 + a^2 - s) / (1 + a^2 + s + 2 u^2/d^2))`` with
    ``s = sqrt(1 + a^4 + 2 a^2 cos(2 theta))``, ``a = alpha = d_jo / d_io``,
    ``theta = theta_ji`` and ``u/d = u_max / d_io``. Evaluated in the algebraically equal,
    cancellation-free form ``s = hypot(1 - a^2, 2 a cos theta)`` and
    ``1 + a^2 - s = 4 a^2 sin^2 theta / (1 + a^2 + s)``.

    Parameters
    ----------
    alpha : array_like
        Distance ratio, finite and non-negative.
    theta : array_like
        Angle ``theta_j - theta_i`` in radians, finite.
    u_over_d : array_like
        ``u_max / d_io``, finite and non-negative.

    Returns
    -------
    float or ndarray
        The bound, broadcast over the inputs.

    Examples
    --------
    Equal distances, perpendicular directions and ``u_max / d_io = 1 / sqrt(2)`` give the
    same scene as the :func:`pair_bounds` example:

    >>> round(pair_bound_polar(1.0, np.pi / 2, 1 / np.sqrt(2)), 6)
    0.816497
    """
    a, th, q = _pair_bound_polar_iv(alpha, theta, u_over_d)
    # The bound is homogeneous of degree 0 in (d_io, d_jo, u_max) = d_io (1, alpha, u/d): for
    # alpha beyond the safe range, divide all three by a power of two m (exact), so that alpha^2
    # cannot overflow; b = 1/m is then the first length (b = 1 and the plain formula otherwise).
    m = pow2_scale(np.maximum(a, 1.0))
    b = 1.0 / m
    a, q = a / m, q / m
    with np.errstate(over="ignore", under="ignore"):
        a2 = a * a
        b2 = b * b
        s = np.hypot(b2 - a2, 2.0 * b * a * np.cos(th))
        plus = b2 + a2 + s
        minus = 4.0 * a2 * b2 * np.sin(th) ** 2 / plus
        out = np.sqrt(minus / (plus + 2.0 * q * q))
    return float(out) if out.ndim == 0 else out


def _pair_bound_polar_iv(alpha, theta, u_over_d) -> tuple:
    """Finite ``alpha >= 0``, ``theta``, ``u_over_d >= 0``, broadcast to one shape."""
    a, th, q = (as_float_array(x, name) for x, name in
                ((alpha, "alpha"), (theta, "theta"), (u_over_d, "u_over_d")))
    for name, x, nonneg in (("alpha", a, True), ("theta", th, False), ("u_over_d", q, True)):
        if not np.isfinite(x).all():
            raise ValueError(f"{name} must be finite")
        if nonneg and (x < 0).any():
            raise ValueError(f"{name} must be non-negative")
    return tuple(broadcast({"alpha": a, "theta": th, "u_over_d": q}))


def worst_case_control(sensors, target, u_max) -> np.ndarray:
    """A control with ``||u|| = u_max`` at which Theorem 1's bound is attained.

    Along the principal eigenvector ``v_max`` of ``O(o)^T O(o)``, adding the row ``u`` raises
    ``lambda_max`` by exactly ``u_max^2`` and leaves ``lambda_min`` unchanged, so both Weyl
    inequalities of the proof of Theorem 1 hold with equality and
    ``C^{-1}(O(o, u_max v_max)) = lower_bound(...)``. The sign is fixed so that the first
    nonzero component is positive.

    Returns
    -------
    ndarray, shape (2,)

    Examples
    --------
    Rows ``(2, 1)`` and ``(-2, 1)``: ``O^T O = diag(8, 2)``, principal direction ``(1, 0)``.

    >>> worst_case_control([[0, 0], [4, 0]], [2, 1], u_max=1.0)
    array([1., 0.])
    """
    rows, u = _lower_bound_iv(sensors, target, u_max)
    return _worst_case_controls(rows, u)


def lower_bounds(rows, u_max) -> np.ndarray:
    """Theorem 1's bound (Eq. (21)) for a stack of scenes, by batched SVD of ``O(o)``.

    The batched form of :func:`lower_bound`: ``sigma_min / sqrt(sigma_max^2 + u_max^2)`` from
    ``numpy.linalg.svd`` of every ``(N, 2)`` matrix at once.

    Parameters
    ----------
    rows : array_like, shape (..., N, 2)
        Rows ``o - p_i`` of each scene (validated by the caller). All-zero rows are padding:
        they change no singular value, so a scene with one real row gets 0 (Theorem 2).
    u_max : float or array_like, shape (...)
        Speed bound of each scene (non-negative).

    Returns
    -------
    ndarray, shape (...)

    Examples
    --------
    >>> lower_bounds([[[1, 1], [-1, 1]]], 1.0).round(6)
    array([0.816497])
    """
    r, u = _lower_bounds_iv(rows, u_max)
    return _lower_bounds(r, u)


def _lower_bounds_iv(rows, u_max) -> tuple:
    """Finite rows ``(..., N, 2)`` and ``u_max`` (finite, non-negative) broadcast to their
    scenes ``(...)``: the arguments of :func:`lower_bounds` and :func:`worst_case_controls`."""
    r = as_stack(rows, "rows", 2)
    return r, as_u_max_stack(u_max, r.shape[:-2])


def _lower_bounds(r: np.ndarray, u: np.ndarray) -> np.ndarray:
    """:func:`lower_bounds` of validated rows ``r`` and speed bounds ``u`` of shape
    ``r.shape[:-2]``."""
    if r.shape[-2] < 2:
        return np.zeros(r.shape[:-2])
    # the bound does not depend on the unit: bring each scene into the safe range (exact)
    p = pow2_scale(np.abs(r).max(axis=(-2, -1)))
    r, u = rescale(r, p[..., None, None]), rescale(u, p)
    sv = np.linalg.svd(r, compute_uv=False)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        den = np.sqrt(sv[..., 0] ** 2 + u**2)
        return np.where(den > 0, sv[..., -1] / np.where(den > 0, den, 1.0), 0.0)


def worst_case_controls(rows, u_max) -> np.ndarray:
    """:func:`worst_case_control` for a stack of scenes: ``u_max v_max`` of each, shape
    ``(..., 2)``.

    ``v_max`` is the principal eigenvector of ``O(o)^T O(o)`` (``numpy.linalg.eigh`` on the
    stacked 2 x 2 matrices), signed so that its first nonzero component is positive. Zero rows
    (padding) do not change ``O(o)^T O(o)``.

    Examples
    --------
    >>> worst_case_controls([[[2, 1], [-2, 1]]], 1.0)
    array([[1., 0.]])
    """
    r, u = _lower_bounds_iv(rows, u_max)
    return _worst_case_controls(r, u)


def _worst_case_controls(r: np.ndarray, u: np.ndarray) -> np.ndarray:
    """:func:`worst_case_controls` of validated rows ``r`` and speed bounds ``u``
    (``r.shape[:-2]``)."""
    if r.shape[-2]:  # the direction does not depend on the unit: into the safe range (exact)
        r = rescale(r, pow2_scale(np.abs(r).max(axis=(-2, -1)))[..., None, None])
    _, vecs = np.linalg.eigh(np.swapaxes(r, -1, -2) @ r)
    v = vecs[..., :, -1]
    flip = (v[..., 0] < 0) | ((v[..., 0] == 0) & (v[..., 1] < 0))
    return np.where(flip[..., None], -v, v) * u[..., None]

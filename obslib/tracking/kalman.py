"""The extended Kalman filter of the tracking experiments, for one filter or many at once: the
predict and the update of a 2-D position measured by range sensors.

The filter follows filterpy's ``ExtendedKalmanFilter`` (and, in the tests, is held to it): a
random-walk prediction, then a Joseph-form update with the Jacobian and the predicted
measurement evaluated at the predicted estimate. Two measurement models
(:data:`MEASUREMENTS`) are supported:

``"half-squared-range"``
    :math:`h(x) = \\tfrac12 \\lVert x - p \\rVert^2`, Jacobian row :math:`(x - p)^T`: Section V
    of the paper (:func:`~obslib.tracking.half_squared_range`,
    :func:`~obslib.tracking.range_jacobian`);
``"range"``
    :math:`h(x) = \\lVert x - p \\rVert`, Jacobian row :math:`(x - p)^T / \\lVert x - p \\rVert`:
    the authors' later multi-target experiment
    (:func:`~obslib.tracking.euclidean_range`,
    :func:`~obslib.tracking.euclidean_range_jacobian`).

:func:`predict` and :func:`update` take matrices (a state ``(..., 2)``, a covariance
``(..., 2, 2)``, any leading shape for many filters) and check them. The tracking engine calls
the workers behind them directly: the same equations written for 2 x 2 matrices as component
arrays (a state ``x = (x0, x1)`` and a covariance ``P = (p00, p01, p10, p11)``, each entry an
array with one element per filter), so that thousands of filters (runs, targets) advance in one
NumPy operation per entry.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_choice, as_float_array

__all__ = ["MEASUREMENTS", "SINGULAR_RTOL", "SingularInnovation", "predict", "update"]

#: The measurement models of :func:`update`: Section V's half squared range and the range.
MEASUREMENTS = ("half-squared-range", "range")

#: The update stops with :class:`SingularInnovation` when the innovation covariance
#: ``S = H P H^T + R`` is singular to this relative precision: when a pivot of its Cholesky
#: factorisation, the variance of a measurement's innovation given the ones before it, is at
#: most ``SINGULAR_RTOL`` times that measurement's own variance ``S_mm`` (for two measurements,
#: ``det S <= SINGULAR_RTOL * S_00 S_11``); the gain would carry no correct digit.
SINGULAR_RTOL = 1e-13


class SingularInnovation(ValueError):
    """The innovation covariance of some filters is singular in floating point; ``ok`` marks the
    filters (broadcast shape of the update) whose update was regular."""

    def __init__(self, ok):
        self.ok = np.asarray(ok)
        super().__init__("the innovation covariance H P H^T + R is singular in floating point")


def innovation_is_regular(s00, s01, s10, s11):
    """Whether ``S = [[s00, s01], [s10, s11]]`` is invertible to :data:`SINGULAR_RTOL`:
    ``det S > SINGULAR_RTOL * s00 * s11`` (false for NaN and infinite entries).

    Examples
    --------
    >>> bool(innovation_is_regular(2.0, 1.0, 1.0, 2.0))
    True
    >>> bool(innovation_is_regular(1.0, 1.0, 1.0, 1.0 + 1e-15))  # rank 1
    False
    """
    return s00 * s11 - s01 * s10 > SINGULAR_RTOL * (s00 * s11)


# --------------------------------------------------------------------------------------------
# The public, checked forms
# --------------------------------------------------------------------------------------------


def _matrix_iv(value, name: str, shape_tail: tuple, what: str) -> np.ndarray:
    a = as_float_array(value, name)
    k = len(shape_tail)
    if a.ndim < k or a.shape[a.ndim - k:] != shape_tail:
        raise ValueError(f"{name} must have shape {what}, got {a.shape}")
    if not np.isfinite(a).all():
        raise ValueError(f"{name} must be finite")
    return a


def _noise_iv(value, name: str, m: int) -> np.ndarray:
    """A noise covariance: a variance (a number, times the identity) or an ``(m, m)`` matrix,
    symmetric and positive semi-definite."""
    a = as_float_array(value, name)
    if a.ndim == 0:
        a = float(a) * np.eye(m)
    if a.shape != (m, m):
        raise ValueError(f"{name} must be a number or a ({m}, {m}) matrix, got shape {a.shape}")
    if not np.isfinite(a).all():
        raise ValueError(f"{name} must be finite")
    if not np.array_equal(a, a.T):
        raise ValueError(f"{name} must be symmetric")
    if m and np.linalg.eigvalsh(a).min() < -1e-12 * max(np.abs(a).max(), 1e-300):
        raise ValueError(f"{name} must be positive semi-definite")
    return a


def predict(P, Q):
    """Predict with the random walk ``F = I``: the estimate stays, the covariance grows.

    .. math::

        \\hat x^- = \\hat x, \\qquad P^- = P + Q

    Parameters
    ----------
    P : array_like, shape (..., 2, 2)
        The covariances of one filter or many.
    Q : array_like, shape (2, 2) or number
        The process noise (a number means that multiple of the identity), shared.

    Returns
    -------
    ndarray, shape (..., 2, 2)

    Examples
    --------
    >>> predict([[1.0, 0.5], [0.5, 2.0]], [[0.1, 0.0], [0.0, 0.2]]).tolist()
    [[1.1, 0.5], [0.5, 2.2]]
    """
    P = _matrix_iv(P, "P", (2, 2), "(..., 2, 2)")
    Q = _noise_iv(Q, "Q", 2)
    out = predict_entries((P[..., 0, 0], P[..., 0, 1], P[..., 1, 0], P[..., 1, 1]), Q.tolist())
    return np.stack(np.broadcast_arrays(*out), axis=-1).reshape(P.shape)


def update(x, P, sensors, z, R, measurement: str = "half-squared-range"):
    """Update with the measurements ``z`` of the ``sensors`` (filterpy's
    ``ExtendedKalmanFilter.update``, Joseph form).

    With the Jacobian rows :math:`H_m` and the innovations :math:`y_m = z_m - h_m(\\hat x)` of
    the measurement model at the (predicted) estimate:

    .. math::

        \\begin{aligned}
        S &= H P H^T + R, \\qquad K = P H^T S^{-1}, \\qquad \\hat x \\leftarrow \\hat x + K y, \\\\
        P &\\leftarrow (I - K H) P (I - K H)^T + K R K^T.
        \\end{aligned}

    Parameters
    ----------
    x : array_like, shape (..., 2)
        The estimates of one filter or many.
    P : array_like, shape (..., 2, 2)
        Their (predicted) covariances.
    sensors : array_like, shape (..., m, 2)
        The ``m`` sensors that measured each filter's target (``m >= 1``).
    z : array_like, shape (..., m)
        Their measurements.
    R : array_like, shape (m, m) or number
        The measurement noise (a number means that variance for every sensor).
    measurement : {"half-squared-range", "range"}
        The measurement model (:data:`MEASUREMENTS`).

    Returns
    -------
    x, P : ndarray, shapes (..., 2) and (..., 2, 2)
        The updated estimates and covariances (the leading shapes broadcast).

    Raises
    ------
    SingularInnovation
        Where ``S`` is singular for some filter (:data:`SINGULAR_RTOL`); a ``ValueError``.

    Examples
    --------
    At :math:`\\hat x = 0` with sensors :math:`e_1, e_2`, :math:`H = -I`; with :math:`P = I`,
    :math:`R = I`, :math:`S = 2I`, :math:`K = -I/2`:

    >>> eye = [[1.0, 0.0], [0.0, 1.0]]
    >>> x, P = update([0.0, 0.0], eye, [[1.0, 0.0], [0.0, 1.0]], [1.5, 0.5], 1.0)
    >>> x.tolist(), P.tolist()
    ([-0.5, 0.0], [[0.5, 0.0], [0.0, 0.5]])

    With ranges, one sensor at :math:`(3, 4)` seen from the origin gives the row
    :math:`-(0.6, 0.8)`:

    >>> x, P = update([0.0, 0.0], eye, [[3.0, 4.0]], [4.0], 1.0,
    ...               measurement="range")
    >>> x.round(12).tolist(), P.round(12).tolist()
    ([0.3, 0.4], [[0.82, -0.24], [-0.24, 0.68]])
    """
    as_choice(measurement, MEASUREMENTS, "measurement")
    x = _matrix_iv(x, "x", (2,), "(..., 2)")
    P = _matrix_iv(P, "P", (2, 2), "(..., 2, 2)")
    s = _matrix_iv(sensors, "sensors", (2,), "(..., m, 2)")
    if s.ndim < 2 or s.shape[-2] < 1:
        raise ValueError(f"sensors must have shape (..., m, 2) with m >= 1, got {s.shape}")
    m = s.shape[-2]
    z = _matrix_iv(z, "z", (m,), f"(..., {m}) (one per sensor)")
    R = _noise_iv(R, "R", m)
    try:
        lead = np.broadcast_shapes(x.shape[:-1], P.shape[:-2], s.shape[:-2], z.shape[:-1])
    except ValueError:
        raise ValueError(f"the leading shapes of x {x.shape[:-1]}, P {P.shape[:-2]}, sensors "
                         f"{s.shape[:-2]} and z {z.shape[:-1]} do not broadcast") from None
    x, P = np.broadcast_to(x, lead + (2,)), np.broadcast_to(P, lead + (2, 2))
    s, z = np.broadcast_to(s, lead + (m, 2)), np.broadcast_to(z, lead + (m,))
    d = x[..., None, :] - s
    if (d == 0).all(axis=-1).any():
        raise ValueError("sensors: a sensor sits on an estimate, where the Jacobian is undefined")
    if measurement == "half-squared-range" and m == 2:
        (xx, xy), Pc = update_pair_entries(
            (x[..., 0], x[..., 1]), (P[..., 0, 0], P[..., 0, 1], P[..., 1, 0], P[..., 1, 1]),
            (s[..., 0, 0], s[..., 0, 1]), (s[..., 1, 0], s[..., 1, 1]),
            (z[..., 0], z[..., 1]), R.tolist())
        return np.stack([xx, xy], axis=-1), np.stack(Pc, axis=-1).reshape(lead + (2, 2))
    H, h = measurement_rows(x.reshape(-1, 2), s.reshape(-1, m, 2), measurement)
    xn, Pn = update_stacked(x.reshape(-1, 2), P.reshape(-1, 2, 2), H,
                          z.reshape(-1, m) - h, R)
    return xn.reshape(lead + (2,)), Pn.reshape(lead + (2, 2))


# --------------------------------------------------------------------------------------------
# The workers of the tracking engine (no checks)
# --------------------------------------------------------------------------------------------


def measurement_rows(x, sensors, measurement: str):
    """The Jacobian rows ``(G, m, 2)`` and the predicted measurements ``(G, m)`` of the model
    at the estimates ``x`` ``(G, 2)`` for the sensors ``(G, m, 2)``.

    Examples
    --------
    >>> import numpy as np
    >>> x, s = np.zeros((1, 2)), np.array([[[3.0, 4.0]]])
    >>> H, h = measurement_rows(x, s, "range")
    >>> H.tolist(), h.tolist()
    ([[[-0.6, -0.8]]], [[5.0]])
    """
    d = x[:, None, :] - sensors
    sq = d[..., 0] * d[..., 0] + d[..., 1] * d[..., 1]
    if measurement == "half-squared-range":
        return d, 0.5 * sq
    r = np.sqrt(sq)
    return d / r[..., None], r


def predict_entries(P, Q):
    """:func:`predict` on component arrays ``P = (p00, p01, p10, p11)`` and a nested ``Q``.

    Zero off-diagonal entries of ``Q`` are not added (the result is the same number).
    """
    p00, p01, p10, p11 = P
    (q00, q01), (q10, q11) = Q
    if q01 == 0 and q10 == 0:
        return p00 + q00, p01, p10, p11 + q11
    return p00 + q00, p01 + q01, p10 + q10, p11 + q11


def update_pair_entries(x, P, s0, s1, z, R):
    """:func:`update` with two half squared ranges, on component arrays: the sensors ``s0 =
    (s0x, s0y)`` and ``s1``, the measurements ``z = (z0, z1)``, a nested 2 x 2 ``R``. Returns
    the new ``x`` and ``P`` (tuples of component arrays); raises :class:`SingularInnovation`
    where ``S`` is singular (``innovation_is_regular``).

    The Jacobian rows are :math:`H_m = (\\hat x - p_m)^T` and the innovations
    :math:`y_m = z_m - \\tfrac12 \\lVert \\hat x - p_m \\rVert^2`; every 2 x 2 product is written
    out.
    """
    xx, xy = x
    p00, p01, p10, p11 = P
    (r00, r01), (r10, r11) = R
    r_diag = r01 == 0 and r10 == 0  # zero products of K R are exact zeros: skipped
    # Jacobian rows H_m = (xhat - p_m)^T and the innovation
    h0x, h0y, h1x, h1y = xx - s0[0], xy - s0[1], xx - s1[0], xy - s1[1]
    y0 = z[0] - 0.5 * (h0x * h0x + h0y * h0y)
    y1 = z[1] - 0.5 * (h1x * h1x + h1y * h1y)
    # P H^T, S = H P H^T + R, K = P H^T S^-1
    a00, a10 = p00 * h0x + p01 * h0y, p10 * h0x + p11 * h0y
    a01, a11 = p00 * h1x + p01 * h1y, p10 * h1x + p11 * h1y
    s00 = h0x * a00 + h0y * a10 + r00
    s01 = h0x * a01 + h0y * a11
    s10 = h1x * a00 + h1y * a10
    s11 = h1x * a01 + h1y * a11 + r11
    if not r_diag:
        s01, s10 = s01 + r01, s10 + r10
    ok = innovation_is_regular(s00, s01, s10, s11)
    if not np.all(ok):
        raise SingularInnovation(ok)
    det = s00 * s11 - s01 * s10
    i00, i01, i10, i11 = s11 / det, -s01 / det, -s10 / det, s00 / det
    k00, k01 = a00 * i00 + a01 * i10, a00 * i01 + a01 * i11
    k10, k11 = a10 * i00 + a11 * i10, a10 * i01 + a11 * i11
    xx = xx + (k00 * y0 + k01 * y1)
    xy = xy + (k10 * y0 + k11 * y1)
    # Joseph form with A = I - K H
    A00 = 1.0 - (k00 * h0x + k01 * h1x)
    A01 = -(k00 * h0y + k01 * h1y)
    A10 = -(k10 * h0x + k11 * h1x)
    A11 = 1.0 - (k10 * h0y + k11 * h1y)
    b00, b01 = A00 * p00 + A01 * p10, A00 * p01 + A01 * p11
    b10, b11 = A10 * p00 + A11 * p10, A10 * p01 + A11 * p11
    if r_diag:
        e00, e01, e10, e11 = k00 * r00, k01 * r11, k10 * r00, k11 * r11
    else:
        e00, e01 = k00 * r00 + k01 * r10, k00 * r01 + k01 * r11
        e10, e11 = k10 * r00 + k11 * r10, k10 * r01 + k11 * r11
    P = ((b00 * A00 + b01 * A01) + (e00 * k00 + e01 * k01),
         (b00 * A10 + b01 * A11) + (e00 * k10 + e01 * k11),
         (b10 * A00 + b11 * A01) + (e10 * k00 + e11 * k01),
         (b10 * A10 + b11 * A11) + (e10 * k10 + e11 * k11))
    return (xx, xy), P


def _regular(S) -> np.ndarray:
    """Whether each of the stacked ``S`` ``(G, m, m)`` is positive definite to
    :data:`SINGULAR_RTOL`: every pivot of its Cholesky factor, squared, above ``SINGULAR_RTOL``
    times its diagonal entry (false for non-finite entries)."""
    ok = np.isfinite(S).all(axis=(1, 2))
    rows = np.flatnonzero(ok)
    try:
        pivots = {None: np.einsum("gii->gi", np.linalg.cholesky(S[rows])) ** 2}
    except np.linalg.LinAlgError:  # one at a time, to tell which
        pivots = {}
        for g in rows:
            try:
                pivots[g] = np.diag(np.linalg.cholesky(S[g])) ** 2
            except np.linalg.LinAlgError:
                ok[g] = False
    diag = np.einsum("gii->gi", S)
    if None in pivots:
        ok[rows] = (pivots[None] > SINGULAR_RTOL * diag[rows]).all(axis=1)
    else:
        for g, piv in pivots.items():
            ok[g] = bool((piv > SINGULAR_RTOL * diag[g]).all())
    return ok


#: Above this many measurements per filter (and with a measurement noise ``R = r I``), the
#: engine's update computes the gain in its information form (:func:`update_stacked`).
INFORMATION_FORM_ROWS = 8


def update_stacked(x, P, H, y, R):
    """:func:`update` for ``G`` filters of ``m`` measurements each, given their Jacobian rows
    ``H`` ``(G, m, 2)`` and innovations ``y`` ``(G, m)``: estimates ``x`` ``(G, 2)``,
    covariances ``P`` ``(G, 2, 2)``, noise ``R`` ``(m, m)`` (or a number: that variance).
    Returns the new ``x, P``; raises :class:`SingularInnovation` where ``S`` is singular to
    :data:`SINGULAR_RTOL`.

    filterpy's order of operations, as stacked matrix products: ``K = P H^T S^{-1}``, then the
    Joseph form. With more than :data:`INFORMATION_FORM_ROWS` measurements of variance ``r``
    (a number ``R``), the same gain is computed as :math:`K = (P^{-1} + H^T H / r)^{-1} H^T / r`
    (the matrix inversion lemma), with 2 x 2 inverses instead of an ``m x m`` one, and the
    Joseph form follows as before; ``S = H P H^T + r I`` is then positive definite whatever
    ``H``, and only its finiteness is checked.
    """
    m = H.shape[1]
    Ht = np.swapaxes(H, 1, 2)
    if np.ndim(R) == 0 and m > INFORMATION_FORM_ROWS:
        r = float(R)
        with np.errstate(all="ignore"):
            A = np.linalg.inv(P) + (Ht @ H) / r
            K = np.linalg.inv(A) @ Ht / r  # (G, 2, m)
            x = x + (K @ y[:, :, None])[:, :, 0]
            IKH = np.eye(2) - K @ H
            P = (IKH @ P) @ np.swapaxes(IKH, 1, 2) + r * (K @ np.swapaxes(K, 1, 2))
        ok = np.isfinite(x).all(axis=1) & np.isfinite(P).all(axis=(1, 2))
        if not ok.all():
            raise SingularInnovation(ok)
        return x, P
    if np.ndim(R) == 0:
        R = float(R) * np.eye(m)
    PHt = P @ Ht  # (G, 2, m)
    S = H @ PHt + R
    ok = _regular(S)
    if not ok.all():
        raise SingularInnovation(ok)
    K = PHt @ np.linalg.inv(S)  # (G, 2, m)
    x = x + (K @ y[:, :, None])[:, :, 0]
    A = np.eye(2) - K @ H
    P = (A @ P) @ np.swapaxes(A, 1, 2) + (K @ R) @ np.swapaxes(K, 1, 2)
    return x, P

"""The extended Kalman filter of the tracking experiments, for many filters at once: the
predict and the update of a 2-D position measured by the half squared ranges of two sensors.

filterpy's ``predict`` and ``update`` are the model (and, in the tests, the reference): small
functions of the state, written here for 2 x 2 matrices as component arrays, so that thousands of
filters (runs, targets) advance in one NumPy operation per entry. A state is ``x = (x0, x1)``
and a covariance ``P = (p00, p01, p10, p11)``, each entry an array with one element per filter
(any common shape) or a number; the noise matrices ``Q`` and ``R`` are 2 x 2 nested sequences
shared by every filter.

The measurement of sensor ``p`` is :math:`h(x) = \\tfrac12 \\lVert x - p \\rVert^2`
(:func:`~obslib.tracking.half_squared_range`), whose Jacobian row is :math:`(x - p)^T`
(:func:`~obslib.tracking.range_jacobian`).
"""

from __future__ import annotations

import numpy as np

__all__ = ["SINGULAR_RTOL", "SingularInnovation"]

#: The update stops with :class:`SingularInnovation` when the innovation covariance
#: ``S = H P H^T + R`` is singular to this relative precision,
#: ``det S <= SINGULAR_RTOL * S_00 S_11`` (its gain would carry no correct digit); the filterpy
#: engine applies the same test.
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


def predict(P, Q):
    """Predict with the random walk ``F = I``: the estimate stays, the covariance grows.

    .. math::

        \\hat x^- = \\hat x, \\qquad P^- = P + Q

    Zero off-diagonal entries of ``Q`` are not added (the result is the same number).

    Examples
    --------
    >>> predict((1.0, 0.5, 0.5, 2.0), [[0.1, 0.0], [0.0, 0.2]])
    (1.1, 0.5, 0.5, 2.2)
    """
    p00, p01, p10, p11 = P
    (q00, q01), (q10, q11) = Q
    if q01 == 0 and q10 == 0:
        return p00 + q00, p01, p10, p11 + q11
    return p00 + q00, p01 + q01, p10 + q10, p11 + q11


def update(x, P, s0, s1, z, R):
    """Update with the measurements ``z = (z0, z1)`` of the sensors ``s0 = (s0x, s0y)`` and
    ``s1`` (filterpy's ``ExtendedKalmanFilter.update``, Joseph form).

    With the Jacobian rows :math:`H_m = (\\hat x - p_m)^T` and the innovation
    :math:`y_m = z_m - \\tfrac12 \\lVert \\hat x - p_m \\rVert^2`:

    .. math::

        \\begin{aligned}
        S &= H P H^T + R, \\qquad K = P H^T S^{-1}, \\qquad \\hat x \\leftarrow \\hat x + K y, \\\\
        P &\\leftarrow (I - K H) P (I - K H)^T + K R K^T.
        \\end{aligned}

    Returns the new ``x`` and ``P`` (tuples of component arrays). Raises
    :class:`SingularInnovation` when ``S`` is singular for some filter
    (``innovation_is_regular``).

    Examples
    --------
    At :math:`\\hat x = 0` with sensors :math:`e_1, e_2`, :math:`H = -I`; with :math:`P = I`,
    :math:`R = I`, :math:`S = 2I`, :math:`K = -I/2`:

    >>> eye = [[1.0, 0.0], [0.0, 1.0]]
    >>> x, P = update((0.0, 0.0), (1.0, 0.0, 0.0, 1.0), (1.0, 0.0), (0.0, 1.0),
    ...               (1.5, 0.5), eye)
    >>> [float(v) for v in x], [float(v) for v in P]
    ([-0.5, 0.0], [0.5, 0.0, 0.0, 0.5])
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

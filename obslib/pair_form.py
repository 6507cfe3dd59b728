r"""Numerics of the pair closed form (Theorems 4-5): the bound on grids of :math:`(\alpha, \theta)`, its maximiser :math:`\alpha^*`, and Weyl's inequalities for 2x2 matrices.

The symbolic side lives in :mod:`obslib.symbolic`; the audits that compare the two, and the
published figure's grid, in :mod:`obslib.studies.pair_form`; the figures in
:mod:`obslib.viz.pair_form`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._scalars import positive_float, positive_int
from .bounds import pair_bound_polar

__all__ = [
    "fine_grid",
    "bound_surface",
    "GridMax",
    "grid_maximum",
    "stationarity_alpha",
    "maximising_alpha",
    "maximising_alpha_closed",
    "random_symmetric_2x2",
    "weyl_2x2_slacks",
]


def fine_grid(
    alpha_max: float = 5.0, alpha_per_unit: int = 100, theta_quarter: int = 180
) -> tuple[np.ndarray, np.ndarray]:
    """A grid that contains ``alpha = 1`` and ``theta = 0, +-pi/2, +-pi`` exactly.

    ``alpha = k / alpha_per_unit`` for ``k = 0 .. alpha_max * alpha_per_unit`` and
    ``theta = pi (k / (2 m) - 1)`` for ``k = 0 .. 4 m`` with ``m = theta_quarter``.
    """
    amax = positive_float("alpha_max", alpha_max)
    per = positive_int("alpha_per_unit", alpha_per_unit)
    m = positive_int("theta_quarter", theta_quarter)
    n_a = int(np.floor(amax * per + 1e-9)) + 1
    return np.arange(n_a) / per, np.pi * (np.arange(4 * m + 1) / (2 * m) - 1.0)


def bound_surface(alpha, theta, u_max: float = 1.0, d_io: float = 1.0) -> np.ndarray:
    """Theorem 4's bound on the grid ``theta x alpha``: ``Z[k, l] = C^-1(alpha_l, theta_k)``.

    Parameters
    ----------
    alpha, theta : array_like, 1-D
        Grid axes (``alpha >= 0``).
    u_max : float
        Speed bound (non-negative); Fig. 2 uses 1.
    d_io : float
        Distance of sensor i (positive); Fig. 2 uses 1. Only ``u_max / d_io`` matters.

    Returns
    -------
    ndarray, shape (len(theta), len(alpha))
    """
    a = np.asarray(alpha, dtype=float)
    t = np.asarray(theta, dtype=float)
    if a.ndim != 1 or t.ndim != 1 or a.size == 0 or t.size == 0:
        raise ValueError("alpha and theta must be non-empty 1-D arrays")
    u = positive_float("u_max", u_max, allow_zero=True)
    d = positive_float("d_io", d_io)
    A, T = np.meshgrid(a, t)
    return pair_bound_polar(A, T, u / d)


@dataclass(frozen=True)
class GridMax:
    """The largest value on a grid and every grid point within ``atol`` of it."""

    value: float
    points: tuple  #: ``((alpha, theta), ...)`` sorted by theta


def grid_maximum(alpha, theta, Z, atol: float = 1e-12) -> GridMax:
    """Maximum of ``Z`` (shape ``(len(theta), len(alpha))``) and where it is attained."""
    Z = np.asarray(Z, dtype=float)
    a = np.asarray(alpha, dtype=float)
    t = np.asarray(theta, dtype=float)
    if Z.shape != (t.size, a.size):
        raise ValueError(
            f"Z must have shape (len(theta), len(alpha)) = {(t.size, a.size)}, got {Z.shape}"
        )
    top = float(Z.max())
    k, l = np.nonzero(Z >= top - atol)
    pts = tuple(sorted((float(a[j]), float(t[i])) for i, j in zip(k, l)))
    return GridMax(top, tuple(sorted(pts, key=lambda p: p[1])))


# --- Theorem 5: the maximising alpha for a fixed theta -------------------------------------------
def _check_theta_q(theta, u_over_d):
    th = np.asarray(theta, dtype=float)
    q = np.asarray(u_over_d, dtype=float)
    if not np.isfinite(th).all():
        raise ValueError("theta must be finite")
    if not np.isfinite(q).all() or (q < 0).any():
        raise ValueError("u_over_d must be finite and non-negative")
    if (np.abs(np.sin(th)) <= 1e-12).any():
        raise ValueError(
            "theta = 0 or pi (mod 2 pi): the bound is 0 for every alpha, so there is no maximiser"
        )
    return np.broadcast_arrays(th, q)


def stationarity_alpha(alpha, theta, u_over_d):
    """Eq. (34): ``g = (1 - a^2)(1 - cos 2 theta) + q^2 (S - (a^2 + cos 2 theta))``, evaluated
    without cancellation.

    ``d C^-1 / d alpha`` has the sign of ``g`` (see :func:`obslib.symbolic.dbound_dalpha_closed`).
    Uses ``1 - cos 2 theta = 2 sin^2 theta`` and, since ``S^2 - (a^2 + c)^2 = sin^2 2 theta``,
    ``S - (a^2 + c) = sin^2(2 theta) / (S + a^2 + c)`` where ``a^2 + c > 0`` (the direct difference
    elsewhere).
    """
    a = np.asarray(alpha, dtype=float)
    th = np.asarray(theta, dtype=float)
    q = np.asarray(u_over_d, dtype=float)
    if not (np.isfinite(a).all() and np.isfinite(th).all() and np.isfinite(q).all()):
        raise ValueError("alpha, theta and u_over_d must be finite")
    if (a < 0).any() or (q < 0).any():
        raise ValueError("alpha and u_over_d must be non-negative")
    a2 = a * a
    c = np.cos(2 * th)
    s = np.hypot(1.0 - a2, 2.0 * a * np.cos(th))
    plus = a2 + c
    with np.errstate(divide="ignore", invalid="ignore"):
        safe = np.where(plus > 0, plus, 1.0)
        gap = np.where(plus > 0, np.sin(2 * th) ** 2 / (s + safe), s - plus)
    return (1.0 - a2) * 2.0 * np.sin(th) ** 2 + q * q * gap


def maximising_alpha(theta, u_over_d, xtol: float = 1e-14):
    """The ``alpha`` maximising Theorem 4's bound for a fixed ``theta``, solved numerically.

    Solves Eq. (34) (:func:`stationarity_alpha`) by bisection, for all ``theta`` at once.
    ``g(1) >= 0`` and ``g < 0`` for large ``alpha``, and ``g > 0`` on ``(0, 1)``, so the root is
    the unique maximiser and lies in ``[1, inf)`` (the bound is 0 at ``alpha = 0`` and tends to 0
    as ``alpha -> inf``). The bracket ``[1, 2^k]`` is doubled until ``g < 0`` at its top, then
    halved until it is narrower than ``xtol + 4 eps alpha`` (or cannot shrink in floating point).
    Bisection needs no derivative and cannot leave the bracket; it is independent of the closed
    form :func:`maximising_alpha_closed` it is compared with.

    Parameters
    ----------
    theta : array_like
        ``theta_ji``, not a multiple of ``pi`` (where the bound is 0 for every ``alpha``).
    u_over_d : array_like
        ``u_max / d_io``, non-negative.
    xtol : float
        Absolute tolerance on ``alpha*``.

    Returns
    -------
    float or ndarray
        ``alpha*``; exactly 1 when ``u_over_d = 0`` or ``cos theta = 0``.
    """
    th, q = _check_theta_q(theta, u_over_d)
    th, q = np.broadcast_arrays(th, q)
    shape = th.shape
    th, q = th.ravel(), q.ravel()
    out = np.ones(th.size)
    inner = stationarity_alpha(np.ones(th.size), th, q) > 0.0  # else alpha* = 1
    th, q = th[inner], q[inner]
    lo, hi = np.ones(th.size), np.full(th.size, 2.0)
    up = stationarity_alpha(hi, th, q) > 0.0
    while up.any():  # double the bracket where g is still positive at its top
        lo[up], hi[up] = hi[up], 2.0 * hi[up]
        up[up] = stationarity_alpha(hi[up], th[up], q[up]) > 0.0
    eps = np.finfo(float).eps
    for _ in range(2100):  # bounds the float halvings of any bracket
        mid = 0.5 * (lo + hi)
        live = (hi - lo > xtol + 4 * eps * mid) & (mid > lo) & (mid < hi)
        if not live.any():
            break
        pos = stationarity_alpha(mid[live], th[live], q[live]) > 0.0
        idx = np.flatnonzero(live)
        lo[idx[pos]], hi[idx[~pos]] = mid[idx[pos]], mid[idx[~pos]]
    out[inner] = 0.5 * (lo + hi)
    out = out.reshape(shape)
    return float(out) if out.ndim == 0 else out


def maximising_alpha_closed(theta, u_over_d):
    """Closed form of the maximiser (derived in :func:`obslib.symbolic.alpha_star_squared`)::

        alpha* = sqrt(r (r sin^2 theta + q^2 |cos theta|) / (q^2 + sin^2 theta)),
        r = sqrt(1 + q^2)

    Same domain as :func:`maximising_alpha`.
    """
    th, q = _check_theta_q(theta, u_over_d)
    r = np.sqrt(1.0 + q * q)
    s2 = np.sin(th) ** 2
    out = np.sqrt(r * (r * s2 + q * q * np.abs(np.cos(th))) / (q * q + s2))
    return float(out) if out.ndim == 0 else out


# --- Theorem 1: Weyl step for 2x2 symmetric matrices -----------------------------------------
def random_symmetric_2x2(n: int, seed: int, psd: bool = False) -> np.ndarray:
    """``n`` random symmetric 2x2 matrices (shape ``(n, 2, 2)``) at scales 1e-3 .. 1e3.

    With ``psd=True`` they are Gram matrices ``R^T R`` (as ``O(o)^T O(o)`` and ``u u^T``); a
    quarter of those are rank one (a single row, like ``u u^T``).
    """
    n = positive_int("n", n)
    rng = np.random.default_rng(seed)
    scale = 10.0 ** rng.uniform(-3, 3, size=(n, 1, 1))
    if not psd:
        m = rng.normal(size=(n, 2, 2))
        return scale * (m + np.swapaxes(m, 1, 2)) / 2
    rows = rng.normal(size=(n, 3, 2))
    rows[: n // 4, 1:] = 0.0
    return scale * np.einsum("nki,nkj->nij", rows, rows)


def weyl_2x2_slacks(X, Y) -> dict[str, np.ndarray]:
    """Slack of each Weyl inequality of Eq. (18) for batches of symmetric 2x2 ``X``, ``Y``.

    Eigenvalues ascending (``numpy.linalg.eigvalsh``). Keys as in
    :func:`obslib.symbolic.weyl_2x2_slacks`; each value is ``rhs - lhs`` oriented so that the
    inequality holds iff the slack is ``>= 0``. Also ``"ratio"``: the slack of Eq. (19),
    ``l1(X+Y)/l2(X+Y) - (l1 X + l1 Y)/(l2 X + l2 Y)``, for positive semidefinite inputs with
    ``l2(X) + l2(Y) > 0`` (NaN elsewhere).
    """
    X = np.asarray(X, dtype=float)
    Y = np.asarray(Y, dtype=float)
    if X.shape != Y.shape or X.ndim < 2 or X.shape[-2:] != (2, 2):
        raise ValueError(
            f"X and Y must have the same shape (..., 2, 2), got {X.shape} and {Y.shape}"
        )
    if not (np.isfinite(X).all() and np.isfinite(Y).all()):
        raise ValueError("X and Y must be finite")
    if not (np.allclose(X, np.swapaxes(X, -1, -2)) and np.allclose(Y, np.swapaxes(Y, -1, -2))):
        raise ValueError("X and Y must be symmetric")
    x = np.linalg.eigvalsh(X)
    y = np.linalg.eigvalsh(Y)
    s = np.linalg.eigvalsh(X + Y)
    x1, x2, y1, y2, s1, s2 = x[..., 0], x[..., 1], y[..., 0], y[..., 1], s[..., 0], s[..., 1]
    out = {
        "l1 >= l1+l1": s1 - (x1 + y1),
        "l1 <= l1+l2": (x1 + y2) - s1,
        "l1 <= l2+l1": (x2 + y1) - s1,
        "l2 <= l2+l2": (x2 + y2) - s2,
        "l2 >= l1+l2": s2 - (x1 + y2),
        "l2 >= l2+l1": s2 - (x2 + y1),
    }
    psd = (x1 >= 0) & (y1 >= 0) & (x2 + y2 > 0)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = s1 / s2 - (x1 + y1) / (x2 + y2)
    out["ratio"] = np.where(psd, ratio, np.nan)
    return out

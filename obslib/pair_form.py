r"""Numerics of the pair closed form (Theorems 4-5): the bound on grids of :math:`(\alpha, \theta)`,
its maximiser :math:`\alpha^*`, and Weyl's inequalities for 2x2 matrices.

The symbolic side lives in :mod:`obslib.symbolic`; the audits that compare the two, and the
published figure's grid, in :mod:`obslib.studies.pair_closed_form`; the figures in
:mod:`obslib.viz.pair_closed_form`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._validate import as_bool, as_float_array, as_int, as_nonnegative, as_positive, broadcast
from .bounds import pair_bound_polar

__all__ = [
    "fine_grid",
    "bound_surface",
    "GridMax",
    "grid_maximum",
    "stationarity_alpha",
    "dbound_dalpha",
    "maximising_alpha",
    "maximising_alpha_closed",
    "random_symmetric_2x2",
    "weyl_2x2_slacks",
]


def fine_grid(
    alpha_max: float = 5.0, alpha_per_unit: int = 100, theta_quarter: int = 180
) -> tuple[np.ndarray, np.ndarray]:
    r"""A grid of :math:`(\alpha, \theta)` that contains :math:`\alpha = 1` and :math:`\theta = 0,
    \pm\pi/2, \pm\pi` exactly.

    :math:`\alpha = k / a` for :math:`k = 0, \dots, \lfloor \alpha_{\max} a \rfloor` with
    :math:`a` = ``alpha_per_unit``, and :math:`\theta = \pi (k / (2 m) - 1)` for
    :math:`k = 0, \dots, 4 m` with :math:`m` = ``theta_quarter``.

    Returns
    -------
    alpha, theta : ndarray

    Examples
    --------
    >>> alpha, theta = fine_grid(alpha_max=1.0, alpha_per_unit=2, theta_quarter=1)
    >>> alpha
    array([0. , 0.5, 1. ])
    >>> theta / np.pi
    array([-1. , -0.5,  0. ,  0.5,  1. ])
    """
    amax, per, m = _fine_grid_iv(alpha_max, alpha_per_unit, theta_quarter)
    n_a = int(np.floor(amax * per + 1e-9)) + 1
    return np.arange(n_a) / per, np.pi * (np.arange(4 * m + 1) / (2 * m) - 1.0)


def _fine_grid_iv(alpha_max, alpha_per_unit, theta_quarter) -> tuple:
    """A positive ``alpha_max`` and two counts of at least 1."""
    return (as_positive(alpha_max, "alpha_max"), as_int(alpha_per_unit, "alpha_per_unit", 1),
            as_int(theta_quarter, "theta_quarter", 1))


def bound_surface(alpha, theta, u_max: float = 1.0, d_io: float = 1.0) -> np.ndarray:
    r"""Theorem 4's bound (Eq. (9)) on the grid :math:`\theta \times \alpha`: ``Z[k, l]`` is
    :math:`\underline{C}^{-1}(\alpha_l, \theta_k)`.

    Parameters
    ----------
    alpha, theta : array_like, 1-D
        Grid axes (:math:`\alpha \ge 0`).
    u_max : float
        Speed bound (non-negative); Fig. 2 uses 1.
    d_io : float
        Distance of sensor :math:`i` (positive); Fig. 2 uses 1. Only :math:`u_{\max} / d_{io}`
        matters.

    Returns
    -------
    ndarray, shape (len(theta), len(alpha))

    Examples
    --------
    >>> Z = bound_surface([0.0, 1.0, 2.0], [0.0, np.pi / 2], u_max=1.0, d_io=1.0)
    >>> Z.round(4)
    array([[0.    , 0.    , 0.    ],
           [0.    , 0.7071, 0.4472]])
    """
    a, t, u, d = _bound_surface_iv(alpha, theta, u_max, d_io)
    A, T = np.meshgrid(a, t)
    return pair_bound_polar(A, T, u / d)


def _bound_surface_iv(alpha, theta, u_max, d_io) -> tuple:
    """Non-empty 1-D axes, ``u_max >= 0`` and ``d_io > 0`` (the axes' values are checked by
    :func:`obslib.pair_bound_polar`)."""
    a = as_float_array(alpha, "alpha")
    t = as_float_array(theta, "theta")
    if a.ndim != 1 or t.ndim != 1 or a.size == 0 or t.size == 0:
        raise ValueError("alpha and theta must be non-empty 1-D arrays")
    return a, t, as_nonnegative(u_max, "u_max"), as_positive(d_io, "d_io")


@dataclass(frozen=True)
class GridMax:
    """The largest value on a grid and every grid point within ``atol`` of it."""

    value: float
    points: tuple  #: ``((alpha, theta), ...)`` sorted by theta


def grid_maximum(alpha, theta, Z, atol: float = 1e-12) -> GridMax:
    r"""Maximum of ``Z`` (shape ``(len(theta), len(alpha))``) and every grid point within ``atol``
    of it.

    Examples
    --------
    >>> alpha, theta = fine_grid(alpha_max=2.0, alpha_per_unit=1, theta_quarter=2)
    >>> m = grid_maximum(alpha, theta, bound_surface(alpha, theta))
    >>> round(m.value, 6), [(a, round(t / np.pi, 6)) for a, t in m.points]
    (0.707107, [(1.0, -0.5), (1.0, 0.5)])
    """
    a, t, Z, atol = _grid_maximum_iv(alpha, theta, Z, atol)
    top = float(Z.max())
    k, l = np.nonzero(Z >= top - atol)
    pts = tuple(sorted((float(a[j]), float(t[i])) for i, j in zip(k, l)))
    return GridMax(top, tuple(sorted(pts, key=lambda p: p[1])))


def _grid_maximum_iv(alpha, theta, Z, atol) -> tuple:
    """Finite 1-D axes, a finite non-empty ``Z`` of shape ``(len(theta), len(alpha))`` and
    ``atol >= 0``."""
    Z = as_float_array(Z, "Z")
    a = as_float_array(alpha, "alpha")
    t = as_float_array(theta, "theta")
    if Z.shape != (t.size, a.size) or a.ndim != 1 or t.ndim != 1 or not Z.size:
        raise ValueError(
            f"Z must have shape (len(theta), len(alpha)) = {(t.size, a.size)}, got {Z.shape}"
        )
    for name, x in (("alpha", a), ("theta", t), ("Z", Z)):
        if not np.isfinite(x).all():
            raise ValueError(f"{name} must be finite")
    return a, t, Z, as_nonnegative(atol, "atol")


# --- Theorem 5: the maximising alpha for a fixed theta -------------------------------------------
def _theta_q_iv(theta, u_over_d):
    """Finite ``theta``, not a multiple of pi, and finite ``u_over_d >= 0``, broadcast
    together: the arguments of :func:`maximising_alpha_closed`."""
    th = as_float_array(theta, "theta")
    q = as_float_array(u_over_d, "u_over_d")
    if not np.isfinite(th).all():
        raise ValueError("theta must be finite")
    if not np.isfinite(q).all() or (q < 0).any():
        raise ValueError("u_over_d must be finite and non-negative")
    if (np.abs(np.sin(th)) <= 1e-12).any():
        raise ValueError(
            "theta = 0 or pi (mod 2 pi): the bound is 0 for every alpha, so there is no maximiser"
        )
    return broadcast({"theta": th, "u_over_d": q})


def _alpha_theta_q_iv(alpha, theta, u_over_d) -> list:
    """Finite ``alpha >= 0``, ``theta`` and ``u_over_d >= 0``, broadcast together."""
    a = as_float_array(alpha, "alpha")
    th = as_float_array(theta, "theta")
    q = as_float_array(u_over_d, "u_over_d")
    if not (np.isfinite(a).all() and np.isfinite(th).all() and np.isfinite(q).all()):
        raise ValueError("alpha, theta and u_over_d must be finite")
    if (a < 0).any() or (q < 0).any():
        raise ValueError("alpha and u_over_d must be non-negative")
    return broadcast({"alpha": a, "theta": th, "u_over_d": q})


def stationarity_alpha(alpha, theta, u_over_d):
    r"""Eq. (34), the numerator of :math:`\partial \underline{C}^{-1} / \partial \alpha`, evaluated
    without cancellation.

    .. math::

       g = (1 - \alpha^2)(1 - \cos 2\theta) + q^2 \bigl(S - (\alpha^2 + \cos 2\theta)\bigr),
       \qquad S = \sqrt{1 + \alpha^4 + 2 \alpha^2 \cos 2\theta},

    with :math:`q = u_{\max} / d_{io}`; :math:`\partial \underline{C}^{-1} / \partial \alpha` has
    the sign of :math:`g` (see :func:`obslib.symbolic.dbound_dalpha_closed`). Uses
    :math:`1 - \cos 2\theta = 2 \sin^2\theta` and, since
    :math:`S^2 - (\alpha^2 + c)^2 = \sin^2 2\theta` with :math:`c = \cos 2\theta`,
    :math:`S - (\alpha^2 + c) = \sin^2(2\theta) / (S + \alpha^2 + c)` where
    :math:`\alpha^2 + c > 0` (the direct difference elsewhere).

    Examples
    --------
    The bound still rises at :math:`\alpha = 1` and falls at :math:`\alpha = 2`
    (:math:`\theta = \pi/4`, :math:`q = 1`):

    >>> for a in (1.0, 2.0):
    ...     print(round(stationarity_alpha(a, np.pi / 4, 1.0), 6))
    0.414214
    -2.876894
    """
    return _stationarity(*_alpha_theta_q_iv(alpha, theta, u_over_d))


def _stationarity(a: np.ndarray, th: np.ndarray, q: np.ndarray) -> np.ndarray:
    """:func:`stationarity_alpha` of validated arrays (the bisection's inner step)."""
    a2 = a * a
    c = np.cos(2 * th)
    s = np.hypot(1.0 - a2, 2.0 * a * np.cos(th))
    plus = a2 + c
    with np.errstate(divide="ignore", invalid="ignore"):
        safe = np.where(plus > 0, plus, 1.0)
        gap = np.where(plus > 0, np.sin(2 * th) ** 2 / (s + safe), s - plus)
    return (1.0 - a2) * 2.0 * np.sin(th) ** 2 + q * q * gap


def dbound_dalpha(alpha, theta, u_over_d):
    r"""The derivative :math:`\partial \underline{C}^{-1} / \partial \alpha` of Theorem 4's
    pair bound (Eq. (9)), evaluated without cancellation.

    With :math:`s = \sin^2\theta`, :math:`S = \sqrt{1 + \alpha^4 + 2\alpha^2 \cos 2\theta}`,
    :math:`P = 1 + \alpha^2 + S` and :math:`D = P + 2q^2`, :math:`q = u_{\max}/d_{io}`, the
    numerator of Eq. (9) is :math:`1 + \alpha^2 - S = 4\alpha^2 s / P`, so the bound is
    :math:`C = 2\alpha\sqrt{s} / \sqrt{P D}` and

    .. math::

       \frac{\partial C}{\partial \alpha} = \frac{2\sqrt{s}}{\sqrt{P D}}
       \Bigl(1 - \frac{\alpha P' (P + D)}{2 P D}\Bigr), \qquad
       P' = 2\alpha + \frac{2\alpha^3 + 2\alpha \cos 2\theta}{S}.

    At :math:`\alpha = 0` it is :math:`\lvert\sin\theta\rvert / \sqrt{1 + q^2}`, the slope
    from the right (the bound is :math:`0` there).

    Parameters
    ----------
    alpha : array_like
        Distance ratios :math:`d_{jo}/d_{io} \ge 0`.
    theta : array_like
        Angles :math:`\theta_{ji}`.
    u_over_d : array_like
        :math:`q = u_{\max}/d_{io} \ge 0`; the three broadcast together.

    Returns
    -------
    ndarray

    Examples
    --------
    The bound rises at :math:`\alpha = 0` and falls at :math:`\alpha = 2`
    (:math:`\theta = \pi/4`, :math:`q = 1`):

    >>> print(np.round(dbound_dalpha([0.0, 2.0], np.pi / 4, 1.0), 6))
    [ 0.5      -0.080343]
    """
    a, th, q = _alpha_theta_q_iv(alpha, theta, u_over_d)
    c = np.cos(2 * th)
    S = np.hypot(1.0 - a * a, 2.0 * a * np.cos(th))  # sqrt(1 + a^4 + 2 a^2 cos 2 theta)
    P = 1.0 + a * a + S
    D = P + 2.0 * q * q
    with np.errstate(divide="ignore", invalid="ignore"):  # S = 0 only at alpha = 1, cos = 0
        dP = 2.0 * a + np.where(S > 0, (2.0 * a**3 + 2.0 * a * c) / np.where(S > 0, S, 1.0),
                                np.nan)
    return 2.0 * np.abs(np.sin(th)) / np.sqrt(P * D) * (1.0 - a * dP * (P + D) / (2.0 * P * D))


def maximising_alpha(theta, u_over_d, xtol: float = 1e-14):
    r"""The :math:`\alpha^*` maximising Theorem 4's bound for a fixed :math:`\theta`, solved
    numerically.

    Solves Eq. (34) (:func:`stationarity_alpha`) by bisection, for all :math:`\theta` at once.
    :math:`g(1) \ge 0` and :math:`g < 0` for large :math:`\alpha`, and :math:`g > 0` on
    :math:`(0, 1)`, so the root is the unique maximiser and lies in :math:`[1, \infty)` (the bound
    is 0 at :math:`\alpha = 0` and tends to 0 as :math:`\alpha \to \infty`). The bracket
    :math:`[1, 2^k]` is doubled until :math:`g < 0` at its top, then halved until it is narrower
    than :math:`x_{tol} + 4 \varepsilon \alpha` (or cannot shrink in floating point). Bisection
    needs no derivative and cannot leave the bracket; it is independent of the closed form
    :func:`maximising_alpha_closed` it is compared with.

    Parameters
    ----------
    theta : array_like
        :math:`\theta_{ji}`, not a multiple of :math:`\pi` (where the bound is 0 for every
        :math:`\alpha`).
    u_over_d : array_like
        :math:`u_{\max} / d_{io}`, non-negative.
    xtol : float
        Absolute tolerance on :math:`\alpha^*`.

    Returns
    -------
    float or ndarray
        :math:`\alpha^*`; 1 when :math:`u_{\max} / d_{io} = 0` or :math:`\cos\theta = 0`.

    Examples
    --------
    >>> round(maximising_alpha(np.pi / 4, 1.0), 10)
    1.1547005384
    >>> maximising_alpha([np.pi / 4, np.pi / 2], 0.0)
    array([1., 1.])
    """
    th, q, xtol = _maximising_alpha_iv(theta, u_over_d, xtol)
    shape = th.shape
    th, q = th.ravel(), q.ravel()
    out = np.ones(th.size)
    # theta and q checked once above; the bisection's own alphas are finite and >= 1
    inner = _stationarity(np.ones(th.size), th, q) > 0.0  # else alpha* = 1
    th, q = th[inner], q[inner]
    lo, hi = np.ones(th.size), np.full(th.size, 2.0)
    up = _stationarity(hi, th, q) > 0.0
    while up.any():  # double the bracket where g is still positive at its top
        lo[up], hi[up] = hi[up], 2.0 * hi[up]
        up[up] = _stationarity(hi[up], th[up], q[up]) > 0.0
    eps = np.finfo(float).eps
    for _ in range(2100):  # bounds the float halvings of any bracket
        mid = 0.5 * (lo + hi)
        live = (hi - lo > xtol + 4 * eps * mid) & (mid > lo) & (mid < hi)
        if not live.any():
            break
        pos = _stationarity(mid[live], th[live], q[live]) > 0.0
        idx = np.flatnonzero(live)
        lo[idx[pos]], hi[idx[~pos]] = mid[idx[pos]], mid[idx[~pos]]
    out[inner] = 0.5 * (lo + hi)
    out = out.reshape(shape)
    return float(out) if out.ndim == 0 else out


def _maximising_alpha_iv(theta, u_over_d, xtol) -> tuple:
    """:func:`_theta_q_iv`, and a positive ``xtol``."""
    th, q = _theta_q_iv(theta, u_over_d)
    return th, q, as_positive(xtol, "xtol")


def maximising_alpha_closed(theta, u_over_d):
    r"""Closed form of the maximiser :math:`\alpha^*` (derived in
    :func:`obslib.symbolic.alpha_star_squared`).

    .. math::

       \alpha^* = \sqrt{\frac{r (r \sin^2\theta + q^2 |\cos\theta|)}{q^2 + \sin^2\theta}},
       \qquad r = \sqrt{1 + q^2}, \quad q = u_{\max} / d_{io}.

    Same domain as :func:`maximising_alpha`.

    Examples
    --------
    >>> round(maximising_alpha_closed(np.pi / 4, 1.0), 10)
    1.1547005384
    """
    th, q = _theta_q_iv(theta, u_over_d)
    r = np.sqrt(1.0 + q * q)
    s2 = np.sin(th) ** 2
    out = np.sqrt(r * (r * s2 + q * q * np.abs(np.cos(th))) / (q * q + s2))
    return float(out) if out.ndim == 0 else out


# --- Theorem 1: Weyl step for 2x2 symmetric matrices -----------------------------------------
def random_symmetric_2x2(n: int, seed: int, psd: bool = False) -> np.ndarray:
    r"""``n`` random symmetric 2x2 matrices (shape ``(n, 2, 2)``) at scales :math:`10^{-3}` to
    :math:`10^3`.

    With ``psd=True`` they are Gram matrices :math:`R^T R` (as :math:`O(o)^T O(o)` and
    :math:`u u^T`); a quarter of those are rank one (a single row, like :math:`u u^T`).

    Examples
    --------
    >>> X = random_symmetric_2x2(100, seed=0, psd=True)
    >>> X.shape, bool(np.allclose(X, X.transpose(0, 2, 1)))
    ((100, 2, 2), True)
    >>> bool((np.linalg.eigvalsh(X)[:, 0] >= -1e-9 * np.abs(X).max()).all())
    True
    """
    n, seed, psd = _random_symmetric_2x2_iv(n, seed, psd)
    rng = np.random.default_rng(seed)
    scale = 10.0 ** rng.uniform(-3, 3, size=(n, 1, 1))
    if not psd:
        m = rng.normal(size=(n, 2, 2))
        return scale * (m + np.swapaxes(m, 1, 2)) / 2
    rows = rng.normal(size=(n, 3, 2))
    rows[: n // 4, 1:] = 0.0
    return scale * np.einsum("nki,nkj->nij", rows, rows)


def _random_symmetric_2x2_iv(n, seed, psd) -> tuple:
    """A count of at least 1, a seed (an integer >= 0) and a flag."""
    return as_int(n, "n", 1), as_int(seed, "seed", 0), as_bool(psd, "psd")


def weyl_2x2_slacks(X, Y) -> dict[str, np.ndarray]:
    r"""Slack of each Weyl inequality of Eq. (18) for batches of symmetric 2x2 ``X``, ``Y``.

    Eigenvalues ascending (``numpy.linalg.eigvalsh``). Keys as in
    :func:`obslib.symbolic.weyl_2x2_slacks`; each value is the right-hand side minus the left-hand
    side, oriented so that the inequality holds iff the slack is :math:`\ge 0`. Also ``"ratio"``:
    the slack of Eq. (19),
    :math:`\lambda_1(X+Y)/\lambda_2(X+Y) - (\lambda_1(X) + \lambda_1(Y))/(\lambda_2(X) +
    \lambda_2(Y))`, for positive semidefinite inputs with :math:`\lambda_2(X) + \lambda_2(Y) >
    0` (NaN elsewhere).

    Examples
    --------
    >>> s = weyl_2x2_slacks(np.diag([1.0, 3.0]), np.diag([2.0, 0.0]))
    >>> for k, v in s.items():
    ...     print(f"{k}: {round(float(v), 6)}")
    l1 >= l1+l1: 2.0
    l1 <= l1+l2: 0.0
    l1 <= l2+l1: 0.0
    l2 <= l2+l2: 2.0
    l2 >= l1+l2: 0.0
    l2 >= l2+l1: 0.0
    ratio: 0.8
    """
    X, Y = _weyl_2x2_slacks_iv(X, Y)
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


def _weyl_2x2_slacks_iv(X, Y) -> tuple:
    """Finite symmetric ``X``, ``Y`` of one shape ``(..., 2, 2)``."""
    X = as_float_array(X, "X")
    Y = as_float_array(Y, "Y")
    if X.shape != Y.shape or X.ndim < 2 or X.shape[-2:] != (2, 2):
        raise ValueError(
            f"X and Y must have the same shape (..., 2, 2), got {X.shape} and {Y.shape}"
        )
    if not (np.isfinite(X).all() and np.isfinite(Y).all()):
        raise ValueError("X and Y must be finite")
    if not (np.allclose(X, np.swapaxes(X, -1, -2)) and np.allclose(Y, np.swapaxes(Y, -1, -2))):
        raise ValueError("X and Y must be symmetric")
    return X, Y

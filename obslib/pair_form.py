"""Numerics around the pair closed form: Fig. 2's grids, the maximising ``alpha`` of Theorem 5,
the Weyl step of Theorem 1 for 2x2 matrices, Figs. 1-2, and the audits behind the ledger.

The symbolic side lives in :mod:`obslib.symbolic`; this module evaluates it, compares it with
:func:`obslib.pair_bounds` and :func:`obslib.pair_bound_polar`, and packages the evidence that
notebook ``02_pair_closed_form`` prints and the claims of :mod:`obslib.claims.pair_form` judge.
Every audit is a pure function of its arguments and is cached.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .bounds import pair_bound_polar, pair_bounds

__all__ = [
    "audit_ratios",
    "paper_grid",
    "fine_grid",
    "bound_surface",
    "GridMax",
    "grid_maximum",
    "stationarity_alpha",
    "maximising_alpha",
    "maximising_alpha_closed",
    "random_symmetric_2x2",
    "weyl_2x2_slacks",
    "dual_weyl_printed_range",
    "plot_fig1",
    "plot_fig2",
    "Theorem4Audit",
    "theorem4_audit",
    "PrintedMatrixAudit",
    "printed_matrix_audit",
    "Theorem5Audit",
    "theorem5_audit",
    "ThetaDerivativeAudit",
    "theta_derivative_audit",
    "AlphaDerivativeAudit",
    "alpha_derivative_audit",
    "AlphaStarAudit",
    "alpha_star_audit",
    "WeylAudit",
    "weyl_audit",
]


def audit_ratios(u_max: float, d_io: float, u_over_d_curves) -> tuple:
    """The values of ``q = u_max / d_io`` the Theorem 5 audits use, sorted: Fig. 2's
    ``u_max / d_io``, the ``u_over_d_curves`` of the maximiser plot, and 0 (a stationary target)."""
    u = _positive_float("u_max", u_max, allow_zero=True)
    d = _positive_float("d_io", d_io)
    curves = [_positive_float("u_over_d_curves", c, allow_zero=True) for c in u_over_d_curves]
    return tuple(sorted({0.0, u / d, *curves}))


def _positive_int(name: str, value) -> int:
    if isinstance(value, bool) or int(value) != value or value < 1:
        raise ValueError(f"{name} must be a positive integer, got {value!r}")
    return int(value)


def _positive_float(name: str, value, allow_zero: bool = False) -> float:
    x = float(value)
    if not np.isfinite(x) or x < 0 or (x == 0 and not allow_zero):
        kind = "non-negative" if allow_zero else "positive"
        raise ValueError(f"{name} must be finite and {kind}, got {value!r}")
    return x


# --- Fig. 2 grids ------------------------------------------------------------------------------
def paper_grid(alpha_max: float = 5.0, step: float = 0.1) -> tuple[np.ndarray, np.ndarray]:
    """The grid of the published Fig. 2: ``alpha = 0:step:alpha_max``, ``theta = -pi:step:pi``.

    Values are ``k * step`` and ``-pi + k * step`` (as a MATLAB colon range), so with the
    default ``step = 0.1`` there are 51 values of ``alpha`` and 63 of ``theta``, and
    ``theta = +-pi/2`` is **not** on the grid (``../shared/EXPERIMENTS.md``, Fig. 2).

    Returns
    -------
    alpha, theta : ndarray
    """
    amax = _positive_float("alpha_max", alpha_max)
    h = _positive_float("step", step)
    n_a = int(np.floor(amax / h + 1e-9)) + 1
    n_t = int(np.floor(2 * np.pi / h + 1e-9)) + 1
    return np.arange(n_a) * h, -np.pi + np.arange(n_t) * h


def fine_grid(
    alpha_max: float = 5.0, alpha_per_unit: int = 100, theta_quarter: int = 180
) -> tuple[np.ndarray, np.ndarray]:
    """A grid that contains ``alpha = 1`` and ``theta = 0, +-pi/2, +-pi`` exactly.

    ``alpha = k / alpha_per_unit`` for ``k = 0 .. alpha_max * alpha_per_unit`` and
    ``theta = pi (k / (2 m) - 1)`` for ``k = 0 .. 4 m`` with ``m = theta_quarter``.
    """
    amax = _positive_float("alpha_max", alpha_max)
    per = _positive_int("alpha_per_unit", alpha_per_unit)
    m = _positive_int("theta_quarter", theta_quarter)
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
    u = _positive_float("u_max", u_max, allow_zero=True)
    d = _positive_float("d_io", d_io)
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
    n = _positive_int("n", n)
    rng = np.random.default_rng(seed)
    scale = 10.0 ** rng.uniform(-3, 3, size=(n, 1, 1))
    if not psd:
        m = rng.normal(size=(n, 2, 2))
        return scale * (m + np.swapaxes(m, 1, 2)) / 2
    rows = rng.normal(size=(n, 3, 2))
    rows[: n // 4, 1:] = 0.0
    return scale * np.einsum("nki,nkj->nij", rows, rows)


_WEYL_NAMES = (
    "l1 >= l1+l1", "l1 <= l1+l2", "l1 <= l2+l1", "l2 <= l2+l2", "l2 >= l1+l2", "l2 >= l2+l1",
)


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


def dual_weyl_printed_range(r: int = 2) -> list[tuple[int, int, int]]:
    """Pairs ``(i, j)`` admitted by the appendix's range for the dual Weyl inequality
    (``i, j >= 1``, ``i + j - r <= r``, indices at most ``r``), with the index ``i + j - r``.

    Returns ``[(i, j, i + j - r), ...]``; entries with index ``< 1`` are meaningless
    (``lambda_0`` does not exist): the correct range is ``i + j - r >= 1``.
    """
    r = _positive_int("r", r)
    return [(i, j, i + j - r) for i in range(1, r + 1) for j in range(1, r + 1) if i + j - r <= r]


# --- figures -----------------------------------------------------------------------------------
def plot_fig1(
    ax=None, d_io: float = 1.0, d_jo: float = 1.5, theta_i: float = 0.35, theta_j: float = 2.0
):
    """Fig. 1: sensors ``i, j`` around the target in the polar coordinates of Eq. (8).

    The target is at the centre; sensor ``i`` at distance ``d_io`` and angle ``theta_i``, sensor
    ``j`` at ``d_jo`` and ``theta_j``; ``theta_ji = theta_j - theta_i``. Returns the axes.
    """
    import matplotlib.pyplot as plt

    d_io = _positive_float("d_io", d_io)
    d_jo = _positive_float("d_jo", d_jo)
    if not (np.isfinite(theta_i) and np.isfinite(theta_j)):
        raise ValueError("theta_i and theta_j must be finite")
    if ax is None:  # the frame's aspect is always 2 : 1.45, so one written-down layout fits it
        fig, ax = plt.subplots(figsize=(4.1, 3))
        fig.subplots_adjust(left=0.024, right=0.976, bottom=0.028, top=0.972)
    pi_ = d_io * np.array([np.cos(theta_i), np.sin(theta_i)])
    pj_ = d_jo * np.array([np.cos(theta_j), np.sin(theta_j)])
    lim = 1.25 * max(d_io, d_jo)
    ax.axhline(0, color="0.6", lw=0.8, ls="--")
    for p, th, name, d, col, side in ((pi_, theta_i, "i", "d_{io}", "C0", -1.0),
                                      (pj_, theta_j, "j", "d_{jo}", "C1", 1.0)):
        ax.plot([0, p[0]], [0, p[1]], color=col, lw=1.5)
        ax.plot(*p, marker="^", ms=12, color=col, ls="none")
        ax.annotate(f"sensor ${name}$: $p_{name}$", p, xytext=(6, 6), textcoords="offset points")
        normal = side * np.array([-np.sin(th), np.cos(th)])
        ax.text(*(0.7 * p + 0.09 * lim * normal), f"${d}$", color=col, ha="center", va="center")
    for r, t0, t1, label, col in (
        (0.22 * lim, 0.0, theta_i, r"$\theta_i$", "C0"),
        (0.34 * lim, 0.0, theta_j, r"$\theta_j$", "C1"),
        (0.5 * lim, theta_i, theta_j, r"$\theta_{ji}$", "k"),
    ):
        t = np.linspace(t0, t1, 60)
        ax.plot(r * np.cos(t), r * np.sin(t), color=col, lw=1)
        tm = t0 + 0.55 * (t1 - t0) if label != r"$\theta_i$" else t1 + 0.25
        rr = 1.15 * r if label != r"$\theta_i$" else 0.8 * r
        ax.text(rr * np.cos(tm), rr * np.sin(tm), label, color=col, ha="center", va="center")
    ax.plot(0, 0, marker="*", ms=16, color="k", ls="none")
    ax.annotate("target $o$", (0, 0), xytext=(6, -14), textcoords="offset points")
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-0.45 * lim, lim)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    return ax


def _even_stride(n: int, most: int = 80) -> int:
    """Smallest stride dividing ``n - 1`` that leaves at most ``most`` cells (else the rounded-up
    stride). Equal cells keep ``plot_surface``'s polygons equal in length: matplotlib fills the
    unused vertices of ragged polygons from ``np.empty``, which can raise spurious overflow
    warnings."""
    cells = max(n - 1, 1)
    for d in range(1, cells + 1):
        if cells % d == 0 and cells // d <= most:
            return d if cells // d > 1 or cells <= most else int(np.ceil(cells / most))
    return int(np.ceil(cells / most))


def plot_fig2(alpha, theta, Z, levels, title: str = "", mark=None, panels: str = "all"):
    """Fig. 2's four panels: surface (a) and contour (b) over ``(alpha, theta)``, surface (c)
    and contour (d) over ``(alpha cos theta, alpha sin theta)``.

    Parameters
    ----------
    alpha, theta : 1-D arrays
        Grid axes; ``Z`` has shape ``(len(theta), len(alpha))`` (:func:`bound_surface`).
    levels : sequence of float
        Contour levels (Fig. 2: 0.1 ... 0.7).
    title : str
        Figure title.
    mark : GridMax, optional
        Grid maxima to mark with red stars.
    panels : {"all", "contour"}
        ``"contour"`` draws only the contour panels (b) and (d), side by side (the 3D surfaces
        take most of the rendering time and show nothing the contours do not).

    Returns
    -------
    matplotlib.figure.Figure
    """
    import matplotlib as mpl
    import matplotlib.pyplot as plt

    if panels not in ("all", "contour"):
        raise ValueError(f"panels must be 'all' or 'contour', got {panels!r}")
    a = np.asarray(alpha, dtype=float)
    t = np.asarray(theta, dtype=float)
    Z = np.asarray(Z, dtype=float)
    if Z.shape != (t.size, a.size):
        raise ValueError(f"Z must have shape {(t.size, a.size)}, got {Z.shape}")
    A, T = np.meshgrid(a, t)
    X, Y = A * np.cos(T), A * np.sin(T)
    surfaces = panels == "all"
    if surfaces:  # 3-D panels (a), (c) on the left, contours (b), (d) on the right
        fig = plt.figure(figsize=(9.55, 8.6))
        grid = fig.add_gridspec(2, 2, width_ratios=[1, 1.534])
    else:  # (b) wide, (d) square
        fig = plt.figure(figsize=(9.65, 4.6))
        grid = fig.add_gridspec(1, 2, width_ratios=[1.45, 1])
    rows = (
        ("(a)", A, T, r"$\alpha$", r"$\theta_{ji}$"),
        ("(c)", X, Y, r"$\alpha\cos\theta_{ji}$", r"$\alpha\sin\theta_{ji}$"),
    )
    for row, (tag, P, R, xl, yl) in enumerate(rows):
        if surfaces:
            # 3-D axes keep Matplotlib's automatic title height (it clears the rotated box),
            # whatever axes.titley says (obslib.notebook.setup_figures fixes it for 2-D axes)
            with mpl.rc_context({"axes.titley": None}):
                ax3 = fig.add_subplot(grid[row, 0], projection="3d")
                ax3.set_title(f"{tag} surface")
            ax3.plot_surface(P, R, Z, cmap="viridis", rstride=_even_stride(t.size),
                             cstride=_even_stride(a.size), linewidth=0)
            ax3.set_xlabel(xl)
            ax3.set_ylabel(yl)
            ax3.set_zlabel(r"$\underline{C}^{-1}$")
        ax2 = fig.add_subplot(grid[row, 1] if surfaces else grid[0, row])
        cs = ax2.contour(P, R, Z, levels=list(levels), cmap="viridis")
        ax2.clabel(cs, fontsize=7, fmt="%.1f")
        ax2.set_xlabel(xl)
        ax2.set_ylabel(yl)
        ax2.set_title(f"({'b' if row == 0 else 'd'}) contour")
        if row == 1:
            ax2.set_aspect("equal")
        if mark is not None:
            pts = np.array(mark.points)
            if row == 0:
                ax2.plot(pts[:, 0], pts[:, 1], "r*", ms=10)
            else:
                ax2.plot(pts[:, 0] * np.cos(pts[:, 1]), pts[:, 0] * np.sin(pts[:, 1]), "r*", ms=10)
    if title:
        fig.suptitle(title)
    # The layout is written down (found once with tight_layout; the 3-D panels' margins by eye):
    # tight_layout or bbox_inches="tight" would draw the figure once more just to measure it.
    if surfaces:
        fig.subplots_adjust(left=0.005, right=0.985, bottom=0.070, top=0.921 if title else 0.955,
                            wspace=0.266, hspace=0.243)
    else:
        fig.subplots_adjust(left=0.067, right=0.986, bottom=0.131, top=0.851 if title else 0.932,
                            wspace=0.185)
    return fig


# --- audits ------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Theorem4Audit:
    """SymPy's eigenvalues of ``O_ij^T O_ij`` against Eq. (33) and Theorem 4, and against obslib."""

    polar_matrix_printed_equal: bool  #: printed polar matrix - derived expands to 0
    eigenvalues_printed_equal: bool  #: SymPy eigenvalues (polar) - Eq. (33): 0 (see theorem4_audit)
    theorem4_ratio_equal: bool  #: lambda_min/(lambda_max + u^2) in alpha, theta, q - Eq. (9)^2 -> 0
    cartesian_discriminant_equal: bool  #: Cartesian discriminant - Eq. (33)'s radicand expands to 0
    cartesian_max_difference: float  #: Cartesian SymPy bound vs Eq. (9) at rational points
    n_rational_points: int
    digits: int
    max_error_pair_bounds: float  #: SymPy (mpmath, 30 digits) vs obslib.pair_bounds
    max_error_pair_bound_polar: float  #: SymPy (mpmath) vs obslib.pair_bound_polar
    max_error_numpy_generic: float  #: lambdified with NumPy vs pair_bounds where the bound > 1e-3
    n_random_points: int


def _random_pair_scenes(n: int, seed: int):
    """``n`` random two-sensor scenes ``(sensors (2, 2), target (2,), u_max)``, scales 1e-2 .. 1e2."""
    from .scenes import random_scenes

    return [(sc.sensors, sc.target, sc.u_max)
            for sc in random_scenes(n, seed, n_sensors=(2, 2), scale=(1e-2, 1e2), kinds=("generic",))]


@lru_cache(maxsize=8)
def theorem4_audit(
    n_rational_points: int, n_random_points: int, seed: int, digits: int = 50
) -> Theorem4Audit:
    """Derive Theorem 4 with SymPy (:mod:`obslib.symbolic`) and check it four ways.

    1. the printed polar matrix equals the derived one (the difference expands to zero), and so
       do the printed eigenvalues (Eq. (33)): the double-angle form of the derived roots expands
       to Eq. (33), and independently the trace and ``(lambda_max - lambda_min)^2`` of the roots
       leave remainder 0 modulo ``cos^2 + sin^2 = 1`` (:func:`obslib.symbolic.theorem4_residuals`);
    2. ``lambda_min / (lambda_max + u^2)`` with ``d_jo = alpha d_io``,
       ``theta_j = theta_i + theta``, ``u = q d_io`` cancels to Eq. (9) squared;
    3. in Cartesian coordinates: the discriminant identity (polynomial, expands to zero) and the
       whole bound, with ``alpha``, ``theta = atan2`` differences and ``q`` computed from the point,
       at ``n_rational_points`` rational points with ``digits`` digits;
    4. the SymPy expressions evaluated (mpmath, 30 digits) equal :func:`obslib.pair_bounds` and
       :func:`obslib.pair_bound_polar` at ``n_random_points`` random points.
    """
    import mpmath

    from . import symbolic as sy

    n_rat = _positive_int("n_rational_points", n_rational_points)
    n_rand = _positive_int("n_random_points", n_random_points)
    res = sy.theorem4_residuals()
    polar_ok = all(e == 0 for e in res["polar matrix"])
    eig_ok = all(
        res[k] == 0 for k in ("lambda_min", "lambda_max", "trace (mod cos^2 + sin^2 = 1)",
                              "(lambda_max - lambda_min)^2 (mod cos^2 + sin^2 = 1)")
    )
    ratio_ok = res["ratio"] == 0
    disc_ok = res["cartesian discriminant"] == 0
    cmin, cmax = sy.cartesian_eigenvalues()
    f_cart = sy.bound_from_eigenvalues(cmin, cmax)
    ranges = {s: (-3.0, 3.0) for s in sy.CARTESIAN_ARGS[:-1]}
    ranges[sy.U] = (0.0, 2.0)
    cart_diff = sy.max_difference_at_rational_points(
        f_cart, sy.theorem4_bound(), ranges, n_rat, seed, digits,
        point_map=lambda pt: sy.cartesian_ratio_values(pt, digits + 10),
    )

    f_mp = sy.lambdify_expr(f_cart, sy.CARTESIAN_ARGS, "mpmath", cse=True)
    f_np = sy.lambdify_expr(f_cart, sy.CARTESIAN_ARGS, "numpy")
    t_mp = sy.lambdify_expr(sy.theorem4_bound(), sy.RATIO_ARGS, "mpmath", cse=True)
    scenes = _random_pair_scenes(n_rand, seed)
    w = np.array([pair_bounds(sen, tgt[None, :], u)[0, 1, 0] for sen, tgt, u in scenes])
    args = np.array([(*tgt, *sen[0], *sen[1], u) for sen, tgt, u in scenes])  # (n, 7)
    # polar points: the same draws as (a, theta, q) = uniform(0, 5), uniform(-pi, pi),
    # uniform(0, 3) per point, in that order
    rng = np.random.default_rng(seed + 1)
    pts = rng.uniform((0.0, -np.pi, 0.0), (5.0, np.pi, 3.0), (n_rand, 3))
    exact = np.empty(n_rand)
    exact_p = np.empty(n_rand)
    with mpmath.workdps(30):
        for k in range(n_rand):
            exact[k] = float(f_mp(*[mpmath.mpf(x) for x in args[k]]))
            exact_p[k] = float(t_mp(*[mpmath.mpf(x) for x in pts[k]]))
    err_pb = float(np.abs(exact - w).max())
    big = exact > 1e-3  # the naive NumPy form loses lambda_min to cancellation near 0
    err_np = float(np.abs(f_np(*args.T) - w)[big].max(initial=0.0))
    err_polar = float(np.abs(exact_p - pair_bound_polar(*pts.T)).max())
    return Theorem4Audit(
        polar_ok, eig_ok, ratio_ok, disc_ok, cart_diff, n_rat, int(digits), err_pb, err_polar,
        err_np, n_rand,
    )


@dataclass(frozen=True)
class PrintedMatrixAudit:
    """The appendix's printed ``O_ij^T O_ij`` (Eq. (32)) against the true one."""

    wrong_entries: tuple  #: ``(row, col)`` of entries whose difference does not expand to 0
    witness: dict  #: a rational point (o, p_i, p_j)
    true_at_witness: tuple  #: the true matrix there (integers)
    printed_at_witness: tuple  #: the printed matrix there
    printed_eigenvalues_at_witness: tuple  #: floats; a negative one means it is no Gram matrix
    polar_printed_consistent: bool  #: printed Cartesian matrix in polar form = printed polar one


@lru_cache(maxsize=1)
def printed_matrix_audit() -> PrintedMatrixAudit:
    """Compare the printed Cartesian matrix of the proof of Theorem 4 with the true one.

    The witness is ``o = (0, 0)``, ``p_i = (1, 2)``, ``p_j = (3, 1)``: there the true matrix is
    ``[[10, 5], [5, 5]]`` and the printed one ``[[1, 6], [6, 1]]``, whose determinant is negative.
    """
    import sympy as sp

    from . import symbolic as sy

    true = sy.cartesian_gram()
    printed = sy.printed_cartesian_gram()
    wrong = tuple(
        (r, c) for r in range(2) for c in range(2) if sp.expand(printed[r, c] - true[r, c]) != 0
    )
    witness = {sy.OX: 0, sy.OY: 0, sy.PIX: 1, sy.PIY: 2, sy.PJX: 3, sy.PJY: 1}
    t_w = true.subs(witness)
    p_w = printed.subs(witness)
    eig = tuple(float(x) for x in sorted(np.linalg.eigvalsh(np.array(p_w, dtype=float))))
    sub = sy.polar_substitution()
    consistent = all(  # remainder modulo cos^2 + sin^2 = 1: 0 iff the identity holds
        sy.pythagorean_remainder(e) == 0 for e in (printed.subs(sub) - sy.printed_polar_gram())
    )
    return PrintedMatrixAudit(
        wrong,
        {str(k): int(v) for k, v in witness.items()},
        tuple(tuple(int(x) for x in row) for row in t_w.tolist()),
        tuple(tuple(int(x) for x in row) for row in p_w.tolist()),
        eig,
        consistent,
    )


@dataclass(frozen=True)
class Theorem5Audit:
    """Extremes of Theorem 4's bound on a fine grid, per ``q = u_max / d_io``."""

    u_over_d: tuple
    grid_max: tuple  #: per q, the grid maximum
    argmax: tuple  #: per q, the grid points within 1e-12 of the maximum
    predicted_max: tuple  #: per q, ``1 / sqrt(1 + q^2)``
    symbolic_max_exact: bool  #: SymPy: C^-1(1, pi/2) - 1/sqrt(1+q^2) expands to 0
    max_on_zero_lines: float  #: largest value on theta = 0, +-pi and on alpha = 0
    value_at_large_alpha: float  #: largest value at alpha = 1e6 over the theta grid and q's
    printed_max_halfpi_equal: float  #: printed max over theta vs C^-1(alpha, pi/2), rational points
    n_alpha: int
    n_theta: int


@lru_cache(maxsize=8)
def theorem5_audit(
    u_over_d: tuple,
    alpha_max: float,
    alpha_per_unit: int,
    theta_quarter: int,
    n_rational_points: int = 50,
) -> Theorem5Audit:
    """Locate the maximum and the zeros of the bound on :func:`fine_grid` for each ``q``.

    Theorem 5: the maximum ``1 / sqrt(1 + q^2)`` at ``alpha = 1``, ``theta = +-pi/2``; the
    minimum 0 at ``theta = 0, pi``, ``alpha = 0`` and ``alpha -> inf``. Also checks the proof's
    printed maximum over ``theta`` for fixed ``alpha`` at rational points.
    """
    import sympy as sp

    from . import symbolic as sy

    qs = tuple(float(_positive_float("u_over_d", q, allow_zero=True)) for q in u_over_d)
    if not qs:
        raise ValueError("u_over_d must list at least one value")
    alpha, theta = fine_grid(alpha_max, alpha_per_unit, theta_quarter)
    gmax, argm, pred = [], [], []
    zero_lines = 0.0
    large = 0.0
    on_zero = np.isclose(np.abs(np.sin(theta)), 0.0, atol=1e-15)
    for q in qs:
        Z = bound_surface(alpha, theta, q, 1.0)
        m = grid_maximum(alpha, theta, Z)
        gmax.append(m.value)
        argm.append(m.points)
        pred.append(1.0 / np.sqrt(1.0 + q * q))
        zero_lines = max(zero_lines, float(Z[on_zero].max()), float(Z[:, alpha == 0].max()))
        large = max(large, float(pair_bound_polar(1e6, theta, q).max()))
    f = sy.theorem4_bound()
    exact = sy.max_value_exact() == 0
    printed = sy.max_difference_at_rational_points(
        sy.printed_max_halfpi(), f.subs(sy.THETA, sp.pi / 2),
        {sy.ALPHA: (0.01, 5.0), sy.Q: (0.0, 3.0)}, n_rational_points, 0, 30,
    )
    return Theorem5Audit(
        qs, tuple(gmax), tuple(argm), tuple(pred), exact, zero_lines, large, printed,
        alpha.size, theta.size,
    )


@dataclass(frozen=True)
class ThetaDerivativeAudit:
    """The proof's ``d C^-1/d theta = 0 => alpha^2 sin 2 theta = 0`` and its second derivatives."""

    closed_form_equal: bool  #: SymPy's derivative - our factored form vanishes identically
    slope_at_zero: str  #: right-hand slope at theta = 0 (a formula; the left one is its negative)
    slope_at_zero_error: float  #: max |derivative at theta = +-1e-12 -+ formula| over the points
    slope_at_zero_min: float  #: smallest slope over those points (> 0: a corner, not stationary)
    square_second_derivative_zero: float  #: min of d^2(C^2)/d theta^2 at theta = 0 (> 0)
    square_second_derivative_halfpi: float  #: its max at theta = pi/2, alpha != 1 (< 0)
    corner_halfpi_slopes: tuple  #: (left, right) slopes in theta at alpha = 1, theta = pi/2, q = 1


@lru_cache(maxsize=4)
def theta_derivative_audit(n_rational_points: int, seed: int) -> ThetaDerivativeAudit:
    """Check the theta part of the proof of Theorem 5 symbolically (see
    :func:`obslib.symbolic.dbound_dtheta_closed`)."""
    import mpmath
    import sympy as sp

    from . import symbolic as sy

    n = _positive_int("n_rational_points", n_rational_points)
    a, th, q = sy.ALPHA, sy.THETA, sy.Q
    closed_ok = sy.closed_forms_hold()["dtheta"]
    deriv = sy.lambdify_expr(sy.dbound_dtheta_closed(), sy.RATIO_ARGS, "mpmath", cse=True)
    slope = sy.lambdify_expr(sy.dbound_dtheta_at_zero(), (a, q), "mpmath")
    rng0 = np.random.default_rng(seed + 7)
    slope_err, slope_min = 0.0, np.inf
    with mpmath.workdps(60):
        tiny = mpmath.mpf(10) ** -12
        for _ in range(n):
            av = mpmath.mpf(int(rng0.integers(1, 4985))) / 997
            qv = mpmath.mpf(int(rng0.integers(0, 2991))) / 997
            right = deriv(av, tiny, qv)
            left = deriv(av, -tiny, qv)
            s0 = slope(av, qv)
            slope_err = max(slope_err, float(abs(right - s0)), float(abs(left + s0)))
            slope_min = min(slope_min, float(s0))
    square = sy.theorem4_bound(squared=True)
    d2 = sy.lambdify_expr(sp.diff(sp.diff(square, th), th), sy.RATIO_ARGS, "mpmath", cse=True)
    rng = np.random.default_rng(seed)
    vals0, valsh = [], []
    with mpmath.workdps(30):
        for _ in range(n):
            k = int(rng.integers(1, 5000))
            qv = mpmath.mpf(int(rng.integers(0, 3000))) / 997
            if k == 997:  # alpha = 1: S = 0 at theta = pi/2
                continue
            av = mpmath.mpf(k) / 997
            vals0.append(float(d2(av, 0, qv)))
            valsh.append(float(d2(av, mpmath.pi / 2, qv)))
    # alpha = 1, q = 1: one-sided slopes at theta = pi/2 (exactly +-(2 + q^2) / (2 (1 + q^2)^1.5));
    # S^2 = 4 cos^2 theta loses 2 log10(1/h) digits to cancellation, O(h) from the limit
    with mpmath.workdps(60):
        h = mpmath.mpf(10) ** -15
        left = float(deriv(1, mpmath.pi / 2 - h, 1))
        right = float(deriv(1, mpmath.pi / 2 + h, 1))
    return ThetaDerivativeAudit(
        closed_ok, str(sy.dbound_dtheta_at_zero()), slope_err, slope_min, min(vals0), max(valsh),
        (left, right),
    )


@dataclass(frozen=True)
class AlphaDerivativeAudit:
    """The proof's ``d C^-1 / d alpha`` at ``theta = +-pi/2`` and at a general fixed ``theta``."""

    closed_form_equal: bool  #: SymPy's derivative - our factored form vanishes identically
    numerator_equals_eq36: bool  #: our numerator g - the printed Eq. (34) expands to 0
    printed_ratio_spread: tuple  #: (min, max) of true / printed derivative over rational points
    slope_at_alpha0: float  #: max |slope at alpha = 0+ - |sin theta| / sqrt(1 + q^2)|
    slope_at_alpha0_min: float  #: smallest slope at alpha = 0+ (> 0: alpha = 0 is not stationary)
    halfpi_true_slopes: tuple  #: theta = pi/2, q = 1: slope on (0, 1), left and right at alpha = 1
    halfpi_printed_at_1: float  #: the printed derivative at alpha = 1 (0)
    halfpi_printed_vs_true: float  #: max |printed - true derivative| at theta = pi/2 on (0, 1)
    halfpi_second_derivative_below_1: float  #: max |d^2 C/d alpha^2| on (0, 1), theta = pi/2 (0)


@lru_cache(maxsize=4)
def alpha_derivative_audit(n_rational_points: int, seed: int) -> AlphaDerivativeAudit:
    """Check the alpha part of the proof of Theorem 5 (see
    :func:`obslib.symbolic.dbound_dalpha_closed`, :func:`obslib.symbolic.printed_dbound_dalpha`)."""
    import mpmath
    import sympy as sp

    from . import symbolic as sy

    n = _positive_int("n_rational_points", n_rational_points)
    a, q = sy.ALPHA, sy.Q
    closed_ok = sy.closed_forms_hold()["dalpha"]
    num_ok = sp.expand(sy.stationarity_alpha() - sy.printed_stationarity_alpha()) == 0
    true_f = sy.lambdify_expr(sy.dbound_dalpha_closed(), sy.RATIO_ARGS, "mpmath", cse=True)
    printed_f = sy.lambdify_expr(sy.printed_dbound_dalpha(), sy.RATIO_ARGS, "mpmath", cse=True)
    rng = np.random.default_rng(seed)
    ratios, slope_err, slopes = [], 0.0, []
    with mpmath.workdps(60):
        for _ in range(n):
            av = mpmath.mpf(int(rng.integers(1, 4900))) / 997
            tv = mpmath.mpf(int(rng.integers(50, 1520))) / 997  # theta in (0.05, 1.52)
            qv = mpmath.mpf(int(rng.integers(1, 3000))) / 997
            p = printed_f(av, tv, qv)
            if abs(p) > mpmath.mpf(10) ** -20:
                ratios.append(float(true_f(av, tv, qv) / p))
            s0 = true_f(mpmath.mpf(10) ** -10, tv, qv)  # O(alpha^2) from the limit
            slopes.append(float(s0))
            expected = abs(mpmath.sin(tv)) / mpmath.sqrt(1 + qv**2)
            slope_err = max(slope_err, float(abs(s0 - expected)))
    # theta = pi/2: the bound is alpha/sqrt(1+q^2) on (0, 1] and 1/sqrt(alpha^2+q^2) on [1, inf)
    pw = sy.bound_halfpi_piecewise().subs(q, 1)
    lo_branch, hi_branch = pw.args[0][0], pw.args[1][0]
    below = float(sp.diff(lo_branch, a).subs(a, sp.Rational(1, 2)))
    left = float(sp.diff(lo_branch, a).subs(a, 1))
    right = float(sp.diff(hi_branch, a).subs(a, 1))
    printed_h = sy.printed_dbound_dalpha_halfpi().subs(q, 1)
    at1 = float(printed_h.subs(a, 1))
    grid = np.arange(1, 50) / 50.0  # alpha = k/50 in (0, 1)
    d_lo = sp.diff(lo_branch, a)

    def on_grid(expr):
        return np.broadcast_to(sy.lambdify_expr(expr, (a,))(grid), grid.shape)

    vs_true = float(np.abs(on_grid(printed_h) - on_grid(d_lo)).max())
    second = float(np.abs(on_grid(sp.diff(lo_branch, a, 2))).max())
    return AlphaDerivativeAudit(
        closed_ok, num_ok, (min(ratios), max(ratios)), slope_err, min(slopes),
        (below, left, right), at1, vs_true, second,
    )


@dataclass(frozen=True)
class AlphaStarAudit:
    """The maximising ``alpha`` for fixed ``theta``: numeric, closed form, brute force."""

    u_over_d: tuple
    n_theta: int
    max_closed_vs_numeric: float  #: max |closed form - bisection root|
    max_brute_force_gap: float  #: max of (best grid value - value at alpha*) (<= 0 up to rounding)
    min_distance_from_1: float  #: min over q > 0 and theta off {0, +-pi/2, pi} of alpha* - 1
    alpha_star_at_q0: float  #: max |alpha* - 1| for q = 0 (stationary target)
    symbolic_root_checks: float  #: max |Eq. (34)| at the derived closed form, rational points
    stationarity_at_1: str  #: Eq. (34) at alpha = 1, factored


@lru_cache(maxsize=8)
def alpha_star_audit(u_over_d: tuple, n_theta: int, n_rational_points: int = 50) -> AlphaStarAudit:
    """Solve Eq. (34) numerically and in closed form on ``theta`` in ``(0, pi)`` for each ``q``.

    ``theta`` runs over ``n_theta`` interior points of ``(0, pi)`` avoiding ``pi/2``
    (``alpha*`` depends on ``theta`` only through ``sin^2`` and ``|cos|``). Brute force: the
    bound never beats its value at ``alpha*`` on a grid over ``[0, 10]`` (step 0.01) and on a
    finer grid around ``alpha*`` (step 1e-4, ``alpha* +- 0.005``).
    """
    import sympy as sp

    from . import symbolic as sy

    qs = tuple(float(_positive_float("u_over_d", q, allow_zero=True)) for q in u_over_d)
    n = _positive_int("n_theta", n_theta)
    theta = np.pi * (np.arange(1, n + 1) / (n + 1))
    theta = theta[np.abs(np.cos(theta)) > 1e-3]
    coarse = np.linspace(0.0, 10.0, 1001)
    local = 1e-4 * np.arange(-50, 51)
    closed_vs_num = gap = 0.0
    min_dist = np.inf
    q0 = 0.0
    for q in qs:
        num = maximising_alpha(theta, q)
        clo = maximising_alpha_closed(theta, q)
        closed_vs_num = max(closed_vs_num, float(np.abs(num - clo).max()))
        dense = np.concatenate(
            [np.broadcast_to(coarse, (theta.size, coarse.size)),
             np.maximum(num[:, None] + local, 0.0)], axis=1,
        )
        best = pair_bound_polar(dense, theta[:, None], q).max(axis=1)
        gap = max(gap, float((best - pair_bound_polar(num, theta, q)).max()))
        if q > 0:
            min_dist = min(min_dist, float((num - 1.0).min()))
        else:
            q0 = max(q0, float(np.abs(num - 1.0).max()))
    root = sy.max_difference_at_rational_points(
        sy.stationarity_alpha().subs(sy.ALPHA, sp.sqrt(sy.alpha_star_squared())), 0,
        {sy.THETA: (0.02, 3.12), sy.Q: (0.0, 3.0)}, n_rational_points, 0, 40,
    )
    at1 = sy.stationarity_alpha_at_1()
    return AlphaStarAudit(qs, int(theta.size), closed_vs_num, gap, min_dist, q0, root, str(at1))


@dataclass(frozen=True)
class WeylAudit:
    """The Weyl inequalities of the proof of Theorem 1 for 2x2 symmetric matrices."""

    symbolic_triangle_equal: dict  #: name -> slack - triangle form expands to 0
    n_pairs: int
    min_relative_slack: dict  #: name -> min of slack / (|X| + |Y|) over random pairs (>= -1e-15)
    min_ratio_slack: float  #: Eq. (19) over random PSD pairs
    printed_range: tuple  #: (i, j, index) admitted by the printed dual-Weyl range for r = 2
    invalid_indices: tuple  #: those with index < 1


@lru_cache(maxsize=4)
def weyl_audit(n_pairs: int, seed: int) -> WeylAudit:
    """Symbolic (triangle inequality) and random checks of Eqs. (18)-(19) for 2x2 matrices."""
    import sympy as sp

    from . import symbolic as sy

    n = _positive_int("n_pairs", n_pairs)
    sym = {k: bool(sp.expand(s - t) == 0) for k, (s, t) in sy.weyl_2x2_slacks().items()}
    X = random_symmetric_2x2(n, seed)
    Y = random_symmetric_2x2(n, seed + 1)
    norm = np.abs(np.linalg.eigvalsh(X)).max(axis=-1) + np.abs(np.linalg.eigvalsh(Y)).max(axis=-1)
    sl = weyl_2x2_slacks(X, Y)
    rel = {k: float((sl[k] / norm).min()) for k in _WEYL_NAMES}
    P = random_symmetric_2x2(n, seed + 2, psd=True)
    R = random_symmetric_2x2(n, seed + 3, psd=True)
    ratio = weyl_2x2_slacks(P, R)["ratio"]
    rng_ = tuple(dual_weyl_printed_range(2))
    return WeylAudit(sym, n, rel, float(np.nanmin(ratio)), rng_, tuple(t for t in rng_ if t[2] < 1))

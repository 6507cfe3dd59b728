r"""Audits of the derivatives in the proof of Theorem 5 (notebook 02): the derivatives of the pair
bound in :math:`\theta` and in :math:`\alpha`, as SymPy computes them and as the paper prints
them.

The symbolic side lives in :mod:`obslib.symbolic`; the statement of Theorem 5 itself (the
maximum on a fine grid, the maximiser :math:`\alpha^*`, where the derivative in :math:`\alpha`
is smallest) is audited in :mod:`obslib.studies.pair_closed_form`. Every audit is a pure function
of its arguments and is cached.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .._validate import as_int

__all__ = ["ThetaDerivativeAudit", "theta_derivative_audit", "AlphaDerivativeAudit",
           "alpha_derivative_audit"]


@dataclass(frozen=True)
class ThetaDerivativeAudit:
    """The proof's ``d C^-1/d theta = 0 => alpha^2 sin 2 theta = 0`` and its second derivatives."""

    closed_form_equal: bool  #: SymPy's derivative - our factored form vanishes identically
    slope_at_zero: str  #: right-hand slope at theta = 0 (a formula; the left one is its negative)
    #: largest :math:`|\partial C / \partial\theta (\pm 10^{-12}) \mp \mathrm{slope}|` over the
    #: points
    slope_at_zero_error: float
    #: smallest slope over those points (positive, so a corner, not a stationary point)
    slope_at_zero_min: float
    #: smallest :math:`\partial^2 (C^2) / \partial\theta^2` at :math:`\theta = 0` (positive)
    square_second_derivative_zero: float
    #: its largest value at :math:`\theta = \pi/2`, :math:`\alpha \ne 1` (negative)
    square_second_derivative_halfpi: float
    corner_halfpi_slopes: tuple  #: (left, right) slopes in theta at alpha = 1, theta = pi/2, q = 1


def theta_derivative_audit(n_rational_points: int, seed: int) -> ThetaDerivativeAudit:
    """Check the theta part of the proof of Theorem 5 symbolically (see
    :func:`obslib.symbolic.dbound_dtheta_closed`).

    Examples
    --------
    >>> a = theta_derivative_audit(n_rational_points=3, seed=0)
    >>> a.closed_form_equal, a.slope_at_zero_min > 0
    (True, True)
    """
    return _theta_derivative_audit(
        as_int(n_rational_points, "n_rational_points", 1), as_int(seed, "seed", 0)
    )


@lru_cache(maxsize=4)
def _theta_derivative_audit(n_rational_points, seed):
    import mpmath
    import sympy as sp

    from .. import symbolic

    n = as_int(n_rational_points, "n_rational_points", 1)
    a, th, q = symbolic.ALPHA, symbolic.THETA, symbolic.Q
    closed_ok = symbolic.closed_forms_hold()["dtheta"]
    deriv = symbolic.lambdify_expr(symbolic.dbound_dtheta_closed(), symbolic.RATIO_ARGS,
                                   "mpmath", cse=True)
    slope = symbolic.lambdify_expr(symbolic.dbound_dtheta_at_zero(), (a, q), "mpmath")
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
    square = symbolic.theorem4_bound(squared=True)
    d2 = symbolic.lambdify_expr(sp.diff(sp.diff(square, th), th), symbolic.RATIO_ARGS, "mpmath",
                                cse=True)
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
        closed_ok, str(symbolic.dbound_dtheta_at_zero()), slope_err, slope_min, min(vals0),
        max(valsh), (left, right),
    )


@dataclass(frozen=True)
class AlphaDerivativeAudit:
    """The proof's ``d C^-1 / d alpha`` at ``theta = +-pi/2`` and at a general fixed ``theta``."""

    closed_form_equal: bool  #: SymPy's derivative - our factored form vanishes identically
    numerator_equals_eq36: bool  #: our numerator g - the printed Eq. (34) expands to 0
    printed_ratio_spread: tuple  #: (min, max) of true / printed derivative over rational points
    #: largest :math:`|\partial C/\partial\alpha (0^+) - |\sin\theta| / \sqrt{1 + q^2}|`
    slope_at_alpha0: float
    #: smallest slope at :math:`\alpha = 0^+` (positive, so :math:`\alpha = 0` is not stationary)
    slope_at_alpha0_min: float
    #: at :math:`\theta = \pi/2`, :math:`q = 1`, the slope on :math:`(0, 1)` and left and right of
    #: :math:`\alpha = 1`
    halfpi_true_slopes: tuple
    halfpi_printed_at_1: float  #: the printed derivative at alpha = 1 (0)
    #: largest :math:`|` printed :math:`-` true derivative :math:`|` at :math:`\theta = \pi/2` on
    #: :math:`(0, 1)`
    halfpi_printed_vs_true: float
    #: largest :math:`|\partial^2 C/\partial\alpha^2|` on :math:`(0, 1)`, :math:`\theta = \pi/2` (0)
    halfpi_second_derivative_below_1: float


def alpha_derivative_audit(n_rational_points: int, seed: int) -> AlphaDerivativeAudit:
    """Check the alpha part of the proof of Theorem 5 (see
    :func:`obslib.symbolic.dbound_dalpha_closed`, :func:`obslib.symbolic.printed_dbound_dalpha`).

    Examples
    --------
    >>> a = alpha_derivative_audit(n_rational_points=3, seed=0)
    >>> a.closed_form_equal, a.numerator_equals_eq36, a.halfpi_printed_at_1
    (True, True, 0.0)
    """
    return _alpha_derivative_audit(
        as_int(n_rational_points, "n_rational_points", 1), as_int(seed, "seed", 0)
    )


@lru_cache(maxsize=4)
def _alpha_derivative_audit(n_rational_points, seed):
    import mpmath
    import sympy as sp

    from .. import symbolic

    n = as_int(n_rational_points, "n_rational_points", 1)
    a, q = symbolic.ALPHA, symbolic.Q
    closed_ok = symbolic.closed_forms_hold()["dalpha"]
    num_ok = sp.expand(symbolic.stationarity_alpha() - symbolic.printed_stationarity_alpha()) == 0
    true_f = symbolic.lambdify_expr(symbolic.dbound_dalpha_closed(), symbolic.RATIO_ARGS,
                                    "mpmath", cse=True)
    printed_f = symbolic.lambdify_expr(symbolic.printed_dbound_dalpha(), symbolic.RATIO_ARGS,
                                       "mpmath", cse=True)
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
    pw = symbolic.bound_halfpi_piecewise().subs(q, 1)
    lo_branch, hi_branch = pw.args[0][0], pw.args[1][0]
    below = float(sp.diff(lo_branch, a).subs(a, sp.Rational(1, 2)))
    left = float(sp.diff(lo_branch, a).subs(a, 1))
    right = float(sp.diff(hi_branch, a).subs(a, 1))
    printed_h = symbolic.printed_dbound_dalpha_halfpi().subs(q, 1)
    at1 = float(printed_h.subs(a, 1))
    grid = np.arange(1, 50) / 50.0  # alpha = k/50 in (0, 1)
    d_lo = sp.diff(lo_branch, a)

    def on_grid(expr):
        return np.broadcast_to(symbolic.lambdify_expr(expr, (a,))(grid), grid.shape)

    vs_true = float(np.abs(on_grid(printed_h) - on_grid(d_lo)).max())
    second = float(np.abs(on_grid(sp.diff(lo_branch, a, 2))).max())
    return AlphaDerivativeAudit(
        closed_ok, num_ok, (min(ratios), max(ratios)), slope_err, min(slopes),
        (below, left, right), at1, vs_true, second,
    )

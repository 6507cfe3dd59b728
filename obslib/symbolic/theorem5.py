r"""Theorem 5 with SymPy: the derivatives of Eq. (9), their stationary points and the maximiser.

The proof of Theorem 5 locates the extremes of :math:`C^{-1}` from its derivatives in
:math:`\theta` and :math:`\alpha`. This module derives them (``sympy.diff``), gives their factored
forms (proved equal by :func:`closed_forms_hold`), transcribes the paper's printed versions
(``printed_*``) and derives the maximising :math:`\alpha` for a fixed :math:`\theta` in closed form,
which the paper does not give.
"""

from __future__ import annotations

from functools import cache

import sympy as sp

from .._validate import as_bool
from ._common import _COS2, _D, _S, ALPHA, C_SYM, D_SYM, S_SYM, THETA, Q
from .theorem4 import pull_out_of_roots, theorem4_bound, vanishes_with_radicals

__all__ = [
    "max_value_exact", "dbound_dtheta", "dbound_dtheta_closed", "dbound_dtheta_at_zero",
    "dbound_dalpha", "stationarity_alpha", "stationarity_alpha_at_1", "closed_forms_hold",
    "dbound_dalpha_closed", "printed_stationarity_alpha", "printed_dbound_dalpha",
    "printed_dbound_dalpha_halfpi", "printed_max_halfpi", "bound_halfpi_piecewise",
    "alpha_star_squared", "alpha_star_closed",
]  # fmt: skip


@cache
def max_value_exact() -> sp.Expr:
    r""":math:`C^{-1}(\alpha = 1, \theta = \pi/2) - 1 / \sqrt{1 + q^2}` with the common factor
    pulled out of the square roots (:func:`pull_out_of_roots`); 0 when Theorem 5's maximum value
    is right.

    Examples
    --------
    >>> from obslib.symbolic import max_value_exact
    >>> max_value_exact()
    0
    """
    at = theorem4_bound().subs({ALPHA: 1, THETA: sp.pi / 2})
    return sp.expand(pull_out_of_roots(at) - 1 / sp.sqrt(1 + Q**2))


@cache
def dbound_dtheta() -> sp.Expr:
    r""":math:`\partial C^{-1} / \partial\theta` of Theorem 4's expression, by SymPy (valid where
    :math:`S > 0` and :math:`C^{-1} > 0`).

    Examples
    --------
    It vanishes at :math:`\theta = \pi/2` when :math:`\alpha \ne 1`:

    >>> import sympy as sp
    >>> from obslib.symbolic import ALPHA, Q, THETA, dbound_dtheta
    >>> dbound_dtheta().subs({ALPHA: 2, THETA: sp.pi / 2, Q: 1})
    0
    """
    return sp.diff(theorem4_bound(), THETA)


def _parts(abbreviate: bool):
    if as_bool(abbreviate, "abbreviate"):
        return S_SYM, C_SYM, D_SYM
    return _S, theorem4_bound(), _D


def dbound_dtheta_closed(abbreviate: bool = False) -> sp.Expr:
    r"""Factored form of :func:`dbound_dtheta`: :math:`2 \alpha^2 \sin 2\theta \,(1 + \alpha^2 +
    q^2) / (S C D^2)` with :math:`D` the denominator of Eq. (9) and :math:`C` the bound itself
    (with ``abbreviate=True``, :math:`S`, :math:`C`, :math:`D` stay symbols, for display).

    Its sign is that of :math:`\sin 2\theta`, which suggests the paper's :math:`\alpha^2 \sin
    2\theta = 0`. But :math:`C` vanishes at :math:`\theta = 0, \pi` (it is proportional to
    :math:`|\sin\theta|` there), so the quotient :math:`\sin 2\theta / C` does not: the one-sided
    slopes are :math:`\pm\alpha / \sqrt{(1 + \alpha^2)(1 + \alpha^2 + q^2)}`, and at
    :math:`\alpha = 1, \theta = \pm\pi/2` the factor :math:`S` vanishes.

    Examples
    --------
    >>> from obslib.symbolic import dbound_dtheta_closed
    >>> dbound_dtheta_closed(abbreviate=True)
    2*alpha**2*(alpha**2 + q**2 + 1)*sin(2*theta)/(C*D**2*S)
    """
    S, C, D = _parts(abbreviate)
    return 2 * ALPHA**2 * sp.sin(2 * THETA) * (1 + ALPHA**2 + Q**2) / (S * C * D**2)


def dbound_dtheta_at_zero() -> sp.Expr:
    r"""The right-hand slope :math:`\lim_{\theta \to 0^+} \partial C^{-1} / \partial\theta =
    \alpha / \sqrt{(1 + \alpha^2)(1 + \alpha^2 + q^2)}`.

    Derived by hand from :func:`dbound_dtheta_closed`. The left-hand slope is its negative, so
    :math:`\theta = 0` is a corner of :math:`C^{-1}`, not a stationary point.

    Examples
    --------
    At :math:`\alpha = 1, q = 0` the slope is :math:`1/2`, and SymPy's derivative just right of
    :math:`\theta = 0` agrees:

    >>> import sympy as sp
    >>> from obslib.symbolic import (ALPHA, Q, THETA, dbound_dtheta,
    ...                              dbound_dtheta_at_zero)
    >>> dbound_dtheta_at_zero().subs({ALPHA: 1, Q: 0})
    1/2
    >>> at = {ALPHA: 1, Q: 0, THETA: sp.Rational(1, 10**6)}
    >>> round(float(dbound_dtheta().subs(at)), 6)
    0.5
    """
    return ALPHA / sp.sqrt((1 + ALPHA**2) * (1 + ALPHA**2 + Q**2))


@cache
def dbound_dalpha() -> sp.Expr:
    r""":math:`\partial C^{-1} / \partial\alpha` of Theorem 4's expression, by SymPy.

    Examples
    --------
    At :math:`\theta = \pi/2`, :math:`q = 0` and :math:`\alpha < 1` the bound is :math:`\alpha`
    (:func:`bound_halfpi_piecewise`), so the slope is 1:

    >>> import sympy as sp
    >>> from obslib.symbolic import ALPHA, Q, THETA, dbound_dalpha
    >>> at = {ALPHA: sp.Rational(1, 2), THETA: sp.pi / 2, Q: 0}
    >>> sp.nsimplify(dbound_dalpha().subs(at))
    1
    """
    return sp.diff(theorem4_bound(), ALPHA)


def stationarity_alpha(abbreviate: bool = False) -> sp.Expr:
    r"""The numerator :math:`g` of :math:`\partial C^{-1} / \partial\alpha` (its sign and zeros
    for :math:`\alpha > 0`):

    .. math::

       g = (1 - \alpha^2)(1 - \cos 2\theta) + q^2 \bigl(S - (\alpha^2 + \cos 2\theta)\bigr),

    which is the paper's Eq. (34). ``abbreviate=True`` keeps :math:`S` as a symbol (display).

    Examples
    --------
    >>> from obslib.symbolic import stationarity_alpha
    >>> stationarity_alpha(abbreviate=True)
    q**2*(S - alpha**2 - cos(2*theta)) + (1 - alpha**2)*(1 - cos(2*theta))
    """
    S = _parts(abbreviate)[0]
    return (1 - ALPHA**2) * (1 - _COS2) + Q**2 * (S - (ALPHA**2 + _COS2))


@cache
def stationarity_alpha_at_1() -> sp.Expr:
    r"""Eq. (34) at :math:`\alpha = 1`, factored.

    There :math:`S = \sqrt{2 + 2 \cos 2\theta}`; with :math:`\cos 2\theta = 2 \cos^2\theta - 1`
    (``sympy.expand_trig``) :math:`S = 2 |\cos\theta|`, and the bracket factors as
    :math:`2 q^2 (|\cos\theta| - \cos^2\theta)`.

    Examples
    --------
    >>> from obslib.symbolic import stationarity_alpha_at_1
    >>> stationarity_alpha_at_1()
    2*q**2*(-cos(theta)**2 + Abs(cos(theta)))
    """
    return sp.factor(sp.expand(sp.expand_trig(stationarity_alpha().subs(ALPHA, 1))))


@cache
def closed_forms_hold() -> dict[str, bool]:
    r"""Whether SymPy's derivatives equal the factored forms, decided once by
    :func:`vanishes_with_radicals` with the radicals :math:`C` (Eq. (9)) and :math:`S`.

    ``"dtheta"``: :func:`dbound_dtheta` against :func:`dbound_dtheta_closed`; ``"dalpha"``:
    :func:`dbound_dalpha` against :func:`dbound_dalpha_closed`.

    Examples
    --------
    >>> from obslib.symbolic import closed_forms_hold
    >>> closed_forms_hold()
    {'dtheta': True, 'dalpha': True}
    """
    radicals = [theorem4_bound(), _S]
    return {
        "dtheta": vanishes_with_radicals(dbound_dtheta() - dbound_dtheta_closed(), radicals),
        "dalpha": vanishes_with_radicals(dbound_dalpha() - dbound_dalpha_closed(), radicals),
    }


def dbound_dalpha_closed(abbreviate: bool = False) -> sp.Expr:
    r"""Factored form of :func:`dbound_dalpha`: :math:`2 \alpha g / (S C D^2)`, :math:`g` of
    :func:`stationarity_alpha`; equivalently :math:`2 \alpha g / (S \sqrt{N} D^{3/2})` with
    :math:`N = 1 + \alpha^2 - S`. ``abbreviate=True`` keeps :math:`S`, :math:`C`, :math:`D` as
    symbols (display).

    Examples
    --------
    The same slope 1 as :func:`dbound_dalpha` at :math:`\alpha = 1/2, \theta = \pi/2, q = 0`:

    >>> import sympy as sp
    >>> from obslib.symbolic import ALPHA, Q, THETA, dbound_dalpha_closed
    >>> at = {ALPHA: sp.Rational(1, 2), THETA: sp.pi / 2, Q: 0}
    >>> sp.nsimplify(dbound_dalpha_closed().subs(at))
    1
    """
    S, C, D = _parts(abbreviate)
    return 2 * ALPHA * stationarity_alpha(abbreviate) / (S * C * D**2)


def printed_stationarity_alpha() -> sp.Expr:
    r"""Eq. (34) as printed in the proof of Theorem 5 (left-hand side).

    Examples
    --------
    It is the derived numerator :func:`stationarity_alpha`:

    >>> import sympy as sp
    >>> from obslib.symbolic import printed_stationarity_alpha, stationarity_alpha
    >>> sp.expand(printed_stationarity_alpha() - stationarity_alpha())
    0
    """
    c = sp.cos(2 * THETA)
    return (1 - ALPHA**2) * (1 - c) + Q**2 * (
        sp.sqrt(1 + ALPHA**4 + 2 * ALPHA**2 * c) - (ALPHA**2 + c)
    )


def printed_dbound_dalpha() -> sp.Expr:
    r"""The expression the proof of Theorem 5 sets to zero for :math:`\partial C^{-1} /
    \partial\alpha` at a fixed :math:`\theta` (the display before Eq. (34)):
    :math:`\alpha\,[\text{Eq. (34)}] / D^{5/2}`.

    Examples
    --------
    Not the derivative, but of the same sign (a positive factor apart):

    >>> import sympy as sp
    >>> from obslib.symbolic import (ALPHA, Q, THETA, dbound_dalpha_closed,
    ...                              printed_dbound_dalpha)
    >>> at = {ALPHA: sp.Rational(1, 2), THETA: sp.pi / 3, Q: 1}
    >>> ratio = printed_dbound_dalpha() / dbound_dalpha_closed()
    >>> float(ratio.subs(at)) > 0
    True
    """
    return ALPHA * printed_stationarity_alpha() / _D ** sp.Rational(5, 2)


def printed_dbound_dalpha_halfpi() -> sp.Expr:
    r"""The proof's :math:`\partial C^{-1} / \partial\alpha` at :math:`\theta = \pm\pi/2`:
    :math:`\alpha (1 - \alpha^2) / (1 + \alpha^2 + |1 - \alpha^2| + 2 q^2)^{5/2}`.

    Examples
    --------
    At :math:`\alpha = 1/2, q = 0` it gives :math:`3 \sqrt{2} / 64`, where the true slope is 1
    (:func:`dbound_dalpha`): the sign is right, the value is not.

    >>> import sympy as sp
    >>> from obslib.symbolic import ALPHA, Q, printed_dbound_dalpha_halfpi
    >>> half = sp.Rational(1, 2)
    >>> printed_dbound_dalpha_halfpi().subs({ALPHA: half, Q: 0})
    3*sqrt(2)/64
    """
    return ALPHA * (1 - ALPHA**2) / (
        1 + ALPHA**2 + sp.Abs(1 - ALPHA**2) + 2 * Q**2
    ) ** sp.Rational(5, 2)


def printed_max_halfpi() -> sp.Expr:
    r"""The proof's maximum over :math:`\theta` for fixed :math:`\alpha` (at :math:`\theta =
    \pm\pi/2`): :math:`\sqrt{(1 + \alpha^2 - |1 - \alpha^2|) / (1 + \alpha^2 + |1 - \alpha^2| +
    2 q^2)}`.

    Examples
    --------
    It agrees with :func:`bound_halfpi_piecewise` on both sides of :math:`\alpha = 1`:

    >>> import sympy as sp
    >>> from obslib.symbolic import (ALPHA, Q, bound_halfpi_piecewise,
    ...                              printed_max_halfpi)
    >>> diff = printed_max_halfpi() - bound_halfpi_piecewise()
    >>> [sp.simplify(diff.subs({ALPHA: a, Q: sp.Rational(1, 3)}))
    ...  for a in (sp.Rational(1, 2), 3)]
    [0, 0]
    """
    a = sp.Abs(1 - ALPHA**2)
    return sp.sqrt((1 + ALPHA**2 - a) / (1 + ALPHA**2 + a + 2 * Q**2))


def bound_halfpi_piecewise() -> sp.Expr:
    r""":math:`C^{-1}` at :math:`\theta = \pm\pi/2` without absolute values: :math:`\alpha /
    \sqrt{1 + q^2}` for :math:`\alpha \le 1` and :math:`1 / \sqrt{\alpha^2 + q^2}` for
    :math:`\alpha \ge 1` (a corner at :math:`\alpha = 1`).

    Examples
    --------
    At :math:`\alpha = 2, q = 0` it is :math:`1/2`, as Eq. (9) gives (:func:`theorem4_bound`):

    >>> import sympy as sp
    >>> from obslib.symbolic import (ALPHA, Q, THETA, bound_halfpi_piecewise,
    ...                              theorem4_bound)
    >>> bound_halfpi_piecewise().subs({ALPHA: 2, Q: 0})
    1/2
    >>> at = {ALPHA: 2, THETA: sp.pi / 2, Q: 0}
    >>> theorem4_bound().subs(at)
    1/2
    """
    return sp.Piecewise(
        (ALPHA / sp.sqrt(1 + Q**2), ALPHA <= 1), (1 / sp.sqrt(ALPHA**2 + Q**2), True)
    )


@cache
def alpha_star_squared() -> sp.Expr:
    r""":math:`\alpha^{*2}`, the square of the maximising :math:`\alpha` for a fixed
    :math:`\theta`, derived.

    Write :math:`t = \alpha^2` and :math:`c = \cos 2\theta = 1 - 2 \sigma` with :math:`\sigma =
    \sin^2\theta > 0`. Eq. (34) is :math:`q^2 S = q^2 (t + c) + (t - 1)(1 - c)`; squaring gives a
    quadratic :math:`A t^2 + B t + C = 0` (``sympy.Poly``), solved by the quadratic formula with
    the discriminant factored (``sympy.factor``). Of its two roots the larger one satisfies the
    unsquared equation (:math:`t \ge 1`, because :math:`S \ge |t + c|` makes the :math:`q^2` term
    of Eq. (34) non-negative). The root is factored and returned in :math:`\theta`, with
    :math:`\sqrt{1 - \sigma} = |\cos\theta|`.

    Raises
    ------
    RuntimeError
        If SymPy returns the root in an unexpected form.

    Examples
    --------
    For a static target (:math:`q = 0`) the maximiser is :math:`\alpha^* = 1`:

    >>> from obslib.symbolic import Q, alpha_star_squared
    >>> alpha_star_squared().subs(Q, 0)
    1
    """
    t = sp.Symbol("t", positive=True)
    sigma = sp.Symbol("sigma", positive=True)
    c = 1 - 2 * sigma
    lhs = Q**4 * (1 + t**2 + 2 * t * c)
    rhs = (Q**2 * (t + c) + (t - 1) * (1 - c)) ** 2
    a, b, c0 = sp.Poly(sp.expand(rhs - lhs), t).all_coeffs()
    root = sp.sqrt(sp.factor(b**2 - 4 * a * c0))
    roots = [(-b + root) / (2 * a), (-b - root) / (2 * a)]
    # the root with + sqrt: evaluate at a generic point to pick the larger one
    at = {sigma: sp.Rational(1, 3), Q: sp.Rational(1, 2)}
    big = sp.factor(max(roots, key=lambda r: float(r.subs(at))))
    big = big.subs(sp.sqrt(1 - sigma), sp.Abs(sp.cos(THETA))).subs(sigma, sp.sin(THETA) ** 2)
    if big.has(sigma) or big.has(t):
        raise RuntimeError(f"unexpected form of the root: {big}")
    return big


def alpha_star_closed() -> sp.Expr:
    r"""Simplified form of the maximiser (beyond the paper):

    .. math::

       \alpha^*(\theta, q) = \sqrt{\frac{\sqrt{1 + q^2}\,\bigl(\sqrt{1 + q^2} \sin^2\theta
       + q^2 |\cos\theta|\bigr)}{q^2 + \sin^2\theta}}.

    :math:`\alpha^* = 1` exactly when :math:`q = 0` or :math:`\cos\theta = 0`; otherwise
    :math:`\alpha^* > 1`.

    Examples
    --------
    Its square is :func:`alpha_star_squared`:

    >>> import sympy as sp
    >>> from obslib.symbolic import alpha_star_closed, alpha_star_squared
    >>> sp.cancel(sp.expand(alpha_star_closed() ** 2 - alpha_star_squared()))
    0
    """
    r = sp.sqrt(1 + Q**2)
    s2 = sp.sin(THETA) ** 2
    return sp.sqrt(r * (r * s2 + Q**2 * sp.Abs(sp.cos(THETA))) / (Q**2 + s2))

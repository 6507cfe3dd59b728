r"""Theorem 4's closed form (Eq. (9)) and its derivation from the Gram eigenvalues, with SymPy.

The paper states the pair bound in polar form:

.. math::

   C^{-1}(O_{ij}(o, u_o)) = \sqrt{\frac{1 + \alpha^2 - S}{1 + \alpha^2 + S + 2 u^2 / d_{io}^2}},

   S = \sqrt{1 + \alpha^4 + 2 \alpha^2 \cos 2\theta_{ji}}, \qquad \alpha = d_{jo} / d_{io}.

This module writes it in :math:`\alpha`, :math:`\theta = \theta_{ji}` and :math:`q = u / d_{io}`,
reduces Theorem 1's ratio of the derived eigenvalues to it, and collects every comparison with
the paper as residuals that are 0 exactly when the two agree.
"""

from __future__ import annotations

from functools import cache

import numpy as np
import sympy as sp

from .._validate import ArgumentTypeError, as_bool, as_int, as_mapping
from ._common import (
    _COS2,
    _D,
    _N,
    ALPHA,
    CARTESIAN_ARGS,
    D_IO,
    D_JO,
    OX,
    OY,
    PIX,
    PIY,
    PJX,
    PJY,
    THETA,
    THETA_I,
    THETA_J,
    Q,
    U,
    as_expr,
)  # fmt: skip
from .gram import (
    discriminant_cartesian,
    eigenvalues,
    polar_eigenvalues,
    polar_gram,
    printed_eigenvalues,
    printed_polar_gram,
    pythagorean_remainder,
)  # fmt: skip

__all__ = [
    "bound_from_eigenvalues", "ratio_substitution", "pull_out_of_roots", "polar_ratio",
    "cartesian_ratio_values", "theorem4_residuals", "theorem4_radicand", "theorem4_bound",
    "vanishes_with_radicals",
]  # fmt: skip


def bound_from_eigenvalues(lmin, lmax, u=U) -> sp.Expr:
    r"""Theorem 1's bound :math:`\sqrt{\lambda_{\min} / (\lambda_{\max} + u^2)}` (Eq. (21)).

    Examples
    --------
    >>> import sympy as sp
    >>> from obslib.symbolic import bound_from_eigenvalues
    >>> bound_from_eigenvalues(sp.Integer(1), 3, u=1)
    1/2
    """
    lmin, lmax, u = as_expr(lmin, "lmin"), as_expr(lmax, "lmax"), as_expr(u, "u")
    return sp.sqrt(lmin / (lmax + u**2))


def ratio_substitution() -> dict:
    r"""From polar to Theorem 4's variables: :math:`d_{jo} = \alpha d_{io}`,
    :math:`\theta_j = \theta_i + \theta`, :math:`u = q d_{io}`.

    Examples
    --------
    >>> from obslib.symbolic import D_JO, ratio_substitution
    >>> ratio_substitution()[D_JO]
    alpha*d_io
    """
    return {D_JO: ALPHA * D_IO, THETA_J: THETA_I + THETA, U: Q * D_IO}


def pull_out_of_roots(expr: sp.Expr) -> sp.Expr:
    r"""Common factors moved out of every square root: :math:`\sqrt{d^4 X} \to d^2 \sqrt{X}` for
    :math:`d > 0` (``sympy.factor_terms`` on each radicand; SymPy then splits the root).

    Examples
    --------
    >>> import sympy as sp
    >>> from obslib.symbolic import ALPHA, D_IO, pull_out_of_roots
    >>> pull_out_of_roots(sp.sqrt(D_IO**4 + D_IO**4 * ALPHA**2))
    d_io**2*sqrt(alpha**2 + 1)
    """
    return as_expr(expr, "expr").replace(
        lambda e: e.is_Pow and e.exp.is_Rational and e.exp.q == 2,
        lambda e: sp.factor_terms(e.base) ** e.exp,
    )


@cache
def polar_ratio() -> sp.Expr:
    r""":math:`\lambda_{\min} / (\lambda_{\max} + u^2)` of :func:`polar_eigenvalues` after
    :func:`ratio_substitution`: :math:`d_{io}^2` leaves the square root
    (:func:`pull_out_of_roots`) and cancels (``sympy.cancel``), so :math:`d_{io}` and
    :math:`\theta_i` drop out.

    Examples
    --------
    >>> from obslib.symbolic import polar_ratio
    >>> sorted(str(s) for s in polar_ratio().free_symbols)
    ['alpha', 'q', 'theta']
    """
    lmin, lmax = polar_eigenvalues()
    ratio = (lmin / (lmax + U**2)).subs(ratio_substitution())
    return sp.cancel(pull_out_of_roots(ratio))


def cartesian_ratio_values(point: dict, digits: int | None = None) -> dict:
    r"""Theorem 4's :math:`\alpha`, :math:`\theta` and :math:`q` at a Cartesian point, as exact
    SymPy values.

    :math:`\alpha = |o - p_j| / |o - p_i|`, :math:`\theta = \operatorname{atan2}(p_j - o) -
    \operatorname{atan2}(p_i - o)` and :math:`q = u / |o - p_i|` (Eq. (8)).

    Parameters
    ----------
    point : dict
        Maps the symbols of :data:`CARTESIAN_ARGS` to numbers (rationals for exact evaluation).
    digits : int, optional
        If given, the same values are returned as mpmath numbers evaluated at ``digits``
        significant digits from the exact rational coordinates (what SymPy's ``N`` of the exact
        values gives, without building them symbolically).

    Raises
    ------
    ValueError
        If ``point`` lacks a coordinate, or a sensor sits on the target.

    Examples
    --------
    Target at the origin, sensors at :math:`(1, 0)` and :math:`(0, 2)`, speed 1:

    >>> from obslib.symbolic import (ALPHA, CARTESIAN_ARGS, Q, THETA,
    ...                              cartesian_ratio_values)
    >>> point = dict(zip(CARTESIAN_ARGS, [0, 0, 1, 0, 0, 2, 1]))
    >>> v = cartesian_ratio_values(point)
    >>> v[ALPHA], v[THETA], v[Q]
    (2, pi/2, 1)
    """
    point = as_mapping(point, "point")
    for k, x in point.items():
        if not isinstance(x, (int, float, sp.Rational, sp.Integer)) or isinstance(x, bool) or (
                isinstance(x, float) and not np.isfinite(x)):
            raise ArgumentTypeError(f"point: the value of {k} must be a finite number, got {x!r}")
    if digits is not None:
        digits = as_int(digits, "digits", 1)
    missing = [s for s in CARTESIAN_ARGS if s not in point]
    if missing:
        raise ValueError(f"point lacks values for {missing}")
    if digits is not None:
        import mpmath

        with mpmath.workdps(int(digits)):
            v = {k: mpmath.mpf(sp.Rational(x).p) / sp.Rational(x).q for k, x in point.items()}
            return _ratio_values(v, mpmath.hypot, mpmath.atan2)
    v = {k: sp.sympify(x) for k, x in point.items()}
    return _ratio_values(v, lambda x, y: sp.sqrt(x**2 + y**2), sp.atan2)


def _ratio_values(v: dict, hypot, atan2) -> dict:
    """Eq. (8)'s ``alpha``, ``theta``, ``q`` from coordinates ``v``, in the arithmetic of
    ``hypot`` and ``atan2`` (SymPy's exact one or mpmath's)."""
    vix, viy, vjx, vjy = v[PIX] - v[OX], v[PIY] - v[OY], v[PJX] - v[OX], v[PJY] - v[OY]
    di, dj = hypot(vix, viy), hypot(vjx, vjy)
    if di == 0 or dj == 0:
        raise ValueError("a sensor sits on the target (zero distance)")
    return {ALPHA: dj / di, THETA: atan2(vjy, vjx) - atan2(viy, vix), Q: v[U] / di}


@cache
def theorem4_residuals() -> dict[str, sp.Expr]:
    r"""Every comparison of the derivation of Theorem 4 with the paper, as a residual that is 0
    exactly when the two agree (computed once).

    ``"polar matrix"``: derived minus printed polar :math:`O_{ij}^T O_{ij}`, entries expanded;
    ``"trace (mod cos^2 + sin^2 = 1)"`` and ``"(lambda_max - lambda_min)^2 (mod ...)"``: the
    roots of the characteristic polynomial against Eq. (33), as :func:`pythagorean_remainder`;
    ``"lambda_min"``, ``"lambda_max"``: :func:`polar_eigenvalues` minus Eq. (33), expanded;
    ``"ratio"``: :func:`polar_ratio` minus Eq. (9) squared, cancelled; ``"cartesian
    discriminant"``: :func:`discriminant_cartesian`, the difference expanded.

    Examples
    --------
    >>> from obslib.symbolic import theorem4_residuals
    >>> r = theorem4_residuals()
    >>> r["polar matrix"], r["ratio"], r["cartesian discriminant"]
    ((0, 0, 0, 0), 0, 0)
    """
    gp = polar_gram()
    rmin, rmax = eigenvalues(gp)
    pmin, pmax = printed_eigenvalues()
    lmin, lmax = polar_eigenvalues()
    disc, paper = discriminant_cartesian()
    return {
        "polar matrix": tuple(sp.expand(e) for e in gp - printed_polar_gram()),
        "trace (mod cos^2 + sin^2 = 1)": pythagorean_remainder(rmin + rmax - (pmin + pmax)),
        "(lambda_max - lambda_min)^2 (mod cos^2 + sin^2 = 1)": pythagorean_remainder(
            (rmax - rmin) ** 2 - (pmax - pmin) ** 2
        ),
        "lambda_min": sp.expand(lmin - pmin),
        "lambda_max": sp.expand(lmax - pmax),
        "ratio": sp.cancel(polar_ratio() - theorem4_bound(squared=True)),
        "cartesian discriminant": sp.expand(disc - paper),
    }


def theorem4_radicand() -> sp.Expr:
    r""":math:`S^2 = 1 + \alpha^4 + 2 \alpha^2 \cos 2\theta` of Eq. (9).

    Examples
    --------
    At :math:`\theta = \pi/2` it is a perfect square, :math:`S = |1 - \alpha^2|`:

    >>> import sympy as sp
    >>> from obslib.symbolic import THETA, theorem4_radicand
    >>> sp.factor(theorem4_radicand().subs(THETA, sp.pi / 2))
    (alpha - 1)**2*(alpha + 1)**2
    """
    return 1 + ALPHA**4 + 2 * ALPHA**2 * _COS2


def theorem4_bound(squared: bool = False) -> sp.Expr:
    r"""Theorem 4 (Eq. (9)) in :math:`\alpha`, :math:`\theta = \theta_{ji}` and
    :math:`q = u / d_{io}`.

    :math:`\sqrt{(1 + \alpha^2 - S) / (1 + \alpha^2 + S + 2 q^2)}` with
    :math:`S = \sqrt{1 + \alpha^4 + 2 \alpha^2 \cos 2\theta}`; with ``squared=True`` the ratio
    itself.

    Examples
    --------
    Two sensors at right angles and equal distances from a static target: :math:`C^{-1} = 1`.

    >>> import sympy as sp
    >>> from obslib.symbolic import ALPHA, Q, THETA, theorem4_bound
    >>> at = {ALPHA: 1, THETA: sp.pi / 2, Q: 0}
    >>> theorem4_bound().subs(at)
    1
    """
    return _theorem4_bound(as_bool(squared, "squared"))


@cache
def _theorem4_bound(squared):
    ratio = _N / _D
    return ratio if squared else sp.sqrt(ratio)


def vanishes_with_radicals(expr: sp.Expr, radicals) -> bool:
    """Whether ``expr``, rational in the given square roots, is identically zero.

    Each radical :math:`\\sqrt{R_k}` (outermost first; :math:`R_k` may contain the later ones) is
    replaced by a symbol :math:`y_k`. Working outwards-in, the numerator of the expression
    (``sympy.together``) is a polynomial in :math:`y_k`; with :math:`y_k^2 = R_k` it splits into
    :math:`P_{even} + y_k P_{odd}`, and the expression vanishes if both parts vanish (checked
    recursively). At the end the numerator must expand to 0. A ``True`` answer is a proof (for
    all values where the radicals are defined and the denominators are nonzero); ``False`` means
    the test found no proof.

    Parameters
    ----------
    expr : sympy.Expr
        The expression to test.
    radicals : sequence of sympy.Expr
        Square roots (``sympy.sqrt(...)``) occurring in ``expr``, outermost first.

    Raises
    ------
    ValueError
        If a radical is not a square root, or the radicals are not listed outermost first.

    Examples
    --------
    >>> import sympy as sp
    >>> from obslib.symbolic import ALPHA, vanishes_with_radicals
    >>> r = sp.sqrt(1 + ALPHA**2)
    >>> vanishes_with_radicals(1 / (r - ALPHA) - (r + ALPHA), [r])
    True
    >>> vanishes_with_radicals(r - ALPHA - 1, [r])
    False
    """
    if isinstance(radicals, (str, bytes)) or not isinstance(radicals, (list, tuple)):
        raise ArgumentTypeError(f"radicals must be a list of square roots, got {radicals!r}")
    radicals = [as_expr(r, "radicals") for r in radicals]
    if not all(r.is_Pow and r.exp == sp.S.Half for r in radicals):
        raise ValueError("radicals must be square roots")
    for k, r in enumerate(radicals):
        if any(r.base.has(outer) for outer in radicals[:k]):
            raise ValueError("radicals must be listed outermost first")
    ys = [sp.Dummy(f"y{k}") for k in range(len(radicals))]
    e = as_expr(expr, "expr")
    for r, y in zip(radicals, ys):
        e = e.subs(r, y)
    bases = [r.base.subs(dict(zip(radicals[k + 1:], ys[k + 1:]))) for k, r in enumerate(radicals)]

    def rec(x, k):
        num = sp.numer(sp.together(x))
        if k == len(ys):
            return sp.expand(num) == 0
        y, b = ys[k], bases[k]
        if not num.has(y):
            return rec(num, k + 1)
        terms = sp.Poly(num, y).terms()
        even = sp.Add(*[cf * b ** (m // 2) for (m,), cf in terms if m % 2 == 0])
        odd = sp.Add(*[cf * b ** (m // 2) for (m,), cf in terms if m % 2 == 1])
        return rec(even, k + 1) and rec(odd, k + 1)

    return rec(e, 0)

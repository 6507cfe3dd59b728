r"""SymPy derivations for the two-sensor closed form (Theorem 4) and its extremes (Theorem 5).

The paper states the pair bound in polar form (Theorem 4, Eq. (9)):

.. math::

   C^{-1}(O_{ij}(o, u_o)) = \sqrt{\frac{1 + \alpha^2 - S}{1 + \alpha^2 + S + 2 u^2 / d_{io}^2}},
   \quad S = \sqrt{1 + \alpha^4 + 2 \alpha^2 \cos 2\theta_{ji}}, \quad \alpha = d_{jo} / d_{io},

and proves it (appendix, proof of Theorem 4) from ``O_ij(o)^T O_ij(o)`` written in Cartesian
coordinates (Eq. (32)) and in the polar coordinates of Eq. (8). Theorem 5 locates its extremes
from derivatives printed in its proof. This module rebuilds every one of those objects with
SymPy, so that the notebook ``02_pair_closed_form`` and the tests can compare the paper's printed
expressions with the derived ones:

* :func:`cartesian_gram`, :func:`polar_gram` and :func:`eigenvalues` derive the matrix and its
  eigenvalues (roots of the characteristic polynomial); :func:`polar_eigenvalues` rewrites them
  with SymPy's double-angle rules, :func:`pythagorean_remainder` decides trigonometric polynomial
  identities exactly (remainder modulo ``cos^2 + sin^2 = 1``), and :func:`polar_ratio` reduces
  ``lambda_min / (lambda_max + u^2)`` to Theorem 4's variables. :func:`printed_cartesian_gram`,
  :func:`printed_polar_gram` and :func:`printed_eigenvalues` are the appendix's printed versions.
* :func:`theorem4_bound` is Eq. (9) in ``alpha``, ``theta`` and ``q = u_max / d_io``;
  :func:`vanishes_with_radicals` proves an expression with nested square roots (such as ``S`` and
  ``C`` of Eq. (9)) identically zero by polynomial remainders, and :func:`pull_out_of_roots`
  moves common factors out of square roots.
* :func:`dbound_dtheta`, :func:`dbound_dalpha` (SymPy's derivatives), their factored forms
  :func:`dbound_dtheta_closed`, :func:`dbound_dalpha_closed`, the stationarity condition
  :func:`stationarity_alpha` and the paper's printed derivatives (``printed_*``).
* :func:`alpha_star_squared` derives the maximising ``alpha`` for a fixed ``theta`` in closed
  form (not in the paper); :func:`alpha_star_closed` is its simplified form.
* :func:`weyl_2x2_slacks` writes the Weyl inequalities of the proof of Theorem 1 for 2x2
  symmetric matrices, each next to an equivalent triangle inequality.
* :func:`lambdify_expr` turns an expression into a NumPy (or mpmath) function
  (:func:`obslib.studies.pair_form.max_difference_at_rational_points` compares two expressions
  at random rational points, evaluated at high precision).

All expressions are built on the module's symbols (:data:`OX`, ..., :data:`Q`) and cached.
Identities are established by polynomial arithmetic (``expand``, ``cancel``, ``sympy.Poly``
remainders), not by the heuristic ``sympy.simplify``: an expansion that returns 0 is a proof.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import sympy as sp
from sympy.simplify.fu import TR5, TR8, TR10i

__all__ = [
    "OX", "OY", "PIX", "PIY", "PJX", "PJY", "U", "D_IO", "D_JO", "THETA_I", "THETA_J",
    "ALPHA", "THETA", "Q", "S_SYM", "C_SYM", "D_SYM", "CARTESIAN_ARGS", "POLAR_ARGS", "RATIO_ARGS",
    "relative_rows", "cartesian_gram", "printed_cartesian_gram", "polar_substitution",
    "polar_gram", "printed_polar_gram", "eigenvalues", "cartesian_eigenvalues", "polar_eigenvalues",
    "printed_eigenvalues", "pythagorean_remainder", "polar_ratio", "vanishes_with_radicals",
    "pull_out_of_roots", "stationarity_alpha_at_1", "max_value_exact", "theorem4_residuals",
    "closed_forms_hold",
    "bound_from_eigenvalues", "ratio_substitution", "cartesian_ratio_values",
    "discriminant_cartesian", "theorem4_bound", "theorem4_radicand", "dbound_dtheta",
    "dbound_dtheta_closed", "dbound_dtheta_at_zero", "dbound_dalpha", "dbound_dalpha_closed",
    "stationarity_alpha",
    "printed_stationarity_alpha", "printed_dbound_dalpha", "printed_dbound_dalpha_halfpi",
    "printed_max_halfpi", "bound_halfpi_piecewise", "alpha_star_squared", "alpha_star_closed",
    "weyl_2x2_slacks", "lambdify_expr", "latex_eq",
]  # fmt: skip

# --- symbols ---------------------------------------------------------------------------------
#: Cartesian coordinates of the target ``o`` and of the sensors ``p_i``, ``p_j`` (Eq. (31)).
OX, OY, PIX, PIY, PJX, PJY = sp.symbols("o_x o_y p_ix p_iy p_jx p_jy", real=True)
#: The target's speed (``u_o``, or its bound ``u_max``).
U = sp.Symbol("u", nonnegative=True)
#: Polar coordinates of Eq. (8): ``p_i - o = d_io (cos theta_i, sin theta_i)``, likewise for j.
D_IO, D_JO = sp.symbols("d_io d_jo", positive=True)
THETA_I, THETA_J = sp.symbols("theta_i theta_j", real=True)
#: Theorem 4's variables: ``alpha = d_jo / d_io``, ``theta = theta_ji = theta_j - theta_i``,
#: ``q = u / d_io``.
ALPHA = sp.Symbol("alpha", positive=True)
THETA = sp.Symbol("theta", real=True)
Q = sp.Symbol("q", nonnegative=True)

CARTESIAN_ARGS = (OX, OY, PIX, PIY, PJX, PJY, U)
POLAR_ARGS = (D_IO, D_JO, THETA_I, THETA_J, U)
RATIO_ARGS = (ALPHA, THETA, Q)

#: Abbreviations for display: ``S`` of Eq. (9), ``C`` the bound, ``D`` its denominator.
S_SYM, C_SYM, D_SYM = sp.symbols("S C D", positive=True)

_COS2 = sp.cos(2 * THETA)
#: ``S = sqrt(1 + alpha^4 + 2 alpha^2 cos 2 theta)`` of Eq. (9).
_S = sp.sqrt(1 + ALPHA**4 + 2 * ALPHA**2 * _COS2)
_N = 1 + ALPHA**2 - _S  # numerator of the squared bound (2 lambda_min / d_io^2)
_D = 1 + ALPHA**2 + _S + 2 * Q**2  # denominator (2 (lambda_max + u^2) / d_io^2)


# --- Theorem 4: the matrix and its eigenvalues ------------------------------------------------
def relative_rows() -> sp.Matrix:
    """``O_ij(o)``: the rows ``o - p_i`` and ``o - p_j`` (appendix, Eq. (31))."""
    return sp.Matrix([[OX - PIX, OY - PIY], [OX - PJX, OY - PJY]])


@lru_cache(maxsize=None)
def cartesian_gram() -> sp.Matrix:
    """``O_ij(o)^T O_ij(o)`` in Cartesian coordinates, derived (the true Eq. (32))."""
    o = relative_rows()
    return (o.T * o).applyfunc(sp.factor_terms)


def printed_cartesian_gram() -> sp.Matrix:
    """The matrix the appendix prints for ``O_ij^T O_ij`` in the proof of Theorem 4 (Eq. (32)).

    Transcribed entry by entry from the paper::

        [[(o_x - p_ix)^2,               (o_x - p_jx)(o_y - p_iy)],
         [(o_y - p_iy)(o_x - p_jx),     (o_y - p_jy)^2          ]]
    """
    return sp.Matrix(
        [
            [(OX - PIX) ** 2, (OX - PJX) * (OY - PIY)],
            [(OY - PIY) * (OX - PJX), (OY - PJY) ** 2],
        ]
    )


def polar_substitution() -> dict:
    """Eq. (8): ``p_ix - o_x = d_io cos theta_i``, ``p_iy - o_y = d_io sin theta_i``, same for j."""
    return {
        PIX: OX + D_IO * sp.cos(THETA_I),
        PIY: OY + D_IO * sp.sin(THETA_I),
        PJX: OX + D_JO * sp.cos(THETA_J),
        PJY: OY + D_JO * sp.sin(THETA_J),
    }


@lru_cache(maxsize=None)
def polar_gram() -> sp.Matrix:
    """``O_ij^T O_ij`` after the polar substitution of Eq. (8), derived."""
    return cartesian_gram().subs(polar_substitution()).applyfunc(sp.expand)


def printed_polar_gram() -> sp.Matrix:
    """The polar matrix printed in the proof of Theorem 4 (unnumbered, after Eq. (32))."""
    ci, si, cj, sj = sp.cos(THETA_I), sp.sin(THETA_I), sp.cos(THETA_J), sp.sin(THETA_J)
    off = D_IO**2 * si * ci + D_JO**2 * sj * cj
    return sp.Matrix(
        [
            [D_IO**2 * ci**2 + D_JO**2 * cj**2, off],
            [D_JO**2 * sj * cj + D_IO**2 * si * ci, D_IO**2 * si**2 + D_JO**2 * sj**2],
        ]
    )


_LAMBDA = sp.Dummy("lambda")


def _eigen_parts(m: sp.Matrix) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """``(tr m, a - c, 2 b)`` for ``m = [[a, b], [b, c]]``, after deriving the eigenvalues.

    SymPy forms the characteristic polynomial ``det(lambda I - m)`` as a polynomial in
    ``lambda``; for the monic quadratic ``lambda^2 + B lambda + C`` the quadratic formula gives
    ``(-B -+ sqrt(B^2 - 4 C)) / 2``. The checks ``-B = tr m`` and
    ``B^2 - 4 C = (a - c)^2 + (2 b)^2`` are polynomial identities (expanded to zero), so the
    roots are ``(tr m -+ |v|) / 2`` with ``v = (a - c, 2 b)``.
    """
    if not isinstance(m, sp.MatrixBase) or m.shape != (2, 2):
        shape = getattr(m, "shape", "")
        raise ValueError(f"expected a 2x2 SymPy matrix, got {type(m).__name__} {shape}")
    if sp.expand(m[0, 1] - m[1, 0]) != 0:
        raise ValueError("matrix is not symmetric: m[0, 1] != m[1, 0]")
    char = sp.Poly((_LAMBDA * sp.eye(2) - m).det(method="berkowitz"), _LAMBDA)
    one, b, c = char.all_coeffs()
    tr, v0, v1 = m[0, 0] + m[1, 1], m[0, 0] - m[1, 1], 2 * m[0, 1]
    if one != 1 or sp.expand(tr + b) != 0 or sp.expand(b**2 - 4 * c - v0**2 - v1**2) != 0:
        raise RuntimeError("characteristic polynomial is not lambda^2 - tr lambda + det")
    return tr, v0, v1


def eigenvalues(m: sp.Matrix) -> tuple[sp.Expr, sp.Expr]:
    """``(lambda_min, lambda_max)`` of a symbolic symmetric 2x2 matrix ``[[a, b], [b, c]]``.

    Derived as the roots of the characteristic polynomial (see :func:`_eigen_parts`):
    ``(tr -+ sqrt((a - c)^2 + 4 b^2)) / 2``; the root with ``- sqrt`` is the smaller.

    Raises
    ------
    ValueError
        If ``m`` is not a symmetric 2x2 SymPy matrix.
    RuntimeError
        If the characteristic polynomial check fails (it cannot for a symmetric matrix).
    """
    tr, v0, v1 = _eigen_parts(m)
    root = sp.sqrt(v0**2 + v1**2)
    return (tr - root) / 2, (tr + root) / 2


@lru_cache(maxsize=None)
def cartesian_eigenvalues() -> tuple[sp.Expr, sp.Expr]:
    """:func:`eigenvalues` of :func:`cartesian_gram`, cached."""
    return eigenvalues(cartesian_gram())


def _double_angle(expr: sp.Expr) -> sp.Expr:
    """Products of ``sin``/``cos`` rewritten with double angles (SymPy's ``fu`` rules: TR8
    product-to-sum, TR5 ``sin^2 = 1 - cos^2``, TR10i sum-to-angle-difference)."""
    return TR10i(sp.expand(TR5(sp.expand(TR8(expr)))))


@lru_cache(maxsize=None)
def polar_eigenvalues() -> tuple[sp.Expr, sp.Expr]:
    """:func:`eigenvalues` of :func:`polar_gram`, in double-angle form, cached.

    In polar form ``v = d_io^2 (cos 2 theta_i, sin 2 theta_i) + d_jo^2 (cos 2 theta_j,
    sin 2 theta_j)`` and ``tr = d_io^2 + d_jo^2`` (SymPy's ``fu`` rules applied to the derived
    ``tr`` and ``v``), so ``|v|^2`` becomes ``d_io^4 + d_jo^4 + 2 d_io^2 d_jo^2
    cos(2 theta_i - 2 theta_j)``. :func:`pythagorean_remainder` confirms the rewriting
    independently (the notebook and the audit do).
    """
    tr, v0, v1 = _eigen_parts(polar_gram())
    tr = sp.expand(TR5(sp.expand(tr)))
    v0, v1 = sp.expand(TR8(v0)), sp.expand(TR8(v1))
    root = sp.sqrt(_double_angle(v0**2 + v1**2))
    return (tr - root) / 2, (tr + root) / 2


def pythagorean_remainder(expr: sp.Expr) -> sp.Expr:
    """Remainder of a trigonometric polynomial in ``theta_i``, ``theta_j`` modulo
    ``cos^2 + sin^2 = 1``.

    Multiple angles are expanded (``sympy.expand_trig``), ``cos theta_k``, ``sin theta_k`` become
    polynomial variables, and the polynomial is reduced by the Groebner basis
    ``{c_i^2 + s_i^2 - 1, c_j^2 + s_j^2 - 1}`` (``sympy.reduced``). The remainder is a canonical
    form: it is 0 exactly when ``expr`` vanishes for all angles.
    """
    ci, si, cj, sj = sp.symbols("c_i s_i c_j s_j", real=True)
    rep = {sp.cos(THETA_I): ci, sp.sin(THETA_I): si, sp.cos(THETA_J): cj, sp.sin(THETA_J): sj}
    poly = sp.expand(sp.expand_trig(expr).subs(rep))
    if poly.has(THETA_I, THETA_J):
        raise ValueError("expr is not a polynomial in cos and sin of theta_i, theta_j")
    gens = (ci, cj, si, sj)
    return sp.reduced(poly, [ci**2 + si**2 - 1, cj**2 + sj**2 - 1], *gens)[1]


def printed_eigenvalues() -> tuple[sp.Expr, sp.Expr]:
    """The eigenvalues printed in the proof of Theorem 4 (Eq. (33)), in ``d_io, d_jo, theta_ji``."""
    root = sp.sqrt(D_IO**4 + D_JO**4 + 2 * D_IO**2 * D_JO**2 * sp.cos(2 * (THETA_J - THETA_I)))
    return (D_IO**2 + D_JO**2 - root) / 2, (D_IO**2 + D_JO**2 + root) / 2


def bound_from_eigenvalues(lmin, lmax, u=U) -> sp.Expr:
    """Theorem 1's bound ``sqrt(lambda_min / (lambda_max + u^2))`` (Eq. (21))."""
    return sp.sqrt(lmin / (lmax + u**2))


def ratio_substitution() -> dict:
    """From polar to Theorem 4's variables: ``d_jo = alpha d_io``, ``theta_j = theta_i + theta``,
    ``u = q d_io``."""
    return {D_JO: ALPHA * D_IO, THETA_J: THETA_I + THETA, U: Q * D_IO}


def pull_out_of_roots(expr: sp.Expr) -> sp.Expr:
    """Common factors moved out of every square root: ``sqrt(d^4 X) -> d^2 sqrt(X)`` for
    ``d > 0`` (``sympy.factor_terms`` on each radicand; SymPy then splits the root)."""
    return sp.sympify(expr).replace(
        lambda e: e.is_Pow and e.exp.is_Rational and e.exp.q == 2,
        lambda e: sp.factor_terms(e.base) ** e.exp,
    )


@lru_cache(maxsize=None)
def polar_ratio() -> sp.Expr:
    """``lambda_min / (lambda_max + u^2)`` of :func:`polar_eigenvalues` after
    :func:`ratio_substitution`: ``d_io^2`` leaves the square root (:func:`pull_out_of_roots`)
    and cancels (``sympy.cancel``), so ``d_io`` and ``theta_i`` drop out."""
    lmin, lmax = polar_eigenvalues()
    ratio = (lmin / (lmax + U**2)).subs(ratio_substitution())
    return sp.cancel(pull_out_of_roots(ratio))


def cartesian_ratio_values(point: dict, digits: int | None = None) -> dict:
    """Theorem 4's ``alpha``, ``theta`` and ``q`` at a Cartesian point, as exact SymPy values.

    ``alpha = |o - p_j| / |o - p_i|``, ``theta = atan2(p_j - o) - atan2(p_i - o)`` and
    ``q = u / |o - p_i|`` (Eq. (8)). ``point`` maps the symbols of :data:`CARTESIAN_ARGS` to
    numbers (rationals for exact evaluation). With ``digits``, the same values are returned as
    mpmath numbers evaluated at ``digits`` significant digits from the exact rational coordinates
    (what SymPy's ``N`` of the exact values gives, without building them symbolically).
    """
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


def discriminant_cartesian() -> tuple[sp.Expr, sp.Expr]:
    """``(lambda_max - lambda_min)^2`` from the Cartesian eigenvalues, and Eq. (33)'s radicand
    ``d_io^4 + d_jo^4 + 2 d_io^2 d_jo^2 cos(2 theta_ji)`` written in Cartesian coordinates.

    With ``v_i = o - p_i`` the angle enters through ``cos(2 theta_ji) = 2 cos^2 theta_ji - 1``
    and ``cos theta_ji = v_i . v_j / (|v_i| |v_j|)``, so the second expression is the polynomial
    ``|v_i|^4 + |v_j|^4 + 2 (2 (v_i . v_j)^2 - |v_i|^2 |v_j|^2)``. Both are polynomials; their
    difference expands to zero.
    """
    lmin, lmax = cartesian_eigenvalues()
    disc = sp.expand((lmax - lmin) ** 2)
    vi = (OX - PIX, OY - PIY)
    vj = (OX - PJX, OY - PJY)
    ri = vi[0] ** 2 + vi[1] ** 2
    rj = vj[0] ** 2 + vj[1] ** 2
    dot = vi[0] * vj[0] + vi[1] * vj[1]
    paper = ri**2 + rj**2 + 2 * (2 * dot**2 - ri * rj)
    return disc, sp.expand(paper)


@lru_cache(maxsize=None)
def theorem4_residuals() -> dict[str, sp.Expr]:
    """Every comparison of the derivation of Theorem 4 with the paper, as a residual that is 0
    exactly when the two agree (computed once; the notebook prints them, the audit tests them).

    ``"polar matrix"``: derived minus printed polar ``O_ij^T O_ij``, entries expanded;
    ``"trace (mod cos^2 + sin^2 = 1)"`` and ``"(lambda_max - lambda_min)^2 (mod ...)"``: the
    roots of the characteristic polynomial against Eq. (33), as :func:`pythagorean_remainder`;
    ``"lambda_min"``, ``"lambda_max"``: :func:`polar_eigenvalues` minus Eq. (33), expanded;
    ``"ratio"``: :func:`polar_ratio` minus Eq. (9) squared, cancelled; ``"cartesian
    discriminant"``: :func:`discriminant_cartesian`, the difference expanded.
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
    """``S^2 = 1 + alpha^4 + 2 alpha^2 cos(2 theta)`` of Eq. (9)."""
    return 1 + ALPHA**4 + 2 * ALPHA**2 * _COS2


@lru_cache(maxsize=None)
def theorem4_bound(squared: bool = False) -> sp.Expr:
    """Theorem 4 (Eq. (9)) in ``alpha``, ``theta = theta_ji`` and ``q = u / d_io``.

    ``sqrt((1 + alpha^2 - S) / (1 + alpha^2 + S + 2 q^2))`` with
    ``S = sqrt(1 + alpha^4 + 2 alpha^2 cos 2 theta)``; with ``squared=True`` the ratio itself.
    """
    ratio = _N / _D
    return ratio if squared else sp.sqrt(ratio)


def vanishes_with_radicals(expr: sp.Expr, radicals) -> bool:
    """Whether ``expr``, rational in the given square roots, is identically zero.

    Each radical ``sqrt(R_k)`` (outermost first; ``R_k`` may contain the later ones) is replaced
    by a symbol ``y_k``. Working outwards-in, the numerator of the expression (``sympy.together``)
    is a polynomial in ``y_k``; with ``y_k^2 = R_k`` it splits into ``P_even + y_k P_odd``, and
    the expression vanishes if both parts vanish (checked recursively). At the end the numerator
    must expand to 0. A ``True`` answer is a proof (for all values where the radicals are defined
    and the denominators are nonzero); ``False`` means the test found no proof.

    Parameters
    ----------
    expr : sympy.Expr
    radicals : sequence of sympy.Expr
        Square roots (``sympy.sqrt(...)``) occurring in ``expr``, outermost first.
    """
    radicals = [sp.sympify(r) for r in radicals]
    if not all(r.is_Pow and r.exp == sp.S.Half for r in radicals):
        raise ValueError("radicals must be square roots")
    for k, r in enumerate(radicals):
        if any(r.base.has(outer) for outer in radicals[:k]):
            raise ValueError("radicals must be listed outermost first")
    ys = [sp.Dummy(f"y{k}") for k in range(len(radicals))]
    e = sp.sympify(expr)
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


@lru_cache(maxsize=None)
def max_value_exact() -> sp.Expr:
    """``C^-1(alpha = 1, theta = pi/2) - 1 / sqrt(1 + q^2)`` with the common factor pulled out of
    the square roots (:func:`pull_out_of_roots`); 0 when Theorem 5's maximum value is right."""
    at = theorem4_bound().subs({ALPHA: 1, THETA: sp.pi / 2})
    return sp.expand(pull_out_of_roots(at) - 1 / sp.sqrt(1 + Q**2))


# --- Theorem 5: derivatives --------------------------------------------------------------------
@lru_cache(maxsize=None)
def dbound_dtheta() -> sp.Expr:
    """``d C^-1 / d theta`` of Theorem 4's expression, by SymPy (valid where ``S > 0`` and
    ``C^-1 > 0``)."""
    return sp.diff(theorem4_bound(), THETA)


def _parts(abbreviate: bool):
    if abbreviate:
        return S_SYM, C_SYM, D_SYM
    return _S, theorem4_bound(), _D


def dbound_dtheta_closed(abbreviate: bool = False) -> sp.Expr:
    """Factored form of :func:`dbound_dtheta`:
    ``2 alpha^2 sin(2 theta) (1 + alpha^2 + q^2) / (S C D^2)`` with ``D`` the denominator of Eq. (9)
    and ``C`` the bound itself (with ``abbreviate=True``, ``S``, ``C``, ``D`` stay symbols, for
    display).

    Its sign is that of ``sin 2 theta``, which suggests the paper's ``alpha^2 sin 2 theta = 0``.
    But ``C`` vanishes at ``theta = 0, pi`` (``C`` is proportional to ``|sin theta|`` there), so the
    quotient ``sin 2 theta / C`` does not: the one-sided slopes are ``+-alpha / sqrt((1 + alpha^2)
    (1 + alpha^2 + q^2))``, and at ``alpha = 1, theta = +-pi/2`` the factor ``S`` vanishes.
    """
    S, C, D = _parts(abbreviate)
    return 2 * ALPHA**2 * sp.sin(2 * THETA) * (1 + ALPHA**2 + Q**2) / (S * C * D**2)


def dbound_dtheta_at_zero() -> sp.Expr:
    """The right-hand slope ``lim_{theta -> 0+} d C^-1 / d theta = alpha / sqrt((1 + alpha^2)
    (1 + alpha^2 + q^2))`` (derived by hand from :func:`dbound_dtheta_closed`; the tests check it
    against the derivative evaluated at ``theta = 10^-12``). The left-hand slope is its negative,
    so ``theta = 0`` is a corner of ``C^-1``, not a stationary point."""
    return ALPHA / sp.sqrt((1 + ALPHA**2) * (1 + ALPHA**2 + Q**2))


@lru_cache(maxsize=None)
def dbound_dalpha() -> sp.Expr:
    """``d C^-1 / d alpha`` of Theorem 4's expression, by SymPy."""
    return sp.diff(theorem4_bound(), ALPHA)


def stationarity_alpha(abbreviate: bool = False) -> sp.Expr:
    """The numerator ``g`` of ``d C^-1 / d alpha`` (its sign and zeros for ``alpha > 0``)::

        g = (1 - alpha^2)(1 - cos 2 theta) + q^2 (S - (alpha^2 + cos 2 theta))

    which is the paper's Eq. (34). ``abbreviate=True`` keeps ``S`` as a symbol (display).
    """
    S = _parts(abbreviate)[0]
    return (1 - ALPHA**2) * (1 - _COS2) + Q**2 * (S - (ALPHA**2 + _COS2))


@lru_cache(maxsize=None)
def stationarity_alpha_at_1() -> sp.Expr:
    """Eq. (34) at ``alpha = 1``: ``S = sqrt(2 + 2 cos 2 theta)``; with ``cos 2 theta =
    2 cos^2 theta - 1`` (``sympy.expand_trig``) ``S = 2 |cos theta|``, and the bracket factors
    as ``2 q^2 (|cos theta| - cos^2 theta)``."""
    return sp.factor(sp.expand(sp.expand_trig(stationarity_alpha().subs(ALPHA, 1))))


@lru_cache(maxsize=None)
def closed_forms_hold() -> dict[str, bool]:
    """Whether SymPy's derivatives equal the factored forms, decided once by
    :func:`vanishes_with_radicals` with the radicals ``C`` (Eq. (9)) and ``S``:
    ``"dtheta"`` (:func:`dbound_dtheta` vs :func:`dbound_dtheta_closed`) and ``"dalpha"``
    (:func:`dbound_dalpha` vs :func:`dbound_dalpha_closed`)."""
    radicals = [theorem4_bound(), _S]
    return {
        "dtheta": vanishes_with_radicals(dbound_dtheta() - dbound_dtheta_closed(), radicals),
        "dalpha": vanishes_with_radicals(dbound_dalpha() - dbound_dalpha_closed(), radicals),
    }


def dbound_dalpha_closed(abbreviate: bool = False) -> sp.Expr:
    """Factored form of :func:`dbound_dalpha`: ``2 alpha g / (S C D^2)``, ``g`` of
    :func:`stationarity_alpha`; equivalently ``2 alpha g / (S sqrt(N) D^(3/2))`` with
    ``N = 1 + alpha^2 - S``. ``abbreviate=True`` keeps ``S``, ``C``, ``D`` as symbols (display)."""
    S, C, D = _parts(abbreviate)
    return 2 * ALPHA * stationarity_alpha(abbreviate) / (S * C * D**2)


def printed_stationarity_alpha() -> sp.Expr:
    """Eq. (34) as printed in the proof of Theorem 5 (left-hand side)."""
    c = sp.cos(2 * THETA)
    return (1 - ALPHA**2) * (1 - c) + Q**2 * (
        sp.sqrt(1 + ALPHA**4 + 2 * ALPHA**2 * c) - (ALPHA**2 + c)
    )


def printed_dbound_dalpha() -> sp.Expr:
    """The expression the proof of Theorem 5 sets to zero for ``d C^-1 / d alpha`` at a fixed
    ``theta`` (the display before Eq. (34)): ``alpha [Eq. (34)] / D^2.5``."""
    return ALPHA * printed_stationarity_alpha() / _D ** sp.Rational(5, 2)


def printed_dbound_dalpha_halfpi() -> sp.Expr:
    """The proof's ``d C^-1 / d alpha`` at ``theta = +-pi/2``:
    ``alpha (1 - alpha^2) / (1 + alpha^2 + |1 - alpha^2| + 2 q^2)^2.5``."""
    return ALPHA * (1 - ALPHA**2) / (
        1 + ALPHA**2 + sp.Abs(1 - ALPHA**2) + 2 * Q**2
    ) ** sp.Rational(5, 2)


def printed_max_halfpi() -> sp.Expr:
    """The proof's maximum over ``theta`` for fixed ``alpha`` (at ``theta = +-pi/2``):
    ``sqrt((1 + alpha^2 - |1 - alpha^2|) / (1 + alpha^2 + |1 - alpha^2| + 2 q^2))``."""
    a = sp.Abs(1 - ALPHA**2)
    return sp.sqrt((1 + ALPHA**2 - a) / (1 + ALPHA**2 + a + 2 * Q**2))


def bound_halfpi_piecewise() -> sp.Expr:
    """``C^-1`` at ``theta = +-pi/2`` without absolute values: ``alpha / sqrt(1 + q^2)`` for
    ``alpha <= 1`` and ``1 / sqrt(alpha^2 + q^2)`` for ``alpha >= 1`` (a corner at
    ``alpha = 1``)."""
    return sp.Piecewise(
        (ALPHA / sp.sqrt(1 + Q**2), ALPHA <= 1), (1 / sp.sqrt(ALPHA**2 + Q**2), True)
    )


@lru_cache(maxsize=None)
def alpha_star_squared() -> sp.Expr:
    """``alpha*^2``, the square of the maximising ``alpha`` for a fixed ``theta``, derived.

    Write ``t = alpha^2`` and ``c = cos 2 theta = 1 - 2 sigma`` with ``sigma = sin^2 theta > 0``.
    Eq. (34) is ``q^2 S = q^2 (t + c) + (t - 1)(1 - c)``; squaring gives a quadratic
    ``A t^2 + B t + C = 0`` (``sympy.Poly``), solved by the quadratic formula with the discriminant
    factored (``sympy.factor``). Of its two roots the larger one satisfies the unsquared equation
    (``t >= 1``, because ``S >= |t + c|`` makes the ``q^2`` term of Eq. (34) non-negative); the
    notebook and tests check this at rational points. The root is factored and returned in
    ``theta``, with ``sqrt(1 - sigma) = |cos theta|``.
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
    """Simplified form of the maximiser (beyond the paper)::

        alpha*(theta, q) = sqrt( sqrt(1 + q^2) (sqrt(1 + q^2) sin^2 theta + q^2 |cos theta|)
                                 / (q^2 + sin^2 theta) )

    ``alpha* = 1`` exactly when ``q = 0`` or ``cos theta = 0``; otherwise ``alpha* > 1``.
    """
    r = sp.sqrt(1 + Q**2)
    s2 = sp.sin(THETA) ** 2
    return sp.sqrt(r * (r * s2 + Q**2 * sp.Abs(sp.cos(THETA))) / (Q**2 + s2))


# --- Theorem 1: the Weyl step for 2x2 symmetric matrices ---------------------------------------
def weyl_2x2_slacks() -> dict[str, tuple[sp.Expr, sp.Expr]]:
    """The Weyl inequalities of the proof of Theorem 1 (Eq. (18)) for 2x2 symmetric ``X, Y``.

    ``X = [[a, b], [b, c]]``, ``Y = [[d, e], [e, f]]``, eigenvalues from :func:`eigenvalues`
    (roots of the characteristic polynomial) in ascending order. Each entry maps a name to
    ``(slack, triangle)``: ``slack >= 0`` is the inequality, and ``triangle`` is the same quantity
    written as a triangle-inequality slack ``(|x| + |y| - |x + y|) / 2`` in the plane, with
    ``v(X) = (a - c, 2 b)`` (so that ``lambda_{1,2}(X) = tr X / 2 -+ |v(X)| / 2``).
    ``slack - triangle`` expands to 0 (``sympy.expand`` brings the radicands, polynomials in
    ``a .. f``, to one canonical form).

    Names: ``"l1 >= l1+l1"`` (Weyl, i = j = 1), ``"l1 <= l1+l2"``, ``"l1 <= l2+l1"``
    (dual Weyl, the two arguments of the ``min``), ``"l2 <= l2+l2"`` (dual Weyl, i = j = 2),
    ``"l2 >= l1+l2"``, ``"l2 >= l2+l1"`` (Weyl, the two arguments of the ``max``).
    """
    a, b, c, d, e, f = sp.symbols("a b c d e f", real=True)
    x = sp.Matrix([[a, b], [b, c]])
    y = sp.Matrix([[d, e], [e, f]])
    x1, x2 = eigenvalues(x)
    y1, y2 = eigenvalues(y)
    s1, s2 = eigenvalues(x + y)

    def norm(v):
        return sp.sqrt(sp.expand(v[0] ** 2 + v[1] ** 2))

    def tri(p, r):
        return (norm(p) + norm(r) - norm((p[0] + r[0], p[1] + r[1]))) / 2

    vx = (a - c, 2 * b)
    vy = (d - f, 2 * e)
    vs = (vx[0] + vy[0], vx[1] + vy[1])
    neg = lambda v: (-v[0], -v[1])  # noqa: E731
    return {
        "l1 >= l1+l1": (s1 - (x1 + y1), tri(vx, vy)),
        "l1 <= l1+l2": ((x1 + y2) - s1, tri(vs, neg(vy))),
        "l1 <= l2+l1": ((x2 + y1) - s1, tri(vs, neg(vx))),
        "l2 <= l2+l2": ((x2 + y2) - s2, tri(vx, vy)),
        "l2 >= l1+l2": (s2 - (x1 + y2), tri(vs, neg(vx))),
        "l2 >= l2+l1": (s2 - (x2 + y1), tri(vs, neg(vy))),
    }


# --- evaluation helpers ------------------------------------------------------------------------
def lambdify_expr(expr, args, modules: str = "numpy", cse: bool = False):
    """A numerical function of ``args`` from a SymPy expression (``sympy.lambdify``).

    Parameters
    ----------
    expr : sympy.Expr
        Expression to evaluate.
    args : sequence of sympy.Symbol
        Positional arguments of the returned function, in order.
    modules : {"numpy", "mpmath"}
        Backend. ``"mpmath"`` evaluates at the working precision of ``mpmath.mp`` (use
        ``mpmath.workdps``) and takes scalars.
    cse : bool
        Evaluate common subexpressions once (``sympy.lambdify(..., cse=True)``): the same
        function, faster for large expressions.

    Raises
    ------
    ValueError
        If ``expr`` has free symbols not among ``args``, or ``modules`` is unknown.
    """
    if modules not in ("numpy", "mpmath"):
        raise ValueError(f"modules must be 'numpy' or 'mpmath', got {modules!r}")
    args = tuple(args)
    if not all(isinstance(a, sp.Symbol) for a in args):
        raise ValueError("args must be SymPy symbols")
    free = sp.sympify(expr).free_symbols - set(args)
    if free:
        names = sorted(str(s) for s in free)
        raise ValueError(f"expression has free symbols not in args: {names}")
    # the NumPy module itself as namespace: the same printer and functions as "numpy", without
    # lambdify's ``from numpy import *`` (which loads f2py, fft, polynomial, ... on first use)
    return sp.lambdify(args, expr, modules=[np] if modules == "numpy" else modules, cse=cse)


def latex_eq(lhs: str, expr) -> str:
    """``lhs = <LaTeX of expr>``, for display with ``IPython.display.Math``."""
    return f"{lhs} = {sp.latex(expr)}"

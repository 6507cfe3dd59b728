r"""The symbols and shared private pieces of the SymPy derivations (Eqs. (8), (9), (31)).

The public symbols are re-exported by :mod:`obslib.symbolic`; the private expressions (``_S``,
``_N``, ``_D`` of Eq. (9)) and the eigenvalue derivation :func:`_eigen_parts` are shared by its
modules through this private module only.
"""

from __future__ import annotations

import sympy as sp
from sympy.simplify.fu import TR5, TR8, TR10i

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

#: Arguments of the Cartesian expressions, in the order of :func:`obslib.symbolic.lambdify_expr`.
CARTESIAN_ARGS = (OX, OY, PIX, PIY, PJX, PJY, U)
#: Arguments of the polar expressions.
POLAR_ARGS = (D_IO, D_JO, THETA_I, THETA_J, U)
#: Arguments of Theorem 4's expression.
RATIO_ARGS = (ALPHA, THETA, Q)

#: Abbreviations for display: ``S`` of Eq. (9), ``C`` the bound, ``D`` its denominator.
S_SYM, C_SYM, D_SYM = sp.symbols("S C D", positive=True)

_COS2 = sp.cos(2 * THETA)
#: ``S = sqrt(1 + alpha^4 + 2 alpha^2 cos 2 theta)`` of Eq. (9).
_S = sp.sqrt(1 + ALPHA**4 + 2 * ALPHA**2 * _COS2)
_N = 1 + ALPHA**2 - _S  # numerator of the squared bound (2 lambda_min / d_io^2)
_D = 1 + ALPHA**2 + _S + 2 * Q**2  # denominator (2 (lambda_max + u^2) / d_io^2)

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


def _double_angle(expr: sp.Expr) -> sp.Expr:
    """Products of ``sin``/``cos`` rewritten with double angles (SymPy's ``fu`` rules: TR8
    product-to-sum, TR5 ``sin^2 = 1 - cos^2``, TR10i sum-to-angle-difference)."""
    return TR10i(sp.expand(TR5(sp.expand(TR8(expr)))))


def as_expr(value, name: str) -> sp.Expr:
    """``value`` as a SymPy expression (a number or an expression; not text, which SymPy would
    parse), or an :class:`obslib._validate.ArgumentTypeError` naming ``name``."""
    from .._validate import ArgumentTypeError

    if isinstance(value, (str, bytes, bool)) or value is None:
        raise ArgumentTypeError(f"{name} must be a SymPy expression, got {value!r}")
    try:
        out = sp.sympify(value, strict=True)
    except (sp.SympifyError, TypeError, ValueError):
        raise ArgumentTypeError(f"{name} must be a SymPy expression, got {value!r}") from None
    if not isinstance(out, sp.Expr):
        raise ArgumentTypeError(f"{name} must be a SymPy expression, got {value!r}")
    return out

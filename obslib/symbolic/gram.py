r"""The pair's Gram matrix :math:`O_{ij}^T O_{ij}` and its eigenvalues (proof of Theorem 4).

The appendix proves Theorem 4 from :math:`O_{ij}(o)^T O_{ij}(o)` written in Cartesian coordinates
(Eq. (32)) and in the polar coordinates of Eq. (8), and prints its eigenvalues (Eq. (33)). Each
derived object here has a ``printed_*`` twin transcribed from the paper, so that the two can be
compared by polynomial arithmetic.
"""

from __future__ import annotations

from functools import cache

import sympy as sp
from sympy.simplify.fu import TR5, TR8

from ._common import (
    D_IO,
    D_JO,
    OX,
    OY,
    PIX,
    PIY,
    PJX,
    PJY,
    THETA_I,
    THETA_J,
    _double_angle,
    _eigen_parts,
    as_expr,
)  # fmt: skip

__all__ = [
    "relative_rows", "cartesian_gram", "printed_cartesian_gram", "polar_substitution",
    "polar_gram", "printed_polar_gram", "eigenvalues", "cartesian_eigenvalues",
    "polar_eigenvalues", "pythagorean_remainder", "printed_eigenvalues", "discriminant_cartesian",
]  # fmt: skip


def relative_rows() -> sp.Matrix:
    r""":math:`O_{ij}(o)`: the rows :math:`o - p_i` and :math:`o - p_j` (appendix, Eq. (31)).

    Examples
    --------
    >>> from obslib.symbolic import relative_rows
    >>> relative_rows()
    Matrix([
    [o_x - p_ix, o_y - p_iy],
    [o_x - p_jx, o_y - p_jy]])
    """
    return sp.Matrix([[OX - PIX, OY - PIY], [OX - PJX, OY - PJY]])


@cache
def cartesian_gram() -> sp.Matrix:
    r""":math:`O_{ij}(o)^T O_{ij}(o)` in Cartesian coordinates, derived (the true Eq. (32)).

    Examples
    --------
    The diagonal holds the squared x and y offsets of both sensors, and the matrix is symmetric:

    >>> from obslib.symbolic import cartesian_gram
    >>> g = cartesian_gram()
    >>> g[0, 0]
    (o_x - p_ix)**2 + (o_x - p_jx)**2
    >>> g[0, 1] == g[1, 0]
    True
    """
    o = relative_rows()
    return (o.T * o).applyfunc(sp.factor_terms)


def printed_cartesian_gram() -> sp.Matrix:
    r"""The matrix the appendix prints for :math:`O_{ij}^T O_{ij}` in the proof of Theorem 4
    (Eq. (32)).

    Transcribed entry by entry from the paper::

        [[(o_x - p_ix)^2,               (o_x - p_jx)(o_y - p_iy)],
         [(o_y - p_iy)(o_x - p_jx),     (o_y - p_jy)^2          ]]

    Examples
    --------
    The printed diagonal lacks the second sensor's term of the derived one
    (:func:`cartesian_gram`):

    >>> from obslib.symbolic import cartesian_gram, printed_cartesian_gram
    >>> (cartesian_gram() - printed_cartesian_gram())[0, 0]
    (o_x - p_jx)**2
    """
    return sp.Matrix(
        [
            [(OX - PIX) ** 2, (OX - PJX) * (OY - PIY)],
            [(OY - PIY) * (OX - PJX), (OY - PJY) ** 2],
        ]
    )


def polar_substitution() -> dict:
    r"""Eq. (8): :math:`p_{ix} - o_x = d_{io} \cos\theta_i`, :math:`p_{iy} - o_y = d_{io}
    \sin\theta_i`, the same for :math:`j`.

    Examples
    --------
    >>> from obslib.symbolic import PIX, polar_substitution
    >>> polar_substitution()[PIX]
    d_io*cos(theta_i) + o_x
    """
    return {
        PIX: OX + D_IO * sp.cos(THETA_I),
        PIY: OY + D_IO * sp.sin(THETA_I),
        PJX: OX + D_JO * sp.cos(THETA_J),
        PJY: OY + D_JO * sp.sin(THETA_J),
    }


@cache
def polar_gram() -> sp.Matrix:
    r""":math:`O_{ij}^T O_{ij}` after the polar substitution of Eq. (8), derived.

    Examples
    --------
    The target's position drops out:

    >>> from obslib.symbolic import polar_gram
    >>> polar_gram()[0, 0]
    d_io**2*cos(theta_i)**2 + d_jo**2*cos(theta_j)**2
    """
    return cartesian_gram().subs(polar_substitution()).applyfunc(sp.expand)


def printed_polar_gram() -> sp.Matrix:
    r"""The polar matrix printed in the proof of Theorem 4 (unnumbered, after Eq. (32)).

    Examples
    --------
    It equals the derived :func:`polar_gram` entry by entry:

    >>> import sympy as sp
    >>> from obslib.symbolic import polar_gram, printed_polar_gram
    >>> [sp.expand(e) for e in polar_gram() - printed_polar_gram()]
    [0, 0, 0, 0]
    """
    ci, si, cj, sj = sp.cos(THETA_I), sp.sin(THETA_I), sp.cos(THETA_J), sp.sin(THETA_J)
    off = D_IO**2 * si * ci + D_JO**2 * sj * cj
    return sp.Matrix(
        [
            [D_IO**2 * ci**2 + D_JO**2 * cj**2, off],
            [D_JO**2 * sj * cj + D_IO**2 * si * ci, D_IO**2 * si**2 + D_JO**2 * sj**2],
        ]
    )


def eigenvalues(m: sp.Matrix) -> tuple[sp.Expr, sp.Expr]:
    r""":math:`(\lambda_{\min}, \lambda_{\max})` of a symbolic symmetric 2x2 matrix
    :math:`\begin{pmatrix} a & b \\ b & c \end{pmatrix}`.

    Derived as the roots of the characteristic polynomial:
    :math:`\bigl(\operatorname{tr} \mp \sqrt{(a - c)^2 + 4 b^2}\bigr) / 2`; the root with
    :math:`-\sqrt{\cdot}` is the smaller.

    Parameters
    ----------
    m : sympy.Matrix
        A symmetric 2x2 matrix.

    Returns
    -------
    tuple of sympy.Expr
        The smaller and the larger eigenvalue.

    Raises
    ------
    ValueError
        If ``m`` is not a symmetric 2x2 SymPy matrix.
    RuntimeError
        If the characteristic polynomial check fails (it cannot for a symmetric matrix).

    Examples
    --------
    >>> import sympy as sp
    >>> from obslib.symbolic import eigenvalues
    >>> eigenvalues(sp.Matrix([[2, 1], [1, 2]]))
    (1, 3)
    >>> eigenvalues(sp.Matrix([[1, 2], [0, 1]]))
    Traceback (most recent call last):
    ...
    ValueError: matrix is not symmetric: m[0, 1] != m[1, 0]
    """
    tr, v0, v1 = _eigen_parts(m)
    root = sp.sqrt(v0**2 + v1**2)
    return (tr - root) / 2, (tr + root) / 2


@cache
def cartesian_eigenvalues() -> tuple[sp.Expr, sp.Expr]:
    """:func:`eigenvalues` of :func:`cartesian_gram`, cached.

    Examples
    --------
    Their sum is the trace, the sum of the squared distances to the two sensors:

    >>> import sympy as sp
    >>> from obslib.symbolic import cartesian_eigenvalues, cartesian_gram
    >>> lmin, lmax = cartesian_eigenvalues()
    >>> sp.expand(lmin + lmax - cartesian_gram().trace())
    0
    """
    return eigenvalues(cartesian_gram())


@cache
def polar_eigenvalues() -> tuple[sp.Expr, sp.Expr]:
    r""":func:`eigenvalues` of :func:`polar_gram`, in double-angle form, cached.

    In polar form :math:`v = d_{io}^2 (\cos 2\theta_i, \sin 2\theta_i) + d_{jo}^2 (\cos 2\theta_j,
    \sin 2\theta_j)` and :math:`\operatorname{tr} = d_{io}^2 + d_{jo}^2` (SymPy's ``fu`` rules
    applied to the derived trace and :math:`v`), so :math:`|v|^2` becomes :math:`d_{io}^4 +
    d_{jo}^4 + 2 d_{io}^2 d_{jo}^2 \cos(2\theta_i - 2\theta_j)`. :func:`pythagorean_remainder`
    confirms the rewriting independently.

    Examples
    --------
    They are Eq. (33) as printed (:func:`printed_eigenvalues`):

    >>> import sympy as sp
    >>> from obslib.symbolic import polar_eigenvalues, printed_eigenvalues
    >>> pairs = zip(polar_eigenvalues(), printed_eigenvalues())
    >>> [sp.expand(a - b) for a, b in pairs]
    [0, 0]
    """
    tr, v0, v1 = _eigen_parts(polar_gram())
    tr = sp.expand(TR5(sp.expand(tr)))
    v0, v1 = sp.expand(TR8(v0)), sp.expand(TR8(v1))
    root = sp.sqrt(_double_angle(v0**2 + v1**2))
    return (tr - root) / 2, (tr + root) / 2


def pythagorean_remainder(expr: sp.Expr) -> sp.Expr:
    r"""Remainder of a trigonometric polynomial in :math:`\theta_i, \theta_j` modulo
    :math:`\cos^2 + \sin^2 = 1`.

    Multiple angles are expanded (``sympy.expand_trig``), :math:`\cos\theta_k, \sin\theta_k`
    become polynomial variables, and the polynomial is reduced by the Groebner basis
    :math:`\{c_i^2 + s_i^2 - 1, c_j^2 + s_j^2 - 1\}` (``sympy.reduced``). The remainder is a
    canonical form: it is 0 exactly when ``expr`` vanishes for all angles.

    Raises
    ------
    ValueError
        If ``expr`` is not a polynomial in the cosines and sines of :math:`\theta_i, \theta_j`.

    Examples
    --------
    >>> import sympy as sp
    >>> from obslib.symbolic import THETA_I, THETA_J, U, pythagorean_remainder
    >>> t = THETA_I
    >>> pythagorean_remainder(sp.cos(2 * t) - 1 + 2 * sp.sin(t) ** 2)
    0
    >>> t = THETA_J
    >>> pythagorean_remainder(sp.sin(t) ** 2 + sp.cos(t) ** 2 - 1 + U)
    u
    """
    ci, si, cj, sj = sp.symbols("c_i s_i c_j s_j", real=True)
    rep = {sp.cos(THETA_I): ci, sp.sin(THETA_I): si, sp.cos(THETA_J): cj, sp.sin(THETA_J): sj}
    poly = sp.expand(sp.expand_trig(as_expr(expr, "expr")).subs(rep))
    if poly.has(THETA_I, THETA_J):
        raise ValueError("expr is not a polynomial in cos and sin of theta_i, theta_j")
    gens = (ci, cj, si, sj)
    return sp.reduced(poly, [ci**2 + si**2 - 1, cj**2 + sj**2 - 1], *gens)[1]


def printed_eigenvalues() -> tuple[sp.Expr, sp.Expr]:
    r"""The eigenvalues printed in the proof of Theorem 4 (Eq. (33)), in :math:`d_{io}, d_{jo},
    \theta_{ji}`.

    Examples
    --------
    Their product is the determinant :math:`d_{io}^2 d_{jo}^2 \sin^2\theta_{ji}`:

    >>> import sympy as sp
    >>> from obslib.symbolic import (D_IO, D_JO, THETA_I, THETA_J,
    ...                              printed_eigenvalues, pythagorean_remainder)
    >>> lmin, lmax = printed_eigenvalues()
    >>> det = (D_IO * D_JO * sp.sin(THETA_J - THETA_I)) ** 2
    >>> pythagorean_remainder(lmin * lmax - det)
    0
    """
    root = sp.sqrt(D_IO**4 + D_JO**4 + 2 * D_IO**2 * D_JO**2 * sp.cos(2 * (THETA_J - THETA_I)))
    return (D_IO**2 + D_JO**2 - root) / 2, (D_IO**2 + D_JO**2 + root) / 2


def discriminant_cartesian() -> tuple[sp.Expr, sp.Expr]:
    r""":math:`(\lambda_{\max} - \lambda_{\min})^2` from the Cartesian eigenvalues, and Eq. (33)'s
    radicand :math:`d_{io}^4 + d_{jo}^4 + 2 d_{io}^2 d_{jo}^2 \cos 2\theta_{ji}` written in
    Cartesian coordinates.

    With :math:`v_i = o - p_i` the angle enters through :math:`\cos 2\theta_{ji} = 2
    \cos^2\theta_{ji} - 1` and :math:`\cos\theta_{ji} = v_i \cdot v_j / (|v_i| |v_j|)`, so the
    second expression is the polynomial :math:`|v_i|^4 + |v_j|^4 + 2 (2 (v_i \cdot v_j)^2 -
    |v_i|^2 |v_j|^2)`. Both are polynomials; their difference expands to zero.

    Examples
    --------
    >>> from obslib.symbolic import discriminant_cartesian
    >>> disc, paper = discriminant_cartesian()
    >>> disc - paper
    0
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

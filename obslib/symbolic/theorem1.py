r"""The Weyl step of the proof of Theorem 1 (Eq. (18)) for 2x2 symmetric matrices, with SymPy."""

from __future__ import annotations

import sympy as sp

from .gram import eigenvalues

__all__ = ["weyl_2x2_slacks"]


def weyl_2x2_slacks() -> dict[str, tuple[sp.Expr, sp.Expr]]:
    r"""The Weyl inequalities of the proof of Theorem 1 (Eq. (18)) for 2x2 symmetric
    :math:`X, Y`.

    :math:`X = \begin{pmatrix} a & b \\ b & c \end{pmatrix}`, :math:`Y = \begin{pmatrix} d & e \\
    e & f \end{pmatrix}`, eigenvalues from :func:`eigenvalues` (roots of the characteristic
    polynomial) in ascending order. Each entry maps a name to ``(slack, triangle)``:
    ``slack >= 0`` is the inequality, and ``triangle`` is the same quantity written as a
    triangle-inequality slack :math:`(|x| + |y| - |x + y|) / 2` in the plane, with :math:`v(X) =
    (a - c, 2 b)` (so that :math:`\lambda_{1,2}(X) = \operatorname{tr} X / 2 \mp |v(X)| / 2`).
    ``slack - triangle`` expands to 0 (``sympy.expand`` brings the radicands, polynomials in
    :math:`a, \dots, f`, to one canonical form).

    Names: ``"l1 >= l1+l1"`` (Weyl, i = j = 1), ``"l1 <= l1+l2"``, ``"l1 <= l2+l1"``
    (dual Weyl, the two arguments of the ``min``), ``"l2 <= l2+l2"`` (dual Weyl, i = j = 2),
    ``"l2 >= l1+l2"``, ``"l2 >= l2+l1"`` (Weyl, the two arguments of the ``max``).

    Examples
    --------
    >>> import sympy as sp
    >>> from obslib.symbolic import weyl_2x2_slacks
    >>> slacks = weyl_2x2_slacks()
    >>> len(slacks), all(sp.expand(s - t) == 0 for s, t in slacks.values())
    (6, True)
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

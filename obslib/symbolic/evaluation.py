r"""Evaluation and display of the SymPy expressions: NumPy or mpmath functions, and LaTeX."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import sympy as sp

from .._validate import ArgumentTypeError, as_bool, as_callable, as_int, as_mapping, as_real, as_str
from ._common import as_expr

__all__ = ["lambdify_expr", "latex_eq", "max_difference_at_rational_points"]


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

    Examples
    --------
    Theorem 4's bound for two sensors at right angles and equal distances, static target:

    >>> import numpy as np
    >>> from obslib.symbolic import (ALPHA, Q, RATIO_ARGS, lambdify_expr,
    ...                              theorem4_bound)
    >>> f = lambdify_expr(theorem4_bound(), RATIO_ARGS)
    >>> round(float(f(1.0, np.pi / 2, 0.0)), 12)
    1.0
    >>> lambdify_expr(ALPHA + Q, [ALPHA])
    Traceback (most recent call last):
    ...
    ValueError: expression has free symbols not in args: ['q']
    """
    if as_str(modules, "modules") not in ("numpy", "mpmath"):
        raise ValueError(f"modules must be 'numpy' or 'mpmath', got {modules!r}")
    cse = as_bool(cse, "cse")
    if isinstance(args, (str, bytes)) or not isinstance(args, (list, tuple)) or not all(
            isinstance(a, sp.Symbol) for a in args):
        raise ValueError("args must be SymPy symbols")
    args = tuple(args)
    free = as_expr(expr, "expr").free_symbols - set(args)
    if free:
        names = sorted(str(s) for s in free)
        raise ValueError(f"expression has free symbols not in args: {names}")
    # the NumPy module itself as namespace: the same printer and functions as "numpy", without
    # lambdify's ``from numpy import *`` (which loads f2py, fft, polynomial, ... on first use)
    return sp.lambdify(args, expr, modules=[np] if modules == "numpy" else modules, cse=cse)


def latex_eq(lhs: str, expr) -> str:
    r"""``lhs = <LaTeX of expr>``, for display with ``IPython.display.Math``.

    Examples
    --------
    >>> from obslib.symbolic import ALPHA, latex_eq
    >>> latex_eq("C^{-1}", ALPHA / 2)
    'C^{-1} = \\frac{\\alpha}{2}'
    """
    return f"{as_str(lhs, 'lhs')} = {sp.latex(as_expr(expr, 'expr'))}"


def _rational(rng: np.random.Generator, lo: float, hi: float, den: int = 997):
    k = int(rng.integers(int(np.ceil(lo * den)), int(np.floor(hi * den)) + 1))
    f = Fraction(k, den)
    return sp.Rational(f.numerator, f.denominator)


def max_difference_at_rational_points(
    lhs, rhs, ranges: dict, n_points: int, seed: int = 0, digits: int = 50, point_map=None
) -> float:
    """Largest ``|lhs - rhs|`` over random rational points, evaluated at ``digits`` digits.

    Where SymPy cannot simplify ``lhs - rhs`` to zero, equality is decided by evaluation at
    exact rational points with ``digits`` significant digits (mpmath): differences of order
    ``10^-digits`` (relative to the size of the terms) mean the two expressions agree, while a
    wrong expression differs by order one.

    Parameters
    ----------
    lhs, rhs : sympy.Expr
        The two expressions.
    ranges : dict
        ``symbol -> (lo, hi)``; each point draws every symbol as a rational ``k / 997`` in
        ``[lo, hi]``.
    n_points : int
        Number of points (positive).
    seed : int
        Seed of the draw.
    digits : int
        Working precision in decimal digits, at least 15.
    point_map : callable, optional
        ``point -> dict`` of extra substitutions computed from the drawn point, e.g.
        :func:`obslib.symbolic.cartesian_ratio_values`: exact SymPy values, evaluated to
        ``digits + 10`` digits, or mpmath numbers already evaluated (at ``digits + 10`` digits,
        say), used as they are.

    Returns
    -------
    float
        The largest absolute difference; a point where the difference is not finite counts
        as infinity.

    Examples
    --------
    >>> import sympy as sp
    >>> from obslib.symbolic import THETA
    >>> from obslib.symbolic.evaluation import max_difference_at_rational_points
    >>> expr = sp.sin(THETA)**2 + sp.cos(THETA)**2
    >>> d = max_difference_at_rational_points(expr, 1, {THETA: (0.0, 3.0)},
    ...                                       n_points=5)
    >>> d < 1e-40
    True
    """
    import mpmath

    n_points = as_int(n_points, "n_points", 1)
    digits = as_int(digits, "digits", 15)
    rng = np.random.default_rng(as_int(seed, "seed", 0))
    for s, r in as_mapping(ranges, "ranges").items():
        if not (isinstance(s, sp.Symbol) and isinstance(r, (tuple, list)) and len(r) == 2
                and all(np.isfinite(as_real(x, "ranges")) for x in r) and r[0] < r[1]):
            raise ValueError(f"ranges: bad range for {s}: {r!r}")
    if point_map is not None:
        as_callable(point_map, "point_map")
    try:
        diff = sp.sympify(lhs, strict=True) - sp.sympify(rhs, strict=True)
    except (sp.SympifyError, TypeError):
        raise ArgumentTypeError("lhs and rhs must be SymPy expressions or numbers") from None
    points = []
    for _ in range(int(n_points)):
        point = {s: _rational(rng, *r) for s, r in ranges.items()}
        extra = point_map(point) if point_map is not None else {}
        points.append((point, extra))
    known = set(points[0][0]) | set(points[0][1])
    free = diff.free_symbols - known
    if free:
        raise ValueError(f"no range for symbols {sorted(map(str, free))}")
    syms = sorted(diff.free_symbols, key=str)
    f = sp.lambdify(syms, diff, modules="mpmath", cse=True)
    worst = mpmath.mpf(0)
    with mpmath.workdps(digits):
        for point, extra in points:
            vals = {s: mpmath.mpf(r.p) / r.q for s, r in point.items()}
            vals.update({
                s: v if isinstance(v, mpmath.mpf) else mpmath.mpf(sp.N(v, digits + 10))
                for s, v in extra.items()
            })
            val = abs(f(*[vals[s] for s in syms]))
            if not mpmath.isfinite(val):
                return float("inf")
            worst = max(worst, val)
    return float(worst)

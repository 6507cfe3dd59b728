r"""Evaluation and display of the SymPy expressions: NumPy or mpmath functions, and LaTeX."""

from __future__ import annotations

import numpy as np
import sympy as sp

__all__ = ["lambdify_expr", "latex_eq"]


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
    >>> from obslib import symbolic as sy
    >>> f = sy.lambdify_expr(sy.theorem4_bound(), sy.RATIO_ARGS)
    >>> round(float(f(1.0, np.pi / 2, 0.0)), 12)
    1.0
    >>> sy.lambdify_expr(sy.ALPHA + sy.Q, [sy.ALPHA])
    Traceback (most recent call last):
    ...
    ValueError: expression has free symbols not in args: ['q']
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
    r"""``lhs = <LaTeX of expr>``, for display with ``IPython.display.Math``.

    Examples
    --------
    >>> from obslib import symbolic as sy
    >>> sy.latex_eq("C^{-1}", sy.ALPHA / 2)
    'C^{-1} = \\frac{\\alpha}{2}'
    """
    return f"{lhs} = {sp.latex(expr)}"

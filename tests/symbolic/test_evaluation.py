"""lambdify_expr (obslib.symbolic.evaluation): validation, and NumPy against mpmath evaluation.
"""

import mpmath
import numpy as np
import pytest

from obslib import symbolic as sy

A, TH, Q = sy.ALPHA, sy.THETA, sy.Q


def test_lambdify_expr_validates():
    with pytest.raises(ValueError, match="free symbols"):
        sy.lambdify_expr(sy.theorem4_bound(), (A, TH))
    with pytest.raises(ValueError, match="modules"):
        sy.lambdify_expr(A, (A,), modules="tensorflow")
    with pytest.raises(ValueError, match="symbols"):
        sy.lambdify_expr(A, ("alpha",))


def test_lambdify_numpy_evaluates_arrays_and_piecewise():
    f = sy.lambdify_expr(sy.bound_halfpi_piecewise().subs(Q, 1), (A,))
    a = np.array([0.5, 1.0, 2.0])
    np.testing.assert_allclose(f(a), [0.5 / np.sqrt(2), 1 / np.sqrt(2), 1 / np.sqrt(5)])
    g = sy.lambdify_expr(sy.theorem4_bound(), sy.RATIO_ARGS, "mpmath", cse=True)
    h = sy.lambdify_expr(sy.theorem4_bound(), sy.RATIO_ARGS, "mpmath")
    with mpmath.workdps(40):
        x = [mpmath.mpf(v) for v in (0.7, 1.1, 0.3)]
        assert abs(g(*x) - h(*x)) < mpmath.mpf(10) ** -38

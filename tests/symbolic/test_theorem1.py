"""The Weyl step of Theorem 1 (obslib.symbolic.theorem1): the slacks equal triangle-inequality
slacks symbolically, and the inequalities hold for random symmetric matrices.
"""

import numpy as np
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from obslib import symbolic as sy


def test_weyl_inequalities_are_triangle_inequalities():
    for name, (slack, tri) in sy.weyl_2x2_slacks().items():
        assert sp.simplify(slack - tri) == 0, name
        assert sp.expand(slack - tri) == 0, name


entry = st.one_of(
    st.integers(-3, 3).map(float),  # exact ties, zeros and commuting pairs: equality cases
    st.floats(-1e3, 1e3, allow_nan=False, allow_infinity=False).map(
        lambda v: v if abs(v) > 1e-6 else 0.0
    ),
)
sym2 = st.tuples(entry, entry, entry)


@settings(derandomize=True, deadline=None, max_examples=300)
@given(sym2, sym2)
def test_weyl_inequalities_hold_for_random_symmetric_matrices(x, y):
    X = np.array([[x[0], x[1]], [x[1], x[2]]])
    Y = np.array([[y[0], y[1]], [y[1], y[2]]])
    lx, ly, ls = np.linalg.eigvalsh(X), np.linalg.eigvalsh(Y), np.linalg.eigvalsh(X + Y)
    tol = 1e-12 * (np.abs(lx).max() + np.abs(ly).max())
    assert ls[0] >= lx[0] + ly[0] - tol
    assert ls[0] <= min(lx[0] + ly[1], lx[1] + ly[0]) + tol
    assert ls[1] <= lx[1] + ly[1] + tol
    assert ls[1] >= max(lx[0] + ly[1], lx[1] + ly[0]) - tol

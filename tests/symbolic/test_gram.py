"""The Gram matrix of a pair and its eigenvalues (obslib.symbolic.gram), and the errata in the
proof of Theorem 4: derived against printed, and numerically against NumPy.
"""

import numpy as np
import pytest
import sympy as sp

from obslib import symbolic as sy


def test_cartesian_gram_is_O_transpose_O_numerically():
    rng = np.random.default_rng(0)
    f = sy.lambdify_expr(sy.cartesian_gram(), sy.CARTESIAN_ARGS[:-1])
    for _ in range(20):
        o, pi, pj = rng.normal(size=(3, 2))
        O = np.array([o - pi, o - pj])
        got = np.array(f(*o, *pi, *pj), dtype=float)
        np.testing.assert_allclose(got, O.T @ O, rtol=1e-13, atol=1e-13)


def test_printed_polar_matrix_equals_derived_one():
    diff = sy.polar_gram() - sy.printed_polar_gram()
    assert all(sp.simplify(e) == 0 for e in diff)


def test_sympy_eigenvalues_in_polar_form_are_eq33():
    gp = sy.polar_gram()
    rmin, rmax = sy.eigenvalues(gp)  # roots of the characteristic polynomial
    lam = sp.Symbol("lam")
    char = (lam * sp.eye(2) - gp).det()
    for r in (rmin, rmax):
        assert sp.simplify(char.subs(lam, r)) == 0
    lmin, lmax = sy.polar_eigenvalues()  # the same roots in double-angle form
    pmin, pmax = sy.printed_eigenvalues()
    assert sp.simplify(lmin - pmin) == 0
    assert sp.simplify(lmax - pmax) == 0
    assert sp.simplify(rmin - pmin) == 0
    assert sp.simplify(rmax - pmax) == 0
    assert all(v == 0 for k, v in sy.theorem4_residuals().items() if k != "polar matrix")
    assert all(v == 0 for v in sy.theorem4_residuals()["polar matrix"])
    # numerically, against numpy's eigenvalues of the printed polar matrix
    f = sy.lambdify_expr(sp.Matrix([lmin, lmax]), sy.POLAR_ARGS[:-1])
    g = sy.lambdify_expr(sy.printed_polar_gram(), sy.POLAR_ARGS[:-1])
    rng = np.random.default_rng(3)
    for _ in range(20):
        d_i, d_j, t_i, t_j = rng.uniform(0.1, 3), rng.uniform(0.1, 3), *rng.uniform(-4, 4, 2)
        got = np.array(f(d_i, d_j, t_i, t_j), dtype=float).ravel()
        want = np.linalg.eigvalsh(np.array(g(d_i, d_j, t_i, t_j), dtype=float))
        np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12)


def test_eigenvalues_of_numeric_and_symbolic_matrices():
    x = sp.Matrix([[3, 1], [1, 2]])
    lo, hi = sy.eigenvalues(x)
    np.testing.assert_allclose([float(lo), float(hi)], np.linalg.eigvalsh([[3, 1], [1, 2]]))
    a, b, c = sp.symbols("a b c", real=True)
    lo, hi = sy.eigenvalues(sp.Matrix([[a, b], [b, c]]))
    assert sp.expand(lo + hi - (a + c)) == 0 and sp.expand(lo * hi - (a * c - b * b)) == 0


def test_pythagorean_remainder_decides_identities():
    ti, tj = sy.THETA_I, sy.THETA_J
    assert sy.pythagorean_remainder(sp.cos(ti) ** 2 + sp.sin(ti) ** 2 - 1) == 0
    assert sy.pythagorean_remainder(sp.cos(2 * (ti - tj)) - 2 * sp.cos(ti - tj) ** 2 + 1) == 0
    assert sy.pythagorean_remainder(sp.cos(ti) ** 2 - sp.sin(ti) ** 2 - 1) != 0
    with pytest.raises(ValueError, match="polynomial"):
        sy.pythagorean_remainder(sp.tan(ti))


def test_cartesian_discriminant_is_eq33_radicand():
    disc, paper = sy.discriminant_cartesian()
    assert sp.expand(disc - paper) == 0


def test_printed_cartesian_matrix_is_wrong_in_every_entry():
    diff = (sy.printed_cartesian_gram() - sy.cartesian_gram()).applyfunc(sp.expand)
    assert all(e != 0 for e in diff)


def test_printed_cartesian_matrix_at_a_rational_point():
    w = {sy.OX: 0, sy.OY: 0, sy.PIX: 1, sy.PIY: 2, sy.PJX: 3, sy.PJY: 1}
    assert sy.cartesian_gram().subs(w) == sp.Matrix([[10, 5], [5, 5]])
    printed = sy.printed_cartesian_gram().subs(w)
    assert printed == sp.Matrix([[1, 6], [6, 1]])
    assert printed.det() < 0  # a Gram matrix has det >= 0
    # the printed matrix does not give Eq. (33)'s eigenvalues there
    true_eigs = sorted(sy.cartesian_gram().subs(w).eigenvals(multiple=True), key=float)
    printed_eigs = sorted(printed.eigenvals(multiple=True), key=float)
    assert [float(x) for x in printed_eigs] == [-5.0, 7.0]
    assert [float(x) for x in printed_eigs] != pytest.approx([float(x) for x in true_eigs])


def test_printed_cartesian_matrix_does_not_give_printed_polar_one():
    printed = sy.printed_cartesian_gram().subs(sy.polar_substitution()).applyfunc(sp.expand)
    assert any(sp.simplify(e) != 0 for e in printed - sy.printed_polar_gram())


def test_eigenvalues_validates():
    with pytest.raises(ValueError, match="2x2"):
        sy.eigenvalues(sp.eye(3))
    with pytest.raises(ValueError, match="symmetric"):
        sy.eigenvalues(sp.Matrix([[1, 2], [3, 4]]))

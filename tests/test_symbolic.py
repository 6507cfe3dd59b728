"""The SymPy derivations of obslib.symbolic: Theorem 4, Theorem 5, the Weyl step, the errata.

The tests assert the derivations (symbolic simplification to zero, or exact rational points at
high precision), and compare the lambdified expressions with obslib.pair_bounds and
obslib.pair_bound_polar. A wrong closed form must fail them (see
test_a_wrong_closed_form_is_detected).
"""

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import obslib as ob
from obslib.scenes import random_scenes
from obslib import symbolic as sy
from obslib.studies.pair_form import max_difference_at_rational_points

A, TH, Q = sy.ALPHA, sy.THETA, sy.Q
CART_RANGES = {**{s: (-3.0, 3.0) for s in sy.CARTESIAN_ARGS[:-1]}, sy.U: (0.0, 2.0)}
RATIO_RANGES = {A: (0.01, 5.0), TH: (-3.14, 3.14), Q: (0.0, 3.0)}


def cartesian_bound():
    lmin, lmax = sy.cartesian_eigenvalues()
    return sy.bound_from_eigenvalues(lmin, lmax)


# --- Theorem 4 -----------------------------------------------------------------------------------
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


def test_polar_ratio_is_theorem4_squared():
    ratio = sy.polar_ratio()
    assert ratio.free_symbols == {A, TH, Q}
    assert sp.cancel(ratio - sy.theorem4_bound(squared=True)) == 0
    assert sp.cancel(ratio - sy.theorem4_bound(squared=True).subs(Q, 2 * Q)) != 0


def test_eigenvalues_reduce_to_theorem4_in_alpha_theta():
    lmin, lmax = sy.polar_eigenvalues()
    ratio = (lmin / (lmax + sy.U**2)).subs(sy.ratio_substitution())
    assert sp.simplify(ratio - sy.theorem4_bound(squared=True)) == 0
    # and the square root of both sides: both are non-negative
    assert max_difference_at_rational_points(
        sp.sqrt(ratio.subs(sy.D_IO, sp.Rational(7, 3))), sy.theorem4_bound(), RATIO_RANGES, 30
    ) < 1e-45


def test_cartesian_discriminant_is_eq33_radicand():
    disc, paper = sy.discriminant_cartesian()
    assert sp.expand(disc - paper) == 0


def test_cartesian_bound_equals_theorem4_at_rational_points():
    err = max_difference_at_rational_points(
        cartesian_bound(), sy.theorem4_bound(), CART_RANGES, 60, seed=3, digits=50,
        point_map=sy.cartesian_ratio_values,
    )
    assert err < 1e-40


def test_a_wrong_closed_form_is_detected():
    """Mutants of Eq. (9) (sign flipped inside the square root, or a wrong factor) must fail the
    same comparisons that the true form passes."""
    c = sp.cos(2 * TH)

    def form(radicand, uterm):
        s = sp.sqrt(radicand)
        return sp.sqrt((1 + A**2 - s) / (1 + A**2 + s + uterm))

    mutants = [
        form(1 + A**4 - 2 * A**2 * c, 2 * Q**2),  # sign flipped inside the square root
        form(1 + A**4 + 2 * A**2 * c, Q**2),  # u^2/d^2 instead of 2 u^2/d^2
        form(1 + A**4 + 2 * A**2 * sp.cos(TH), 2 * Q**2),  # cos(theta) instead of cos(2 theta)
    ]
    lmin, lmax = sy.polar_eigenvalues()
    ratio = (lmin / (lmax + sy.U**2)).subs(sy.ratio_substitution())
    ratio = ratio.subs(sy.D_IO, 2)  # the ratio does not depend on d_io
    for m in mutants:
        assert max_difference_at_rational_points(ratio, m**2, RATIO_RANGES, 20) > 1e-3
        assert max_difference_at_rational_points(
            cartesian_bound(), m, CART_RANGES, 20, point_map=sy.cartesian_ratio_values
        ) > 1e-3
        f = sy.lambdify_expr(m, sy.RATIO_ARGS)
        rng = np.random.default_rng(1)
        a, t = rng.uniform(0.1, 5, 200), rng.uniform(-np.pi, np.pi, 200)
        q = rng.uniform(0.1, 3, 200)
        assert np.abs(f(a, t, q) - ob.pair_bound_polar(a, t, q)).max() > 1e-3


def _scenes(n, seed):
    return [(sc.sensors, sc.target, sc.u_max)
            for sc in random_scenes(n, seed, n_sensors=(2, 2), scale=(1e-2, 1e2), kinds=("generic",))]


def test_lambdified_cartesian_bound_equals_pair_bounds():
    f_mp = sy.lambdify_expr(cartesian_bound(), sy.CARTESIAN_ARGS, "mpmath")
    f_np = sy.lambdify_expr(cartesian_bound(), sy.CARTESIAN_ARGS, "numpy")
    n_np = 0
    with mpmath.workdps(30):
        for sensors, target, u in _scenes(300, 5):
            w = ob.pair_bounds(sensors, target[None], u)[0, 1, 0]
            args = (*target, *sensors[0], *sensors[1], u)
            exact = float(f_mp(*map(mpmath.mpf, args)))
            assert abs(exact - w) < 1e-10
            if exact > 1e-3:  # the naive NumPy form loses lambda_min to cancellation near 0
                n_np += 1
                assert abs(float(f_np(*args)) - w) < 1e-10
    assert n_np > 200


def test_lambdified_theorem4_equals_pair_bound_polar():
    rng = np.random.default_rng(7)
    a, t, q = rng.uniform(0, 5, 3000), rng.uniform(-np.pi, np.pi, 3000), rng.uniform(0, 3, 3000)
    f_np = sy.lambdify_expr(sy.theorem4_bound(), sy.RATIO_ARGS)
    with np.errstate(invalid="ignore"):
        naive = np.nan_to_num(f_np(a, t, q))
    ok = np.abs(np.sin(t)) > 1e-3
    assert np.abs(naive - ob.pair_bound_polar(a, t, q))[ok].max() < 1e-10
    f_mp = sy.lambdify_expr(sy.theorem4_bound(), sy.RATIO_ARGS, "mpmath")
    with mpmath.workdps(30):
        for k in range(300):
            exact = float(f_mp(*map(mpmath.mpf, (a[k], t[k], q[k]))))
            assert abs(exact - ob.pair_bound_polar(a[k], t[k], q[k])) < 1e-10


# --- Errata in the proof of Theorem 4 ------------------------------------------------------------
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


# --- Theorem 5 -----------------------------------------------------------------------------------
def test_theta_derivative_closed_form_and_corner_at_zero():
    assert sp.simplify(sy.dbound_dtheta() - sy.dbound_dtheta_closed()) == 0
    assert sy.closed_forms_hold() == {"dtheta": True, "dalpha": True}
    d = sy.lambdify_expr(sy.dbound_dtheta_closed(), sy.RATIO_ARGS, "mpmath")
    s = sy.lambdify_expr(sy.dbound_dtheta_at_zero(), (A, Q), "mpmath")
    with mpmath.workdps(60):
        h = mpmath.mpf(10) ** -12  # the slope differs from its limit by O(h^2)
        for a, q in [(0.3, 0.0), (1.0, 1.0), (2.5, 0.7)]:
            a, q = mpmath.mpf(a), mpmath.mpf(q)
            assert s(a, q) > 0.05
            assert abs(d(a, h, q) - s(a, q)) < 1e-20  # right slope
            assert abs(d(a, -h, q) + s(a, q)) < 1e-20  # left slope: a corner, not a zero


def test_theta_stationarity_is_alpha2_sin2theta_for_the_square():
    d2 = sp.diff(sy.theorem4_bound(squared=True), TH)
    c = sp.cos(2 * TH)
    S = sp.sqrt(1 + A**4 + 2 * A**2 * c)
    D = 1 + A**2 + S + 2 * Q**2
    assert sp.simplify(d2 - 4 * A**2 * sp.sin(2 * TH) * (1 + A**2 + Q**2) / (S * D**2)) == 0


def test_vanishes_with_radicals_proves_and_refutes():
    radicals = [sy.theorem4_bound(), sp.sqrt(sy.theorem4_radicand())]
    for d, closed in ((sy.dbound_dtheta(), sy.dbound_dtheta_closed()),
                      (sy.dbound_dalpha(), sy.dbound_dalpha_closed())):
        assert sy.vanishes_with_radicals(d - closed, radicals)
        assert not sy.vanishes_with_radicals(d - closed * (1 + sp.Rational(1, 10**6)), radicals)
        assert not sy.vanishes_with_radicals(d - closed.subs(Q, 2 * Q), radicals)
    s = sp.sqrt(1 + A**2)
    assert sy.vanishes_with_radicals(s**3 - (1 + A**2) * s, [s])
    assert not sy.vanishes_with_radicals(s - A, [s])
    with pytest.raises(ValueError, match="square roots"):
        sy.vanishes_with_radicals(A, [A**2])
    with pytest.raises(ValueError, match="outermost"):
        sy.vanishes_with_radicals(A, radicals[::-1])


def test_maximum_value_and_location_exact():
    f = sy.theorem4_bound()
    assert sp.simplify(f.subs({A: 1, TH: sp.pi / 2}) - 1 / sp.sqrt(1 + Q**2)) == 0
    assert sy.max_value_exact() == 0
    assert sp.simplify(f.subs({A: 1, TH: -sp.pi / 2}) - 1 / sp.sqrt(1 + Q**2)) == 0
    for t in (0, sp.pi):  # S = 1 + alpha^2 there, so the numerator 1 + alpha^2 - S vanishes
        S = sp.sqrt(sp.factor(sy.theorem4_radicand().subs(TH, t)))
        assert S == 1 + A**2
    assert sy.theorem4_bound().subs(A, 0) == 0
    assert sp.limit(f.subs({TH: sp.Rational(7, 10), Q: 1}), A, sp.oo) == 0
    # the inequality C^2 <= 1/(1+q^2), i.e. q^2 (a^2 - 1) <= S (2 + q^2), at random points
    rng = np.random.default_rng(2)
    a, t, q = rng.uniform(0, 5, 5000), rng.uniform(-np.pi, np.pi, 5000), rng.uniform(0, 3, 5000)
    assert (ob.pair_bound_polar(a, t, q) <= 1 / np.sqrt(1 + q * q) + 1e-15).all()


def test_printed_max_over_theta_is_correct():
    err = max_difference_at_rational_points(
        sy.printed_max_halfpi(), sy.theorem4_bound().subs(TH, sp.pi / 2),
        {A: (0.01, 5), Q: (0, 3)}, 60,
    )
    assert err < 1e-40
    pw = sy.bound_halfpi_piecewise()
    ranges = {A: (0.01, 5), Q: (0, 3)}
    assert max_difference_at_rational_points(sy.printed_max_halfpi(), pw, ranges, 60) < 1e-40


def test_printed_alpha_derivative_at_halfpi_is_wrong():
    printed = sy.printed_dbound_dalpha_halfpi()
    pw = sy.bound_halfpi_piecewise()
    below, above = pw.args[0][0], pw.args[1][0]
    # true derivative: 1/sqrt(1+q^2) on (0, 1), -alpha/(alpha^2+q^2)^(3/2) on (1, inf): never 0
    assert sp.simplify(sp.diff(below, A) - 1 / sp.sqrt(1 + Q**2)) == 0
    assert sp.simplify(sp.diff(above, A) + A / (A**2 + Q**2) ** sp.Rational(3, 2)) == 0
    assert printed.subs({A: 1, Q: 1}) == 0  # the printed one vanishes at the corner
    assert abs(float((printed - sp.diff(below, A)).subs({A: sp.Rational(1, 2), Q: 1}))) > 0.5
    assert sp.diff(below, A, 2) == 0  # not > 0 at alpha = 0 as printed


def test_alpha_derivative_numerator_is_eq34_but_printed_derivative_is_not():
    assert sp.simplify(sy.dbound_dalpha() - sy.dbound_dalpha_closed()) == 0
    assert sp.simplify(sy.stationarity_alpha() - sy.printed_stationarity_alpha()) == 0
    true_f = sy.lambdify_expr(sy.dbound_dalpha_closed(), sy.RATIO_ARGS, "mpmath")
    printed_f = sy.lambdify_expr(sy.printed_dbound_dalpha(), sy.RATIO_ARGS, "mpmath")
    with mpmath.workdps(60):
        r1 = true_f(0.5, 0.7, 1.0) / printed_f(0.5, 0.7, 1.0)
        r2 = true_f(3.0, 0.7, 1.0) / printed_f(3.0, 0.7, 1.0)
        assert abs(r1 / r2 - 1) > 0.1  # not a constant factor
        # at alpha -> 0 the true slope is |sin theta| / sqrt(1 + q^2), the printed form gives 0
        for t, q in [(0.7, 1.0), (2.0, 0.3), (-1.0, 2.0)]:
            t, q = mpmath.mpf(t), mpmath.mpf(q)
            s0 = true_f(mpmath.mpf(10) ** -12, t, q)
            assert abs(s0 - abs(mpmath.sin(t)) / mpmath.sqrt(1 + q * q)) < 1e-20
            assert abs(printed_f(mpmath.mpf(10) ** -12, t, q)) < 1e-11


def test_alpha_star_closed_form_solves_eq34():
    ranges = {TH: (0.02, 3.12), Q: (0.0, 3.0)}
    root = sp.sqrt(sy.alpha_star_squared())
    g_at_root = sy.stationarity_alpha().subs(A, root)
    assert max_difference_at_rational_points(g_at_root, 0, ranges, 40) < 1e-35
    closed2 = sy.alpha_star_closed() ** 2
    err = max_difference_at_rational_points(sy.alpha_star_squared(), closed2, ranges, 40)
    assert err < 1e-40
    # the other root of the squared equation is spurious (alpha* >= 1 by the sign argument)
    f = sy.lambdify_expr(sy.alpha_star_closed(), (TH, Q))
    t = np.linspace(0.05, 3.09, 50)
    for q in (0.25, 1.0, 3.0):
        assert (f(t, q) >= 1.0).all()


def test_alpha_equal_1_is_stationary_only_for_q0_or_special_angles():
    g1 = sp.simplify(sp.expand_trig(sy.stationarity_alpha().subs(A, 1)))
    assert sp.simplify(g1 - sy.stationarity_alpha_at_1()) == 0
    assert sy.stationarity_alpha_at_1() == 2 * Q**2 * (sp.Abs(sp.cos(TH)) - sp.cos(TH) ** 2)
    assert sp.simplify(g1.subs(Q, 0)) == 0
    assert sp.simplify(g1.subs(TH, sp.pi / 2)) == 0
    assert sp.simplify(g1.subs(TH, 0)) == 0
    assert sp.simplify(g1.subs({TH: sp.pi / 3, Q: 1})) != 0
    assert sp.simplify(sy.alpha_star_closed().subs(Q, 0)) == 1


# --- Theorem 1: Weyl step ----------------------------------------------------------------------
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


# --- helpers: validation -----------------------------------------------------------------------
def test_lambdify_expr_validates():
    with pytest.raises(ValueError, match="free symbols"):
        sy.lambdify_expr(sy.theorem4_bound(), (A, TH))
    with pytest.raises(ValueError, match="modules"):
        sy.lambdify_expr(A, (A,), modules="tensorflow")
    with pytest.raises(ValueError, match="symbols"):
        sy.lambdify_expr(A, ("alpha",))


def test_rational_point_comparison_validates():
    with pytest.raises(ValueError, match="n_points"):
        max_difference_at_rational_points(A, A, {A: (0, 1)}, 0)
    with pytest.raises(ValueError, match="digits"):
        max_difference_at_rational_points(A, A, {A: (0, 1)}, 3, digits=10)
    with pytest.raises(ValueError, match="range"):
        max_difference_at_rational_points(A, A, {A: (1, 0)}, 3)
    with pytest.raises(ValueError, match="no range"):
        max_difference_at_rational_points(A + Q, A, {A: (0, 1)}, 3)


def test_eigenvalues_validates():
    with pytest.raises(ValueError, match="2x2"):
        sy.eigenvalues(sp.eye(3))
    with pytest.raises(ValueError, match="symmetric"):
        sy.eigenvalues(sp.Matrix([[1, 2], [3, 4]]))


def test_cartesian_ratio_values_in_mpmath_equal_the_exact_ones():
    rng = np.random.default_rng(9)
    for _ in range(10):
        point = {s: sp.Rational(int(rng.integers(-2991, 2992)), 997) for s in sy.CARTESIAN_ARGS}
        point[sy.U] = abs(point[sy.U])
        exact = sy.cartesian_ratio_values(point)
        fast = sy.cartesian_ratio_values(point, digits=60)
        with mpmath.workdps(60):
            for s in exact:
                assert isinstance(fast[s], mpmath.mpf)
                assert abs(fast[s] - mpmath.mpf(sp.N(exact[s], 70))) < mpmath.mpf(10) ** -55


def test_lambdify_numpy_evaluates_arrays_and_piecewise():
    f = sy.lambdify_expr(sy.bound_halfpi_piecewise().subs(Q, 1), (A,))
    a = np.array([0.5, 1.0, 2.0])
    np.testing.assert_allclose(f(a), [0.5 / np.sqrt(2), 1 / np.sqrt(2), 1 / np.sqrt(5)])
    g = sy.lambdify_expr(sy.theorem4_bound(), sy.RATIO_ARGS, "mpmath", cse=True)
    h = sy.lambdify_expr(sy.theorem4_bound(), sy.RATIO_ARGS, "mpmath")
    with mpmath.workdps(40):
        x = [mpmath.mpf(v) for v in (0.7, 1.1, 0.3)]
        assert abs(g(*x) - h(*x)) < mpmath.mpf(10) ** -38


def test_cartesian_ratio_values_rejects_sensor_on_target():
    point = {s: sp.Integer(0) for s in sy.CARTESIAN_ARGS}
    point[sy.PJX] = sp.Integer(1)
    with pytest.raises(ValueError, match="zero distance"):
        sy.cartesian_ratio_values(point)
    with pytest.raises(ValueError, match="zero distance"):
        sy.cartesian_ratio_values(point, digits=30)

"""Theorem 5 (obslib.symbolic.theorem5): the derivatives, their factored forms, Eq. (34), the
printed derivatives and the maximiser, checked exactly and at high precision.
"""

import mpmath
import numpy as np
import sympy as sp

import obslib as ob
from obslib import symbolic as sy
from obslib.symbolic.evaluation import max_difference_at_rational_points

A, TH, Q = sy.ALPHA, sy.THETA, sy.Q


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

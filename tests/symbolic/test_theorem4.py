"""Theorem 4's closed form (obslib.symbolic.theorem4): the eigenvalue ratio reduces to Eq. (9),
exactly at rational points and against obslib.pair_bounds / obslib.pair_bound_polar; a wrong
closed form must fail the same comparisons (test_a_wrong_closed_form_is_detected).
"""

import mpmath
import numpy as np
import pytest
import sympy as sp

import obslib as ob
from obslib import symbolic as sy
from obslib.scenes import random_scenes
from obslib.symbolic.evaluation import max_difference_at_rational_points

A, TH, Q = sy.ALPHA, sy.THETA, sy.Q
CART_RANGES = {**{s: (-3.0, 3.0) for s in sy.CARTESIAN_ARGS[:-1]}, sy.U: (0.0, 2.0)}
RATIO_RANGES = {A: (0.01, 5.0), TH: (-3.14, 3.14), Q: (0.0, 3.0)}


def cartesian_bound():
    lmin, lmax = sy.cartesian_eigenvalues()
    return sy.bound_from_eigenvalues(lmin, lmax)


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
    return [
        (sc.sensors, sc.target, sc.u_max)
        for sc in random_scenes(n, seed, n_sensors=(2, 2), scale=(1e-2, 1e2), kinds=("generic",))
    ]


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


def test_rational_point_comparison_validates():
    with pytest.raises(ValueError, match="n_points"):
        max_difference_at_rational_points(A, A, {A: (0, 1)}, 0)
    with pytest.raises(ValueError, match="digits"):
        max_difference_at_rational_points(A, A, {A: (0, 1)}, 3, digits=10)
    with pytest.raises(ValueError, match="range"):
        max_difference_at_rational_points(A, A, {A: (1, 0)}, 3)
    with pytest.raises(ValueError, match="no range"):
        max_difference_at_rational_points(A + Q, A, {A: (0, 1)}, 3)


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


def test_cartesian_ratio_values_rejects_sensor_on_target():
    point = {s: sp.Integer(0) for s in sy.CARTESIAN_ARGS}
    point[sy.PJX] = sp.Integer(1)
    with pytest.raises(ValueError, match="zero distance"):
        sy.cartesian_ratio_values(point)
    with pytest.raises(ValueError, match="zero distance"):
        sy.cartesian_ratio_values(point, digits=30)

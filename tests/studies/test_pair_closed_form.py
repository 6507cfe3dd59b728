"""Audits of the pair closed form (obslib.studies.pair_closed_form): Fig. 2's grids, the printed
Weyl range and Theorem 4's audit against a straightforward loop."""

import numpy as np
import pytest

import obslib as ob
from obslib import symbolic
from obslib.pair_form import bound_surface, fine_grid, grid_maximum
from obslib.scenes import random_scenes
from obslib.studies import pair_closed_form, weyl


def test_paper_grid_is_51_by_63_and_misses_half_pi():
    a, t = pair_closed_form.paper_grid()
    assert a.size == 51 and t.size == 63
    assert a[0] == 0 and a[-1] == pytest.approx(5.0) and a[10] == 1.0
    assert t[0] == -np.pi and t[-1] <= np.pi
    assert np.abs(np.abs(t) - np.pi / 2).min() > 0.01


def test_paper_grid_validation():
    with pytest.raises(ValueError, match="alpha_max"):
        pair_closed_form.paper_grid(-1.0)
    with pytest.raises(ValueError, match="step"):
        pair_closed_form.paper_grid(5.0, 0.0)


def test_fig2_maxima_paper_grid_versus_fine_grid():
    a, t = pair_closed_form.paper_grid()
    m = grid_maximum(a, t, bound_surface(a, t, 1.0, 1.0))
    assert m.value < 1 / np.sqrt(2) - 1e-3
    assert len(m.points) == 1 and m.points[0][0] == 1.0
    assert m.points[0][1] == pytest.approx(-np.pi + 4.7)


def test_fig2_grids_are_the_bound_on_both_grids():
    g = pair_closed_form.fig2_grids(1.0, 1.0, 5.0, 0.1, 20, 30)
    for name, (a, t) in (("paper", pair_closed_form.paper_grid(5.0, 0.1)),
                         ("fine", fine_grid(5.0, 20, 30))):
        np.testing.assert_array_equal(g[name].alpha, a)
        np.testing.assert_array_equal(g[name].theta, t)
        A, T = np.meshgrid(a, t)
        np.testing.assert_array_equal(g[name].Z, ob.pair_bound_polar(A, T, 1.0))
        k, l = np.unravel_index(np.argmax(g[name].Z), g[name].Z.shape)
        assert g[name].maximum.value == g[name].Z[k, l] and (a[l], t[k]) in g[name].maximum.points
    assert g["fine"].maximum.value == pytest.approx(1 / np.sqrt(2), abs=1e-12)


def test_printed_dual_weyl_range_admits_index_zero():
    rng = weyl.dual_weyl_printed_range(2)
    assert (1, 1, 0) in rng
    assert [t for t in rng if t[2] >= 1] == [(1, 2, 1), (2, 1, 1), (2, 2, 2)]
    with pytest.raises(ValueError):
        weyl.dual_weyl_printed_range(0)


def test_theorem4_audit_numerics_match_a_per_scene_loop():
    """The audit evaluates the scenes in arrays; the straightforward loop gives the same errors."""
    import mpmath

    a = pair_closed_form.theorem4_audit(5, 60, 3, 30)
    cmin, cmax = symbolic.cartesian_eigenvalues()
    f_cart = symbolic.bound_from_eigenvalues(cmin, cmax)
    f_mp = symbolic.lambdify_expr(f_cart, symbolic.CARTESIAN_ARGS, "mpmath")
    f_np = symbolic.lambdify_expr(f_cart, symbolic.CARTESIAN_ARGS, "numpy")
    t_mp = symbolic.lambdify_expr(symbolic.theorem4_bound(), symbolic.RATIO_ARGS, "mpmath")
    err_pb = err_np = err_polar = 0.0
    rng = np.random.default_rng(3 + 1)
    with mpmath.workdps(30):
        for sc in random_scenes(60, 3, n_sensors=(2, 2), scale=(1e-2, 1e2), kinds=("generic",)):
            sensors, target, u = sc.sensors, sc.target, sc.u_max
            w = ob.pair_bounds(sensors, target[None, :], u)[0, 1, 0]
            args = (*target, *sensors[0], *sensors[1], u)
            exact = f_mp(*[mpmath.mpf(float(x)) for x in args])
            err_pb = max(err_pb, abs(float(exact) - w))
            if float(exact) > 1e-3:
                err_np = max(err_np, abs(float(f_np(*args)) - w))
            al, th, q = rng.uniform(0, 5), rng.uniform(-np.pi, np.pi), rng.uniform(0, 3)
            exact_p = t_mp(mpmath.mpf(al), mpmath.mpf(th), mpmath.mpf(q))
            err_polar = max(err_polar, abs(float(exact_p) - ob.pair_bound_polar(al, th, q)))
    assert a.max_error_pair_bounds == pytest.approx(err_pb, abs=1e-18)
    assert a.max_error_pair_bound_polar == pytest.approx(err_polar, abs=1e-18)
    assert a.max_error_numpy_generic == pytest.approx(err_np, abs=1e-15)
    assert a.polar_matrix_printed_equal and a.eigenvalues_printed_equal
    assert a.theorem4_ratio_equal and a.cartesian_discriminant_equal
    assert a.cartesian_max_difference < 1e-20


def test_theorem5_audit_grids_match_bound_surface_per_ratio():
    """The audit evaluates every q in one broadcast call; bound_surface per q gives the same."""
    qs = (0.0, 0.3, 1.0, 2.5)
    a5 = pair_closed_form.theorem5_audit(qs, 3.0, 8, 6, 3)
    alpha, theta = fine_grid(3.0, 8, 6)
    on_zero = np.isclose(np.abs(np.sin(theta)), 0.0, atol=1e-15)
    zero_lines = 0.0
    for q, gmax, argm in zip(qs, a5.grid_max, a5.argmax):
        Z = bound_surface(alpha, theta, q, 1.0)
        m = grid_maximum(alpha, theta, Z)
        assert gmax == pytest.approx(m.value, rel=1e-15) and argm == m.points
        zero_lines = max(zero_lines, Z[on_zero].max(), Z[:, alpha == 0].max())
    assert a5.max_on_zero_lines == pytest.approx(zero_lines, abs=1e-300)

"""Audits of the pair closed form (Theorems 4-5, Fig. 2) against SymPy and brute force (notebook
02, claims of :mod:`obslib.claims.pair_closed_form`).

The symbolic side lives in :mod:`obslib.symbolic` and the numerics in :mod:`obslib.pair_form`; this
module compares them with :func:`obslib.pair_bounds` and :func:`obslib.pair_bound_polar` and
packages the evidence that notebook ``02_pair_closed_form`` prints and the ledger judges. The
derivatives of Theorem 5's proof are audited in :mod:`obslib.studies.theorem5_proof` and the Weyl
step of Theorem 1 in :mod:`obslib.studies.weyl`. Every audit is a pure function of its arguments and
is cached.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .._validate import as_int, as_nonnegative, as_positive, as_sequence
from ..bounds import pair_bound_polar, pair_bounds
from ..pair_form import (
    GridMax,
    bound_surface,
    fine_grid,
    grid_maximum,
    maximising_alpha,
    maximising_alpha_closed,
)

__all__ = ["NOTEBOOK", "audit_ratios", "paper_grid", "Fig2Grid", "fig2_grids", "Theorem4Audit",
           "theorem4_audit", "PrintedMatrixAudit", "printed_matrix_audit", "Theorem5Audit",
           "theorem5_audit", "alpha_star_thetas", "AlphaStarAudit", "alpha_star_audit",
           "DalphaMinimumAudit", "dalpha_minimum_audit"]

#: The chapter of these studies.
NOTEBOOK = "02_pair_closed_form"


def audit_ratios(u_max: float, d_io: float, u_over_d_curves) -> tuple:
    r"""The values of :math:`q = u_{\max} / d_{io}` the Theorem 5 audits use, sorted: Fig. 2's
    :math:`u_{\max} / d_{io}`, the ``u_over_d_curves`` of the maximiser plot, and 0 (a stationary
    target).

    Examples
    --------
    >>> audit_ratios(u_max=1.0, d_io=2.0, u_over_d_curves=[1.0])
    (0.0, 0.5, 1.0)
    """
    u = as_nonnegative(u_max, "u_max")
    d = as_positive(d_io, "d_io")
    curves = [as_nonnegative(c, "u_over_d_curves")
              for c in as_sequence(u_over_d_curves, "u_over_d_curves")]
    return tuple(sorted({0.0, u / d, *curves}))


# --- exact comparison at rational points ----------------------------------------------------
# --- Fig. 2 grid --------------------------------------------------------------------------------
def paper_grid(alpha_max: float = 5.0, step: float = 0.1) -> tuple[np.ndarray, np.ndarray]:
    r"""The grid of the published Fig. 2: ``alpha = 0:step:alpha_max``, ``theta = -pi:step:pi``
    (MATLAB ranges).

    Values are :math:`k h` and :math:`-\pi + k h` with :math:`h` = ``step``, so with the
    default ``step = 0.1`` there are 51 values of :math:`\alpha` and 63 of :math:`\theta`, and
    :math:`\theta = \pm\pi/2` is **not** on the grid (the experiments' parameters; see the book's
    Experimental setup page).

    Returns
    -------
    alpha, theta : ndarray

    Examples
    --------
    >>> alpha, theta = paper_grid()
    >>> alpha.size, theta.size, bool(np.isclose(theta, np.pi / 2).any())
    (51, 63, False)
    """
    amax = as_positive(alpha_max, "alpha_max")
    h = as_positive(step, "step")
    n_a = int(np.floor(amax / h + 1e-9)) + 1
    n_t = int(np.floor(2 * np.pi / h + 1e-9)) + 1
    return np.arange(n_a) * h, -np.pi + np.arange(n_t) * h


@dataclass(frozen=True)
class Fig2Grid:
    """Theorem 4's bound on one grid of Fig. 2 and where it is largest."""

    alpha: np.ndarray  #: grid axis of ``alpha``
    theta: np.ndarray  #: grid axis of ``theta_ji``
    #: the bound, shape ``(len(theta), len(alpha))`` (:func:`obslib.pair_form.bound_surface`)
    Z: np.ndarray
    maximum: GridMax  #: its maximum and the grid points attaining it


def fig2_grids(u_max: float, d_io: float, alpha_max: float, paper_step: float,
               fine_alpha_per_unit: int, fine_theta_quarter: int) -> dict:
    r"""Fig. 2's bound on the published grid (:func:`paper_grid`) and on a fine grid that holds
    :math:`\alpha = 1`, :math:`\theta = \pm\pi/2` (:func:`obslib.pair_form.fine_grid`).

    Returns
    -------
    dict
        ``{"paper": Fig2Grid, "fine": Fig2Grid}``.

    Examples
    --------
    On the published grid the maximum misses :math:`1/\sqrt{2}`; on the fine grid it is attained at
    :math:`\alpha = 1`, :math:`\theta = \pm\pi/2`:

    >>> g = fig2_grids(1.0, 1.0, alpha_max=5.0, paper_step=0.1,
    ...                fine_alpha_per_unit=20, fine_theta_quarter=30)
    >>> round(g["paper"].maximum.value, 4), round(g["fine"].maximum.value, 6)
    (0.7005, 0.707107)
    >>> [(a, round(t / np.pi, 6)) for a, t in g["fine"].maximum.points]
    [(1.0, -0.5), (1.0, 0.5)]
    """
    return _fig2_grids(as_nonnegative(u_max, "u_max"), as_positive(d_io, "d_io"),
                       as_positive(alpha_max, "alpha_max"), as_positive(paper_step, "paper_step"),
                       as_int(fine_alpha_per_unit, "fine_alpha_per_unit", 1),
                       as_int(fine_theta_quarter, "fine_theta_quarter", 1))


@lru_cache(maxsize=4)
def _fig2_grids(u_max, d_io, alpha_max, paper_step, fine_alpha_per_unit, fine_theta_quarter):
    out = {}
    for name, (a, t) in (("paper", paper_grid(alpha_max, paper_step)),
                         ("fine", fine_grid(alpha_max, fine_alpha_per_unit, fine_theta_quarter))):
        Z = bound_surface(a, t, u_max, d_io)
        out[name] = Fig2Grid(a, t, Z, grid_maximum(a, t, Z))
    return out


# --- audits ------------------------------------------------------------------------------------
@dataclass(frozen=True)
class Theorem4Audit:
    """SymPy's eigenvalues of ``O_ij^T O_ij`` against Eq. (33) and Theorem 4, and against obslib."""

    polar_matrix_printed_equal: bool  #: printed polar matrix - derived expands to 0
    #: SymPy's eigenvalues (polar) minus Eq. (33) vanish (see :func:`theorem4_audit`)
    eigenvalues_printed_equal: bool
    #: :math:`\lambda_{\min}/(\lambda_{\max} + u^2)` in :math:`\alpha, \theta, q` minus Eq. (9)
    #: squared cancels to 0
    theorem4_ratio_equal: bool
    cartesian_discriminant_equal: bool  #: Cartesian discriminant - Eq. (33)'s radicand expands to 0
    cartesian_max_difference: float  #: Cartesian SymPy bound vs Eq. (9) at rational points
    n_rational_points: int
    digits: int
    max_error_pair_bounds: float  #: SymPy (mpmath, 30 digits) vs obslib.pair_bounds
    max_error_pair_bound_polar: float  #: SymPy (mpmath) vs obslib.pair_bound_polar
    max_error_numpy_generic: float  #: lambdified with NumPy vs pair_bounds where the bound > 1e-3
    n_random_points: int


def _random_pair_scenes(n: int, seed: int):
    """``n`` random two-sensor scenes ``(sensors (2, 2), target (2,), u_max)``, scales 1e-2 ..
    1e2."""
    from ..scenes import random_scenes

    scenes = random_scenes(n, seed, n_sensors=(2, 2), scale=(1e-2, 1e2), kinds=("generic",))
    return [(sc.sensors, sc.target, sc.u_max) for sc in scenes]


def theorem4_audit(
    n_rational_points: int, n_random_points: int, seed: int, digits: int = 50
) -> Theorem4Audit:
    """Derive Theorem 4 with SymPy (:mod:`obslib.symbolic`) and check it four ways.

    1. the printed polar matrix equals the derived one (the difference expands to zero), and so
       do the printed eigenvalues (Eq. (33)): the double-angle form of the derived roots expands
       to Eq. (33), and independently the trace and ``(lambda_max - lambda_min)^2`` of the roots
       leave remainder 0 modulo ``cos^2 + sin^2 = 1`` (:func:`obslib.symbolic.theorem4_residuals`);
    2. ``lambda_min / (lambda_max + u^2)`` with ``d_jo = alpha d_io``,
       ``theta_j = theta_i + theta``, ``u = q d_io`` cancels to Eq. (9) squared;
    3. in Cartesian coordinates: the discriminant identity (polynomial, expands to zero) and the
       whole bound, with ``alpha``, ``theta = atan2`` differences and ``q`` computed from the point,
       at ``n_rational_points`` rational points with ``digits`` digits;
    4. the SymPy expressions evaluated (mpmath, 30 digits) equal :func:`obslib.pair_bounds` and
       :func:`obslib.pair_bound_polar` at ``n_random_points`` random points.

    Examples
    --------
    >>> a = theorem4_audit(n_rational_points=3, n_random_points=5, seed=0,
    ...                    digits=20)
    >>> (a.polar_matrix_printed_equal, a.eigenvalues_printed_equal,
    ...  a.theorem4_ratio_equal)
    (True, True, True)
    >>> a.max_error_pair_bounds < 1e-12
    True
    """
    return _theorem4_audit(as_int(n_rational_points, "n_rational_points", 1),
                           as_int(n_random_points, "n_random_points", 1), as_int(seed, "seed", 0),
                           as_int(digits, "digits", 16))


@lru_cache(maxsize=8)
def _theorem4_audit(n_rational_points, n_random_points, seed, digits):
    import mpmath

    from .. import symbolic
    from ..symbolic.evaluation import max_difference_at_rational_points

    n_rat = as_int(n_rational_points, "n_rational_points", 1)
    n_rand = as_int(n_random_points, "n_random_points", 1)
    res = symbolic.theorem4_residuals()
    polar_ok = all(e == 0 for e in res["polar matrix"])
    eig_ok = all(
        res[k] == 0 for k in ("lambda_min", "lambda_max", "trace (mod cos^2 + sin^2 = 1)",
                              "(lambda_max - lambda_min)^2 (mod cos^2 + sin^2 = 1)")
    )
    ratio_ok = res["ratio"] == 0
    disc_ok = res["cartesian discriminant"] == 0
    cmin, cmax = symbolic.cartesian_eigenvalues()
    f_cart = symbolic.bound_from_eigenvalues(cmin, cmax)
    ranges = {s: (-3.0, 3.0) for s in symbolic.CARTESIAN_ARGS[:-1]}
    ranges[symbolic.U] = (0.0, 2.0)
    cart_diff = max_difference_at_rational_points(
        f_cart, symbolic.theorem4_bound(), ranges, n_rat, seed, digits,
        point_map=lambda pt: symbolic.cartesian_ratio_values(pt, digits + 10),
    )

    f_mp = symbolic.lambdify_expr(f_cart, symbolic.CARTESIAN_ARGS, "mpmath", cse=True)
    f_np = symbolic.lambdify_expr(f_cart, symbolic.CARTESIAN_ARGS, "numpy")
    t_mp = symbolic.lambdify_expr(symbolic.theorem4_bound(), symbolic.RATIO_ARGS, "mpmath",
                                  cse=True)
    scenes = _random_pair_scenes(n_rand, seed)
    w = np.array([pair_bounds(sen, tgt[None, :], u)[0, 1, 0] for sen, tgt, u in scenes])
    args = np.array([(*tgt, *sen[0], *sen[1], u) for sen, tgt, u in scenes])  # (n, 7)
    # polar points: the same draws as (a, theta, q) = uniform(0, 5), uniform(-pi, pi),
    # uniform(0, 3) per point, in that order
    rng = np.random.default_rng(seed + 1)
    pts = rng.uniform((0.0, -np.pi, 0.0), (5.0, np.pi, 3.0), (n_rand, 3))
    exact = np.empty(n_rand)
    exact_p = np.empty(n_rand)
    mpf = mpmath.mpf
    with mpmath.workdps(30):  # the same numbers as Python floats: mpf converts those faster
        for k, (a_k, p_k) in enumerate(zip(args.tolist(), pts.tolist())):
            exact[k] = float(f_mp(*map(mpf, a_k)))
            exact_p[k] = float(t_mp(*map(mpf, p_k)))
    err_pb = float(np.abs(exact - w).max())
    big = exact > 1e-3  # the naive NumPy form loses lambda_min to cancellation near 0
    err_np = float(np.abs(f_np(*args.T) - w)[big].max(initial=0.0))
    err_polar = float(np.abs(exact_p - pair_bound_polar(*pts.T)).max())
    return Theorem4Audit(
        polar_ok, eig_ok, ratio_ok, disc_ok, cart_diff, n_rat, int(digits), err_pb, err_polar,
        err_np, n_rand,
    )


@dataclass(frozen=True)
class PrintedMatrixAudit:
    """The appendix's printed ``O_ij^T O_ij`` (Eq. (32)) against the true one."""

    wrong_entries: tuple  #: ``(row, col)`` of entries whose difference does not expand to 0
    witness: dict  #: a rational point (o, p_i, p_j)
    true_at_witness: tuple  #: the true matrix there (integers)
    printed_at_witness: tuple  #: the printed matrix there
    printed_eigenvalues_at_witness: tuple  #: floats; a negative one means it is no Gram matrix
    polar_printed_consistent: bool  #: printed Cartesian matrix in polar form = printed polar one


@lru_cache(maxsize=1)
def printed_matrix_audit() -> PrintedMatrixAudit:
    """Compare the printed Cartesian matrix of the proof of Theorem 4 with the true one.

    The witness is ``o = (0, 0)``, ``p_i = (1, 2)``, ``p_j = (3, 1)``: there the true matrix is
    ``[[10, 5], [5, 5]]`` and the printed one ``[[1, 6], [6, 1]]``, whose determinant is negative.

    Examples
    --------
    >>> a = printed_matrix_audit()
    >>> a.true_at_witness, a.printed_at_witness
    (((10, 5), (5, 5)), ((1, 6), (6, 1)))
    >>> [round(x, 9) for x in a.printed_eigenvalues_at_witness]
    [-5.0, 7.0]
    """
    import sympy as sp

    from .. import symbolic

    true = symbolic.cartesian_gram()
    printed = symbolic.printed_cartesian_gram()
    wrong = tuple(
        (r, c) for r in range(2) for c in range(2) if sp.expand(printed[r, c] - true[r, c]) != 0
    )
    witness = {symbolic.OX: 0, symbolic.OY: 0, symbolic.PIX: 1, symbolic.PIY: 2,
               symbolic.PJX: 3, symbolic.PJY: 1}
    t_w = true.subs(witness)
    p_w = printed.subs(witness)
    eig = tuple(float(x) for x in sorted(np.linalg.eigvalsh(np.array(p_w, dtype=float))))
    sub = symbolic.polar_substitution()
    consistent = all(  # remainder modulo cos^2 + sin^2 = 1: 0 iff the identity holds
        symbolic.pythagorean_remainder(e) == 0
        for e in (printed.subs(sub) - symbolic.printed_polar_gram())
    )
    return PrintedMatrixAudit(
        wrong,
        {str(k): int(v) for k, v in witness.items()},
        tuple(tuple(int(x) for x in row) for row in t_w.tolist()),
        tuple(tuple(int(x) for x in row) for row in p_w.tolist()),
        eig,
        consistent,
    )


@dataclass(frozen=True)
class Theorem5Audit:
    """Extremes of Theorem 4's bound on a fine grid, per ``q = u_max / d_io``."""

    u_over_d: tuple
    grid_max: tuple  #: per q, the grid maximum
    argmax: tuple  #: per q, the grid points within 1e-12 of the maximum
    predicted_max: tuple  #: per q, ``1 / sqrt(1 + q^2)``
    symbolic_max_exact: bool  #: SymPy expands :math:`C^{-1}(1, \pi/2) - 1/\sqrt{1+q^2}` to 0
    max_on_zero_lines: float  #: largest value on theta = 0, +-pi and on alpha = 0
    value_at_large_alpha: float  #: largest value at alpha = 1e6 over the theta grid and q's
    printed_max_halfpi_equal: float  #: printed max over theta vs C^-1(alpha, pi/2), rational points
    n_alpha: int
    n_theta: int


def _ratios_iv(u_over_d) -> tuple:
    """The values of ``q = u_max / d_io`` of a Theorem 5 audit, a non-empty tuple of floats."""
    if isinstance(u_over_d, np.ndarray):
        u_over_d = u_over_d.tolist()
    qs = tuple(as_nonnegative(q, "u_over_d") for q in as_sequence(u_over_d, "u_over_d"))
    if not qs:
        raise ValueError("u_over_d must list at least one value")
    return qs


def theorem5_audit(u_over_d: tuple, alpha_max: float, alpha_per_unit: int, theta_quarter: int,
                   n_rational_points: int = 50) -> Theorem5Audit:
    """Locate the maximum and the zeros of the bound on :func:`fine_grid` for each ``q``.

    Theorem 5: the maximum ``1 / sqrt(1 + q^2)`` at ``alpha = 1``, ``theta = +-pi/2``; the
    minimum 0 at ``theta = 0, pi``, ``alpha = 0`` and ``alpha -> inf``. Also checks the proof's
    printed maximum over ``theta`` for fixed ``alpha`` at rational points.

    Examples
    --------
    >>> a = theorem5_audit((0.0, 1.0), alpha_max=2.0, alpha_per_unit=4,
    ...                    theta_quarter=4, n_rational_points=3)
    >>> ([round(float(v), 6) for v in a.grid_max],
    ...  [round(float(v), 6) for v in a.predicted_max])
    ([1.0, 0.707107], [1.0, 0.707107])
    >>> a.symbolic_max_exact
    True
    """
    return _theorem5_audit(_ratios_iv(u_over_d),
                           as_positive(alpha_max, "alpha_max"),
                           as_int(alpha_per_unit, "alpha_per_unit", 1),
                           as_int(theta_quarter, "theta_quarter", 1),
                           as_int(n_rational_points, "n_rational_points", 1))


@lru_cache(maxsize=8)
def _theorem5_audit(u_over_d, alpha_max, alpha_per_unit, theta_quarter, n_rational_points):
    import sympy as sp

    from .. import symbolic
    from ..symbolic.evaluation import max_difference_at_rational_points

    qs = u_over_d
    alpha, theta = fine_grid(alpha_max, alpha_per_unit, theta_quarter)
    gmax, argm, pred = [], [], []
    zero_lines = 0.0
    large = 0.0
    on_zero = np.isclose(np.abs(np.sin(theta)), 0.0, atol=1e-15)
    # bound_surface(alpha, theta, q, 1.0) for every q in one call: broadcasting q over a leading
    # axis computes the q-free part of Eq. (9) (S, the numerator) once, not once per q; the
    # same elementwise operations, so the same values (0.04 s against 0.14 s for five q's)
    A, T = np.meshgrid(alpha, theta)
    surfaces = pair_bound_polar(A, T, np.array(qs)[:, None, None])
    for q, Z in zip(qs, surfaces):
        m = grid_maximum(alpha, theta, Z)
        gmax.append(m.value)
        argm.append(m.points)
        pred.append(1.0 / np.sqrt(1.0 + q * q))
        zero_lines = max(zero_lines, float(Z[on_zero].max()), float(Z[:, alpha == 0].max()))
        large = max(large, float(pair_bound_polar(1e6, theta, q).max()))
    f = symbolic.theorem4_bound()
    exact = symbolic.max_value_exact() == 0
    printed = max_difference_at_rational_points(
        symbolic.printed_max_halfpi(), f.subs(symbolic.THETA, sp.pi / 2),
        {symbolic.ALPHA: (0.01, 5.0), symbolic.Q: (0.0, 3.0)}, n_rational_points, 0, 30,
    )
    return Theorem5Audit(
        qs, tuple(gmax), tuple(argm), tuple(pred), exact, zero_lines, large, printed,
        alpha.size, theta.size,
    )


def alpha_star_thetas(n_theta: int) -> np.ndarray:
    r"""The angles on which :math:`\alpha^*` is audited and plotted: ``n_theta`` interior points of
    :math:`(0, \pi)`, without those within :math:`10^{-3}` of :math:`\cos\theta = 0`.

    Examples
    --------
    >>> (alpha_star_thetas(7) / np.pi).round(4)
    array([0.125, 0.25 , 0.375, 0.625, 0.75 , 0.875])
    """
    n = as_int(n_theta, "n_theta", 1)
    theta = np.pi * (np.arange(1, n + 1) / (n + 1))
    return theta[np.abs(np.cos(theta)) > 1e-3]


@dataclass(frozen=True)
class AlphaStarAudit:
    """The maximising ``alpha`` for fixed ``theta``: numeric, closed form, brute force."""

    u_over_d: tuple
    n_theta: int
    #: largest :math:`|` closed form :math:`-` bisection root :math:`|`
    max_closed_vs_numeric: float
    max_brute_force_gap: float  #: max of (best grid value - value at alpha*) (<= 0 up to rounding)
    min_distance_from_1: float  #: min over q > 0 and theta off {0, +-pi/2, pi} of alpha* - 1
    alpha_star_at_q0: float  #: largest :math:`|\alpha^* - 1|` for :math:`q = 0` (stationary target)
    #: largest absolute value of Eq. (34) at the derived closed form, at rational points
    symbolic_root_checks: float
    stationarity_at_1: str  #: Eq. (34) at alpha = 1, factored


def alpha_star_audit(u_over_d: tuple, n_theta: int, n_rational_points: int = 50) -> AlphaStarAudit:
    """Solve Eq. (34) numerically and in closed form on ``theta`` in ``(0, pi)`` for each ``q``.

    ``theta`` runs over ``n_theta`` interior points of ``(0, pi)`` avoiding ``pi/2``
    (``alpha*`` depends on ``theta`` only through ``sin^2`` and ``|cos|``). Brute force: the
    bound never beats its value at ``alpha*`` on a grid over ``[0, 10]`` (step 0.01) and on a
    finer grid around ``alpha*`` (step 1e-4, ``alpha* +- 0.005``).

    Examples
    --------
    >>> a = alpha_star_audit((1.0,), n_theta=9, n_rational_points=3)
    >>> a.max_closed_vs_numeric < 1e-12, a.min_distance_from_1 > 0
    (True, True)
    """
    return _alpha_star_audit(_ratios_iv(u_over_d), as_int(n_theta, "n_theta", 1),
                             as_int(n_rational_points, "n_rational_points", 1))


@lru_cache(maxsize=8)
def _alpha_star_audit(u_over_d, n_theta, n_rational_points):
    import sympy as sp

    from .. import symbolic
    from ..symbolic.evaluation import max_difference_at_rational_points

    qs = u_over_d
    theta = alpha_star_thetas(n_theta)
    coarse = np.linspace(0.0, 10.0, 1001)
    local = 1e-4 * np.arange(-50, 51)
    closed_vs_num = gap = 0.0
    min_dist = np.inf
    q0 = 0.0
    for q in qs:
        num = maximising_alpha(theta, q)
        clo = maximising_alpha_closed(theta, q)
        closed_vs_num = max(closed_vs_num, float(np.abs(num - clo).max()))
        dense = np.concatenate(
            [np.broadcast_to(coarse, (theta.size, coarse.size)),
             np.maximum(num[:, None] + local, 0.0)], axis=1,
        )
        best = pair_bound_polar(dense, theta[:, None], q).max(axis=1)
        gap = max(gap, float((best - pair_bound_polar(num, theta, q)).max()))
        if q > 0:
            min_dist = min(min_dist, float((num - 1.0).min()))
        else:
            q0 = max(q0, float(np.abs(num - 1.0).max()))
    root = max_difference_at_rational_points(
        symbolic.stationarity_alpha().subs(symbolic.ALPHA,
                                           sp.sqrt(symbolic.alpha_star_squared())), 0,
        {symbolic.THETA: (0.02, 3.12), symbolic.Q: (0.0, 3.0)}, n_rational_points, 0, 40,
    )
    at1 = symbolic.stationarity_alpha_at_1()
    return AlphaStarAudit(qs, int(theta.size), closed_vs_num, gap, min_dist, q0, root, str(at1))


@dataclass(frozen=True)
class DalphaMinimumAudit:
    r"""Where :math:`\partial C/\partial\alpha` is smallest for a fixed :math:`\theta_{ji}`
    (:func:`dalpha_minimum_audit`)."""

    u_over_d: tuple
    n_theta: int
    n_cases: int  #: pairs (q, theta) examined
    #: cases where the derivative's minimum lies at a finite alpha > 0, below its values at
    #: alpha = 0 and at the largest alpha of the grid
    n_interior_minimum: int
    n_maximum_at_0: int  #: cases where the derivative is largest at alpha = 0
    alpha_at_minimum: tuple  #: smallest and largest alpha of the minimum over the cases
    minimum: tuple  #: smallest and largest value of the minimum (negative: C falls there)
    #: smallest and largest ratio of the alpha of the minimum to the maximiser alpha* of C
    beyond_alpha_star: tuple
    #: largest error of the slope at 0 against its closed form sin(theta) / sqrt(1 + q^2)
    slope_at_0_error: float
    #: largest size of the derivative at the grid's largest alpha (it tends to 0)
    at_largest_alpha: float
    largest_alpha: float  #: the grid's largest alpha
    bound_at_ends: float  #: largest bound C at alpha = 0 and at the largest alpha


def dalpha_minimum_audit(u_over_d: tuple, n_theta: int) -> DalphaMinimumAudit:
    r"""Locate the minimum over :math:`\alpha` of :math:`\partial C/\partial\alpha`
    (:func:`obslib.pair_form.dbound_dalpha`) for fixed :math:`\theta_{ji}` and :math:`q`.

    The proof of Theorem 5 says that for :math:`\theta_{ji} \ne 0, \pm\pi/2, \pi`,
    :math:`\partial C/\partial\alpha` "also reaches its minimum at :math:`\alpha = 0` or
    :math:`\alpha \to \infty`". For every ``q`` in ``u_over_d`` and the angles of
    :func:`alpha_star_thetas` ``(n_theta)``, the derivative is evaluated on :math:`\alpha = 0`
    and 4,001 points spaced evenly in :math:`\log\alpha` over :math:`[10^{-4}, 10^{4}]`, and
    its minimum refined by a bounded scalar search between the grid's neighbours. Cached on the
    arguments.

    Examples
    --------
    >>> a = dalpha_minimum_audit((0.0, 1.0), n_theta=9)
    >>> a.n_interior_minimum == a.n_cases, a.n_maximum_at_0 == a.n_cases
    (True, True)
    """
    return _dalpha_minimum_audit(_ratios_iv(u_over_d), as_int(n_theta, "n_theta", 1))


@lru_cache(maxsize=8)
def _dalpha_minimum_audit(u_over_d, n_theta):
    from scipy.optimize import minimize_scalar

    from ..pair_form import dbound_dalpha, maximising_alpha

    theta = alpha_star_thetas(n_theta)
    grid = np.r_[0.0, np.geomspace(1e-4, 1e4, 4001)]
    n_int = n_max0 = 0
    where, lows, beyond = [], [], []
    slope_err = tail = ends = 0.0
    for q in u_over_d:
        d = dbound_dalpha(grid[None, :], theta[:, None], q)  # (theta, alpha)
        star = maximising_alpha(theta, q)
        for k, th in enumerate(theta):
            row = d[k]
            j = int(np.argmin(row))
            lo, hi = grid[max(j - 1, 0)], grid[min(j + 1, grid.size - 1)]
            best = minimize_scalar(lambda a, th=th: float(dbound_dalpha(a, th, q)),
                                   bounds=(lo, hi), method="bounded",
                                   options={"xatol": 1e-10 * max(1.0, hi)})
            a_min, v_min = (best.x, best.fun) if best.fun <= row[j] else (grid[j], row[j])
            n_int += bool(0 < j < grid.size - 1 and v_min < min(row[0], row[-1]))
            n_max0 += bool(row[0] >= row.max())
            where.append(a_min)
            lows.append(v_min)
            beyond.append(a_min / star[k])
            expected = abs(np.sin(th)) / np.sqrt(1 + q * q)
            slope_err = max(slope_err, abs(row[0] - expected))
            tail = max(tail, abs(row[-1]))
            ends = max(ends, float(pair_bound_polar(grid[[0, -1]], th, q).max()))
    return DalphaMinimumAudit(
        tuple(u_over_d), int(theta.size), len(where), n_int, n_max0,
        (float(min(where)), float(max(where))), (float(min(lows)), float(max(lows))),
        (float(min(beyond)), float(max(beyond))), float(slope_err), float(tail),
        float(grid[-1]), ends)


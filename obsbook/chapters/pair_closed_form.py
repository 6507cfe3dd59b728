r"""The formulas, numbers and tables of the chapter on the bound of a pair of sensors (Theorems 4
and 5).

:func:`show` and :func:`show_entries` display SymPy's results in the chapter's visible cells;
each ``glue_*`` function formats the result of one audit of
:mod:`obslib.studies.pair_closed_form` (or :mod:`obslib.studies.theorem5_proof`,
:mod:`obslib.studies.weyl`) and glues it under the names the chapter's prose uses.
"""

from __future__ import annotations

import numpy as np

from obslib.bounds import pair_bound_polar
from obslib.claims.pair_closed_form import WEYL_TEX
from obslib.formatting import count, listing, number, setting, small, span
from obslib.pair_form import maximising_alpha

from ..glue import glue_texts
from ..tables import numbered_table, rows_table

__all__ = ["show", "show_entries", "equal", "where", "glue_thm4_symbolic", "glue_thm4_numeric",
           "glue_fig2", "glue_thm5", "glue_alpha_star", "glue_weyl", "glue_printed_matrix",
           "glue_dtheta", "glue_halfpi", "glue_dalpha", "glue_dalpha_min", "EXERCISE_PAIR",
           "EXERCISE_U_RERUN", "EXERCISE_ALPHA_UNEQUAL", "exercise_numbers", "glue_exercises"]


def show(lhs: str, expr) -> None:
    """Display the equation ``lhs = expr`` in LaTeX.

    Parameters
    ----------
    lhs : str
        The left side, in LaTeX.
    expr : sympy.Expr
        The right side.
    """
    from IPython.display import Math, display

    from obslib import symbolic

    display(Math(symbolic.latex_eq(lhs, expr)))


def show_entries(lhs: str, M) -> None:
    """Display a symmetric 2 x 2 matrix entry by entry, so that it fits the page.

    Parameters
    ----------
    lhs : str
        The matrix's name, in LaTeX.
    M : sympy.Matrix
        The matrix; its entries (1, 1), (1, 2) and (2, 2) are shown.
    """
    import sympy as sp
    from IPython.display import Math, display

    rows = [f"\\big({lhs}\\big)_{{{k}}} &= {sp.latex(M[i, j])}"
            for k, (i, j) in (("11", (0, 0)), ("12", (0, 1)), ("22", (1, 1)))]
    display(Math("\\begin{aligned}" + " \\\\ ".join(rows) + "\\end{aligned}"))


def equal(residual, how: str = "the difference is $0$") -> str:
    """A symbolic comparison's outcome in words: ``"equal: "`` and ``how`` when the residual
    (or each of a list of residuals) simplifies to 0, else ``"different"``.

    Examples
    --------
    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> equal(sp.sin(x) ** 2 + sp.cos(x) ** 2 - 1), equal([x - 1])
    ('equal: the difference is $0$', 'different')
    """
    import sympy as sp

    parts = residual if isinstance(residual, (list, tuple)) else [residual]
    return f"equal: {how}" if all(sp.simplify(r) == 0 for r in parts) else "different"


def where(points) -> str:
    r"""Grid points :math:`(\alpha, \theta)` in words; the pair :math:`(1, \pm\pi/2)` as one.

    Examples
    --------
    >>> where([(1.0, -np.pi / 2), (1.0, np.pi / 2)])
    '$\\alpha = 1$, $\\theta_{ji} = \\pm\\pi/2$'
    """
    signs = {np.sign(th) for _, th in points}
    if (all(abs(al - 1) < 1e-12 and abs(abs(th) - np.pi / 2) < 1e-12 for al, th in points)
            and signs == {-1.0, 1.0}):
        return r"$\alpha = 1$, $\theta_{ji} = \pm\pi/2$"
    return listing([f"$({setting(al)}, {number(th, 4)})$" for al, th in points])


def glue_thm4_symbolic(residuals: dict) -> None:
    """The table of Theorem 4 derived step by step and compared with the paper
    (``tab-02-thm4-symbolic``).

    Parameters
    ----------
    residuals : dict
        :func:`obslib.symbolic.theorem4_residuals`: each comparison's residual by name.
    """
    mod = r"remainder $0$ modulo $\cos^2 + \sin^2 = 1$"
    expands = "the difference expands to $0$"
    rows = [
        (r"$O_{ij}^T O_{ij}$ in polar form", "the printed polar matrix (Eq. (33))",
         equal(residuals["polar matrix"], "each entry's difference expands to $0$")),
        ("sum of the two eigenvalues", "Eq. (33)",
         equal(residuals["trace (mod cos^2 + sin^2 = 1)"], mod)),
        ("squared difference of the eigenvalues", "Eq. (33)",
         equal(residuals["(lambda_max - lambda_min)^2 (mod cos^2 + sin^2 = 1)"], mod)),
        (r"$\lambda_{\min}$ in double angles", "Eq. (33)", equal(residuals["lambda_min"], expands)),
        (r"$\lambda_{\max}$ in double angles", "Eq. (33)", equal(residuals["lambda_max"], expands)),
        (r"$\lambda_{\min}/(\lambda_{\max} + u^2)$", "the square of Eq. (9)",
         equal(residuals["ratio"], "the difference cancels to $0$")),
        (r"Cartesian discriminant $(G_{11} - G_{22})^2 + 4G_{12}^2$", "the radicand of Eq. (33)",
         equal(residuals["cartesian discriminant"], expands)),
    ]
    glue_texts(tab_thm4_symbolic=rows_table(
        rows, "Theorem 4 derived step by step with SymPy and compared with the paper.",
        "tab-02-thm4-symbolic", headers=("derived", "compared with", "outcome")))


def glue_thm4_numeric(audit) -> None:
    """Theorem 4 evaluated: the largest difference between two ways of computing the bound
    (``tab-02-thm4-numeric``).

    Parameters
    ----------
    audit : obslib.studies.pair_closed_form.Theorem4Audit
        The audit's result.
    """
    points = f"{number(audit.n_rational_points)} rational points, {number(audit.digits)} digits"
    scenes = f"{number(audit.n_random_points)} random scenes"
    rows = [
        ("the Cartesian bound against Eq. (9)", points,
         small(audit.cartesian_max_difference, 1e-40)),
        ("the library's bound from the positions against the Cartesian SymPy bound", scenes,
         small(audit.max_error_pair_bounds, 1e-14)),
        (r"the library's bound in $(\alpha, \theta_{ji}, q)$ against Eq. (9)", scenes,
         small(audit.max_error_pair_bound_polar, 1e-14)),
        ("Eq. (9) evaluated in floating point against the library", scenes
         + r" where the bound exceeds $10^{-3}$", small(audit.max_error_numpy_generic, 1e-10)),
    ]
    glue_texts(
        tab_thm4_numeric=rows_table(
            rows, "Theorem 4 evaluated: the largest difference between two ways of computing "
            "the bound.", "tab-02-thm4-numeric", headers=("compared", "at", "largest difference")),
        thm4_scenes=number(audit.n_random_points),
        thm4_error=small(max(audit.max_error_pair_bounds, audit.max_error_pair_bound_polar),
                         1e-14),
    )


def glue_fig2(paper, fine, u_max: float, d_io: float, alpha_max: float, paper_step: float) -> None:
    r"""Fig. 2's grids: the maximum of the bound on the paper's grid and on a fine one, against
    the largest value possible, :math:`1/\sqrt{1 + u_{\max}^2/d_{io}^2}` (``tab-02-fig2``).

    Parameters
    ----------
    paper, fine : obslib.studies.pair_closed_form.Fig2Grid
        The paper's grid and the fine grid (:func:`obslib.studies.pair_closed_form.fig2_grids`).
    u_max, d_io, alpha_max, paper_step : float
        Fig. 2's speed bound, distance of sensor :math:`i`, largest :math:`\alpha` and step.
    """
    peak = 1 / np.sqrt(1 + (u_max / d_io)**2)
    rows = [{"grid": r"fine, containing $\theta_{ji} = \pm\pi/2$",
             "size": f"{fine.alpha.size:,} × {fine.theta.size:,}",
             "max": number(fine.maximum.value, 6), "at": where(fine.maximum.points)},
            {"grid": f"the paper's, steps of {setting(paper_step)}",
             "size": f"{paper.alpha.size:,} × {paper.theta.size:,}",
             "max": number(paper.maximum.value, 6), "at": where(paper.maximum.points)}]
    glue_texts(
        fig2_u=setting(u_max), fig2_d=setting(d_io), fig2_alpha_max=setting(alpha_max),
        fig2_step=setting(paper_step),
        fig2_paper_max=number(paper.maximum.value, 6),
        fig2_fine_max=number(fine.maximum.value, 6),
        fig2_exact=number(peak, 6), fig2_diff=small(fine.maximum.value - peak),
        tab_fig2=numbered_table(
            rows, r"The maximum of the bound on two grids; the largest value possible is "
            rf"$1/\sqrt{{1 + u_{{\max}}^2/d_{{io}}^2}}$ = {number(peak, 6)}.", "tab-02-fig2",
            columns={"grid": ("grid", "s"),
                     r"points ($\alpha \times \theta_{ji}$)": ("size", "s"),
                     "maximum": ("max", "s"), "attained at": ("at", "s")}),
    )


def glue_thm5(audit) -> None:
    """Theorem 5 on a fine grid, for several speeds: the table of the grid's maxima
    (``tab-02-thm5``), the symbolic check of the maximum, the bound on the lines where it is
    zero and at a large distance ratio.

    Parameters
    ----------
    audit : obslib.studies.pair_closed_form.Theorem5Audit
        The audit's result.
    """
    rows = [{"q": setting(q), "max": number(m, 6), "peak": number(e, 6), "at": where(pts)}
            for q, m, e, pts in zip(audit.u_over_d, audit.grid_max, audit.predicted_max,
                                    audit.argmax)]
    glue_texts(
        tab_thm5=numbered_table(
            rows, f"The maximum of the bound on a grid of {number(audit.n_alpha)} × "
            rf"{number(audit.n_theta)} points $(\alpha, \theta_{{ji}})$ containing "
            r"$\theta_{ji} = \pm\pi/2$, for several speeds $q = u_{\max}/d_{io}$.", "tab-02-thm5",
            columns={"$q$": ("q", "s"), "grid maximum": ("max", "s"),
                     r"$1/\sqrt{1 + q^2}$": ("peak", "s"), "attained at": ("at", "s")}),
        thm5_exact=("exactly, the difference expands to $0$" if audit.symbolic_max_exact
                    else "not exactly"),
        thm5_zero=small(audit.max_on_zero_lines, 1e-15),
        thm5_large=number(audit.value_at_large_alpha),
        thm5_qs=listing(audit.u_over_d),
    )


def glue_alpha_star(audit, u_over_d_curves) -> None:
    r"""The best distance ratio :math:`\alpha^*` at two angles for each speed of
    ``u_over_d_curves`` (``tab-02-alpha-star``), and its audit: closed form, numerical root and
    dense search (``tab-02-alpha-star-check``).

    Parameters
    ----------
    audit : obslib.studies.pair_closed_form.AlphaStarAudit
        The audit's result.
    u_over_d_curves : list of float
        The speeds :math:`q = u_{\max}/d_{io}` of the table.
    """
    angles = {r"$\pi/4$": np.pi / 4, r"$\pi/8$": np.pi / 8}
    rows = [{"q": setting(q), **{a: number(maximising_alpha(t, q), 4)
                                 for a, t in angles.items()}} for q in u_over_d_curves]
    columns = {"$q$": ("q", "s"),
               **{rf"$\alpha^*$ at $\theta_{{ji}} =$ {a}": (a, "s") for a in angles}}
    rows_check = [
        ("closed form against the numerical root of Eq. (34)",
         small(audit.max_closed_vs_numeric, 1e-13)),
        (r"$\lvert g(\alpha^*)\rvert$ at rational points",
         small(audit.symbolic_root_checks, 1e-30)),
        (r"gain of a dense search over $\alpha$ on $\alpha^*$",
         small(max(audit.max_brute_force_gap, 0.0), 1e-13)),
        (r"smallest $\alpha^* - 1$ for $q > 0$", number(audit.min_distance_from_1)),
        (r"largest $\lvert\alpha^* - 1\rvert$ for $q = 0$", small(audit.alpha_star_at_q0)),
    ]
    glue_texts(
        tab_alpha_star=numbered_table(
            rows, r"The best distance ratio $\alpha^*$ at two angles, for several speeds "
            r"$q = u_{\max}/d_{io}$.", "tab-02-alpha-star", columns=columns),
        tab_alpha_star_check=rows_table(
            rows_check, rf"The maximiser $\alpha^*$ at {number(audit.n_theta)} angles and $q$ = "
            f"{listing(audit.u_over_d)}: closed form, numerical root and dense search.",
            "tab-02-alpha-star-check"),
        alpha_star_q1=number(maximising_alpha(np.pi / 4, 1.0)),
        alpha_star_gap=number(audit.min_distance_from_1),
        alpha_star_q0=small(audit.alpha_star_at_q0),
        alpha_star_closed=small(audit.max_closed_vs_numeric, 1e-13),
    )


def _violations(slack: float, tol: float) -> str:
    return "none" if slack >= -tol else f"some, down to {number(slack)}"


def glue_weyl(audit) -> None:
    """Theorem 1's Weyl step: the six inequalities of Eq. (18) and Eq. (19), SymPy's proof and
    their violations in random pairs (``tab-02-weyl``), and the index pairs the printed range
    admits (``tab-02-weyl-range``).

    Parameters
    ----------
    audit : obslib.studies.weyl.WeylAudit
        The audit's result.
    """
    rows = [(WEYL_TEX[k], "yes" if audit.symbolic_triangle_equal[k] else "no",
             _violations(v, 1e-14)) for k, v in audit.min_relative_slack.items()]
    rows.append(("Eq. (19), on positive semidefinite pairs", "not needed",
                 _violations(audit.min_ratio_slack, 1e-12)))
    glue_texts(
        tab_weyl=rows_table(
            rows, f"The six inequalities of Eq. (18) and Eq. (19): SymPy's proof, and the "
            f"violations in {number(audit.n_pairs)} random pairs of symmetric matrices.",
            "tab-02-weyl",
            headers=("inequality", "a triangle inequality (SymPy)", "violations")),
        tab_weyl_range=rows_table(
            [(f"$({i}, {j})$", number(k), "yes" if k >= 1 else "no")
             for i, j, k in audit.printed_range],
            r"The index pairs $(i, j)$ that the printed range admits for $r = 2$.",
            "tab-02-weyl-range", headers=("$(i, j)$", "$i + j - r$", "a valid index")),
        weyl_pairs=number(audit.n_pairs),
        weyl_invalid=listing([f"$(i, j) = ({i}, {j})$" for i, j, _ in audit.invalid_indices]),
    )


def _bmatrix(rows) -> str:
    body = r" \\ ".join(" & ".join(str(int(v)) for v in row) for row in rows)
    return rf"$\begin{{bmatrix}} {body} \end{{bmatrix}}$"


def glue_printed_matrix(audit) -> None:
    """The printed Cartesian matrix of Eq. (32) against the derived one at the audit's witness
    (``tab-02-matrix``).

    Parameters
    ----------
    audit : obslib.studies.pair_closed_form.PrintedMatrixAudit
        The audit's result.
    """
    w = audit.witness
    at = (f"$o = ({w['o_x']}, {w['o_y']})$, $p_i = ({w['p_ix']}, {w['p_iy']})$, "
          f"$p_j = ({w['p_jx']}, {w['p_jy']})$")
    true_eig = np.linalg.eigvalsh(np.array(audit.true_at_witness, dtype=float))
    rows = [("derived", _bmatrix(audit.true_at_witness), listing([number(x) for x in true_eig])),
            ("printed (Eq. (32))", _bmatrix(audit.printed_at_witness),
             listing([number(x) for x in audit.printed_eigenvalues_at_witness]))]
    glue_texts(
        tab_matrix=rows_table(rows, f"The two matrices at {at}.", "tab-02-matrix",
                              headers=("matrix", "value", "eigenvalues")),
        n_wrong=count(len(audit.wrong_entries), of=4),
        printed_eig_min=number(min(audit.printed_eigenvalues_at_witness)),
        polar_consistent="gives" if audit.polar_printed_consistent else "does not give",
    )


def glue_dtheta(audit, n_rational_points: int) -> None:
    r"""The derivative in :math:`\theta` at sampled points (``tab-02-dtheta``).

    Parameters
    ----------
    audit : obslib.studies.theorem5_proof.ThetaDerivativeAudit
        The audit of :math:`\partial C/\partial\theta`
        (:func:`obslib.studies.theorem5_proof.theta_derivative_audit`).
    n_rational_points : int
        The rational points :math:`(\alpha, q)` it samples.
    """
    left, right = audit.corner_halfpi_slopes
    rows = [
        (r"one-sided slopes of $C$ at $\theta = 0$ against the limit above",
         small(audit.slope_at_zero_error, 1e-20)),
        ("smallest of those slopes", number(audit.slope_at_zero_min)),
        (r"slopes of $C$ left and right of $\theta = \pi/2$, for $\alpha = 1$, $q = 1$",
         listing([number(left), number(right)])),
        (r"smallest second derivative of $C^2$ at $\theta = 0$",
         number(audit.square_second_derivative_zero)),
        (r"largest second derivative of $C^2$ at $\theta = \pi/2$, $\alpha \ne 1$",
         number(audit.square_second_derivative_halfpi)),
    ]
    glue_texts(
        tab_dtheta=rows_table(
            rows, f"The derivative in $\\theta$ at {number(n_rational_points)} sampled points "
            r"$(\alpha, q)$.", "tab-02-dtheta"),
        dtheta_closed="equal" if audit.closed_form_equal else "not equal",
        corner_slopes=listing([number(left), number(right)]),
        dtheta_min_slope=number(audit.slope_at_zero_min),
    )


def glue_halfpi(audit, theorem5, n_rational_points: int) -> None:
    r"""The derivative of the bound in :math:`\alpha` at :math:`\theta = \pi/2`, :math:`q = 1`
    (``tab-02-halfpi``), and the printed maximum over :math:`\theta` there.

    Parameters
    ----------
    audit : obslib.studies.theorem5_proof.AlphaDerivativeAudit
        The audit's result.
    theorem5 : obslib.studies.pair_closed_form.Theorem5Audit
        Theorem 5's audit (the printed maximum at :math:`\theta = \pi/2`).
    n_rational_points : int
        The points sampled.
    """
    below, left, right = audit.halfpi_true_slopes
    rows = [
        (r"true derivative on $(0, 1)$", number(below)),
        (r"true derivative left and right of $\alpha = 1$", listing([number(left), number(right)])),
        (r"the printed expression at $\alpha = 1$", number(audit.halfpi_printed_at_1)),
        (r"largest difference, printed minus true, on $(0, 1)$",
         number(audit.halfpi_printed_vs_true)),
        (r"largest second derivative on $(0, 1)$", number(audit.halfpi_second_derivative_below_1)),
    ]
    glue_texts(
        tab_halfpi=rows_table(
            rows, r"The derivative of the bound in $\alpha$ at $\theta = \pi/2$, $q = 1$.",
            "tab-02-halfpi"),
        halfpi_max_diff=small(theorem5.printed_max_halfpi_equal, 1e-25),
        n_rat=number(n_rational_points),
        halfpi_below=number(below), halfpi_right=number(right),
    )


def glue_dalpha(audit, n_rational_points: int) -> None:
    r"""The printed derivative in :math:`\alpha` against the true one at sampled points
    (``tab-02-dalpha``).

    Parameters
    ----------
    audit : obslib.studies.theorem5_proof.AlphaDerivativeAudit
        The audit of the derivatives in :math:`\alpha`.
    n_rational_points : int
        How many points :math:`(\alpha, \theta, q)` it compares the two at.
    """
    lo, hi = audit.printed_ratio_spread
    rows = [
        ("the numerator $g$ against Eq. (34)",
         "equal: the difference expands to $0$" if audit.numerator_equals_eq36 else "different"),
        (r"SymPy's derivative against the factored form above",
         "equal: the difference reduces to $0$" if audit.closed_form_equal else "different"),
        ("true over printed derivative", span(lo, hi)),
        (r"slope at $\alpha = 0$ against $|\sin\theta|/\sqrt{1 + q^2}$",
         small(audit.slope_at_alpha0, 1e-12)),
        (r"smallest slope at $\alpha = 0$", number(audit.slope_at_alpha0_min)),
    ]
    glue_texts(
        tab_dalpha=rows_table(
            rows, f"The printed derivative in $\\alpha$ against the true one at "
            rf"{number(n_rational_points)} sampled points $(\alpha, \theta, q)$.",
            "tab-02-dalpha"),
        ratio_span=span(lo, hi),
        slope_min=number(audit.slope_at_alpha0_min),
    )


def glue_dalpha_min(audit) -> None:
    r"""Where :math:`\partial C/\partial\alpha` is smallest for a fixed angle and speed
    (:func:`obslib.studies.pair_closed_form.dalpha_minimum_audit`): the cases, those with the
    minimum at a finite :math:`\alpha`, where that is, and the derivative's value at
    :math:`\alpha = 0`.

    Parameters
    ----------
    audit : obslib.studies.pair_closed_form.DalphaMinimumAudit
        The audit's result.
    """
    glue_texts(
        dm_cases=number(audit.n_cases),
        dm_angles=number(audit.n_theta),
        dm_interior=count(audit.n_interior_minimum, of=audit.n_cases),
        dm_max0=count(audit.n_maximum_at_0, of=audit.n_cases),
        dm_where=span(*audit.alpha_at_minimum),
        dm_beyond=span(*audit.beyond_alpha_star),
        dm_value=span(*audit.minimum),
        dm_slope0=small(audit.slope_at_0_error),
        dm_tail=small(audit.at_largest_alpha),
        dm_largest=number(audit.largest_alpha),
    )


#: Exercise 1: a pair at equal distances (``alpha``), the angle between the sensors
#: (``theta``, and as TeX) and the speed ``q = u_max / d_io``.
EXERCISE_PAIR = {"alpha": 1.0, "theta": np.pi / 4, "theta_tex": r"$\pi/4$", "q": 0.5}
#: Exercise 2: the speed bound (m/s) at which Fig. 2 is redrawn, and the distance ratio of an
#: unequal pair at a right angle.
EXERCISE_U_RERUN = 2.0
EXERCISE_ALPHA_UNEQUAL = 2.0


def exercise_numbers(u_max: float, d_io: float, u_rerun: float = EXERCISE_U_RERUN) -> dict:
    r"""The numbers of the chapter's exercises.

    Returns
    -------
    dict
        ``"by_hand"``: :data:`EXERCISE_PAIR`'s :math:`S = \sqrt{1 + \alpha^4 + 2\alpha^2\cos
        2\theta}` and its bound (Eq. (9)); ``"rerun"``: the peak of Fig. 2, :math:`1/\sqrt{1 +
        q^2}`, at the chapter's speed and at ``u_rerun``, and the bound at :math:`\alpha` =
        :data:`EXERCISE_ALPHA_UNEQUAL`, :math:`\theta = \pi/2` at both; ``"counter"``: at the
        angle of :data:`EXERCISE_PAIR` and ``q = u_max / d_io``, the maximiser
        :math:`\alpha^*` and the bound there and at :math:`\alpha = 1`, and the maximiser for
        a stationary target.

    Parameters
    ----------
    u_max, d_io : float
        The speed bound and the distance of sensor :math:`i` of Fig. 2.
    u_rerun : float
        The speed bound the rerun exercise asks about.
    """
    e = EXERCISE_PAIR
    a, th = e["alpha"], e["theta"]
    S = float(np.sqrt(1 + a**4 + 2 * a**2 * np.cos(2 * th)))
    q, q2 = u_max / d_io, u_rerun / d_io
    star, star0 = float(maximising_alpha(th, q)), float(maximising_alpha(th, 0.0))
    return {
        "by_hand": {"S": S, "bound": float(pair_bound_polar(a, th, e["q"]))},
        "rerun": {"q": q, "q_rerun": q2,
                  "peak": float(pair_bound_polar(1.0, np.pi / 2, q)),
                  "peak_rerun": float(pair_bound_polar(1.0, np.pi / 2, q2)),
                  "unequal": float(pair_bound_polar(EXERCISE_ALPHA_UNEQUAL, np.pi / 2, q)),
                  "unequal_rerun": float(pair_bound_polar(EXERCISE_ALPHA_UNEQUAL, np.pi / 2, q2))},
        "counter": {"q": q, "alpha_star": star, "at_star": float(pair_bound_polar(star, th, q)),
                    "at_one": float(pair_bound_polar(1.0, th, q)), "alpha_star_q0": star0},
    }


def glue_exercises(u_max: float, d_io: float, u_rerun: float = EXERCISE_U_RERUN) -> dict:
    """Glue the numbers of the chapter's exercises (:func:`exercise_numbers`); returns them.

    ``u_max``, ``d_io`` and ``u_rerun`` are those of :func:`exercise_numbers`.
    """
    x = exercise_numbers(u_max, d_io, u_rerun)
    h, r, c = x["by_hand"], x["rerun"], x["counter"]
    e = EXERCISE_PAIR
    glue_texts(
        x1_alpha=setting(e["alpha"]), x1_theta=e["theta_tex"], x1_q=setting(e["q"]),
        x1_S=number(h["S"]), x1_bound=number(h["bound"]),
        x2_u=setting(u_max), x2_d=setting(d_io), x2_u_rerun=setting(u_rerun),
        x2_alpha=setting(EXERCISE_ALPHA_UNEQUAL),
        x2_peak=number(r["peak"]), x2_peak_rerun=number(r["peak_rerun"]),
        x2_unequal=number(r["unequal"]), x2_unequal_rerun=number(r["unequal_rerun"]),
        x3_q=setting(c["q"]), x3_star=number(c["alpha_star"]), x3_at_star=number(c["at_star"]),
        x3_at_one=number(c["at_one"]), x3_star0=number(c["alpha_star_q0"]),
    )
    return x

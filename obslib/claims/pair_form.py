"""Claims of the pair closed form (Theorems 4-5, Fig. 2 and the printed steps of their proofs),
checked at the sizes of notebook 02's profile in :mod:`obslib.profiles`.
"""

from __future__ import annotations

from dataclasses import asdict

import numpy as np

from ..profiles import params
from ..studies import pair_form as pf
from .._format import format_small
from ._ledger import Finding, claim

NB = "02_pair_closed_form"

#: Floating-point agreement required between independent evaluations (values in [0, 1]).
TOL_FLOAT = 1e-10
#: Exact (high-precision) checks at ``digits`` digits must agree to ``digits - TOL_EXACT_DIGITS``.
TOL_EXACT_DIGITS = 10


def _cmp(text: str) -> str:
    """``"= 0.3"`` or ``"< 1e-12"``: a relation for a :func:`obslib.notebook.format_small` string."""
    return text if text.startswith("<") else f"= {text}"


def _qs(p: dict) -> tuple:
    """The values of u_max / d_io audited (:func:`obslib.pair_form.audit_ratios`)."""
    return pf.audit_ratios(p["u_max"], p["d_io"], p["u_over_d_curves"])


@claim(
    id="thm4",
    where="Theorem 4 (Sec. III, Eq. (9)); proof in the appendix (Eq. (33))",
    title=r"Closed form of the pair bound in $\alpha = d_{jo}/d_{io}$ and $\theta_{ji}$.",
    statement=r"For two sensors $i, j$ the lower bound is $\sqrt{\lambda_{\min}/(\lambda_{\max} "
    r"+ u_{\max}^2)} = \sqrt{\dfrac{1 + \alpha^2 - S}{1 + \alpha^2 + S + 2u_{\max}^2/d_{io}^2}}$ "
    r"with $S = \sqrt{1 + \alpha^4 + 2\alpha^2 \cos 2\theta_{ji}}$ and $\alpha = d_{jo}/d_{io}$; "
    r"the eigenvalues of $O_{ij}^T O_{ij}$ are $\tfrac12\bigl(d_{io}^2 + d_{jo}^2 \mp "
    r"\sqrt{d_{io}^4 + d_{jo}^4 + 2 d_{io}^2 d_{jo}^2 \cos 2\theta_{ji}}\bigr)$.",
    paper="Eq. (9) and Eq. (33).",
    notebook=NB,
)
def _thm4(profile: str) -> Finding:
    p = params(NB, profile)
    a = pf.theorem4_audit(p["n_rational_points"], p["n_random_points"], p["seed"], p["digits"])
    symbolic = (
        a.polar_matrix_printed_equal and a.eigenvalues_printed_equal and a.theorem4_ratio_equal
        and a.cartesian_discriminant_equal
    )
    exact_ok = a.cartesian_max_difference < 10.0 ** -(a.digits - TOL_EXACT_DIGITS)
    numeric_ok = max(a.max_error_pair_bounds, a.max_error_pair_bound_polar) < TOL_FLOAT
    ok = symbolic and exact_ok and numeric_ok
    return Finding(
        "reproduced" if ok else "refuted",
        r"SymPy's eigenvalues of $O_{ij}^T O_{ij}$ in polar form equal Eq. (33) and reduce to "
        f"Eq. (9) (symbolic simplification to zero: {symbolic}); in Cartesian form the "
        r"discriminant identity expands to zero and the whole bound, with $\alpha$, "
        r"$\theta_{ji}$ (difference of the two polar angles) and $u_{\max}/d_{io}$ computed from "
        f"the point, matches Eq. (9) at {a.n_rational_points} rational points "
        f"to {format_small(a.cartesian_max_difference, 1e-40)} ({a.digits} digits). Evaluated, "
        f"it equals `obslib.pair_bounds` to {format_small(a.max_error_pair_bounds, 1e-14)} and "
        f"`pair_bound_polar` to {format_small(a.max_error_pair_bound_polar, 1e-14)} at "
        f"{a.n_random_points} random points.",
        asdict(a),
    )


@claim(
    id="fig2-max",
    where="Fig. 2 and its discussion (Sec. III)",
    title=r"Fig. 2: the plotted bound peaks at $\alpha = 1$, $\theta_{ji} = \pm\pi/2$.",
    statement=r"With $u_{\max} = 1$ and $d_{io} = 1$ the bound plotted over $\alpha \in [0, 5]$, "
    r"$\theta_{ji} \in [-\pi, \pi]$ reaches its maximum at $\alpha = 1$, "
    r"$\theta_{ji} = \pm\pi/2$.",
    paper=r"Maximum at $\alpha = 1$, $\theta_{ji} = \pm\pi/2$ (Fig. 2 a-d).",
    notebook=NB,
)
def _fig2_max(profile: str) -> Finding:
    p = params(NB, profile)
    q = p["u_max"] / p["d_io"]
    grids = pf.fig2_grids(p["u_max"], p["d_io"], p["alpha_max"], p["paper_step"],
                          p["fine_alpha_per_unit"], p["fine_theta_quarter"])
    a_p, t_p, mp = grids["paper"].alpha, grids["paper"].theta, grids["paper"].maximum
    a_f, t_f, mf = grids["fine"].alpha, grids["fine"].theta, grids["fine"].maximum
    exact = 1.0 / np.sqrt(1.0 + q * q)
    at = {(round(al, 12), round(abs(th), 12)) for al, th in mf.points}
    fine_ok = abs(mf.value - exact) < TOL_FLOAT and at == {(1.0, round(np.pi / 2, 12))}
    # on the paper's grid the maximum must sit at the grid points nearest to (1, +-pi/2)
    near = {(1.0, float(t_p[np.argmin(np.abs(t_p - s * np.pi / 2))])) for s in (-1, 1)}
    paper_at = {(round(al, 12), th) for al, th in mp.points}
    paper_ok = mp.value <= exact + TOL_FLOAT and paper_at <= {(1.0, th) for _, th in near}
    ok = fine_ok and paper_ok
    pts = ", ".join(f"({al:g}, {th:.4f})" for al, th in mp.points)
    return Finding(
        "reproduced" if ok else "refuted",
        rf"On a fine grid containing $\theta_{{ji}} = \pm\pi/2$ ({a_f.size} $\times$ {t_f.size}) "
        rf"the maximum is {mf.value:.6f} $= 1/\sqrt{{1 + u_{{\max}}^2/d_{{io}}^2}}$ at "
        rf"$\alpha = 1$, $\theta_{{ji}} = \pm\pi/2$. The paper's grid ($\alpha = 0, 0.1, \dots, 5$, "
        rf"$\theta_{{ji}} = -\pi, -\pi + 0.1, \dots$; {a_p.size} $\times$ {t_p.size}) misses "
        rf"$\pm\pi/2$: its plotted maximum is {mp.value:.4f} at $(\alpha, \theta_{{ji}})$ = {pts}, "
        "the grid point nearest to the true peak.",
        {"fine_max": mf.value, "fine_at": mf.points, "paper_max": mp.value, "paper_at": mp.points,
         "exact": exact},
    )


@claim(
    id="thm5",
    where="Theorem 5 (Sec. III)",
    title=r"The pair bound is largest at $\alpha = 1$, $\theta_{ji} = \pm\pi/2$ and $0$ on the "
    "degenerate geometries.",
    statement=r"The pair bound reaches its maximum $1/\sqrt{1 + u_{\max}^2/d_{io}^2}$ at "
    r"$\alpha = 1$ and $\theta_{ji} = \pm\pi/2$, and its minimum $0$ at $\theta_{ji} = 0, \pi$, "
    r"$\alpha = 0$ or $\alpha \to \infty$.",
    paper=r"Maximum $1/\sqrt{1 + u_{\max}^2/d_{io}^2}$ at $(1, \pm\pi/2)$; minimum $0$.",
    notebook=NB,
)
def _thm5(profile: str) -> Finding:
    p = params(NB, profile)
    qs = _qs(p)
    a = pf.theorem5_audit(
        qs, p["alpha_max"], p["fine_alpha_per_unit"], p["fine_theta_quarter"], p["n_rational_points"]
    )
    peaks_ok = all(
        abs(m - e) < TOL_FLOAT
        and {(round(al, 12), round(abs(th), 12)) for al, th in pts} == {(1.0, round(np.pi / 2, 12))}
        for m, e, pts in zip(a.grid_max, a.predicted_max, a.argmax)
    )
    ok = (
        peaks_ok and a.symbolic_max_exact and a.max_on_zero_lines < TOL_FLOAT
        and a.value_at_large_alpha < 1e-5 and a.printed_max_halfpi_equal < 1e-20
    )
    return Finding(
        "reproduced" if ok else "refuted",
        rf"For $q = u_{{\max}}/d_{{io}}$ in {list(qs)} the maximum over a {a.n_alpha} $\times$ "
        rf"{a.n_theta} grid containing $\theta_{{ji}} = \pm\pi/2$ equals $1/\sqrt{{1 + q^2}}$ "
        r"(to $< 10^{-10}$) and is attained only at $\alpha = 1$, $\theta_{ji} = \pm\pi/2$; "
        "SymPy gives the value exactly. The bound is $0$ (to "
        f"{format_small(a.max_on_zero_lines, 1e-15)}) on $\\theta_{{ji}} = 0, \\pm\\pi$ and "
        f"$\\alpha = 0$, and below {a.value_at_large_alpha:.1e} at $\\alpha = 10^6$. Proof (ours): "
        r"$C^2 \le 1/(1+q^2)$ if and only if $q^2 (\alpha^2 - 1) \le S (2 + q^2)$, true as "
        r"$S \ge \lvert 1 - \alpha^2\rvert$, with equality only at $\alpha = 1$, "
        r"$\cos\theta_{ji} = 0$. The maximum is a cone-shaped peak ($S = 0$ there), not a "
        "stationary point.",
        asdict(a),
    )


@claim(
    id="thm5-alpha-not-1",
    where="Theorem 5 (Sec. III), last sentence; proof, Eq. (34)",
    title=r"For a fixed $\theta_{ji} \ne 0, \pm\pi/2, \pi$ the best $\alpha$ is not $1$.",
    statement=r"For a fixed $\theta_{ji}$ other than $0, \pm\pi/2, \pi$, the maximum over "
    r"$\alpha$ is not at $\alpha = 1$ (the minima are at $\alpha = 0$ and $\alpha \to \infty$).",
    paper=r"$\alpha = 1$ does not satisfy Eq. (34) when $\theta_{ji}$ is not $0, \pm\pi/2, \pi$.",
    notebook=NB,
)
def _thm5_alpha(profile: str) -> Finding:
    p = params(NB, profile)
    qs = _qs(p)
    a = pf.alpha_star_audit(qs, p["n_theta_curve"])
    consistent = a.max_closed_vs_numeric < TOL_FLOAT and a.max_brute_force_gap < TOL_FLOAT
    moving_ok = a.min_distance_from_1 > 0
    stationary_is_1 = 0.0 in qs and a.alpha_star_at_q0 < TOL_FLOAT
    if consistent and moving_ok and stationary_is_1:
        status = "partly"
    elif consistent and moving_ok:
        status = "reproduced"
    else:
        status = "refuted"
    return Finding(
        status,
        r"True for a moving target only. Eq. (34) at $\alpha = 1$ simplifies to "
        r"$2 q^2 \lvert\cos\theta_{ji}\rvert (1 - \lvert\cos\theta_{ji}\rvert)$, "
        r"$q = u_{\max}/d_{io}$, which vanishes for $q = 0$: with $u_{\max} = 0$ the maximiser is "
        r"$\alpha = 1$ for every $\theta_{ji}$ (largest $\lvert\alpha^* - 1\rvert$ "
        f"{_cmp(format_small(a.alpha_star_at_q0))}). For $q > 0$ the maximiser exceeds $1$ "
        f"(smallest $\\alpha^* - 1$ = {a.min_distance_from_1:.2g} over {a.n_theta} "
        "angles and $q$ in " + str([x for x in qs if x > 0]) + "), in closed form (ours) "
        r"$\alpha^{*2} = r\,(r \sin^2\theta_{ji} + q^2 \lvert\cos\theta_{ji}\rvert) / (q^2 + "
        r"\sin^2\theta_{ji})$, $r = \sqrt{1 + q^2}$; it matches the bisection root of Eq. (34) to "
        f"{format_small(a.max_closed_vs_numeric, 1e-13)} and "
        "a dense brute-force search.",
        asdict(a),
    )


@claim(
    id="thm1-weyl-step",
    where="Proof of Theorem 1 (appendix, Eqs. (16)-(19))",
    title=r"The Weyl step of Theorem 1's proof: $\lambda_1/\lambda_2$ of a sum of $2\times 2$ "
    "matrices.",
    statement=r"For symmetric $2\times 2$ matrices $X, Y$ with eigenvalues "
    r"$\lambda_1 \le \lambda_2$: $\lambda_1(X+Y) \ge \lambda_1(X)+\lambda_1(Y)$, "
    r"$\lambda_1(X+Y) \le \min(\lambda_1(X)+\lambda_2(Y), \lambda_2(X)+\lambda_1(Y))$, "
    r"$\lambda_2(X+Y) \le \lambda_2(X)+\lambda_2(Y)$ and "
    r"$\lambda_2(X+Y) \ge \max(\lambda_1(X)+\lambda_2(Y), \lambda_2(X)+\lambda_1(Y))$; hence "
    r"$\lambda_1(X+Y)/\lambda_2(X+Y) \ge (\lambda_1(X) + \lambda_1(Y))/(\lambda_2(X) + "
    r"\lambda_2(Y))$ for positive semidefinite $X, Y$.",
    paper=r"Weyl and dual Weyl inequalities applied to $O(o)^T O(o) + O(u_o)^T O(u_o)$.",
    notebook=NB,
)
def _weyl(profile: str) -> Finding:
    p = params(NB, profile)
    a = pf.weyl_audit(p["n_weyl"], p["seed"])
    sym_ok = all(a.symbolic_triangle_equal.values())
    num_ok = min(a.min_relative_slack.values()) >= -1e-14 and a.min_ratio_slack >= -1e-12
    ok = sym_ok and num_ok
    return Finding(
        "reproduced" if ok else "refuted",
        r"Proved symbolically: with $\lambda_{1,2}(X) = \tfrac12\operatorname{tr} X \mp "
        r"\tfrac12\lVert v(X)\rVert$, $v = (a - c, 2b)$ for $X = \begin{bmatrix} a & b \\ b & c"
        r"\end{bmatrix}$, each of the six inequalities is a triangle inequality in the plane "
        "(SymPy: slack minus triangle form simplifies to $0$ for all six: "
        f"{sym_ok}). Random check over {a.n_pairs} pairs at scales "
        r"$10^{-3}$ to $10^{3}$: every slack $\ge -10^{-14}$ relative to "
        rf"$\lVert X\rVert + \lVert Y\rVert$: {num_ok} (Eq. (19) on positive semidefinite pairs "
        "included).",
        {"symbolic": a.symbolic_triangle_equal, "min_relative_slack": a.min_relative_slack,
         "min_ratio_slack": a.min_ratio_slack, "n_pairs": a.n_pairs},
    )


@claim(
    id="thm1-proof-dual-weyl-range",
    where="Proof of Theorem 1 (appendix, dual Weyl inequality, Eq. (17))",
    title=r"The proof of Theorem 1 states the dual Weyl inequality for $i + j - r \le r$.",
    statement=r"The proof of Theorem 1 states the dual Weyl inequality as "
    r"$\lambda_{i+j-r}(X+Y) \le \lambda_i(X) + \lambda_j(Y)$ for $i, j \ge 1$ and "
    r"$i + j - r \le r$.",
    paper=r"Range printed as $i + j - r \le r$.",
    notebook=NB,
)
def _weyl_range(profile: str) -> Finding:
    p = params(NB, profile)
    a = pf.weyl_audit(p["n_weyl"], p["seed"])
    bad = a.invalid_indices
    dual = ("l1 <= l1+l2", "l1 <= l2+l1", "l2 <= l2+l2")
    holds_on_valid = min(a.min_relative_slack[k] for k in dual) >= -1e-14
    status = "partly" if bad and holds_on_valid else ("reproduced" if holds_on_valid else "refuted")
    return Finding(
        status,
        r"The inequality holds on its proper range $i + j - r \ge 1$ (the three instances the "
        r"proof uses, verified in the Weyl-step claim), but the printed condition "
        r"$i + j - r \le r$ is always true and admits meaningless indices: for $r = 2$ it admits "
        f"$(i, j)$ = {[(i, j) for i, j, _ in bad]}, giving $\\lambda_0$. Corrected: "
        r"$i + j - r \ge 1$.",
        {"printed_range": a.printed_range, "invalid": bad},
    )


@claim(
    id="thm4-proof-matrix",
    where="Proof of Theorem 4 (appendix, Eq. (32))",
    title=r"Eq. (32), in the proof of Theorem 4, gives $O_{ij}^T O_{ij}$ in Cartesian form.",
    statement=r"The proof of Theorem 4 prints $O_{ij}^T O_{ij} = \begin{bmatrix} "
    r"(o_x-p_{ix})^2 & (o_x-p_{jx})(o_y-p_{iy}) \\ (o_y-p_{iy})(o_x-p_{jx}) & (o_y-p_{jy})^2 "
    r"\end{bmatrix}$.",
    paper="The matrix as printed.",
    notebook=NB,
)
def _matrix(profile: str) -> Finding:
    a = pf.printed_matrix_audit()
    neg = min(a.printed_eigenvalues_at_witness) < 0
    status = "refuted" if a.wrong_entries else "reproduced"
    return Finding(
        status,
        f"Wrong in {len(a.wrong_entries)} of 4 entries: the true matrix has diagonal "
        r"$(o_x-p_{ix})^2 + (o_x-p_{jx})^2$, $(o_y-p_{iy})^2 + (o_y-p_{jy})^2$ and off-diagonal "
        r"$(o_x-p_{ix})(o_y-p_{iy}) + (o_x-p_{jx})(o_y-p_{jy})$. At $o = (0, 0)$, "
        r"$p_i = (1, 2)$, $p_j = (3, 1)$ it is "
        f"{[list(r) for r in a.true_at_witness]}, the printed one "
        f"{[list(r) for r in a.printed_at_witness]}"
        + (
            f" (eigenvalues {a.printed_eigenvalues_at_witness[0]:.0f} and "
            f"{a.printed_eigenvalues_at_witness[1]:.0f}: not even positive semidefinite)"
            if neg else ""
        )
        + ". The polar matrix printed next to it and the eigenvalues (Eq. (33)) are correct, so "
        "the error is typographical"
        + ("" if not a.polar_printed_consistent else " (yet consistent with the polar form)")
        + ".",
        asdict(a),
    )


@claim(
    id="thm5-proof-dtheta",
    where=r"Proof of Theorem 5 (appendix, derivative in $\theta_{ji}$)",
    title=r"The proof of Theorem 5 treats $\theta_{ji} = 0, \pm\pi/2, \pi$ as stationary points "
    r"of $C$.",
    statement=r"The proof of Theorem 5 prints: $\partial C/\partial\theta = 0 \Rightarrow "
    r"\alpha^2 \sin 2\theta = 0 \Rightarrow \theta = 0, \pm\pi/2, \pi$, with "
    r"$\partial^2 C/\partial\theta^2 > 0$ at $\theta = 0, \pi$ and $< 0$ at $\pm\pi/2$.",
    paper="As printed (first display of the proof).",
    notebook=NB,
)
def _dtheta(profile: str) -> Finding:
    p = params(NB, profile)
    a = pf.theta_derivative_audit(p["n_rational_points"], p["seed"])
    kink = a.slope_at_zero_min > 0 and a.slope_at_zero_error < 1e-20
    corner = a.corner_halfpi_slopes[0] > 0 > a.corner_halfpi_slopes[1]
    square_ok = a.square_second_derivative_zero > 0 > a.square_second_derivative_halfpi
    if a.closed_form_equal and square_ok and (kink or corner):
        status = "partly"
    elif a.closed_form_equal and square_ok:
        status = "reproduced"
    else:
        status = "refuted"
    l, r = a.corner_halfpi_slopes
    return Finding(
        status,
        r"For $C$ itself $\theta = 0, \pi$ are not stationary "
        r"points: $C \sim \lvert\sin\theta\rvert$ there, with one-sided slopes "
        r"$\pm\alpha / \bigl(\sqrt{\alpha^2 + 1}\,\sqrt{\alpha^2 + q^2 + 1}\bigr)$ "
        f"(smallest {a.slope_at_zero_min:.3f} over the sampled points), "
        r"and at $\alpha = 1$ the maximum $\theta = \pi/2$ is a corner too ($S = 0$; slopes "
        f"{l:+.3f} and {r:+.3f} for $q = 1$). The second derivatives printed there do not exist. "
        r"The argument is right for $C^2$ ($\partial(C^2)/\partial\theta$ is proportional to "
        r"$\sin 2\theta$; its second derivative is $> 0$ at $\theta = 0$ and $< 0$ at $\pi/2$ "
        r"for $\alpha \ne 1$), so the extremes found are right.",
        asdict(a),
    )


@claim(
    id="thm5-proof-dalpha-halfpi",
    where=r"Proof of Theorem 5 (appendix, derivative in $\alpha$ at $\theta_{ji} = \pm\pi/2$)",
    title=r"The proof of Theorem 5: at $\theta_{ji} = \pm\pi/2$, $\partial C/\partial\alpha$ "
    r"vanishes at $\alpha = 0, 1, \infty$.",
    statement=r"The proof of Theorem 5 prints: at $\theta = \pm\pi/2$, "
    r"$\partial C/\partial\alpha = 0 \Rightarrow \alpha (1 - \alpha^2) / (1 + \alpha^2 + "
    r"\lvert 1 - \alpha^2\rvert + 2u_{\max}^2/d_{io}^2)^{5/2} = 0 \Rightarrow \alpha = 0, 1, "
    r"\infty$, with $\partial^2 C/\partial\alpha^2 > 0$ at $\alpha = 0, \infty$ and $< 0$ at "
    r"$\alpha = 1$.",
    paper="As printed.",
    notebook=NB,
)
def _dalpha_halfpi(profile: str) -> Finding:
    p = params(NB, profile)
    a = pf.alpha_derivative_audit(p["n_rational_points"], p["seed"])
    below, left, right = a.halfpi_true_slopes
    never_zero = below > 0 and left > 0 > right
    wrong = (
        never_zero and a.halfpi_printed_vs_true > 1e-3
        and a.halfpi_second_derivative_below_1 < 1e-15
    )
    return Finding(
        "refuted" if wrong else "reproduced",
        "The printed expression is not the derivative: it differs from it by up to "
        f"{a.halfpi_printed_vs_true:.3f} on "
        r"$(0, 1)$ and is $0$ at $\alpha = 1$, where the bound has a corner. At "
        r"$\theta = \pi/2$ the bound is $\alpha/\sqrt{1 + q^2}$ for $\alpha \le 1$ and "
        r"$1/\sqrt{\alpha^2 + q^2}$ for $\alpha \ge 1$. Its derivative is never $0$: "
        f"{below:.4f} on $(0, 1)$ ($q = 1$), jumping from "
        f"{left:+.4f} to {right:+.4f} at $\\alpha = 1$ (so no second derivative there). "
        r"On $(0, 1)$ the second derivative is $0$, not "
        r"$> 0$, at $\alpha = 0$. The conclusion (maximum at $\alpha = 1$, value "
        r"$1/\sqrt{1 + q^2}$; the printed maximum over $\theta$ is correct) stands.",
        asdict(a),
    )


@claim(
    id="thm5-proof-dalpha",
    where=r"Proof of Theorem 5 (appendix, derivative in $\alpha$ for a fixed $\theta_{ji}$, "
    "before Eq. (34))",
    title=r"The proof of Theorem 5 gives $\partial C/\partial\alpha$ up to a positive factor.",
    statement=r"The proof of Theorem 5 prints, up to a positive factor, "
    r"$\partial C/\partial\alpha = \alpha \bigl[(1 - \alpha^2)(1 - \cos 2\theta) + "
    r"\tfrac{u_{\max}^2}{d_{io}^2} (S - (\alpha^2 + \cos 2\theta))\bigr] / (1 + \alpha^2 + S + "
    r"2u_{\max}^2/d_{io}^2)^{5/2}$, zero at $\alpha = 0$, $\alpha \to \infty$ and where "
    "Eq. (34) holds.",
    paper="As printed (the display before Eq. (34)).",
    notebook=NB,
)
def _dalpha(profile: str) -> Finding:
    p = params(NB, profile)
    a = pf.alpha_derivative_audit(p["n_rational_points"], p["seed"])
    lo, hi = a.printed_ratio_spread
    not_constant = hi / lo > 1 + 1e-6
    nonzero_at_0 = a.slope_at_alpha0_min > 0 and a.slope_at_alpha0 < 1e-12
    if a.closed_form_equal and a.numerator_equals_eq36 and (not_constant or nonzero_at_0):
        status = "partly"
    elif a.closed_form_equal and a.numerator_equals_eq36:
        status = "reproduced"
    else:
        status = "refuted"
    return Finding(
        status,
        "The printed expression is not the derivative up to a "
        r"positive constant: $\partial C/\partial\alpha = 2 \alpha g / (S \sqrt{N} D^{3/2})$ with "
        r"$N = 1 + \alpha^2 - S$ and $D$ the printed base, and the ratio of the derivative to the "
        f"printed expression ranges over [{lo:.2f}, {hi:.1f}]. Because "
        r"$\sqrt{N} \sim \alpha \lvert\sin\theta\rvert$ near $0$, $\alpha = 0$ is not a "
        r"stationary point: the slope there is $\lvert\sin\theta\rvert/\sqrt{1 + q^2}$ (checked "
        f"to {format_small(a.slope_at_alpha0, 1e-12)}), a boundary minimum. The numerator, hence "
        "the stationarity condition Eq. (34), is right (SymPy: the difference simplifies to $0$).",
        asdict(a),
    )

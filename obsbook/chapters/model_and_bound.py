r"""The numbers and tables of the chapter on the model and the lower bound (Sections II-III).

Each ``glue_*`` function formats the results of one check of the chapter and glues them under
the names its prose uses. The checks themselves are the
audits of :mod:`obslib.studies.model_and_bound`, called in the chapter's visible cells.
"""

from __future__ import annotations

import numpy as np

import obslib as ob
from obslib.formatting import count, number, percent, setting, small, span

from ..glue import glue_texts
from ..tables import numbered_table

__all__ = ["SCENE_KINDS", "CONDITIONS", "glue_example", "glue_scene_check",
           "glue_theorem1", "glue_theorem2", "glue_theorem3", "glue_remark1", "glue_rank",
           "glue_squared_range", "show_lie_rows", "EXERCISE_ROWS", "EXERCISE_U_MAX",
           "EXERCISE_U_RERUN", "EXERCISE_SHRINK", "exercise_numbers", "glue_exercises"]

#: The kinds of random scene of the Theorem 1 audit, in words.
SCENE_KINDS = {"generic": "generic positions", "collinear": "all in line with the target",
               "near-parallel": "nearly in line with the target",
               "spread": "distances over seven orders of magnitude"}

#: The conditions of the Theorem 3 audit, in words.
CONDITIONS = {
    "stated": r"the theorem's: $C^{-1}(O(o))$ and $\sigma_{\min}(O(o))$ both up",
    "ratio only": r"only $C^{-1}(O(o))$ up",
    "sigma_min only": r"only $\sigma_{\min}(O(o))$ up",
    "neither": "neither up",
    "printed": r"the proof's (Eq. (27)): ratio up and $\lambda'_{\min} \ge \lambda_{\max}$",
    "remark 2": r"Remark 2's: $T_1 + T_2 \ge 0$",
}


def glue_example(sensors, target, O) -> None:
    """The running example: its observability matrix ``O`` (sensors' rows, then the control
    row) as a displayed formula, and the inverse condition number with the control, without it,
    and with the worst control of the same speed.

    Parameters
    ----------
    sensors : ndarray, shape (N, 2)
        The example's sensors.
    target : ndarray, shape (2,)
        The target.
    O : ndarray, shape (N + 1, 2)
        :func:`obslib.observability_matrix` of the scene with its control.
    """
    rows = r" \\ ".join(" & ".join(setting(float(v)) for v in row) for row in O)
    glue_texts(
        O_example="$$\n" + rf"O(o, u_o) = \begin{{bmatrix}} {rows} \end{{bmatrix}}" + "\n$$",
        c_example=number(ob.inverse_condition_number(sensors, target, O[-1])),
        c_example_known=number(ob.inverse_condition_number(sensors, target)),
        c_example_worst=number(ob.lower_bound(sensors, target, np.linalg.norm(O[-1]))),
    )


def glue_scene_check(sensors, target, exact, bound, u_star) -> None:
    """Theorem 1 on the running example: the range of the exact values over the disc, the
    bound, and the gap between them at the worst-case control ``u_star``.

    Parameters
    ----------
    sensors, target : ndarray
        The scene.
    exact : ndarray
        The exact :math:`C^{-1}` at the controls of the disc.
    bound : float
        Theorem 1's bound.
    u_star : ndarray, shape (2,)
        The worst-case control.
    """
    glue_texts(
        ex_bound=number(bound),
        ex_min=number(exact.min()),
        ex_max=number(exact.max()),
        ex_at_star=small(ob.inverse_condition_number(sensors, target, u_star) - bound),
    )


def glue_theorem1(audit, n_controls: int) -> None:
    """Theorem 1 on random scenes: the counts, the largest excess of the bound and the table of
    the smallest margin by kind of scene (``tab-01-thm1``).

    Parameters
    ----------
    audit : obslib.studies.model_and_bound.Theorem1Audit
        The audit's result.
    n_controls : int
        Random controls per scene.
    """
    rows = [{"kind": SCENE_KINDS.get(k, k), "slack": small(v)}
            for k, v in audit.min_slack_by_kind.items()]
    glue_texts(
        thm1_scenes=number(audit.n_scenes),
        thm1_controls=number(n_controls),
        thm1_violations=count(audit.n_violations, of=audit.n_evaluations),
        thm1_excess=small(audit.worst_excess),
        tab_thm1=numbered_table(
            rows, r"Theorem 1 in random scenes: the smallest margin of the exact "
            r"$C^{-1}(O(o,u_o))$ over the bound, by kind of scene.", "tab-01-thm1",
            columns={"sensors": ("kind", "s"),
                     "smallest margin, exact minus bound": ("slack", "s")}),
    )


def glue_theorem2(audit) -> None:
    """Theorem 2 on random one-sensor scenes: the bound, the eigenvalue ratio, and the range of
    the exact value with a known control.

    Parameters
    ----------
    audit : obslib.studies.model_and_bound.Theorem2Audit
        Theorem 2's audit (:func:`obslib.studies.model_and_bound.theorem2_audit`).
    """
    glue_texts(
        thm2_scenes=count(audit.n_scenes, of=audit.n_scenes),
        thm2_bound=small(audit.max_bound, 1e-7),
        thm2_ratio=small(audit.max_relative_lambda_min, 1e-14),
        thm2_exact=span(*audit.exact_range),
    )


def glue_theorem3(audit) -> None:
    """Theorem 3 on random before-and-after configurations: the table of the conditions met and
    how often the bound decreased (``tab-01-thm3``), a witness of one condition alone failing,
    the proof's condition (Eq. (27)) and Remark 2's.

    Parameters
    ----------
    audit : obslib.studies.model_and_bound.Theorem3Audit
        The audit's result.
    """
    rows = [{"condition": text, "met": number(audit.counts[key][0]),
             "down": count(audit.counts[key][1], of=audit.counts[key][0])}
            for key, text in CONDITIONS.items()]
    n_stated, n_stated_down = audit.counts["stated"]
    n_printed, _ = audit.counts["printed"]
    n_remark2, n_remark2_down = audit.counts["remark 2"]
    w = audit.witnesses.get("ratio only")  # None when no trial shows one
    glue_texts(
        tab_thm3=numbered_table(
            rows, f"Random before-and-after configurations ({number(audit.n_trials)} trials) by "
            "the condition they meet.", "tab-01-thm3",
            columns={"condition met": ("condition", "s"), "trials": ("met", "s"),
                     "the bound decreased": ("down", "s")}),
        thm3_trials=number(audit.n_trials),
        thm3_stated=number(n_stated),
        thm3_stated_down=count(n_stated_down, of=n_stated),
        thm3_printed=count(n_printed, of=n_stated),
        thm3_witness=(f"in the first configuration where only the ratio rose, the bound fell "
                      f"from {number(w['bound_before'])} to {number(w['bound_after'])}." if w
                      else "among these trials, none raised the ratio alone and lowered the "
                      "bound."),
        thm3_implied="every" if audit.printed_implies_stated else "not every",
        remark2_down=count(n_remark2_down, of=n_remark2),
        remark2_up=count(audit.remark2_necessary_violations),
    )


def glue_remark1(audit) -> None:
    """Remark 1 and the tightness for a moving target on random scenes.

    Parameters
    ----------
    audit : obslib.studies.model_and_bound.Remark1Audit
        The audit of the bound at a stationary and at a moving target, scene by scene.
    """
    glue_texts(
        r1_scenes=count(audit.n_scenes, of=audit.n_scenes),
        r1_stationary=small(audit.max_stationary_error),
        r1_moving=small(audit.max_moving_error),
        r1_gap=small(audit.min_over_disc_gap, 1e-9),
    )


def show_lie_rows(rows) -> None:
    r"""Display the gradients :math:`\nabla L^k_f h_i` (:func:`obslib.symbolic.lie.lie_rows`),
    one aligned line each.

    Parameters
    ----------
    rows : tuple of tuple of sympy.Expr
        The rows, ``(d/do_x, d/do_y)`` each.
    """
    import sympy as sp
    from IPython.display import Math, display

    lines = [rf"\nabla L^{{{k}}}_f h_i &= \big({sp.latex(a)},\ {sp.latex(b)}\big)"
             for k, (a, b) in enumerate(rows)]
    display(Math(r"\begin{aligned}" + r" \\ ".join(lines) + r"\end{aligned}"))


def glue_rank(audit) -> None:
    """What full column rank buys, on random scenes
    (:func:`obslib.studies.model_and_bound.rank_observability_audit`): the scenes of full rank
    and of rank one, the smallest stretch of the output map over sigma_min, the twins' output
    gap.

    Parameters
    ----------
    audit : obslib.studies.model_and_bound.RankAudit
        The audit's result.
    """
    glue_texts(
        rk_full=number(audit.n_full),
        rk_deficient=number(audit.n_deficient),
        rk_ratio=number(audit.min_ratio, 6),
        rk_twin=small(audit.max_twin_gap),
        rk_icn=small(audit.max_deficient_icn),
        rk_span=span(*audit.icn_range),
    )


def glue_squared_range(audit) -> None:
    """Half the squared range against the range
    (:func:`obslib.studies.model_and_bound.squared_range_audit`): the scenes, the share whose best
    pair changes, the best pair's value with the range over the one with the square.

    Parameters
    ----------
    audit : obslib.studies.model_and_bound.SquaredRangeAudit
        The audit's result.
    """
    glue_texts(
        sq_scenes=number(audit.n_scenes),
        sq_sensors=number(audit.n_sensors),
        sq_same_rank=count(audit.same_rank, of=audit.n_scenes),
        sq_differs=percent(audit.pair_differs),
        sq_ratio=span(*audit.icn_ratio),
    )


#: Exercise 1: the rows :math:`o - p_i` of two sensors (m) and the speed bound (m/s).
EXERCISE_ROWS = ((3.0, 0.0), (0.0, 4.0))
EXERCISE_U_MAX = 1.0
#: Exercise 2: the speed bound (m/s) at which the running example is rerun.
EXERCISE_U_RERUN = 3.0
#: Exercise 3: the rows before and after a change that raises C^-1(O(o)) and lowers sigma_min.
EXERCISE_SHRINK = {"before": ((2.0, 0.0), (0.0, 1.0)), "after": ((0.4, 0.0), (0.0, 0.4))}


def _pair_numbers(rows, u_max: float) -> dict:
    """sigma_min, sigma_max, C^-1(O(o)) and Theorem 1's bound of the rows ``o - p_i``."""
    rows = np.asarray(rows, dtype=float)
    s = np.linalg.svd(rows, compute_uv=False)
    target = np.zeros(2)
    bound = float(ob.lower_bound(target - rows, target, u_max))  # sensors at o - row
    return {"sigma_min": float(s[-1]), "sigma_max": float(s[0]),
            "icn": float(s[-1] / s[0]), "bound": bound}


def exercise_numbers(sensors, target, u_max: float, u_rerun: float = EXERCISE_U_RERUN) -> dict:
    """The numbers of the chapter's exercises.

    Parameters
    ----------
    sensors, target : ndarray
        The running example's scene.
    u_max : float
        The chapter's speed bound.
    u_rerun : float
        The speed bound the rerun exercise asks about.

    Returns
    -------
    dict
        ``"by_hand"``: :data:`EXERCISE_ROWS` at :data:`EXERCISE_U_MAX`: ``sigma_min``,
        ``sigma_max``, ``bound``, the worst control ``u_star`` and the exact value there;
        ``"rerun"``: the example's bound at ``u_max`` and at ``u_rerun`` and the exact value at
        the worst control of ``u_rerun``; ``"counter"``: :data:`EXERCISE_SHRINK` before and
        after (``icn`` and ``bound`` at :data:`EXERCISE_U_MAX`).
    """
    rows = np.asarray(EXERCISE_ROWS)
    hand = _pair_numbers(rows, EXERCISE_U_MAX)
    u_star = ob.worst_case_control(-rows, np.zeros(2), EXERCISE_U_MAX)
    hand["u_star"] = np.abs(u_star)  # the sign of the eigenvector is arbitrary
    hand["exact_at_star"] = float(ob.inverse_condition_number(-rows, np.zeros(2), u_star))
    u_worst = ob.worst_case_control(sensors, target, u_rerun)
    rerun = {"sigma_max": float(np.linalg.svd(np.asarray(target) - sensors, compute_uv=False)[0]),
             "bound": float(ob.lower_bound(sensors, target, u_max)),
             "bound_rerun": float(ob.lower_bound(sensors, target, u_rerun)),
             "exact_rerun": float(ob.inverse_condition_number(sensors, target, u_worst))}
    counter = {k: _pair_numbers(v, EXERCISE_U_MAX) for k, v in EXERCISE_SHRINK.items()}
    return {"by_hand": hand, "rerun": rerun, "counter": counter}


def _vec(v) -> str:
    return "$(" + ", ".join(setting(float(x)) for x in v) + ")$"


def glue_exercises(sensors, target, u_max: float, u_rerun: float = EXERCISE_U_RERUN) -> dict:
    """Glue the numbers of the chapter's exercises (:func:`exercise_numbers`) and return them.

    ``sensors``, ``target``, ``u_max`` and ``u_rerun`` are those of :func:`exercise_numbers`.
    """
    e = exercise_numbers(sensors, target, u_max, u_rerun)
    h, r, c = e["by_hand"], e["rerun"], e["counter"]
    glue_texts(
        x1_rows=" and ".join(_vec(v) for v in EXERCISE_ROWS),
        x1_u=setting(EXERCISE_U_MAX),
        x1_smin=number(h["sigma_min"]),
        x1_smax=number(h["sigma_max"]),
        x1_bound=number(h["bound"]),
        x1_ustar=_vec(h["u_star"]),
        x1_exact=number(h["exact_at_star"]),
        x2_u=setting(u_max),
        x2_u_rerun=setting(u_rerun),
        x2_smax=number(r["sigma_max"]),
        x2_bound=number(r["bound"]),
        x2_bound_rerun=number(r["bound_rerun"]),
        x2_exact_rerun=number(r["exact_rerun"]),
        x3_before=" and ".join(_vec(v) for v in EXERCISE_SHRINK["before"]),
        x3_after=" and ".join(_vec(v) for v in EXERCISE_SHRINK["after"]),
        x3_icn_before=number(c["before"]["icn"]),
        x3_icn_after=number(c["after"]["icn"]),
        x3_smin_before=number(c["before"]["sigma_min"]),
        x3_smin_after=number(c["after"]["sigma_min"]),
        x3_bound_before=number(c["before"]["bound"]),
        x3_bound_after=number(c["after"]["bound"]),
    )
    return e

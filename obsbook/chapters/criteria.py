r"""The intuition, numbers and tables of the chapter that asks whether the bound is the right
criterion, against the classical criteria of optimal design.

:func:`intuition` computes the two pairs the intuition compares; each ``glue_*`` function
formats one result of :mod:`obslib.studies.criteria` and glues it under the names the chapter's
prose uses (names built by :func:`key` from the settings and strategies they describe).
"""

from __future__ import annotations

import json

import numpy as np
import pandas as pd

from obslib.formatting import count, number, percent, setting, small, span
from obslib.studies import criteria

from ..glue import glue_texts
from ..tables import numbered_table

__all__ = ["NAMES", "p_text", "key", "intuition", "glue_intuition", "glue_tracking",
           "glue_adversary", "glue_cost", "glue_assignment"]

#: How the tables name the strategies.
NAMES = {"best-pair": "bound (best pair)", "best-partner": "best partner",
         "fixed-pair": "fixed pair", "d-optimal": "D-optimal", "a-optimal": "A-optimal",
         "e-optimal": "E-optimal", "exact-icn": "exact $C^{-1}$ (oracle)", "random": "random"}


def p_text(p: float) -> str:
    """A p-value as the book prints it.

    Examples
    --------
    >>> p_text(0.535), p_text(1e-20)
    ('$p$ = 0.535', '$p < 10^{-12}$')
    """
    text = small(p, 1e-12)
    return f"$p {text[1:]}" if text.startswith("$<") else f"$p$ = {text}"


def key(*parts) -> str:
    """A glue name from ``parts``, strategy and setting names.

    Examples
    --------
    >>> key("err", "circle", "mahalanobis", "d-optimal")
    'err_circle_mahalanobis_d_optimal'
    """
    return "_".join(str(p) for p in parts).replace("-", "_")


def intuition() -> dict:
    r"""The intuition's two candidate pairs at distance 2 from the estimate (the origin): A at a
    right angle, B below the target and 40 degrees apart; a prior that knows :math:`x` well and
    :math:`y` poorly, the covariance after the update with each pair, and each criterion's score
    of each pair.

    Returns
    -------
    dict
        ``angles`` and ``pairs`` (the sensors' directions in degrees, and positions), ``prior``,
        ``after`` and ``scores`` (pair -> criterion -> score).
    """
    xhat = np.zeros((1, 2))
    angles = {"A": (180.0, 270.0), "B": (250.0, 290.0)}  # directions of the sensors (degrees)
    pairs = {k: 2.0 * np.c_[np.cos(np.radians(a)), np.sin(np.radians(a))]
             for k, a in angles.items()}
    prior = np.diag([0.1, 2.0])  # the covariance before the update
    noise = 2.0 * np.eye(2)  # R: the noise of the two half-squared ranges
    after, scores = {}, {}
    for k, P in pairs.items():
        H = xhat - P  # rows (xhat - p_i)^T
        J = np.linalg.inv(prior) + H.T @ np.linalg.inv(noise) @ H
        after[k] = np.linalg.inv(J)
        scores[k] = {name: float(criteria.criterion_scores(name, P, xhat, prior[None],
                                                           np.zeros((2, 2)), noise, u_max=1.0,
                                                           metric="euclidean")[0, 0])
                     for name in ("bound", "d-optimal", "a-optimal", "e-optimal")}
    return {"angles": angles, "pairs": pairs, "prior": prior, "after": after, "scores": scores}


def glue_intuition(scene: dict) -> None:
    """The two pairs of the intuition by each criterion (``tab-criteria-intuition``).

    Parameters
    ----------
    scene : dict
        :func:`intuition`.
    """
    angles = scene["angles"]
    rows = [{
        "pair": f"{k}, {number(round(angles[k][1] - angles[k][0]))}° apart",
        "bound ($u_{\\max} = 1$)": number(s["bound"]),
        "$\\det J$ (D)": number(s["d-optimal"]),
        "$\\operatorname{tr} J^{-1}$ (A)": number(-s["a-optimal"]),
        "$\\lambda_{\\min}(J)$ (E)": number(s["e-optimal"]),
    } for k, s in scene["scores"].items()]
    glue_texts(tab_criteria_intuition=numbered_table(
        pd.DataFrame(rows), "The two pairs of the figure by each criterion: the bound, "
        "$\\det J$ and $\\lambda_{\\min}(J)$ are better when larger, $\\operatorname{tr} J^{-1}$ "
        "(squared length units) when smaller.", "tab-criteria-intuition"))


def _won(r: dict) -> str:
    """Runs the bound wins / runs the other wins, with p where it is not below 1e-12."""
    p = "" if r["vs_p_wilcoxon"] < 1e-12 else f" ({p_text(r['vs_p_wilcoxon'])})"
    return f"{count(r['vs_reference_better'])} / {count(r['vs_other_better'])}{p}"


def glue_tracking(study: dict, n_seeds: int, loss_threshold: float) -> None:
    """The criteria in Section V's experiments: the mean error of each strategy by setting
    (``tab-criteria-error``), the paired comparison with the bound (``tab-criteria-paired``),
    the pairs each chooses on the circle (``tab-criteria-pairs``), and each number of them.

    Parameters
    ----------
    study : dict
        :func:`obslib.studies.criteria.tracking_study`: ``(setting, metric) -> runs``.
    n_seeds : int
        The runs per strategy.
    loss_threshold : float
        The run-mean error above which a run is lost.
    """
    rows = {k: criteria.summary_rows(mc, loss_threshold=loss_threshold)
            for k, mc in study.items()}
    by = {k: {r["strategy"]: r for r in rs} for k, rs in rows.items()}
    settings = list(rows)
    strategies = list(by[settings[0]])
    head = {k: f"{k[0]}, {k[1].capitalize()}" for k in settings}
    errors = [{"strategy": NAMES[s], **{head[k]: f"{number(by[k][s]['mean_error'])} "
                                                 f"({number(by[k][s]['sd_error'])})"
                                        for k in settings}} for s in strategies]
    paired = [{"strategy": NAMES[s], **{head[k]: _won(by[k][s]) for k in settings}}
              for s in strategies if s != criteria.REFERENCE]
    circle = [k for k in settings if k[0] == "circle"]
    chosen = [{"strategy": NAMES[s],
               **{f"pair switches ({k[1][0].upper()})": number(by[k][s]["switches"])
                  for k in circle},
               **{f"mean bound ({k[1][0].upper()})": number(by[k][s]["mean_bound"])
                  for k in circle},
               **{f"mean $\\operatorname{{tr}}\\Sigma$ ({k[1][0].upper()})":
                  number(by[k][s]["mean_trace"]) for k in circle}} for s in strategies]
    each = {}
    for k, d in by.items():
        for s, r in d.items():
            each[key("err", *k, s)] = number(r["mean_error"])
            each[key("lost", *k, s)] = count(r["lost"])
            each[key("switches", *k, s)] = number(r["switches"])
            each[key("bound", *k, s)] = number(r["mean_bound"])
            if "vs_n" in r:
                each[key("win", *k, s)] = count(r["vs_other_better"], of=r["vs_n"])
                each[key("pw", *k, s)] = p_text(r["vs_p_wilcoxon"])
    best = {k: min(("d-optimal", "a-optimal", "e-optimal"),
                   key=lambda c: by[k][c]["mean_error"]) for k in settings}
    for k in settings:
        each[key("lower", *k)] = percent(1 - by[k][best[k]]["mean_error"]
                                         / by[k][criteria.REFERENCE]["mean_error"])
        each[key("best", *k)] = NAMES[best[k]]
    glue_texts(
        n_runs=number(n_seeds),
        tab_criteria_error=numbered_table(
            pd.DataFrame(errors), f"Mean tracking error of a run (length units), over "
            f"{number(n_seeds)} runs, with its standard deviation over runs in brackets, by "
            "strategy and setting (trajectory, and the distances in the bound).",
            "tab-criteria-error"),
        tab_criteria_paired=numbered_table(
            pd.DataFrame(paired), f"Runs, of {number(n_seeds)}, in which the bound's choice "
            "tracks better / in which the other strategy does (the rest are ties). The "
            "two-sided Wilcoxon signed-rank test of the paired differences gives "
            "$p < 10^{-12}$ wherever no $p$ is shown.", "tab-criteria-paired"),
        tab_criteria_pairs=numbered_table(
            pd.DataFrame(chosen), "The pairs each strategy chooses on the circle: pair changes "
            "per run, the mean bound of the chosen pairs, and the mean trace of the covariance "
            "(squared length units), with Mahalanobis (M) or Euclidean (E) distances in the "
            "bound.", "tab-criteria-pairs"),
        **each,
    )


def glue_adversary(study: dict, metrics, n_seeds: int) -> None:
    """The adversary facing each criterion, one table per metric of the bound
    (``tab-criteria-adversary-<metric>``), and how far it gets.

    Parameters
    ----------
    study : dict
        :func:`obslib.studies.criteria.tracking_study`.
    metrics : list of str
        The metrics of the bound's distances.
    n_seeds : int
        The runs per strategy.
    """
    adv = {m: criteria.adversary_rows(study[("adversary", m)]) for m in metrics}
    texts = {}
    for m, rs in adv.items():
        texts[f"tab_adv_{m}"] = numbered_table(pd.DataFrame([{
            "strategy": NAMES[r["strategy"]],
            f"runs entrapped (of {number(n_seeds)})": count(round(r["entrapped"] * n_seeds)),
            "farthest from the start (length units)": number(r["max_from_start"]),
            "mean exact $C^{-1}$": number(r["icn_mean"]),
            "smallest exact $C^{-1}$": small(r["icn_min"], 1e-12),
            "mean bound": number(r["bound_mean"]),
            "pair switches": number(r["switches"]),
        } for r in rs]), f"The adversary's escape, the bound with {m.capitalize()} distances.",
            f"tab-criteria-adversary-{m}")
        for r in rs:
            texts[key("trap", m, r["strategy"])] = count(round(r["entrapped"] * n_seeds),
                                                         of=n_seeds)
            texts[key("reach", m, r["strategy"])] = number(r["max_from_start"])
    glue_texts(**texts, adv_reach=number(adv[metrics[0]][0]["reach"]))


def glue_cost(times_file) -> None:
    """The time to score the pairs by each criterion (``tab-criteria-cost``), as measured and
    stored in ``times_file`` (``book/data/criteria_times.json``).

    Parameters
    ----------
    times_file : str or path
        The measured times: ``per_pair_us`` and ``per_decision_us`` by criterion, and the
        ``machine``.
    """
    with open(times_file) as f:
        measured = json.load(f)
    per_pair, per_decision = measured["per_pair_us"], measured["per_decision_us"]
    words = {"bound": "bound (Theorem 4)", "d-optimal": "D-optimal", "a-optimal": "A-optimal",
             "e-optimal": "E-optimal", "exact-icn": "exact $C^{-1}$ (oracle)"}
    glue_texts(
        tab_criteria_cost=numbered_table(pd.DataFrame([{
            "criterion": words[name],
            "µs per pair, a thousand estimates at once": number(per_pair[name]),
            "µs per decision, one estimate": number(per_decision[name]),
        } for name in per_pair]), "Time to score the pairs, measured once on one machine "
            f"({measured['machine']}).", "tab-criteria-cost"),
        cost_bound=number(per_pair["bound"]),
        cost_d=number(per_pair["d-optimal"]),
        cost_e=number(per_pair["e-optimal"]),
        cost_icn=number(per_pair["exact-icn"]),
        cost_one=span(min(per_decision.values()), max(per_decision.values())),
    )


def glue_assignment(arun: dict, params: dict) -> None:
    """Assignments judged by tracking: each rule's errors, lost targets and pair changes
    (``tab-assign``), its own objective and the paired comparison with the bound's assignment
    (``tab-assign-tests``), the settings, and each number of the tables.

    Parameters
    ----------
    arun : dict
        :func:`obslib.studies.criteria.assignment_study`: ``{L: {rule: runs}}``.
    params : dict
        The chapter's parameters (``assign_loss``, ``assign_seeds``, ``assign_steps``,
        ``assign_side``, ``assign_u_max``, ``assign_noise_std``, ``assign_targets``).
    """
    arows = criteria.assignment_rows(arun, loss_threshold=params["assign_loss"])
    rules = {"bound": "bound", "d-optimal": "D-optimal", "random": "random"}
    tracking = pd.DataFrame([{
        "$L$": number(r["L"]),
        "rule": rules[r["rule"]],
        "median error": number(r["median_error"]),
        "mean error (sd)": f"{number(r['mean_error'])} ({number(r['sd_error'])})",
        "targets lost": count(r["lost"]),
        "of them at the mirror image": count(r["lost_mirrored"]),
        "steps with a pair change": percent(r["switch_rate"]),
    } for r in arows])
    tests = pd.DataFrame([{
        "$L$": number(r["L"]),
        "rule": rules[r["rule"]],
        "bound per step": number(r["bound_sum"]),
        "gain per step": number(r["gain_sum"]),
        "median difference": number(r["vs_median_diff"]) if "vs_n" in r else "–",
        "runs won, bound / other": (f"{count(r['vs_reference_better'])} / "
                                    f"{count(r['vs_other_better'])}" if "vs_n" in r else "–"),
        "$p$, sign": small(r["vs_p_sign"], 1e-12) if "vs_n" in r else "–",
        "$p$, Wilcoxon": small(r["vs_p_wilcoxon"], 1e-12) if "vs_n" in r else "–",
    } for r in arows])
    each = {}
    for r in arows:
        k = key(r["L"], r["rule"])
        for col in ("median_error", "mean_error", "switch_rate", "bound_sum", "gain_sum"):
            each[f"a_{col}_{k}"] = number(r[col])
        for col in ("lost", "lost_mirrored"):
            each[f"a_{col}_{k}"] = count(r[col])
        each[f"a_switch_pct_{k}"] = percent(r["switch_rate"])
        if "vs_n" in r:
            each[f"a_pw_{k}"] = p_text(r["vs_p_wilcoxon"])
            each[f"a_psign_{k}"] = p_text(r["vs_p_sign"])
            each[f"a_win_{k}"] = count(r["vs_other_better"], of=r["vs_n"])
            each[f"a_bwin_{k}"] = count(r["vs_reference_better"], of=r["vs_n"])
    glue_texts(
        tab_assign=numbered_table(
            tracking, f"Tracking by each assignment rule, {number(params['assign_seeds'])} runs "
            f"of {number(params['assign_steps'])} steps: the error of a run (length units, "
            "summed over the targets), the targets lost over all runs and how many of them end "
            "nearer the target's mirror image across their pair's baseline, and how often a "
            "target's pair changes.", "tab-assign"),
        tab_assign_tests=numbered_table(
            tests, "Each rule's own objective, the chosen pairs' bound and information gain "
            "summed over the targets, per step; and the paired comparison of the runs' errors "
            "with the bound's assignment (Algorithm 1): the median of the differences (length "
            "units), the runs each wins, and the two-sided sign and Wilcoxon tests.",
            "tab-assign-tests"),
        side_g=setting(params["assign_side"]),
        umax_g=setting(params["assign_u_max"]),
        sigma_g=setting(params["assign_noise_std"]),
        aloss_g=setting(params["assign_loss"]),
        aseeds_g=number(params["assign_seeds"]),
        L_max=number(max(params["assign_targets"])),
        **each,
    )

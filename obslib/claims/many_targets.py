"""The authors' later multi-target experiment (notebook 12): its statements, judged with the
saved data and our runs; what their team script does; and the book's question of which
assignment to use on a larger network.

The experiment is not in the paper: the authors' code repository holds it, with one saved run of
each of its two scripts (:mod:`obslib.later_experiment`). Its statements are entries of kind
``"later"`` (verdicts on that material, never on the paper), the findings about its code are of
kind ``"code"`` and the comparison on a larger network is a question of this book (``"beyond"``).
Every number comes from :mod:`obslib.studies.many_targets`, cached there and shared with the
chapter. Each check fixes its verdict rule in its docstring before the evidence.
"""

from __future__ import annotations

import numpy as np

from .. import tracking
from ..formatting import count, listing, number, percent, setting, small
from ..later_experiment import RUN_NAMES, saved_run
from ..studies.criteria import significance
from ..studies.many_targets import (
    NOTEBOOK,
    REFERENCE,
    code_treatment,
    comparison_rows,
    later_runs,
    network_comparison,
    network_runs,
    run_statistics,
    saved_comparison,
)
from ..studies.published import FIGURE_TOLERANCE
from ._ledger import Finding, Table, claim
from .criteria import ALPHA
from .two_sensors_tracking import TYPICAL_SHARE

#: The saved data hold six significant digits: a trace of ours matches a saved one within this
#: relative distance.
SAVED_RTOL = 5e-6

#: "A fifth to a third of the steps", the share of the steps a target goes without a sensor.
FIFTH_TO_THIRD = (1 / 5, 1 / 3)

#: The assignments in words, as the tables of the chapter and the report name them.
ASSIGNMENT_WORDS = {
    "unique-pairs": "unique pairs by the bound (Algorithm 1)",
    "d-optimal-pairs": "unique pairs by information gain (D-optimal)",
    "optimal-pairs": "unique pairs, exact optimum of Problem 1",
    "random": "random pairs",
    "logdet-teams": r"$\log\det$ teams, the code's rounding",
    "logdet-teams-as-run": r"$\log\det$ teams as the script runs them",
    "logdet-teams-exact": r"$\log\det$ teams, exact arithmetic",
    "logdet-teams-prior": r"$\log\det$ teams with a prior $\varepsilon I$",
    "d-optimal-teams": "D-optimal teams",
    "a-optimal-teams": "A-optimal teams",
    "e-optimal-teams": "E-optimal teams",
}

#: The statistics of a target that the saved runs log, in words.
STATISTIC_WORDS = {"mean_error": "mean error", "mean_trace": r"mean $\operatorname{tr}\Sigma$",
                   "unobserved": "steps without a sensor"}


def target_math(l: int) -> str:
    """Target ``l`` (0-based) as the book writes it: ``$t_1$``."""
    return f"$t_{{{int(l) + 1}}}$"


def team_math(team) -> str:
    """A team of sensors (0-based indices) as the book writes it: ``$s_1, s_8$``, or "none"."""
    team = list(team)
    return "$" + ", ".join(f"s_{{{int(i) + 1}}}" for i in team) + "$" if team else "none"


def _p(value: float) -> str:
    """A p-value as the book prints it: ``$p$ = 0.13`` or ``$p < 10^{-12}$``."""
    text = small(value, 1e-12)
    return f"$p {text[1:]}" if text.startswith("$<") else f"$p$ = {text}"


def _verdict(row: dict, trace: bool = False) -> str:
    """``"better"``, ``"worse"`` or ``"same"``: the paired Wilcoxon test of a comparison row's
    error (or trace) against its reference at :data:`ALPHA`."""
    pre = "vs_trace_" if trace else "vs_"
    return significance({"vs_p_wilcoxon": row[pre + "p_wilcoxon"],
                         "vs_median_diff": row[pre + "median_diff"]}, ALPHA)


def _runs(p: dict) -> dict:
    """Every assignment over the notebook's noise seeds (cached in the study)."""
    return later_runs(p["n_seeds"], p["seed"])


def _span_of(x, fmt=number) -> str:
    """The 5th to 95th percentile of ``x`` in words (each formatted by ``fmt``)."""
    lo, hi = np.percentile(x, [5, 95])
    return f"{fmt(float(lo))} to {fmt(float(hi))}"


# --------------------------------------------------------------------------------------------
# The saved run of unique pairs
# --------------------------------------------------------------------------------------------


def saved_typicality(batch, name: str, rtol: float = FIGURE_TOLERANCE) -> dict:
    """How the saved run ``name`` sits among our runs ``batch`` of its assignment: the share of
    our runs whose six per-target means (error and trace, steps 2 to 100) all come within
    ``rtol`` of the saved run's (``share_like``), and per statistic and target the saved value,
    our runs' values, and the shares of them below and above it."""
    saved = saved_run(name).summary()
    ours = {"mean_error": batch.error[:, 1:].mean(axis=1),
            "mean_trace": batch.trace_cov[:, 1:].mean(axis=1)}
    like = np.all([np.abs(ours[k] / saved[k] - 1) <= rtol for k in ours], axis=(0, 2))
    return {"share_like": float(like.mean()), "saved": {k: saved[k].tolist() for k in ours},
            "ours": ours,
            "below": {k: (ours[k] < saved[k]).mean(axis=0).tolist() for k in ours},
            "above": {k: (ours[k] > saved[k]).mean(axis=0).tolist() for k in ours}}


@claim(
    id="later-unique-pairs",
    kind="later",
    where="The authors' later experiment, unique-pair script",
    title="Unique pairs re-assigned at every step keep all three targets tracked.",
    statement="With the sensors re-assigned at every step by the unique-pair greedy "
    "(Algorithm 1 on Theorem 4's bound at the estimates), each of the three targets has a pair "
    "at every step and stays tracked, as the saved run shows.",
    paper="The authors' code repository, not the paper, saves one run of its unique-pair "
    "script: each target's error and trace of the covariance at every step, and snapshots of "
    "the assignment.",
    notebook=NOTEBOOK,
)
def _unique_pairs(p: dict) -> Finding:
    """The saved run against ours over ``n_seeds`` noise seeds. The saved run is *one the
    experiment gives* when its trace after the first update, which no noise changes, is ours
    within :data:`SAVED_RTOL`, and at least :data:`TYPICAL_SHARE` of our runs come within
    :data:`FIGURE_TOLERANCE` of all six of its per-target means (error and trace, steps 2 to
    100), the rule chapter 5 applies to the published runs. The statement *holds in our runs*
    when none of them leaves a target without a pair at any step or loses one (a mean error
    above :data:`obslib.studies.many_targets.LOSS_THRESHOLD`).

    reproduced: both; partly: one of the two; refuted: neither."""
    name = "unique-pairs"
    b = _runs(p)[name]
    sc = saved_comparison(p["n_seeds"], p["seed"])[name]
    typ = saved_typicality(b, name)
    stats = run_statistics(b)
    first = sc["step2_max_rel_diff"] <= SAVED_RTOL and sc["step2_same_every_seed"]
    one_of_ours = first and typ["share_like"] >= TYPICAL_SHARE
    unobserved, lost = int(stats["unobserved"].sum()), int(stats["lost"].sum())
    holds = unobserved == 0 and lost == 0
    status = ("reproduced" if one_of_ours and holds else
              "partly" if one_of_ours or holds else "refuted")
    n = number(p["n_seeds"])
    like = (f"{percent(typ['share_like'])} of the runs come within "
            f"{percent(FIGURE_TOLERANCE)} of all six of the saved run's per-target mean errors "
            "and traces")
    if holds:
        summary = (f"Over {n} noise draws, re-assigning unique pairs at every step keeps every "
                   "target tracked as the saved run does: no target goes a step without a pair "
                   f"or is lost, and {like}.")
    else:
        summary = (f"Over {n} noise draws, re-assigning unique pairs at every step does not "
                   f"keep every target tracked: {count(unobserved)} target-steps go without a "
                   f"pair and {count(lost)} tracks are lost, while {like}.")
    # where the saved run lies outside every one of our runs
    outside = [(k, l) for k in ("mean_error", "mean_trace") for l in range(3)
               if typ["below"][k][l] in (0.0, 1.0)]
    detail = (f"Its trace after the first update, which no noise changes, is ours to "
              f"{small(sc['step2_max_rel_diff'], 1e-12)} (relative)")
    if outside:
        k, l = outside[0]
        side = "lower" if typ["below"][k][l] == 0.0 else "higher"
        detail += (f"; its {STATISTIC_WORDS[k]} of {target_math(l)}, "
                   f"{number(typ['saved'][k][l])}, is {side} than in every one of our runs, at "
                   f"the {'good' if side == 'lower' else 'bad'} end of what the noise gives")
    ours = summary + " " + detail + "."
    rows = []
    for l in range(3):
        rows.append((target_math(l),
                     number(typ["saved"]["mean_error"][l]),
                     f"{number(float(typ['ours']['mean_error'][:, l].mean()))} "
                     f"({_span_of(typ['ours']['mean_error'][:, l])})",
                     number(typ["saved"]["mean_trace"][l]),
                     f"{number(float(typ['ours']['mean_trace'][:, l].mean()))} "
                     f"({_span_of(typ['ours']['mean_trace'][:, l])})",
                     f"{count(int(saved_run(name).unobserved()[:, l].sum()))} / "
                     f"{count(int(stats['unobserved'][:, l].sum()))}"))
    ev = {"step2_saved": sc["step2_saved"], "step2_ours": sc["step2_ours"],
          "step2_max_rel_diff": sc["step2_max_rel_diff"], "share_like": typ["share_like"],
          "typical_share": TYPICAL_SHARE, "tolerance": FIGURE_TOLERANCE,
          "saved": typ["saved"], "below": typ["below"], "above": typ["above"],
          "ours_mean": {k: v.mean(axis=0).tolist() for k, v in typ["ours"].items()},
          "unobserved": unobserved, "lost": lost, "n_runs": int(b.n_runs)}
    return Finding(status, summary=summary, ours=ours, evidence=ev, table=Table(
        f"The saved run of unique pairs against our {n} runs with other noise: each target's "
        "means over steps 2 to 100 (ours: the mean over the runs, and the 5th to 95th "
        "percentile), and the steps without a pair (saved / all our runs).",
        ("target", "mean error, saved", "mean error, ours",
         r"mean $\operatorname{tr}\Sigma$, saved", r"mean $\operatorname{tr}\Sigma$, ours",
         "steps without a pair"), rows))


# --------------------------------------------------------------------------------------------
# The team greedy: steps without a sensor, and teams against pairs
# --------------------------------------------------------------------------------------------

AS_RUN = "logdet-teams-as-run"


@claim(
    id="later-teams-unobserved",
    kind="later",
    where="The authors' later experiment, team script",
    title="The team greedy leaves each target without a sensor at a fifth to a third of the "
    "steps.",
    statement="With the sensors re-assigned at every step by the team greedy of Fig. 9, as the "
    "authors' team script runs it, each of the three targets goes without a sensor at a fifth "
    "to a third of the steps.",
    paper="The saved run of the authors' team script, not in the paper: a target's trace "
    r"grows by exactly $\operatorname{tr} Q$ over a step at which it has no sensor.",
    notebook=NOTEBOOK,
)
def _teams_unobserved(p: dict) -> Finding:
    """Our runs of the team greedy as the script runs it (``"logdet-teams-as-run"``) over
    ``n_seeds`` noise seeds; steps 1 to 99, as the saved traces show them. Each target's mean
    share of the steps without a sensor is read against "a fifth to a third"
    (:data:`FIFTH_TO_THIRD`) with the tolerance of chapter 5's published numbers,
    :data:`FIGURE_TOLERANCE`: within ``[1/5 / (1 + tol), 1/3 (1 + tol)]``.

    reproduced: every target's share is within; partly: at least one target's is, not every
    target's; refuted: no target's is."""
    sc = saved_comparison(p["n_seeds"], p["seed"])[AS_RUN]
    b = _runs(p)[AS_RUN]
    steps = b.steps - 1
    ours = b.unobserved[:, :-1].sum(axis=1)  # (runs, targets), steps 1..99
    saved = saved_run(AS_RUN).unobserved().sum(axis=0)
    share = ours.mean(axis=0) / steps
    lo, hi = FIFTH_TO_THIRD[0] / (1 + FIGURE_TOLERANCE), FIFTH_TO_THIRD[1] * (1 + FIGURE_TOLERANCE)
    within = (share >= lo) & (share <= hi)
    status = "reproduced" if within.all() else "partly" if within.any() else "refuted"
    n = number(p["n_seeds"])
    out = [l for l in range(3) if not within[l]]
    if status == "reproduced":
        summary = (f"Over {n} runs the team greedy as its script runs it leaves each target "
                   "without a sensor at a fifth to a third of the steps, between "
                   f"{percent(share.min())} and {percent(share.max())} on average.")
    else:
        worst = max(out, key=lambda l: abs(share[l] - 0.25))
        summary = (f"Over {n} runs the team greedy as its script runs it leaves targets without "
                   "a sensor at many steps, but not each at a fifth to a third of them: "
                   f"{target_math(worst)} goes without one at {percent(share[worst])} of the "
                   "steps on average.")
    total = int(saved.sum())
    at_least = float((ours.sum(axis=1) >= total).mean())
    ours_text = (summary + f" The saved run, with {count(total)} such steps over its three "
                 f"targets, lies at the unlucky end: {percent(at_least)} of our runs have as "
                 "many.")
    rows = [(target_math(l), count(int(saved[l])), number(float(ours[:, l].mean())),
             _span_of(ours[:, l], setting), percent(share[l]),
             percent(float((ours[:, l] >= saved[l]).mean())))
            for l in range(3)]
    ev = {"share": share.tolist(), "band": [lo, hi], "within": within.tolist(),
          "saved": saved.tolist(), "ours_mean": ours.mean(axis=0).tolist(),
          "saved_total": total, "share_runs_at_least_saved_total": at_least,
          "steps": steps, "rows": sc["rows"]}
    return Finding(status, summary=summary, ours=ours_text, evidence=ev, table=Table(
        f"Steps 1 to {steps} at which each target has no sensor, in the saved run of the team "
        f"script and in our {n} runs of it with other noise.",
        ("target", f"saved (of {steps})", "ours, mean", "ours, 5th to 95th percentile",
         "ours, share of the steps", "our runs with at least the saved count"), rows))


#: A saved difference in words: +1, the teams' mean is larger; -1, smaller.
SIZE_WORDS = {1: "larger", -1: "smaller"}


def saved_directions() -> dict:
    """The saved runs' per-target comparison of the team script with the unique-pair script:
    ``{(statistic, target): +1 / -1}``, +1 where the teams' mean (steps 2 to 100) is larger."""
    pairs, teams = (saved_run(n).summary() for n in RUN_NAMES)
    return {(k, l): int(np.sign(teams[k][l] - pairs[k][l]))
            for k in ("mean_error", "mean_trace") for l in range(3)}


@claim(
    id="later-teams-vs-pairs",
    kind="later",
    where="The authors' later experiment, both scripts",
    title="The team greedy tracks worse than unique pairs: a larger covariance for every "
    "target.",
    statement="The saved runs compare the two assignments: re-assigning teams by the greedy of "
    "Fig. 9, as the team script runs it, leaves every target a larger covariance than unique "
    "pairs, targets 1 and 3 a larger error and target 2 a smaller one.",
    paper="The saved runs of the authors' two scripts, not in the paper, with the same noise "
    "at each step and sensor.",
    notebook=NOTEBOOK,
)
def _teams_vs_pairs(p: dict) -> Finding:
    """The six per-target comparisons of the saved runs (mean error and mean trace of each
    target, steps 2 to 100, teams as run against unique pairs: :func:`saved_directions`) against
    our paired runs over ``n_seeds`` noise seeds: a comparison *goes the saved way* when the
    paired Wilcoxon test at :data:`ALPHA` finds the teams worse where the saved teams' mean is
    larger, better where it is smaller.

    reproduced: all six go the saved way; partly: some do; refuted: none does."""
    runs = _runs(p)
    stats = {k: run_statistics(runs[k]) for k in (REFERENCE, AS_RUN)}
    rows = {(r["target"]): r for r in comparison_rows(stats) if r["assignment"] == AS_RUN}
    want = saved_directions()
    pairs, teams = (saved_run(n).summary() for n in RUN_NAMES)
    got, table = {}, []
    for (k, l), sign in want.items():
        r = rows[l + 1]
        verdict = _verdict(r, trace=k == "mean_trace")
        got[(k, l)] = verdict
        pre = "vs_" if k == "mean_error" else "vs_trace_"
        agrees = verdict == ("worse" if sign > 0 else "better")
        table.append((target_math(l), STATISTIC_WORDS[k],
                      f"{number(pairs[k][l])} and {number(teams[k][l])}",
                      f"{number(_mean(stats, REFERENCE, k, l))} and "
                      f"{number(_mean(stats, AS_RUN, k, l))}",
                      f"{count(r[pre + 'other_better'])} / {count(r[pre + 'reference_better'])}",
                      small(r[pre + "p_wilcoxon"], 1e-12),
                      "yes" if agrees else "no"))
    same = [kl for kl, sign in want.items() if got[kl] == ("worse" if sign > 0 else "better")]
    status = ("reproduced" if len(same) == len(want) else "partly" if same else "refuted")
    n = number(p["n_seeds"])
    off = [kl for kl in want if kl not in same]

    def said(kl):
        k, l = kl
        what = f"the {STATISTIC_WORDS[k]} of {target_math(l)}"
        if got[kl] == "same":
            return f"{what}, where our runs show no clear difference"
        bigger = "larger" if got[kl] == "worse" else "smaller"
        return f"{what}, which the teams make {bigger}, not {SIZE_WORDS[want[kl]]}"

    if status == "reproduced":
        summary = (f"Over {n} paired runs the team greedy as run goes the way the saved runs "
                   "show in all 6 of their per-target comparisons with unique pairs, a larger "
                   "covariance for every target among them.")
    else:
        summary = (f"Over {n} paired runs the team greedy as run goes the way the saved runs "
                   f"show in {count(len(same))} of their 6 per-target comparisons with unique "
                   f"pairs, but not for {listing([said(kl) for kl in off])}.")
    overall = rows["all"]
    ours = (summary + " Over the three targets the teams as run have the mean error "
            f"{number(overall['mean_error'])} against {number(_mean_all(stats))} and the mean "
            f"trace {number(overall['mean_trace'])} against "
            f"{number(_mean_all(stats, 'mean_trace'))}.")
    ev = {"saved_directions": {f"{k}, target {l + 1}": s for (k, l), s in want.items()},
          "ours": {f"{k}, target {l + 1}": v for (k, l), v in got.items()},
          "same_way": len(same), "alpha": ALPHA,
          "overall": {"mean_error": overall["mean_error"], "mean_trace": overall["mean_trace"],
                      "verdict": _verdict(overall), "verdict_trace": _verdict(overall, True)}}
    return Finding(status, summary=summary, ours=ours, evidence=ev, table=Table(
        f"Each target's means over steps 2 to 100 with unique pairs and with the teams as run, "
        f"in the saved runs and over our {n} paired runs; the runs in which the teams are lower "
        f"and higher, and the paired Wilcoxon test (at {setting(ALPHA)}).",
        ("target", "quantity", "saved: pairs and teams", "ours: pairs and teams",
         "runs teams lower / higher", "Wilcoxon $p$", "the saved way"), table))


def _mean(stats: dict, name: str, key: str, l: int) -> float:
    """The mean over the runs of one target's statistic ``key`` under assignment ``name``."""
    return float(np.asarray(stats[name][key])[:, l].mean())


def _mean_all(stats: dict, key: str = "mean_error", name: str = REFERENCE) -> float:
    """The mean over the runs and targets of ``key`` under ``name`` (the unique pairs)."""
    return float(np.asarray(stats[name][key]).mean())


# --------------------------------------------------------------------------------------------
# The team script's code
# --------------------------------------------------------------------------------------------


@claim(
    id="later-code-rounds",
    kind="code",
    where="The authors' later experiment, team script",
    title="The team script measures each target with the sensors numbered by the rounds it "
    "won.",
    statement="In the team script, each target's filter measures with the sensors the team "
    "greedy gave it.",
    paper="Not in the paper. The script hands the filters the column indices of the greedy's "
    "table of picks, which number the greedy's rounds, not the sensors.",
    notebook=NOTEBOOK,
)
def _code_rounds(p: dict) -> Finding:
    """The saved team run's trace after the first update does not depend on the noise: it is
    fixed by the sensors each filter measures with at step 1. agrees: it is the trace the
    sensors the greedy picked give (within :data:`SAVED_RTOL`); differs: it is not (the finding
    says whether the rounds' reading gives it, and how much that reading changes the tracking,
    in paired runs against the teams as picked and against unique pairs, Wilcoxon at
    :data:`ALPHA`)."""
    c = code_treatment(p["n_seeds"], p["seed"])
    saved = np.array(c["saved_step2"])
    first = c["first_step"]["code"]
    gap = {k: float(np.abs(np.array(first[f"trace_{k}"]) / saved - 1).max())
           for k in ("picked", "rounds")}
    status = "agrees" if gap["picked"] <= SAVED_RTOL else "differs"
    runs = _runs(p)
    stats = {k: run_statistics(runs[k]) for k in (REFERENCE, "logdet-teams", AS_RUN)}
    vs_picked = comparison_rows({k: stats[k] for k in ("logdet-teams", AS_RUN)},
                                reference="logdet-teams")
    vs_pairs = {r["assignment"]: r for r in comparison_rows(stats) if r["target"] == "all"}
    rp = next(r for r in vs_picked if r["assignment"] == AS_RUN and r["target"] == "all")
    n = number(p["n_seeds"])
    picked_err, run_err = vs_pairs["logdet-teams"]["mean_error"], rp["mean_error"]
    verdict = {k: _verdict(v) for k, v in vs_pairs.items() if k != REFERENCE}
    effect = {"worse": "raises", "better": "lowers", "same": "hardly changes"}[_verdict(rp)]
    flips = verdict["logdet-teams"] != verdict[AS_RUN]
    words = {"worse": "worse than", "better": "better than", "same": "no differently from"}
    if status == "differs" and gap["rounds"] <= SAVED_RTOL:
        summary = ("The team script measures each target with the sensors numbered by the "
                   "rounds the target won, not with the sensors it won: only this reading gives "
                   f"the saved trace after the first update, and over {n} paired runs it "
                   f"{effect} the mean error from {number(picked_err)} to {number(run_err)}"
                   + (f", so that the teams track {words[verdict[AS_RUN]]} unique pairs where "
                      f"the teams as picked track {words[verdict['logdet-teams']]} them."
                      if flips else "."))
    elif status == "differs":
        summary = ("The saved team run's trace after the first update is not the one its "
                   "greedy's teams give, read as picked or by rounds.")
    else:
        summary = ("The team script measures each target with the sensors the greedy gave it: "
                   "the saved trace after the first update is the one these teams give.")
    ours = summary + (" The rounds are the order in which the greedy handed out the sensors, so "
                      "a target measures with sensors it never won.")
    rows = [("saved run", "", ", ".join(number(x) for x in saved), "", "", "")]
    for name, key in (("logdet-teams", "picked"), (AS_RUN, "rounds")):
        v = vs_pairs[name]
        rows.append((ASSIGNMENT_WORDS[name],
                     "; ".join(team_math(t) for t in first[key]),
                     ", ".join(number(x) for x in first[f"trace_{key}"]),
                     number(v["mean_error"]), number(v["mean_trace"]),
                     f"{words[verdict[name]]} unique pairs ({_p(v['vs_p_wilcoxon'])})"))
    ev = {"gap_picked": gap["picked"], "gap_rounds": gap["rounds"],
          "picked": first["picked"], "rounds": first["rounds"],
          "as_run_vs_picked": {"mean_error": rp["mean_error"],
                               "median_diff": rp["vs_median_diff"],
                               "p_wilcoxon": rp["vs_p_wilcoxon"], "verdict": _verdict(rp)},
          "picked_mean_error": picked_err, "vs_pairs": verdict}
    return Finding(status, summary=summary, ours=ours, evidence=ev, table=Table(
        f"The first step's teams ($t_1$; $t_2$; $t_3$) of the code's greedy read as picked and "
        f"by rounds, the trace of each target's covariance after the first update (which no "
        f"noise changes) against the saved run's, and over {n} paired runs the mean error and "
        f"trace and the paired test of the error against unique pairs (Wilcoxon at "
        f"{setting(ALPHA)}).",
        ("reading", "teams at step 1", r"$\operatorname{tr}\Sigma$ after step 1",
         "mean error", r"mean $\operatorname{tr}\Sigma$", "error against unique pairs"), rows))


@claim(
    id="later-code-singular",
    kind="code",
    where="The authors' later experiment, team script",
    title="The team greedy spreads the sensors over the targets only through rounding.",
    statement=r"The team greedy gives each sensor, round by round, to the target whose "
    r"$\log\det(O_l^T O_l)$ grows most, the measure of Fig. 9.",
    paper=r"Not in the paper. A team of one sensor has a singular $O_l^T O_l$, whose "
    r"$\log\det$ is $-\infty$; the code's floating point gives a rounding residue instead.",
    notebook=NOTEBOOK,
)
def _code_singular(p: dict) -> Finding:
    """The first step's teams at the initial estimates in the code's arithmetic (an LU
    factorisation with a fused multiply-add), without the fused multiply-add, and exactly
    (:func:`obslib.tracking.code_logdet.logdet_rounds`). agrees: the code's teams are the exact
    measure's; differs: they are not (the finding says how much that matters: over ``n_seeds``
    runs, the share of the target-steps without a sensor and the tracks lost with the code's
    teams, exactly, and with the prior of ``"logdet-teams-prior"``)."""
    c = code_treatment(p["n_seeds"], p["seed"])
    first = c["first_step"]
    same = first["code"]["picked"] == first["exact"]["picked"]
    status = "agrees" if same else "differs"
    runs = _runs(p)
    names = ("logdet-teams", "logdet-teams-exact", "logdet-teams-prior")
    lost = {k: int(run_statistics(runs[k])["lost"].sum()) for k in names}
    none = {k: c["team_sizes"][k]["share_none"] for k in names}
    n = number(p["n_seeds"])
    exact_one = [len(t) for t in first["exact"]["picked"]]
    N = sum(exact_one)
    if status == "differs":
        taker = int(np.argmax(exact_one))
        others = [l for l in range(len(exact_one)) if l != taker]
        starved = runs["logdet-teams-exact"].unobserved[..., others]
        when = (f"at every step of all {n} runs" if starved.all() else
                f"at {percent(float(starved.mean()))} of their steps over {n} runs")
        summary = (r"The team greedy spreads the sensors over the targets only through "
                   r"rounding: the $\log\det$ of a one-sensor team is $-\infty$, and evaluated "
                   f"exactly it gives all {number(N)} sensors to {target_math(taker)} and "
                   f"leaves {listing([target_math(l) for l in others])} without a sensor "
                   f"{when}, where the code's rounding residues leave a target without "
                   f"one at {percent(none['logdet-teams'])} of the target-steps.")
    else:
        summary = ("The code's rounding gives the teams of the exact measure: the team greedy's "
                   "spread of the sensors is the measure's own.")
    k_lost = lost["logdet-teams-prior"]
    ours = summary + (" Without the fused multiply-add the code's factorisation gives the exact "
                      "teams too; with a prior $\\varepsilon I$ "
                      + ("no target goes without a sensor" if none["logdet-teams-prior"] == 0
                         else "targets go without a sensor at "
                         f"{percent(none['logdet-teams-prior'])} of the target-steps")
                      + (" and no track is lost." if k_lost == 0 else
                         f" and {count(k_lost)} tracks are lost."))
    words = {"code": "the code's: LU with a fused multiply-add",
             "code-unfused": "LU without a fused multiply-add", "exact": "exact"}
    rows = []
    for a in ("code", "code-unfused", "exact"):
        run = {"code": "logdet-teams", "exact": "logdet-teams-exact"}.get(a)
        rows.append((words[a], "; ".join(team_math(t) for t in first[a]["picked"]),
                     percent(none[run]) if run else "",
                     count(lost[run], of=3 * p["n_seeds"]) if run else ""))
    prior = runs["logdet-teams-prior"].run(0).teams[0]
    rows.append((r"with a prior $\varepsilon I$, $\varepsilon$ = "
                 f"{setting(tracking.LATER_MULTI_TARGET.eps)}",
                 "; ".join(team_math(t) for t in prior), percent(none["logdet-teams-prior"]),
                 count(lost["logdet-teams-prior"], of=3 * p["n_seeds"])))
    ev = {"first_step": {a: first[a]["picked"] for a in first}, "share_none": none,
          "lost": lost, "n_runs": p["n_seeds"]}
    return Finding(status, summary=summary, ours=ours, evidence=ev, table=Table(
        r"The team greedy on $\log\det(O_l^T O_l)$ with the singular teams evaluated in three "
        r"arithmetics, and on $\log\det(O_l^T O_l + \varepsilon I)$: the teams at the first "
        f"step ($t_1$; $t_2$; $t_3$) and, over {n} runs, the target-steps without a sensor and "
        "the tracks lost.",
        ("arithmetic", "teams at step 1", "target-steps without a sensor", "tracks lost"),
        rows))


# --------------------------------------------------------------------------------------------
# Beyond the authors: which assignment on a larger network
# --------------------------------------------------------------------------------------------

#: The assignments the book recommends if the evidence bears it out: greedy teams on the
#: filters' information.
INFORMATION_TEAMS = ("d-optimal-teams", "a-optimal-teams")


def network_evidence(p: dict) -> dict:
    """The comparison on the larger network at the parameters ``p`` of notebook 12: the rows of
    :func:`obslib.studies.many_targets.network_comparison` (against unique pairs) and, for each
    of :data:`INFORMATION_TEAMS`, the rows against it (runs paired by scene)."""
    args = (p["net_sensors"], p["net_targets"], p["net_scenes"], p["net_steps"], p["seed"])
    runs = network_runs(*args)
    stats = {k: run_statistics(v) for k, v in runs.items()}
    against = {ref: {r["assignment"]: r for r in comparison_rows(stats, reference=ref)
                     if r["target"] == "all"} for ref in INFORMATION_TEAMS}
    return {"rows": network_comparison(*args), "against": against}


@claim(
    id="beyond-many-targets",
    kind="beyond",
    where="Beyond the paper (many targets, closed loop)",
    title="Which assignment should track many targets: pairs by the bound, log-det teams or "
    "teams on the filters' information?",
    statement="On a larger network of range sensors re-assigned at every step, which "
    "assignment tracks many targets best: the paper's unique pairs by the bound (Algorithm 1), "
    r"its teams on $\log\det$ (Fig. 9), or greedy teams on the filters' information (D- or "
    "A-optimal)?",
    paper="Not asked. The paper's experiments track one target at a time; Figs. 8-9 judge "
    "assignments by their own objective.",
    notebook=NOTEBOOK,
)
def _many_targets(p: dict) -> Finding:
    """``net_scenes`` random scenes of ``net_sensors`` sensors and ``net_targets`` targets
    (:func:`obslib.tracking.network_scene`), every assignment of
    :data:`obslib.studies.many_targets.NETWORK_ASSIGNMENTS`, runs paired by scene. answered:
    each of :data:`INFORMATION_TEAMS` has a lower mean error than every other assignment but
    the other one, significantly (paired Wilcoxon test at :data:`ALPHA`), and loses no track;
    open otherwise."""
    ev = network_evidence(p)
    against = ev["against"]
    names = [r["assignment"] for r in ev["rows"] if r["target"] == "all"]
    best = {ref: all(_verdict(against[ref][k]) == "worse" for k in names
                     if k not in INFORMATION_TEAMS)
            and against[ref][ref]["lost"] == 0 for ref in INFORMATION_TEAMS}
    status = "answered" if all(best.values()) else "open"
    by = {r["assignment"]: r for r in ev["rows"] if r["target"] == "all"}
    d, u = by["d-optimal-teams"], by[REFERENCE]
    size = (f"$N = {p['net_sensors']}$ sensors and $L = {p['net_targets']}$ targets")
    wins = d["vs_other_better"]
    scenes = p["net_scenes"]
    if status == "answered":
        summary = (f"With {size}, greedy teams on the filters' information track best: the "
                   f"D-optimal teams' mean error is {number(d['mean_error'])} against "
                   f"{number(u['mean_error'])} for the paper's unique pairs, lower in "
                   f"{count(wins, of=scenes)} scenes, and the A-optimal teams do as well.")
    else:
        summary = (f"With {size}, over {count(scenes)} scenes, no assignment tracks clearly "
                   "better than all others: the D-optimal teams' mean error is "
                   f"{number(d['mean_error'])} against {number(u['mean_error'])} for the "
                   "paper's unique pairs.")
    prior = by["logdet-teams-prior"]
    ours = (summary + r" The paper's $\log\det$ teams, with a prior to make them well defined, "
            f"come between the two ({number(prior['mean_error'])}); the E-optimal teams give "
            "every sensor to one target and lose the others, as the isotropic first "
            "covariances leave every first gain at zero.")
    rows = []
    for k in names:
        r = by[k]
        t = against["d-optimal-teams"].get(k)
        rows.append((ASSIGNMENT_WORDS[k], number(r["mean_error"]), number(r["mean_trace"]),
                     number(r["unobserved"]), count(r["lost"]),
                     "" if k == "d-optimal-teams" else
                     f"{count(t['vs_reference_better'], of=t['vs_n'])} "
                     f"({_p(t['vs_p_wilcoxon'])})"))
    evidence = {"best": best, "alpha": ALPHA,
                "rows": [{k: v for k, v in r.items() if not isinstance(v, np.ndarray)}
                         for r in ev["rows"] if r["target"] == "all"],
                "against": {ref: {k: {"verdict": _verdict(v), "wins": v["vs_reference_better"]}
                                  for k, v in rows_.items() if k != ref}
                            for ref, rows_ in against.items()}}
    return Finding(status, summary=summary, ours=ours, evidence=evidence, table=Table(
        f"Every assignment on {count(scenes)} random scenes with {size}, "
        f"{number(p['net_steps'])} steps: the mean error and trace over the runs and targets, "
        "the target-steps without a sensor per run, the tracks lost, and the scenes in which "
        f"the D-optimal teams have the lower error (paired Wilcoxon test at {setting(ALPHA)}).",
        ("assignment", "mean error", r"mean $\operatorname{tr}\Sigma$",
         "target-steps without a sensor", "tracks lost", "D-optimal teams better"), rows))

"""Claims of Section IV-A: Algorithm 1 and Theorem 6 (notebook 03)."""

from __future__ import annotations

from dataclasses import asdict

import numpy as np

from ..assignment import greedy_pair_assignment, optimal_pair_assignment
from ..formatting import count, number, percent, setting, small
from ..studies import unchecked_statements
from ..studies.greedy_tightness import (
    TIGHT_U_MAX,
    first_pick_margin,
    jitter_summary,
    tight_witness,
    witness_jitter_ratios,
)
from ..studies.greedy_unique_pairs import (
    NOTEBOOK,
    GreedyStudy,
    charging_audit,
    greedy_vs_optimal,
    signed_weights_study,
    tight_weights,
    worst_instance_search,
)
from ._ledger import Finding, Table, claim


def _study(p: dict) -> GreedyStudy:
    """The greedy against the exact optimum on notebook 03's random instances."""
    return greedy_vs_optimal(p["n_instances"], p["seed"], (p["targets_min"], p["targets_max"]),
                             (0, p["extra_max"]), p["u_max"])


def _worst(p: dict) -> float:
    """Greedy / optimum at the worst layout notebook 03's local search finds."""
    return worst_instance_search(p["search_sensors"], p["search_targets"], p["seed"],
                                 p["n_starts"], p["n_steps"], p["u_max"])[0]


def _sizes(p: dict, n: int) -> str:
    """The random instances of notebook 03 in words."""
    return (f"{number(n)} random instances ($L$ = {p['targets_min']} to {p['targets_max']} "
            f"targets, $N = 2L$ to $2L + {p['extra_max']}$ sensors)")


#: What the abstract of the later journal version states about Theorem 6.
JOURNAL_THM6 = (r"The abstract of the later journal version {cite}`zhou2019sensor` states the "
                r"$1/3$ guarantee for arbitrary value functions, for a pair problem that assigns "
                "exactly two sensors to each target.")


@claim(
    id="thm6",
    where="Theorem 6 (Sec. IV-A)",
    title="Greedy unique pairs (Algorithm 1) is a $1/3$-approximation.",
    statement="Algorithm 1 (greedy unique pairs) collects at least $1/3$ of the optimum of "
    "Problem 1.",
    paper=r"$\omega(\mathrm{GREEDY}) \ge \mathrm{OPT}/3$ for any $\omega$ (charging proof).",
    quote=r"We prove that the greedy algorithm achieves a $1/3$--approximation of the optimal "
    "solution.",
    notebook=NOTEBOOK,
    journal=JOURNAL_THM6,
)
def _thm6(p: dict) -> Finding:
    """reproduced: greedy / optimum (the optimum exact, by dynamic programming) is at least 1/3
    on every random instance and at the worst layout the local search finds; refuted
    otherwise. The hand-made weights are shown, not judged."""
    study, worst_ratio = _study(p), _worst(p)
    W = tight_weights(1e-3)
    tight = greedy_pair_assignment(W).value / optimal_pair_assignment(W).value
    ratios = study.ratio
    lowest = float(ratios.min())
    ok = lowest >= 1 / 3 - 1e-12 and worst_ratio >= 1 / 3 - 1e-12
    return Finding(
        "reproduced" if ok else "refuted",
        summary=(f"Theorem 6 holds: the greedy never collects less than a third of the exact "
                 f"optimum, its worst being {number(lowest)} of it on "
                 f"{number(ratios.size)} random instances and {number(worst_ratio)} on the "
                 "worst layout a local search finds." if ok else
                 "Theorem 6 fails: the greedy collects less than a third of the exact optimum on "
                 f"some instance, down to {number(min(lowest, worst_ratio))} of it."),
        ours=("The greedy never collects less than a third of the exact optimum, neither on "
              "random instances nor on the worst geometry a local search finds, and hand-made "
              f"weights on which it collects {number(tight, 4)} of it show that $1/3$ is the "
              r"best constant for a general $\omega$." if ok else ""),
        evidence={
            "n_instances": int(ratios.size),
            "min_ratio": lowest,
            "median_ratio": float(np.median(ratios)),
            "fraction_optimal": float(np.mean(ratios >= 1 - 1e-12)),
            "worst_search_ratio": float(worst_ratio),
            "tight_weights_ratio": float(tight),
        },
        table=Table("Greedy over the exact optimum of Problem 1.",
                    ("instances", "greedy / optimum"), [
                        (f"{_sizes(p, ratios.size)}: smallest", number(lowest)),
                        ("the same: median", number(float(np.median(ratios)))),
                        (f"the worst geometry of a local search ({p['n_starts']} starts of "
                         f"{p['n_steps']} steps)", number(float(worst_ratio))),
                        ("hand-made weights", number(float(tight), 4)),
                    ]),
    )


@claim(
    id="thm6-any-omega",
    where="Sec. II (before Sec. III) and Theorem 6 (Sec. IV-A)",
    title=r"Algorithm 1 is a $1/3$-approximation for any value function $\omega$.",
    statement=r"Algorithm 1 collects at least a third of the optimum of Problem 1 for any value "
    r"$\omega(\cdot)$ of the triples.",
    paper=r"Stated for any $\omega$; the charging proof compares values, and its last step, "
    r"charging at most three triples to a pick, bounds their sum by three times the pick's "
    "value.",
    quote=r"We present a $1/3$--approximation to solve Problem~\ref{prob:unique} for any "
    r"$\omega(\cdot)$.",
    notebook=NOTEBOOK,
)
def _thm6_any_omega(p: dict) -> Finding:
    """Random weights uniform in [-1, 1], every assignment enumerated. partly: the greedy falls
    below a third of the optimum on some signed instances but on none of the same instances
    with the absolute values (the guarantee needs omega >= 0, which the last step of the proof
    uses: n_k w_k <= 3 w_k only for w_k >= 0); reproduced: it never falls below a third;
    refuted: it falls below a third with non-negative values too."""
    st = signed_weights_study(p["n_instances"], p["seed"], (p["targets_min"],
                                                            p["targets_max"]))
    n = st.greedy.size
    bad, bad_abs = int(st.below_third.sum()), int(st.below_third_abs.sum())
    negative = int(((st.greedy < 0) & (st.optimum > 0)).sum())
    w = st.witness
    if bad_abs:
        status = "refuted"
    else:
        status = "partly" if bad else "reproduced"
    summary = {
        "partly": r"Theorem 6's third needs values $\omega \ge 0$: with values of both signs the "
                  f"greedy collects less than a third of the optimum in {count(bad, of=n)} random "
                  f"instances, down to {number(w['greedy'])} against an optimum of "
                  f"{number(w['optimum'])}, and never with the same values made non-negative.",
        "reproduced": r"Theorem 6's third holds for values of both signs: the greedy collects at "
                      f"least a third of the optimum in all {number(n)} random instances.",
        "refuted": "The greedy collects less than a third of the optimum even with non-negative "
                   f"values, in {count(bad_abs, of=n)} random instances.",
    }[status]
    return Finding(
        status,
        summary=summary,
        ours=(r"The charging argument shows $\mathrm{OPT} \le \sum_k n_k w_k$ for picks of value "
              r"$w_k$ charged with $n_k \le 3$ optimal triples, and $\sum_k n_k w_k \le "
              r"3 \sum_k w_k$ only when every $w_k \ge 0$: a pick of negative value charged with "
              "fewer than three triples breaks it. With values of both signs the greedy's total "
              f"is even negative while the optimum is positive in {count(negative, of=n)} random "
              r"instances, so Theorem 6 holds for $\omega \ge 0$, as the pair bound is."
              if status == "partly" else ""),
        evidence={"n_instances": n, "below_third": bad, "below_third_nonnegative": bad_abs,
                  "negative_greedy_positive_optimum": negative, "witness": w},
        table=Table(f"Algorithm 1 against the optimum (every assignment enumerated) on {number(n)} "
                    r"random instances, $L$ = " + f"{p['targets_min']} to {p['targets_max']} "
                    r"targets, $N = 2L$ sensors, values uniform in $[-1, 1]$, and on the same "
                    "instances with the values' absolute values.",
                    ("values", r"greedy below $\mathrm{OPT}/3$",
                     r"greedy below 0 with $\mathrm{OPT} > 0$"),
                    [("of both signs", count(bad, of=n), count(negative, of=n)),
                     ("the same, made non-negative", count(bad_abs, of=n), "none")]),
    )


@claim(
    id="thm6-proof-charging",
    where="Proof of Theorem 6 (Sec. IV-A)",
    title="The charging argument of Theorem 6's proof.",
    statement="Charging each greedy pick, in order, with the optimal triples not charged before "
    "that share a sensor or the target with it charges every optimal triple exactly once, to a "
    "pick of at least its value, and at most three triples to a pick; hence "
    r"$\mathrm{OPT} \le 3\,\omega(\mathrm{GREEDY})$.",
    paper="Three cases: the pick is itself optimal; two of its elements are in one optimal "
    "triple; no two are.",
    quote=r"We will charge the value $\omega(s_i,s_j,t_l)$ to at most three triples in OPT that "
    "have not been charged in previous rounds.",
    notebook=NOTEBOOK,
)
def _thm6_charging(p: dict) -> Finding:
    """On notebook 03's random instances (the exact optimum's assignment from the dynamic
    program): reproduced when every optimal triple is charged exactly once, none is heavier than
    its pick, no pick takes more than three, and OPT <= sum n_k w_k <= 3 GREEDY on every
    instance; refuted when any step fails."""
    a = charging_audit(p["n_instances"], p["seed"], (p["targets_min"], p["targets_max"]),
                       (0, p["extra_max"]), p["u_max"])
    fails = a.n_not_once + a.n_heavier + a.n_over_three + a.n_chain_broken
    picks = a.charges_per_pick
    return Finding(
        "reproduced" if not fails else "refuted",
        summary=(f"The proof's charging argument holds step by step: on all "
                 f"{number(a.n_instances)} random instances every optimal triple is charged "
                 "exactly once, to a greedy pick of at least its value, and no pick is charged "
                 "with more than three." if not fails else
                 "The proof's charging argument fails on some random instances: "
                 f"{count(a.n_not_once)} leave an optimal triple charged other than once, "
                 f"{count(a.n_heavier)} charged triples outweigh their pick and "
                 f"{count(a.n_over_three)} picks take more than three."),
        ours=("Every optimal triple is charged exactly once, since the greedy serves every "
              "target; a triple charged in round $k$ was still free then, so it weighs no more "
              f"than the pick; and of the {number(a.n_picks)} picks, {count(picks[3])} take three "
              "triples, the case that makes the constant $1/3$." if not fails else ""),
        evidence=asdict(a),
        table=Table(f"The charging argument on {_sizes(p, a.n_instances)}: the greedy's picks by "
                    "the number of optimal triples charged to them, and the steps of the proof "
                    "that fail.", ("quantity", "value"), [
                        *[(f"picks charged with {words} optimal {noun}", number(c))
                          for words, noun, c in zip(("no", "one", "two", "three"),
                                                    ("triple", "triple", "triples", "triples"),
                                                    picks[:4])],
                        ("picks charged with more than three", count(a.n_over_three)),
                        ("instances where an optimal triple is charged other than once",
                         count(a.n_not_once)),
                        ("charged triples heavier than their pick", count(a.n_heavier)),
                        ("largest value of a charged triple minus its pick's",
                         small(a.largest_slack) if a.largest_slack else "0"),
                        (r"instances where $\mathrm{OPT} \le \sum_k n_k w_k \le "
                         r"3\,\omega(\mathrm{GREEDY})$ fails", count(a.n_chain_broken)),
                    ]),
    )


@claim(
    id="thm6-practice",
    where="Sec. I and V-C",
    title="In practice the greedy does much better than $1/3$.",
    statement="The greedy performs much better than $1/3$ in practice.",
    paper="Greedy close to the relaxed matching, much higher than a third of it (Fig. 8).",
    quote=r"Thus, even though we give a theoretical $1/3$--approximation for the greedy "
    "algorithm, it performs much better in practice.",
    notebook=NOTEBOOK,
)
def _thm6_practice(p: dict) -> Finding:
    """reproduced when the 5 % quantile of greedy / optimum over random instances (Fig. 8's kind)
    is >= 0.75, refuted otherwise. Geometries built to be hard are another question
    (``thm6-tight``)."""
    study, worst_ratio = _study(p), _worst(p)
    r = study.ratio
    q05 = float(np.quantile(r, 0.05))
    optimal = float(np.mean(r >= 1 - 1e-12))
    ok = q05 >= 0.75
    return Finding(
        "reproduced" if ok else "refuted",
        summary=(f"The greedy does much better than a third in practice: on {number(r.size)} "
                 f"random instances it collects at least {number(q05)} of the exact optimum in "
                 f"95% of them, and the optimum itself in {percent(optimal)}." if ok else
                 f"The greedy does not do much better than a third in practice: on "
                 f"{number(r.size)} random instances it collects less than {number(q05)} of the "
                 "exact optimum in 5% of them."),
        ours=(f"On random instances the greedy finds the optimum in {percent(optimal)} of them, "
              f"and in 95% of them collects more than {number(q05)} of it; only geometries built "
              f"to be hard bring it down, to {number(float(worst_ratio))} at the worst layout a "
              "local search finds." if ok else ""),
        evidence={
            "quantile_05": q05,
            "median": float(np.median(r)),
            "fraction_optimal": optimal,
            "worst_search_ratio": float(worst_ratio),
        },
        table=Table(f"Greedy over the exact optimum on {_sizes(p, r.size)}.",
                    ("quantity", "value"), [
                        ("instances solved optimally by the greedy", percent(optimal)),
                        ("median of greedy / optimum", number(float(np.median(r)))),
                        ("5% quantile of greedy / optimum", number(q05)),
                        ("worst geometry of a local search", number(float(worst_ratio))),
                    ]),
    )


# ---------------------------------------------------------------------------------------------
# Theorem 6 on geometric weights: how close to 1/3, and how fragile (notebook 11)
# ---------------------------------------------------------------------------------------------

#: "Nearly attained": a geometry where greedy / optimum is at most this.
NEAR_THIRD = 0.35


@claim(
    id="thm6-tight",
    kind="beyond",
    where="Theorem 6 (Sec. IV-A)",
    title="Is Theorem 6's $1/3$ nearly attained by the pair bound's own weights?",
    statement="Is the $1/3$ of Theorem 6 nearly attained also by the pair bound's own weights, "
    "that is, do sensor-target geometries exist where Algorithm 1 collects at most "
    f"{NEAR_THIRD:g} of the optimum?",
    paper="A $1/3$-approximation \"for any $\\omega$\"; tightness is not discussed.",
    notebook=unchecked_statements.NOTEBOOK,
    uses=(NOTEBOOK,),
)
def _thm6_tight(p: dict) -> Finding:
    """The answer rests on the stored witness geometry (:data:`obslib.studies.greedy_tightness.
    TIGHT_SENSORS`, found by the local search at the paper's sizes), re-evaluated at every
    profile: answered (yes) when greedy / optimum there is at most :data:`NEAR_THIRD`, open
    otherwise (a search that finds no such geometry does not show that none exists). The search
    at the profile's sizes and the fragility of the witness (every point jittered by a fraction
    of the spread) are reported, not judged."""
    q = p[NOTEBOOK]
    S, T = tight_witness()
    margin = first_pick_margin(S, T, TIGHT_U_MAX)
    ratio = margin["ratio"]
    searched = _worst(q)
    fr = p["jitter_fractions"]
    rows = jitter_summary(witness_jitter_ratios(fr, p["n_jitter"], p["seed"]), fr)
    answered = ratio <= NEAR_THIRD
    lifted = next((r for r in rows if r["below_half"] < 0.5), None)
    if lifted is None:
        fragile = (f"and jitters of up to {setting(rows[-1]['fraction'])} of its spread leave "
                   "the greedy below half the optimum in most draws")
    else:
        fragile = (f"but it is a knife edge: moving every point by {percent(lifted['fraction'])} "
                   "of the layout's spread lifts the greedy above half the optimum in "
                   f"{percent(1 - lifted['below_half'])} of draws")
    ours = (
        f"A geometry of six sensors and three targets exists where the greedy collects "
        f"{number(ratio)} of the optimum (nearly attained meaning at most "
        f"{setting(NEAR_THIRD)}): its first pick outweighs the heaviest optimal triple it blocks "
        f"by a relative {number(margin['relative_margin'])}, so the example is a knife edge that "
        "a small jitter of the points mostly undoes."
    )
    ev = {"witness_ratio": ratio, "near_third": NEAR_THIRD, "search_ratio": searched,
          "relative_margin": margin["relative_margin"], "first_pick_w": margin["w"],
          "blocked_w": margin["blocked_w"], "jitter": rows}
    table = Table(
        f"Greedy over optimum at the witness geometry with every point jittered by a fraction of "
        f"the spread ({number(p['n_jitter'])} draws per fraction); a local search of "
        f"{q['n_starts']} starts of {q['n_steps']} steps reaches {number(searched)}.",
        ("jitter (fraction of the spread)", "median ratio", "draws below 1/2"),
        [(setting(r["fraction"]), number(r["median"]), percent(r["below_half"])) for r in rows])
    return Finding(
        "answered" if answered else "open",
        summary=(f"Yes: with the pair bound's own values the greedy collects only "
                 f"{number(ratio)} of the optimum at a layout of six sensors and three targets, "
                 f"{fragile}." if answered else
                 f"Not known: the closest layout found brings the greedy to {number(ratio)} of "
                 f"the optimum, above {setting(NEAR_THIRD)}."),
        ours=ours if answered else "",
        evidence=ev,
        table=table,
    )

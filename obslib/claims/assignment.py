"""Claims of Section IV-A: Algorithm 1 and Theorem 6 (notebook 03)."""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .._format import number, percent, setting
from ..assignment import greedy_pair_assignment, optimal_pair_assignment
from ..profiles import params
from ..studies import assignment as sa
from ..studies import greedy_tightness as gt
from ..studies.unchecked import NOTEBOOK as UNCHECKED
from ._ledger import Finding, Table, claim

NB = "03_greedy_unique_pairs"


@lru_cache(maxsize=4)
def _study(n_instances, seed, t_min, t_max, extra_max, u_max):
    return sa.greedy_vs_optimal(n_instances, seed, (t_min, t_max), (0, extra_max), u_max)


@lru_cache(maxsize=4)
def _search(n_sensors, n_targets, seed, n_starts, n_steps, u_max):
    return sa.worst_instance_search(n_sensors, n_targets, seed, n_starts, n_steps, u_max)


def _run(profile):
    p = params(NB, profile)
    study = _study(
        p["n_instances"], p["seed"], p["targets_min"], p["targets_max"], p["extra_max"], p["u_max"]
    )
    worst = _search(
        p["search_sensors"], p["search_targets"], p["seed"], p["n_starts"], p["n_steps"], p["u_max"]
    )
    return p, study, worst


#: What the abstract of the later journal version states about Theorem 6.
LATER_THM6 = (r"The abstract of the later journal version {cite}`zhou2019sensor` states the "
              r"$1/3$ guarantee for arbitrary value functions, for a pair problem that assigns "
              "exactly two sensors to each target.")


@claim(
    id="thm6",
    where="Theorem 6 (Sec. IV-A)",
    title="Greedy unique pairs (Algorithm 1) is a $1/3$-approximation.",
    statement="Algorithm 1 (greedy unique pairs) collects at least $1/3$ of the optimum of "
    "Problem 1.",
    paper=r"$\omega(\mathrm{GREEDY}) \ge \mathrm{OPT}/3$ for any $\omega$ (charging proof).",
    notebook=NB,
    later=LATER_THM6,
)
def _thm6(profile: str) -> Finding:
    p, study, (worst_ratio, _, _) = _run(profile)
    W = sa.tight_weights(1e-3)
    tight = greedy_pair_assignment(W).value / optimal_pair_assignment(W).value
    ratios = study.ratio
    ok = ratios.min() >= 1 / 3 - 1e-12 and worst_ratio >= 1 / 3 - 1e-12
    return Finding(
        "reproduced" if ok else "refuted",
        "The greedy never collects less than a third of the exact optimum, neither on random "
        "instances nor on the worst geometry a local search finds, and hand-made weights on "
        "which it collects barely more than a third show that $1/3$ is the best constant for a "
        r"general $\omega$.",
        {
            "n_instances": int(ratios.size),
            "min_ratio": float(ratios.min()),
            "median_ratio": float(np.median(ratios)),
            "fraction_optimal": float(np.mean(ratios >= 1 - 1e-12)),
            "worst_search_ratio": float(worst_ratio),
            "tight_weights_ratio": float(tight),
        },
        Table("Greedy over the exact optimum of Problem 1.", ("instances", "greedy / optimum"), [
            (f"{number(ratios.size)} random instances ($L$ = {p['targets_min']} to "
             f"{p['targets_max']} targets, $N = 2L$ to $2L + {p['extra_max']}$ sensors): smallest",
             number(float(ratios.min()))),
            ("the same: median", number(float(np.median(ratios)))),
            (f"the worst geometry of a local search ({p['n_starts']} starts of {p['n_steps']} "
             "steps)", number(float(worst_ratio))),
            ("hand-made weights", number(float(tight), 4)),
        ]),
    )


@claim(
    id="thm6-practice",
    where="Sec. I and V-C",
    title="In practice the greedy does much better than $1/3$.",
    statement="The greedy performs much better than $1/3$ in practice.",
    paper="Greedy close to the relaxed matching, much higher than a third of it (Fig. 8).",
    notebook=NB,
)
def _thm6_practice(profile: str) -> Finding:
    """reproduced when the 5 % quantile of greedy / optimum over random instances (Fig. 8's kind)
    is >= 0.75, refuted otherwise. Geometries built to be hard are another question
    (``thm6-tight``)."""
    p, study, (worst_ratio, _, _) = _run(profile)
    r = study.ratio
    q05 = float(np.quantile(r, 0.05))
    status = "reproduced" if q05 >= 0.75 else "refuted"
    return Finding(
        status,
        "On random instances the greedy is often optimal and collects more than three quarters "
        "of the optimum in 95% of them; only geometries built to be hard bring it near a third.",
        {
            "quantile_05": q05,
            "median": float(np.median(r)),
            "worst_search_ratio": float(worst_ratio),
        },
        Table(
            f"Greedy over the exact optimum on {number(r.size)} random instances.",
            ("quantity", "value"),
            [
                (
                    "instances solved optimally by the greedy",
                    percent(float(np.mean(r >= 1 - 1e-12))),
                ),
                ("median of greedy / optimum", number(float(np.median(r)))),
                ("5% quantile of greedy / optimum", number(q05)),
                ("worst geometry of a local search", number(float(worst_ratio))),
            ],
        ),
    )


# ---------------------------------------------------------------------------------------------
# Theorem 6 on geometric weights: how close to 1/3, and how fragile (notebook 11)
# ---------------------------------------------------------------------------------------------

#: "Nearly attained": a geometry where greedy / optimum is at most this.
NEAR_THIRD = 0.35


@claim(
    id="thm6-tight",
    where="Theorem 6 (Sec. IV-A)",
    title="Theorem 6's $1/3$ is nearly attained by the pair bound's own weights.",
    statement="The $1/3$ of Theorem 6 is nearly attained also by the pair bound's own weights: "
    "sensor-target geometries exist where Algorithm 1 collects at most "
    f"{NEAR_THIRD:g} of the optimum.",
    paper="A $1/3$-approximation \"for any $\\omega$\"; tightness is not discussed.",
    notebook="11_unchecked_statements",
)
def _thm6_tight(profile: str) -> Finding:
    """The verdict rests on the stored witness geometry (:data:`obslib.studies.greedy_tightness.
    TIGHT_SENSORS`, found by the local search at the paper's sizes), re-evaluated at every
    profile: reproduced when greedy / optimum there is at most :data:`NEAR_THIRD`, partly when
    below 1/2, refuted otherwise. The search at the profile's sizes and the fragility of the
    witness (every point jittered by a fraction of the spread) are reported, not judged."""
    p = params(NB, profile)
    q = params(UNCHECKED, profile)
    S, T = gt.tight_witness()
    margin = gt.first_pick_margin(S, T, gt.TIGHT_U_MAX)
    ratio = margin["ratio"]
    searched, _, _ = gt.tight_geometry(p["search_sensors"], p["search_targets"], p["seed"],
                                       p["n_starts"], p["n_steps"], p["u_max"])
    fr = q["jitter_fractions"]
    rows = gt.jitter_summary(gt.jitter_ratios(S, T, fr, q["n_jitter"], q["seed"], gt.TIGHT_U_MAX),
                             fr)
    status = "reproduced" if ratio <= NEAR_THIRD else ("partly" if ratio < 0.5 else "refuted")
    ours = (
        f"A geometry of six sensors and three targets exists where the greedy collects "
        f"{number(ratio)} of the optimum (nearly attained meaning at most {setting(NEAR_THIRD)}): "
        "its first pick outweighs the heaviest optimal triple it blocks by a relative "
        f"{number(margin['relative_margin'])}, so the example is a knife edge that a jitter of a "
        "percent of the layout's spread mostly undoes."
    )
    ev = {"witness_ratio": ratio, "near_third": NEAR_THIRD, "search_ratio": searched,
          "relative_margin": margin["relative_margin"], "first_pick_w": margin["w"],
          "blocked_w": margin["blocked_w"], "jitter": rows}
    table = Table(
        f"Greedy over optimum at the witness geometry with every point jittered by a fraction of "
        f"the spread ({number(q['n_jitter'])} draws per fraction); a local search of "
        f"{p['n_starts']} starts of {p['n_steps']} steps reaches {number(searched)}.",
        ("jitter (fraction of the spread)", "median ratio", "draws below 1/2"),
        [(setting(r["fraction"]), number(r["median"]), percent(r["below_half"])) for r in rows])
    return Finding(status, ours, ev, table)

"""Claims of Section IV-A: Algorithm 1 and Theorem 6 (notebook 03)."""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from ..studies import assignment as st
from ..assignment import greedy_pair_assignment, optimal_pair_assignment
from ..profiles import params
from ._ledger import Finding, claim

NB = "03_greedy_unique_pairs"


@lru_cache(maxsize=4)
def _study(n_instances, seed, t_min, t_max, extra_max, u_max):
    return st.greedy_vs_optimal(n_instances, seed, (t_min, t_max), (0, extra_max), u_max)


@lru_cache(maxsize=4)
def _search(n_sensors, n_targets, seed, n_starts, n_steps, u_max):
    return st.worst_instance_search(n_sensors, n_targets, seed, n_starts, n_steps, u_max)


def _run(profile):
    p = params(NB, profile)
    study = _study(p["n_instances"], p["seed"], p["targets_min"], p["targets_max"], p["extra_max"], p["u_max"])
    worst = _search(p["search_sensors"], p["search_targets"], p["seed"], p["n_starts"], p["n_steps"], p["u_max"])
    return p, study, worst


@claim(
    id="thm6",
    where="Theorem 6 (Sec. IV-A)",
    title="Greedy unique pairs (Algorithm 1) is a $1/3$-approximation.",
    statement="Algorithm 1 (greedy unique pairs) collects at least $1/3$ of the optimum of "
    "Problem 1.",
    paper=r"$\omega(\mathrm{GREEDY}) \ge \mathrm{OPT}/3$ for any $\omega$ (charging proof).",
    notebook=NB,
)
def _thm6(profile: str) -> Finding:
    p, study, (worst_ratio, _, _) = _run(profile)
    W = st.tight_weights(1e-3)
    tight = greedy_pair_assignment(W).value / optimal_pair_assignment(W).value
    ratios = study.ratio
    ok = ratios.min() >= 1 / 3 - 1e-12 and worst_ratio >= 1 / 3 - 1e-12
    return Finding(
        "reproduced" if ok else "refuted",
        f"Greedy over exact optimum on {ratios.size} random instances ($L$ = {p['targets_min']} "
        f"to {p['targets_max']} targets, $N = 2L$ to $2L + {p['extra_max']}$ sensors): minimum "
        f"{ratios.min():.3f}, median {np.median(ratios):.3f}; the worst geometry found by local "
        f"search reaches {worst_ratio:.3f}; on hand-made weights the greedy gets {tight:.4f}, so "
        r"$1/3$ is the best constant for a general $\omega$.",
        {
            "n_instances": int(ratios.size),
            "min_ratio": float(ratios.min()),
            "median_ratio": float(np.median(ratios)),
            "fraction_optimal": float(np.mean(ratios >= 1 - 1e-12)),
            "worst_search_ratio": float(worst_ratio),
            "tight_weights_ratio": float(tight),
        },
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
    p, study, (worst_ratio, _, _) = _run(profile)
    r = study.ratio
    q05 = float(np.quantile(r, 0.05))
    # "much better than 1/3 in practice" is about random instances (Fig. 8's kind): reproduced
    # when the 5 % quantile is >= 0.75, refuted otherwise. Geometries built to be hard are a
    # separate question (thm6-tight).
    status = "reproduced" if q05 >= 0.75 else "refuted"
    return Finding(
        status,
        f"On random instances yes: the greedy is optimal in {np.mean(r >= 1 - 1e-12):.0%} of "
        f"{r.size} small instances, median {np.median(r):.3f} of the optimum and above "
        f"{q05:.2f} in 95 %. (Geometries built by local search get down to {worst_ratio:.3f}: "
        "see `thm6-tight`.)",
        {"quantile_05": q05, "median": float(np.median(r)),
         "worst_search_ratio": float(worst_ratio)},
    )


# ---------------------------------------------------------------------------------------------
# Theorem 6 on geometric weights: how close to 1/3, and how fragile (notebook 11)
# ---------------------------------------------------------------------------------------------

#: The worst geometry counts as near 1/3 when its ratio is below this.
NEAR_THIRD = 0.35


@claim(
    id="thm6-tight",
    where="Theorem 6 (Sec. IV-A)",
    title="Theorem 6's $1/3$ is nearly attained by the pair bound's own weights.",
    statement="The 1/3 of Theorem 6 is nearly attained also by the pair bound's own weights: "
    "sensor-target geometries exist where Algorithm 1 collects about a third of the optimum.",
    paper="A 1/3-approximation \"for any $\\omega$\"; tightness is not discussed.",
    notebook="11_unchecked_statements",
)
def _thm6_tight(profile: str) -> Finding:
    """reproduced: the local search of notebook 03 finds a geometry with greedy / optimum below
    :data:`NEAR_THIRD`; partly: below 1/2; refuted otherwise. The fragility (jitter of every
    point by a fraction of the spread) is reported, not judged: a tight example may be fragile."""
    from ..studies import greedy_tightness as gt
    from ..studies.unchecked import NOTEBOOK as UNCHECKED

    p = params(NB, profile)
    q = params(UNCHECKED, profile)
    ratio, S, T = gt.tight_geometry(p["search_sensors"], p["search_targets"], p["seed"],
                                    p["n_starts"], p["n_steps"], p["u_max"])
    margin = gt.first_pick_margin(S, T, p["u_max"])
    fr = q["jitter_fractions"]
    rows = gt.jitter_summary(gt.jitter_ratios(S, T, fr, q["n_jitter"], q["seed"], p["u_max"]), fr)
    status = "reproduced" if ratio < NEAR_THIRD else ("partly" if ratio < 0.5 else "refuted")
    by = {r["fraction"]: r for r in rows}
    small, big = by[min(by)], by[max(by)]
    flip = next((r for r in rows if r["median"] > 0.5), None)
    ours = (
        f"Local search finds a geometry where the greedy gets {ratio:.3f} of the optimum: its "
        f"first pick outweighs the heaviest of the three optimal triples it blocks by only "
        f"{margin['relative_margin']:.1e} (relative). The example is a knife edge: jittering "
        f"every point by {small['fraction']:.0e} of the spread keeps the ratio at "
        f"{small['median']:.3f} (median of {q['n_jitter']} draws), "
        + (
            f"but at {flip['fraction']:.0e} the median ratio is {flip['median']:.2f} and only "
            f"{flip['below_half']:.0%} of draws stay below 1/2; "
            if flip
            else ""
        )
        + f"at {big['fraction']:.0e}, {big['below_half']:.0%} of draws stay below 1/2."
    )
    ev = {"worst_ratio": ratio, "relative_margin": margin["relative_margin"],
          "first_pick_w": margin["w"], "blocked_w": margin["blocked_w"], "jitter": rows}
    return Finding(status, ours, ev)

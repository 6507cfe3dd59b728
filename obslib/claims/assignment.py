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
    # "much better than 1/3": random instances well above it (5 % quantile >= 0.75), and no
    # geometry found near it (>= 0.5); partly when only the first holds
    if q05 < 0.75:
        status = "refuted"
    else:
        status = "reproduced" if worst_ratio >= 0.5 else "partly"
    return Finding(
        status,
        f"On random instances yes: the greedy is optimal in {np.mean(r >= 1 - 1e-12):.0%} of "
        f"{r.size} small instances and above {q05:.2f} of the optimum in 95 % of them. Not for "
        f"every geometry: local search finds sensor-target layouts where it gets "
        f"{worst_ratio:.3f}, close to the $1/3$ guarantee.",
        {"quantile_05": q05, "worst_search_ratio": float(worst_ratio)},
    )

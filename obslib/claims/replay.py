"""The published runs of Figs. 4-7 replayed with their own measurement noise (notebook 11).

Registered after the tracking claims of Sections V-A and V-B, which it sharpens.
"""

from __future__ import annotations

from .._format import count, small
from ..profiles import params
from ..studies import replay as rp
from ..studies.unchecked import NOTEBOOK
from ._ledger import Finding, Table, claim

#: The log is printed to 12 significant digits and its numbers are at most about 10.
REPLAY_TOLERANCE = rp.LOG_TOLERANCE

#: The runs the noise table determines in full.
REPLAYED = ("best-pair", "best-partner", "adversarial")


def _comparisons():
    """Every published run against its replay (computed once, in :mod:`obslib.studies.replay`)."""
    return {name: rp.compare_replay(name) for name in rp.RUN_NAMES}


#: The published runs by name, in words.
RUN_WORDS = {"best-pair": "strategy (1), Figs. 4-6", "best-partner": "strategy (2), Figs. 4-6",
             "adversarial": "the adversarial run, Fig. 7"}


@claim(
    id="published-replay",
    where="Sec. V-A/B, Figs. 4-7 (published runs)",
    title="The published runs of Figs. 4-7 follow from the experiments' model.",
    statement="The published runs of Figs. 4-7 follow from the experiments' model: replayed "
    "with the noise they used, strategies (1) and (2) and the adversarial run give the logged "
    "pairs, bounds, covariances and target moves.",
    paper="The code and figures of the simulations are published (Sec. V footnote); the saved "
    "runs hold their per-step data.",
    notebook=NOTEBOOK,
)
def _published_replay(profile: str) -> Finding:
    """reproduced: each of the three runs has the logged pair at every step, reads no unknown
    noise entry (two fills give identical runs) and every logged number within
    :data:`REPLAY_TOLERANCE`; partly: the pairs agree but some number does not; refuted: a pair
    differs. The noise was solved from each run's own estimates, so the estimates agree by
    construction; what the replay tests is counted apart (:func:`obslib.studies.replay.
    independent_checks`). How typical the published adversarial run is among random noise seeds
    is in the evidence (it sharpens ``fig7-figure-data``)."""
    p = params(NOTEBOOK, profile)
    cmp = _comparisons()
    runs = [cmp[n] for n in REPLAYED]
    pairs_ok = all(c.pair_mismatches == 0 for c in runs)
    exact = all(c.matches for c in runs)
    status = "reproduced" if exact else ("partly" if pairs_ok else "refuted")
    checks = {n: rp.independent_checks(n) for n in REPLAYED}
    t = rp.seed_typicality(p["n_seeds_typical"], p["seed"])
    fixed_steps = cmp["fixed-pair"].steps
    if exact:
        ours = ("The model reproduces the three runs: fed the noise recovered from the logs, it "
                "chooses the logged pair at every step and gives the logged bounds, covariances "
                "and target moves to rounding, and where a run reads noise recovered from "
                "another run's log the two agree. The estimates themselves agree by "
                "construction, since the noise was solved from them, and strategy (3)'s run "
                f"can be checked only up to step {fixed_steps}.")
    else:
        ours = ("Fed the noise recovered from the logs, the model does not reproduce every run: "
                + ("the pairs agree but some logged number does not." if pairs_ok else
                   "the chosen pairs differ from the logged ones."))
    rows = [(RUN_WORDS[n], checks[n]["pairs"], checks[n]["bounds"], checks[n]["covariances"],
             checks[n]["target"],
             f"{count(checks[n]['shared_noise'], of=checks[n]['read_noise'])}",
             small(cmp[n].largest, 1e-10)) for n in REPLAYED]
    ev = {
        "runs": {
            n: {
                "steps": c.steps,
                "largest_abs_diff": c.largest,
                "max_abs_diff": c.max_abs_diff,
                "n_values": c.n_values,
                "pair_mismatches": c.pair_mismatches,
                "fills_agree": c.fills_agree,
                "unknown_reads": c.unknown_reads,
            }
            for n, c in cmp.items()
        },
        "independent_checks": checks,
        "typicality": {
            "n_seeds": p["n_seeds_typical"],
            "published_mean_bound": round(t["published"], 4),
            "percentile": round(t["percentile"], 2),
            "at_least": round(t["at_least"], 4),
            "within_tolerance": round(t["within_tolerance"], 4),
            "quantiles": {q: round(v, 4) for q, v in t["quantiles"].items()},
        },
    }
    return Finding(status, ours, ev, Table(
        "What the replays test: the logged numbers that the recovered noise does not fix (pairs "
        "chosen, bounds, covariance entries and traces, the target's positions and moves), the "
        "noise entries read that another run's log gave, and the largest difference from the "
        "log. The estimates and errors, which agree by construction, are not counted.",
        ("run", "pairs", "bounds", "covariances", "target", "noise from another run",
         "largest difference"), rows))

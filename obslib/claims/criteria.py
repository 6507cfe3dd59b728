"""Beyond the paper: is the bound the right criterion? (notebook 10).

The paper's implied claims that choosing sensors by its bound tracks better than other choices,
tested against the classical criteria of optimal experimental design and, for assignments, by
how well the targets are then tracked. The evidence is computed by
:mod:`obslib.studies.criteria`, shared with the notebook.
"""

from __future__ import annotations

from ..profiles import params
from ..studies import criteria as cs
from ._ledger import Finding, claim

NB = cs.NOTEBOOK
#: Significance level of the paired tests (two-sided Wilcoxon signed-rank).
ALPHA = 0.01
CLASSICAL = ("d-optimal", "a-optimal", "e-optimal")


def _verdicts(rows):
    """Per strategy: "better" / "worse" than the bound's choice (significant) or "same"."""
    return {r["strategy"]: cs.significance(r, ALPHA) for r in rows if "vs_p_wilcoxon" in r}


def criteria_evidence(profile: str) -> dict:
    """The summary rows of every (setting, metric) at ``profile``'s sizes."""
    p = params(NB, profile)
    study = cs.tracking_study(p["n_seeds"], p["seed"], p["metrics"])
    return {
        f"{setting}, {metric}": cs.summary_rows(mc, loss_threshold=p["loss_threshold"])
        for (setting, metric), mc in study.items()
    }


@claim(
    id="beyond-criteria",
    where="Beyond the paper (Sec. V-A, V-B)",
    title="Choosing the pair by the bound tracks better than the classical design criteria.",
    statement="Choosing the pair by the bound (strategy (1)) tracks better than other ways of "
    "choosing it, including the classical criteria of optimal design (D-, A-, E-optimality of "
    "the filter's information).",
    paper="Implied by Sec. V; compared only with a fixed pair and a fixed sensor's best partner.",
    notebook=NB,
)
def _criteria(profile: str) -> Finding:
    p = params(NB, profile)
    missing = [c for c in CLASSICAL if c not in cs.available_strategies()]
    if missing:
        return Finding(
            "untestable",
            f"The tracking engine does not yet offer the criteria {missing}.",
            {"missing": missing},
        )
    ev = criteria_evidence(profile)
    verdict = {k: _verdicts(rows) for k, rows in ev.items()}
    beats = {k: [c for c in CLASSICAL if v.get(c) == "better"] for k, v in verdict.items()}
    loses = {k: [c for c in CLASSICAL if v.get(c) == "worse"] for k, v in verdict.items()}
    if all(beats.values()):
        status = "refuted"
    elif any(beats.values()):
        status = "partly"
    else:
        status = "reproduced"
    parts = []
    for k, rows in ev.items():
        by = {r["strategy"]: r for r in rows}
        ref = by[cs.REFERENCE]["mean_error"]
        best = min(CLASSICAL, key=lambda c: by[c]["mean_error"])
        parts.append(
            f"{k}: bound {ref:.3f}, best classical {best} {by[best]['mean_error']:.3f}, better in "
            f"{by[best]['vs_other_better']} of {by[best]['vs_n']} runs (significantly better than "
            f"the bound: {', '.join(beats[k]) or 'none'}; worse: {', '.join(loses[k]) or 'none'}"
            + (f"; exact-$C^{{-1}}$ oracle {by['exact-icn']['mean_error']:.3f}" if "exact-icn" in by else "") + ")"
        )
    ours = (
        f"Mean tracking error over {p['n_seeds']} seeds with common noise, paired Wilcoxon test at "
        f"{ALPHA}: " + "; ".join(parts) + "."
    )
    evidence = {
        k: [{key: (round(v, 4) if isinstance(v, float) else v) for key, v in r.items()} for r in rows]
        for k, rows in ev.items()
    }
    return Finding(status, ours, {"alpha": ALPHA, "verdicts": verdict, "rows": evidence})


def _cell(r):
    return f"{r['median_error']:.3f} ({r['mean_error']:.3f}, {r['lost']})"


@claim(
    id="beyond-assignment-tracking",
    where="Beyond the paper (Sec. V-C, Fig. 8)",
    title="Assigning pairs by the bound tracks moving targets better than by information gain.",
    statement="Assigning unique pairs by the bound (Algorithm 1), re-assigned every step, tracks "
    "moving targets better than assigning them by the information gain (D-optimality) or at "
    "random.",
    paper="Implied by Figs. 8-9, which judge assignments only by the bound's own total.",
    notebook=NB,
)
def _assignment(profile: str) -> Finding:
    p = params(NB, profile)
    rows = cs.assignment_rows(cs.assignment_study(p), loss_threshold=p["assign_loss"])
    verdict = {}
    for r in rows:
        if "vs_p_wilcoxon" in r:
            verdict[f"L={r['L']}, {r['rule']}"] = cs.significance(r, ALPHA)
    beats_random = all(v == "worse" for k, v in verdict.items() if k.endswith("random"))
    d_better = [k for k, v in verdict.items() if k.endswith("d-optimal") and v == "better"]
    d_worse = [k for k, v in verdict.items() if k.endswith("d-optimal") and v == "worse"]
    if not beats_random:
        status = "refuted"
    elif d_better:
        status = "partly"
    else:
        status = "reproduced" if d_worse else "partly"
    by = {(r["L"], r["rule"]): r for r in rows}
    parts = [
        f"L = {L}: median (mean, lost targets) bound {_cell(by[(L, 'bound')])}, D-optimal "
        f"{_cell(by[(L, 'd-optimal')])}, random {_cell(by[(L, 'random')])}"
        for L in sorted({r["L"] for r in rows})
    ]
    ours = (
        f"Per-run mean error summed over targets after each update, {p['assign_seeds']} seeds, "
        f"{p['assign_steps']} steps, N = 2L: " + "; ".join(parts) + ". Paired Wilcoxon at "
        f"{ALPHA}, direction by the median difference: the bound beats random {'everywhere' if beats_random else 'not everywhere'}; "
        f"D-optimal is better at {', '.join(k.split(',')[0] for k in d_better) or 'no L'} and "
        f"worse at {', '.join(k.split(',')[0] for k in d_worse) or 'no L'}."
    )
    evidence = [{k: (round(v, 4) if isinstance(v, float) else v) for k, v in r.items()} for r in rows]
    return Finding(status, ours, {"alpha": ALPHA, "verdicts": verdict, "rows": evidence})

"""Beyond the paper: is the bound the right criterion? (notebook 10).

Two questions of this book, not claims of the paper (entries of kind ``"beyond"``, status
``answered`` or ``open``): does choosing the pair by the bound track better than the classical
criteria of optimal experimental design, and do assignments by the bound track moving targets
better than assignments by information gain or at random? The evidence is computed by
:mod:`obslib.studies.criteria`, shared with the notebook.
"""

from __future__ import annotations

from .._format import count, fixed, listing, number, percent, setting, small
from ..profiles import params
from ..studies import criteria as cs
from ._ledger import Finding, Table, claim

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


#: The classical criteria in words.
CRITERION_NAMES = {"d-optimal": "D-optimal", "a-optimal": "A-optimal", "e-optimal": "E-optimal",
                   "exact-icn": r"exact-$C^{-1}$ oracle", "bound": "bound", "random": "random"}


def _p(row) -> str:
    """``p = 0.13`` or ``p < 10^-12``, as the book prints a p-value."""
    text = small(row["vs_p_wilcoxon"], 1e-12)
    return f"$p {text[1:]}" if text.startswith("$<") else f"$p$ = {text}"


@claim(
    id="beyond-criteria",
    where="Beyond the paper (Sec. V-A, V-B)",
    title="Does choosing the pair by the bound track better than the classical design criteria?",
    statement="Does choosing the pair by the bound (strategy (1)) track better than choosing it "
    "by the classical criteria of optimal design (D-, A- and E-optimality of the filter's "
    "information)?",
    paper="Not asked. The paper compares the bound's choice only with a fixed pair and with a "
    "fixed sensor's best partner (Sec. V-A).",
    notebook=NB,
    kind="beyond",
)
def _criteria(profile: str) -> Finding:
    """answered: in every setting (trajectory and metric) the paired Wilcoxon test at
    :data:`ALPHA` decides the comparison with at least one classical criterion, or with all of
    them in the bound's favour; open otherwise."""
    p = params(NB, profile)
    missing = [c for c in CLASSICAL if c not in cs.available_strategies()]
    if missing:
        return Finding("open", f"The tracking engine does not offer the criteria {missing} yet.",
                       {"missing": missing})
    ev = criteria_evidence(profile)
    verdict = {k: _verdicts(rows) for k, rows in ev.items()}
    beats = {k: [c for c in CLASSICAL if v.get(c) == "better"] for k, v in verdict.items()}
    loses = {k: [c for c in CLASSICAL if v.get(c) == "worse"] for k, v in verdict.items()}
    all_beat = all(len(b) == len(CLASSICAL) for b in beats.values())
    settled = all(beats.values()) or all(len(w) == len(CLASSICAL) for w in loses.values())
    status = "answered" if settled else "open"
    if all_beat:
        ours = ("No: on the circle and against the adversary, with either metric, each of the D-, "
                "A- and E-optimal criteria tracks better than the bound, in nearly every run. The "
                "criteria use the filter's $Q$, $R$ and covariance, which the bound ignores by "
                "design, so this measures what that information is worth, not a flaw in the "
                "bound's computation.")
    elif all(beats.values()):
        ours = ("No: in every setting at least one classical criterion tracks better than the "
                "bound. The criteria use the filter's $Q$, $R$ and covariance, which the bound "
                "ignores by design.")
    else:
        ours = ("The paired comparisons do not decide the question in every setting at these "
                "sizes.")
    rows = []
    for k, rs in ev.items():
        by = {r["strategy"]: r for r in rs}
        ref = by[cs.REFERENCE]["mean_error"]
        best = min(CLASSICAL, key=lambda c: by[c]["mean_error"])
        rows.append((k.replace("circle", "the circle").replace("adversary", "the adversary")
                     .replace("mahalanobis", "Mahalanobis").replace("euclidean", "Euclidean"),
                     fixed(ref, 3), f"{CRITERION_NAMES[best]}, {fixed(by[best]['mean_error'], 3)}",
                     percent(1 - by[best]["mean_error"] / ref),
                     f"{number(by[best]['vs_other_better'])} of {number(by[best]['vs_n'])}",
                     listing([CRITERION_NAMES[c] for c in beats[k]]) if beats[k] else "none",
                     fixed(by["exact-icn"]["mean_error"], 3) if "exact-icn" in by else ""))
    evidence = {
        k: [{key: (round(v, 4) if isinstance(v, float) else v) for key, v in r.items()} for r in rs]
        for k, rs in ev.items()
    }
    return Finding(status, ours, {"alpha": ALPHA, "verdicts": verdict, "rows": evidence}, Table(
        f"Mean tracking error over {number(p['n_seeds'])} runs with common noise, by trajectory "
        f"and distance metric of the bound; paired Wilcoxon test at {setting(ALPHA)}.",
        ("setting", "bound", "best classical criterion", "lower by", "runs it wins",
         "significantly better than the bound", r"exact-$C^{-1}$ oracle"), rows))


@claim(
    id="beyond-assignment-tracking",
    where="Beyond the paper (Sec. V-C, Fig. 8)",
    title="Do assignments by the bound track moving targets better than by information gain or "
    "at random?",
    statement="Does assigning unique pairs by the bound (Algorithm 1), re-assigned every step, "
    "track moving targets better than assigning them by the information gain (D-optimality) or "
    "at random?",
    paper="Not asked. Figs. 8-9 judge assignments only by the bound's own total.",
    notebook=NB,
    kind="beyond",
)
def _assignment(profile: str) -> Finding:
    """answered: the paired Wilcoxon test at :data:`ALPHA` decides the comparison with random
    assignment at every number of targets (the comparison with D-optimality is reported as it
    comes out, decided or not); open otherwise."""
    p = params(NB, profile)
    rows = cs.assignment_rows(cs.assignment_study(p), loss_threshold=p["assign_loss"])
    by = {(r["L"], r["rule"]): r for r in rows}
    Ls = sorted({r["L"] for r in rows})
    sig = {(L, rule): cs.significance(by[(L, rule)], ALPHA) for L in Ls
           for rule in ("d-optimal", "random")}
    status = "answered" if all(sig[(L, "random")] != "same" for L in Ls) else "open"
    median_wins = [L for L in Ls if sig[(L, "random")] == "worse"]
    mean_loses = [L for L in Ls if by[(L, "bound")]["mean_error"] > by[(L, "random")]["mean_error"]]
    d_better = [L for L in Ls if sig[(L, "d-optimal")] == "better"]
    d_worse = [L for L in Ls if sig[(L, "d-optimal")] == "worse"]

    def ls(values):
        return listing([f"$L = {L}$" for L in values])

    first = ("Against random assignment the bound's assignment wins the typical run"
             + ("" if median_wins == Ls else f" only at {ls(median_wins)}" if median_wins else
                " at no $L$")
             + (f", but not on average at {ls(mean_loses)}, where random assignment has the lower "
                "mean error" + (" because the bound's assignment loses targets" if any(
                    by[(L, "bound")]["lost"] > by[(L, "random")]["lost"] for L in mean_loses)
                    else "") if mean_loses else ", and on average too"))
    if not d_better and not d_worse:
        second = ("against the greedy information-gain (D-optimal) assignment it is neither "
                  "clearly better nor clearly worse.")
    else:
        second = ("against the greedy information-gain (D-optimal) assignment it is "
                  + (f"worse at {ls(d_better)}" if d_better else "")
                  + (" and " if d_better and d_worse else "")
                  + (f"better at {ls(d_worse)}" if d_worse else "") + ".")
    ours = first + "; " + second
    table = []
    for L in Ls:
        for rule in ("bound", "d-optimal", "random"):
            r = by[(L, rule)]
            test = "" if rule == "bound" else (
                {"better": "better than the bound", "worse": "worse than the bound",
                 "same": "no clear difference"}[sig[(L, rule)]] + f" ({_p(r)})")
            table.append((L, CRITERION_NAMES[rule], fixed(r["median_error"], 3),
                          fixed(r["mean_error"], 3), count(r["lost"]), test))
    evidence = [{k: (round(v, 4) if isinstance(v, float) else v) for k, v in r.items()}
                for r in rows]
    return Finding(status, ours, {"alpha": ALPHA, "verdicts": {f"L={L}, {rule}": v for
                                                               (L, rule), v in sig.items()},
                                  "rows": evidence}, Table(
        f"Error summed over the targets after each update, per run ({number(p['assign_seeds'])} "
        f"runs of {number(p['assign_steps'])} steps, $N = 2L$ sensors re-assigned every step), "
        f"and the paired Wilcoxon test against the bound's assignment at {setting(ALPHA)}.",
        ("$L$", "assignment", "median error", "mean error", "targets lost", "paired test"),
        table))

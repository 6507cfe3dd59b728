"""Beyond the paper: is the bound the right criterion? (notebook 10).

Two questions of this book, not claims of the paper (entries of kind ``"beyond"``, status
``answered`` or ``open``): does choosing the pair by the bound track better than the classical
criteria of optimal experimental design, and do assignments by the bound track moving targets
better than assignments by information gain or at random? The evidence is computed by
:mod:`obslib.studies.criteria`, shared with the notebook.
"""

from __future__ import annotations

from ..formatting import count, listing, number, percent, setting, small
from ..studies.criteria import (
    NOTEBOOK,
    REFERENCE,
    assignment_rows,
    assignment_study,
    significance,
    summary_rows,
    tracking_study,
)
from ._ledger import Finding, Table, claim

#: Significance level of the paired tests (two-sided Wilcoxon signed-rank).
ALPHA = 0.01
CLASSICAL = ("d-optimal", "a-optimal", "e-optimal")


def _verdicts(rows):
    """Per strategy: "better" / "worse" than the bound's choice (significant) or "same"."""
    return {r["strategy"]: significance(r, ALPHA) for r in rows if "vs_p_wilcoxon" in r}


def criteria_evidence(p: dict) -> dict:
    """The summary rows of every (setting, metric) with the parameters ``p`` of notebook 10."""
    study = tracking_study(p["n_seeds"], p["seed"], p["metrics"])
    return {
        f"{setting}, {metric}": summary_rows(mc, loss_threshold=p["loss_threshold"])
        for (setting, metric), mc in study.items()
    }


#: The classical criteria in words.
CRITERION_NAMES = {"d-optimal": "D-optimal", "a-optimal": "A-optimal", "e-optimal": "E-optimal",
                   "exact-icn": r"exact-$C^{-1}$ oracle", "bound": "bound", "random": "random"}


def _p(row, key: str = "vs_p_wilcoxon") -> str:
    """``p = 0.13`` or ``p < 10^-12``, as the book prints a p-value (of the Wilcoxon test, or of
    the test ``key`` names)."""
    text = small(row[key], 1e-12)
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
    notebook=NOTEBOOK,
    kind="beyond",
)
def _criteria(p: dict) -> Finding:
    """answered: in every setting (trajectory and metric) the paired Wilcoxon test at
    :data:`ALPHA` decides the comparison with at least one classical criterion, or with all of
    them in the bound's favour; open otherwise."""
    ev = criteria_evidence(p)
    verdict = {k: _verdicts(rows) for k, rows in ev.items()}
    beats = {k: [c for c in CLASSICAL if v.get(c) == "better"] for k, v in verdict.items()}
    loses = {k: [c for c in CLASSICAL if v.get(c) == "worse"] for k, v in verdict.items()}
    all_beat = all(len(b) == len(CLASSICAL) for b in beats.values())
    settled = all(beats.values()) or all(len(w) == len(CLASSICAL) for w in loses.values())
    status = "answered" if settled else "open"
    by = {k: {r["strategy"]: r for r in rs} for k, rs in ev.items()}
    # the fewest runs a criterion that beats the bound wins, over settings and criteria
    won = [(by[k][c]["vs_other_better"], by[k][c]["vs_n"]) for k in ev for c in beats[k]]
    fewest = min(won) if won else None
    n = number(p["n_seeds"])
    why = ("The criteria use the filter's $Q$, $R$ and covariance, which the bound ignores by "
           "design, so this measures what that information is worth, not a flaw in the bound's "
           "computation.")
    if all_beat:
        summary = ("No: on the circle and against the adversary, with either distance in the "
                   "bound, each of the D-, A- and E-optimal criteria tracks better than the "
                   f"bound, winning at least {count(fewest[0], of=fewest[1])} paired runs.")
    elif all(beats.values()):
        summary = ("No: in every setting at least one classical criterion tracks better than the "
                   f"bound, winning at least {count(fewest[0], of=fewest[1])} paired runs.")
    else:
        summary = (f"Over {n} paired runs the comparisons with the classical criteria do not "
                   "decide the question in every setting.")
    ours = summary + (" " + why if all(beats.values()) else "")
    rows = []
    for k in ev:
        b = by[k]
        ref = b[REFERENCE]["mean_error"]
        best = min(CLASSICAL, key=lambda c: b[c]["mean_error"])
        rows.append((k.replace("circle", "the circle").replace("adversary", "the adversary")
                     .replace("mahalanobis", "Mahalanobis").replace("euclidean", "Euclidean"),
                     number(ref), f"{CRITERION_NAMES[best]}, {number(b[best]['mean_error'])}",
                     percent(1 - b[best]["mean_error"] / ref),
                     count(b[best]["vs_other_better"], of=b[best]["vs_n"]),
                     listing([CRITERION_NAMES[c] for c in beats[k]]) if beats[k] else "none",
                     number(b["exact-icn"]["mean_error"]) if "exact-icn" in b else ""))
    return Finding(status, summary=summary, ours=ours,
                   evidence={"alpha": ALPHA, "verdicts": verdict, "rows": ev},
                   table=Table(
        f"Mean tracking error over {n} runs with common noise, by trajectory "
        f"and distance metric of the bound; paired Wilcoxon test at {setting(ALPHA)}.",
        ("setting", "bound", "best classical criterion", "lower by", "runs it wins",
         "significantly better than the bound", r"exact-$C^{-1}$ oracle"), rows))


def runs_and_mean(row: dict, alpha: float = ALPHA) -> dict:
    """A rule's paired comparison with the bound's assignment, as two findings.

    ``runs``: which of the two is better in the paired runs, ``"bound"``, ``"other"`` or
    ``None``: decided by the Wilcoxon signed-rank test at ``alpha`` when it rejects (by the sign
    of the median difference, :func:`obslib.studies.criteria.significance`), else by the
    two-sided sign test at ``alpha`` (the one that wins more runs), else by neither; ``test``
    names the test that decided. ``mean``: which has the lower mean error, ``"bound"`` or
    ``"other"``. Where the two disagree the comparison is mixed.

    Examples
    --------
    >>> r = {"vs_reference_better": 81, "vs_other_better": 119,
    ...      "vs_p_sign": 0.0087, "vs_p_wilcoxon": 0.44,
    ...      "vs_median_diff": -0.012, "vs_mean_diff": 0.016}
    >>> runs_and_mean(r)
    {'runs': 'other', 'test': 'sign', 'mean': 'bound'}
    """
    sig = significance(row, alpha)
    if sig != "same":
        runs, test = ("other" if sig == "better" else "bound"), "wilcoxon"
    elif row["vs_p_sign"] < alpha:
        runs = "other" if row["vs_other_better"] > row["vs_reference_better"] else "bound"
        test = "sign"
    else:
        runs, test = None, None
    return {"runs": runs, "test": test, "mean": "bound" if row["vs_mean_diff"] > 0 else "other"}


def _against(name: str, L: int, row: dict, lost: bool) -> str:
    """How the bound's assignment compares with the assignment ``name`` at ``L`` targets, in
    words; ``lost``: the bound's assignment loses more targets than the other."""
    rm = runs_and_mean(row)
    who = {"bound": "the bound's assignment", "other": name}
    at = f"at $L = {L}$"
    n = row["vs_n"]
    if rm["runs"] is None:
        return (f"{at} neither is clearly better ({name} wins {count(row['vs_other_better'], of=n)}"
                f" runs) and {who[rm['mean']]} has the lower mean error")
    wins = row["vs_reference_better"] if rm["runs"] == "bound" else row["vs_other_better"]
    won = f"{who[rm['runs']]} wins {count(wins, of=n)} runs"
    if rm["test"] == "sign":
        won += f" (sign test {_p(row, 'vs_p_sign')})"
    if rm["runs"] == rm["mean"]:
        return f"{at} {won} and has the lower mean error"
    why = ", since the bound's assignment loses targets" if lost and rm["mean"] == "other" else ""
    return (f"{at} the result is mixed: {won} while {who[rm['mean']]} has the lower mean "
            f"error{why}")


@claim(
    id="beyond-assignment-tracking",
    where="Beyond the paper (Sec. V-C, Fig. 8)",
    title="Do assignments by the bound track moving targets better than by information gain or "
    "at random?",
    statement="Does assigning unique pairs by the bound (Algorithm 1), re-assigned every step, "
    "track moving targets better than assigning them by the information gain (D-optimality) or "
    "at random?",
    paper="Not asked. Figs. 8-9 judge assignments only by the bound's own total.",
    notebook=NOTEBOOK,
    kind="beyond",
)
def _assignment(p: dict) -> Finding:
    """answered: the paired Wilcoxon test at :data:`ALPHA` decides the comparison with random
    assignment at every number of targets; open otherwise. The comparisons with random and with
    the greedy information-gain (D-optimal) assignment are then stated as they come out, by the
    runs each wins (sign test at :data:`ALPHA`) and by the mean error (:func:`runs_and_mean`):
    where the two disagree the result is mixed, and the finding says both."""
    rows = assignment_rows(assignment_study(p), loss_threshold=p["assign_loss"])
    by = {(r["L"], r["rule"]): r for r in rows}
    Ls = sorted({r["L"] for r in rows})
    sig = {(L, rule): significance(by[(L, rule)], ALPHA) for L in Ls
           for rule in ("d-optimal", "random")}
    status = "answered" if all(sig[(L, "random")] != "same" for L in Ls) else "open"
    def part(rule, name):
        return "; ".join(_against(name, L, by[(L, rule)],
                                  by[(L, "bound")]["lost"] > by[(L, rule)]["lost"]) for L in Ls)

    top = Ls[-1]
    summary = ("Against random assignment "
               + _against("random assignment", top, by[(top, "random")],
                          by[(top, "bound")]["lost"] > by[(top, "random")]["lost"])
               + "; against the greedy information-gain (D-optimal) assignment "
               + _against("the D-optimal assignment", top, by[(top, "d-optimal")],
                          by[(top, "bound")]["lost"] > by[(top, "d-optimal")]["lost"]) + ".")
    ours = (f"Against random assignment, {part('random', 'random assignment')}; against the "
            "greedy information-gain (D-optimal) assignment, "
            f"{part('d-optimal', 'the D-optimal assignment')}.")
    table = []
    for L in Ls:
        for rule in ("bound", "d-optimal", "random"):
            r = by[(L, rule)]
            test = "" if rule == "bound" else (
                f"{count(r['vs_other_better'], of=r['vs_n'])} runs won, sign test "
                + _p(r, "vs_p_sign") + "; Wilcoxon " + {"better": "better than the bound",
                                   "worse": "worse than the bound",
                                   "same": "no clear difference"}[sig[(L, rule)]]
                + f" ({_p(r)})")
            table.append((L, CRITERION_NAMES[rule], number(r["median_error"]),
                          number(r["mean_error"]), count(r["lost"]), test))
    return Finding(status, summary=summary, ours=ours,
                   evidence={"alpha": ALPHA,
                             "verdicts": {f"L={L}, {rule}": v for (L, rule), v in sig.items()},
                             "runs_and_mean": {f"L={L}, {rule}": runs_and_mean(by[(L, rule)])
                                               for L in Ls for rule in ("d-optimal", "random")},
                             "rows": rows},
                   table=Table(
        f"Error summed over the targets after each update, per run ({number(p['assign_seeds'])} "
        f"runs of {number(p['assign_steps'])} steps, $N = 2L$ sensors re-assigned every step), "
        f"and the paired comparison with the bound's assignment at {setting(ALPHA)}: runs each "
        "rule wins (two-sided sign test) and the Wilcoxon signed-rank test.",
        ("$L$", "assignment", "median error", "mean error", "targets lost", "paired comparison"),
        table))

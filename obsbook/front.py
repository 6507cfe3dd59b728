"""What the front page states about the ledger, rendered from it (``book/_front.md``).

The front page (``book/intro.md``) includes two generated parts, between the marker comments
of :data:`MARKERS`:

``findings``
    "What this book found": one bullet per :class:`Headline`, most important first. A headline
    opens with a few bold words of its own, then states each of its entries through the entry's
    one sentence (its ``summary``, and its caveat when the robustness study changes the
    verdict) with a link to the section that shows the evidence. The bold words assert a status
    for each entry (:attr:`Headline.statuses`); rendering refuses a headline whose entries the
    ledger now judges otherwise, so the front page can never say more, or other, than its
    evidence.
``exceptions``
    The table of the paper's claims that do not hold as printed: each claim, its verdict with
    its caveat, and its one sentence.

``python -m obsbook.report --front book/_front.md`` writes the file.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from obslib._validate import as_mapping, as_str

from .report import list_table, statement_of, typeset, verdict_line

__all__ = ["MARKERS", "Headline", "HEADLINES", "render_front"]

#: Marker comments around the parts of ``book/_front.md`` that the front page includes.
MARKERS = {
    "findings": ("% findings: start", "% findings: end"),
    "exceptions": ("% exceptions: start", "% exceptions: end"),
}


@dataclass(frozen=True)
class Headline:
    """One finding of the front page: ``lead``, a few bold words (MyST), and the entries it
    states, id -> the status the lead asserts for it, in the order they are stated."""

    lead: str
    statuses: dict = field(default_factory=dict)

    def __post_init__(self):
        as_str(self.lead, "lead")
        if not as_mapping(self.statuses, "statuses"):
            raise ValueError(f"headline {self.lead!r} states no entry")


#: The front page's findings, most important first.
HEADLINES = (
    Headline("The bound holds, and it is sharper than the paper says.",
             {"thm1": "reproduced", "thm1-tight": "reproduced"}),
    Headline("The pair formula is right; printed steps of its proofs are not.",
             {"thm4": "reproduced", "thm4-proof-matrix": "refuted"}),
    Headline("The greedy pair assignment keeps its guarantee and does better in practice.",
             {"thm6": "reproduced", "thm6-practice": "reproduced"}),
    Headline("Theorem 7 is true, but one of its two examples is not, and one of Theorem 8's "
             "four measures fails.",
             {"thm7-case2": "refuted", "thm8-trace-inverse": "refuted"}),
    Headline("The tracking experiments hold on average, not at every step.",
             {"fig6-best-pair": "partly", "fig7-entrapment": "reproduced"}),
    Headline("Fig. 9's even spread depends on the measure.",
             {"fig9-even": "partly", "sec5d-logdet-measure": "differs"}),
    Headline("Beyond the paper, the classical design criteria track better than the bound.",
             {"beyond-criteria": "answered"}),
    Headline("In the authors' later multi-target experiment the team greedy leaves targets "
             "without a sensor, and only its code's rounding spreads the sensors at all.",
             {"later-teams-unobserved": "partly", "later-code-singular": "differs"}),
)


def _check(headlines, records) -> dict:
    by_id = {r.id: r for r in records}
    for h in headlines:
        for cid, status in h.statuses.items():
            if cid not in by_id:
                raise ValueError(f"front page: headline {h.lead!r} states {cid!r}, which the "
                                 "ledger does not hold")
            if by_id[cid].status != status:
                raise ValueError(f"front page: headline {h.lead!r} asserts {cid!r} is {status}, "
                                 f"but the ledger finds it {by_id[cid].status}; rewrite the "
                                 "headline")
    return by_id


def render_front(records, headlines=HEADLINES) -> str:
    """MyST of the front page's generated parts (see the module docstring).

    Raises
    ------
    ValueError
        When a headline asserts a status its entry does not have, or states an unknown entry.
    """
    by_id = _check(headlines, records)
    lines = [MARKERS["findings"][0]]
    for h in headlines:
        said = " ".join(f"{statement_of(by_id[cid])} ([evidence](#{by_id[cid].label}))"
                        for cid in h.statuses)
        lines.append(f"- **{typeset(h.lead)}** {said}")
    lines += [MARKERS["findings"][1], "", MARKERS["exceptions"][0]]
    paper = [r for r in records if r.kind == "paper"]
    bad = [r for s in ("refuted", "partly") for r in paper if r.status == s]
    if bad:
        lines += list_table(
            "The paper's claims that do not hold as printed, refuted first.",
            ["the paper says", "verdict", "what we found"],
            [[f"[{typeset(r.title).rstrip('.')}](#claim-{r.id})", verdict_line(r),
              statement_of(r)] for r in bad],
            name="table-intro-exceptions", widths=(3, 2, 5))
    else:
        lines.append("Every claim of the paper holds as printed.")
    lines.append(MARKERS["exceptions"][1])
    return "\n".join(lines) + "\n"

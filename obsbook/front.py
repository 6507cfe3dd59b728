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

:func:`obsbook.report.render_front` renders them, and
``python -m obsbook.report --front book/_front.md`` writes the file.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from obslib._validate import as_mapping, as_str

__all__ = ["MARKERS", "Headline", "HEADLINES", "check_headlines"]

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
)


def check_headlines(records, headlines=HEADLINES) -> dict:
    """The records by id, once every headline's asserted statuses are the ledger's.

    Raises
    ------
    ValueError
        When a headline asserts a status its entry does not have, or states an unknown entry.
    """
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

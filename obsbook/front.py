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
    The table of the paper's claims that the evidence refutes as printed, each with its one
    sentence, and how many more hold only in part (the report lists them all).

The same file holds, between the markers of :data:`CODE_MARKERS`, what the ledger finds about the
authors' code and saved runs, which the notes on the original code (``book/original_code.md``)
include: so that page, too, states each finding only through its entry's one sentence.
:func:`obsbook.report.render_front` renders them all, and
``python -m obsbook.report --front book/_front.md`` writes the file.

The front page also shows a picture of the bound at a glance,
:func:`obslib.viz.pair_closed_form.plot_bound_at_a_glance`, drawn the book's way
(:mod:`obsbook.figures`) and written by
``python -m obsbook.front --figure book/_static/front.png`` (:func:`write_figure`), which
``make book`` runs before the build: like every figure of the book it is made by code, never
committed.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass, field
from pathlib import Path

from obslib._io import command
from obslib._validate import as_mapping, as_str

__all__ = ["MARKERS", "CODE_MARKERS", "Headline", "HEADLINES", "check_headlines", "FIGURE",
           "front_figure", "write_figure", "main"]

#: Marker comments around the parts of ``book/_front.md`` that the front page includes.
MARKERS = {
    "findings": ("% findings: start", "% findings: end"),
    "exceptions": ("% exceptions: start", "% exceptions: end"),
}

#: Marker comments around the findings about the authors' code in ``book/_front.md``, which the
#: notes on the original code include.
CODE_MARKERS = ("% code: start", "% code: end")


@dataclass(frozen=True)
class Headline:
    """One finding of the front page: ``lead``, a few bold words (MyST); ``statuses``, id -> the
    status the lead asserts for that entry; ``states``, the entries whose one sentences follow
    the lead, in order (default: all of ``statuses``). Every asserted entry is linked."""

    lead: str
    statuses: dict = field(default_factory=dict)
    states: tuple = ()

    def __post_init__(self):
        as_str(self.lead, "lead")
        if not as_mapping(self.statuses, "statuses"):
            raise ValueError(f"headline {self.lead!r} asserts no entry")
        states = tuple(self.states) or tuple(self.statuses)
        if not set(states) <= set(self.statuses):
            raise ValueError(f"headline {self.lead!r} states an entry it asserts nothing of")
        object.__setattr__(self, "states", states)


#: The front page's findings, most important first.
HEADLINES = (
    Headline("The bound holds, and it is the exact worst case.",
             {"thm1": "reproduced", "thm1-tight": "reproduced"}, ("thm1-tight",)),
    Headline("The pair formula is right; printed steps of its proofs are not.",
             {"thm4": "reproduced", "thm4-proof-matrix": "refuted"}, ("thm4-proof-matrix",)),
    Headline("The greedy pair assignment keeps its guarantee and does better in practice.",
             {"thm6": "reproduced", "thm6-practice": "reproduced"}, ("thm6-practice",)),
    Headline("Theorem 7 holds, but one of its two examples shows nothing, and one of Theorem "
             "8's four measures fails.",
             {"thm7": "reproduced", "thm7-case2": "refuted", "thm8-trace-inverse": "refuted"},
             ("thm7-case2", "thm8-trace-inverse")),
    Headline("The tracking experiments hold on average, not at every step.",
             {"fig6-best-pair": "partly", "fig7-entrapment": "reproduced"},
             ("fig6-best-pair",)),
    Headline("Fig. 9's even spread depends on a measure the code changed.",
             {"fig9-even": "partly", "sec5d-logdet-measure": "differs"}, ("fig9-even",)),
    Headline("Beyond the paper, the classical design criteria track better than the bound.",
             {"beyond-criteria": "answered"}),
    Headline("In the authors' later multi-target experiment the team greedy leaves targets "
             "without a sensor, and only its code's rounding spreads the sensors at all.",
             {"later-teams-unobserved": "partly", "later-code-singular": "differs"}),
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



# -------------------------------------------------------------------------------------------
# The front page's picture
# -------------------------------------------------------------------------------------------

#: Where ``make book`` writes the front page's picture, which ``book/intro.md`` shows.
FIGURE = Path(__file__).resolve().parent.parent / "book" / "_static" / "front.png"


def front_figure() -> tuple[bytes, dict]:
    """The front page's picture as PNG and its description (:func:`obsbook.figures.render`),
    drawn with the book's figure settings.

    Raises
    ------
    ValueError
        When its texts overlap, are cut off or are smaller than the book allows
        (:func:`obsbook.figures.problems`).
    """
    import matplotlib

    matplotlib.use("agg")
    import matplotlib.pyplot as plt

    from obslib.viz.pair_closed_form import plot_bound_at_a_glance

    from . import figures

    with matplotlib.rc_context(figures._rc()):
        fig = plot_bound_at_a_glance()
        try:
            png, description = figures.render(fig)
        finally:
            plt.close(fig)
    found = figures.problems(description)
    if found:
        raise ValueError("the front page's picture: " + "; ".join(found))
    return png, description


def write_figure(path=FIGURE) -> bool:
    """Write :func:`front_figure`'s PNG to ``path`` atomically (:func:`obslib._io.write_output`:
    a temporary file in the same folder, then a rename), leaving the file as it is when it
    already holds the same image; returns whether anything was written. A failed write leaves
    the old file as it was."""
    from obslib._io import write_output

    png, _ = front_figure()
    return write_output(path, png)


@command("python -m obsbook.front")
def main(argv=None) -> int:
    """``python -m obsbook.front --figure FILE``: draw the front page's picture and store it
    (exit status 2 for a path that cannot be written)."""
    from obslib._io import OutputPathError, as_output_path, write_or_report

    ap = argparse.ArgumentParser(prog="python -m obsbook.front",
                                 description="Draw the front page's picture.")
    ap.add_argument("--figure", required=True, help="store the PNG here")
    args = ap.parse_args(argv)
    try:
        path = as_output_path(args.figure)
    except OutputPathError as exc:
        ap.error(f"--figure {exc}")
    png, _ = front_figure()
    if not write_or_report("python -m obsbook.front", path, png):
        return 1
    print(f"{path}: the front page's picture")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

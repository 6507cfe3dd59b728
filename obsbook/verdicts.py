"""A chapter's verdict boxes, rendered from the ledger with the chapter's own parameters.

A chapter states the verdict on a claim in one box, right after the evidence: its title names
the verdict (or, for the other kinds of entry, the status), its text is the entry's one sentence
(``summary``) with the caveat of the robustness study, and it links to the entry of the
reproduction report. The box is never typed: the chapter calls :func:`glue_verdicts` once, which
re-checks each entry with the chapter's parameters (:func:`obslib.claims.recheck`) and glues its
box as ``verdict_<id>`` (dashes as underscores) for ``{glue:md}`` with ``:format: myst``. At the
paper's parameters the box is therefore the report's own statement; a rerun with other values
shows the verdict those values give.
"""

from __future__ import annotations

from collections.abc import Mapping

from obslib.claims import recheck, registry, robustness
from obslib.profiles import defaults

from .glue import glue_text
from .report import statement_of

__all__ = ["TITLES", "glue_name", "box", "glue_verdicts"]

#: Kind -> the words before the status in a box's title.
TITLES = {"paper": "Verdict", "beyond": "Our question", "code": "The authors' code",
          "later": "The later experiment"}


def glue_name(id: str) -> str:
    """The glue key of entry ``id``'s box.

    Examples
    --------
    >>> glue_name("thm1-tight")
    'verdict_thm1_tight'
    """
    return "verdict_" + id.replace("-", "_")


def box(record) -> str:
    """The MyST admonition of one evaluated entry.

    Examples
    --------
    >>> from obslib.claims import Record
    >>> r = Record("x", "", "", "", "", "refuted", "", {}, summary="It fails.")
    >>> print(box(r))
    ```{admonition} Verdict: refuted
    :class: verdict verdict-refuted
    <BLANKLINE>
    It fails. [The report's entry](#claim-x)
    ```
    """
    return (f"```{{admonition}} {TITLES[record.kind]}: {record.status}\n"
            f":class: verdict verdict-{record.status}\n\n"
            f"{statement_of(record)} [The report's entry](#claim-{record.id})\n```")


def glue_verdicts(notebook: str, namespace: Mapping, ids) -> dict:
    """Re-check ``ids`` and glue their boxes (:func:`box`) in the running chapter.

    Parameters
    ----------
    notebook : str
        The chapter's notebook (its stem).
    namespace : mapping
        The chapter's variables (``globals()``), holding its parameters.
    ids : iterable of str
        The entries whose boxes the chapter shows. An entry of this chapter is checked with its
        parameters; an entry of another chapter with that chapter's, at the paper's values.

    Returns
    -------
    dict
        Id -> the :class:`obslib.claims.Record`.
    """
    reg = registry()
    own = {k: namespace[k] for k in defaults(notebook)}
    caveats = robustness.caveats()
    out = {}
    for cid in ids:
        if cid not in reg:
            raise ValueError(f"unknown claim id {cid!r}")
        p = own if reg[cid].notebook == notebook else None
        out[cid] = rec = recheck(cid, p, caveats=caveats)
        glue_text(glue_name(cid), box(rec))
    return out

"""The ledger's machinery: the kinds of entry and their status words, claim registration and
evaluation.

The ledger has two kinds of entry:

``"paper"``
    A claim the paper makes. Its verdict is one of :data:`STATUSES`: ``reproduced`` (it holds
    as stated), ``partly`` (it holds with a correction, or only in part), ``refuted`` (the
    evidence contradicts it as printed) or ``untestable`` (nothing we can compute decides it).
``"beyond"``
    A question this book asks that the paper does not (beyond the paper). It is reported as a
    finding with one of :data:`BEYOND_STATUSES`: ``answered`` (the evidence settles the
    question; the finding says how) or ``open`` (it does not settle it). A beyond entry is never
    a verdict on the paper.

A check returns a :class:`Finding`: the status, one or two sentences saying what we found
(numbers formatted by :mod:`obslib._format`), the raw evidence, and optionally a :class:`Table`
of the numbers behind the sentence.
"""

from __future__ import annotations

import numbers
from collections.abc import Callable
from dataclasses import dataclass, field

from .._validate import as_names, as_str

__all__ = [
    "KINDS",
    "STATUSES",
    "BEYOND_STATUSES",
    "STATUS_WORDS",
    "REQUIRED_IDS",
    "Table",
    "Finding",
    "Claim",
    "Record",
    "claim",
    "registry",
    "evaluate",
]

#: The two kinds of entry: a claim of the paper, or a question of this book beyond the paper.
KINDS = ("paper", "beyond")

#: Verdicts of a claim of the paper. A verdict is a finding, not a target.
STATUSES = ("reproduced", "partly", "refuted", "untestable")

#: Status words of an entry beyond the paper: the question is answered, or still open.
BEYOND_STATUSES = ("answered", "open")

#: Kind -> the status words its entries may take.
STATUS_WORDS = {"paper": STATUSES, "beyond": BEYOND_STATUSES}

#: Ids every ledger must carry; the report lists those not yet audited.
REQUIRED_IDS = (
    "thm1", "thm2", "thm3", "remark1", "thm4", "thm5", "thm6", "thm7-case1", "thm7-case2",
    "thm8-trace", "thm8-logdet", "thm8-rank", "thm8-trace-inverse", "fig2-max",
    "fig6-best-pair", "fig7-entrapment", "fig8-greedy-near-relaxed", "fig9-even",
)  # fmt: skip


@dataclass(frozen=True)
class Table:
    """The numbers behind a finding, shown under its sentence as a numbered table.

    ``caption`` is one sentence (MyST) saying what the table shows; ``columns`` the column
    headers, units included (MyST); ``rows`` one tuple per row, each cell MyST text or a real
    number (printed by :func:`obslib._format.number`).

    Examples
    --------
    >>> t = Table("Greedy over optimum.", ("$L$", "ratio"), [(2, 0.95), (3, 0.9)])
    >>> t.rows
    ((2, 0.95), (3, 0.9))
    >>> Table("x", ("a", "b"), [(1,)])
    Traceback (most recent call last):
    ...
    ValueError: table 'x': row 0 has 1 cells for 2 columns
    """

    caption: str
    columns: tuple
    rows: tuple

    def __post_init__(self):
        cols = tuple(str(c) for c in self.columns)
        if not self.caption or not cols:
            raise ValueError("a table needs a caption and at least one column")
        rows = tuple(tuple(r) for r in self.rows)
        for i, row in enumerate(rows):
            if len(row) != len(cols):
                raise ValueError(f"table {self.caption!r}: row {i} has {len(row)} cells for "
                                 f"{len(cols)} columns")
            for cell in row:
                if isinstance(cell, bool) or not isinstance(cell, (str, numbers.Real)):
                    raise ValueError(f"table {self.caption!r}: cell {cell!r} is neither text nor "
                                     "a number")
        object.__setattr__(self, "columns", cols)
        object.__setattr__(self, "rows", rows)


@dataclass(frozen=True)
class Finding:
    """What a check returns: the ``status``, the sentence ``ours``, the raw ``evidence`` and an
    optional ``table`` of the numbers the sentence summarises."""

    status: str
    ours: str
    evidence: dict = field(default_factory=dict)
    table: Table | None = None

    def __post_init__(self):
        if self.status not in STATUSES + BEYOND_STATUSES:
            raise ValueError(f"status must be one of {STATUSES + BEYOND_STATUSES}, got "
                             f"{self.status!r}")
        if self.table is not None and not isinstance(self.table, Table):
            raise ValueError(f"table must be a Table, got {type(self.table).__name__}")


@dataclass(frozen=True)
class Claim:
    """An entry of the ledger and the function that re-checks it under a profile.

    ``title`` is the claim in words, one line (MyST, math in ``$...$``): the link text wherever
    the entry is linked. ``statement``, ``paper`` and the finding's ``ours`` are full sentences
    in MyST. ``label`` is the MyST target (``(label)=``) that the entry's notebook puts before
    the section showing the evidence. ``kind`` is one of :data:`KINDS`. ``later`` says, where it
    bears on the entry, what the abstract of the paper's later journal version states.
    """

    id: str
    where: str
    statement: str
    paper: str
    notebook: str
    check: Callable[[str], Finding]
    title: str = ""
    label: str = ""
    kind: str = "paper"
    later: str = ""


@dataclass(frozen=True)
class Record:
    """One evaluated entry of the ledger."""

    id: str
    where: str
    statement: str
    paper: str
    ours: str
    status: str
    notebook: str
    evidence: dict
    title: str = ""
    label: str = ""
    kind: str = "paper"
    table: Table | None = None
    later: str = ""


_REGISTRY: dict[str, Claim] = {}


def claim(*, id: str, where: str, statement: str, paper: str, notebook: str, title: str = "",
          label: str = "", kind: str = "paper", later: str = ""):
    """Decorator registering ``check(profile) -> Finding`` as the check of one entry.

    Entries are kept in registration order, which follows the paper (the submodules of
    :mod:`obslib.claims` are imported in section order). ``title`` defaults to ``statement``,
    ``label`` to ``"<id>-evidence"``.
    """
    for name, value in (("id", id), ("where", where), ("statement", statement),
                        ("paper", paper), ("notebook", notebook), ("title", title),
                        ("label", label), ("later", later)):
        as_str(value, name)
    if as_str(kind, "kind") not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")

    def register(check: Callable[[str], Finding]) -> Callable[[str], Finding]:
        if id in _REGISTRY:
            raise ValueError(f"claim id {id!r} registered twice")
        _REGISTRY[id] = Claim(id, where, statement, paper, notebook, check,
                              title or statement, label or f"{id}-evidence", kind, later)
        return check

    return register


def registry() -> dict[str, Claim]:
    """All registered entries, by id, in paper order."""
    return dict(_REGISTRY)


def evaluate(profile: str = "quick", ids=None) -> list[Record]:
    """Re-check the entries under ``profile`` and return one :class:`Record` per entry.

    Parameters
    ----------
    profile : str
        A profile of :mod:`obslib.profiles` (``"paper"`` for the report, ``"quick"`` for tests).
        A status does not depend on it; the numbers may.
    ids : iterable of str, optional
        Only these entries (default: all, in paper order).

    Examples
    --------
    >>> records = evaluate("quick", ids=["thm1", "remark1"])
    >>> [(r.id, r.kind, r.status) for r in records]
    [('thm1', 'paper', 'reproduced'), ('remark1', 'paper', 'reproduced')]
    """
    from ..profiles import profile_names

    if as_str(profile, "profile") not in profile_names():
        raise ValueError(f"unknown profile {profile!r}; known: {profile_names()}")
    claims = registry()
    if ids is not None:
        ids = list(as_names(ids, "ids"))
        unknown = [i for i in ids if i not in claims]
        if unknown:
            raise ValueError(f"unknown claim id(s): {unknown}")
        claims = {i: claims[i] for i in ids}
    out = []
    for c in claims.values():
        f = c.check(profile)
        if f.status not in STATUS_WORDS[c.kind]:
            raise ValueError(f"claim {c.id!r} ({c.kind}) returned status {f.status!r}; a "
                             f"{c.kind} entry takes one of {STATUS_WORDS[c.kind]}")
        out.append(Record(c.id, c.where, c.statement, c.paper, f.ours, f.status, c.notebook,
                          f.evidence, c.title, c.label, c.kind, f.table, c.later))
    return out

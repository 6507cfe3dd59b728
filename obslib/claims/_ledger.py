"""The ledger's machinery: the kinds of entry and their status words, registration, the
parameters a check is a function of, and evaluation.

The ledger has four kinds of entry (:data:`KINDS`):

``"paper"``
    A statement the paper prints. It carries ``quote``, the paper's own words (at least four
    consecutive words of its LaTeX source, math as written there), and a verdict of
    :data:`STATUSES`:

    - ``reproduced``: it holds as printed. A departure of the authors' code from the text that
      changes no conclusion the statement draws is recorded as a ``code`` entry, not against it;
    - ``partly``: it holds only with a correction (a condition added, a quantifier or a number
      changed), or only for part of what it says;
    - ``refuted``: the evidence contradicts it as printed;
    - ``untestable``: nothing we can compute decides it.

    Only these entries are verdicts on the paper and count in its tally.
``"beyond"``
    A question this book asks that the paper does not. Its status is one of
    :data:`BEYOND_STATUSES`: ``answered`` (the evidence settles it; the finding says how) or
    ``open``.
``"code"``
    A finding about the authors' code or their saved runs: ``agrees`` when they do what the
    paper's text says, ``differs`` when they depart from it (the finding says how, and how much
    the departure matters).
``"later"``
    A statement of the authors' later material, which the paper never published (their
    multi-target experiment). It takes the verdicts of :data:`STATUSES`, on that material, never
    on the paper.

A check is a pure function of its parameters: ``check(p) -> Finding``, where ``p`` holds the
parameters of the entry's notebook (:func:`obslib.profiles.params`) and, under the name of each
other notebook the entry ``uses``, that notebook's parameters. :func:`resolve` builds ``p`` for a
profile, :func:`evaluate` checks every entry at a profile, :func:`recheck` one entry with given
parameters (what a chapter's verdict box and the robustness study call).

A :class:`Finding` holds the status, ``summary`` (the one sentence, written as a person would,
that the front page, the report and the chapter's verdict box state about the entry; its
numbers come from the check's one computation), ``ours`` (the full finding, one or two
sentences), the raw ``evidence`` and optionally a :class:`Table` of the numbers behind it.
"""

from __future__ import annotations

import numbers
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from .._validate import as_mapping, as_names, as_str

__all__ = [
    "KINDS",
    "STATUSES",
    "BEYOND_STATUSES",
    "CODE_STATUSES",
    "STATUS_WORDS",
    "QUOTED_KINDS",
    "REQUIRED_IDS",
    "Table",
    "Finding",
    "Claim",
    "Record",
    "claim",
    "registry",
    "resolve",
    "evaluate",
    "recheck",
]

#: The kinds of entry: a statement of the paper, a question of this book, a finding about the
#: authors' code or saved runs, a statement of the authors' later material.
KINDS = ("paper", "beyond", "code", "later")

#: Verdicts of a statement of the paper (and of the later material). A verdict is a finding,
#: not a target.
STATUSES = ("reproduced", "partly", "refuted", "untestable")

#: Status words of an entry beyond the paper: the question is answered, or still open.
BEYOND_STATUSES = ("answered", "open")

#: Status words of a finding about the authors' code or saved runs: they do what the text says,
#: or they depart from it.
CODE_STATUSES = ("agrees", "differs")

#: Kind -> the status words its entries may take.
STATUS_WORDS = {"paper": STATUSES, "beyond": BEYOND_STATUSES, "code": CODE_STATUSES,
                "later": STATUSES}

#: Kinds whose entries quote their source word for word.
QUOTED_KINDS = ("paper",)

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
    number (printed by :func:`obslib.formatting.number`).

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
    """What a check returns.

    ``status`` is a status word of the entry's kind; ``summary`` the one sentence the book
    states about the entry wherever it summarises it (front page, report, verdict box);
    ``ours`` the full finding, one or two sentences (default: the summary); ``evidence`` the
    raw numbers; ``table`` the numbers the sentences summarise.

    Examples
    --------
    >>> f = Finding("reproduced", "It holds in all 10 trials.")
    >>> f.ours
    'It holds in all 10 trials.'
    >>> Finding("reproduced", "It holds. It fails.")
    Traceback (most recent call last):
    ...
    ValueError: summary must be one sentence, got 'It holds. It fails.'
    """

    status: str
    summary: str
    ours: str = ""
    evidence: dict = field(default_factory=dict)
    table: Table | None = None

    def __post_init__(self):
        words = sorted({w for ws in STATUS_WORDS.values() for w in ws})
        if self.status not in words:
            raise ValueError(f"status must be one of {words}, got {self.status!r}")
        summary = " ".join(as_str(self.summary, "summary").split())
        if not summary or not summary.endswith((".", "?")) or _sentences(summary) != 1:
            raise ValueError(f"summary must be one sentence, got {self.summary!r}")
        object.__setattr__(self, "summary", summary)
        object.__setattr__(self, "ours", " ".join(as_str(self.ours, "ours").split()) or summary)
        if self.table is not None and not isinstance(self.table, Table):
            raise ValueError(f"table must be a Table, got {type(self.table).__name__}")


def _sentences(text: str) -> int:
    """How many sentences ``text`` has: full stops outside math, code and parentheses that end
    a word and are followed by a space and a capital or by the end."""
    depth, n, dollar, tick = 0, 0, False, False
    for i, ch in enumerate(text):
        if ch == "`":
            tick = not tick
        elif ch == "$" and not tick:
            dollar = not dollar
        elif dollar or tick:
            continue
        elif ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth = max(0, depth - 1)
        elif ch in ".?" and depth == 0:
            rest = text[i + 1:]
            before = text[:i].split()[-1] if text[:i].split() else ""
            if before in {"e.g", "i.e", "Fig", "Figs", "Eq", "Eqs", "Sec", "Secs", "vs", "al"}:
                continue
            if not rest or (rest[0] == " " and rest[1:2].isupper()):
                n += 1
    return n


@dataclass(frozen=True)
class Claim:
    """An entry of the ledger and the function that re-checks it.

    ``title`` is the claim in words, one line (MyST, math in ``$...$``): the link text wherever
    the entry is linked. ``quote`` is the source's own words (LaTeX as printed; required for a
    statement of the paper), ``statement`` the statement in our words (MyST), ``paper`` what the
    paper offers for it (a proof, a figure, a value). ``notebook`` is the chapter that shows the
    evidence, under the MyST target ``label``; ``uses`` the other notebooks whose parameters the
    check reads. ``journal`` says, where it bears on the entry, what the abstract of the paper's
    later journal version states.
    """

    id: str
    where: str
    statement: str
    paper: str
    notebook: str
    check: Callable[[dict], Finding]
    title: str = ""
    label: str = ""
    kind: str = "paper"
    quote: str = ""
    uses: tuple = ()
    journal: str = ""


@dataclass(frozen=True)
class Record:
    """One evaluated entry of the ledger: the entry's fields and its :class:`Finding`'s.

    ``caveat`` says, in words, where the robustness study finds the verdict changing under a
    change of one parameter of its experiment (empty when it holds, or was not varied); it is
    filled by :func:`evaluate` from the stored study, at the paper's parameters only.
    """

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
    journal: str = ""
    summary: str = ""
    quote: str = ""
    caveat: str = ""


_REGISTRY: dict[str, Claim] = {}


def claim(*, id: str, where: str, statement: str, paper: str, notebook: str, title: str = "",
          label: str = "", kind: str = "paper", quote: str = "", uses=(), journal: str = ""):
    """Decorator registering ``check(p) -> Finding`` as the check of one entry.

    Entries are kept in registration order, which follows the paper (the submodules of
    :mod:`obslib.claims` are imported in section order). ``title`` defaults to ``statement``,
    ``label`` to ``"<id>-evidence"``. An entry of a kind in :data:`QUOTED_KINDS` needs its
    ``quote``.
    """
    for name, value in (("id", id), ("where", where), ("statement", statement),
                        ("paper", paper), ("notebook", notebook), ("title", title),
                        ("label", label), ("quote", quote), ("journal", journal)):
        as_str(value, name)
    if as_str(kind, "kind") not in KINDS:
        raise ValueError(f"kind must be one of {KINDS}, got {kind!r}")
    if kind in QUOTED_KINDS and len(quote.split()) < 4:
        raise ValueError(f"claim {id!r}: a statement of the paper quotes at least four of its "
                         f"words, got quote={quote!r}")
    uses = tuple(as_names(uses, "uses"))

    def register(check: Callable[[dict], Finding]) -> Callable[[dict], Finding]:
        if id in _REGISTRY:
            raise ValueError(f"claim id {id!r} registered twice")
        _REGISTRY[id] = Claim(id, where, statement, paper, notebook, check,
                              title or statement, label or f"{id}-evidence", kind, quote, uses,
                              journal)
        return check

    return register


def registry() -> dict[str, Claim]:
    """All registered entries, by id, in paper order."""
    return dict(_REGISTRY)


def _claim_iv(id) -> Claim:
    claims = registry()
    if as_str(id, "id") not in claims:
        raise ValueError(f"unknown claim id {id!r}")
    return claims[id]


def _profile_iv(profile) -> str:
    from ..profiles import profile_names

    if as_str(profile, "profile") not in profile_names():
        raise ValueError(f"unknown profile {profile!r}; known: {profile_names()}")
    return profile


def resolve(id: str, profile: str = "paper", overrides=None) -> dict:
    """The parameters the check of entry ``id`` is a function of, under ``profile``.

    Parameters
    ----------
    id : str
        An entry of the ledger.
    profile : str
        A profile of :mod:`obslib.profiles`.
    overrides : mapping, optional
        Notebook -> parameters replacing that notebook's (all of them, as a notebook holds
        them; a chapter passes its own).

    Returns
    -------
    dict
        The parameters of the entry's notebook, and under the name of each notebook it
        ``uses``, that notebook's parameters. An entry whose notebook has no parameters gets
        an empty dict.

    Examples
    --------
    >>> resolve("thm1", "quick")["n_scenes"]
    200
    """
    from ..profiles import RANGES, params

    c = _claim_iv(id)
    profile = _profile_iv(profile)
    overrides = {} if overrides is None else dict(as_mapping(overrides, "overrides"))

    def of(nb):
        if nb in overrides:
            return dict(as_mapping(overrides[nb], f"overrides[{nb!r}]"))
        return params(nb, profile) if nb in RANGES else {}

    p = of(c.notebook)
    for nb in c.uses:
        p[nb] = of(nb)
    return p


def _record(c: Claim, f: Finding, caveat: str = "") -> Record:
    if not isinstance(f, Finding):
        raise ValueError(f"claim {c.id!r}: its check returned {type(f).__name__}, not a Finding")
    if f.status not in STATUS_WORDS[c.kind]:
        raise ValueError(f"claim {c.id!r} ({c.kind}) returned status {f.status!r}; a "
                         f"{c.kind} entry takes one of {STATUS_WORDS[c.kind]}")
    return Record(c.id, c.where, c.statement, c.paper, f.ours, f.status, c.notebook,
                  f.evidence, c.title, c.label, c.kind, f.table, c.journal, f.summary, c.quote,
                  caveat)


def recheck(id: str, params: Mapping | None = None, profile: str = "paper",
            caveats: Mapping | None = None) -> Record:
    """Check one entry with its notebook's parameters ``params`` (default: the profile's).

    What a chapter's verdict box calls with the chapter's own parameters, so that a rerun with
    other values shows the verdict those values give. Parameters of the other notebooks the
    entry uses come from ``profile``. ``caveats`` (id -> sentence, from the robustness study)
    are attached only when ``params`` are the profile's own.

    Examples
    --------
    >>> from obslib.profiles import params
    >>> p = params("01_model_and_bound", "quick")
    >>> recheck("remark1", p).status
    'reproduced'
    """
    c = _claim_iv(id)
    base = resolve(id, profile)
    p = base if params is None else resolve(id, profile, {c.notebook: params})
    caveat = (caveats or {}).get(id, "") if p == base else ""
    return _record(c, c.check(p), caveat)


def evaluate(profile: str = "quick", ids=None, caveats: Mapping | None = None) -> list[Record]:
    """Re-check the entries under ``profile`` and return one :class:`Record` per entry.

    Parameters
    ----------
    profile : str
        A profile of :mod:`obslib.profiles` (``"paper"`` for the report, ``"quick"`` for tests).
        A status does not depend on it; the numbers may.
    ids : iterable of str, optional
        Only these entries (default: all, in paper order).
    caveats : mapping, optional
        Id -> the sentence of the robustness study's caveat for that entry
        (:func:`obslib.claims.robustness.caveats`), attached to the records.

    Examples
    --------
    >>> records = evaluate("quick", ids=["thm1", "remark1"])
    >>> [(r.id, r.kind, r.status) for r in records]
    [('thm1', 'paper', 'reproduced'), ('remark1', 'paper', 'reproduced')]
    """
    profile = _profile_iv(profile)
    claims = registry()
    if ids is not None:
        ids = list(as_names(ids, "ids"))
        unknown = [i for i in ids if i not in claims]
        if unknown:
            raise ValueError(f"unknown claim id(s): {unknown}")
        claims = {i: claims[i] for i in ids}
    caveats = {} if caveats is None else as_mapping(caveats, "caveats")
    return [_record(c, c.check(resolve(c.id, profile)), caveats.get(c.id, ""))
            for c in claims.values()]

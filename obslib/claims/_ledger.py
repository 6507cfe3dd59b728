"""The ledger's machinery: claim registration, evaluation and the report table."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

__all__ = [
    "STATUSES",
    "REQUIRED_IDS",
    "ALIASES",
    "Finding",
    "Claim",
    "Record",
    "claim",
    "registry",
    "evaluate",
]

#: A status is a finding, not a target.
STATUSES = ("reproduced", "partly", "refuted", "untestable")

#: Ids every ledger must carry; the report lists those not yet audited.
REQUIRED_IDS = (
    "thm1", "thm2", "thm3", "remark1", "thm4", "thm5", "thm6", "thm7-case1", "thm7-case2",
    "thm8-trace", "thm8-logdet", "thm8-rank", "thm8-trace-inverse", "fig2-max",
    "fig6-best-pair", "fig7-entrapment", "fig8-greedy-near-relaxed", "fig9-even",
)  # fmt: skip


#: Former ids of renamed claims -> current id. The report keeps an anchor under each former id
#: and :func:`evaluate` accepts it, so links and commands written with it keep working.
ALIASES = {
    "erratum-thm1-dual-weyl-range": "thm1-proof-dual-weyl-range",
    "erratum-thm4-matrix": "thm4-proof-matrix",
    "erratum-thm5-dtheta": "thm5-proof-dtheta",
    "erratum-thm5-dalpha-halfpi": "thm5-proof-dalpha-halfpi",
    "erratum-thm5-dalpha": "thm5-proof-dalpha",
}


@dataclass(frozen=True)
class Finding:
    """What a check returns: the ``status``, a one-sentence ``ours`` and the raw ``evidence``."""

    status: str
    ours: str
    evidence: dict = field(default_factory=dict)

    def __post_init__(self):
        if self.status not in STATUSES:
            raise ValueError(f"status must be one of {STATUSES}, got {self.status!r}")


@dataclass(frozen=True)
class Claim:
    """A claim of the paper and the function that re-checks it under a profile.

    ``title`` is the claim in one line (MyST, math in ``$...$``) for the tables; ``statement``,
    ``paper`` and the finding's ``ours`` are full sentences in MyST. ``label`` is the MyST target
    (``(label)=``) that the claim's notebook puts before the section showing the evidence.
    """

    id: str
    where: str
    statement: str
    paper: str
    notebook: str
    check: Callable[[str], Finding]
    title: str = ""
    label: str = ""


@dataclass(frozen=True)
class Record:
    """One evaluated row of the ledger."""

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


_REGISTRY: dict[str, Claim] = {}


def claim(*, id: str, where: str, statement: str, paper: str, notebook: str, title: str = "",
          label: str = ""):
    """Decorator registering ``check(profile) -> Finding`` as the check of one claim.

    Claims are kept in registration order, which follows the paper (the submodules of
    :mod:`obslib.claims` are imported in section order). ``title`` defaults to ``statement``,
    ``label`` to ``"<id>-evidence"``.
    """

    def register(check: Callable[[str], Finding]) -> Callable[[str], Finding]:
        if id in _REGISTRY:
            raise ValueError(f"claim id {id!r} registered twice")
        if id in ALIASES:
            raise ValueError(f"claim id {id!r} is the former id of {ALIASES[id]!r}")
        _REGISTRY[id] = Claim(id, where, statement, paper, notebook, check,
                              title or statement, label or f"{id}-evidence")
        return check

    return register


def registry() -> dict[str, Claim]:
    """All registered claims, by id, in paper order."""
    return dict(_REGISTRY)


def evaluate(profile: str = "quick", ids=None) -> list[Record]:
    """Re-check the claims under ``profile`` and return one :class:`Record` per claim.

    Parameters
    ----------
    profile : str
        A profile of :mod:`obslib.profiles` (``"paper"`` for the report, ``"quick"`` for tests).
    ids : iterable of str, optional
        Only these claims (default: all, in paper order). A former id (:data:`ALIASES`) stands
        for the current one.

    Examples
    --------
    >>> [(r.id, r.status) for r in evaluate("quick", ids=["thm1", "remark1"])]
    [('thm1', 'reproduced'), ('remark1', 'reproduced')]
    """
    from ..profiles import profile_names

    if profile not in profile_names():
        raise ValueError(f"unknown profile {profile!r}; known: {profile_names()}")
    claims = registry()
    if ids is not None:
        ids = [ALIASES.get(i, i) for i in ids]
        unknown = [i for i in ids if i not in claims]
        if unknown:
            raise ValueError(f"unknown claim id(s): {unknown}")
        claims = {i: claims[i] for i in ids}
    out = []
    for c in claims.values():
        f = c.check(profile)
        out.append(Record(c.id, c.where, c.statement, c.paper, f.ours, f.status, c.notebook,
                          f.evidence, c.title, c.label))
    return out

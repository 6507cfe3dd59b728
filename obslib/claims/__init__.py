"""The claims ledger: one entry per statement of the paper (and per question of this book, per
finding about the authors' code, per statement of their later material), each with a function
that re-checks it.

>>> import obslib.claims as claims
>>> records = claims.evaluate(profile="quick")          # doctest: +SKIP
>>> {r.id: r.status for r in records}["thm1"]            # doctest: +SKIP
'reproduced'

Each record has ``id``, ``kind`` (one of :data:`KINDS`), ``where``, ``title``, ``quote``,
``statement``, ``paper``, ``summary``, ``ours``, ``status``, ``caveat``, ``notebook``,
``label``, ``evidence`` and ``table``. A statement of the paper has a verdict of
:data:`STATUSES`; the other kinds have their own status words (:data:`STATUS_WORDS`; see
:mod:`obslib.claims._ledger`). A status never depends on the profile. A check is a pure function
of its parameters: :func:`resolve` gives them for a profile, :func:`recheck` checks one entry
with a chapter's own. The book's reproduction report is rendered from :func:`evaluate` at the
``paper`` profile by the book's own tooling (``python -m obsbook.report``);
:mod:`obslib.claims.robustness` varies the experiments' parameters one at a time.

Entries live in one submodule per chapter, named after its notebook without its number
(:mod:`obslib.claims.model_and_bound`, ...), imported below in paper order.
"""

from .._validate import as_instance, as_sequence
from ._ledger import (
    BEYOND_STATUSES,
    CODE_STATUSES,
    KINDS,
    QUOTED_KINDS,
    REQUIRED_IDS,
    STATUS_WORDS,
    STATUSES,
    Claim,
    Finding,
    Record,
    Table,
    claim,
    evaluate,
    recheck,
    registry,
    resolve,
)

# Registration order is paper order (kept out of the import sorting).
# isort: off
from . import model_and_bound  # noqa: E402,F401  Sec. II-III: Theorems 1-3, Remarks 1-2
from . import pair_closed_form  # noqa: E402,F401  Sec. III (pair): Theorems 4-5, Fig. 2, errata
from . import greedy_unique_pairs  # noqa: E402,F401  Sec. IV-A: Algorithm 1, Theorem 6
from . import submodularity  # noqa: E402,F401  Sec. IV-B: Theorems 7-8
from . import two_sensors_tracking  # noqa: E402,F401  Sec. V-A: Figs. 4-6
from . import adversarial_target  # noqa: E402,F401  Sec. V-B: Fig. 7
from . import greedy_vs_relaxed  # noqa: E402,F401  Sec. V-C: Fig. 8
from . import general_assignment  # noqa: E402,F401  Sec. V-D: Fig. 9, greedy teams
from . import replay  # noqa: E402,F401  Sec. V-A/B: the published runs replayed
from . import unchecked_statements  # noqa: E402,F401  statements the paper does not check
from . import misprints  # noqa: E402,F401  the misprints and a citation of the paper
from . import many_targets  # noqa: E402,F401  the authors' later experiment, many targets
from . import criteria  # noqa: E402,F401  beyond the paper: the bound against classical criteria
# isort: on

__all__ = [
    "KINDS",
    "STATUSES",
    "BEYOND_STATUSES",
    "CODE_STATUSES",
    "QUOTED_KINDS",
    "STATUS_WORDS",
    "REQUIRED_IDS",
    "Claim",
    "Finding",
    "Record",
    "Table",
    "claim",
    "evaluate",
    "recheck",
    "registry",
    "resolve",
    "as_json",
]


def as_json(records) -> list[dict]:
    """The records as JSON-ready dicts (what ``python -m obslib.claims --json`` prints): every
    field, the table as ``{"caption", "columns", "rows"}`` or ``None``.

    Examples
    --------
    >>> (d,) = as_json(evaluate("quick", ids=["thm1"]))
    >>> d["id"], d["kind"], d["status"]
    ('thm1', 'paper', 'reproduced')
    """
    from dataclasses import asdict

    records = as_sequence(records, "records")
    for r in records:
        as_instance(r, Record, "each of records")
    return [asdict(r) for r in records]

"""The claims ledger: one record per claim of the paper, each with a function that re-checks it.

>>> import obslib.claims as claims
>>> records = claims.evaluate(profile="quick")          # doctest: +SKIP
>>> {r.id: r.status for r in records}["thm1"]            # doctest: +SKIP
'reproduced'

Each record has ``id``, ``where``, ``statement``, ``paper``, ``ours``, ``status`` (one of
``reproduced``, ``partly``, ``refuted``, ``untestable``), ``notebook`` and ``evidence``.
The book's reproduction report is rendered from :func:`evaluate` at the ``paper`` profile
(``python -m obslib.claims --profile paper --write book/report.md``).

Claims live in one submodule per section of the paper, imported below in paper order.
"""

from ._ledger import REQUIRED_IDS, STATUSES, Claim, Finding, Record, claim, evaluate, registry
from .report import render_report

# Registration order is paper order.
from . import section3  # noqa: E402,F401  Sec. II-III: Theorems 1-3, Remarks 1-2
from . import pair_form  # noqa: E402,F401  Sec. III (pair): Theorems 4-5, Fig. 2, errata
from . import assignment  # noqa: E402,F401  Sec. IV-A: Algorithm 1, Theorem 6
from . import submodularity  # noqa: E402,F401  Sec. IV-B: Theorems 7-8
from . import tracking  # noqa: E402,F401  Sec. V-A/B: Figs. 4-7
from . import greedy_vs_relaxed  # noqa: E402,F401  Sec. V-C: Fig. 8
from . import teams  # noqa: E402,F401  Sec. V-D: Fig. 9, greedy teams
from . import replay  # noqa: E402,F401  Sec. V-A/B: the published runs replayed
from . import unchecked  # noqa: E402,F401  statements the paper does not check
from . import criteria  # noqa: E402,F401  beyond the paper: the bound against classical criteria

__all__ = [
    "STATUSES",
    "REQUIRED_IDS",
    "Claim",
    "Finding",
    "Record",
    "claim",
    "evaluate",
    "registry",
    "render_report",
]

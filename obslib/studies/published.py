"""The numbers the paper publishes, in one place, for the studies and the ledger to compare with,
when one of ours counts as matching one of them, and the history of the repository that holds the
code of its simulations."""

from __future__ import annotations

import csv
from functools import lru_cache
from importlib import resources

import numpy as np

from .._validate import as_float_array, as_nonnegative, as_real

__all__ = ["THEOREM7_PRINTED", "THEOREM7_PRINTED_WITNESS", "FIG8_PUBLISHED_L20",
           "PUBLISHED_CIRCLE", "PUBLISHED_ADVERSARIAL", "FIGURE_TOLERANCE", "near_published",
           "CODE_URL_PRINTED", "CODE_REPOSITORY", "CODE_ACCOUNT_PRINTED", "code_commits"]

#: Values printed in the proof of Theorem 7 (0-based sensor indices).
THEOREM7_PRINTED = {
    "case1": {(0, 2): 0.5345, (0, 1, 2): 0.1823},
    "case2": {(0, 1, 2): 0.3310, (0, 1): 0.5345, (0, 1, 2, 3): 0.8765, (0, 1, 3): 0.9258},
}
#: The comparison each case prints. Case 1 ``omega({s1,s3}) > omega({s1,s2,s3})`` (a
#: monotonicity witness ``A = {s1, s3}``, ``x = s2``); Case 2 ``omega({s1,s2,s3}) -
#: omega({s1,s2}) < omega({s1,s2,s4,s3}) - omega({s1,s2,s4})`` (a submodularity witness
#: ``A = {s1, s2}``, ``B = {s1, s2, s4}``, ``x = s3``).
THEOREM7_PRINTED_WITNESS = {
    "case1": {"A": (0, 2), "x": 1},
    "case2": {"A": (0, 1), "B": (0, 1, 3), "x": 2},
}

#: Fig. 8's published means at L = 20 (read off the figure's data).
FIG8_PUBLISHED_L20 = {"relaxed": 18.95, "greedy": 16.52}


#: Pair changes over 314 transitions and run means, per strategy, of the published Figs. 4-6 run.
PUBLISHED_CIRCLE = {
    "best-pair": {"switches": 148, "mean_bound": 0.73, "mean_error": 0.16, "mean_trace": 0.073},
    "best-partner": {"switches": 102, "mean_bound": 0.49, "mean_error": 0.19, "mean_trace": 0.140},
    "fixed-pair": {"switches": 0, "mean_bound": 0.27, "mean_error": 0.22, "mean_trace": 0.217},
}

#: Mean bound and pair changes over 314 transitions of the published Fig. 7 run.
PUBLISHED_ADVERSARIAL = {"mean_bound": 0.79, "switches": 306, "transitions": 314}

#: A published figure number counts as matched when ours is within this relative distance.
FIGURE_TOLERANCE = 0.15


def near_published(ours, published, rtol: float = FIGURE_TOLERANCE):
    """Whether our value(s) lie within ``rtol`` (relative) of a published number; a published
    zero must be matched exactly.

    Examples
    --------
    >>> near_published([0.70, 0.60], 0.79).tolist()
    [True, False]
    """
    ours = as_float_array(ours, "ours")
    published, rtol = as_real(published, "published"), as_nonnegative(rtol, "rtol")
    if published == 0:
        return ours == 0
    return np.abs(ours - published) <= rtol * abs(published)


#: The address of the simulations' code printed in the paper's footnote (Sec. V), and the
#: repository where that code and the saved runs of Figs. 4-7 are found today.
CODE_URL_PRINTED = "https://github.com/lovetuliper/observability-based-sensor-assignment.git"
CODE_REPOSITORY = "lfzhou917/observability-based-sensor-assignment"

#: The GitHub account the printed address names.
CODE_ACCOUNT_PRINTED = CODE_URL_PRINTED.split("github.com/", 1)[1].split("/", 1)[0]


def code_commits() -> tuple:
    """The commits of :data:`CODE_REPOSITORY`, newest first, as stored with the package
    (``obslib/data/code_repository/commits.csv``, whose header says how they were read): one
    ``(commit, author_date, author)`` per commit, the date in ISO 8601.

    Examples
    --------
    >>> from obslib.studies.published import code_commits
    >>> commits = code_commits()
    >>> len(commits), commits[-1][1][:10], commits[0][1][:10]
    (10, '2017-09-06', '2018-01-30')
    >>> sorted({author for _, _, author in commits})
    ['lovetuliper']
    """
    return _code_commits()


@lru_cache(maxsize=1)
def _code_commits() -> tuple:
    path = resources.files("obslib").joinpath("data", "code_repository", "commits.csv")
    lines = [ln for ln in path.read_text().splitlines() if ln and not ln.startswith("#")]
    rows = list(csv.reader(lines))
    if rows[0] != ["commit", "author_date", "author"] or any(len(r) != 3 for r in rows[1:]):
        raise ValueError(f"{path}: not a commit list (commit, author_date, author)")
    return tuple(tuple(r) for r in rows[1:])

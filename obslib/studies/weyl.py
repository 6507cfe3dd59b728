"""Audits of the Weyl step of Theorem 1's proof for 2x2 symmetric matrices: Eqs. (18)-(19) and the
appendix's range of the dual Weyl inequality (notebook 02, claims of
:mod:`obslib.claims.pair_closed_form`)."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .._validate import as_int
from ..pair_form import random_symmetric_2x2, weyl_2x2_slacks

__all__ = ["dual_weyl_printed_range", "WeylAudit", "weyl_audit"]


def dual_weyl_printed_range(r: int = 2) -> list[tuple[int, int, int]]:
    """Pairs ``(i, j)`` admitted by the appendix's range for the dual Weyl inequality
    (``i, j >= 1``, ``i + j - r <= r``, indices at most ``r``), with the index ``i + j - r``.

    Returns ``[(i, j, i + j - r), ...]``; entries with index ``< 1`` are meaningless
    (``lambda_0`` does not exist): the correct range is ``i + j - r >= 1``.

    Examples
    --------
    >>> dual_weyl_printed_range(2)
    [(1, 1, 0), (1, 2, 1), (2, 1, 1), (2, 2, 2)]
    """
    r = as_int(r, "r", 1)
    return [(i, j, i + j - r) for i in range(1, r + 1) for j in range(1, r + 1) if i + j - r <= r]


_WEYL_NAMES = (
    "l1 >= l1+l1", "l1 <= l1+l2", "l1 <= l2+l1", "l2 <= l2+l2", "l2 >= l1+l2", "l2 >= l2+l1",
)


@dataclass(frozen=True)
class WeylAudit:
    """The Weyl inequalities of the proof of Theorem 1 for 2x2 symmetric matrices."""

    symbolic_triangle_equal: dict  #: name -> slack - triangle form expands to 0
    n_pairs: int
    #: name -> smallest slack / :math:`(\|X\| + \|Y\|)` over random pairs (at least
    #: :math:`-10^{-15}`)
    min_relative_slack: dict
    min_ratio_slack: float  #: Eq. (19) over random PSD pairs
    printed_range: tuple  #: (i, j, index) admitted by the printed dual-Weyl range for r = 2
    invalid_indices: tuple  #: those with index < 1


def weyl_audit(n_pairs: int, seed: int) -> WeylAudit:
    """Symbolic (triangle inequality) and random checks of Eqs. (18)-(19) for 2x2 matrices.

    Examples
    --------
    >>> a = weyl_audit(n_pairs=200, seed=0)
    >>> (all(a.symbolic_triangle_equal.values()),
    ...  min(a.min_relative_slack.values()) >= -1e-14)
    (True, True)
    >>> a.invalid_indices
    ((1, 1, 0),)
    """
    return _weyl_audit(as_int(n_pairs, "n_pairs", 1), as_int(seed, "seed", 0))


@lru_cache(maxsize=4)
def _weyl_audit(n_pairs, seed):
    import sympy as sp

    from .. import symbolic

    n = as_int(n_pairs, "n_pairs", 1)
    sym = {k: bool(sp.expand(s - t) == 0) for k, (s, t) in symbolic.weyl_2x2_slacks().items()}
    X = random_symmetric_2x2(n, seed)
    Y = random_symmetric_2x2(n, seed + 1)
    norm = np.abs(np.linalg.eigvalsh(X)).max(axis=-1) + np.abs(np.linalg.eigvalsh(Y)).max(axis=-1)
    sl = weyl_2x2_slacks(X, Y)
    rel = {k: float((sl[k] / norm).min()) for k in _WEYL_NAMES}
    P = random_symmetric_2x2(n, seed + 2, psd=True)
    R = random_symmetric_2x2(n, seed + 3, psd=True)
    ratio = weyl_2x2_slacks(P, R)["ratio"]
    rng_ = tuple(dual_weyl_printed_range(2))
    return WeylAudit(sym, n, rel, float(np.nanmin(ratio)), rng_, tuple(t for t in rng_ if t[2] < 1))

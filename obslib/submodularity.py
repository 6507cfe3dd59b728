r"""Monotonicity and submodularity of set functions, exhaustively, with the smallest witness.

Section IV-B of the paper needs, for the greedy 1/2-approximation of Problem 2, a sensor-set
function :math:`f` that is

* **monotone increasing**: :math:`f(A) \le f(A + x)` for every set :math:`A` and sensor
  :math:`x`;
* **submodular** (diminishing returns): :math:`f(A + x) - f(A) \ge f(B + x) - f(B)` for all
  :math:`A \subseteq B` and :math:`x \notin B`.

Theorem 7 says Theorem 1's lower bound :math:`\omega(S)` is neither, by two counter-examples
(Cases 1 and 2, Fig. 3); Theorem 8 says four measures of :math:`O^T O` are both
(:mod:`obslib.measures`). This module decides such claims by brute force over a small ground
set (:math:`N \le 10`): every subset is evaluated **once** into a table of :math:`2^N` values,
and all additions :math:`(A, x)` and all nested triples :math:`(A, B, x)` are compared at once
with NumPy (fewer than :math:`N 3^{N-1}` triples: 191 710 for :math:`N = 10`). For thousands of
random instances, :func:`audit_flags` reaches the same verdicts (and the size of each smallest
witness) with a min / max sum-over-subsets transform of the gains instead of every triple; the
random audits use it and run the full comparison only on the instance whose witness they report.

Conventions
-----------
Subsets.
    Elements are the indices ``0 .. N-1`` of the ground set. The set function is called with
    a sorted tuple of indices (``()`` for the empty set). Internally subset ``k`` of the table
    is the set of bits of ``k`` (:func:`obslib.measures.subset_masks`).
Smallest sets compared, ``min_size``.
    Only sets with at least ``min_size`` elements enter a comparison (``A`` and hence ``B``,
    ``A + x``, ``B + x``). With ``min_size = 0`` the whole lattice is used, the empty set
    included. Theorem 1 is stated for ``N >= 2`` and the bound is 0 for fewer sensors
    (Theorem 2), so ``omega`` *trivially* breaks submodularity at the bottom of the lattice
    (``omega(x) - omega({}) = 0 < omega({y, x}) - omega({y})``); ``min_size = 2`` asks the
    meaningful question, among sets on which Theorem 1 is defined. Values of smaller sets are
    not evaluated.
Tolerance.
    A difference counts only beyond ``tol = rtol * max |f| + atol`` (over the compared sets;
    defaults ``1e-9`` and ``1e-12``), so rounding never makes a witness: a modular function
    such as the trace shows neither violation.
Order of witnesses (documented, deterministic).
    Subsets are compared as sorted index tuples, lexicographically (Python tuple order, so
    ``(0,) < (0, 1) < (1,)``). A monotonicity witness ``(A, x)`` has ``f(A + x) < f(A) - tol``;
    the smallest is the one with the smallest ``|A + x|``, then the smallest ``A + x``, then the
    smallest ``A``. A submodularity witness ``(A, B, x)``, ``A`` a proper subset of ``B``,
    ``x`` not in ``B``, has ``f(B + x) - f(B) > f(A + x) - f(A) + tol``; the smallest has the
    smallest ``|B|``, then the smallest ``B``, then ``A``, then ``x``. All nested pairs
    ``A`` proper subset of ``B`` are compared, not only single steps ``B = A + y``, so the
    counts are complete. (A violation along a chain has a violating single step inside it, so
    the smallest ``|B|`` is the same either way.)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import asdict, dataclass
from functools import cache
from numbers import Real

import numpy as np

from ._validate import (
    as_callable,
    as_float_array,
    as_int,
    as_nonnegative,
    as_points,
    check_distinct,
)
from .measures import subset_masks

__all__ = [
    "MAX_GROUND_SET",
    "MonotonicityWitness",
    "SubmodularityWitness",
    "SetFunctionAudit",
    "set_function_table",
    "audit_set_function",
    "audit_tables",
    "audit_flags",
    "TableFlags",
    "table_values",
]

#: Largest ground set the exhaustive check accepts.
MAX_GROUND_SET = 10
RTOL = 1e-9
ATOL = 1e-12


# ---------------------------------------------------------------------------------------------
# enumeration
# ---------------------------------------------------------------------------------------------


def _members(mask: int, n: int) -> tuple:
    return tuple(i for i in range(n) if (mask >> i) & 1)


@cache
def _lex_rank(n: int) -> np.ndarray:
    """Rank of each bitmask among all subsets ordered as sorted tuples, lexicographically."""
    order = sorted(range(2**n), key=lambda m: _members(m, n))
    rank = np.empty(2**n, dtype=np.int64)
    rank[order] = np.arange(2**n)
    return rank


@cache
def _popcount(n: int) -> np.ndarray:
    return subset_masks(n).sum(axis=1)


@cache
def _additions(n: int, min_size: int):
    """All ``(A, x)``, ``x`` not in ``A``, ``|A| >= min_size``, in witness order."""
    pc, lex = _popcount(n), _lex_rank(n)
    a = np.repeat(np.arange(2**n), n)
    x = np.tile(np.arange(n), 2**n)
    keep = (((a >> x) & 1) == 0) & (pc[a] >= min_size)
    a, x = a[keep], x[keep]
    ax = a | (1 << x)
    order = np.lexsort((lex[a], lex[ax], pc[ax]))
    return a[order], x[order]


@cache
def _triples(n: int, min_size: int):
    """All ``(A, B, x)``, ``A`` proper subset of ``B``, ``x`` not in ``B``, in witness order."""
    pc, lex = _popcount(n), _lex_rank(n)
    codes = np.arange(3**n)
    digits = (codes[:, None] // 3 ** np.arange(n)[None, :]) % 3  # 0: out of B, 1: B \ A, 2: A
    bits = 1 << np.arange(n)
    a = (digits == 2) @ bits
    b = (digits >= 1) @ bits
    out = digits == 0  # candidates for x
    rows, x = np.nonzero(out)
    a, b = a[rows], b[rows]
    keep = (pc[a] >= min_size) & (a != b)
    a, b, x = a[keep], b[keep], x[keep]
    order = np.lexsort((x, lex[a], lex[b], pc[b]))
    return a[order], b[order], x[order]


def _ground_size(ground) -> int:
    if isinstance(ground, (int, np.integer)) and not isinstance(ground, bool):
        n = int(ground)
        if n < 0:
            raise ValueError(f"ground set size must be non-negative, got {n}")
    else:
        pts = as_points(ground, "sensors")
        check_distinct(pts)
        n = pts.shape[0]
    if n > MAX_GROUND_SET:
        raise ValueError(f"ground set of {n} elements is too large for the exhaustive check "
                         f"(max {MAX_GROUND_SET})")
    return n


def _min_size_iv(min_size, n: int) -> int:
    min_size = as_int(min_size, "min_size", 0)
    if min_size > n:
        raise ValueError(f"min_size {min_size} exceeds the ground set size {n}")
    return int(min_size)


# ---------------------------------------------------------------------------------------------
# witnesses and the audit
# ---------------------------------------------------------------------------------------------


def _num(v: float, digits: int) -> str:
    """A value for a difference ``a - b``: negative values in parentheses."""
    return f"({v:.{digits}f})" if v < 0 else f"{v:.{digits}f}"


def _fmt_set(s: tuple, labels) -> str:
    if labels is None:
        return "{" + ", ".join(str(i) for i in s) + "}"
    return "{" + ", ".join(labels[i] for i in s) + "}"


@dataclass(frozen=True)
class MonotonicityWitness:
    """``f(A + x) < f(A)``: adding ``x`` to ``A`` lowers the value (0-based indices)."""

    A: tuple
    x: int
    f_A: float
    f_Ax: float

    @property
    def B(self) -> tuple:
        """``A + x``."""
        return tuple(sorted(self.A + (self.x,)))

    @property
    def gain(self) -> float:
        return self.f_Ax - self.f_A

    def describe(self, labels=None, digits: int = 4) -> str:
        lab = (lambda i: labels[i]) if labels is not None else str
        return (f"f({_fmt_set(self.B, labels)}) = {self.f_Ax:.{digits}f} < "
                f"f({_fmt_set(self.A, labels)}) = {self.f_A:.{digits}f}: adding {lab(self.x)} "
                f"changes f by {self.gain:+.{digits}f}")

    def as_dict(self) -> dict:
        d = asdict(self)
        d.update(A=list(self.A), B=list(self.B), gain=self.gain)
        return d


@dataclass(frozen=True)
class SubmodularityWitness:
    """``f(B + x) - f(B) > f(A + x) - f(A)`` with ``A`` a proper subset of ``B``, ``x`` not in
    ``B``."""

    A: tuple
    B: tuple
    x: int
    f_A: float
    f_Ax: float
    f_B: float
    f_Bx: float

    @property
    def gain_A(self) -> float:
        """Marginal gain of ``x`` at the smaller set, ``f(A + x) - f(A)``."""
        return self.f_Ax - self.f_A

    @property
    def gain_B(self) -> float:
        """Marginal gain of ``x`` at the larger set, ``f(B + x) - f(B)``."""
        return self.f_Bx - self.f_B

    def describe(self, labels=None, digits: int = 4) -> str:
        lab = (lambda i: labels[i]) if labels is not None else str
        A, B = _fmt_set(self.A, labels), _fmt_set(self.B, labels)
        d = digits
        return (f"gain of {lab(self.x)} at A = {A}: {_num(self.f_Ax, d)} - {_num(self.f_A, d)} "
                f"= {self.gain_A:+.{d}f} < gain at B = {B}: {_num(self.f_Bx, d)} - "
                f"{_num(self.f_B, d)} = {self.gain_B:+.{d}f}")

    def as_dict(self) -> dict:
        d = asdict(self)
        d.update(A=list(self.A), B=list(self.B), gain_A=self.gain_A, gain_B=self.gain_B)
        return d


@dataclass(frozen=True)
class SetFunctionAudit:
    """Exhaustive check of one set function over a ground set of ``n`` elements.

    Counts are over all additions ``(A, x)`` and all nested triples ``(A, B, x)`` among sets
    of at least ``min_size`` elements; witnesses are the smallest in the documented order.
    """

    n: int
    min_size: int
    tol: float
    n_additions: int  #: pairs ``(A, x)`` compared
    n_decreases: int  #: ``f(A + x) < f(A) - tol``
    n_increases: int  #: ``f(A + x) > f(A) + tol``
    n_triples: int  #: triples ``(A, B, x)`` compared
    n_submodular_violations: int  #: gain at ``B`` exceeds gain at ``A`` by more than ``tol``
    n_supermodular_violations: int  #: gain at ``A`` exceeds gain at ``B`` by more than ``tol``
    max_decrease: float  #: largest ``f(A) - f(A + x)`` (negative: strictly increasing)
    max_excess: float  #: largest ``gain_B - gain_A`` (positive: not submodular)
    monotone_witness: MonotonicityWitness | None  #: smallest decrease
    increase_witness: MonotonicityWitness | None  #: smallest increase (breaks "decreasing")
    submodular_witness: SubmodularityWitness | None  #: smallest violation of submodularity

    @property
    def monotone_increasing(self) -> bool:
        return self.n_decreases == 0

    @property
    def monotone_decreasing(self) -> bool:
        return self.n_increases == 0

    @property
    def submodular(self) -> bool:
        return self.n_submodular_violations == 0

    @property
    def supermodular(self) -> bool:
        return self.n_supermodular_violations == 0

    @property
    def modular(self) -> bool:
        return self.submodular and self.supermodular

    def as_dict(self) -> dict:
        out = {k: getattr(self, k) for k in (
            "n", "min_size", "tol", "n_additions", "n_decreases", "n_increases", "n_triples",
            "n_submodular_violations", "n_supermodular_violations", "max_decrease", "max_excess",
            "monotone_increasing", "monotone_decreasing", "submodular", "modular")}
        for k in ("monotone_witness", "increase_witness", "submodular_witness"):
            w = getattr(self, k)
            out[k] = None if w is None else w.as_dict()
        return out


def set_function_table(ground, f: Callable[[tuple], float], min_size: int = 0) -> np.ndarray:
    """Evaluate ``f`` once on every subset with at least ``min_size`` elements.

    Parameters
    ----------
    ground : int or array_like, shape (N, 2)
        The ground set: its size, or the sensors themselves (validated: finite, distinct).
    f : callable
        ``f(idx) -> float`` for a sorted tuple of indices ``idx``.
    min_size : int
        Smaller sets are not evaluated (their entries are NaN).

    Returns
    -------
    ndarray, shape (2**N,)
        ``table[k]`` is ``f`` of the set of bits of ``k``.

    Raises
    ------
    ValueError
        If ``f`` returns something that is not a finite real number (the message names the set).

    Examples
    --------
    Coverage of two elements (the empty set is worth 0, any other 1):

    >>> set_function_table(2, lambda s: float(len(s) > 0))
    array([0., 1., 1., 1.])
    """
    n, f, m = _set_function_table_iv(ground, f, min_size)
    pc = _popcount(n)
    out = np.full(2**n, np.nan)
    for k in range(2**n):
        if pc[k] < m:
            continue
        idx = _members(k, n)
        v = f(idx)
        if isinstance(v, np.ndarray) and v.shape == ():
            v = v.item()
        if not isinstance(v, Real) or isinstance(v, bool) or not np.isfinite(v):
            raise ValueError(f"f{idx} = {v!r} is not a finite real number")
        out[k] = float(v)
    return out


def _set_function_table_iv(ground, f, min_size) -> tuple:
    """The ground set's size, a function, and ``0 <= min_size <= N``."""
    n = _ground_size(ground)
    m = _min_size_iv(min_size, n)
    return n, as_callable(f, "f"), m


def _tables_iv(values, n: int, min_size: int, rtol: float, atol: float):
    """The arguments of :func:`audit_tables` and :func:`audit_flags`: ``n``, ``min_size``, the
    tables ``(I, 2**N)`` (finite on the sets compared) and each table's tolerance
    ``rtol * max |f| + atol``."""
    n = _ground_size(as_int(n, "n", 0))
    m = _min_size_iv(min_size, n)
    rtol, atol = as_nonnegative(rtol, "rtol"), as_nonnegative(atol, "atol")
    v = as_float_array(values, "values")
    if v.ndim == 1:
        v = v[None, :]
    if v.ndim != 2 or v.shape[1] != 2**n:
        raise ValueError(f"values must have shape (I, {2**n}), got {np.shape(values)}")
    if not (rtol >= 0 and atol >= 0):
        raise ValueError("rtol and atol must be non-negative")
    used = _popcount(n) >= m
    vu = v if used.all() else v[:, used]
    if vu.shape[1] == 0:
        return n, m, v, np.full(v.shape[0], float(atol))
    # max and min propagate NaN and keep +-inf, so they also decide finiteness in one pass each
    hi, lo = vu.max(axis=1), vu.min(axis=1)
    if not (np.isfinite(hi).all() and np.isfinite(lo).all()):
        i, j = (int(t) for t in np.argwhere(~np.isfinite(vu))[0])
        k = int(np.flatnonzero(used)[j])
        raise ValueError(f"table {i}: value of set {_members(k, n)} is {v[i, k]}, not finite "
                         "(raise min_size or regularise the function)")
    tol = rtol * np.maximum(hi, -lo) + atol  # rtol * max |f| + atol
    return n, m, v, tol


def audit_tables(values, n: int, min_size: int = 0, rtol: float = RTOL,
                 atol: float = ATOL) -> list[SetFunctionAudit]:
    """Vectorised audit of many set functions given as tables, one row each.

    Parameters
    ----------
    values : array_like, shape (I, 2**n) or (2**n,)
        Tables as made by :func:`set_function_table`, :func:`lower_bound_tables` or
        :func:`obslib.measures.measure_from_vectors`; entries of sets below ``min_size`` are
        ignored.
    n : int
        Ground set size.
    min_size, rtol, atol
        See the module docstring.

    Returns
    -------
    list of SetFunctionAudit

    Examples
    --------
    A modular table (the size of the set) and a coverage table, audited at once:

    >>> modular, coverage = audit_tables([[0, 1, 1, 2], [0, 1, 1, 1]], n=2)
    >>> modular.modular, coverage.submodular, coverage.supermodular
    (True, True, False)
    """
    n, m, v, tol = _tables_iv(values, n, min_size, rtol, atol)
    pa, px = _additions(n, m)
    ta, tb, tx = _triples(n, m)
    pax = pa | (1 << px)
    tax, tbx = ta | (1 << tx), tb | (1 << tx)
    n_i = v.shape[0]
    res = {k: np.zeros(n_i, dtype=np.int64) for k in ("dec", "inc", "sub", "sup")}
    first = {k: np.full(n_i, -1, dtype=np.int64) for k in ("dec", "inc", "sub")}
    max_dec = np.full(n_i, -np.inf)
    max_ex = np.full(n_i, -np.inf)
    chunk = max(1, 4_000_000 // max(1, len(ta) + len(pa)))
    for s in range(0, n_i, chunk):
        vv, tt = v[s:s + chunk], tol[s:s + chunk, None]
        sl = slice(s, s + vv.shape[0])
        if len(pa):
            g = vv[:, pax] - vv[:, pa]
            for key, viol in (("dec", g < -tt), ("inc", g > tt)):
                res[key][sl] = viol.sum(axis=1)
                first[key][sl] = np.where(viol.any(axis=1), viol.argmax(axis=1), -1)
            max_dec[sl] = (-g).max(axis=1)
        if len(ta):
            ex = (vv[:, tbx] - vv[:, tb]) - (vv[:, tax] - vv[:, ta])
            sub = ex > tt
            res["sub"][sl] = sub.sum(axis=1)
            res["sup"][sl] = (ex < -tt).sum(axis=1)
            first["sub"][sl] = np.where(sub.any(axis=1), sub.argmax(axis=1), -1)
            max_ex[sl] = ex.max(axis=1)

    out = []
    for i in range(n_i):
        row = v[i]

        def mono(j):
            if j < 0:
                return None
            a, x = int(pa[j]), int(px[j])
            return MonotonicityWitness(_members(a, n), x, float(row[a]), float(row[a | (1 << x)]))

        j = int(first["sub"][i])
        sw = None
        if j >= 0:
            a, b, x = int(ta[j]), int(tb[j]), int(tx[j])
            sw = SubmodularityWitness(_members(a, n), _members(b, n), x, float(row[a]),
                                      float(row[a | (1 << x)]), float(row[b]),
                                      float(row[b | (1 << x)]))
        out.append(
            SetFunctionAudit(
                n=n,
                min_size=m,
                tol=float(tol[i]),
                n_additions=len(pa),
                n_decreases=int(res["dec"][i]),
                n_increases=int(res["inc"][i]),
                n_triples=len(ta),
                n_submodular_violations=int(res["sub"][i]),
                n_supermodular_violations=int(res["sup"][i]),
                max_decrease=float(max_dec[i]),
                max_excess=float(max_ex[i]),
                monotone_witness=mono(int(first["dec"][i])),
                increase_witness=mono(int(first["inc"][i])),
                submodular_witness=sw,
            )
        )
    return out


@dataclass(frozen=True)
class TableFlags:
    """Per-table verdicts of :func:`audit_flags` (arrays of shape ``(I,)``)."""

    tol: np.ndarray  #: the tolerance of each table, as in :func:`audit_tables`
    decreases: np.ndarray  #: some ``f(A + x) < f(A) - tol`` (not monotone increasing)
    increases: np.ndarray  #: some ``f(A + x) > f(A) + tol`` (not monotone decreasing)
    not_submodular: np.ndarray  #: some triple with ``gain_B > gain_A + tol``
    not_supermodular: np.ndarray  #: some triple with ``gain_B < gain_A - tol``
    monotone_witness_size: np.ndarray  #: ``|A + x|`` of the smallest decrease, -1 if none
    #: ``|B|`` of the smallest submodularity witness, -1 if none
    submodular_witness_size: np.ndarray


@cache
def _gain_index(n: int):
    """Sets ``S`` not containing ``x`` for every ``x``: bitmasks ``S``, ``S + x`` and ``|S|``.

    Shape ``(2**(n-1), n)``: row ``c`` of column ``x`` is the subset whose members are the
    elements other than ``x`` picked by the bits of ``c`` (in increasing order), so bit ``j`` of
    ``c`` is one element and the subset lattice of ``c`` is that of the sets without ``x``.
    """
    c = np.arange(2 ** (n - 1))[:, None]
    x = np.arange(n)[None, :]
    low = c & ((1 << x) - 1)
    S = low | ((c - low) << 1)
    return S, S | (1 << x), _popcount(n)[S]


def _subset_transform(h: np.ndarray, op) -> np.ndarray:
    """In place over the leading lattice axis of ``h`` (``2**k`` sets): ``op`` over all subsets.

    The sum-over-subsets transform with ``op`` (``np.fmin`` or ``np.fmax``, which skip NaN) in
    place of the sum: afterwards ``h[B] = op(h[A] for A subset of B)``, NaN only if every
    ``h[A]`` is NaN.
    """
    k = h.shape[0].bit_length() - 1
    flat = h.reshape(h.shape[0], -1)
    for j in range(k):
        v = flat.reshape(2 ** (k - 1 - j), 2, 2**j, -1)
        op(v[:, 1], v[:, 0], out=v[:, 1])
    return h


#: Tables per block in :func:`audit_flags` (keeps the working arrays in cache).
_FLAGS_BLOCK = 512


def audit_flags(values, n: int, min_size: int = 0, rtol: float = RTOL,
                atol: float = ATOL) -> TableFlags:
    """Which tables are monotone / submodular, exactly as :func:`audit_tables` decides, faster.

    :func:`audit_tables` compares every nested triple ``(A, B, x)``; when only *whether* a
    table has a violation (and the size of its smallest witness) is needed, it suffices to
    compare the gain ``g(B, x) = f(B + x) - f(B)`` with the smallest (largest) gain
    ``g(A, x)`` over the proper subsets ``A`` of ``B`` with ``|A| >= min_size``. Those extremes
    come from a min (max) sum-over-subsets transform of the gain table, ``O(n^2 2^n)`` per
    table instead of ``O(n 3^n)`` (``A = B`` may be included: it gives a difference of 0,
    never beyond the tolerance). The verdicts are bitwise those of :func:`audit_tables`: the
    gains are the same floating-point numbers, and since rounding is monotone,
    ``fl(g_B - min_A g_A) = max_A fl(g_B - g_A)``. A test checks the equality on random tables.

    Parameters
    ----------
    values, n, min_size, rtol, atol
        As in :func:`audit_tables`.

    Returns
    -------
    TableFlags

    Examples
    --------
    The same verdicts as :func:`audit_tables`, without the witnesses:

    >>> flags = audit_flags([[0, 1, 1, 2], [0, 1, 1, 1]], n=2)
    >>> flags.not_submodular, flags.not_supermodular
    (array([False, False]), array([False,  True]))
    """
    n, m, v, tol = _tables_iv(values, n, min_size, rtol, atol)
    n_i = v.shape[0]
    inc = np.zeros(n_i, dtype=bool)
    sup = np.zeros(n_i, dtype=bool)
    mono = np.full(n_i, -1, dtype=np.int64)
    subs = np.full(n_i, -1, dtype=np.int64)
    if n == 0:
        return TableFlags(tol, mono >= 0, inc, subs >= 0, sup, mono, subs)
    S, Sx, size = _gain_index(n)  # (2**(n-1), n): S, S + x, |S|
    size = size[:, 0]  # |S| = popcount of the lattice index, the same for every x
    unused = size < m
    by_size = [(k, np.flatnonzero(size == k)) for k in range(int(size.max()), -1, -1)]

    def smallest(viol, out, shift):
        # |set| of the smallest violation of each table, found by trying sizes downwards
        hit = viol.any(axis=1)  # (2**(n-1), block): some x violates at this set
        for k, rows in by_size:
            out[hit[rows].any(axis=0)] = k + shift

    for c in range(0, n_i, _FLAGS_BLOCK):
        blk = slice(c, c + _FLAGS_BLOCK)
        vt = np.ascontiguousarray(v[blk].T)  # (2**n, block)
        t = tol[blk]
        with np.errstate(invalid="ignore"):  # sets below min_size may hold +-inf or NaN
            g = vt[Sx]
            g -= vt[S]  # (2**(n-1), n, block): the gain of x at S
        g[unused] = np.nan  # NaN compares False and is skipped by fmin / fmax
        smallest(g < -t, mono[blk], 1)
        inc[blk] = (g > t).any(axis=(0, 1))
        # min / max of the gain over all A subset of B; A = B adds a difference of 0, which is
        # never beyond the tolerance, so it changes no verdict.
        ext = _subset_transform(g.copy(), np.fmin)
        np.subtract(g, ext, out=ext)
        smallest(ext > t, subs[blk], 0)
        ext = _subset_transform(g.copy(), np.fmax)
        np.subtract(g, ext, out=ext)
        sup[blk] = (ext < -t).any(axis=(0, 1))
    return TableFlags(
        tol=tol,
        decreases=mono >= 0,
        increases=inc,
        not_submodular=subs >= 0,
        not_supermodular=sup,
        monotone_witness_size=mono,
        submodular_witness_size=subs,
    )


def audit_set_function(
    ground,
    f: Callable[[tuple], float] | None = None,
    *,
    values=None,
    min_size: int = 0,
    rtol: float = RTOL,
    atol: float = ATOL,
) -> SetFunctionAudit:
    """Check a set function for monotonicity and submodularity over all nested subsets.

    Parameters
    ----------
    ground : int or array_like, shape (N, 2)
        The ground set (its size, or the sensors), ``N <= 10``.
    f : callable, optional
        ``f(idx) -> float`` on sorted index tuples; evaluated once per subset.
    values : array_like, shape (2**N,), optional
        Precomputed table instead of ``f`` (exactly one of the two).
    min_size : int
        Only sets with at least this many elements are compared (see the module docstring).
    rtol, atol : float
        Tolerance ``rtol * max |f| + atol`` below which differences are rounding.

    Returns
    -------
    SetFunctionAudit
        Counts of violations and the smallest witnesses.

    Examples
    --------
    >>> # a threshold: not submodular
    >>> a = audit_set_function(3, lambda s: float(len(s) >= 2))
    >>> a.monotone_increasing, a.submodular
    (True, False)
    >>> w = a.submodular_witness
    >>> w.A, w.B, w.x, w.gain_A, w.gain_B
    ((), (0,), 1, 0.0, 1.0)
    """
    n = _audit_set_function_iv(ground, f, values)
    if values is None:
        values = set_function_table(n, f, min_size)
    return audit_tables(values, n, min_size, rtol, atol)[0]


def _audit_set_function_iv(ground, f, values) -> int:
    """The ground set's size, given exactly one of ``f`` and ``values`` (each checked by the
    function it goes to)."""
    n = _ground_size(ground)
    if (f is None) == (values is None):
        raise ValueError("give exactly one of f and values, got "
                         + ("both" if f is not None else "neither"))
    return n


def table_values(table) -> dict:
    """A table of :func:`set_function_table` as a dict: sorted index tuple -> value, in the
    table's (bitmask) order.

    Examples
    --------
    >>> table_values([0.0, 1.0, 2.0, 4.0])
    {(): 0.0, (0,): 1.0, (1,): 2.0, (0, 1): 4.0}
    """
    t, n = _table_values_iv(table)
    return {_members(k, n): float(t[k]) for k in range(t.size)}


def _table_values_iv(table) -> tuple:
    """A 1-D table of length ``2**N``, and ``N``."""
    t = as_float_array(table, "table")
    n = max(t.size.bit_length() - 1, 0)
    if t.ndim != 1 or t.size != 1 << n:
        raise ValueError(f"table must be 1-D of length 2**N, got shape {t.shape}")
    return t, n

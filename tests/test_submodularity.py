"""The witness finder (obslib.submodularity) against brute force, and Theorem 7 recomputed."""

import doctest
import itertools

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import obslib.submodularity as subm
from obslib.measures import subset_masks

SETTINGS = settings(derandomize=True, deadline=None, max_examples=60, database=None)


def subsets(n, min_size=0):
    return [S for k in range(min_size, n + 1) for S in itertools.combinations(range(n), k)]


def brute_force(n, f, min_size=0, tol=0.0):
    """All violations with plain loops, each sorted by the documented witness order."""
    val = {S: f(S) for S in subsets(n, min_size)}
    add = lambda S, x: tuple(sorted(S + (x,)))  # noqa: E731
    mono, incr, sub, sup = [], [], [], []
    for A in val:
        for x in set(range(n)) - set(A):
            g = val[add(A, x)] - val[A]
            key = (len(A) + 1, add(A, x), A)
            if g < -tol:
                mono.append((key, A, x))
            if g > tol:
                incr.append((key, A, x))
    for B in val:
        for x in set(range(n)) - set(B):
            gB = val[add(B, x)] - val[B]
            for A in val:
                if set(A) < set(B):
                    gA = val[add(A, x)] - val[A]
                    key = (len(B), B, A, x)
                    if gB > gA + tol:
                        sub.append((key, A, B, x))
                    if gA > gB + tol:
                        sup.append(key)
    return sorted(mono), sorted(incr), sorted(sub), sup


# --------------------------------------------------------------------------- the finder


@SETTINGS
@given(st.integers(1, 5), st.integers(0, 3), st.randoms(use_true_random=False))
def test_finder_equals_brute_force_on_random_functions(n, min_size, rnd):
    assume(min_size <= n)
    table = {S: float(rnd.choice([0, 1, 2, 3])) for S in subsets(n)}  # many ties and violations
    f = table.__getitem__
    a = subm.audit_set_function(n, f, min_size=min_size)
    mono, incr, sub, sup = brute_force(n, f, min_size, tol=a.tol)
    assert a.n_decreases == len(mono) and a.n_increases == len(incr)
    assert a.n_submodular_violations == len(sub) and a.n_supermodular_violations == len(sup)
    if mono:
        _, A, x = mono[0]
        assert (a.monotone_witness.A, a.monotone_witness.x) == (A, x)
    else:
        assert a.monotone_witness is None
    if sub:
        _, A, B, x = sub[0]
        w = a.submodular_witness
        assert (w.A, w.B, w.x) == (A, B, x)
        assert w.gain_B > w.gain_A
        assert np.isclose(w.gain_A, f(tuple(sorted(A + (x,)))) - f(A))
    else:
        assert a.submodular_witness is None


def test_known_non_submodular_function():
    """f(S) = |S|^2 is supermodular: the smallest witness is A = {}, B = {0}, x = 1."""
    f = lambda S: float(len(S) ** 2)  # noqa: E731
    a = subm.audit_set_function(4, f)
    assert a.monotone_increasing and not a.submodular and a.supermodular
    w = a.submodular_witness
    assert (w.A, w.B, w.x) == ((), (0,), 1) and (w.gain_A, w.gain_B) == (1.0, 3.0)
    _, _, sub, _ = brute_force(4, f)
    # the gain 2|A| + 1 grows with |A|: every proper nested triple violates, 4 * 3^3 - 4 * 2^3
    assert a.n_submodular_violations == len(sub) == a.n_triples == 76


def test_known_submodular_and_modular_functions():
    cover = [{0, 1}, {1, 2}, {2, 3}, {0, 3}, {4}]
    f = lambda S: float(len(set().union(*(cover[i] for i in S))))  # noqa: E731  coverage
    a = subm.audit_set_function(5, f)
    assert a.monotone_increasing and a.submodular and not a.modular
    w = np.array([0.3, 1.7, 2.2, 0.1])
    a = subm.audit_set_function(4, lambda S: float(w[list(S)].sum()))
    assert a.modular and a.monotone_increasing and a.max_excess <= a.tol


def test_decreasing_function_witness():
    a = subm.audit_set_function(3, lambda S: -float(len(S)))
    assert a.monotone_decreasing and not a.monotone_increasing
    w = a.monotone_witness
    assert (w.A, w.x, w.B, w.gain) == ((), 0, (0,), -1.0)


def test_tolerance_hides_rounding():
    rng = np.random.default_rng(0)
    w = rng.uniform(0, 1, 6)
    f = lambda S: float(np.sum(w[list(S)]) * (1 + 1e-15 * rng.standard_normal()))  # noqa: E731
    assert subm.audit_set_function(6, f).modular


def test_each_subset_is_evaluated_once_and_small_sets_never():
    calls = []

    def f(S):
        assert len(S) >= 2, "called below min_size"
        calls.append(S)
        return float(len(S))

    subm.audit_set_function(6, f, min_size=2)
    assert len(calls) == len(set(calls)) == 2**6 - 1 - 6


def test_doctests():
    assert doctest.testmod(subm, raise_on_error=False).failed == 0


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: subm.audit_set_function(11, lambda S: 0.0), "too large"),
        (lambda: subm.audit_set_function(-1, lambda S: 0.0), "non-negative"),
        (lambda: subm.audit_set_function(3, lambda S: 0.0, min_size=4), "exceeds"),
        (lambda: subm.audit_set_function(3, lambda S: 0.0, min_size=-1), "min_size"),
        (lambda: subm.audit_set_function(3, lambda S: float("nan")), "not a finite"),
        (lambda: subm.audit_set_function(3, lambda S: "a"), "not a finite"),
        (lambda: subm.audit_set_function(3, lambda S: -np.inf), r"f\(\) = -inf"),
        (lambda: subm.audit_set_function(3, 5), "callable"),
        (lambda: subm.audit_set_function(3), "exactly one"),
        (lambda: subm.audit_set_function(3, lambda S: 0.0, values=np.zeros(8)), "exactly one"),
        (lambda: subm.audit_set_function(3, values=np.zeros(7)), "shape"),
        (lambda: subm.audit_set_function(2, values=[0.0, 1.0, np.inf, 2.0]), r"set \(1,\)"),
        (lambda: subm.audit_set_function([[0, 0], [0, np.nan]], lambda S: 0.0), "sensor 1"),
        (lambda: subm.audit_set_function([[0, 0], [0, 0]], lambda S: 0.0), "coincide"),
        (lambda: subm.audit_tables(np.zeros((2, 8)), 3, rtol=-1.0), "non-negative"),
    ],
)
def test_bad_input_raises(call, match):
    with pytest.raises(ValueError, match=match):
        call()


# --------------------------------------------------------------------------- the fast verdicts


def _flags_from_audits(audits):
    """The per-table verdicts audit_flags promises, read off the full audit_tables objects."""
    return {
        "decreases": [not a.monotone_increasing for a in audits],
        "increases": [not a.monotone_decreasing for a in audits],
        "not_submodular": [not a.submodular for a in audits],
        "not_supermodular": [not a.supermodular for a in audits],
        "monotone_witness_size": [len(a.monotone_witness.B) if a.monotone_witness else -1
                                  for a in audits],
        "submodular_witness_size": [len(a.submodular_witness.B) if a.submodular_witness else -1
                                    for a in audits],
        "tol": [a.tol for a in audits],
    }


@pytest.mark.parametrize("n, min_size", [(n, m) for n in range(1, 8) for m in range(4) if m <= n])
def test_audit_flags_equal_the_full_audit(n, min_size):
    """audit_flags (subset-min transform) decides exactly as audit_tables (every triple)."""
    rng = np.random.default_rng(100 * n + min_size)
    k = 2**n
    tables = [
        rng.integers(0, 4, size=(300, k)).astype(float),  # many ties and violations
        rng.normal(size=(300, k)),
        np.cumsum(rng.random((300, k)), axis=1),  # increasing in the bitmask, not in the lattice
        # modular up to rounding (a sum of per-element weights): never beyond the tolerance
        (subset_masks(n)[None, :, :] * rng.random((300, 1, n))).sum(axis=2) * 1e3,
    ]
    # log-determinant-like values with -inf below min_size: ignored, never warned about
    small = subset_masks(n).sum(axis=1) < min_size
    t = rng.normal(size=(300, k))
    t[:, small] = -np.inf
    tables.append(t)
    for v in tables:
        fast = subm.audit_flags(v, n, min_size)
        slow = _flags_from_audits(subm.audit_tables(v, n, min_size))
        for key, want in slow.items():
            assert np.array_equal(getattr(fast, key), want), key


def test_audit_flags_is_blockwise_independent(monkeypatch):
    """Tables are processed in blocks; the verdicts do not depend on the block size."""
    v = np.random.default_rng(7).normal(size=(1000, 32))
    full = subm.audit_flags(v, 5, 1)
    monkeypatch.setattr(subm, "_FLAGS_BLOCK", 37)
    part = subm.audit_flags(v, 5, 1)
    for key in full.__dataclass_fields__:
        assert np.array_equal(getattr(full, key), getattr(part, key)), key


def test_audit_flags_bad_input():
    with pytest.raises(ValueError, match="not finite"):
        subm.audit_flags(np.full((2, 8), np.nan), 3)
    with pytest.raises(ValueError, match="shape"):
        subm.audit_flags(np.zeros((2, 7)), 3)

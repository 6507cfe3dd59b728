"""The witness finder (obslib.submodularity) against brute force, and Theorem 7 recomputed."""

import doctest
import itertools

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import obslib as ob
import obslib.submodularity as sm
from obslib.measures import measure_from_vectors, subset_masks

SETTINGS = settings(derandomize=True, deadline=None, max_examples=60, database=None)
R3 = np.sqrt(3.0)
T1 = np.array([R3, 1.0])
CASE1 = np.array([[0, 0], [2 * R3, -9], [R3, 3]], dtype=float)
CASE2 = np.array([[0, 0], [2 * R3, 0], [R3, 0.1], [R3, 3]], dtype=float)


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
    a = sm.audit_set_function(n, f, min_size=min_size)
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
    a = sm.audit_set_function(4, f)
    assert a.monotone_increasing and not a.submodular and a.supermodular
    w = a.submodular_witness
    assert (w.A, w.B, w.x) == ((), (0,), 1) and (w.gain_A, w.gain_B) == (1.0, 3.0)
    _, _, sub, _ = brute_force(4, f)
    # the gain 2|A| + 1 grows with |A|: every proper nested triple violates, 4 * 3^3 - 4 * 2^3
    assert a.n_submodular_violations == len(sub) == a.n_triples == 76


def test_known_submodular_and_modular_functions():
    cover = [{0, 1}, {1, 2}, {2, 3}, {0, 3}, {4}]
    f = lambda S: float(len(set().union(*(cover[i] for i in S))))  # noqa: E731  coverage
    a = sm.audit_set_function(5, f)
    assert a.monotone_increasing and a.submodular and not a.modular
    w = np.array([0.3, 1.7, 2.2, 0.1])
    a = sm.audit_set_function(4, lambda S: float(w[list(S)].sum()))
    assert a.modular and a.monotone_increasing and a.max_excess <= a.tol


def test_decreasing_function_witness():
    a = sm.audit_set_function(3, lambda S: -float(len(S)))
    assert a.monotone_decreasing and not a.monotone_increasing
    w = a.monotone_witness
    assert (w.A, w.x, w.B, w.gain) == ((), 0, (0,), -1.0)


def test_tolerance_hides_rounding():
    rng = np.random.default_rng(0)
    w = rng.uniform(0, 1, 6)
    f = lambda S: float(np.sum(w[list(S)]) * (1 + 1e-15 * rng.standard_normal()))  # noqa: E731
    assert sm.audit_set_function(6, f).modular


def test_each_subset_is_evaluated_once_and_small_sets_never():
    calls = []

    def f(S):
        assert len(S) >= 2, "called below min_size"
        calls.append(S)
        return float(len(S))

    sm.audit_set_function(6, f, min_size=2)
    assert len(calls) == len(set(calls)) == 2**6 - 1 - 6


def test_doctests():
    assert doctest.testmod(sm, raise_on_error=False).failed == 0


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: sm.audit_set_function(11, lambda S: 0.0), "too large"),
        (lambda: sm.audit_set_function(-1, lambda S: 0.0), "non-negative"),
        (lambda: sm.audit_set_function(3, lambda S: 0.0, min_size=4), "exceeds"),
        (lambda: sm.audit_set_function(3, lambda S: 0.0, min_size=-1), "min_size"),
        (lambda: sm.audit_set_function(3, lambda S: float("nan")), "not a finite"),
        (lambda: sm.audit_set_function(3, lambda S: "a"), "not a finite"),
        (lambda: sm.audit_set_function(3, lambda S: -np.inf), r"f\(\) = -inf"),
        (lambda: sm.audit_set_function(3, 5), "callable"),
        (lambda: sm.audit_set_function(3), "exactly one"),
        (lambda: sm.audit_set_function(3, lambda S: 0.0, values=np.zeros(8)), "exactly one"),
        (lambda: sm.audit_set_function(3, values=np.zeros(7)), "shape"),
        (lambda: sm.audit_set_function(2, values=[0.0, 1.0, np.inf, 2.0]), r"set \(1,\)"),
        (lambda: sm.audit_set_function([[0, 0], [0, np.nan]], lambda S: 0.0), "sensor 1"),
        (lambda: sm.audit_set_function([[0, 0], [0, 0]], lambda S: 0.0), "coincide"),
        (lambda: sm.audit_tables(np.zeros((2, 8)), 3, rtol=-1.0), "non-negative"),
        (lambda: sm.lower_bound_table(CASE1, T1, -1.0), "u_max"),
        (lambda: sm.lower_bound_table(CASE1, CASE1[0], 1.0), "coincides with target"),
        (lambda: sm.case_audit("case3"), "unknown case"),
        (lambda: sm.random_instances(5, 3, 0, kind="grid"), "kind"),
        (lambda: sm.measure_audit("trace", 5, 3, 0, 1.0, 1.0, "other"), "unknown config"),
        (lambda: sm.measure_audit("cond", 5, 3, 0, 1.0, 1.0, sm.CONFIGS[0][0]), "unknown measure"),
    ],
)
def test_bad_input_raises(call, match):
    with pytest.raises(ValueError, match=match):
        call()


# --------------------------------------------------------------------------- omega as a set function

coord = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)


@SETTINGS
@given(st.lists(st.tuples(coord, coord), min_size=2, max_size=7), st.floats(0.0, 3.0))
def test_lower_bound_table_matches_svd(points, u_max):
    pts = np.array(points)
    d = np.linalg.norm(pts[:, None] - pts[None], axis=-1) + np.eye(len(pts))
    assume(d.min() > 1e-3)
    s, o = pts[1:], pts[0]
    table = sm.lower_bound_table(s, o, u_max)
    for k, m in enumerate(subset_masks(len(s))):
        assert abs(table[k] - ob.lower_bound(s[m], o, u_max)) < 1e-9


def omega(sensors, idx, u_max=1.0):
    return ob.lower_bound(sensors[list(idx)], T1, u_max)


def test_case1_values_and_claim():
    assert round(omega(CASE1, (0, 2)), 4) == 0.5345
    assert round(omega(CASE1, (0, 1, 2)), 4) == 0.1823
    assert omega(CASE1, (0, 2)) > omega(CASE1, (0, 1, 2))  # not monotone, as printed
    ca = sm.case_audit("case1")
    assert ca.all_match and ca.shows_with_printed and ca.shows_with_ours


def test_case1_smallest_monotone_witness_rederived():
    w = sm.case_audit("case1").audits[2].monotone_witness
    assert (w.A, w.x) == ((0, 1), 2)
    # independently: omega({s1,s2}) > omega({s1,s2,s3}) by 0.0009
    drop = omega(CASE1, (0, 1)) - omega(CASE1, (0, 1, 2))
    assert round(drop, 4) == 0.0009 and np.isclose(-w.gain, drop)


def test_case2_printed_value_is_wrong_and_the_printed_triple_is_no_counter_example():
    v = {S: omega(CASE2, S) for S in subsets(4, 2)}
    assert round(v[(0, 1, 2)], 4) == 0.6336  # printed: 0.3310
    assert round(v[(0, 2)], 4) == round(v[(1, 2)], 4) == 0.3310  # where 0.3310 comes from
    assert [round(v[S], 4) for S in [(0, 1), (0, 1, 2, 3), (0, 1, 3)]] == [0.5345, 0.8765, 0.9258]
    gain_small = v[(0, 1, 2)] - v[(0, 1)]  # adding s3 to {s1, s2}
    gain_large = v[(0, 1, 2, 3)] - v[(0, 1, 3)]  # adding s3 to {s1, s2, s4}
    assert round(gain_small, 4) == 0.0991 and round(gain_large, 4) == -0.0493
    assert gain_small >= gain_large  # diminishing returns hold for this triple
    # with the printed numbers the comparison would have shown a violation
    assert 0.3310 - 0.5345 < 0.8765 - 0.9258
    ca = sm.case_audit("case2")
    assert ca.shows_with_printed and not ca.shows_with_ours and not ca.all_match
    assert [k for k, ok in ca.matches.items() if not ok] == [(0, 1, 2)]


def test_case2_geometry_has_a_witness_rederived():
    w = sm.case_audit("case2").audits[2].submodular_witness
    assert (w.A, w.B, w.x) == ((0, 2), (0, 1, 2), 3)
    gA = omega(CASE2, (0, 2, 3)) - omega(CASE2, (0, 2))  # s4 joins {s1, s3}
    gB = omega(CASE2, (0, 1, 2, 3)) - omega(CASE2, (0, 1, 2))  # s4 joins {s1, s2, s3}
    assert (round(gA, 4), round(gB, 4)) == (0.2027, 0.2429)
    assert gB > gA and np.isclose(gA, w.gain_A) and np.isclose(gB, w.gain_B)
    # and it is the smallest: no violation with |B| = 3 and a lexicographically smaller B
    for B in [(0, 1, 2)]:
        for A in itertools.combinations(B, 2):
            if A < (0, 2):
                for x in set(range(4)) - set(B):
                    assert (omega(CASE2, tuple(sorted(A + (x,)))) - omega(CASE2, A)
                            >= omega(CASE2, tuple(sorted(B + (x,)))) - omega(CASE2, B))


def test_trivial_witness_below_two_sensors():
    """With the empty set and singletons allowed, omega breaks submodularity trivially."""
    w = sm.case_audit("case1").audits[0].submodular_witness
    assert (w.A, w.B, w.x) == ((), (0,), 1)
    assert omega(CASE1, (1,)) - omega(CASE1, ()) == 0.0 < omega(CASE1, (0, 1)) - omega(CASE1, (0,))


def test_random_lower_bound_witnesses_rederived():
    for u_max in (1.0, 0.0):
        a = sm.lower_bound_audit(50, 5, 1, u_max)
        assert a.n_not_submodular > 0 and a.n_not_increasing > 0
        for w in (a.witness, a.monotone_witness):
            s, o = np.array(w["sensors"]), np.array(w["target"])
            f = lambda S: ob.lower_bound(s[list(S)], o, u_max)  # noqa: E731
            A, x = tuple(w["A"]), w["x"]
            gA = f(tuple(sorted(A + (x,)))) - f(A)
            if "gain_B" in w:
                B = tuple(w["B"])
                gB = f(tuple(sorted(B + (x,)))) - f(B)
                assert set(A) < set(B) and len(A) >= 2 and gB > gA
            else:
                assert len(A) >= 2 and gA < 0


def test_random_instances_are_seeded_and_legal():
    for kind in sm.INSTANCE_KINDS:
        s1, t1 = sm.random_instances(30, 6, 5, kind)
        s2, t2 = sm.random_instances(30, 6, 5, kind)
        assert np.array_equal(s1, s2) and np.array_equal(t1, t2)
        for s, t in zip(s1, t1):
            ob.relative_rows(s, t)  # distinct, none on the target
    # the "lines" kind does produce rank-deficient pairs
    s, t = sm.random_instances(30, 6, 5, "lines")
    ranks = measure_from_vectors(t[:, None, :] - s, subset_masks(6), "rank")
    pairs = subset_masks(6).sum(axis=1) == 2
    assert (ranks[:, pairs] == 1).any() and (ranks[:, pairs] == 2).any()


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
        fast = sm.audit_flags(v, n, min_size)
        slow = _flags_from_audits(sm.audit_tables(v, n, min_size))
        for key, want in slow.items():
            assert np.array_equal(getattr(fast, key), want), key


def test_audit_flags_is_blockwise_independent(monkeypatch):
    """Tables are processed in blocks; the verdicts do not depend on the block size."""
    v = np.random.default_rng(7).normal(size=(1000, 32))
    full = sm.audit_flags(v, 5, 1)
    monkeypatch.setattr(sm, "_FLAGS_BLOCK", 37)
    part = sm.audit_flags(v, 5, 1)
    for key in full.__dataclass_fields__:
        assert np.array_equal(getattr(full, key), getattr(part, key)), key


def test_audit_flags_bad_input():
    with pytest.raises(ValueError, match="not finite"):
        sm.audit_flags(np.full((2, 8), np.nan), 3)
    with pytest.raises(ValueError, match="shape"):
        sm.audit_flags(np.zeros((2, 7)), 3)


def test_random_audits_equal_the_per_instance_audits():
    """lower_bound_audit and measure_audit (fast verdicts) against audit_tables instance by instance."""
    for u_max, min_size in ((1.0, 2), (0.0, 2), (0.5, 0)):
        a = sm.lower_bound_audit(150, 5, 3, u_max, min_size)
        s, t = sm.random_instances(150, 5, 3, "generic")
        audits = sm.audit_tables(sm.lower_bound_tables(t[:, None, :] - s, u_max), 5, min_size)
        assert a.n_not_increasing == sum(not x.monotone_increasing for x in audits)
        assert a.n_not_submodular == sum(not x.submodular for x in audits)
        for key, attr in (("witness", "submodular_witness"), ("monotone_witness", "monotone_witness")):
            hits = [(len(getattr(x, attr).B), i) for i, x in enumerate(audits) if getattr(x, attr)]
            w = getattr(a, key)
            if not hits:
                assert w is None
                continue
            i = min(hits)[1]
            want = getattr(audits[i], attr).as_dict()
            assert w["instance"] == i and all(w[k] == want[k] for k in want)
            assert np.array_equal(w["sensors"], s[i]) and np.array_equal(w["target"], t[i])

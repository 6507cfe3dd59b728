"""Section IV-B's audits (obslib.studies.submodularity): Theorem 7's cases and the random audits of
Theorems 7-8, each rederived with obslib.lower_bound or NumPy's dense routines."""

import itertools

import numpy as np
import pytest

import obslib as ob
import obslib.measures as me
import obslib.submodularity as subm
from obslib.bound_tables import lower_bound_tables
from obslib.measures import measure_from_vectors, subset_masks
from obslib.studies import submodularity as sm

R3 = np.sqrt(3.0)
T1 = np.array([R3, 1.0])
CASE1 = np.array([[0, 0], [2 * R3, -9], [R3, 3]], dtype=float)
CASE2 = np.array([[0, 0], [2 * R3, 0], [R3, 0.1], [R3, 3]], dtype=float)


def subsets(n, min_size=0):
    return [S for k in range(min_size, n + 1) for S in itertools.combinations(range(n), k)]


def gram(sensors, target, u=None, eps=0.0):
    O = np.asarray(target, float)[None, :] - np.asarray(sensors, float).reshape(-1, 2)
    if u is not None:
        O = np.vstack([O, u])
    return O.T @ O + eps * np.eye(2), O


def test_paper_geometry_is_the_one_of_fig3():
    np.testing.assert_array_equal(sm.FIG3_TARGET, T1)
    np.testing.assert_array_equal(sm.FIG3_CASES["case1"], CASE1)
    np.testing.assert_array_equal(sm.FIG3_CASES["case2"], CASE2)


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: sm.case_audit("case3"), "unknown case"),
        (lambda: sm.random_instances(5, 3, 0, kind="grid"), "kind"),
        (lambda: sm.measure_audit("trace", 5, 3, 0, 1.0, 1.0, "other"), "unknown config"),
        (lambda: sm.measure_audit("cond", 5, 3, 0, 1.0, 1.0, sm.CONFIGS[0][0]), "unknown measure"),
    ],
)
def test_bad_input_raises(call, match):
    with pytest.raises(ValueError, match=match):
        call()


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


def test_random_audits_equal_the_per_instance_audits():
    """lower_bound_audit and measure_audit (fast verdicts) against audit_tables instance by
    instance."""
    for u_max, min_size in ((1.0, 2), (0.0, 2), (0.5, 0)):
        a = sm.lower_bound_audit(150, 5, 3, u_max, min_size)
        s, t = sm.random_instances(150, 5, 3, "generic")
        audits = subm.audit_tables(lower_bound_tables(t[:, None, :] - s, u_max), 5, min_size)
        assert a.n_not_increasing == sum(not x.monotone_increasing for x in audits)
        assert a.n_not_submodular == sum(not x.submodular for x in audits)
        for key, attr in (
            ("witness", "submodular_witness"),
            ("monotone_witness", "monotone_witness"),
        ):
            hits = [(len(getattr(x, attr).B), i) for i, x in enumerate(audits) if getattr(x, attr)]
            w = getattr(a, key)
            if not hits:
                assert w is None
                continue
            i = min(hits)[1]
            want = getattr(audits[i], attr).as_dict()
            assert w["instance"] == i and all(w[k] == want[k] for k in want)
            assert np.array_equal(w["sensors"], s[i]) and np.array_equal(w["target"], t[i])


def test_theorem8_rows_equal_per_instance_audits():
    """theorem8_audit (instances and tr/det shared, fast verdicts) against audit_tables per
    instance."""
    n_inst, n_sens, seed, eps, u_max = 60, 4, 5, 1.0, 1.0
    rows = sm.theorem8_audit(n_inst, n_sens, seed, eps, u_max)
    assert [(r.measure, r.config) for r in rows] == [
        (m, c[0]) for m in me.MEASURES for c in sm.CONFIGS
    ]
    for r in rows:
        assert r == sm.measure_audit(r.measure, n_inst, n_sens, seed, eps, u_max, r.config)
    for name, use_eps, use_u, min_size, kinds in ((c[0],) + c[1:] for c in sm.CONFIGS):
        for measure in me.MEASURES:
            audits = []
            for k, kind in enumerate(kinds):  # the draws of measure_audit, one instance at a time
                s, t = sm.random_instances(n_inst, n_sens, seed + 7919 * k, kind)
                phi = np.random.default_rng(seed + 104729 + k).uniform(0, 2 * np.pi, n_inst)
                for i in range(n_inst):
                    u = u_max * np.array([np.cos(phi[i]), np.sin(phi[i])]) if use_u else None
                    table = me.measure_table(s[i], t[i], measure, eps if use_eps else 0.0, u)
                    audits.append(subm.audit_set_function(s[i], values=table, min_size=min_size))
            r = next(x for x in rows if x.measure == measure and x.config == name)
            assert r.n_instances == len(audits)
            assert r.n_not_increasing == sum(not a.monotone_increasing for a in audits)
            assert r.n_not_decreasing == sum(not a.monotone_decreasing for a in audits)
            assert r.n_not_submodular == sum(not a.submodular for a in audits)
            assert r.n_not_supermodular == sum(not a.supermodular for a in audits)


def test_neg_trace_inverse_witnesses_rederived():
    """Every witness of the random audit, recomputed with numpy.linalg.inv (no witness finder)."""
    rows = sm.theorem8_audit(100, 4, 3, 1.0, 1.0)
    found = 0
    for r in rows:
        if r.measure != "neg_trace_inverse" or r.witness is None:
            continue
        w = r.witness
        s, o = np.array(w["sensors"]), np.array(w["target"])
        u = None if w["u"] is None else np.array(w["u"])

        def f(idx):
            G, _ = gram(s[list(idx)], o, u, r.eps)
            return -np.trace(np.linalg.inv(G))

        A, B, x = tuple(w["A"]), tuple(w["B"]), w["x"]
        assert set(A) < set(B) and x not in B
        gA = f(tuple(sorted(A + (x,)))) - f(A)
        gB = f(tuple(sorted(B + (x,)))) - f(B)
        assert np.isclose(gA, w["gain_A"]) and np.isclose(gB, w["gain_B"])
        assert gB > gA + 1e-9
        found += 1
    assert found == 3  # in every configuration


def test_logdet_domains_share_the_theorem8_draws():
    """The three matrices the Theorem 8 audit also checks give its logdet rows exactly."""
    rows = {r.config: r for r in sm.theorem8_audit(30, 4, 5, 1.0, 1.0) if r.measure == "logdet"}
    for d in sm.logdet_domain_audit(30, 4, 5, 1.0, 1.0):
        if d.audit.config in rows:
            assert d.audit == rows[d.audit.config]
        assert d.finite_from == {"prior, no control row": 0, "prior and control row": 0,
                                 "control row, no prior": 1, "no control row, no prior": 2}[
                                     d.matrix]

"""The batch optimum against the MILP, the charging argument, the tight weights, the ledger."""

import numpy as np
import pytest

import obslib as ob
from obslib import assignment_study as st
from obslib import claims


def test_enumerated_optimum_equals_milp():
    rng = np.random.default_rng(0)
    for n, L in [(4, 2), (5, 2), (6, 3), (7, 3), (8, 4)]:
        Ws = np.stack([ob.pair_bounds(rng.uniform(0, 100, (n, 2)), rng.uniform(0, 100, (L, 2)), 1.0) for _ in range(5)])
        for W, v in zip(Ws, st.optimal_values(Ws)):
            assert v == pytest.approx(ob.optimal_pair_assignment(W).value, abs=1e-12)


def test_pair_assignments_count():
    # N!/(2^L (N-2L)!) ordered choices of L disjoint pairs
    for n, L, count in [(4, 2, 6), (6, 3, 90), (8, 3, 2520), (5, 1, 10)]:
        P, Q = st.pair_assignments(n, L)
        assert P.shape == (count, L) and np.all(P < Q)
    with pytest.raises(ValueError, match="N >= 2L"):
        st.pair_assignments(3, 2)


def test_charging_covers_the_optimum_within_three_times_each_pick():
    rng = np.random.default_rng(1)
    for _ in range(100):
        W = ob.pair_bounds(rng.uniform(0, 100, (8, 2)), rng.uniform(0, 100, (3, 2)), 1.0)
        g, o = ob.greedy_pair_assignment(W), ob.optimal_pair_assignment(W)
        rounds = st.charging(W, g.triples, o.triples)
        assert sum(len(r["charged"]) for r in rounds) == len(o.triples)
        for r in rounds:
            assert len(r["charged"]) <= 3 and all(w <= r["w"] + 1e-12 for w in r["charged_w"])


def test_tight_weights_give_one_third():
    W = st.tight_weights(1e-6)
    ratio = ob.greedy_pair_assignment(W).value / ob.optimal_pair_assignment(W).value
    assert ratio == pytest.approx((1 + 1e-6) / 3)


def test_search_result_is_what_it_claims():
    r, S, T = st.worst_instance_search(6, 3, seed=3, n_starts=2, n_steps=50)
    W = ob.pair_bounds(S, T, 1.0)
    assert r == pytest.approx(ob.greedy_pair_assignment(W).value / ob.optimal_pair_assignment(W).value)
    assert r >= 1 / 3


def test_section_4a_statuses_follow_the_evidence():
    recs = {r.id: r for r in claims.evaluate("quick", ids=["thm6", "thm6-practice"])}
    ev = recs["thm6"].evidence
    assert recs["thm6"].status == ("reproduced" if min(ev["min_ratio"], ev["worst_search_ratio"]) >= 1 / 3 else "refuted")
    assert ev["tight_weights_ratio"] == pytest.approx(1.001 / 3)
    pe = recs["thm6-practice"].evidence
    expected = "refuted" if pe["quantile_05"] < 0.75 else ("reproduced" if pe["worst_search_ratio"] >= 0.5 else "partly")
    assert recs["thm6-practice"].status == expected


def test_fig8_trials_do_not_depend_on_sweep_order():
    a = st.fig8_sweep([3, 1, 2], trials=2, seed=5)
    b = st.fig8_sweep([1, 2, 3], trials=2, seed=5)
    for k in ("greedy", "relaxed", "relaxed_ordered"):
        np.testing.assert_array_equal(a[k][[1, 2, 0]], b[k])
    t = st.fig8_trial(2, 1, 5)
    assert t["greedy"] == b["greedy"][1, 1]


def test_fig8_values_are_ordered_as_the_theory_says():
    r = st.fig8_sweep([1, 2, 3, 4, 5], trials=3, seed=0, optimum_max_L=5)
    assert np.all(r["greedy"] <= r["optimum"] + 1e-12)
    assert np.all(r["optimum"] <= r["relaxed"] + 1e-12)
    assert np.all(r["relaxed"] <= r["relaxed_ordered"] + 1e-12)
    np.testing.assert_allclose(r["greedy"][0], r["relaxed"][0])  # L = 1: both take the best pair


def test_fig8_status_follows_the_ratio():
    rec = claims.evaluate("quick", ids=["fig8-greedy-near-relaxed"])[0]
    ratio = np.array(rec.evidence["ratio_by_L"])
    expected = "reproduced" if ratio[1:].min() >= 0.75 and abs(ratio[0] - 1) < 1e-9 else "refuted"
    assert rec.status == expected

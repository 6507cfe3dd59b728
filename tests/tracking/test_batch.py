"""Section V on the tracking engine (obslib.tracking.batch) against filterpy, step by step, and
its arms and seeds."""

from __future__ import annotations

import numpy as np
import pytest

from obslib import tracking as tr
from obslib._validate import ArgumentTypeError
from obslib.studies import adversarial_target, two_sensors_tracking

from .filterpy_reference import simulate as filterpy_simulate

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


@pytest.mark.parametrize("setup", [CIRCLE, ADV], ids=["circle", "adversarial"])
@pytest.mark.parametrize("strategy", tr.STRATEGIES)
def test_batch_engine_equals_filterpy_engine(setup, strategy):
    """Same picks at every step; values to rounding at every step. Against the fixed pair the
    adversary parks the target near the pair's baseline (C^-1 ~ 1e-3), where rounding
    differences grow to ~1e-7."""
    seeds = [0, 5]
    tol = 1e-6 if (setup.motion, strategy) == ("adversarial", "fixed-pair") else 1e-9
    b = tr.simulate_batch(setup, strategy, seeds=seeds)
    for n, seed in enumerate(seeds):
        r = filterpy_simulate(setup, strategy, seed=seed)
        one = tr.simulate(setup, strategy, seed=seed)
        np.testing.assert_array_equal(b.pairs[n], r["pairs"])
        np.testing.assert_array_equal(one.pairs, r["pairs"])
        np.testing.assert_array_equal(b.next_pair[n], r["next_pair"])
        for f in ("estimate", "cov", "truth", "bound"):
            np.testing.assert_allclose(getattr(b, f)[n], r[f], rtol=0, atol=tol, err_msg=f)
            np.testing.assert_allclose(getattr(one, f), r[f], rtol=0, atol=tol, err_msg=f)


def test_monte_carlo_trial_is_the_seeded_run():
    mc = tr.monte_carlo(CIRCLE.replace(steps=40), 4, first_seed=10, batch=3)
    for s in tr.STRATEGIES:
        assert mc[s].seeds == (10, 11, 12, 13)
        r = tr.simulate(CIRCLE.replace(steps=40), s, seed=12)
        np.testing.assert_array_equal(mc[s].pairs[2], r.pairs)
        np.testing.assert_allclose(mc[s].error[2], r.error, atol=1e-10)
    cmp = tr.compare_strategies(mc)
    assert set(cmp["wins"]) == {"best-partner", "fixed-pair"}
    for d in cmp["wins"].values():
        assert all(0 <= v <= 1 for v in d.values())


def test_simulate_many_runs_do_not_depend_on_the_company():
    """A run of the batch engine is the same alone or batched with other arms (same picks;
    values to 1e-12: the engine uses only elementwise IEEE operations, equal in practice
    whatever the batch shape, and 1e-12 is far below any pick's margin), and identical arms are
    computed once."""
    setup = CIRCLE.replace(steps=60)
    eu = setup.replace(metric="euclidean")
    arms = {s: (setup, s) for s in tr.STRATEGIES}
    arms.update({("eu", s): (eu, s) for s in tr.STRATEGIES})
    arms.update({("partner", j): a for j, a in two_sensors_tracking.partner_arms(setup).items()})
    many = tr.simulate_many(arms, seeds=[4, 5, 6])
    assert many[("partner", 0)] is many["fixed-pair"]  # the same arm: fixed pair (s2, s1)
    for key, (su, s) in arms.items():
        alone = tr.simulate_batch(su, s, seeds=[4, 5, 6])
        np.testing.assert_array_equal(many[key].pairs, alone.pairs)
        for f in ("bound", "estimate", "cov", "truth", "true_icn", "objective"):
            np.testing.assert_allclose(getattr(many[key], f), getattr(alone, f), rtol=0,
                                       atol=1e-12, err_msg=f)
    mc = tr.monte_carlo(setup, 3, first_seed=4, batch=2)
    for s in tr.STRATEGIES:
        np.testing.assert_array_equal(mc[s].pairs, many[s].pairs)
        for f in ("bound", "estimate", "cov", "error", "trace_cov"):
            np.testing.assert_allclose(getattr(mc[s], f), getattr(many[s], f), rtol=0,
                                       atol=1e-12, err_msg=f)


def test_simulate_many_adversaries_equal_filterpy_runs():
    """Arms with different adversaries and control sets in one call, against simulate."""
    setup = ADV.replace(steps=80)
    variants = adversarial_target.adversary_variants(setup, 3, 24)
    many = tr.simulate_many({k: (v, "best-pair") for k, v in variants.items()}, seeds=[1, 2])
    for k, v in variants.items():
        alone = tr.simulate_batch(v, "best-pair", seeds=[1, 2])
        np.testing.assert_array_equal(many[k].pairs, alone.pairs)  # the company does not matter
        for f in ("truth", "estimate", "cov", "bound"):  # 1e-12: as in the test above
            np.testing.assert_allclose(getattr(many[k], f), getattr(alone, f), rtol=0,
                                       atol=1e-12, err_msg=f)
        for b, seed in enumerate([1, 2]):
            r = tr.simulate(v, "best-pair", seed=seed)
            np.testing.assert_array_equal(many[k].pairs[b], r.pairs)
            np.testing.assert_allclose(many[k].truth[b], r.truth, rtol=0, atol=1e-9)
            np.testing.assert_allclose(many[k].estimate[b], r.estimate, rtol=0, atol=1e-9)
            np.testing.assert_allclose(many[k].objective[b], r.objective, rtol=0, atol=1e-9)


def test_simulate_many_bad_arguments_raise():
    with pytest.raises(ValueError, match="no arms"):
        tr.simulate_many({}, seeds=[0])
    with pytest.raises(ValueError, match="unknown strategy"):
        tr.simulate_many({"a": (CIRCLE, "random-pair")}, seeds=[0])  # "random" is a criterion
    with pytest.raises(ValueError, match="TrackingSetup"):
        tr.simulate_many({"a": ("setup", "best-pair")}, seeds=[0])
    with pytest.raises(ValueError, match="either seeds or noise"):
        tr.simulate_many({"a": (CIRCLE, "best-pair")})
    with pytest.raises(ValueError, match="seeds is empty"):
        tr.simulate_many({"a": (CIRCLE, "best-pair")}, seeds=[])
    with pytest.raises(ValueError, match="shape"):
        tr.simulate_many({"a": (CIRCLE, "best-pair")}, noise=np.zeros((1, 10, 6)))


def test_monte_carlo_arguments_of_the_wrong_kind_raise():
    with pytest.raises(ArgumentTypeError, match="strategies must be a list of names, got the str"):
        tr.monte_carlo(CIRCLE, 2, strategies="best-pair")
    with pytest.raises(ArgumentTypeError, match="n_seeds must be an integer"):
        tr.monte_carlo(CIRCLE, 2.5)
    with pytest.raises(ArgumentTypeError, match="n_seeds must be an integer, got 2.0"):
        tr.monte_carlo(CIRCLE, n_seeds=2.0)
    with pytest.raises(ArgumentTypeError, match="first_seed must be an integer, got None"):
        tr.monte_carlo(CIRCLE, 2, first_seed=None)
    with pytest.raises(ArgumentTypeError, match="each seed must be an integer, got None"):
        tr.simulate_batch(CIRCLE, "best-pair", seeds=[0, None])
    with pytest.raises(ArgumentTypeError, match="seeds must be an iterable"):
        tr.simulate_batch(CIRCLE, "best-pair", seeds=5)


@pytest.mark.parametrize("setup", [CIRCLE, ADV], ids=["circle", "adversarial"])
@pytest.mark.parametrize("name", ["d-optimal", "a-optimal", "e-optimal", "exact-icn", "random"])
def test_batch_engine_equals_filterpy_engine_for_the_criteria(setup, name):
    """Same decisions (the reference chooses with the public ``choose_pairs`` from filterpy's
    states, equal to the engine's to rounding ~1e-14), and values to 1e-9: the filters differ
    only in the order of floating operations, which over 315 steps leaves differences of ~1e-14
    (the adversary, which parks the target near a baseline, amplifies them to ~1e-12)."""
    seeds = [0, 5]
    b = tr.simulate_batch(setup, name, seeds=seeds)
    for n, seed in enumerate(seeds):
        r = filterpy_simulate(setup, name, seed=seed)
        np.testing.assert_array_equal(b.pairs[n], r["pairs"])
        np.testing.assert_array_equal(b.next_pair[n], r["next_pair"])
        for f in ("estimate", "cov", "truth", "bound"):
            np.testing.assert_allclose(getattr(b, f)[n], r[f], rtol=0, atol=1e-9, err_msg=f)


def test_criteria_share_a_monte_carlo_with_common_random_numbers():
    """All names in one call: every arm sees the same noise tables, and the runs equal the arms
    run alone (one pass or several)."""
    setup = CIRCLE.replace(steps=40)
    names = tr.STRATEGIES + tr.CRITERIA
    mc = tr.monte_carlo(setup, 3, names, first_seed=7)
    for name in names:
        np.testing.assert_array_equal(mc[name].noise, mc["best-pair"].noise)
        alone = tr.simulate_batch(setup, name, seeds=[7, 8, 9])
        np.testing.assert_array_equal(mc[name].pairs, alone.pairs)
        # 1e-12: different batch shapes, elementwise operations only (see the test above)
        np.testing.assert_allclose(mc[name].estimate, alone.estimate, rtol=0, atol=1e-12)


def test_criteria_arguments_raise():
    adv_next = ADV.replace(adversary="next-pair", steps=5)
    with pytest.raises(ValueError, match="exact-icn run cannot face a next-pair adversary"):
        tr.simulate(adv_next, "exact-icn")
    with pytest.raises(ValueError, match="exact-icn run cannot face a next-pair adversary"):
        tr.simulate_batch(adv_next, "exact-icn", seeds=[0])
    with pytest.raises(ValueError, match="random strategy draws its pairs from the run's seed"):
        tr.simulate_batch(CIRCLE, "random", noise=tr.noise_table(CIRCLE, 0)[None])


def test_criteria_runs_are_shared_between_metrics_and_log_each_metric_s_bound():
    """A criterion's picks do not depend on the metric: the Euclidean arm reuses the
    Mahalanobis arm's runs and only its logged bound differs, each equal to pair_bound_series
    in its own metric."""
    setup = CIRCLE.replace(steps=30)
    eu = setup.replace(metric="euclidean")
    arms = {(m, n): (su, n) for m, su in (("maha", setup), ("eu", eu)) for n in tr.CRITERIA}
    many = tr.simulate_many(arms, seeds=[0, 1])
    for n in tr.CRITERIA:
        a, b = many[("maha", n)], many[("eu", n)]
        assert b.estimate is a.estimate and b.setup == eu  # one run, two logs
        for r, su, cov in ((a, setup, a.cov), (b, eu, None)):
            want = tr.pair_bound_series(su, r.estimate.reshape(-1, 2), r.pairs.reshape(-1, 2),
                                        None if cov is None else cov.reshape(-1, 2, 2))
            np.testing.assert_allclose(r.bound.ravel(), want, rtol=1e-12)
        alone = tr.simulate_batch(eu, n, seeds=[0, 1])  # the same as running it by itself
        np.testing.assert_array_equal(alone.pairs, b.pairs)
        np.testing.assert_allclose(alone.bound, b.bound, rtol=0, atol=1e-12)


@pytest.mark.parametrize("base", [CIRCLE, ADV], ids=["circle", "adversary"])
def test_exact_icn_shares_a_pass_without_changing_the_runs(base):
    """An exact-icn arm runs in the pass of the other arms (the target moves before the next
    choice, which changes nothing for the others), or in its own pass next to a next-pair
    adversary; every arm equals its run alone and the filterpy engine's run."""
    setup = base.replace(steps=40)
    arms = {s: (setup, s) for s in ("best-pair", "fixed-pair", "exact-icn", "d-optimal")}
    if base.motion == "adversarial":
        arms["next"] = (setup.replace(adversary="next-pair"), "best-pair")
    many = tr.simulate_many(arms, seeds=[3, 4])
    for key, (su, s) in arms.items():
        alone = tr.simulate_batch(su, s, seeds=[3, 4])
        np.testing.assert_array_equal(many[key].pairs, alone.pairs)
        for f in ("bound", "estimate", "cov", "truth"):
            np.testing.assert_allclose(getattr(many[key], f), getattr(alone, f), rtol=0,
                                       atol=1e-12, err_msg=f"{key} {f}")
        r = tr.simulate(su, s, seed=4)
        np.testing.assert_array_equal(many[key].pairs[1], r.pairs)
        np.testing.assert_allclose(many[key].truth[1], r.truth, rtol=0, atol=1e-9)
        np.testing.assert_allclose(many[key].estimate[1], r.estimate, rtol=0, atol=1e-9)

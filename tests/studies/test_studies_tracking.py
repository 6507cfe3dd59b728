"""The shared studies of Sections V-A/V-B (obslib.studies.two_sensors_tracking,
obslib.studies.adversarial_target, obslib.studies.published)."""

from __future__ import annotations

import numpy as np
import pytest

from obslib import tracking as tr
from obslib._validate import ArgumentTypeError
from obslib.studies import adversarial_target, published, two_sensors_tracking

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


def test_partner_study_equals_one_monte_carlo_per_partner():
    setup = CIRCLE.replace(steps=50)
    ps = two_sensors_tracking.partner_study(setup, 3, first_seed=2)
    assert sorted(ps) == [0, 2, 3, 4, 5]
    for j, d in ps.items():
        r = tr.monte_carlo(setup.replace(fixed_pair=(1, j)), 3, ["fixed-pair"], 2)["fixed-pair"]
        run_err = r.error[:, 1:].mean(axis=1)
        assert d["mean_error"] == pytest.approx(run_err.mean(), rel=1e-12)
        assert d["mean_trace"] == pytest.approx(r.trace_cov[:, 1:].mean(), rel=1e-12)
        assert d["mean_bound"] == pytest.approx(r.bound[:, 1:].mean(), rel=1e-12)


def test_stretches_are_the_maximal_runs_of_true():
    rng = np.random.default_rng(1)
    for _ in range(50):
        m = rng.random(rng.integers(0, 40)) < 0.6
        want = []  # scan by hand
        for i, v in enumerate(m):
            if v and (i == 0 or not m[i - 1]):
                want.append([i, i])
            elif v:
                want[-1][1] = i
        got = two_sensors_tracking.stretches(m, first=3, min_length=2)
        assert got == [(a + 3, b + 3) for a, b in want if b - a + 1 >= 2]


def test_window_rates_split_transitions_at_the_window():
    x = np.arange(1.0, 101.0)  # x[k - 1] belongs to transition k -> k + 1
    inside, outside = two_sensors_tracking.window_rates(x, (30, 70))
    assert inside == np.mean(np.arange(30, 70))  # k = 30 .. 69
    assert outside == np.mean(np.r_[np.arange(1, 30), np.arange(70, 101)])


def test_hot_windows_are_other_windows_at_least_as_busy():
    rate = np.zeros(200)
    rate[29:69] = 0.8  # the window k = 30..69
    rate[119:170] = 0.9  # another busy stretch, k = 120..170
    width = 40
    got = two_sensors_tracking.hot_windows(rate, (30, 70))
    starts = [k for k in range(1, 200 - width + 2)
              if rate[k - 1 : k - 1 + width].mean() >= 0.8 - 1e-12 and (k > 70 or k + width < 30)]
    assert got == two_sensors_tracking.stretches(np.isin(np.arange(1, 200), starts), first=1)
    assert got == [(116, 135)]  # windows holding >= 36 of the 0.9 entries (36 * 0.9 >= 32)


def test_best_partners_pick_extremes():
    ps = {0: dict(mean_trace=1.0, mean_error=2.0, median_error=1.0, lost=0.1, mean_bound=0.3),
          2: dict(mean_trace=0.5, mean_error=2.0, median_error=3.0, lost=0.0, mean_bound=0.2),
          3: dict(mean_trace=0.7, mean_error=1.0, median_error=2.0, lost=0.0, mean_bound=0.4)}
    assert two_sensors_tracking.best_partners(ps) == {
        "mean_trace": 2, "mean_error": 3, "median_error": 0, "lost": 2, "mean_bound": 3}


def test_pooled_switch_mechanism_counts_over_all_transitions():
    b = tr.simulate_batch(tr.PAPER_ADVERSARIAL.replace(steps=40), "best-pair", seeds=[0, 1])
    m = adversarial_target.pooled_switch_mechanism(b)
    s = b.setup.sensor_array
    closer = switched_after = switches = raised = 0
    for r in range(2):
        run = b.run(r)
        for k in range(run.steps - 1):
            ps = s[run.pairs[k]]
            before = min(np.hypot(*(run.truth[k] - p)) for p in ps)
            after = min(np.hypot(*(run.truth[k + 1] - p)) for p in ps)
            sw = tuple(run.pairs[k + 1]) != tuple(run.pairs[k])
            switches += sw
            raised += sw and run.true_icn[k + 1] > run.objective[k]
            if after < before:
                closer += 1
                switched_after += sw
    assert m["transitions"] == 2 * 39
    assert m["closer_fraction"] == pytest.approx(closer / 78)
    assert m["switch_if_closer"] == pytest.approx(switched_after / max(closer, 1))
    assert m["switch_fraction"] == pytest.approx(switches / 78)
    assert m["raised"] == pytest.approx(raised / max(switches, 1))


def test_pooled_switch_mechanism_of_runs_without_switches_is_nan_not_zero():
    # a run with a single transition and one switch-free run: the rates over no event are
    # undefined, while those over events that happened are pooled from the runs that had them
    b = tr.simulate_batch(tr.PAPER_ADVERSARIAL.replace(steps=2), "fixed-pair", seeds=[0, 1])
    m = adversarial_target.pooled_switch_mechanism(b)
    assert m["transitions"] == 2 and m["switches"] == 0
    assert np.isnan(m["raised"]) and np.isnan(m["mean_gain"])
    if 0 < m["closer_fraction"]:
        assert m["switch_if_closer"] == 0.0
    else:
        assert np.isnan(m["switch_if_closer"])


def test_near_published_is_a_relative_window_and_zero_is_exact():
    assert published.near_published(0.79 * 1.149, 0.79)
    assert not published.near_published(0.79 * 1.151, 0.79)
    assert published.near_published(0.0, 0) and not published.near_published(1e-9, 0)
    np.testing.assert_array_equal(published.near_published([100, 88, 85], 100, rtol=0.12),
                                  [True, True, False])


def test_study_arguments_of_the_wrong_kind_raise():
    with pytest.raises(ArgumentTypeError, match="n_seeds must be an integer"):
        two_sensors_tracking.partner_study(CIRCLE, 2.5)
    with pytest.raises(ValueError, match="n_seeds must be at least 1"):
        two_sensors_tracking.partner_study(CIRCLE, 0)
    with pytest.raises(ArgumentTypeError, match="first_seed must be an integer, got None"):
        two_sensors_tracking.partner_study(CIRCLE, 2, None)
    with pytest.raises(ValueError, match="first_seed must be at least 0, got -1"):
        two_sensors_tracking.partner_study(CIRCLE, 2, -1)
    with pytest.raises(ArgumentTypeError, match="n_angles must be an integer"):
        adversarial_target.adversary_variants(ADV, 3, 10.0)
    with pytest.raises(ValueError, match="setup must be a TrackingSetup"):
        adversarial_target.adversary_variants({"u_max": 0.1}, 3, 10)

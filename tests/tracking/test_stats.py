"""Statistics of runs (obslib.tracking.stats) against direct computations."""

from __future__ import annotations

import numpy as np
import pytest

from obslib import tracking as tr

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


def test_entrapment_measures_are_consistent():
    r = tr.simulate(ADV, "best-pair")
    e = tr.entrapment(r)
    assert e.reach == pytest.approx(315 * 0.1)
    assert e.path_length <= e.reach + 1e-9
    assert 0 <= e.net_displacement <= e.max_from_start <= e.path_length + 1e-9
    assert e.radius <= e.max_from_start + 1e-9 or e.radius <= 2 * e.max_from_start
    assert 0 <= e.icn_min <= e.icn_mean <= 1
    assert e.switches == r.switches
    assert e.bound_mean == pytest.approx(r.bound.mean())


def test_mirror_point():
    m = tr.mirror_point([[1.0, 1.0]], [0.0, 0.0], [2.0, 0.0])
    np.testing.assert_allclose(m, [[1.0, -1.0]])


def test_spearman_along_either_axis_is_scipys_per_slice():
    """The batched correlation (ranks of rankdata, Pearson along the axis) against spearmanr
    called on each slice (ranks and numpy.corrcoef), ties included."""
    from scipy.stats import spearmanr

    rng = np.random.default_rng(2)
    a = rng.integers(0, 5, (4, 30)).astype(float)  # many ties
    b = rng.normal(size=(4, 30))
    for i in range(4):
        assert tr.spearman(a, b)[i] == pytest.approx(spearmanr(a[i], b[i])[0], abs=1e-12)
    for j in range(30):
        assert tr.spearman(a, b, axis=0)[j] == pytest.approx(spearmanr(a[:, j], b[:, j])[0],
                                                             abs=1e-12, nan_ok=True)
    assert np.isnan(tr.spearman(np.ones(5), np.arange(5.0)))
    assert np.isnan(tr.spearman([1.0, np.nan, 3.0], [1.0, 2.0, 3.0]))


def test_ties_between_strategies_count_for_neither():
    a = np.array([1.0, 2.0, 3.0, 0.0])
    b = np.array([1.0 + 1e-13, 2.5, 3.0 * (1 + 2e-9), 0.0])
    np.testing.assert_array_equal(tr.clearly_lower(a, b), [False, True, True, False])
    np.testing.assert_array_equal(tr.clearly_lower(b, a), [False, False, False, False])
    # a strategy compared with an identical copy of itself wins nowhere
    mc = tr.monte_carlo(CIRCLE.replace(steps=30), 3, first_seed=0)
    same = {
        "best-pair": mc["best-pair"],
        "best-partner": mc["best-pair"],
        "fixed-pair": mc["fixed-pair"],
    }
    assert all(v == 0.0 for v in tr.compare_strategies(same)["wins"]["best-partner"].values())


def test_switch_back_fraction_counts_returns_to_the_previous_pair():
    mc = tr.monte_carlo(CIRCLE.replace(steps=60), 3, first_seed=0)
    b = mc["best-pair"]
    back = switches = 0
    for r in range(b.pairs.shape[0]):
        p = [tuple(x) for x in b.pairs[r]]
        for k in range(1, len(p) - 1):  # transition k -> k + 1, with a step k - 1 before it
            if p[k + 1] != p[k]:
                switches += 1
                back += p[k + 1] == p[k - 1]
    assert switches > 0
    assert tr.switch_back_fraction(b) == back / switches


def test_statistics_name_bad_arguments():
    mc = tr.monte_carlo(CIRCLE.replace(steps=10), 2, ["best-pair", "fixed-pair"])
    with pytest.raises(ValueError, match="reference 'best-partner' is not among"):
        tr.compare_strategies(mc, reference="best-partner")
    with pytest.raises(ValueError, match="mc must be a non-empty dict"):
        tr.compare_strategies({})
    with pytest.raises(ValueError, match="batch must be a BatchResult"):
        tr.switch_rate(mc["best-pair"].run(0))
    with pytest.raises(ValueError, match="threshold must be a finite real number"):
        tr.track_loss(mc["fixed-pair"], threshold="0.5")
    with pytest.raises(ValueError, match="result must be one run"):
        tr.entrapment(mc["best-pair"])


def test_bound_correlation_equals_spearman_of_the_public_series():
    """bound_correlation ranks the bound once and skips pair_bound_series's validation; the
    correlations are spearman's of the validated series."""
    setup = tr.PAPER_CIRCLE.replace(steps=40)
    b = tr.simulate_batch(setup, "best-pair", seeds=[0, 1, 2])
    eu = tr.pair_bound_series(setup, b.estimate.reshape(-1, 2),
                              b.pairs.reshape(-1, 2)).reshape(b.bound.shape)
    for name, bound in (("own", b.bound), ("euclidean", eu)):
        got = tr.bound_correlation(b, name)
        np.testing.assert_allclose(got["error"], tr.spearman(bound[:, 1:], b.error[:, 1:]),
                                   rtol=1e-14)
        np.testing.assert_allclose(got["trace"],
                                   tr.spearman(bound[:, 1:], b.trace_cov[:, 1:]), rtol=1e-14)


def test_track_loss_of_a_shared_path_equals_per_run_paths():
    """The circle's runs share one path (a broadcast view): its mirror image is computed once;
    the losses equal those computed from a copy with one path per run."""
    import dataclasses

    b = tr.simulate_batch(CIRCLE.replace(steps=60), "fixed-pair", seeds=range(6))
    assert b.truth.strides[0] == 0
    own = dataclasses.replace(b, truth=np.ascontiguousarray(b.truth))
    got, want = tr.track_loss(b, 0.3), tr.track_loss(own, 0.3)
    for k in want:
        np.testing.assert_array_equal(got[k], want[k])

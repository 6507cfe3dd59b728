"""The published runs shipped as data (obslib.published_runs), checked against what they must be."""

import numpy as np
import pytest

import obslib.tracking as tr
from obslib.published_runs import RUN_NAMES, published_noise, published_run
from obslib.studies.published import PUBLISHED_ADVERSARIAL, PUBLISHED_CIRCLE


def test_noise_table_shape_and_known_entries():
    t = published_noise()
    assert t.shape == (315, 6)
    assert np.isfinite(t).sum() == 1240
    # the noise of the experiments is N(0, 0.5^2): the recovered values look like it
    v = t[np.isfinite(t)]
    assert abs(v.mean()) < 4 * 0.5 / np.sqrt(v.size)
    assert 0.45 < v.std(ddof=1) < 0.55


def test_known_entries_are_exactly_those_the_three_runs_measured():
    # a run measures its pair at every step; the table knows every such entry and nothing else
    measured = np.zeros((315, 6), bool)
    for name in ("best-pair", "best-partner", "adversarial"):
        p = published_run(name).pairs
        measured[np.arange(315)[:, None], p] = True
    assert np.array_equal(measured, np.isfinite(published_noise()))


def test_noise_recovered_independently_from_one_filter_update():
    # x+ = x- + K (z - h(x-)) with K from the predicted covariance: solve for z by hand and
    # subtract the true half squared range; compare with the table
    run = published_run("best-pair")
    S = np.array(tr.PAPER_CIRCLE.sensors)
    Q = R = 0.5 * np.eye(2)
    t = published_noise()
    for k in (0, 1, 50, 200, 313):
        x, P = run.estimate[k], run.cov[k]
        x_next = run.estimate[k + 1]
        ps = S[run.pairs[k]]
        Pp = P + Q
        H = x - ps
        K = Pp @ H.T @ np.linalg.inv(H @ Pp @ H.T + R)
        hx = 0.5 * ((ps - x) ** 2).sum(1)
        z = hx + np.linalg.solve(K, x_next - x)
        noise = z - 0.5 * ((ps - run.truth[k]) ** 2).sum(1)
        # the log has 12 significant digits; K's condition amplifies its rounding a little
        np.testing.assert_allclose(noise, t[k, run.pairs[k]], atol=1e-8)


def test_headline_numbers_of_the_runs():
    for name in ("best-pair", "best-partner", "fixed-pair"):
        r = published_run(name)
        pub = PUBLISHED_CIRCLE[name]
        assert r.switches == pub["switches"]
        assert round(r.bound.mean(), 2) == pub["mean_bound"]
        assert round(r.error.mean(), 2) == pub["mean_error"]
        assert abs(r.trace_cov.mean() - pub["mean_trace"]) < 5e-4
    a = published_run("adversarial")
    assert a.switches == PUBLISHED_ADVERSARIAL["switches"]
    assert round(a.bound.mean(), 2) == PUBLISHED_ADVERSARIAL["mean_bound"]


def test_first_step_is_the_initial_filter_and_truth_follows_the_model():
    for name in RUN_NAMES:
        r = published_run(name)
        assert r.steps == 315 and r.bound.shape == r.error.shape == r.trace_cov.shape == (315,)
        assert r.trace_cov[0] == pytest.approx(1.0)  # trace of cov0 = 0.5 I
        assert r.error[0] == pytest.approx(np.sqrt(0.5))  # estimate0 is (0.5, +-0.5) off
    truth = tr.circle_truth(tr.PAPER_CIRCLE)
    r = published_run("best-pair")
    np.testing.assert_allclose(r.truth, truth[:315], atol=1e-9)
    np.testing.assert_allclose(r.error, np.hypot(*(r.estimate - r.truth).T), atol=1e-9)
    np.testing.assert_allclose(r.trace_cov, r.cov[:, 0, 0] + r.cov[:, 1, 1], atol=1e-9)
    a = published_run("adversarial")
    np.testing.assert_allclose(a.truth[1:] - a.truth[:-1], a.control[:-1], atol=1e-9)
    np.testing.assert_allclose(np.hypot(*a.control.T), 0.1, atol=1e-9)
    assert (published_run("best-partner").pairs == 1).any(axis=1).all()  # always s2


def test_pairs_are_sorted_zero_based():
    for name in RUN_NAMES:
        p = published_run(name).pairs
        assert p.dtype.kind == "i" and (p[:, 0] < p[:, 1]).all() and p.min() >= 0 and p.max() <= 5


def test_returns_copies():
    t = published_noise()
    t[:] = 0
    assert np.isfinite(published_noise()).sum() == 1240
    r = published_run("adversarial")
    r.bound[:] = 0
    assert published_run("adversarial").bound.mean() > 0.5


@pytest.mark.parametrize("bad", ["strategy-1", "", None, 3, "Best-Pair"])
def test_unknown_run_names_are_rejected_with_the_accepted_ones(bad):
    names = "best-pair, best-partner, fixed-pair, adversarial"
    with pytest.raises(ValueError, match=f"accepted names: {names}"):
        published_run(bad)

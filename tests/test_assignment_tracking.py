"""The assignment-by-tracking study on the tracking engine: its rules' weights vs direct
formulas, the batched greedy vs Algorithm 1, valid assignments, determinism and common random
numbers."""

import numpy as np
import pytest

import obslib as ob
from obslib.assignment import greedy_pair_assignment_literal, greedy_pairs_batch
from obslib.studies import assignment_tracking as at
from obslib.tracking import assigners

SMALL = at.AssignmentTrackingSetup(n_targets=3, steps=12, side=20.0)


def _random_spd(rng, shape):
    A = rng.normal(size=shape + (2, 2))
    return A @ np.swapaxes(A, -1, -2) + 0.2 * np.eye(2)


def _full(w, n):
    """The pair weights ``w`` ``(B, P, L)`` of the pairs i < j as symmetric ``(B, N, N, L)``."""
    ii, jj = np.triu_indices(n, 1)
    W = np.zeros((w.shape[0], n, n, w.shape[2]))
    W[:, ii, jj], W[:, jj, ii] = w, w
    return W


@pytest.mark.parametrize("metric", ob.tracking.METRICS)
def test_bound_weights_equal_pair_bounds(metric):
    """The "bound" rule's weights (the engine's "unique-pairs") are pair_bounds' numbers."""
    rng = np.random.default_rng(2)
    S = rng.uniform(0, 10, size=(4, 6, 2))
    X = rng.uniform(0, 10, size=(4, 3, 2))
    C = _random_spd(rng, (4, 3))
    W = _full(assigners.pair_weights(S, X, C, 1.5, metric == "mahalanobis"), 6)
    for b in range(4):
        want = ob.pair_bounds(S[b], X[b], 1.5, cov=C[b] if metric == "mahalanobis" else None)
        np.testing.assert_allclose(W[b], want, rtol=1e-12, atol=1e-15)


def test_info_gain_equals_log_det_difference():
    """The "d-optimal" rule's weights (the engine's "d-optimal-pairs")."""
    rng = np.random.default_rng(3)
    S = rng.uniform(0, 10, size=(2, 5, 2))
    X = rng.uniform(0, 10, size=(2, 3, 2))
    Pm = _random_spd(rng, (2, 3))
    r = 0.4
    W = _full(assigners.pair_gain_weights(S, X, Pm, r, "half-squared-range"), 5)
    for b in range(2):
        for l in range(3):
            prior = np.linalg.inv(Pm[b, l])
            for i in range(5):
                for j in range(5):
                    if i == j:
                        continue
                    H = X[b, l] - S[b, [i, j]]
                    J = prior + H.T @ H / r
                    want = np.linalg.slogdet(J)[1] - np.linalg.slogdet(prior)[1]
                    assert W[b, i, j, l] == pytest.approx(want, rel=1e-10, abs=1e-12)


def test_batch_greedy_equals_algorithm_1():
    rng = np.random.default_rng(4)
    S = rng.uniform(0, 10, size=(5, 8, 2))
    X = rng.uniform(0, 10, size=(5, 3, 2))
    C = _random_spd(rng, (5, 3))
    ties = rng.integers(0, 3, size=(5, 28, 3)).astype(float)  # the tie rule decides
    ii, jj = np.triu_indices(8, 1)
    for w in (assigners.pair_weights(S, X, C, 1.0, True),
              assigners.pair_gain_weights(S, X, C, 0.5, "half-squared-range"), ties):
        picks, _ = greedy_pairs_batch(w, 8)
        W = _full(w, 8)
        for b in range(5):
            ref = greedy_pair_assignment_literal(W[b])  # the algorithm as printed
            assert sorted(map(tuple, picks[b].tolist())) == sorted(ref.triples)


def test_random_assignments_from_permutation():
    perm = np.array([[3, 1, 0, 2, 5, 4]])
    assert assigners._random_pairs(perm, 2).tolist() == [[1, 0, 1, 0, -1, -1]]


@pytest.mark.parametrize("rule", at.RULES)
def test_assignments_are_valid(rule):
    r = at.run(SMALL.replace(n_sensors=8), rule, [0, 1, 2])
    p = r.pairs
    assert p.shape == (3, SMALL.steps, 3, 2)
    assert (p[..., 0] < p[..., 1]).all() and p.min() >= 0 and p.max() < 8
    flat = p.reshape(3, SMALL.steps, 6)
    for row in flat.reshape(-1, 6):
        assert len(set(row.tolist())) == 6  # no sensor serves two targets


def test_each_rule_maximises_its_own_greedy_objective_per_step():
    """The logged bound / gain are the chosen pairs' weights, so each greedy rule's own total is
    at least a third of the other rule's total of its objective (Theorem 6 bounds the greedy
    against any assignment)."""
    runs = at.run_all(SMALL, [0, 1])
    b, d = runs["bound"], runs["d-optimal"]
    assert (b.bound.sum(-1) >= d.bound.sum(-1) / 3 - 1e-12).all()
    assert (d.gain.sum(-1) >= b.gain.sum(-1) / 3 - 1e-12).all()


def test_determinism_and_batch_independence():
    a = at.run(SMALL, "bound", [4, 7])
    b = at.run(SMALL, "bound", [7])
    assert np.array_equal(a.pairs[1], b.pairs[0])
    np.testing.assert_allclose(a.error[1], b.error[0], rtol=1e-12, atol=1e-12)
    c = at.run(SMALL, "bound", [4, 7])
    assert np.array_equal(a.error, c.error) and np.array_equal(a.pairs, c.pairs)


def test_common_random_numbers():
    runs = at.run_all(SMALL, [0, 1, 2])
    sc = at.scenario(SMALL, [0, 1, 2])
    # step 1 logs the error of the shared initial estimate, identical for every rule
    first = [r.error[:, 0] for r in runs.values()]
    for e in first[1:]:
        assert np.array_equal(e, first[0])
    want = np.hypot(*(sc.estimate0 - sc.start).transpose(2, 0, 1))
    np.testing.assert_allclose(first[0], want, rtol=1e-14)
    # the random rule uses the scenario's permutations, target l taking entries 2l and 2l + 1
    want = np.sort(sc.perm[:, 3, :6].reshape(3, 3, 2), axis=-1)
    assert np.array_equal(runs["random"].pairs[:, 3], want)
    # controls stay in the disc of radius u_max
    assert (np.hypot(*sc.controls.transpose(3, 0, 1, 2)) <= SMALL.u_max).all()


@pytest.mark.parametrize("rule", at.RULES)
def test_filters_are_consistent(rule):
    """The logged error is the prior one (the target has moved since the last update), so its
    mean square should match the filter's own prediction tr(Sigma) + tr(Q) (a NEES check)."""
    setup = SMALL.replace(steps=40)
    r = at.run(setup, rule, range(50))
    ratio = (r.error[:, 10:] ** 2).mean() / (r.trace[:, 10:] + 2 * setup.Q).mean()
    assert 0.8 < ratio < 1.25


@pytest.mark.parametrize(
    "kw",
    [dict(n_targets=0), dict(n_targets=2, n_sensors=3), dict(steps=0), dict(side=-1.0),
     dict(u_max=float("nan")), dict(metric="manhattan"), dict(n_targets=1.5)],
)
def test_bad_setup_raises(kw):
    with pytest.raises(ValueError):
        at.AssignmentTrackingSetup(**kw)


def test_bad_rule_and_seeds_raise():
    with pytest.raises(ValueError, match="rule"):
        at.run(SMALL, "best", [0])
    with pytest.raises(ValueError, match="seeds"):
        at.run(SMALL, "bound", [])
    with pytest.raises(ValueError, match="rule"):
        at.run_all(SMALL, [0], rules=["bound", "x"])


def test_logged_values_are_the_chosen_weights():
    """The logged bound and gain equal the full weight tensors at the chosen pairs."""
    sc = at.scenario(SMALL, [0, 1])
    runs = at._run(sc, list(at.RULES))
    for rule in at.RULES:
        r = runs[rule]
        # replay step 1, whose estimate and covariance are the scenario's
        x0 = sc.estimate0
        P0 = np.broadcast_to(SMALL.p0 * np.eye(2), x0.shape[:2] + (2, 2))
        n = sc.sensors.shape[1]
        Wb = _full(assigners.pair_weights(sc.sensors, x0, P0, SMALL.u_max, True), n)
        Wd = _full(assigners.pair_gain_weights(sc.sensors, x0, P0 + SMALL.Q * np.eye(2), SMALL.R,
                                               "half-squared-range"), n)
        p = r.pairs[:, 0]
        b, l = np.arange(2)[:, None], np.arange(3)[None, :]
        np.testing.assert_allclose(r.bound[:, 0], Wb[b, p[..., 0], p[..., 1], l], rtol=1e-12)
        np.testing.assert_allclose(r.gain[:, 0], Wd[b, p[..., 0], p[..., 1], l], rtol=1e-10)


def test_rules_together_equal_rules_alone():
    together = at.run_all(SMALL, [2, 3])
    for rule in at.RULES:
        alone = at.run(SMALL, rule, [2, 3])
        assert np.array_equal(alone.pairs, together[rule].pairs)
        np.testing.assert_allclose(
            alone.post_error, together[rule].post_error, rtol=1e-12, atol=1e-14
        )


def test_mirrored_uses_the_reflection_across_the_last_pair():
    r = at.run(SMALL, "bound", [0, 1])
    got = r.mirrored()
    S = r.extras["sensors"]
    for b in range(2):
        for l in range(3):
            i, j = r.pairs[b, -1, l]
            m = ob.tracking.mirror_point(r.truth[b, -1, l], S[b, i], S[b, j])
            x, o = r.estimate[b, -1, l], r.truth[b, -1, l]
            assert got[b, l] == (np.hypot(*(x - m)) < np.hypot(*(x - o)))
    assert np.array_equal(r.lost(0.5), r.post_error[:, 1:].mean(axis=1) > 0.5)
    np.testing.assert_allclose(
        np.hypot(*(r.estimate - r.truth).transpose(3, 0, 1, 2)), r.post_error
    )

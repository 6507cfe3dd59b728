"""The pair choosers (obslib.tracking.choosers) against brute-force evaluations of their
formulas."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

import obslib as ob
from obslib import tracking as tr
from obslib.tracking.choosers import PairChooser
from obslib.tracking.choosers import candidates as strategy_candidates

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


def brute_pair_bound(sensors, xhat, cov, i, j, u_max, metric):
    """Theorem 4 with Mahalanobis distances and the Euclidean angle (the published runs), or
    Theorem 1 (SVD) with Euclidean distances."""
    vi, vj = sensors[i] - xhat, sensors[j] - xhat
    if metric == "euclidean":
        return ob.lower_bound(sensors[[i, j]], xhat, u_max)
    prec = np.linalg.inv(cov)
    di, dj = np.sqrt(vi @ prec @ vi), np.sqrt(vj @ prec @ vj)
    cos = vi @ vj / (np.linalg.norm(vi) * np.linalg.norm(vj))
    theta = np.arccos(np.clip(cos, -1, 1))
    return ob.pair_bound_polar(dj / di, theta, u_max / di)


def candidates(setup, strategy):
    n = setup.n_sensors
    if strategy == "best-pair":
        return list(itertools.combinations(range(n), 2))
    if strategy == "best-partner":
        a = setup.anchor
        return [tuple(sorted((a, j))) for j in range(n) if j != a]
    return [tuple(sorted(setup.fixed_pair))]


@pytest.mark.parametrize("metric", ["mahalanobis", "euclidean"])
@pytest.mark.parametrize("strategy", tr.STRATEGIES)
def test_pick_is_brute_force_argmax_at_every_step(runs, strategy, metric):
    r = runs[(strategy, metric)]
    s = r.setup.sensor_array
    cands = candidates(r.setup, strategy)
    for k in range(r.steps):
        vals = np.array([
            brute_pair_bound(s, r.estimate[k], r.cov[k], i, j, r.setup.u_max, metric)
            for i, j in cands
        ])
        best = int(np.argmax(vals))  # first maximum in (i, j) order
        assert r.bound[k] == pytest.approx(vals[best], rel=1e-9, abs=1e-12)
        top2 = np.sort(vals)[-2:] if len(vals) > 1 else vals
        if len(vals) == 1 or top2[1] - top2[0] > 1e-9:
            assert tuple(r.pairs[k]) == cands[best], f"step {k + 1}"
        else:  # a near tie: the pick must be one of the tied maxima
            assert vals[cands.index(tuple(r.pairs[k]))] >= vals[best] - 1e-9


def test_ties_keep_first_maximum():
    # Four sensors symmetric about the estimate: every pair of neighbours scores the same.
    setup = tr.TrackingSetup(
        sensors=((1, 0), (0, 1), (-1, 0), (0, -1)), steps=1, estimate0=(0, 0), anchor=2,
        fixed_pair=(3, 1),
    )
    pairs, b = tr.choose_pairs(setup, "best-pair", [[0.0, 0.0]], np.eye(2)[None])
    assert pairs.tolist() == [[0, 1]]
    pairs, _ = tr.choose_pairs(setup, "best-partner", [[0.0, 0.0]], np.eye(2)[None])
    assert pairs.tolist() == [[1, 2]]  # partners of sensor 2 in index order: 0 (opposite), 1, 3
    pairs, _ = tr.choose_pairs(setup, "fixed-pair", [[0.0, 0.0]], np.eye(2)[None])
    assert pairs.tolist() == [[1, 3]]


@pytest.mark.parametrize("seed", [0, 1])
def test_batch_pair_chooser_equals_pair_bounds_and_brute_force(seed, random_states):
    """PairChooser (no per-step validation, only the candidates' pairs) against
    obslib.pair_bounds and the argmax over each strategy's candidates."""
    rng = np.random.default_rng(seed)
    setup = CIRCLE
    s = setup.sensor_array
    ii, jj = np.triu_indices(s.shape[0], 1)
    n = 300
    x, cov = random_states(rng, n)
    strategies = rng.choice(tr.STRATEGIES, n)
    maha = rng.random(n) < 0.5
    anchors = rng.integers(0, 6, n)
    fixed = [tuple(rng.choice(6, 2, replace=False)) for _ in range(n)]
    setups = [
        setup.replace(anchor=int(a), fixed_pair=f, metric="mahalanobis" if m else "euclidean")
        for a, f, m in zip(anchors, fixed, maha)
    ]
    cand = np.stack([strategy_candidates(su, st_) for su, st_ in zip(setups, strategies)])
    ch = PairChooser(s, cand, maha, setup.u_max**2)
    best, bound = ch(x[:, 0], x[:, 1], cov[:, 0, 0], cov[:, 0, 1], cov[:, 1, 0], cov[:, 1, 1])
    Wm = ob.pair_bounds(s, x, setup.u_max, cov=cov)[ii, jj]  # (P, n)
    We = ob.pair_bounds(s, x, setup.u_max)[ii, jj]
    W = np.where(maha, Wm, We)
    multi = cand.sum(axis=1) > 1
    for r in range(n):
        c = np.flatnonzero(cand[r])
        if not multi[r]:
            assert best[r] == c[0] and np.isnan(bound[r])  # fixed pair: bound filled in later
            continue
        vals = W[c, r]
        want = c[int(np.argmax(vals))]
        top2 = np.sort(vals)[-2:]
        if top2[1] - top2[0] > 1e-12:
            assert best[r] == want
        assert bound[r] == pytest.approx(W[best[r], r], rel=1e-13, abs=1e-15)
        assert W[best[r], r] >= vals.max() - 1e-13
    # the fixed pairs' bound over whole "runs" (here: runs of one step)
    single = np.flatnonzero(~multi)
    np.testing.assert_array_equal(ch.deferred, single)
    fb = ch.deferred_bounds(best[single, None], x[:, None, :], cov[:, None])
    np.testing.assert_allclose(fb[:, 0], W[best[single], single], rtol=1e-13, atol=1e-15)


def test_batch_pair_chooser_rejects_an_estimate_on_a_sensor():
    s = CIRCLE.sensor_array
    cand = np.ones((1, 15), bool)
    ch = PairChooser(s, cand, np.array([True]), 9.0)
    one, zero = np.ones(1), np.zeros(1)
    with pytest.raises(ValueError, match="sits on a sensor"):
        ch(s[2:3, 0].copy(), s[2:3, 1].copy(), one, zero, zero, one)
    with pytest.raises(ValueError, match="not finite"):
        ch(np.array([np.nan]), one, one, zero, zero, one)


def test_mahalanobis_length_is_scale_free():
    """v^T Sigma^-1 v for Sigma of scale 1e-170 (det underflows to 0) and 1e120 (det overflows)
    is the value at scale 1 divided by the scale (to rounding: the scaled path divides by the
    largest entry, a few ulps)."""
    from obslib.tracking.choosers import mahalanobis_sq

    rng = np.random.default_rng(0)
    vx, vy = rng.normal(size=(2, 50))
    A = rng.normal(size=(50, 2, 2))
    c = A @ np.swapaxes(A, 1, 2) + 0.1 * np.eye(2)
    one = mahalanobis_sq(vx, vy, c[:, 0, 0], c[:, 0, 1], c[:, 1, 0], c[:, 1, 1])
    want = np.einsum("ni,nij,nj->n", np.column_stack([vx, vy]), np.linalg.inv(c),
                     np.column_stack([vx, vy]))
    np.testing.assert_allclose(one, want, rtol=1e-10)
    for scale in (1e-170, 1e120):
        cs = c * scale
        got = mahalanobis_sq(vx, vy, cs[:, 0, 0], cs[:, 0, 1], cs[:, 1, 0], cs[:, 1, 1])
        np.testing.assert_allclose(got * scale, one, rtol=1e-12)


# --------------------------------------------------------------------------------------------
# Criteria beyond the paper: each pick against a direct evaluation of its formula
# --------------------------------------------------------------------------------------------


def brute_criterion(name, s, x, P, Q, R, u):
    """Score of every pair (i < j in (i, j) order), higher is better, with numpy.linalg."""
    out = []
    for i, j in itertools.combinations(range(s.shape[0]), 2):
        H = np.array([x - s[i], x - s[j]])
        J = np.linalg.inv(P + Q) + H.T @ np.linalg.inv(R) @ H
        if name == "d-optimal":
            out.append(np.linalg.det(J))
        elif name == "a-optimal":
            out.append(-np.trace(np.linalg.inv(J)))
        elif name == "e-optimal":
            out.append(np.linalg.eigvalsh(J)[0])
        else:  # exact-icn: sigma_min / sigma_max of [x - p_i; x - p_j; u] by SVD
            sv = np.linalg.svd(np.vstack([H, u]), compute_uv=False)
            out.append(sv[-1] / sv[0])
    return np.array(out)


def spd(rng, n, scale):
    A = rng.normal(size=(n, 2, 2))
    return scale * (A @ np.swapaxes(A, 1, 2) + 0.05 * np.eye(2))


@pytest.mark.parametrize("name", ["d-optimal", "a-optimal", "e-optimal", "exact-icn"])
def test_criterion_pick_is_the_brute_force_optimum(name, random_states):
    """PairChooser's closed forms (2 x 2 adjugate, trace, lambda_min; C^-1 from the Gram
    matrix) against numpy.linalg over all pairs at random states, with random Q and R. Where two
    pairs score within 1e-9 (relative) the pick must be one of them."""
    rng = np.random.default_rng(11)
    s = CIRCLE.sensor_array
    n = 200
    x, P = random_states(rng, n)
    Q, R = spd(rng, 1, 0.3)[0], spd(rng, 1, 0.5)[0]
    R = 0.5 * (R + R.T)
    u = rng.normal(scale=0.5, size=(n, 2))
    ch = PairChooser(s, np.ones((n, 15), bool), np.ones(n, bool), 9.0, [name] * n, Q, R)
    best, bound = ch(x[:, 0].copy(), x[:, 1].copy(), P[:, 0, 0].copy(), P[:, 0, 1].copy(),
                     P[:, 1, 0].copy(), P[:, 1, 1].copy(), u, 0)
    assert np.isnan(bound).all()  # the paper's bound of the pick is evaluated afterwards
    np.testing.assert_array_equal(ch.deferred, np.arange(n))
    for r in range(n):
        vals = brute_criterion(name, s, x[r], P[r], Q, R, u[r])
        top = vals.max()
        tol = 1e-9 * max(abs(top), 1e-300)
        if np.sort(vals)[-2] < top - tol:
            assert best[r] == int(np.argmax(vals)), r
        else:
            assert vals[best[r]] >= top - tol
            assert best[r] == int(np.flatnonzero(vals >= top - tol)[0])  # the smallest (i, j)


def test_ties_between_criteria_scores_go_to_the_smallest_pair():
    # Four sensors symmetric about the estimate, isotropic covariance: every neighbouring pair
    # has the same information matrix up to rotation, so the same det, trace and lambda_min.
    sensors = np.array([(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)])
    for name in ("d-optimal", "a-optimal", "e-optimal", "exact-icn"):
        ch = PairChooser(sensors, np.ones((1, 6), bool), [True], 1.0, [name], np.eye(2), np.eye(2))
        one, zero = np.ones(1), np.zeros(1)
        best, _ = ch(zero.copy(), zero.copy(), one, zero, zero, one, np.zeros((1, 2)), 0)
        assert (ch.ii[best[0]], ch.jj[best[0]]) == (0, 1), name


def test_criteria_disagree_somewhere():
    """The criteria are different rules: at some random states D- and E-optimality and the
    bound pick different pairs (each pick checked against its brute-force optimum)."""
    rng = np.random.default_rng(4)
    s = CIRCLE.sensor_array
    Q, R = 0.5 * np.eye(2), 0.5 * np.eye(2)
    seen = set()
    for _ in range(200):
        x = rng.normal([2.0, 2.0], 2.0)
        P = spd(rng, 1, 0.5)[0]
        picks = {}
        for name in ("d-optimal", "e-optimal"):
            picks[name] = int(np.argmax(brute_criterion(name, s, x, P, Q, R, None)))
        W = ob.pair_bounds(s, x[None], 3.0, cov=P[None])[np.triu_indices(6, 1)][:, 0]
        picks["bound"] = int(np.argmax(W))
        seen.add(len(set(picks.values())))
        if len(set(picks.values())) == 3:
            setup = CIRCLE.replace(estimate0=tuple(x), cov0=P, Q=Q, R=R, steps=1)
            for name in ("d-optimal", "e-optimal"):
                got = tr.simulate(setup, name).pairs[0]
                pairs = list(itertools.combinations(range(6), 2))
                assert tuple(got) == pairs[picks[name]], name
            assert tuple(tr.simulate(setup, "best-pair").pairs[0]) == pairs[picks["bound"]]
            break
    else:
        raise AssertionError(f"no state with three different picks; seen {seen}")


def test_random_pairs_follow_the_seeded_draws():
    from obslib.tracking.choosers import pair_draws

    setup = CIRCLE.replace(steps=50)
    r = tr.simulate(setup, "random", seed=3)
    d = pair_draws(3, 50, 15)
    ii, jj = np.triu_indices(6, 1)
    np.testing.assert_array_equal(r.pairs, np.column_stack([ii[d[:50]], jj[d[:50]]]))
    np.testing.assert_array_equal(r.next_pair, [ii[d[50]], jj[d[50]]])
    np.testing.assert_array_equal(r.noise, tr.noise_table(setup, 3))  # noise still common
    counts = np.bincount(pair_draws(0, 14999, 15), minlength=15)
    assert counts.min() > 850 and counts.max() < 1150  # 1000 each; 5 sd = 150
    # the logged bound is the paper's bound of the random pair
    np.testing.assert_allclose(
        r.bound, tr.pair_bound_series(setup, r.estimate, r.pairs, cov=r.cov), rtol=1e-12)


def test_choose_pairs_accepts_tiny_covariances_and_names_bad_ones():
    """A covariance of scale 1e-170 (its determinant underflows) is positive definite; the
    Mahalanobis distances are then ~1e85 and u_max^2 / d^2 vanishes, so the bound is the
    exact C^-1 of the two rows: 1 for the pair (s4, s6), whose rows from (5.5, 3.5) are
    perpendicular and of equal length."""
    pairs, bound = tr.choose_pairs(CIRCLE, "best-pair", [[5.5, 3.5]], 1e-170 * np.eye(2)[None])
    assert pairs.tolist() == [[3, 5]]
    assert bound[0] == pytest.approx(1.0, abs=1e-12)
    bad = np.array([np.eye(2), -np.eye(2)])
    with pytest.raises(ValueError, match=r"cov 1 is not positive definite: \[\[-1.0"):
        tr.choose_pairs(CIRCLE, "best-pair", [[5.5, 3.5], [1.0, 1.0]], bad)
    with pytest.raises(ValueError, match="unknown strategy"):
        tr.choose_pairs(CIRCLE, "psychic", [[5.5, 3.5]], np.eye(2)[None])


@pytest.mark.parametrize("name", ["d-optimal", "a-optimal", "e-optimal", "exact-icn"])
def test_choose_pairs_for_a_criterion_is_the_brute_force_optimum(name, random_states):
    rng = np.random.default_rng(8)
    x, P = random_states(rng, 30)
    u = rng.normal(scale=0.3, size=(30, 2))
    setup = CIRCLE.replace(Q=0.3, R=[[0.6, 0.1], [0.1, 0.4]])
    pairs, bound = tr.choose_pairs(setup, name, x, P, control=u)
    allp = list(itertools.combinations(range(6), 2))
    for r in range(30):
        vals = brute_criterion(name, setup.sensor_array, x[r], P[r], np.array(setup.Q),
                               np.array(setup.R), u[r])
        if np.sort(vals)[-2] < vals.max() - 1e-9 * abs(vals.max()):
            assert tuple(pairs[r]) == allp[int(np.argmax(vals))]
    # the logged bound is the paper's bound of the pick
    np.testing.assert_allclose(bound, tr.pair_bound_series(setup, x, pairs, cov=P), rtol=1e-12)
    with pytest.raises(ValueError, match="no state-based pick"):
        tr.choose_pairs(setup, "random", x, P)
    with pytest.raises(ValueError, match="exact-icn needs the targets' control"):
        tr.choose_pairs(setup, "exact-icn", x, P)


def test_icn_picks_equal_argmax_of_the_exact_scores():
    """The oracle's screened pick is the first maximiser of icn_scores, also on symmetric
    scenes (ties), with zero controls, on a baseline, and at extreme scales."""
    from obslib.tracking.choosers import _icn_picks, icn_scores

    rng = np.random.default_rng(9)
    s = tr.PAPER_CIRCLE.sensor_array
    ii, jj = np.triu_indices(len(s), 1)
    M = 600
    x = rng.normal([4.0, 3.0], 3.0, size=(M, 2))
    x[:50] = s[0] + rng.random((50, 1)) * (s[1] - s[0])  # on a baseline
    x[50:100] = s.mean(axis=0)  # the centre of the scene
    u = rng.normal(0.0, 0.3, size=(M, 2))
    u[::3] = 0.0  # the first step has no control
    hx, hy = x[:, 0, None] - s[:, 0], x[:, 1, None] - s[:, 1]
    for scale in (1.0, 1e-120, 1e120):
        got = _icn_picks(hx * scale, hy * scale, u * scale, ii, jj)
        want = icn_scores(hx * scale, hy * scale, u * scale, ii, jj).argmax(axis=1)
        np.testing.assert_array_equal(got, want)
    # a square of sensors seen from its centre: many exact ties, the first pair must win
    sq = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    a, b = np.triu_indices(4, 1)
    hx, hy = 1.0 - sq[:, 0][None], 1.0 - sq[:, 1][None]
    for ctrl in ([0.0, 0.0], [0.3, 0.0], [0.2, 0.2]):
        c = np.array([ctrl])
        assert _icn_picks(hx, hy, c, a, b)[0] == icn_scores(hx, hy, c, a, b).argmax(axis=1)[0]

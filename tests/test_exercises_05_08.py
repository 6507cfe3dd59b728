"""The exercises of chapters 05-08: every number a solution states, recomputed another way (by
hand formulas, by brute force, or with the other engine) and held against the chapter's
function that glues it."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from obslib import tracking as tr
from obslib.formatting import count, number, span

# ---------------------------------------------------------------- capture what a chapter glues


@pytest.fixture
def glued(monkeypatch):
    """The texts the chapters' functions glue, name -> text, captured instead of glued."""
    import obsbook.chapters.adversarial_target as ch06
    import obsbook.chapters.general_assignment as ch08
    import obsbook.chapters.greedy_vs_relaxed as ch07
    import obsbook.chapters.two_sensors_tracking as ch05

    texts = {}

    def capture(**kw):
        texts.update(kw)
        return kw

    for mod in (ch05, ch06, ch07, ch08):
        monkeypatch.setattr(mod, "glue_texts", capture)
    return texts


def _distance_to_line(points, a, b):
    """Distance of each point to the line through ``a`` and ``b``, by the cross product."""
    d = np.asarray(b, float) - np.asarray(a, float)
    rel = np.asarray(points, float) - np.asarray(a, float)
    return np.abs(rel[..., 0] * d[1] - rel[..., 1] * d[0]) / np.hypot(*d)


# ---------------------------------------------------------------- 05: the fixed pair's baseline


def test_05_baseline_by_hand_is_the_circle_s_closest_step(glued):
    from obsbook.chapters.two_sensors_tracking import baseline_approach, glue_exercise_baseline

    setup = tr.PAPER_CIRCLE
    a = baseline_approach(setup)
    # by hand: the centre (2, 3) lies 13 / sqrt(13) = sqrt(13) from the line through the origin
    # and (-3, 2), whose normal is (2, 3) / sqrt(13)
    assert a["center_distance"] == pytest.approx(math.sqrt(13), rel=1e-12)
    assert a["closest"] == pytest.approx(math.sqrt(13) - 3, rel=1e-12)
    # brute force: the true path, one point per step, and a fine sampling of the circle
    path = tr.circle_truth(setup.replace(steps=400))
    s = setup.sensor_array
    dist = _distance_to_line(path, s[1], s[0])
    assert a["step"] == int(np.argmin(dist)) + 1 == 207
    phi = np.linspace(0, 2 * np.pi, 2_000_001)
    circle = np.array(setup.center) + setup.radius * np.column_stack([np.cos(phi), np.sin(phi)])
    fine = _distance_to_line(circle, s[1], s[0])
    assert fine.min() == pytest.approx(a["closest"], abs=1e-9)
    assert phi[fine.argmin()] == pytest.approx(a["angle"], abs=1e-5)

    loss = {"lost": np.array([True, False, True]), "flip_step": np.array([190, 0, 240])}
    glue_exercise_baseline(setup, loss)
    assert glued["ex_closest"] == number(math.sqrt(13) - 3) == "0.606"
    assert glued["ex_step"] == "207" and glued["ex_step_real"] == "207.2"
    assert "between 190 and 240" in glued["ex_when"]
    glue_exercise_baseline(setup.replace(steps=100), loss)
    assert "never gets there" in glued["ex_when"]


def test_05_baseline_refuses_a_circle_that_crosses_the_line():
    from obsbook.chapters.two_sensors_tracking import baseline_approach

    with pytest.raises(ValueError, match="crosses the baseline"):
        baseline_approach(tr.PAPER_CIRCLE.replace(radius=4.0))


def test_05_half_noise_counts_the_lost_runs_of_the_reference_engine(glued):
    from obsbook.chapters.two_sensors_tracking import glue_exercise_noise

    setup = tr.PAPER_CIRCLE.replace(steps=240)
    n, seed = 6, 3
    out = glue_exercise_noise(setup, n, seed, lost_above=0.5)
    for sd in (0.5, 0.25):
        # the reference engine, one run at a time, and the definition of a lost run
        runs = [tr.simulate(setup.replace(noise_std=sd), s, seed=k)
                for s in tr.STRATEGIES for k in range(seed, seed + n)]
        by = {s: runs[i * n:(i + 1) * n] for i, s in enumerate(tr.STRATEGIES)}
        lost = sum(r.error.mean() > 0.5 for r in by["fixed-pair"])
        assert out[sd]["lost"] == lost
        for s in tr.STRATEGIES:  # mean error over steps 2.. and over the runs
            mean = np.mean([r.error[1:].mean() for r in by[s]])
            assert out[sd]["mean_error"][s] == pytest.approx(mean, rel=1e-6)
    assert glued["ex_lost_half"] == count(out[0.25]["lost"], of=n)
    assert glued["ex_half"] == "0.25"


# ---------------------------------------------------------------- 06: the valley, a slow target


def test_06_valley_by_hand_against_brute_force(glued):
    from obsbook.chapters.adversarial_target import glue_exercise_valley, valley_steps

    setup = tr.PAPER_ADVERSARIAL
    v = valley_steps(setup)
    assert v["distance"] == pytest.approx(10 / math.sqrt(13), rel=1e-12)  # |(2,3).(2,2)|/sqrt13
    t = np.linspace(-50, 50, 2_000_001)[:, None]
    line = t * np.array([-3.0, 2.0])  # the line through s2 = (0, 0) and s1 = (-3, 2)
    assert np.hypot(*(line - np.array(setup.start)).T).min() == pytest.approx(
        v["distance"], abs=1e-6)
    assert v["moves"] == math.ceil(v["distance"] / setup.u_max) == 28
    assert valley_steps(setup.replace(u_max=10 / math.sqrt(13) / 7))["moves"] == 7

    # the first step below the level, from a run of the reference engine
    run = tr.simulate(setup.replace(steps=120), "fixed-pair", seed=0)
    first = next(k for k in range(2, run.steps + 1) if run.true_icn[k - 1] < 0.01)
    got = glue_exercise_valley(setup, run)
    assert got["first"] == first and glued["ex_first"] == f"at step {first}"
    assert glued["ex_moves"] == "28" and glued["ex_dist"] == "2.77"
    short = tr.simulate(setup.replace(steps=5), "fixed-pair", seed=0)
    assert glue_exercise_valley(setup, short)["first"] is None
    assert glued["ex_first"] == "at none of the 5 steps"


def test_06_slow_target_conditions_checked_one_by_one(glued):
    from obsbook.chapters.adversarial_target import glue_exercise_slow

    setup = tr.PAPER_ADVERSARIAL.replace(steps=150)
    n = 3
    out = glue_exercise_slow(setup, n, 0)
    slow = setup.u_max / 4
    es = [tr.entrapment(tr.simulate(setup.replace(u_max=slow), "best-pair", seed=k))
          for k in range(n)]
    reach = 150 * slow  # the most a target at the slow speed can travel
    far = [e.max_from_start > 0.2 * reach for e in es]
    low_bound = [e.bound_mean < 0.5 for e in es]
    low_icn = [e.icn_min < 0.1 for e in es]
    held = [not (a or b or c) for a, b, c in zip(far, low_bound, low_icn)]
    assert out[slow]["entrapped"] == pytest.approx(np.mean(held))
    assert out[slow]["reach"] == pytest.approx(reach)
    assert glued["ex_fail_reach"] == count(sum(far), of=n)
    assert glued["ex_fail_bound"] == count(sum(low_bound), of=n)
    assert glued["ex_fail_icn"] == count(sum(low_icn), of=n)
    assert glued["ex_radius_slow"] == number(0.2 * reach)
    assert glued["ex_icn_slow"] == number(min(e.icn_min for e in es))


# ---------------------------------------------------------------- 07: by hand, loose, speed


def _brute_force(W):
    """Greedy by hand, the optimum of Problem 1 and of Problem 3 for two targets, by
    enumeration."""
    n = W.shape[0]
    pairs = list(itertools.combinations(range(n), 2))
    triples = sorted(((W[i, j, l], i, j, l) for i, j in pairs for l in range(2)), reverse=True)
    w1, i1, j1, l1 = triples[0]
    w2 = max(W[i, j, 1 - l1] for i, j in pairs if not {i, j} & {i1, j1})
    opt = max(W[a[0], a[1], 0] + W[b[0], b[1], 1]
              for a in pairs for b in pairs if not set(a) & set(b))
    rel = max(W[a[0], a[1], 0] + W[b[0], b[1], 1] for a in pairs for b in pairs if a != b)
    return w1 + w2, opt, rel


def test_07_hand_instance_against_enumeration(glued):
    from obsbook.chapters.greedy_vs_relaxed import _example_trial, glue_exercise_hand

    (trial, W, res), six = glue_exercise_hand(0, 100.0, 1.0)
    g, opt, rel = _brute_force(W)
    assert res["greedy"].value == pytest.approx(g, rel=1e-12)
    assert res["optimal"].value == pytest.approx(opt, rel=1e-12)
    assert res["relaxed"].value == pytest.approx(rel, rel=1e-12)
    assert max(v for _, v in six) == pytest.approx(opt, rel=1e-12) and len(six) == 6
    assert trial != _example_trial(0, 100.0, 1.0, 30)[0] and g < opt  # another, greedy not optimal
    assert glued["exh_g"] == number(g) and glued["exh_o"] == number(opt)
    assert glued["exh_r"] == number(rel)
    assert "$s_{" in glued["exh_shared"]


@pytest.mark.parametrize("L", [2, 3, 4, 5])
def test_07_loose_instance_by_hand(L, glued):
    from obsbook.chapters.greedy_vs_relaxed import glue_exercise_loose, loose_instance

    W, res = loose_instance(L)
    # by hand: one pair with s1 for Problem 1, L pairs with s1 for Problem 3
    assert [res[k].value for k in ("greedy", "optimal", "relaxed")] == pytest.approx([1, 1, L])
    assert all(0 in t[:2] for t in res["relaxed"].triples)
    sweep = {"greedy": np.array([[1.0, 2.0], [3.0, 1.0]]),
             "relaxed": np.array([[2.0, 3.0], [4.0, 4.0]]), "L": np.array([1, 2])}
    glue_exercise_loose(sweep, L)
    assert glued["exl_ratio"] == number(1 / L) and glued["exl_r"] == number(float(L))
    assert glued["exl_min"] == number(0.25) and glued["exl_min_L"] == "2"
    with pytest.raises(ValueError, match="n_targets"):
        loose_instance(1)


def test_07_speed_ratio_from_single_instances(glued):
    from obsbook.chapters.greedy_vs_relaxed import glue_exercise_speed
    from obslib import greedy_pair_assignment, pair_bounds, relaxed_pair_assignment
    from obslib.studies.greedy_vs_relaxed import fig8_instance, fig8_summary, fig8_sweep

    L_max, trials = 4, 3
    base = fig8_summary(fig8_sweep(range(1, L_max + 1), trials, 0, 1.0, 100.0))
    out = glue_exercise_speed(base, L_max, trials, 0, 1.0, 100.0)
    assert sorted(out) == [2, 4]
    for L in (2, 4):  # the mean totals over the instances, one assignment at a time
        for k, u in enumerate((1.0, 10.0)):
            g = r = 0.0
            for t in range(trials):
                W = pair_bounds(*fig8_instance(L, t, 0, 100.0), u)
                g += greedy_pair_assignment(W).value
                r += relaxed_pair_assignment(W).value
            assert out[L][k] == pytest.approx(g / r, rel=1e-12)
    assert glued["exs_2"] == number(out[2][1]) and glued["exs_last0"] == number(out[4][0])
    assert glued["exs_u"] == "10" and glued["exs_L"] == "4"


# ---------------------------------------------------------------- 08: gains by hand, the prior


@pytest.mark.parametrize("eps", [1.0, 0.5, 100.0])
def test_08_gains_by_the_determinant_lemma(eps, glued):
    from obsbook.chapters.general_assignment import (
        HAND_SENSORS,
        HAND_TARGET,
        glue_exercise_gains,
    )
    from obslib.teams import greedy_team_assignment

    rounds = glue_exercise_gains(eps)
    v = np.array(HAND_TARGET) - np.array(HAND_SENSORS)  # rows o - p
    # round 1: log(1 + |v|^2 / eps)
    first = {i: math.log1p(v[i] @ v[i] / eps) for i in range(3)}
    assert rounds[0]["gains"] == pytest.approx(first, rel=1e-12)
    team, G = [], eps * np.eye(2)
    for r in rounds:  # each gain log(1 + w^T G^-1 w), and the slogdet of the grown matrix
        for i, gain in r["gains"].items():
            lemma = math.log1p(v[i] @ np.linalg.solve(G, v[i]))
            direct = (np.linalg.slogdet(G + np.outer(v[i], v[i]))[1]
                      - np.linalg.slogdet(G)[1])
            assert gain == pytest.approx(lemma, rel=1e-9) == pytest.approx(direct, rel=1e-9)
        team.append(r["pick"])
        G = G + np.outer(v[r["pick"]], v[r["pick"]])
    assert team == greedy_team_assignment(HAND_SENSORS, [HAND_TARGET], "logdet", eps)[0]
    assert team == [1, 0, 2]
    if eps == 1.0:  # the solution's numbers: log 10, log 17, log 10, then log(1 + 9/10)
        assert glued["exg_r1_s2"] == number(math.log(17)) == "2.83"
        assert glued["exg_r2_s1"] == glued["exg_r2_s3"] == number(math.log(10))
        assert glued["exg_r3_s3"] == number(math.log(1.9)) == "0.642"


def test_08_prior_spread_against_the_binomial_baseline(glued):
    from obsbook.chapters.general_assignment import glue_exercise_prior
    from obslib.studies import general_assignment

    N, trials, L = np.array([10, 12]), 3, 2
    counts = general_assignment.fig9_sweep(N, trials, 0, L, "logdet", 1.0, 100.0)
    text = {None: general_assignment.evenness(counts, N, L)}
    even = text[None]
    big = glue_exercise_prior(N, trials, 0, L, 100.0, 1.0, text, even)
    counts = general_assignment.fig9_sweep(N, trials, 0, L, "logdet", 1e4, 100.0)
    # by hand: the standard deviation of a trial's counts, averaged over the trials, over that
    # of a binomial count, sqrt(N (1/L)(1 - 1/L))
    rel = counts.std(axis=2).mean(axis=1) / np.sqrt(N * (1 / L) * (1 - 1 / L))
    assert big.relative == pytest.approx(rel, rel=1e-12)
    assert glued["exp_span"] == span(rel.min(), rel.max())
    assert glued["exp_above"] == count(int((rel >= 1).sum()), of=2)
    assert glued["exp_eps"] == "10,000" and glued["exp_factor"] == "10,000"

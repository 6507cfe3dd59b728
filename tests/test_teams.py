"""Greedy teams (Problem 2): the greedy rule evaluated directly, the exact optimum, the 1/2
bound."""

import numpy as np
import pytest

import obslib as ob
from obslib.measures import measure as w
from obslib.teams import greedy_team_assignment, optimal_team_assignment, team_value


def direct_greedy(S, T, name, eps):
    """The greedy rule by direct evaluation of the measure: every round, every (sensor, target)."""
    teams = [[] for _ in T]
    free = list(range(len(S)))
    while free:
        best = None
        for i in free:
            for l in range(len(T)):
                gain = w(S[teams[l] + [i]], T[l], name, eps) - w(S[teams[l]], T[l], name, eps)
                if best is None or gain > best[0] + 1e-12:
                    best = (gain, i, l)
        _, i, l = best
        teams[l].append(i)
        free.remove(i)
    return teams


@pytest.mark.parametrize("name", ["logdet", "trace", "neg_trace_inverse", "rank"])
def test_greedy_equals_direct_evaluation_of_the_rule(name):
    rng = np.random.default_rng(0)
    for _ in range(40):
        S = rng.uniform(0, 100, size=(int(rng.integers(3, 9)), 2))
        T = rng.uniform(0, 100, size=(int(rng.integers(1, 4)), 2))
        assert greedy_team_assignment(S, T, name, eps=1.0) == direct_greedy(S, T, name, 1.0)


def test_greedy_is_within_half_of_the_optimum_for_logdet():
    rng = np.random.default_rng(1)
    worst = 1.0
    for _ in range(60):
        S = rng.uniform(0, 100, size=(int(rng.integers(3, 8)), 2))
        T = rng.uniform(0, 100, size=(int(rng.integers(1, 4)), 2))
        teams = greedy_team_assignment(S, T, "logdet", eps=1.0)
        _, opt = optimal_team_assignment(S, T, "logdet", eps=1.0)
        g = team_value(S, T, teams, "logdet", eps=1.0)
        # with eps = 1 the empty team has logdet 0, so values are non-negative and the ratio is
        # meaningful
        assert g <= opt + 1e-9
        assert g >= 0.5 * opt - 1e-9
        worst = min(worst, g / opt)
    assert worst <= 1.0


def test_optimum_equals_brute_force_over_team_values():
    rng = np.random.default_rng(2)
    S = rng.uniform(0, 100, size=(5, 2))
    T = rng.uniform(0, 100, size=(2, 2))
    teams, value = optimal_team_assignment(S, T, "logdet", eps=1.0)
    assert value == pytest.approx(team_value(S, T, teams, "logdet", eps=1.0))
    best = max(
        team_value(
            S,
            T,
            [[i for i in range(5) if (k >> i) & 1], [i for i in range(5) if not (k >> i) & 1]],
            "logdet",
            eps=1.0,
        )
        for k in range(32)
    )
    assert value == pytest.approx(best)


def test_every_sensor_is_assigned_once():
    rng = np.random.default_rng(3)
    S, T = rng.uniform(0, 100, (20, 2)), rng.uniform(0, 100, (5, 2))
    teams = greedy_team_assignment(S, T)
    assert sorted(i for t in teams for i in t) == list(range(20))


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"measure": "trace_inverse"}, "decreases"),
        ({"measure": "logdet", "eps": 0.0}, "eps > 0"),
        ({"measure": "volume"}, "unknown measure"),
        ({"eps": -1.0}, "eps"),
    ],
)
def test_bad_arguments(kwargs, message):
    with pytest.raises(ValueError, match=message):
        greedy_team_assignment([[0, 0], [1, 1]], [[5, 5]], **kwargs)


def test_bad_geometry():
    with pytest.raises(ValueError, match="sensor 1 has a non-finite"):
        greedy_team_assignment([[0, 0], [np.nan, 1]], [[5, 5]])
    with pytest.raises(ValueError, match="at least one target"):
        greedy_team_assignment([[0, 0], [1, 1]], np.zeros((0, 2)))
    with pytest.raises(ValueError, match="too many"):
        optimal_team_assignment(
            np.random.default_rng(0).uniform(0, 9, (30, 2)), [[50, 50], [60, 60]]
        )
    assert ob.greedy_team_assignment is greedy_team_assignment


def test_batched_counts_equal_single_instances():
    from obslib.teams import greedy_team_counts

    rng = np.random.default_rng(4)
    for name, eps in [("logdet", 1.0), ("trace", 0.0), ("neg_trace_inverse", 0.5), ("rank", 0.0)]:
        S, T = rng.uniform(0, 100, (12, 9, 2)), rng.uniform(0, 100, (12, 3, 2))
        counts = greedy_team_counts(S, T, name, eps)
        single = [[len(t) for t in greedy_team_assignment(s, t, name, eps)] for s, t in zip(S, T)]
        np.testing.assert_array_equal(counts, single)
    with pytest.raises(ValueError, match="coincide"):
        greedy_team_counts(np.zeros((1, 2, 2)), np.ones((1, 1, 2)))


def test_batched_picks_are_the_single_instance_teams_in_order():
    from obslib.teams import greedy_team_picks

    rng = np.random.default_rng(5)
    S, T = rng.uniform(0, 100, (8, 7, 2)), rng.uniform(0, 100, (8, 3, 2))
    picks_i, picks_l = greedy_team_picks(S, T, "logdet", 1.0)
    for k in range(len(S)):
        teams = greedy_team_assignment(S[k], T[k], "logdet", 1.0)
        rebuilt = [
            [int(i) for i, l in zip(picks_i[k], picks_l[k]) if l == target] for target in range(3)
        ]
        assert rebuilt == teams
    with pytest.raises(ValueError, match="unknown measure"):
        greedy_team_picks(S, T, "volume")


def test_best_labelling_equals_a_loop_over_all_labellings():
    from itertools import product

    from obslib.teams import best_team_labelling

    rng = np.random.default_rng(6)
    n, n_targets, batch = 4, 3, 5
    tables = rng.normal(size=(n_targets, batch, 2**n))
    labels, total = best_team_labelling(tables)
    for b in range(batch):
        best = None
        for lab in product(range(n_targets), repeat=n):  # lexicographic: the first best wins ties
            value = sum(
                tables[l, b, sum(1 << i for i in range(n) if lab[i] == l)] for l in range(n_targets)
            )
            if best is None or value > best[0]:
                best = (value, lab)
        assert tuple(labels[b]) == best[1]
        assert total[b] == pytest.approx(best[0], rel=1e-12)
    for bad, message in [(np.zeros((2, 6)), "2\\*\\*N"), (np.zeros(4), "shape"),
                         (np.full((1, 4), np.nan), "NaN"), (np.zeros((3, 2**14)), "too many")]:
        with pytest.raises(ValueError, match=message):
            best_team_labelling(bad)


def test_batch_vectors_equal_relative_vectors_and_raise_the_same_errors():
    from obslib.bounds import relative_vectors
    from obslib.teams import _batch_vectors

    rng = np.random.default_rng(30)
    S, T = rng.uniform(0, 100, (7, 9, 2)), rng.uniform(0, 100, (7, 3, 2))
    np.testing.assert_array_equal(
        _batch_vectors(S, T), np.stack([relative_vectors(s, t) for s, t in zip(S, T)])
    )
    bad = [(S.copy(), T.copy()) for _ in range(3)]
    bad[0][0][4, 2] = bad[0][0][4, 5]  # two sensors coincide in instance 4
    bad[1][0][2, 1] = T[2, 0]  # a sensor on a target
    bad[2][0][6, 0, 0], bad[2][1][6, 1, 0] = 1.7e308, -1.7e308  # a difference overflows
    for bs, bt in bad:
        with pytest.raises(ValueError) as got:
            _batch_vectors(bs, bt)
        k = next(k for k in range(7) if (bs[k] != S[k]).any())
        with pytest.raises(ValueError) as want:
            relative_vectors(bs[k], bt[k])
        assert str(got.value) == str(want.value)

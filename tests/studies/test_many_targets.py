"""The studies of many targets (obslib.studies.many_targets): each number recomputed another
way from the runs, the saved run's checks, and one computation shared by its callers."""

from __future__ import annotations

import numpy as np
import pytest

from obslib import tracking as tr
from obslib.later_experiment import saved_run
from obslib.studies import criteria
from obslib.studies import many_targets as mt

N_SEEDS = 8


def test_saved_comparison_ranks_the_saved_values_among_our_runs():
    c = mt.saved_comparison(N_SEEDS)
    runs = mt.later_runs(N_SEEDS, assignments=tuple(c))
    for name, d in c.items():
        b = runs[name]
        teams = [b.run(r).teams for r in range(N_SEEDS)]
        saved = saved_run(name)
        for row in d["rows"]:
            l = row["target"] - 1
            if row["statistic"] == "mean_error":
                ours, theirs = b.error[:, 1:, l].mean(axis=1), saved.error[1:, l].mean()
            elif row["statistic"] == "mean_trace":
                ours, theirs = b.trace_cov[:, 1:, l].mean(axis=1), saved.trace_cov[1:, l].mean()
            else:  # steps 1..99 without a sensor, ours from the teams, theirs from the trace
                ours = np.array([sum(len(team[l]) == 0 for team in teams[r][:99])
                                 for r in range(N_SEEDS)])
                theirs = saved.unobserved()[:, l].sum()
            assert row["saved"] == pytest.approx(theirs, rel=1e-12)
            assert row["below"] == np.mean(ours < theirs)
            assert row["above"] == np.mean(ours > theirs)
            assert row["ours_median"] == pytest.approx(np.median(ours))
        # the trace after the first update does not depend on the noise, and is the saved one
        assert d["step2_same_every_seed"] and d["step2_max_rel_diff"] < 5e-6


def test_the_code_s_first_step_explains_the_saved_run():
    """Only the code's arithmetic with the fused update, read by rounds, gives the saved trace
    after the first update; without the fused update, as in exact arithmetic, the first target
    takes every sensor."""
    c = mt.code_treatment(N_SEEDS)
    saved = c["saved_step2"]
    code = c["first_step"]["code"]
    np.testing.assert_allclose(code["trace_rounds"], saved, rtol=5e-6)
    assert not np.allclose(code["trace_picked"], saved, rtol=1e-3)
    for arithmetic in ("code-unfused", "exact"):
        assert c["first_step"][arithmetic]["picked"] == [list(range(8)), [], []]
    # the first update's trace with a team, by filterpy's equations written out here
    su = tr.LATER_MULTI_TARGET
    team = code["rounds"][1]
    x0 = np.array(su.estimate0[1])
    P = np.array(su.cov0) + np.array(su.Q)
    d = x0 - su.sensor_array[team]
    H = d / np.hypot(d[:, 0], d[:, 1])[:, None]
    K = P @ H.T @ np.linalg.inv(H @ P @ H.T + su.R * np.eye(len(team)))
    A = np.eye(2) - K @ H
    assert np.trace(A @ P @ A.T + su.R * K @ K.T) == pytest.approx(code["trace_rounds"][1])


def test_team_sizes_are_counted_from_the_teams():
    c = mt.code_treatment(N_SEEDS)
    runs = mt.later_runs(N_SEEDS, assignments=("logdet-teams",))
    b = runs["logdet-teams"]
    sizes = np.array([[[len(t) for t in b.run(r).teams[k]] for k in range(b.steps)]
                      for r in range(N_SEEDS)])
    got = c["team_sizes"]["logdet-teams"]
    assert got["share_none"] == pytest.approx((sizes == 0).mean())
    assert got["mean_size"] == pytest.approx(8 / 3)  # every sensor is given to some target
    longest = [max((len(s) for s in "".join("x" if z == 0 else "." for z in sizes[r, :, l])
                    .split(".")), default=0) for r in range(N_SEEDS) for l in range(3)]
    assert got["longest_without"] == pytest.approx(np.mean(longest))


def test_comparison_rows_are_the_paired_tests_of_the_run_means():
    names = ("unique-pairs", "random", "d-optimal-teams", "logdet-teams-exact")
    rows = mt.later_comparison(N_SEEDS, assignments=names)
    runs = mt.later_runs(N_SEEDS, assignments=names)
    ref = runs["unique-pairs"].error[:, 1:].mean(axis=1)  # (B, L)
    for row in rows:
        b = runs[row["assignment"]]
        err = b.error[:, 1:].mean(axis=1)
        pick = (lambda a: a.mean(axis=1)) if row["target"] == "all" else (
            lambda a, t=row["target"]: a[:, t - 1])
        assert row["mean_error"] == pytest.approx(pick(err).mean())
        lost = err > tr.LOSS_THRESHOLD
        assert row["lost"] == (lost.sum() if row["target"] == "all"
                               else lost[:, row["target"] - 1].sum())
        if row["assignment"] != "unique-pairs":
            want = criteria.paired_test(pick(ref), pick(err))
            assert row["vs_p_wilcoxon"] == pytest.approx(want["p_wilcoxon"])
            assert row["vs_reference_better"] == want["reference_better"]
    exact = [r for r in rows if r["assignment"] == "logdet-teams-exact"]
    assert [r["unobserved"] for r in exact] == [0.0, 100.0, 100.0, 200.0]


def test_the_studies_share_one_computation():
    names = ("unique-pairs", "random")
    assert mt.later_runs(N_SEEDS, assignments=names)["random"] is mt.later_runs(
        N_SEEDS, assignments=("random",))["random"]
    a = mt.later_comparison(N_SEEDS, assignments=names)
    assert a is mt.later_comparison(N_SEEDS, assignments=["unique-pairs", "random"])


def test_network_comparison_pairs_runs_by_scene():
    names = ("unique-pairs", "d-optimal-teams")
    rows = mt.network_comparison(16, 4, n_scenes=3, steps=12, assignments=names)
    runs = mt.network_runs(16, 4, n_scenes=3, steps=12, assignments=names)
    for s in range(3):
        one = tr.simulate_targets(tr.network_scene(16, 4, steps=12, seed=s), "d-optimal-teams",
                                  seed=s)
        np.testing.assert_array_equal(runs["d-optimal-teams"].labels[s], one.labels)
    row = [r for r in rows if r["assignment"] == "d-optimal-teams" and r["target"] == "all"][0]
    err = runs["d-optimal-teams"].error[:, 1:].mean(axis=(1, 2))
    assert row["n"] == 3 and row["mean_error"] == pytest.approx(err.mean())


def test_bad_arguments_are_named():
    with pytest.raises(ValueError, match="n_seeds must be at least 2"):
        mt.later_runs(1)
    with pytest.raises(ValueError, match="unknown name 'greedy'"):
        mt.later_comparison(4, assignments=("unique-pairs", "greedy"))
    with pytest.raises(ValueError, match="must include the reference"):
        mt.later_comparison(4, assignments=("random",))
    with pytest.raises(ValueError, match="two sensors per target"):
        mt.network_runs(10, 6, n_scenes=1, steps=5)
    with pytest.raises(ValueError, match="optimal-pairs"):
        mt.network_runs(200, 50, n_scenes=1, steps=5, assignments=("optimal-pairs",))
    with pytest.raises(ValueError, match="TargetsBatch"):
        mt.run_statistics({"error": 1})

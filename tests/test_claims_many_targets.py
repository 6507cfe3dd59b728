"""The ledger's entries on the authors' later experiment (obslib.claims.many_targets): each
number recomputed another way, from the saved data file read here, from our runs' teams, by the
filter's equations written out, by a plain greedy and by scipy's paired tests."""

from __future__ import annotations

import csv
from importlib import resources

import numpy as np
import pytest
from scipy import stats

from obslib import claims
from obslib import tracking as tr
from obslib.claims import many_targets as lm
from obslib.studies import many_targets as mt

IDS = ("later-unique-pairs", "later-teams-unobserved", "later-teams-vs-pairs",
       "later-code-singular", "later-code-rounds", "beyond-many-targets")


@pytest.fixture(scope="module")
def records():
    return {r.id: r for r in claims.evaluate("quick", ids=IDS)}


@pytest.fixture(scope="module")
def p():
    return claims.resolve("later-unique-pairs", "quick")


def saved_columns() -> dict:
    """The saved data file, read with the csv module: column -> values, step k at k - 1."""
    path = resources.files("obslib").joinpath("data", "later_experiment",
                                              "per_step_error_and_trace.csv")
    rows = list(csv.DictReader(path.read_text().splitlines()))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def saved(prefix: str, what: str) -> np.ndarray:
    col = saved_columns()
    return np.stack([col[f"{prefix}_tar_{what}_{l}"] for l in (1, 2, 3)], axis=1)


def first_update_trace(team, l: int) -> float:
    """tr P after the first update of target ``l`` with the sensors ``team``, Joseph form of
    the range measurement written out (no noise enters the covariance)."""
    su = tr.LATER_MULTI_TARGET
    x = np.array(su.estimate0[l])
    P = np.array(su.cov0) + np.array(su.Q)
    if not len(team):
        return float(np.trace(P))
    d = x - su.sensor_array[list(team)]
    H = d / np.linalg.norm(d, axis=1)[:, None]
    R = su.R * np.eye(len(team))
    K = P @ H.T @ np.linalg.inv(H @ P @ H.T + R)
    A = np.eye(2) - K @ H
    return float(np.trace(A @ P @ A.T + K @ R @ K.T))


# ------------------------------------------------------------------ kinds and statuses

def test_entries_are_of_their_kinds_with_their_statuses(records):
    want = {"later-unique-pairs": ("later", "reproduced"),
            "later-teams-unobserved": ("later", "partly"),
            "later-teams-vs-pairs": ("later", "partly"),
            "later-code-singular": ("code", "differs"),
            "later-code-rounds": ("code", "differs"),
            "beyond-many-targets": ("beyond", "answered")}
    assert {i: (r.kind, r.status) for i, r in records.items()} == want
    assert all(i.startswith("later-") for i, r in records.items() if r.kind == "later")


def test_later_entries_are_not_counted_as_claims_of_the_paper(records):
    from obsbook import report

    recs = list(records.values())
    assert "later" in report.SECTIONS
    text = report.render_report(recs, "quick", targets={}, robustness=None)
    later = text.split("(report-later)=", 1)[1].split("(report-beyond)=", 1)[0]
    for cid in ("later-unique-pairs", "later-teams-unobserved", "later-teams-vs-pairs"):
        assert f"(claim-{cid})=" in later
    assert report.counts_sentence(recs) == "The ledger holds no claim of the paper yet."


# ------------------------------------------------------------------ the saved data, recounted

def test_saved_steps_without_a_sensor_are_recounted_from_the_file(records):
    trace = saved("gen", "tra_cova")
    recount = (np.abs(np.diff(trace, axis=0) - 0.4) < 1e-5).sum(axis=0)
    ev = records["later-teams-unobserved"].evidence
    assert ev["saved"] == recount.tolist() == [33, 22, 19]
    assert ev["saved_total"] == 74
    assert (np.abs(np.diff(saved("uni", "tra_cova"), axis=0) - 0.4) < 1e-5).sum() == 0


def test_statement_of_teams_against_pairs_is_what_the_file_shows():
    """The statement says: larger trace for every target, larger error for targets 1 and 3,
    smaller for target 2 (means over steps 2 to 100 of the two saved runs)."""
    err = saved("gen", "mean_error")[1:].mean(axis=0) - saved("uni", "mean_error")[1:].mean(axis=0)
    tra = saved("gen", "tra_cova")[1:].mean(axis=0) - saved("uni", "tra_cova")[1:].mean(axis=0)
    assert np.sign(err).tolist() == [1, -1, 1] and (tra > 0).all()
    want = lm.saved_directions()
    assert [want[("mean_error", l)] for l in range(3)] == [1, -1, 1]
    assert [want[("mean_trace", l)] for l in range(3)] == [1, 1, 1]


def test_saved_first_updates_are_the_filter_s_with_the_first_teams(records):
    """The trace after the first update does not depend on the noise: with the first step's
    pairs (unique pairs) and with the teams numbered by rounds it is the saved one; with the
    teams as picked it is not."""
    runs = mt.later_runs(4, assignments=("unique-pairs",))
    pairs = runs["unique-pairs"].run(0).teams[0]
    uni = saved("uni", "tra_cova")[1]
    assert [first_update_trace(pairs[l], l) for l in range(3)] == pytest.approx(uni, rel=5e-6)
    ev = records["later-code-rounds"].evidence
    gen = saved("gen", "tra_cova")[1]
    by_rounds = [first_update_trace(ev["rounds"][l], l) for l in range(3)]
    picked = [first_update_trace(ev["picked"][l], l) for l in range(3)]
    assert by_rounds == pytest.approx(gen, rel=5e-6)
    assert np.abs(np.array(picked) / gen - 1).max() > 0.1
    assert ev["gap_rounds"] < 5e-6 < ev["gap_picked"]


# ------------------------------------------------------------------ our runs, recounted

def test_share_of_runs_like_the_saved_one_recomputed(records, p):
    b = mt.later_runs(p["n_seeds"], p["seed"])["unique-pairs"]
    err = np.array([[b.error[r, 1:, l].mean() for l in range(3)] for r in range(b.n_runs)])
    trc = np.array([[b.trace_cov[r, 1:, l].mean() for l in range(3)] for r in range(b.n_runs)])
    s_err, s_trc = saved("uni", "mean_error")[1:].mean(axis=0), saved("uni", "tra_cova")[1:].mean(
        axis=0)
    like = [all(abs(err[r, l] / s_err[l] - 1) <= 0.15 and abs(trc[r, l] / s_trc[l] - 1) <= 0.15
                for l in range(3)) for r in range(b.n_runs)]
    ev = records["later-unique-pairs"].evidence
    assert ev["share_like"] == pytest.approx(np.mean(like))
    teams = [b.run(r).teams for r in range(b.n_runs)]
    assert ev["unobserved"] == sum(len(t) == 0 for run in teams for step in run for t in step) == 0


def test_steps_without_a_sensor_recounted_from_the_teams(records, p):
    b = mt.later_runs(p["n_seeds"], p["seed"])["logdet-teams-as-run"]
    counts = np.array([[sum(len(step[l]) == 0 for step in b.run(r).teams[:99]) for l in range(3)]
                       for r in range(b.n_runs)])
    ev = records["later-teams-unobserved"].evidence
    assert ev["share"] == pytest.approx((counts.mean(axis=0) / 99).tolist())
    lo, hi = 0.2 / 1.15, 1 / 3 * 1.15
    assert ev["within"] == [bool(lo <= s <= hi) for s in counts.mean(axis=0) / 99]
    assert records["later-teams-unobserved"].status == (
        "reproduced" if all(ev["within"]) else "partly" if any(ev["within"]) else "refuted")


def test_teams_against_pairs_by_scipy_s_paired_test(records, p):
    runs = mt.later_runs(p["n_seeds"], p["seed"])
    ev = records["later-teams-vs-pairs"].evidence
    for key, field in (("mean_error", "error"), ("mean_trace", "trace_cov")):
        for l in range(3):
            a = getattr(runs["unique-pairs"], field)[:, 1:, l].mean(axis=1)
            b = getattr(runs["logdet-teams-as-run"], field)[:, 1:, l].mean(axis=1)
            d = b - a
            pval = stats.wilcoxon(d[d != 0]).pvalue
            want = "same" if pval >= 0.01 else ("worse" if np.median(d) > 0 else "better")
            assert ev["ours"][f"{key}, target {l + 1}"] == want, (key, l)
    same = sum(ev["ours"][k] == ("worse" if s > 0 else "better")
               for k, s in ev["saved_directions"].items())
    assert ev["same_way"] == same


def test_the_exact_greedy_gives_every_sensor_to_the_first_target(records):
    """A plain greedy on log det(O^T O), exact: -inf for a team of fewer than two sensors
    (a sum of squared cross products, Cauchy-Binet, that is zero)."""
    su = tr.LATER_MULTI_TARGET
    S, X = su.sensor_array, np.array(su.estimate0)

    def logdet(team, l):
        rows = X[l] - S[list(team)]
        det = sum((rows[a, 0] * rows[b, 1] - rows[a, 1] * rows[b, 0]) ** 2
                  for a in range(len(rows)) for b in range(a + 1, len(rows)))
        return np.log(det) if det > 0 else -np.inf

    teams = [[], [], []]
    free = list(range(len(S)))
    with np.errstate(invalid="ignore"):
        while free:
            best, pick = None, None
            for l in range(3):  # first target, then first sensor, on ties (NaN never wins)
                for i in free:
                    gain = logdet(teams[l] + [i], l) - logdet(teams[l], l) if teams[l] else (
                        logdet([i], l))
                    if best is None or gain > best:
                        best, pick = gain, (l, i)
            teams[pick[0]].append(pick[1])
            free.remove(pick[1])
    teams = [sorted(t) for t in teams]
    assert teams == [list(range(8)), [], []]
    ev = records["later-code-singular"].evidence
    assert ev["first_step"]["exact"] == teams
    assert ev["first_step"]["code"] != teams
    assert ev["share_none"]["logdet-teams-exact"] == pytest.approx(2 / 3)
    assert ev["lost"]["logdet-teams-exact"] == 2 * ev["n_runs"]


def test_rounds_reading_changes_the_error_as_a_paired_test_says(records, p):
    runs = mt.later_runs(p["n_seeds"], p["seed"])
    a = runs["logdet-teams"].error[:, 1:].mean(axis=(1, 2))
    b = runs["logdet-teams-as-run"].error[:, 1:].mean(axis=(1, 2))
    ev = records["later-code-rounds"].evidence
    assert ev["picked_mean_error"] == pytest.approx(a.mean())
    assert ev["as_run_vs_picked"]["mean_error"] == pytest.approx(b.mean())
    d = b - a
    assert ev["as_run_vs_picked"]["p_wilcoxon"] == pytest.approx(stats.wilcoxon(d[d != 0]).pvalue)


def test_network_comparison_by_scipy_s_paired_test(records, p):
    net = mt.network_runs(p["net_sensors"], p["net_targets"], p["net_scenes"], p["net_steps"],
                          p["seed"])
    d_opt = net["d-optimal-teams"].error[:, 1:].mean(axis=(1, 2))
    ev = records["beyond-many-targets"].evidence
    for name, batch in net.items():
        if name == "d-optimal-teams":
            continue
        other = batch.error[:, 1:].mean(axis=(1, 2))
        d = other - d_opt
        pval = stats.wilcoxon(d[d != 0]).pvalue
        want = "same" if pval >= 0.01 else ("worse" if np.median(d) > 0 else "better")
        assert ev["against"]["d-optimal-teams"][name]["verdict"] == want, name
        assert ev["against"]["d-optimal-teams"][name]["wins"] == int((d > 0).sum()), name
    assert ev["best"] == {"d-optimal-teams": True, "a-optimal-teams": True}


# ------------------------------------------------------------------ rules that can fail

def test_a_saved_run_our_model_does_not_give_is_not_reproduced(monkeypatch, p):
    real = mt.saved_comparison

    def off(n_seeds, seed=0):
        out = {k: dict(v) for k, v in real(n_seeds, seed).items()}
        out["unique-pairs"]["step2_max_rel_diff"] = 1e-3
        return out

    monkeypatch.setattr(lm, "saved_comparison", off)  # the name the check calls
    assert claims.recheck("later-unique-pairs", p, "quick").status == "partly"


def test_teams_against_pairs_refuted_when_no_comparison_goes_the_saved_way(monkeypatch, p):
    flipped = {k: -v for k, v in lm.saved_directions().items()}
    monkeypatch.setattr(lm, "saved_directions", lambda: flipped)
    r = claims.recheck("later-teams-vs-pairs", p, "quick")
    assert r.status == "refuted" and r.evidence["same_way"] == 0


# ------------------------------------------------------------------ the chapter's intuition

def test_intuition_trace_grows_by_tr_q_at_each_step_without_a_sensor():
    from obsbook.chapters import many_targets as chapter

    scene = chapter.intuition(tr.LATER_MULTI_TARGET)
    t, seen = scene["trace"], scene["observed"]
    jumps = np.diff(t)[~seen[1:]]
    assert jumps == pytest.approx(0.4)
    i, j = scene["fixed_pair"]
    W = tr.LATER_MULTI_TARGET
    from obslib.bounds import lower_bound

    o = W.truth_array[1, 0]  # step 2
    assert scene["fixed"][0] == pytest.approx(lower_bound(W.sensor_array[[i, j]], o, W.u_max))
    assert scene["rechosen"][0] == pytest.approx(scene["fixed"][0])
    assert (scene["rechosen"] >= scene["fixed"] - 1e-12).all()

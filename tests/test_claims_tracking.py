"""The ledger's claims of Sections V-A and V-B (obslib.claims.tracking), at the quick profile.

Each status is asserted against the evidence the check returns, by the rule in its docstring,
and then pinned to what we found (a change of verdict must be a deliberate, reviewed change).
"""

from __future__ import annotations

import pytest

import obslib.claims as claims
import obslib.claims.tracking as ct  # registers the claims of this module
import obslib.tracking as tr
from obslib.published_runs import published_run
from obslib.studies.published import PUBLISHED_CIRCLE

IDS = [
    "fig6-figure-data",
    "fig6-best-pair",
    "fig6-higher-bound",
    "fig6-bound-correlation",
    "fig5-switching-k50",
    "sec5a-s1-best-partner",
    "fig7-entrapment",
    "fig7-switch-mechanism",
    "fig7-figure-data",
]

#: What the evidence gives at the quick profile (and at the paper profile, checked by hand).
EXPECTED = {
    "fig6-figure-data": "reproduced",
    "fig6-best-pair": "partly",
    "fig6-higher-bound": "reproduced",
    "fig6-bound-correlation": "partly",
    "fig5-switching-k50": "reproduced",
    "sec5a-s1-best-partner": "partly",
    "fig7-entrapment": "reproduced",
    "fig7-switch-mechanism": "partly",
    "fig7-figure-data": "reproduced",
}


@pytest.fixture(scope="module")
def records():
    return {r.id: r for r in claims.evaluate("quick", IDS)}


def test_registered_with_required_ids():
    reg = claims.registry()
    for i in IDS:
        assert i in reg
    assert reg["fig6-best-pair"].notebook == ct.NB5
    assert reg["fig7-entrapment"].notebook == ct.NB6
    assert {"fig6-best-pair", "fig7-entrapment"} <= set(claims.REQUIRED_IDS)


def test_statuses_follow_from_evidence(records):
    r = records["fig6-best-pair"]
    w = r.evidence["wins"]
    runs_ok = all(w[o][k] >= 0.95 for o in w for k in ("run_error", "run_trace"))
    times_ok = all(w[o][k] >= 0.90 for o in w for k in ("error_stepmean", "trace_stepmean"))
    want = "reproduced" if runs_ok and times_ok else "partly" if runs_ok else "refuted"
    assert r.status == want

    r = records["fig6-higher-bound"]
    assert (r.status == "reproduced") == (min(r.evidence["stepmean"].values()) >= 0.9)

    r = records["fig6-bound-correlation"]
    n = sum(r.evidence["holds"].values())
    assert r.status == {3: "reproduced", 0: "refuted"}.get(n, "partly")

    r = records["fig5-switching-k50"]
    (mw, mr), (sw, sr) = r.evidence["mc"], r.evidence["single"]
    ok = [mw >= 0.5 and mw > mr, sw >= 0.5 and sw > sr]
    assert r.status == ("reproduced" if all(ok) else "partly" if any(ok) else "refuted")

    r = records["sec5a-s1-best-partner"]
    best = r.evidence["best"]
    if best["mean_trace"] == "s1" and best["mean_error"] == "s1":
        assert r.status == "reproduced"
    else:
        wins = [k for k in ("mean_trace", "mean_error", "median_error", "lost") if best[k] == "s1"]
        assert r.status == ("partly" if wins else "refuted")

    r = records["fig7-entrapment"]
    frac = r.evidence["paper_adversary"]["entrapped"]
    assert r.status == ("reproduced" if frac == 1 else "partly" if frac > 0 else "refuted")
    # the control: a fixed pair lets the same adversary drive C^-1 far lower
    assert r.evidence["fixed_pair_control"]["icn_min"] < r.evidence["paper_adversary"]["icn_min"]

    r = records["fig7-switch-mechanism"]
    e = r.evidence
    if e["switch_if_closer"] >= 0.9 and e["raised"] >= 0.9:
        assert r.status == "reproduced"
    else:
        assert r.status == ("partly" if e["switch_if_closer"] >= 0.9 else "refuted")

    r = records["fig6-figure-data"]
    e = r.evidence
    replay_ok = all(d["matches_log"] and all(v["printed_match"] for v in d["printed"].values())
                    for d in e["replays"].values())
    typical = e["fixed_pair"]["share_like_published"] >= ct.TYPICAL_SHARE
    assert r.status == ("refuted" if not replay_ok else "reproduced" if typical else "partly")

    r = records["fig7-figure-data"]
    e = r.evidence
    ok = e["matches_log"] and all(e["printed_match"].values())
    assert r.status == ("reproduced" if ok else "refuted")


def test_figure_data_against_the_published_log(records):
    # the printed numbers recomputed from the saved runs themselves, not through the replay
    for name in ("best-pair", "best-partner"):
        log = published_run(name)
        rep = records["fig6-figure-data"].evidence["replays"][name]["printed"]
        assert rep["switches"]["replay"] == log.switches == PUBLISHED_CIRCLE[name]["switches"]
        assert rep["mean_bound"]["replay"] == pytest.approx(log.bound.mean(), abs=1e-4)
        assert round(log.error.mean(), 2) == PUBLISHED_CIRCLE[name]["mean_error"]
        assert round(log.trace_cov.mean(), 3) == PUBLISHED_CIRCLE[name]["mean_trace"]
    adv = published_run("adversarial")
    e = records["fig7-figure-data"].evidence
    assert e["switches"] == adv.switches == 306
    assert e["mean_bound"] == pytest.approx(adv.bound.mean(), abs=1e-4)
    assert round(adv.bound.mean(), 2) == 0.79


def test_strategy3_share_recounted_from_runs():
    # the share of our strategy-3 runs like the published one, counted run by run with simulate
    p = ct.params(ct.NB5, "quick")
    setup = ct.circle_setup(p)
    pub = PUBLISHED_CIRCLE["fixed-pair"]
    n = 6
    like = 0
    for seed in range(p["seed"], p["seed"] + n):
        s = tr.simulate(setup, "fixed-pair", seed=seed).summary()
        like += all(abs(s[k] - v) <= 0.15 * v if v else s[k] == 0 for k, v in pub.items())
    p6 = dict(p, n_seeds=n)
    mc = ct._mc(ct.circle_setup(p6), n, p["seed"])
    r3 = mc["fixed-pair"]
    vals = {"switches": r3.switches, "mean_bound": r3.bound.mean(1), "mean_error": r3.error.mean(1),
            "mean_trace": r3.trace_cov.mean(1)}
    ours = sum(all(abs(vals[k][i] - v) <= 0.15 * v if v else vals[k][i] == 0
                   for k, v in pub.items()) for i in range(n))
    assert ours == like


def test_printed_match_rounds_at_the_printed_precision():
    assert ct.printed_match(0.7263, 0.73, "mean_bound")
    assert not ct.printed_match(0.7249, 0.73, "mean_bound")
    assert ct.printed_match(0.13975, 0.140, "mean_trace")
    assert not ct.printed_match(0.1394, 0.140, "mean_trace")
    assert ct.printed_match(306, 306, "switches") and not ct.printed_match(305, 306, "switches")


def test_fig7_figure_data_refuted_when_the_replay_misses(monkeypatch):
    # the check has teeth: a replay that differs from the log by more than its rounding
    import dataclasses

    good = ct.rp.compare_replay("adversarial")
    bad = dataclasses.replace(good, max_abs_diff=dict(good.max_abs_diff, bound=1e-3))
    monkeypatch.setattr(ct.rp, "compare_replay", lambda name: bad)
    (r,) = claims.evaluate("quick", ["fig7-figure-data"])
    assert r.status == "refuted" and "not reproduced" in r.ours


def test_fig7_figure_data_reports_typicality_shared_with_published_replay(records):
    (pr,) = claims.evaluate("quick", ["published-replay"])
    t, u = records["fig7-figure-data"].evidence["typicality"], pr.evidence["typicality"]
    assert t["n_seeds"] == u["n_seeds"]
    assert t["within_tolerance"] == pytest.approx(u["within_tolerance"])
    assert t["percentile"] == pytest.approx(u["percentile"])
    assert t["median"] == pytest.approx(u["quantiles"][50], abs=1e-4)


def test_statuses_as_found(records):
    assert {i: records[i].status for i in IDS} == EXPECTED


def test_records_are_complete(records):
    for r in records.values():
        assert r.status in claims.STATUSES
        assert r.ours and r.paper and r.statement and r.where


def test_quick_profile_shrinks_only_sizes():
    for nb in (ct.NB5, ct.NB6):
        quick, paper = ct.params(nb, "quick"), ct.params(nb, "paper")
        assert set(quick) == set(paper)
        changed = {k for k in paper if quick[k] != paper[k]}
        assert changed <= {"n_seeds", "n_seeds_strong", "n_radii", "n_angles", "anim_every"}

"""The ledger's claims of Sections V-A and V-B (obslib.claims.tracking), at the quick profile.

Each status is asserted against the evidence the check returns, by the rule in its docstring,
and then pinned to what we found (a change of verdict must be a deliberate, reviewed change).
"""

from __future__ import annotations


import pytest

import obslib.claims as claims
import obslib.claims.tracking as ct  # registers the claims of this module

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
    "fig7-figure-data": "partly",
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
    rows = r.evidence["rows"].values()
    within = [v["within"] for row in rows for k, v in row.items() if k != "mc_mean"]
    half = 2 * sum(within) >= len(within)
    assert r.status == ("reproduced" if all(within) else "partly" if half else "refuted")


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

"""The claims ledger: structure, and each Section III status against recomputed evidence."""

import numpy as np
import pytest

import obslib as ob
import obslib.studies.section3 as bc
from obslib import claims
from obslib.run import NOTEBOOK_DIR, ROOT


@pytest.fixture(scope="module")
def records():
    return {r.id: r for r in claims.evaluate("quick")}


def test_records_are_complete(records):
    assert records, "the ledger is empty"
    for r in records.values():
        assert r.status in claims.STATUSES
        for field in ("id", "where", "statement", "paper", "ours", "notebook"):
            assert getattr(r, field).strip(), f"{r.id}: empty {field}"
        assert (NOTEBOOK_DIR / f"{r.notebook}.ipynb").exists(), f"{r.id}: no notebook {r.notebook}"


def test_unknown_profile_and_id_are_rejected():
    with pytest.raises(ValueError, match="unknown profile"):
        claims.evaluate("nope")
    with pytest.raises(ValueError, match="unknown claim"):
        claims.evaluate("quick", ids=["thm99"])


def test_finding_rejects_a_status_outside_the_four():
    with pytest.raises(ValueError, match="status"):
        claims.Finding("mostly", "x")


def test_section3_statuses(records):
    expected = {
        "thm1": "reproduced", "thm1-tight": "reproduced", "thm2": "reproduced",
        "thm3": "reproduced", "thm3-proof-condition": "partly",
        "remark1": "reproduced", "remark2": "reproduced",
    }  # fmt: skip
    assert {k: records[k].status for k in expected} == expected


def test_thm1_evidence_recomputed(records):
    ev = records["thm1"].evidence
    assert ev["n_violations"] == 0 and ev["worst_excess"] <= 1e-12
    # independently: the exact value over a fine circle of controls never dips below the bound
    rng = np.random.default_rng(99)
    phi = np.linspace(0, 2 * np.pi, 2001)
    for _ in range(100):
        s = rng.uniform(-10, 10, size=(3, 2))
        o = rng.uniform(-10, 10, size=2)
        u_max = rng.uniform(0.1, 5)
        O = o - s
        lam = np.linalg.eigvalsh(O.T @ O)
        bound = np.sqrt(lam[0] / (lam[1] + u_max**2))
        for u in u_max * np.column_stack([np.cos(phi), np.sin(phi)])[::50]:
            M = np.vstack([O, u])
            sv = np.linalg.svd(M, compute_uv=False)
            assert sv[-1] / sv[0] >= bound - 1e-12


def test_thm1_check_can_fail(monkeypatch):
    """A wrong bound (ignoring u_max) must make the check report 'refuted'."""
    monkeypatch.setattr(bc, "lower_bounds", lambda rows, u: ob.bounds.lower_bounds(rows, 0.0))
    f = claims.registry()["thm1"].check("quick")
    assert f.status == "refuted" and f.evidence["n_violations"] > 0


def test_thm3_witnesses_recomputed(records):
    w = records["thm3"].evidence["witnesses"]["ratio only"]
    before, after = np.array(w["before"]), np.array(w["after"])
    o = np.zeros(2)

    def eig(s):
        O = o - s
        return np.linalg.eigvalsh(O.T @ O)

    lb, la = eig(before), eig(after)
    assert la[0] / la[1] >= lb[0] / lb[1]  # ratio up
    assert la[0] < lb[0]  # sigma_min down
    assert ob.lower_bound(after, o, w["u"]) < ob.lower_bound(before, o, w["u"])
    n, bad = records["thm3"].evidence["counts"]["stated"]
    assert n > 0 and bad == 0


def test_proof_condition_is_stronger_than_stated(records):
    counts = records["thm3-proof-condition"].evidence["counts"]
    assert 0 < counts["printed"][0] < counts["stated"][0]


def test_report_lists_every_claim(records):
    text = claims.render_report(list(records.values()), "quick")
    committed = (ROOT / "book" / "report.md").read_text()
    for cid in records:
        assert f"`{cid}`" in text
        assert f"`{cid}`" in committed, f"book/report.md is stale: no {cid} (run make book)"
    for cid in claims.REQUIRED_IDS:
        assert f"`{cid}`" in committed, f"required id {cid} neither in the table nor listed as missing"

"""Verdict robustness (obslib.claims.robustness): each variant is the check, a pure function of
its parameters, called with one of them changed; the caveats a verdict then carries."""

import dataclasses
import json

import pytest

from obsbook import report
from obslib import claims
from obslib.claims import robustness as rb
from obslib.profiles import PROFILES, params

ROBUSTNESS_FILE = rb.DATA


def test_identity_variation_reproduces_the_base_verdict(monkeypatch):
    # changing u_max by a factor 1 must give the base verdict and the very same finding back
    monkeypatch.setitem(rb.DIMENSIONS, "u_max", (1.0,))
    (row,) = rb.verdict_robustness(["thm7-case2"], dimensions=["u_max"])
    (rec,) = claims.evaluate("quick", ids=["thm7-case2"])
    assert row["base"] == rec.status
    assert row["variants"] == {"u_max": [("x1", rec.status, True)]}


def test_a_variation_changes_one_parameter_and_no_global_table(monkeypatch):
    """Each variant calls the check with the base parameters and one changed: no profile is
    written, and the check sees exactly that one change."""
    from obslib.claims import _ledger

    seen = []
    c = claims.registry()["fig6-best-pair"]

    def spy(p):
        seen.append(dict(p))
        return c.check(p)

    monkeypatch.setitem(_ledger._REGISTRY, c.id, dataclasses.replace(c, check=spy))
    before = {k: dict(v) for k, v in PROFILES.items()}
    rb.verdict_robustness([c.id], base="quick", dimensions=["noise_std"])
    assert {k: dict(v) for k, v in PROFILES.items()} == before
    base = params(c.notebook, "quick")
    assert seen[0] == base
    for p, f in zip(seen[1:], rb.DIMENSIONS["noise_std"]):
        assert p == {**base, "noise_std": base["noise_std"] * f}


def test_caveat_sentences_name_each_change_in_words():
    row = {"id": "a", "base": "partly",
           "variants": {"u_max": [("x0.25", "refuted"), ("x4", "partly")],
                        "noise_std": [("x2", "reproduced")],
                        "size": [("n_seeds x0.5", "reproduced"), ("n_seeds x2", "partly")]}}
    assert rb.caveat(row) == ("Partly at the paper's values; refuted with a quarter of "
                              "$u_{\\max}$; reproduced with twice the measurement noise and "
                              "with half the noise seeds.")
    assert rb.caveat({"id": "b", "base": "reproduced", "variants": {}}) == ""
    assert rb.caveats({"base": "quick", "dimensions": {}, "rows": [row]}) == {}
    assert rb.caveats({"base": "paper", "dimensions": {}, "rows": [row]}) == {"a": rb.caveat(row)}


def test_dimensions_follow_the_notebook_parameters():
    track = rb._variants(params("05_two_sensors_tracking", "quick"), "05_two_sensors_tracking")
    assert set(track) == {"u_max", "noise_std", "metric", "size"}
    assert track["metric"] == [("euclidean", "metric", "euclidean")]
    pair = rb._variants(params("02_pair_closed_form", "quick"), "02_pair_closed_form")
    assert set(pair) == {"u_max"}


def test_table_says_where_a_verdict_changes():
    rows = [
        {
            "id": "a",
            "base": "partly",
            "variants": {
                "u_max": [("x2", "partly", False)],
                "metric": [("euclidean", "refuted", False)],
                "size": [("n_seeds x0.5", "partly", True), ("n_seeds x2", "partly", True)],
            },
        },
        {
            "id": "b",
            "base": "reproduced",
            "fixed": ["u_max", "noise_std", "metric", "size"],
            "variants": {},
        },
    ]
    assert rb.describe(rows[0], "refuted") == (
        "refuted (partly in the stored study)",
        ["holds", "n/a", "refuted at Euclidean", "unchanged finding"])
    assert rb.describe(rows[1]) == ("reproduced", ["fixed by the published run"] * 4)
    lines = rb.robustness_table(rows, statuses={"a": "refuted"}).splitlines()
    assert len(lines) == 3 and lines[1].split()[:2] == ["a", "refuted"]
    assert "refuted at Euclidean" in lines[1] and lines[2].count("fixed by the published run") == 4


def test_published_run_claims_are_not_varied_in_their_run_parameters():
    (row,) = rb.verdict_robustness(["fig7-figure-data"])
    assert row["variants"] == {} and row["fixed"] == list(rb.DIMENSIONS)
    (row,) = rb.verdict_robustness(["fig6-figure-data"], dimensions=["noise_std", "size"])
    assert row["fixed"] == ["noise_std"] and set(row["variants"]) == {"size"}


# ----------------------------------------------------------------------- the stored data


@pytest.fixture(scope="module")
def stored():
    return rb.read_json(ROBUSTNESS_FILE)


def test_stored_robustness_covers_the_current_ledger(stored):
    # same claims, same base verdicts, same dimensions as a fresh evaluation: else rerun
    # python -m obslib.claims --robustness --write obslib/data/robustness.json
    base = stored["base"]
    assert stored["dimensions"] == {k: list(v) for k, v in rb.DIMENSIONS.items()}
    recs = {r.id: r.status for r in claims.evaluate(base)}
    assert [r["id"] for r in stored["rows"]] == rb.default_ids(base)
    assert {r["id"]: r["base"] for r in stored["rows"]} == {
        r["id"]: recs[r["id"]] for r in stored["rows"]}


@pytest.mark.parametrize("cid, dim", [("fig7-switch-mechanism", "metric"),
                                      ("fig5-switching-k50", "metric"),
                                      ("thm7-case2", "u_max"),
                                      ("fig7-entrapment", "u_max")])
def test_stored_robustness_agrees_with_a_fresh_recomputation(stored, cid, dim):
    (row,) = [r for r in stored["rows"] if r["id"] == cid]
    (fresh,) = rb.verdict_robustness([cid], base=stored["base"], dimensions=[dim])
    assert [list(v) for v in fresh["variants"][dim]] == row["variants"][dim]


def test_report_section_from_the_stored_data(stored):
    recs = claims.evaluate("quick", ids=["fig7-switch-mechanism", "thm1", "beyond-criteria"])
    text = report.render_report(recs, "quick", targets={}, robustness=stored)
    sec = text.split("## How robust are the verdicts?")[1]
    rows = [line for line in sec.splitlines() if line.startswith("* - [")]
    # only the claims of the report that the data covers, each linking to its entry
    assert len(rows) == 1 and "(#claim-fig7-switch-mechanism)" in rows[0]
    assert "  - refuted at Euclidean" in sec.splitlines() or stored["base"] == "paper"
    assert "## How robust" not in report.render_report(recs, "quick", targets={})


def test_beyond_entries_are_not_varied():
    assert not [i for i in rb.default_ids("quick") if claims.registry()[i].kind != "paper"]


def test_read_json_rejects_other_files(tmp_path):
    bad = tmp_path / "x.json"
    bad.write_text("[1, 2]")
    with pytest.raises(ValueError, match="not a robustness data file"):
        rb.read_json(bad)
    with pytest.raises(ValueError, match="not a robustness data file"):
        rb.read_json(tmp_path / "missing.json")


def test_cli_robustness_write_needs_json(capsys, tmp_path):
    from obslib.claims.__main__ import main, parse_args

    with pytest.raises(SystemExit) as exc:
        parse_args(["--robustness", "--write", str(tmp_path / "r.md")])
    assert exc.value.code == 2 and "must end in .json" in capsys.readouterr().err
    assert parse_args(["--robustness"]).profile == "paper"
    assert parse_args([]).profile == "paper"
    out = tmp_path / "r.json"
    assert main(["--robustness", "--profile", "quick", "--id", "thm7-case2", "--write",
                 str(out)]) == 0
    data = rb.read_json(out)
    assert [r["id"] for r in data["rows"]] == ["thm7-case2"] and data["base"] == "quick"
    assert json.loads(out.read_text()) == json.loads(rb.to_json(data["rows"], "quick"))


def test_bad_input():
    with pytest.raises(ValueError, match="unknown profile"):
        rb.verdict_robustness(["thm7-case2"], base="nope")
    with pytest.raises(ValueError, match="dimension"):
        rb.verdict_robustness(["thm7-case2"], dimensions=["speed"])
    with pytest.raises(ValueError, match="claim id"):
        rb.verdict_robustness(["thm99"])

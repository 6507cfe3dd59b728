"""Verdict robustness (obslib.studies.robustness): variations go through temporary profiles."""

import pytest

from obslib import claims
from obslib.profiles import PROFILES, params
from obslib.studies import robustness as rb


def test_identity_variation_reproduces_the_base_verdict(monkeypatch):
    # changing u_max by a factor 1 must give the base verdict back, through a temporary profile
    monkeypatch.setitem(rb.DIMENSIONS, "u_max", (1.0,))
    (row,) = rb.verdict_robustness(["thm7-case2"], dimensions=["u_max"])
    (rec,) = claims.evaluate("quick", ids=["thm7-case2"])
    assert row["base"] == rec.status
    assert row["variants"] == {"u_max": [("x1", rec.status)]}
    assert rb._TMP not in PROFILES  # the temporary profile is gone


def test_temporary_profile_sets_one_parameter_and_is_removed_on_error():
    nb = "05_two_sensors_tracking"
    with pytest.raises(RuntimeError):
        with rb._profile_with("quick", nb, "noise_std", 1.25) as name:
            p, q = params(nb, name), params(nb, "quick")
            assert p["noise_std"] == 1.25
            assert {k: v for k, v in p.items() if k != "noise_std"} == {
                k: v for k, v in q.items() if k != "noise_std"}
            raise RuntimeError("boom")
    assert rb._TMP not in PROFILES


def test_dimensions_follow_the_notebook_parameters():
    track = rb._variants(params("05_two_sensors_tracking", "quick"), "05_two_sensors_tracking")
    assert set(track) == {"u_max", "noise_std", "metric", "size"}
    assert track["metric"] == [("euclidean", "metric", "euclidean")]
    pair = rb._variants(params("02_pair_closed_form", "quick"), "02_pair_closed_form")
    assert set(pair) == {"u_max"}


def test_table_says_where_a_verdict_changes():
    rows = [{"id": "a", "base": "partly", "variants": {"u_max": [("x2", "partly")],
                                                        "metric": [("euclidean", "refuted")]}}]
    text = rb.robustness_table(rows)
    assert "| `a` | partly | holds (x2) | n/a | changes at euclidean: refuted | n/a |" in text


def test_bad_input():
    with pytest.raises(ValueError, match="unknown profile"):
        rb.verdict_robustness(["thm7-case2"], base="nope")
    with pytest.raises(ValueError, match="dimension"):
        rb.verdict_robustness(["thm7-case2"], dimensions=["speed"])
    with pytest.raises(ValueError, match="claim id"):
        rb.verdict_robustness(["thm99"])

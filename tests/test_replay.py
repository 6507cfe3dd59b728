"""Replaying the published runs (obslib.studies.replay) and the published-replay claim."""

import numpy as np
import pytest

import obslib.tracking as tr
from obslib import claims
from obslib.published_runs import published_noise, published_run
from obslib.studies import replay as rp


@pytest.fixture(scope="module")
def comparisons():
    names = ("best-pair", "best-partner", "fixed-pair", "adversarial")
    return {n: rp.compare_replay(n) for n in names}


@pytest.mark.parametrize("name", ["best-pair", "best-partner", "adversarial"])
def test_replay_gives_every_logged_number(comparisons, name):
    c = comparisons[name]
    assert c.steps == 315 and c.exact
    # the log is printed to 12 significant digits; the numbers are at most about 10
    assert c.largest < 1e-10
    assert {"bound", "error", "trace_cov", "truth", "estimate"} <= set(c.max_abs_diff)


def test_replay_against_the_log_directly():
    r = rp.replay("adversarial")
    pub = published_run("adversarial")
    assert np.array_equal(r.pairs, pub.pairs)
    np.testing.assert_allclose(r.bound, pub.bound, atol=1e-10)
    np.testing.assert_allclose(r.objective, pub.objective, atol=1e-10)
    assert r.switches == 306


def test_unknown_entries_do_not_matter():
    # two fills of the unknown entries give the same run, and a third, wild one too
    a = rp.replay("best-partner", fill=0.0)
    b = rp.replay("best-partner", fill=-1e3)
    assert np.array_equal(a.estimate, b.estimate) and np.array_equal(a.pairs, b.pairs)


def test_the_unknown_entries_would_matter_if_read():
    # the check has teeth: a random noise table in place of the published one changes the run
    t = np.nan_to_num(published_noise(), nan=0.0)
    t[5:, :] = tr.noise_table(tr.PAPER_ADVERSARIAL, 1)[5:]
    r = tr.simulate(tr.PAPER_ADVERSARIAL, "best-pair", noise=t)
    assert np.abs(r.bound - published_run("adversarial").bound).max() > 1e-3


def test_fixed_pair_is_replayable_only_where_the_table_knows_s1_and_s2(comparisons):
    c = comparisons["fixed-pair"]
    t = published_noise()
    first_unknown = np.flatnonzero(~np.isfinite(t[:, :2]).all(axis=1))[0]
    assert c.steps == first_unknown + 1 and c.exact and c.largest < 1e-10


def test_seed_typicality_is_consistent():
    t = rp.seed_typicality(30, 0)
    m = t["per_run"]
    assert m.shape == (30,)
    assert t["percentile"] == pytest.approx(100 * np.mean(m < t["published"]))
    assert t["quantiles"][5] <= t["quantiles"][50] <= t["quantiles"][95]
    # seed 0 is the run the batch engine and filterpy agree on
    one = tr.simulate(tr.PAPER_ADVERSARIAL, "best-pair", seed=0)
    assert m[0] == pytest.approx(one.bound.mean(), abs=1e-9)


@pytest.mark.parametrize("bad", [dict(name="nope"), dict(name="best-pair", fill=np.nan),
                                 dict(name="best-pair", fill="x")])
def test_bad_input(bad):
    with pytest.raises(ValueError):
        rp.replay(**bad)
    with pytest.raises(ValueError, match="accepted names"):
        rp.compare_replay("nope")
    with pytest.raises(ValueError, match="n_seeds"):
        rp.seed_typicality(0)


def test_published_replay_claim():
    (r,) = claims.evaluate("quick", ids=["published-replay"])
    # the runs replay exactly, but with the model as the authors' code runs it, whose angle and
    # controls depart from the text: a finding about the code, not the paper's model
    assert r.kind == "code" and r.status == "differs"
    assert all(d["pair_mismatches"] == 0 for d in r.evidence["runs"].values())
    assert r.evidence["code_model"]["departs"] and "as the authors' code runs it" in r.summary
    assert r.evidence["runs"]["fixed-pair"]["steps"] == 1


def test_seed_typicality_share_within_tolerance_and_cache():
    t = rp.seed_typicality(30, 0)
    m, pub = t["per_run"], t["published"]
    near = [abs(x - pub) <= 0.15 * pub for x in m.tolist()]
    assert t["within_tolerance"] == pytest.approx(sum(near) / len(near))
    # computed once: a second call returns the same runs, which nobody can alter
    assert rp.seed_typicality(30, 0)["per_run"] is m
    with pytest.raises(ValueError):
        m[0] = 0.0
    assert rp.compare_replay("adversarial") is rp.compare_replay("adversarial")
    assert rp.compare_replay("adversarial").matches


@pytest.mark.parametrize("name", ["best-pair", "best-partner", "adversarial"])
def test_replays_of_both_fills_equal_single_runs(name):
    """The two fills' replays (and the circle's two strategies) share one batched pass; each
    equals the replay run alone."""
    from obslib.studies import replay as rp

    steps = 40
    setup = rp.replay_setup(name).replace(steps=steps)
    for fill in (rp.REPLAY_FILLS[1], 3.5):
        got = rp._replay(name, fill, steps)
        alone = tr.simulate_batch(setup, rp._strategy(name), noise=rp._table(steps, fill)[None])
        np.testing.assert_array_equal(got.pairs, alone.pairs[0])
        for f in ("bound", "estimate", "cov", "truth"):
            np.testing.assert_allclose(getattr(got, f), getattr(alone, f)[0], rtol=0,
                                       atol=1e-12, err_msg=f)

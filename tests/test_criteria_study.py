"""The criteria study: each criterion's score against a direct evaluation of its formula, the
paired test against scipy, the summaries against the runs they summarise."""

import numpy as np
import pytest

import obslib as ob
from obslib import tracking as tr
from obslib.profiles import params
from obslib.studies import adversarial_target
from obslib.studies import criteria as cs

RNG = np.random.default_rng(7)
S = RNG.uniform(-3, 5, size=(5, 2))
X = RNG.uniform(-1, 4, size=(4, 2))
A = RNG.normal(size=(4, 2, 2))
C = A @ np.swapaxes(A, 1, 2) + 0.3 * np.eye(2)
Q = np.array([[0.5, 0.1], [0.1, 0.4]])
R = np.array([[0.5, 0.0], [0.0, 0.3]])
U = RNG.uniform(-1, 1, size=(4, 2))


def _direct(name, b, i, j, metric="mahalanobis"):
    H = np.array([X[b] - S[i], X[b] - S[j]])
    J = np.linalg.inv(C[b] + Q) + H.T @ np.linalg.inv(R) @ H
    if name == "d-optimal":
        return np.linalg.det(J)
    if name == "a-optimal":
        return -np.trace(np.linalg.inv(J))
    if name == "e-optimal":
        return np.linalg.eigvalsh(J)[0]
    if name == "exact-icn":
        s = np.linalg.svd(np.vstack([H, U[b]]), compute_uv=False)
        return s[-1] / s[0]
    cov = C[b] if metric == "mahalanobis" else None
    return ob.pair_bounds(S, X[b][None], 1.3, cov=None if cov is None else cov[None])[i, j, 0]


@pytest.mark.parametrize("name", cs.SCORES)
def test_scores_equal_direct_formulas(name):
    got = cs.criterion_scores(name, S, X, C, Q, R, 1.3, control=U)
    ii, jj = np.triu_indices(5, 1)
    want = np.array([[_direct(name, b, i, j) for i, j in zip(ii, jj)] for b in range(4)])
    np.testing.assert_allclose(got, want, rtol=1e-9, atol=1e-12)


def test_euclidean_bound_score():
    got = cs.criterion_scores("bound", S, X, C, Q, R, 1.3, metric="euclidean")
    ii, jj = np.triu_indices(5, 1)
    want = np.array(
        [[_direct("bound", b, i, j, "euclidean") for i, j in zip(ii, jj)] for b in range(4)]
    )
    np.testing.assert_allclose(got, want, rtol=1e-12)


def test_bad_score_input():
    with pytest.raises(ValueError, match="criterion"):
        cs.criterion_scores("c-optimal", S, X, C, Q, R, 1.0)
    with pytest.raises(ValueError, match="control"):
        cs.criterion_scores("exact-icn", S, X, C, Q, R, 1.0)
    with pytest.raises(ValueError, match="sensors"):
        cs.criterion_scores("bound", S[:1], X, C, Q, R, 1.0)
    with pytest.raises(ValueError, match="metric"):
        cs.criterion_scores("bound", S, X, C, Q, R, 1.0, metric="l1")


def test_paired_test_p_values_by_enumeration():
    """Both p-values against their definitions, enumerated: the sign test over the binomial
    outcomes, Wilcoxon's exact test over the 2^n sign patterns of the ranks (n = 7, no ties)."""
    from itertools import product
    from math import comb

    a = np.array([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0])
    b = a + np.array([0.5, -0.2, 0.3, 0.0, 0.9, 0.4, -0.1, 0.7])
    t = cs.paired_test(a, b)
    assert (t["n"], t["reference_better"], t["other_better"], t["ties"]) == (8, 5, 2, 1)
    assert t["p_sign"] == pytest.approx(2 * sum(comb(7, i) for i in range(3)) / 2**7, rel=1e-12)
    d = (b - a)[b != a]
    rank = np.argsort(np.argsort(np.abs(d))) + 1
    t_plus = rank[d > 0].sum()
    sums = np.array([rank[np.array(s, bool)].sum() for s in product((0, 1), repeat=d.size)])
    mid = d.size * (d.size + 1) / 4
    p_exact = np.mean(np.abs(sums - mid) >= abs(t_plus - mid))
    assert t["p_wilcoxon"] == pytest.approx(p_exact, rel=1e-12)
    assert t["mean_diff"] == pytest.approx(np.mean(b - a))
    with pytest.raises(ValueError):
        cs.paired_test(a, b[:-1])


def test_summary_rows_match_runs():
    setup = tr.PAPER_CIRCLE.replace(steps=30)
    mc = tr.monte_carlo(setup, 4, ("best-pair", "fixed-pair"))
    rows = {r["strategy"]: r for r in cs.summary_rows(mc)}
    e = mc["fixed-pair"].error[:, 1:].mean(axis=1)
    assert rows["fixed-pair"]["mean_error"] == pytest.approx(e.mean())
    assert rows["fixed-pair"]["sd_error"] == pytest.approx(e.std(ddof=1))
    assert rows["fixed-pair"]["switches"] == 0
    assert rows["fixed-pair"]["lost"] == int((e > 0.5).sum())
    ref = mc["best-pair"].error[:, 1:].mean(axis=1)
    assert rows["fixed-pair"]["vs_mean_diff"] == pytest.approx((e - ref).mean())
    assert "vs_n" not in rows["best-pair"]


def test_tracking_study_validates():
    with pytest.raises(ValueError, match="n_seeds"):
        cs.tracking_study(1)
    with pytest.raises(ValueError, match="metrics"):
        cs.tracking_study(5, metrics=["l1"])
    with pytest.raises(ValueError, match="unknown"):
        cs.tracking_study(5, strategies=["best-pair", "nope"])


def test_params_profiles():
    p, q = params(cs.NOTEBOOK, "paper"), params(cs.NOTEBOOK, "quick")
    assert q["n_seeds"] < p["n_seeds"] and p["n_seeds"] >= 200 and p["assign_seeds"] >= 100
    with pytest.raises(ValueError, match="profile"):
        params(cs.NOTEBOOK, "nonsense")


def test_figures_label_their_axes():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from obslib.studies import assignment_tracking as at
    from obslib.viz.assignment_tracking import plot_assignment_errors
    from obslib.viz.criteria import plot_run_errors

    setup = tr.PAPER_CIRCLE.replace(steps=20)
    study = {("circle", "mahalanobis"): tr.monte_carlo(setup, 3, ("best-pair", "fixed-pair"))}
    fig = plot_run_errors(study)
    assert fig.get_figwidth() <= 9 and "error" in fig.axes[0].get_ylabel()
    assert [t.get_text() for t in fig.axes[0].get_xticklabels()] == [
        "bound\n(best pair)",
        "fixed\npair",
    ]
    runs = {2: at.run_all(at.AssignmentTrackingSetup(n_targets=2, steps=5), [0, 1])}
    fig2 = plot_assignment_errors(runs)
    assert fig2.get_figwidth() <= 9 and "length units" in fig2.axes[0].get_ylabel()
    plt.close("all")
    with pytest.raises(ValueError):
        plot_run_errors(study, "euclidean")


@pytest.mark.parametrize(
    "base", [tr.PAPER_CIRCLE, tr.PAPER_ADVERSARIAL], ids=["circle", "adversary"]
)
def test_criteria_runs_reused_across_metrics_equal_direct_runs(base):
    """The criteria's runs do not depend on the bound's metric; re-logging the bound of one
    metric's runs under the other equals running them with the other metric."""
    names = list(tr.CRITERIA)
    maha, eucl = (base.replace(steps=25, metric=m) for m in ("mahalanobis", "euclidean"))
    a = tr.monte_carlo(maha, 3, names)
    b = tr.monte_carlo(eucl, 3, names)
    for n in names:
        r = cs.relog_bound(a[n], eucl)
        assert np.array_equal(r.pairs, b[n].pairs)
        np.testing.assert_allclose(r.error, b[n].error, rtol=1e-12)
        np.testing.assert_allclose(r.bound, b[n].bound, rtol=1e-10, atol=1e-14)


def test_adversary_rows_equal_entrapment_summary():
    setup = tr.PAPER_ADVERSARIAL.replace(steps=40)
    names = ["best-pair", "fixed-pair", "d-optimal"]
    mc = tr.monte_carlo(setup, 4, names)
    for row in cs.adversary_rows(mc):
        want = adversarial_target.entrapment_summary(mc[row["strategy"]])
        for key in ("entrapped", "max_from_start", "reach", "icn_mean", "icn_min", "bound_mean",
                    "switches", "mean_error"):
            assert row[key] == pytest.approx(want[key], rel=1e-12, abs=1e-15), key


def test_tracking_study_equals_a_monte_carlo_per_metric():
    """The study runs every metric and strategy in one batched pass per setting; each batch
    equals the Monte Carlo of that metric alone (same pairs, numbers to rounding)."""
    names = ("best-pair", "best-partner", "fixed-pair", "d-optimal", "exact-icn", "random")
    got = cs._tracking_study(3, 5, ("mahalanobis", "euclidean"), names)
    for (label, metric), runs in got.items():
        base = tr.PAPER_CIRCLE if label == "circle" else tr.PAPER_ADVERSARIAL
        for n in names:  # the full 315 steps: the study's length is fixed
            want = tr.monte_carlo(base.replace(metric=metric), 3, [n], 5)[n]
            assert np.array_equal(runs[n].pairs, want.pairs), (label, metric, n)
            for f in ("bound", "estimate", "cov", "truth"):
                np.testing.assert_allclose(getattr(runs[n], f), getattr(want, f), rtol=0,
                                           atol=1e-12, err_msg=f"{label} {metric} {n} {f}")

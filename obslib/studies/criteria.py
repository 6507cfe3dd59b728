"""The pair bound against the field's standard criteria: is the bound the right criterion?

Computed once here and shared by notebook 10 and the claims ledger:

* the tracking experiments of Section V (the circle of V-A and the adversary of V-B) run with the
  paper's strategies and the classical criteria of optimal experimental design, over many seeds
  with common noise (:func:`tracking_study`), summarised per strategy (:func:`summary_rows`) and
  compared run by run with the bound's choice (:func:`paired_test`);
* the cost of scoring one pair by each criterion (:func:`criterion_scores`, timed in the
  notebook);
* the assignment-by-tracking experiment of :mod:`obslib.studies.assignment_tracking`
  (:func:`assignment_study`).

The criteria score a pair ``(i, j)`` at the estimate :math:`\\hat x` with covariance
:math:`\\Sigma` through the information the filter's next update would have,

.. math::

    J(i, j) = (\\Sigma^-)^{-1} + H^T R^{-1} H, \\qquad \\Sigma^- = \\Sigma + Q, \\qquad
    H = \\begin{bmatrix} (\\hat x - p_i)^T \\\\ (\\hat x - p_j)^T \\end{bmatrix},

D-optimality maximising :math:`\\det J`, A-optimality minimising :math:`\\operatorname{tr}
J^{-1}`, E-optimality maximising :math:`\\lambda_{\\min}(J)`; the ``exact-icn`` oracle maximises
the exact :math:`C^{-1}` of :math:`[\\hat x - p_i; \\hat x - p_j; u]` for the target's actual
control ``u``; the paper's ``best-pair`` maximises Theorem 4's bound (Eq. (9)).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .. import tracking
from .._kernels import inverse_condition, pair_kernel
from .._validate import (
    as_choice,
    as_covariances,
    as_float_array,
    as_instance,
    as_int,
    as_mapping,
    as_names,
    as_nonnegative,
    as_points,
    as_positive,
    as_real,
    as_real_array,
    as_sequence,
    as_str,
)
from . import assignment_tracking

__all__ = [
    "NOTEBOOK",
    "REFERENCE",
    "SCORES",
    "criterion_scores",
    "paired_test",
    "summary_rows",
    "tracking_study",
    "relog_bound",
    "adversary_rows",
    "assignment_study",
    "assignment_rows",
    "significance",
]

NOTEBOOK = "10_criteria"

#: The bound's choice, the reference of every paired test.
REFERENCE = "best-pair"
#: The scores :func:`criterion_scores` computes (``"bound"`` is ``best-pair``'s).
SCORES = ("bound", "d-optimal", "a-optimal", "e-optimal", "exact-icn")


def _mc_iv(mc) -> dict:
    """A Monte Carlo result ``{strategy: BatchResult}``."""
    mc = as_mapping(mc, "mc")
    for b in mc.values():
        as_instance(b, tracking.BatchResult, "mc")
    return mc


# --------------------------------------------------------------------------------------------
# Scores of every pair, batched over estimates
# --------------------------------------------------------------------------------------------


def _process_noise_iv(Q) -> np.ndarray:
    """The filter's process noise ``Q``: finite, symmetric and positive semi-definite (it may be
    zero, a target known to stand still), or a named ValueError."""
    m = as_real_array(Q, "Q", "a real 2x2 matrix")
    if m.shape != (2, 2):
        raise ValueError(f"Q must have shape (2, 2), got {m.shape}")
    if not np.isfinite(m).all():
        raise ValueError(f"Q has a non-finite entry: {m.tolist()}")
    top = float(np.abs(m).max())
    n = m / top if top > 0 else m
    if abs(n[0, 1] - n[1, 0]) > 1e-12:
        raise ValueError(f"Q is not symmetric: {m.tolist()}")
    if n[0, 0] < 0 or n[1, 1] < 0 or n[0, 0] * n[1, 1] - n[0, 1] * n[1, 0] < -1e-12:
        raise ValueError(f"Q is not positive semi-definite: {m.tolist()}")
    return m


def criterion_scores(name: str, sensors, xhat, cov, Q, R, u_max, control=None,
                     metric: str = "mahalanobis") -> np.ndarray:
    """Each criterion's score of every pair at a batch of estimates, shape (B, P).

    Pairs ``i < j`` in ``(i, j)`` order (``numpy.triu_indices``); larger is better for every
    score (A-optimality returns :math:`-\\operatorname{tr} J^{-1}`).

    Parameters
    ----------
    name : one of :data:`SCORES`
    sensors : (N, 2)
    xhat : (B, 2) estimates
    cov : (B, 2, 2) their covariances :math:`\\Sigma`
    Q, R : (2, 2) process and measurement noise covariances of the filter
    u_max : float, the bound's control bound
    control : (B, 2), the target's actual control (``exact-icn`` only)
    metric : the bound's distances, ``"mahalanobis"`` in ``cov`` or ``"euclidean"``

    Examples
    --------
    D-optimality is :math:`\\det J`, here checked for the pair (0, 1) against
    ``numpy.linalg.det`` of :math:`J` built directly; the bound is
    :func:`obslib.pair_bounds` with Mahalanobis distances in ``cov``:

    >>> import obslib as ob
    >>> S = np.array([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]])
    >>> x, C = np.array([[1.0, 2.0]]), np.array([[[0.6, 0.1], [0.1, 0.4]]])
    >>> Q = R = 0.5 * np.eye(2)
    >>> d = criterion_scores("d-optimal", S, x, C, Q, R, u_max=1.0)
    >>> d.shape  # one estimate, pairs (0, 1), (0, 2), (1, 2)
    (1, 3)
    >>> H = x[0] - S[[0, 1]]  # rows (xhat - p_0)^T, (xhat - p_1)^T
    >>> J = np.linalg.inv(C[0] + Q) + H.T @ np.linalg.inv(R) @ H
    >>> bool(np.isclose(d[0, 0], np.linalg.det(J), rtol=1e-12))
    True
    >>> b = criterion_scores("bound", S, x, C, Q, R, u_max=1.0)
    >>> W = ob.pair_bounds(S, x, 1.0, cov=C)[:, :, 0]
    >>> bool(np.allclose(b[0], W[np.triu_indices(3, 1)], rtol=1e-12))
    True
    """
    as_choice(name, SCORES, "criterion")
    S = as_points(sensors, "sensors", min_count=2)
    x = as_points(np.atleast_2d(as_float_array(xhat, "xhat")), "xhat")
    C = as_covariances(cov, x.shape[0], np.inf)
    Q, R = _process_noise_iv(Q), as_covariances(R, 1, np.inf, "R")[0]
    u_max = as_nonnegative(u_max, "u_max")
    if name == "exact-icn":
        if control is None:
            raise ValueError("exact-icn needs the target's control")
        u = as_float_array(control, "control")
        if u.shape not in ((2,), x.shape) or not np.isfinite(u).all():
            raise ValueError(f"control must be finite, of shape (2,) or {x.shape}, got {u.shape}")
        u = np.broadcast_to(u, x.shape)
    if as_str(metric, "metric") not in ("mahalanobis", "euclidean"):
        raise ValueError(f"metric must be 'mahalanobis' or 'euclidean', got {metric!r}")
    return _scores(name, S, x, C, np.asarray(Q, float), np.asarray(R, float), float(u_max),
                   u if name == "exact-icn" else None, metric)


def _scores(name, S, x, C, Q, R, u_max, u, metric):
    ii, jj = np.triu_indices(S.shape[0], 1)
    v = x[:, None, :] - S[None, :, :]  # (B, N, 2) rows xhat - p_i
    if name == "bound":  # Theorem 4 on the pairs only: the tracking engine's row scaling
        c = (C[:, 0, 0], C[:, 0, 1], C[:, 1, 0], C[:, 1, 1])
        maha = np.full(x.shape[0], metric == "mahalanobis")
        vx, vy, inv = tracking.choosers.scaled_rows(v[..., 0].copy(), v[..., 1].copy(), c, maha)
        return pair_kernel(vx[:, ii], vy[:, ii], vx[:, jj], vy[:, jj], (u_max**2 * inv)[:, None])
    if name == "exact-icn":
        rows = np.stack([v[:, ii], v[:, jj], np.broadcast_to(u[:, None], v[:, ii].shape)], axis=-2)
        return inverse_condition(rows)  # (B, P)
    # J = (Sigma + Q)^{-1} + H^T R^{-1} H entry by entry (2x2 closed forms, no LAPACK calls)
    M = C + Q
    mdet = M[:, 0, 0] * M[:, 1, 1] - M[:, 0, 1] * M[:, 1, 0]
    p00, p01, p11 = (
        (M[:, 1, 1] / mdet)[:, None],
        (-M[:, 0, 1] / mdet)[:, None],
        (M[:, 0, 0] / mdet)[:, None],
    )
    rdet = R[0, 0] * R[1, 1] - R[0, 1] * R[1, 0]
    r00, r01, r11 = R[1, 1] / rdet, -R[0, 1] / rdet, R[0, 0] / rdet
    xi, yi, xj, yj = v[:, ii, 0], v[:, ii, 1], v[:, jj, 0], v[:, jj, 1]  # (B, P)
    a = p00 + r00 * xi * xi + 2 * r01 * xi * xj + r11 * xj * xj
    b = p01 + r00 * xi * yi + r01 * (xi * yj + xj * yi) + r11 * xj * yj
    d = p11 + r00 * yi * yi + 2 * r01 * yi * yj + r11 * yj * yj
    det = a * d - b * b
    if name == "d-optimal":
        return det
    if name == "a-optimal":
        return -(a + d) / det
    return 0.5 * (a + d) - np.hypot(0.5 * (a - d), b)  # lambda_min of [[a, b], [b, d]]


# --------------------------------------------------------------------------------------------
# Statistics
# --------------------------------------------------------------------------------------------


def paired_test(reference, other, rtol: float = tracking.TIE_RTOL) -> dict:
    """Paired comparison of per-run values (lower is better), run ``b`` against run ``b``.

    Returns ``n``, the mean, median and standard deviation of ``other - reference``, the counts of
    runs where each is clearly lower (:func:`obslib.tracking.clearly_lower`) and of ties, the
    two-sided sign-test p-value (ties dropped; ``scipy.stats.binomtest`` at :math:`p = 1/2`) and the
    Wilcoxon signed-rank p-value of the nonzero differences (``scipy.stats.wilcoxon``: exact up
    to 50 differences, beyond that the normal approximation with the tie correction).

    Examples
    --------
    The reference is lower in 3 runs of 4, so the two-sided sign test gives
    :math:`2 \\cdot 5/16`:

    >>> ref = np.array([1.0, 2.0, 3.0, 4.0])
    >>> t = paired_test(ref, ref + [0.5, 0.5, -0.1, 0.5])
    >>> t["n"], t["reference_better"], t["other_better"], t["ties"]
    (4, 3, 1, 0)
    >>> round(t["mean_diff"], 12), round(t["median_diff"], 12), t["p_sign"]
    (0.35, 0.5, 0.625)
    """
    from scipy import stats  # 0.6 s to import: only where a test is computed

    a = as_float_array(reference, "reference")
    b = as_float_array(other, "other")
    rtol = as_nonnegative(rtol, "rtol")
    if not (np.isfinite(a).all() and np.isfinite(b).all()):
        raise ValueError("reference and other must be finite")
    if a.shape != b.shape or a.ndim != 1 or a.size < 2:
        raise ValueError(
            f"reference and other must be two equal-length 1-D samples of at least 2 runs, got "
            f"{a.shape}, {b.shape}"
        )
    d = b - a
    ref_better = int(tracking.clearly_lower(a, b, rtol).sum())
    other_better = int(tracking.clearly_lower(b, a, rtol).sum())
    ties = a.size - ref_better - other_better
    n_signed = ref_better + other_better
    p_sign = float(stats.binomtest(ref_better, n_signed, 0.5).pvalue) if n_signed else 1.0
    nonzero = d[d != 0]
    p_wil = float(stats.wilcoxon(nonzero).pvalue) if nonzero.size >= 2 else 1.0
    return {
        "n": int(a.size),
        "mean_diff": float(d.mean()),
        "median_diff": float(np.median(d)),
        "sd_diff": float(d.std(ddof=1)),
        "reference_better": ref_better,
        "other_better": other_better,
        "ties": ties,
        "p_sign": p_sign,
        "p_wilcoxon": p_wil,
    }


def significance(row: dict, alpha: float = 0.01) -> str:
    """Verdict of a row's paired test against the reference: ``"better"`` or ``"worse"`` (the
    other strategy, by the sign of the median paired difference, when the Wilcoxon test rejects
    at ``alpha``) or ``"same"``.

    Examples
    --------
    >>> significance({"vs_p_wilcoxon": 0.001, "vs_median_diff": -0.2})
    'better'
    >>> significance({"vs_p_wilcoxon": 0.001, "vs_median_diff": 0.2})
    'worse'
    >>> significance({"vs_p_wilcoxon": 0.05, "vs_median_diff": -0.2})
    'same'
    >>> significance({"strategy": "best-pair"})  # the reference: no test
    'same'
    """
    row = as_mapping(row, "row")
    alpha = as_real(alpha, "alpha")
    if not 0 < alpha < 1:
        raise ValueError(f"alpha must lie in (0, 1), got {alpha}")
    p = row.get("vs_p_wilcoxon", 1.0)
    if not isinstance(p, (int, float)) or ("vs_median_diff" not in row and p < alpha):
        raise ValueError("row must be a row of summary_rows (vs_p_wilcoxon, vs_median_diff)")
    if p >= alpha:
        return "same"
    return "better" if row["vs_median_diff"] < 0 else "worse"


def _run_means(batch, skip_first=True):
    sl = slice(1, None) if skip_first and batch.error.shape[1] > 1 else slice(None)
    return batch.error[:, sl].mean(axis=1), batch.trace_cov[:, sl].mean(axis=1)


def summary_rows(mc: dict, reference: str = REFERENCE,
                 loss_threshold: float = tracking.LOSS_THRESHOLD) -> list:
    """One row per strategy of a Monte Carlo (``{strategy: BatchResult}``).

    Keys: ``strategy``, ``mean_error`` / ``sd_error`` and ``mean_trace`` / ``sd_trace`` (mean over
    runs and steps, standard deviation over runs of the run means; step 1 left out), ``lost``
    (runs whose mean error exceeds ``loss_threshold``, :func:`obslib.tracking.track_loss`),
    ``switches`` (mean pair changes per run), ``mean_bound`` (the chosen pairs' bound), and the
    paired test of the run-mean error against ``reference`` (:func:`paired_test`, prefixed
    ``vs_``; empty for the reference itself).

    Examples
    --------
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=10)
    >>> mc = tracking.monte_carlo(setup, 3, ["best-pair", "random"])
    >>> rows = summary_rows(mc)
    >>> [r["strategy"] for r in rows], "vs_n" in rows[0], rows[1]["vs_n"]
    (['best-pair', 'random'], False, 3)
    >>> err = mc["random"].error[:, 1:].mean(axis=1)  # run means, step 1 out
    >>> bool(np.isclose(rows[1]["mean_error"], err.mean(), rtol=1e-12))
    True
    """
    mc = _mc_iv(mc)
    as_str(reference, "reference")
    loss_threshold = as_nonnegative(loss_threshold, "loss_threshold")
    ref_err = _run_means(mc[reference])[0] if reference in mc else None
    rows = []
    for name, b in mc.items():
        err, trc = _run_means(b)
        row = {
            "strategy": name,
            "mean_error": float(err.mean()),
            "sd_error": float(err.std(ddof=1)),
            "mean_trace": float(trc.mean()),
            "sd_trace": float(trc.std(ddof=1)),
            "lost": int(tracking.track_loss(b, loss_threshold)["lost"].sum()),
            "switches": float(b.switches.mean()),
            "mean_bound": float(b.bound[:, 1:].mean()),
        }
        if ref_err is not None and name != reference:
            row.update({f"vs_{k}": v for k, v in paired_test(ref_err, err).items()})
        rows.append(row)
    return rows


def relog_bound(batch, setup):
    """``batch`` with its logged bound re-evaluated under ``setup``'s metric.

    The classical criteria choose without the bound, so their runs do not depend on the
    bound's metric; only the logged bound of the chosen pair does
    (:func:`obslib.tracking.pair_bound_series` at the logged estimates and covariances).

    Examples
    --------
    A random run logged under Euclidean distances is the same run as the one
    simulated with them:

    >>> setup = tracking.PAPER_CIRCLE.replace(steps=5)
    >>> b = tracking.simulate_batch(setup, "random", seeds=[0, 1])
    >>> eu = relog_bound(b, setup.replace(metric="euclidean"))
    >>> eu.setup.metric, bool((eu.error == b.error).all())
    ('euclidean', True)
    >>> direct = tracking.simulate_batch(eu.setup, "random", seeds=[0, 1])
    >>> bool(np.allclose(eu.bound, direct.bound, rtol=1e-9))
    True
    """
    import dataclasses

    as_instance(batch, tracking.BatchResult, "batch")
    as_instance(setup, tracking.TrackingSetup, "setup")
    B, K = batch.pairs.shape[:2]
    cov = batch.cov.reshape(-1, 2, 2) if setup.metric == "mahalanobis" else None
    bound = tracking.pair_bound_series(
        setup, batch.estimate.reshape(-1, 2), batch.pairs.reshape(-1, 2), cov
    )
    return dataclasses.replace(batch, setup=setup, bound=bound.reshape(B, K))


@lru_cache(maxsize=8)
def _tracking_study(n_seeds, seed, metrics, strategies):
    # one batched pass per setting for every metric and strategy: the runs of a criterion or
    # of the fixed pair do not depend on the metric, so simulate_many runs them once and only
    # re-evaluates their logged bound (1.0 s against 2.3 s for four Monte Carlo calls per
    # metric and exact-icn pass; the runs are the same, the tests check it)
    seeds = range(seed, seed + n_seeds)
    out = {}
    for label, base in (("circle", tracking.PAPER_CIRCLE),
                        ("adversary", tracking.PAPER_ADVERSARIAL)):
        arms = {(m, s): (base.replace(metric=m), s) for m in metrics for s in strategies}
        runs = tracking.simulate_many(arms, seeds=seeds)
        for m in metrics:
            out[(label, m)] = {s: runs[(m, s)] for s in strategies}
    return out


def tracking_study(n_seeds: int, seed: int = 0, metrics=("mahalanobis", "euclidean"),
                   strategies=None) -> dict:
    """Monte Carlo of every strategy on the circle (V-A) and the adversary (V-B), per metric.

    Seeds ``seed .. seed + n_seeds - 1``, the same noise for every strategy
    (:func:`obslib.tracking.monte_carlo`). ``strategies`` defaults to those of the paper and
    the criteria (:data:`obslib.tracking.STRATEGIES`, :data:`obslib.tracking.CRITERIA`).

    Returns ``{(setting, metric): {strategy: BatchResult}}`` with ``setting`` in
    ``("circle", "adversary")``. Cached: the notebook and the ledger share one computation.

    Examples
    --------
    >>> s = tracking_study(2, strategies=("best-pair", "random"))
    >>> len(s), list(s[("circle", "mahalanobis")])
    (4, ['best-pair', 'random'])
    >>> mc = tracking.monte_carlo(tracking.PAPER_CIRCLE, 2, ["best-pair"], 0)
    >>> a = s[("circle", "mahalanobis")]["best-pair"].error
    >>> bool(np.allclose(a, mc["best-pair"].error, rtol=1e-9))
    True
    """
    n_seeds = as_int(n_seeds, "n_seeds")
    if n_seeds < 2:
        raise ValueError(f"n_seeds must be at least 2 for the paired tests, got {n_seeds}")
    seed = as_int(seed, "seed", 0)
    metrics = as_names(metrics, "metrics")
    bad = [m for m in metrics if m not in tracking.METRICS]
    if bad or not metrics:
        raise ValueError(f"metrics must be among {tracking.METRICS}, got {list(metrics)}")
    known = tracking.STRATEGIES + tracking.CRITERIA
    strategies = (known if strategies is None
                  else as_names(strategies, "strategies", known))
    if REFERENCE not in strategies:
        raise ValueError(f"strategies must include the reference {REFERENCE!r}")
    return _tracking_study(int(n_seeds), int(seed), metrics, strategies)


def adversary_rows(mc: dict) -> list:
    """How the adversary of Section V-B fares against each strategy: one row per strategy with the
    fraction of runs that entrap it (:data:`obslib.tracking.ENTRAPMENT_CRITERIA`), its largest
    distance from the start, the exact ``C^{-1}`` the sensors face (mean and minimum), the mean
    bound, mean switches and mean error: the numbers of
    :func:`obslib.studies.adversarial_target.entrapment_summary`, computed over whole batches at
    once.

    Examples
    --------
    >>> from obslib.studies.adversarial_target import entrapment_summary
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=10)
    >>> mc = tracking.monte_carlo(setup, 2, ["best-pair"])
    >>> row, = adversary_rows(mc)
    >>> s = entrapment_summary(mc["best-pair"])
    >>> keys = ("entrapped", "max_from_start", "reach", "mean_error")
    >>> all(np.isclose(row[k], s[k], rtol=1e-9) for k in keys)
    True
    """
    mc = _mc_iv(mc)
    crit = tracking.ENTRAPMENT_CRITERIA
    rows = []
    for name, b in mc.items():
        path = np.concatenate([b.truth, (b.truth[:, -1] + b.control[:, -1])[:, None]], axis=1)
        far = np.hypot(*(path - path[:, :1]).transpose(2, 0, 1)).max(axis=1)  # (B,)
        ctrl = b.setup.control_array
        reach = b.steps * float(np.hypot(ctrl[:, 0], ctrl[:, 1]).max())
        icn = b.true_icn[:, 1:]
        bound_mean = b.bound.mean(axis=1)
        trapped = (far <= crit["reach_fraction"] * reach) & (bound_mean >= crit["bound_mean"]) & (
            icn.min(axis=1) >= crit["icn_min"])
        rows.append({
            "strategy": name,
            "entrapped": float(trapped.mean()),
            "max_from_start": float(far.max()),
            "reach": reach,
            "icn_mean": float(icn.mean(axis=1).mean()),
            "icn_min": float(icn.min()),
            "bound_mean": float(bound_mean.mean()),
            "switches": float(b.switches.mean()),
            "mean_error": float(b.error.mean(axis=1).mean()),
        })
    return rows


@lru_cache(maxsize=8)
def _assignment_study(targets, n_seeds, seed, steps, side, u_max, noise_std, p0, metric):
    out = {}
    seeds = range(seed, seed + n_seeds)
    for L in targets:
        setup = assignment_tracking.AssignmentTrackingSetup(
            n_targets=L, steps=steps, side=side, u_max=u_max, noise_std=noise_std, p0=p0,
            metric=metric)
        out[L] = assignment_tracking.run_all(setup, seeds)
    return out


def assignment_study(p: dict, metric: str = "mahalanobis") -> dict:
    """The assignment-by-tracking runs at the parameters ``p`` (:func:`obslib.profiles.params`),
    per ``L``.

    Returns ``{L: {rule: AssignmentRuns}}`` (cached).

    Examples
    --------
    >>> from obslib.profiles import params
    >>> p = dict(params(NOTEBOOK), assign_targets=[1, 2], assign_seeds=2,
    ...          assign_steps=5)
    >>> runs = assignment_study(p)
    >>> sorted(runs), list(runs[2])
    ([1, 2], ['bound', 'd-optimal', 'random'])
    >>> setup = assignment_tracking.AssignmentTrackingSetup(  # p's values
    ...     n_targets=2, steps=5)
    >>> direct = assignment_tracking.run(setup, "bound", [0, 1])
    >>> e = runs[2]["bound"].post_error
    >>> bool(np.allclose(e, direct.post_error, rtol=1e-9))
    True
    """
    p = as_mapping(p, "p")
    keys = ("assign_targets", "assign_seeds", "seed", "assign_steps", "assign_side",
            "assign_u_max", "assign_noise_std", "assign_p0")
    if not all(k in p for k in keys):
        raise ValueError(f"p must hold the parameters {keys} (obslib.profiles.params)")
    as_str(metric, "metric")
    targets = tuple(as_int(L, "assign_targets", 1)
                    for L in as_sequence(p["assign_targets"], "assign_targets"))
    return _assignment_study(
        targets, as_int(p["assign_seeds"], "assign_seeds", 1), as_int(p["seed"], "seed", 0),
        as_int(p["assign_steps"], "assign_steps", 1), as_positive(p["assign_side"], "assign_side"),
        as_positive(p["assign_u_max"], "assign_u_max"),
        as_positive(p["assign_noise_std"], "assign_noise_std"),
        as_positive(p["assign_p0"], "assign_p0"), metric)


def assignment_rows(runs: dict, reference: str = "bound",
                    loss_threshold: float = tracking.LOSS_THRESHOLD) -> list:
    """One row per ``(L, rule)``: mean, spread and median over runs of the per-run mean error
    summed over targets (after the update), ``lost`` (targets, over all runs, whose mean error
    exceeds ``loss_threshold``), ``lost_mirrored`` (those whose last estimate is nearer the
    target's mirror image across its last pair's baseline than the target), ``switch_rate``
    (fraction of steps where a target's pair changes), the chosen pairs' bound and information gain
    summed over targets, and the paired test against ``reference``.

    Examples
    --------
    >>> setup = assignment_tracking.AssignmentTrackingSetup(n_targets=2, steps=5)
    >>> runs = {2: assignment_tracking.run_all(setup, [0, 1, 2])}
    >>> rows = assignment_rows(runs)
    >>> [r["rule"] for r in rows], "vs_n" in rows[0], rows[2]["vs_n"]
    (['bound', 'd-optimal', 'random'], False, 3)
    >>> e = runs[2]["random"].post_error[:, 1:].sum(axis=-1).mean(axis=1)
    >>> bool(np.isclose(rows[2]["mean_error"], e.mean(), rtol=1e-12))
    True
    """
    runs = as_mapping(runs, "runs")
    for by_rule in runs.values():
        for r in as_mapping(by_rule, "runs").values():
            as_instance(r, assignment_tracking.AssignmentRuns, "runs")
        if as_str(reference, "reference") not in by_rule:
            raise ValueError(f"reference {reference!r} is not a rule of the runs")
    loss_threshold = as_nonnegative(loss_threshold, "loss_threshold")
    rows = []
    for L, by_rule in runs.items():
        ref = by_rule[reference].run_mean_error()
        for rule, r in by_rule.items():
            e = r.run_mean_error()
            row = {
                "L": int(L),
                "rule": rule,
                "mean_error": float(e.mean()),
                "sd_error": float(e.std(ddof=1)),
                "median_error": float(np.median(e)),
                "lost": int(r.lost(loss_threshold).sum()),
                "lost_mirrored": int((r.lost(loss_threshold) & r.mirrored()).sum()),
                "switch_rate": float((r.pairs[:, 1:] != r.pairs[:, :-1]).any(-1).mean()),
                "bound_sum": float(r.bound[:, 1:].sum(-1).mean()),
                "gain_sum": float(r.gain[:, 1:].sum(-1).mean()),
            }
            if rule != reference:
                row.update({f"vs_{k}": v for k, v in paired_test(ref, e).items()})
            rows.append(row)
    return rows

"""Statistics of tracking runs: strategy comparisons with common noise, rank correlations,
pair switches, track loss at the mirror image, and how far an adversarial target escapes.

Every function takes the results of :func:`~obslib.tracking.simulate` or the batch engine
(:class:`~obslib.tracking.TrackingResult`, :class:`~obslib.tracking.BatchResult`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._kernels import pair_series
from .._validate import (
    as_float_array,
    as_instance,
    as_int,
    as_nonnegative,
    as_point,
    as_real,
    broadcast,
)
from .results import BatchResult, TrackingResult

__all__ = [
    "TIE_RTOL",
    "LOSS_THRESHOLD",
    "clearly_lower",
    "compare_strategies",
    "spearman",
    "switch_rate",
    "switch_back_fraction",
    "bound_correlation",
    "mirror_point",
    "track_loss",
    "Entrapment",
    "entrapment",
    "ENTRAPMENT_CRITERIA",
    "is_entrapped",
]


#: Relative difference below which two logged values count as equal when strategies are compared.
TIE_RTOL = 1e-9

#: A run (or a target's track) is lost when its mean error exceeds this, unless told otherwise.
LOSS_THRESHOLD = 0.5


def _batch(batch, name: str = "batch") -> BatchResult:
    if not isinstance(batch, BatchResult):
        raise ValueError(f"{name} must be a BatchResult (simulate_batch, simulate_many, "
                         f"monte_carlo), got {type(batch).__name__}")
    return batch


def _result(result) -> TrackingResult:
    if not isinstance(result, TrackingResult) or isinstance(result, BatchResult):
        raise ValueError(f"result must be one run (a TrackingResult; batch.run(b) of a batch), "
                         f"got {type(result).__name__}")
    return result


def clearly_lower(a, b, rtol: float = TIE_RTOL) -> np.ndarray:
    """``a < b`` by more than ``rtol`` times the larger magnitude, elementwise.

    Two strategies that pick the same pairs for long enough drive their filters to the same
    state, equal up to rounding; whether such values compare as exactly equal then depends on the
    order of floating-point operations (and could differ between engines or machines). Counting
    only clear differences makes the win fractions independent of that: a tie wins for neither.

    Examples
    --------
    >>> clearly_lower([1.0, 1.0], [2.0, 1.0 + 1e-12]).tolist()
    [True, False]
    """
    a, b = broadcast({"a": as_float_array(a, "a"), "b": as_float_array(b, "b")})
    rtol = as_nonnegative(rtol, "rtol")
    return a < b - rtol * np.maximum(np.abs(a), np.abs(b))


def compare_strategies(mc: dict, reference: str = "best-pair", skip_first: bool = True) -> dict:
    """Monte Carlo statistics of Fig. 6: means, spreads and how often ``reference`` wins.

    Step 1 logs the values before any update, identical for all strategies by construction;
    ``skip_first`` leaves it out of the win fractions and overall means.

    Returns
    -------
    dict
        ``{"strategies": {name: {...}}, "wins": {other: {...}}}``. Per strategy: overall
        ``mean_error``, ``mean_trace``, ``mean_bound`` (over seeds and steps), their spread
        ``sd_*`` (standard deviation over seeds of the per-run means), ``switches`` (mean pair
        changes per run) and per-step arrays ``step_mean_*`` and ``step_sd_*`` (over seeds).
        Per other strategy: ``error_pointwise`` / ``trace_pointwise``, the fraction of
        (seed, step) with the reference lower; ``error_stepmean`` / ``trace_stepmean``,
        the fraction of steps where the reference's Monte Carlo mean is lower;
        ``bound_pointwise``, the fraction with the reference's bound higher; ``run_error`` /
        ``run_trace``, the fraction of runs with the reference's run mean lower. Lower and higher
        mean by more than :data:`TIE_RTOL` relatively (:func:`clearly_lower`): ties count for
        neither.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=20)
    >>> mc = {name: tracking.simulate_batch(setup, name, seeds=[0, 1])
    ...       for name in ("best-pair", "fixed-pair")}
    >>> c = tracking.compare_strategies(mc)
    >>> sorted(c["strategies"]), list(c["wins"])
    (['best-pair', 'fixed-pair'], ['fixed-pair'])
    >>> c["strategies"]["fixed-pair"]["switches"]  # a fixed pair never changes
    0.0
    >>> 0 <= c["wins"]["fixed-pair"]["error_pointwise"] <= 1
    True
    """
    if not isinstance(mc, dict) or not mc:
        raise ValueError("mc must be a non-empty dict {strategy: BatchResult}")
    for name, r in mc.items():
        _batch(r, f"mc[{name!r}]")
    if reference not in mc:
        raise ValueError(f"reference {reference!r} is not among the strategies {list(mc)}")
    steps = next(iter(mc.values())).error.shape[1]
    sl = slice(1, None) if skip_first and steps > 1 else slice(None)
    stats = {}
    for name, r in mc.items():
        d = {}
        for key, arr in (("error", r.error), ("trace", r.trace_cov), ("bound", r.bound)):
            a = arr[:, sl]
            d[f"mean_{key}"] = float(a.mean())
            d[f"sd_{key}"] = float(a.mean(axis=1).std(ddof=1)) if a.shape[0] > 1 else 0.0
            d[f"step_mean_{key}"] = arr.mean(axis=0)
            d[f"step_sd_{key}"] = arr.std(axis=0, ddof=1) if arr.shape[0] > 1 else 0 * arr[0]
        d["switches"] = float(r.switches.mean())
        stats[name] = d
    ref = mc[reference]
    wins = {}
    for name, r in mc.items():
        if name == reference:
            continue
        e1, e2 = ref.error[:, sl], r.error[:, sl]
        t1, t2 = ref.trace_cov[:, sl], r.trace_cov[:, sl]
        wins[name] = {
            "error_pointwise": float(clearly_lower(e1, e2).mean()),
            "trace_pointwise": float(clearly_lower(t1, t2).mean()),
            "error_stepmean": float(clearly_lower(e1.mean(0), e2.mean(0)).mean()),
            "trace_stepmean": float(clearly_lower(t1.mean(0), t2.mean(0)).mean()),
            "bound_pointwise": float(clearly_lower(r.bound[:, sl], ref.bound[:, sl]).mean()),
            "run_error": float(clearly_lower(e1.mean(1), e2.mean(1)).mean()),
            "run_trace": float(clearly_lower(t1.mean(1), t2.mean(1)).mean()),
        }
    return {"strategies": stats, "wins": wins}


def spearman(a, b, axis: int = -1) -> np.ndarray:
    """Spearman rank correlation of ``a`` and ``b`` along ``axis`` (ties by average rank): the
    Pearson correlation of ``scipy.stats.rankdata`` ranks, one value per slice (NaN where a
    slice is constant or holds a NaN).

    Examples
    --------
    >>> round(float(spearman([1, 2, 3], [3, 5, 4])), 12)
    0.5
    """
    from scipy import stats  # 0.6 s to import: not at ``import obslib``

    a, b = as_float_array(a, "a"), as_float_array(b, "b")
    axis = as_int(axis, "axis")
    if a.shape != b.shape or a.ndim == 0 or not -a.ndim <= axis < a.ndim or a.shape[axis] < 2:
        raise ValueError(f"a and b must have the same shape, with at least 2 values along axis "
                         f"{axis}, got {a.shape} and {b.shape}")
    ra = stats.rankdata(a, axis=axis)
    rb = stats.rankdata(b, axis=axis)
    return _pearson(ra, rb, axis)


def _pearson(ra, rb, axis: int = -1) -> np.ndarray:
    """``scipy.stats.pearsonr`` along ``axis``, NaN (without a warning) for a constant slice."""
    import warnings

    from scipy import stats

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", stats.ConstantInputWarning)
        return stats.pearsonr(ra, rb, axis=axis).statistic


def switch_back_fraction(batch: BatchResult) -> float:
    """Fraction of the pair switches that return at once to the pair of the step before.

    Over all runs of ``batch`` and the transitions ``k -> k + 1`` with ``k >= 2``: a switch
    (``pairs[k + 1] != pairs[k]``) counts as going back when ``pairs[k + 1] == pairs[k - 1]``.
    Chattering between two nearly equal pairs shows as a high fraction.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=20)
    >>> batch = tracking.simulate_batch(setup, "fixed-pair", seeds=[0, 1])
    >>> tracking.switch_back_fraction(batch)
    0.0
    >>> b = tracking.simulate_batch(setup, "best-pair", seeds=[0, 1])
    >>> 0.0 <= tracking.switch_back_fraction(b) <= 1.0
    True
    """
    sw = _batch(batch).switched[:, 1:]
    back = (batch.pairs[:, 2:] == batch.pairs[:, :-2]).all(axis=2) & sw
    return float(back.sum() / max(sw.sum(), 1))


def switch_rate(batch: BatchResult) -> np.ndarray:
    """Fraction of runs whose pair changes at each transition ``k -> k + 1``, ``(steps - 1,)``.

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=20)
    >>> batch = tracking.simulate_batch(setup, "fixed-pair", seeds=[0, 1])
    >>> rate = tracking.switch_rate(batch)
    >>> rate.shape, float(rate.max())
    ((19,), 0.0)
    """
    return _batch(batch).switched.mean(axis=0)


def bound_correlation(batch: BatchResult, bound: str = "own", skip_first: bool = True) -> dict:
    """Spearman correlation, within each run and over time, of the bound with error and trace.

    Section V-A: "higher C^-1 correlates with lower epsilon and trace(Sigma)". ``bound="own"``
    uses the logged bound (the setup's metric, Mahalanobis in the published runs, which itself
    shrinks as ``Sigma`` grows); ``bound="euclidean"`` re-evaluates the chosen pairs at the
    estimates with Euclidean distances, i.e. the geometry alone.

    Returns
    -------
    dict
        ``error`` and ``trace``: per-run correlations ``(B,)``.

    Examples
    --------
    >>> import numpy as np
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=20)
    >>> b = tracking.simulate_batch(setup, "best-pair", seeds=[0, 1, 2])
    >>> rho = tracking.bound_correlation(b, "euclidean")
    >>> ({k: v.shape for k, v in rho.items()},
    ...  bool((np.abs(rho["error"]) <= 1).all()))
    ({'error': (3,), 'trace': (3,)}, True)
    """
    _batch(batch)
    sl = slice(1, None) if skip_first else slice(None)
    if bound == "own":
        b = batch.bound
    elif bound == "euclidean":
        # pair_bound_series's worker, without re-validating the engine's estimates (finite:
        # the engine checks them); the same numbers (0.02 s against 0.05 s per 63,000 points)
        s = batch.setup.sensor_array
        x, pr = batch.estimate.reshape(-1, 2), batch.pairs.reshape(-1, 2)
        b = pair_series(x[None, :, :] - s[:, None, :], pr, batch.setup.u_max)
        b = b.reshape(batch.bound.shape)
    else:
        raise ValueError(f"bound must be 'own' or 'euclidean', got {bound!r}")
    from scipy.stats import rankdata

    rb = rankdata(b[:, sl], axis=1)  # ranked once for both correlations
    return {
        "error": _pearson(rb, rankdata(batch.error[:, sl], axis=1), axis=1),
        "trace": _pearson(rb, rankdata(batch.trace_cov[:, sl], axis=1), axis=1),
    }


def mirror_point(points, a, b) -> np.ndarray:
    """Reflection of ``points`` (..., 2) across the line through ``a`` and ``b``.

    Two range measurements cannot tell ``o`` from its mirror image across the baseline of the
    two sensors; a filter fed by one fixed pair can lock onto the mirror image.

    Examples
    --------
    >>> mirror_point([1.0, 1.0], [0.0, 0.0], [2.0, 0.0]).tolist()
    [1.0, -1.0]
    """
    a, b = as_point(a, "a"), as_point(b, "b")
    if (a == b).all():
        raise ValueError(f"a and b must be two points of a line, got twice {a.tolist()}")
    d = b - a
    d = d / np.hypot(*d)
    v = as_float_array(points, "points")
    if v.ndim < 1 or v.shape[-1] != 2 or not np.isfinite(v).all():
        raise ValueError(f"points must be finite, of shape (..., 2), got {v.shape}")
    v = v - a
    return a + 2 * (v @ d)[..., None] * d - v


def track_loss(batch: BatchResult, threshold: float = LOSS_THRESHOLD) -> dict:
    """Runs of a fixed pair whose estimate ends at the mirror image of the target.

    A run is *lost* when its mean error exceeds ``threshold``. For each run, also whether the
    last estimate is closer to the target's mirror image across the pair's baseline than to the
    target, and the first step from which it stays so.

    Returns
    -------
    dict
        ``lost`` (B,) bool, ``mirrored`` (B,) bool, ``flip_step`` (B,) int (1-based; 0 if never).

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=20)
    >>> b = tracking.simulate_batch(setup, "fixed-pair", seeds=[0, 1])
    >>> tracking.track_loss(b, threshold=1e9)["lost"].tolist()
    [False, False]
    >>> tracking.track_loss(b, threshold=-1.0)["lost"].tolist()
    [True, True]
    """
    _batch(batch)
    real = isinstance(threshold, (int, float, np.integer, np.floating))
    if isinstance(threshold, (bool, np.bool_)) or not real or not np.isfinite(threshold):
        raise ValueError(f"threshold must be a finite real number, got {threshold!r}")
    s = batch.setup.sensor_array
    i, j = batch.pairs[0, 0]
    t = batch.truth
    if t.shape[0] > 1 and t.strides[0] == 0:  # one path for every run (the circle): once
        m = np.broadcast_to(mirror_point(t[0], s[i], s[j]), t.shape)
    else:
        m = mirror_point(t, s[i], s[j])
    dm = np.hypot(*(batch.estimate - m).transpose(2, 0, 1))
    closer = dm < batch.error
    # first step from which the estimate stays closer to the mirror image
    stays = np.flip(np.logical_and.accumulate(np.flip(closer, axis=1), axis=1), axis=1)
    flip = np.where(stays.any(axis=1), stays.argmax(axis=1) + 1, 0)
    return {
        "lost": batch.error.mean(axis=1) > threshold,
        "mirrored": closer[:, -1],
        "flip_step": flip,
    }


@dataclass(frozen=True)
class Entrapment:
    """Measures of how "entrapped" an adversarial target is (Fig. 7).

    Attributes
    ----------
    reach : float
        How far the target could go: steps times the largest :math:`\\lVert u \\rVert` of its
        control set.
    net_displacement : float
        :math:`\\lVert o_{\\text{end}} - o_{\\text{start}} \\rVert`.
    max_from_start : float
        Largest distance from the start over the run.
    radius : float
        Radius of the smallest disc about the path's centroid containing the whole path.
    path_length : float
        Total distance travelled.
    bound_mean : float
        Mean of the sensors' pair bound over the run.
    bound_min : float
        Minimum of the sensors' pair bound over the run.
    icn_mean : float
        Mean of the exact :math:`C^{-1}` the sensors face (``true_icn``), steps 2.. (step 1 has
        no control).
    icn_min : float
        Its minimum over the same steps.
    objective_mean : float
        Mean of the value the target aimed at (its minimised :math:`C^{-1}`).
    switches : int
        Pair changes over ``steps - 1`` transitions.
    switch_gain : float
        Mean of ``true_icn[k+1] - objective[k]`` over transitions where the pair switched: what
        the switch gave back to the sensors.
    mean_error : float
        Mean tracking error over the run.
    mean_trace : float
        Mean trace of the filter's covariance over the run.
    """

    reach: float
    net_displacement: float
    max_from_start: float
    radius: float
    path_length: float
    bound_mean: float
    bound_min: float
    icn_mean: float
    icn_min: float
    objective_mean: float
    switches: int
    transitions: int
    switch_gain: float
    mean_error: float
    mean_trace: float


def entrapment(result: TrackingResult) -> Entrapment:
    """Measure how well the adversarial target of Fig. 7 escapes (:class:`Entrapment`).

    Examples
    --------
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=20)
    >>> r = tracking.simulate(setup, "best-pair", seed=0)
    >>> e = tracking.entrapment(r)
    >>> e.transitions, e.max_from_start <= e.reach, 0 <= e.switches <= 19
    (19, True, True)
    """
    _result(result)
    path = np.vstack([result.truth, result.truth[-1] + result.control[-1]])
    c = path.mean(axis=0)
    ctrl = result.setup.control_array
    reach = result.steps * float(np.hypot(ctrl[:, 0], ctrl[:, 1]).max())
    sw = result.switched
    gain = result.true_icn[1:][sw] - result.objective[:-1][sw]
    return Entrapment(
        reach=reach,
        net_displacement=float(np.hypot(*(path[-1] - path[0]))),
        max_from_start=float(np.hypot(*(path - path[0]).T).max()),
        radius=float(np.hypot(*(path - c).T).max()),
        path_length=float(np.hypot(*np.diff(path, axis=0).T).sum()),
        bound_mean=float(result.bound.mean()),
        bound_min=float(result.bound.min()),
        icn_mean=float(result.true_icn[1:].mean()) if result.steps > 1 else float("nan"),
        icn_min=float(result.true_icn[1:].min()) if result.steps > 1 else float("nan"),
        objective_mean=float(result.objective.mean()),
        switches=int(sw.sum()),
        transitions=int(sw.size),
        switch_gain=float(gain.mean()) if gain.size else 0.0,
        mean_error=float(result.error.mean()),
        mean_trace=float(result.trace_cov.mean()),
    )


#: What "entrapped" means in this book (fixed before looking at the runs), the target stays
#: within ``reach_fraction`` of its reach (``steps * max ||u||``) from its start, the sensors'
#: bound averages at least ``bound_mean`` and the exact C^-1 they face never drops below
#: ``icn_min``.
ENTRAPMENT_CRITERIA = {"reach_fraction": 0.2, "bound_mean": 0.5, "icn_min": 0.1}


def is_entrapped(e: Entrapment, reach_fraction=None, bound_mean=None, icn_min=None) -> bool:
    """Whether one adversarial run meets :data:`ENTRAPMENT_CRITERIA` (or the values given).

    Examples
    --------
    Criteria that every run meets, and a bound no run reaches (:math:`C^{-1} \\le 1`):

    >>> from obslib import tracking
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=20)
    >>> r = tracking.simulate(setup, "best-pair", seed=0)
    >>> e = tracking.entrapment(r)
    >>> tracking.is_entrapped(e, reach_fraction=1.0, bound_mean=0.0, icn_min=0.0)
    True
    >>> tracking.is_entrapped(e, bound_mean=1.5)
    False
    """
    as_instance(e, Entrapment, "e")
    c = dict(ENTRAPMENT_CRITERIA)
    given = {"reach_fraction": reach_fraction, "bound_mean": bound_mean, "icn_min": icn_min}
    c.update({k: as_real(v, k) for k, v in given.items() if v is not None})
    return bool(
        e.max_from_start <= c["reach_fraction"] * e.reach
        and e.bound_mean >= c["bound_mean"]
        and e.icn_min >= c["icn_min"]
    )

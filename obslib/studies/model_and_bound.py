"""Audits of Section III's Theorems 1-3 and Remark 1 on seeded random scenes (notebook 01, claims of
:mod:`obslib.claims.model_and_bound`).

Each audit draws seeded random scenes (:mod:`obslib.scenes`), computes the quantity a claim
is about in two independent ways, and returns the counts and extremes that decide it. The
claims ledger (:mod:`obslib.claims`) and notebook 01 both call these functions, which validate
their arguments and then call a worker cached on them, so the report and the notebook show the
numbers of one computation.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from .._validate import as_float_array, as_int, broadcast, check_scene_batch
from ..bounds import lower_bounds, worst_case_controls
from ..observability import inverse_condition_numbers, inverse_condition_numbers_polar
from ..scenes import random_scene_batch

__all__ = [
    "NOTEBOOK",
    "Theorem1Audit",
    "theorem1_audit",
    "Theorem2Audit",
    "theorem2_audit",
    "Theorem3Audit",
    "theorem3_audit",
    "theorem3_terms",
    "Remark1Audit",
    "remark1_audit",
    "RankAudit",
    "rank_observability_audit",
    "SquaredRangeAudit",
    "squared_range_audit",
]

#: The chapter of these studies.
NOTEBOOK = "01_model_and_bound"

#: Absolute slack allowed when comparing two floating-point evaluations of values in [0, 1].
ATOL = 1e-12


@dataclass(frozen=True)
class Theorem1Audit:
    """Bound versus exact ``C^{-1}`` over random scenes and controls in the disc."""

    n_scenes: int
    n_evaluations: int
    n_violations: int
    worst_excess: float  #: max over all evaluations of ``bound - exact`` (<= 0 when it holds)
    max_attainment_error: float  #: max ``|C^{-1}(o, u*) - bound|`` at the worst-case control
    min_slack_by_kind: dict = field(default_factory=dict)


def theorem1_audit(n_scenes: int, n_controls: int, seed: int) -> Theorem1Audit:
    r"""Check Theorem 1, :math:`\underline{C}^{-1} \le C^{-1}(O(o, u))`, for random :math:`\|u\| \le
    u_{\max}`.

    For every scene (:func:`obslib.scenes.random_scene_batch`), ``n_controls`` controls are
    drawn uniformly in the disc, plus the worst-case control :math:`u_{\max} v_{\max}`
    (:func:`obslib.bounds.worst_case_controls`); the bound (SVD of :math:`O(o)`,
    :func:`obslib.bounds.lower_bounds`) is compared with the exact inverse condition number of
    :math:`O(o, u)` (from its Gram matrix, :func:`obslib.observability.inverse_condition_numbers`).
    All scenes are evaluated at once; the batched functions equal the per-scene ones
    (:func:`lower_bound`, :func:`worst_case_control`, :func:`inverse_condition_number`) to
    rounding, as the tests check.

    Examples
    --------
    >>> a = theorem1_audit(n_scenes=50, n_controls=8, seed=0)
    >>> a.n_evaluations, a.n_violations
    (450, 0)
    """
    return _theorem1_audit(
        as_int(n_scenes, "n_scenes", 1),
        as_int(n_controls, "n_controls", 1),
        as_int(seed, "seed", 0),
    )


@lru_cache(maxsize=8)
def _theorem1_audit(n_scenes, n_controls, seed) -> Theorem1Audit:
    batch = random_scene_batch(n_scenes, seed)
    rows, u_max = batch.rows, batch.u_max
    rng = np.random.default_rng(seed + 1)
    r = u_max[:, None] * np.sqrt(rng.uniform(size=(n_scenes, n_controls)))
    phi = rng.uniform(0, 2 * np.pi, size=(n_scenes, n_controls))
    bound = lower_bounds(rows, u_max)
    u_star = worst_case_controls(rows, u_max)
    controls = np.concatenate(
        [np.stack([r * np.cos(phi), r * np.sin(phi)], axis=-1), u_star[:, None, :]], axis=1
    )
    exact = inverse_condition_numbers(rows, controls)  # (S, n_controls + 1), u* last
    excess = bound[:, None] - exact
    kinds = np.array(batch.kinds)
    slack = (-excess).min(axis=1)
    min_slack = {k: float(slack[kinds == k].min()) for k in dict.fromkeys(batch.kinds)}
    return Theorem1Audit(
        n_scenes=n_scenes,
        n_evaluations=int(exact.size),
        n_violations=int((excess > ATOL).sum()),
        worst_excess=float(excess.max()),
        max_attainment_error=float(np.abs(exact[:, -1] - bound).max()),
        min_slack_by_kind=min_slack,
    )


@dataclass(frozen=True)
class Theorem2Audit:
    """One sensor: the bound from the eigenvalues of ``O_i(o)^T O_i(o)``, and the exact value."""

    n_scenes: int
    max_bound: float  #: max of ``sqrt(lambda_min / (lambda_max + u^2))`` from eigvalsh
    max_relative_lambda_min: float  #: max ``|lambda_min| / lambda_max`` (0 up to rounding)
    exact_range: tuple  #: (min, max) of the exact one-sensor ``C^{-1}`` over random controls


def theorem2_audit(n_scenes: int, seed: int) -> Theorem2Audit:
    r"""Check Theorem 2: with one sensor the bound is 0 wherever the sensor is.

    The bound is recomputed from ``numpy.linalg.eigvalsh`` of the 2x2 matrices
    :math:`O_i(o)^T O_i(o)` (stacked over the scenes; not from :func:`lower_bound`, which returns 0
    for :math:`N < 2` by definition). The exact one-sensor :math:`C^{-1}` with a random control is
    reported too: it is not 0, so the sensor's geometry does matter once :math:`u_o` is known.

    Examples
    --------
    >>> a = theorem2_audit(n_scenes=50, seed=0)
    >>> a.max_bound < 1e-7, a.max_relative_lambda_min < 1e-14
    (True, True)
    """
    return _theorem2_audit(
        as_int(n_scenes, "n_scenes", 1),
        as_int(seed, "seed", 0),
    )


@lru_cache(maxsize=8)
def _theorem2_audit(n_scenes, seed) -> Theorem2Audit:
    batch = random_scene_batch(n_scenes, seed, n_sensors=(1, 1), kinds=("generic", "spread"))
    rows = batch.rows  # (S, 1, 2)
    lam = np.linalg.eigvalsh(np.swapaxes(rows, 1, 2) @ rows)
    rng = np.random.default_rng(seed + 2)
    mag = batch.u_max * rng.uniform(size=n_scenes)
    a = rng.uniform(0, 2 * np.pi, size=n_scenes)
    u = mag[:, None] * np.column_stack([np.cos(a), np.sin(a)])
    exact = inverse_condition_numbers(rows, u)
    bound = np.sqrt(np.maximum(lam[:, 0], 0.0) / (lam[:, 1] + batch.u_max**2))
    return Theorem2Audit(
        n_scenes=n_scenes,
        max_bound=float(bound.max()),
        max_relative_lambda_min=float((np.abs(lam[:, 0]) / lam[:, 1]).max()),
        exact_range=(float(exact.min()), float(exact.max())),
    )


def theorem3_terms(lam_before, lam_after, u2):
    """The two terms of the numerator in the proof of Theorem 3 (Eq. (29)).

    ``bound'^2 - bound^2`` has the positive denominator
    ``(lambda'_max + u^2)(lambda_max + u^2)`` and numerator ``T1 + T2`` with
    ``T1 = lambda'_min lambda_max - lambda'_max lambda_min`` and
    ``T2 = u^2 (lambda'_min - lambda_min)``.

    Examples
    --------
    >>> theorem3_terms((1.0, 4.0), (2.0, 4.0), u2=1.0)
    (4.0, 1.0)
    """
    checked = {}
    for name, lam in (("lam_before", lam_before), ("lam_after", lam_after), ("u2", u2)):
        a = checked[name] = as_float_array(lam, name)
        if name != "u2" and (a.ndim < 1 or a.shape[0] != 2):
            raise ValueError(f"{name} must be (lambda_min, lambda_max), got shape {a.shape}")
        if not np.isfinite(a).all() or (name == "u2" and (a < 0).any()):
            raise ValueError(f"{name} must be finite" + (" and non-negative" * (name == "u2")))
    broadcast({"lam_before": checked["lam_before"][0], "lam_after": checked["lam_after"][0],
               "u2": checked["u2"]})
    (lmin, lmax), (lmin2, lmax2) = lam_before, lam_after
    return lmin2 * lmax - lmax2 * lmin, u2 * (lmin2 - lmin)


@dataclass(frozen=True)
class Theorem3Audit:
    """Outcomes of random before/after configurations, grouped by which conditions hold."""

    n_trials: int
    counts: dict  #: condition name -> (trials where it holds, of those where the bound decreased)
    witnesses: dict  #: condition name -> one trial where it holds and the bound decreased
    #: every trial meeting the proof's printed condition meets the stated one
    printed_implies_stated: bool
    #: trials where the bound clearly increased but ``T1 + T2 < 0``
    remark2_necessary_violations: int


def theorem3_audit(n_trials: int, seed: int) -> Theorem3Audit:
    r"""Check Theorem 3 and the condition printed in its proof on random configurations.

    Each trial draws a "before" and an "after" set of 2-4 sensors, uniform in a square of
    half-side :math:`10^{U(-1, 1)}` around a target at the origin, and a speed
    :math:`u \sim U(0, 2)`. The theorem's condition ("stated") is that both :math:`C^{-1}(O(o))` and
    :math:`\sigma_{\min}(O(o))` do not decrease; the proof's Eq. (27) ("printed") asks instead for
    the ratio not to decrease and :math:`\lambda'_{\min} \ge \lambda_{\max}`. Also counted: each
    half of the stated condition alone, and the weaker condition of Remark 2
    (:math:`T_1 + T_2 \ge 0`), which is necessary and sufficient. All trials are drawn and evaluated
    at once (``eigvalsh`` of the stacked 2x2 matrices :math:`O(o)^T O(o)`); a witness is the first
    trial, in draw order, of its row.

    Examples
    --------
    >>> a = theorem3_audit(n_trials=500, seed=0)
    >>> (a.counts["stated"], a.printed_implies_stated,
    ...  a.remark2_necessary_violations)
    ((168, 0), True, 0)
    """
    return _theorem3_audit(
        as_int(n_trials, "n_trials", 1),
        as_int(seed, "seed", 0),
    )


@lru_cache(maxsize=8)
def _theorem3_audit(n_trials, seed) -> Theorem3Audit:
    rng = np.random.default_rng(seed)
    T = n_trials
    counts_n = rng.integers(2, 5, size=(T, 2))  # sensors before / after
    scale = 10.0 ** rng.uniform(-1, 1, size=(T, 2))
    sensors = rng.uniform(-1, 1, size=(T, 2, 4, 2)) * scale[..., None, None]
    u = rng.uniform(0, 2, size=T)
    valid = np.arange(4) < counts_n[..., None]  # (T, 2, 4)
    flat = np.where(valid[..., None], sensors, np.nan).reshape(2 * T, 4, 2)
    check_scene_batch(flat, np.zeros((2 * T, 2)), counts_n.reshape(-1))
    rows = np.where(valid[..., None], -sensors, 0.0)  # o - p_i with o = 0, zero padding
    lam = np.linalg.eigvalsh(np.swapaxes(rows, -1, -2) @ rows)  # (T, 2, 2)
    u2 = u**2
    lmin, lmax, lmin2, lmax2 = lam[:, 0, 0], lam[:, 0, 1], lam[:, 1, 0], lam[:, 1, 1]
    b_before = np.sqrt(lmin / (lmax + u2))
    b_after = np.sqrt(lmin2 / (lmax2 + u2))
    decreased = b_after < b_before * (1 - 1e-12)
    ratio_up = lmin2 * lmax >= lmax2 * lmin
    smin_up = lmin2 >= lmin
    t1, t2 = theorem3_terms((lmin, lmax), (lmin2, lmax2), u2)
    holds = {
        "stated": ratio_up & smin_up,
        "printed": ratio_up & (lmin2 >= lmax),
        "ratio only": ratio_up & ~smin_up,
        "sigma_min only": smin_up & ~ratio_up,
        "remark 2": t1 + t2 >= 0,
        "neither": ~ratio_up & ~smin_up,
    }
    necessary = int(((b_after > b_before * (1 + 1e-9)) & ~holds["remark 2"]).sum())
    counts, witnesses = {}, {}
    for k, h in holds.items():
        bad = h & decreased
        counts[k] = (int(h.sum()), int(bad.sum()))
        if bad.any():
            i = int(np.argmax(bad))
            witnesses[k] = {
                "before": sensors[i, 0, : counts_n[i, 0]].round(6).tolist(),
                "after": sensors[i, 1, : counts_n[i, 1]].round(6).tolist(),
                "u": round(float(u[i]), 6),
                "bound_before": round(float(b_before[i]), 6),
                "bound_after": round(float(b_after[i]), 6),
            }
    return Theorem3Audit(
        n_trials=n_trials,
        counts=counts,
        witnesses=witnesses,
        printed_implies_stated=bool(not (holds["printed"] & ~holds["stated"]).any()),
        remark2_necessary_violations=necessary,
    )


@dataclass(frozen=True)
class Remark1Audit:
    """Tightness of Theorem 1's bound: stationary target, and moving at full speed."""

    n_scenes: int
    max_stationary_error: float  #: max ``|C^{-2}(O(o, 0)) - lambda_min / lambda_max|``
    max_moving_error: float  #: max ``|C^{-1}(O(o, u*)) - bound(u_max)|`` with ``||u*|| = u_max``
    #: min over scenes of (grid minimum of ``C^{-1}`` over the disc) - bound
    min_over_disc_gap: float


def remark1_audit(n_scenes: int, seed: int, n_radii: int = 8, n_angles: int = 64) -> Remark1Audit:
    r"""Check Remark 1 (the bound is exact for :math:`u_o = 0`) and its moving-target counterpart.

    For every scene: the exact :math:`C^{-1}` of the stationary target (:math:`O(o, 0)`, zero
    row included) against the bound in eigenvalue form with :math:`u_{\max} = 0` (``eigvalsh`` of
    :math:`O(o)^T O(o)`; compared as squares, since a tiny :math:`\lambda_{\min}` is only known to
    :math:`\varepsilon \lambda_{\max}`); the exact :math:`C^{-1}` at the worst-case control (norm
    :math:`u_{\max}` along the principal eigenvector) against the bound (SVD); and the minimum of
    the exact value over a polar grid of the disc (:func:`obslib.controls.disc_controls`), which can
    only approach the bound from above. All scenes at once, with the batched functions of
    :func:`theorem1_audit`.

    Examples
    --------
    >>> a = remark1_audit(n_scenes=50, seed=0)
    >>> (a.max_stationary_error < 1e-12, a.max_moving_error < 1e-12,
    ...  a.min_over_disc_gap >= -1e-12)
    (True, True, True)
    """
    return _remark1_audit(
        as_int(n_scenes, "n_scenes", 1),
        as_int(seed, "seed", 0),
        as_int(n_radii, "n_radii", 1),
        as_int(n_angles, "n_angles", 1),
    )


@lru_cache(maxsize=8)
def _remark1_audit(n_scenes, seed, n_radii, n_angles) -> Remark1Audit:
    batch = random_scene_batch(n_scenes, seed, kinds=("generic", "spread"))
    rows, u_max = batch.rows, batch.u_max
    lam = np.linalg.eigvalsh(np.swapaxes(rows, 1, 2) @ rows)
    exact0 = inverse_condition_numbers(rows, np.zeros((n_scenes, 2)))
    stat = np.abs(exact0**2 - lam[:, 0] / lam[:, 1]).max()
    b = lower_bounds(rows, u_max)
    u_star = worst_case_controls(rows, u_max)
    moving = np.abs(inverse_condition_numbers(rows, u_star) - b).max()
    # the polar grid of disc_controls(u_max, n_radii, n_angles): u = 0, then n_radii rings
    radii = u_max[:, None] * np.arange(1, n_radii + 1)[None, :] / n_radii
    rings = inverse_condition_numbers_polar(rows, radii, 2 * np.pi * np.arange(n_angles) / n_angles)
    grid_min = np.minimum(exact0, rings.min(axis=(1, 2)))
    gap = (grid_min - b).min()
    return Remark1Audit(
        n_scenes=n_scenes,
        max_stationary_error=float(stat),
        max_moving_error=float(moving),
        min_over_disc_gap=float(gap),
    )


@dataclass(frozen=True)
class RankAudit:
    """The rank test of Sec. III against what the outputs can tell apart, in random scenes."""

    n_full: int  #: scenes whose matrix of Eq. (5) has full column rank
    #: min over them of the smallest stretch of the output map over sigma_min of Eq. (4)
    min_ratio: float
    min_stretch: float  #: the smallest stretch over them, relative to the scene's length scale
    n_deficient: int  #: one sensor and a stationary target: rank one
    max_twin_gap: float  #: max relative output difference between a position and its twin
    max_deficient_icn: float  #: max C^-1 of the rank-one matrices (0: singular)
    icn_range: tuple  #: (min, max) of C^-1 over every scene (in [0, 1])


def _outputs(sensors: np.ndarray, o: np.ndarray, u: np.ndarray) -> np.ndarray:
    """The outputs of Eq. (3) and their rates: ``z_i = |p_i - o|^2 / 2``, ``(o - p_i) . u``,
    for positions ``o`` of shape (..., 2); shape (..., 2 N)."""
    d = o[..., None, :] - sensors
    return np.concatenate([0.5 * (d**2).sum(-1), d @ u], axis=-1)


def rank_observability_audit(n_scenes: int, seed: int, n_directions: int = 72) -> RankAudit:
    r"""Check the rank test of Sec. III: full column rank of :math:`O(o, u_o)` and local
    observability.

    The outputs the sensors see near a position are the measurements and their rates, the map
    :math:`F(o) = (z_i(o), \dot z_i(o))_i` whose Jacobian has the rows of Eq. (4). For random
    scenes of 1 to 4 sensors and controls (zero for a quarter of them), the smallest stretch
    :math:`\min_{\lVert d\rVert = 1} \lVert F(o + \varepsilon d) - F(o)\rVert / \varepsilon`
    over ``n_directions`` directions is compared with :math:`\sigma_{\min}` of that Jacobian
    (it is that value, to the grid and to first order in :math:`\varepsilon`), which has the
    rank of Eq. (5)'s matrix: positive stretch means no nearby position gives the same
    outputs. Where the matrix has rank one (one
    sensor, a stationary target) the position turned about the sensor by a small angle is an
    exact twin: the outputs are the same.

    Examples
    --------
    >>> a = rank_observability_audit(200, seed=0)
    >>> a.min_ratio > 0.99, a.max_twin_gap < 1e-12, a.max_deficient_icn < 1e-7
    (True, True, True)
    """
    return _rank_observability_audit(
        as_int(n_scenes, "n_scenes", 4),
        as_int(seed, "seed", 0),
        as_int(n_directions, "n_directions", 8),
    )


@lru_cache(maxsize=8)
def _rank_observability_audit(n_scenes, seed, n_directions) -> RankAudit:
    rng = np.random.default_rng(seed)
    phi = 2 * np.pi * np.arange(n_directions) / n_directions
    dirs = np.column_stack([np.cos(phi), np.sin(phi)])
    ratios, stretches, twins, deficient_icn, icns = [], [], [], [], []
    for k in range(n_scenes):
        n = int(rng.integers(1, 5))
        scale = float(10.0 ** rng.uniform(-1, 2))
        o = rng.uniform(-scale, scale, size=2)
        sensors = o + rng.uniform(-scale, scale, size=(n, 2))
        u = np.zeros(2) if k % 4 == 0 else rng.uniform(-scale, scale, size=2)
        M = np.vstack([o - sensors, u])  # Eq. (5)
        sv = np.linalg.svd(M, compute_uv=False)
        icns.append(sv[-1] / sv[0])
        # the Jacobian of F: the rows of Eq. (4), a control row per sensor (same rank as M)
        sv4 = np.linalg.svd(np.vstack([o - sensors, np.tile(u, (n, 1))]), compute_uv=False)
        if n == 1 and not u.any():
            # rank one: turn o about the sensor by a small angle, same range, zero rate
            c, s = np.cos(1e-3), np.sin(1e-3)
            twin = sensors[0] + np.array([[c, -s], [s, c]]) @ (o - sensors[0])
            gap = np.abs(_outputs(sensors, twin, u) - _outputs(sensors, o, u)).max()
            twins.append(gap / scale**2)
            deficient_icn.append(sv[-1] / sv[0])
            continue
        eps = 1e-6 * scale
        diff = _outputs(sensors, o + eps * dirs, u) - _outputs(sensors, o, u)
        stretch = np.sqrt((diff**2).sum(-1)).min() / eps
        ratios.append(stretch / sv4[-1])
        stretches.append(stretch / scale)
    return RankAudit(
        n_full=len(ratios),
        min_ratio=float(min(ratios)),
        min_stretch=float(min(stretches)),
        n_deficient=len(twins),
        max_twin_gap=float(max(twins)) if twins else 0.0,
        max_deficient_icn=float(max(deficient_icn)) if deficient_icn else 0.0,
        icn_range=(float(min(icns)), float(max(icns))),
    )


@dataclass(frozen=True)
class SquaredRangeAudit:
    """Half the squared range against the range itself, for a stationary target."""

    n_scenes: int
    n_sensors: int
    same_rank: int  #: scenes where the two matrices have the same rank
    pair_differs: float  #: share of scenes where the best pair by C^-1 differs
    icn_ratio: tuple  #: (min, max) over scenes of the best pair's C^-1, range over squared range


def squared_range_audit(n_scenes: int, seed: int, n_sensors: int = 6) -> SquaredRangeAudit:
    r"""What the square in :math:`z_i = \tfrac12\lVert p_i - o\rVert^2` changes.

    With the range :math:`\lVert p_i - o\rVert` as the measurement, the sensor's row of the
    local observability matrix is the unit vector :math:`(o - p_i)^T / d_i` instead of
    :math:`(o - p_i)^T` (:func:`obslib.symbolic.lie.lie_rows`), so the rank is the same but not
    the condition number. For a stationary target, where the exact :math:`C^{-1}` is
    :math:`\sigma_{\min}/\sigma_{\max}` of the rows (Remark 1), the best pair of ``n_sensors``
    random sensors is chosen by each measurement model; the share of scenes where the two
    choices differ says whether the square is only a convenience.

    Examples
    --------
    >>> a = squared_range_audit(300, seed=0)
    >>> a.same_rank == a.n_scenes, 0 < a.pair_differs < 1
    (True, True)
    """
    return _squared_range_audit(
        as_int(n_scenes, "n_scenes", 1),
        as_int(seed, "seed", 0),
        as_int(n_sensors, "n_sensors", 3),
    )


@lru_cache(maxsize=8)
def _squared_range_audit(n_scenes, seed, n_sensors) -> SquaredRangeAudit:
    rng = np.random.default_rng(seed)
    targets = rng.uniform(0, 100, size=(n_scenes, 2))
    sensors = rng.uniform(0, 100, size=(n_scenes, n_sensors, 2))
    rows = targets[:, None, :] - sensors
    unit = rows / np.linalg.norm(rows, axis=-1, keepdims=True)
    i, j = np.triu_indices(n_sensors, 1)

    def pair_icn(r):
        pairs = np.stack([r[:, i], r[:, j]], axis=2)  # (S, P, 2, 2)
        return inverse_condition_numbers(pairs.reshape(-1, 2, 2)).reshape(n_scenes, -1)

    sq, rg = pair_icn(rows), pair_icn(unit)
    best_sq, best_rg = sq.argmax(axis=1), rg.argmax(axis=1)
    k = np.arange(n_scenes)
    same_rank = int((np.linalg.matrix_rank(rows) == np.linalg.matrix_rank(unit)).sum())
    ratio = rg[k, best_rg] / sq[k, best_sq]
    return SquaredRangeAudit(n_scenes, n_sensors, same_rank,
                             float(np.mean(best_sq != best_rg)),
                             (float(ratio.min()), float(ratio.max())))

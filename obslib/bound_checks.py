"""Numerical audits of Section III: Theorems 1-3 and Remark 1.

Each audit draws seeded random scenes (:mod:`obslib.scenes`), computes the quantity a claim
is about in two independent ways, and returns the counts and extremes that decide it. The
claims ledger (:mod:`obslib.claims`) and notebook 01 both call these functions, so the
report and the notebook show the same numbers.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .bounds import lower_bound, worst_case_control
from .observability import inverse_condition_number, relative_rows
from .scenes import random_scenes

__all__ = [
    "disc_controls",
    "Theorem1Audit",
    "theorem1_audit",
    "Theorem2Audit",
    "theorem2_audit",
    "Theorem3Audit",
    "theorem3_audit",
    "theorem3_terms",
    "Remark1Audit",
    "remark1_audit",
]

#: Absolute slack allowed when comparing two floating-point evaluations of values in [0, 1].
ATOL = 1e-12


def disc_controls(u_max: float, n_radii: int, n_angles: int) -> np.ndarray:
    """Polar grid of controls covering the disc ``||u|| <= u_max``, boundary included.

    Returns ``1 + n_radii * n_angles`` controls: ``u = 0`` and ``n_angles`` directions at each
    of ``n_radii`` radii spaced evenly up to ``u_max``.
    """
    radii = u_max * np.arange(1, n_radii + 1) / n_radii
    phi = 2 * np.pi * np.arange(n_angles) / n_angles
    ring = np.column_stack([np.cos(phi), np.sin(phi)])
    grid = (radii[:, None, None] * ring[None, :, :]).reshape(-1, 2)
    return np.vstack([np.zeros((1, 2)), grid])


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
    """Check ``lower_bound <= C^{-1}(O(o, u))`` for random ``||u|| <= u_max`` (Theorem 1).

    For every scene, ``n_controls`` controls are drawn uniformly in the disc, plus the
    worst-case control of :func:`obslib.bounds.worst_case_control`; the bound (SVD of ``O(o)``)
    is compared with the exact inverse condition number of ``O(o, u)`` (from its Gram matrix,
    :func:`obslib.inverse_condition_number`).
    """
    rng = np.random.default_rng(seed + 1)
    n_eval = 0
    n_viol = 0
    worst_excess = -np.inf
    max_attain = 0.0
    min_slack: dict[str, float] = {}
    for sc in random_scenes(n_scenes, seed):
        bound = lower_bound(sc.sensors, sc.target, sc.u_max)
        r = sc.u_max * np.sqrt(rng.uniform(size=n_controls))
        phi = rng.uniform(0, 2 * np.pi, size=n_controls)
        u_star = worst_case_control(sc.sensors, sc.target, sc.u_max)
        controls = np.vstack([np.column_stack([r * np.cos(phi), r * np.sin(phi)]), u_star])
        exact = inverse_condition_number(sc.sensors, sc.target, controls)
        excess = bound - exact
        n_eval += exact.size
        n_viol += int((excess > ATOL).sum())
        worst_excess = max(worst_excess, float(excess.max()))
        max_attain = max(max_attain, float(abs(exact[-1] - bound)))
        min_slack[sc.kind] = min(min_slack.get(sc.kind, np.inf), float((-excess).min()))
    return Theorem1Audit(
        n_scenes=n_scenes,
        n_evaluations=n_eval,
        n_violations=n_viol,
        worst_excess=worst_excess,
        max_attainment_error=max_attain,
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
    """Check Theorem 2: with one sensor the bound is 0 wherever the sensor is.

    The bound is recomputed from ``numpy.linalg.eigvalsh`` of the 2x2 matrix
    ``O_i(o)^T O_i(o)`` (not from :func:`lower_bound`, which returns 0 for ``N < 2`` by
    definition). The exact one-sensor ``C^{-1}`` with a random control is reported too: it is
    not 0, so the sensor's geometry does matter once ``u_o`` is known.
    """
    rng = np.random.default_rng(seed + 2)
    max_bound = 0.0
    max_rel = 0.0
    exact_vals = []
    for sc in random_scenes(n_scenes, seed, n_sensors=(1, 1), kinds=("generic", "spread")):
        rows = relative_rows(sc.sensors, sc.target)
        lam = np.linalg.eigvalsh(rows.T @ rows)
        max_rel = max(max_rel, abs(lam[0]) / lam[1])
        max_bound = max(max_bound, float(np.sqrt(max(lam[0], 0.0) / (lam[1] + sc.u_max**2))))
        u = sc.u_max * rng.uniform() * np.array([np.cos(a := rng.uniform(0, 2 * np.pi)), np.sin(a)])
        exact_vals.append(inverse_condition_number(sc.sensors, sc.target, u))
    return Theorem2Audit(
        n_scenes=n_scenes,
        max_bound=max_bound,
        max_relative_lambda_min=float(max_rel),
        exact_range=(float(min(exact_vals)), float(max(exact_vals))),
    )


def theorem3_terms(lam_before, lam_after, u2):
    """The two terms of the numerator in the proof of Theorem 3 (Eq. (29)).

    ``bound'^2 - bound^2`` has the positive denominator
    ``(lambda'_max + u^2)(lambda_max + u^2)`` and numerator ``T1 + T2`` with
    ``T1 = lambda'_min lambda_max - lambda'_max lambda_min`` and
    ``T2 = u^2 (lambda'_min - lambda_min)``.
    """
    (lmin, lmax), (lmin2, lmax2) = lam_before, lam_after
    return lmin2 * lmax - lmax2 * lmin, u2 * (lmin2 - lmin)


@dataclass(frozen=True)
class Theorem3Audit:
    """Outcomes of random before/after configurations, grouped by which conditions hold."""

    n_trials: int
    counts: dict  #: condition name -> (trials where it holds, of those where the bound decreased)
    witnesses: dict  #: condition name -> one trial where it holds and the bound decreased
    printed_implies_stated: bool  #: every trial meeting the proof's printed condition meets the stated one
    remark2_necessary_violations: int  #: trials where the bound clearly increased but ``T1 + T2 < 0``


def theorem3_audit(n_trials: int, seed: int) -> Theorem3Audit:
    """Check Theorem 3 and the condition printed in its proof on random configurations.

    Each trial draws a "before" and an "after" set of 2-4 sensors around a target at the
    origin and a speed ``u``. The theorem's condition ("stated") is that both
    ``C^{-1}(O(o))`` and ``sigma_min(O(o))`` do not decrease; the proof's Eq. (27)
    ("printed") asks instead for the ratio not to decrease and ``lambda'_min >= lambda_max``.
    Also counted: each half of the stated condition alone, and the weaker condition of
    Remark 2 (``T1 + T2 >= 0``), which is necessary and sufficient.
    """
    rng = np.random.default_rng(seed)
    names = ("stated", "printed", "ratio only", "sigma_min only", "remark 2", "neither")
    counts = {k: [0, 0] for k in names}
    witnesses: dict[str, dict] = {}
    printed_implies = True
    necessary_violations = 0
    target = np.zeros(2)
    for _ in range(n_trials):
        lams = []
        configs = []
        for _side in range(2):
            n = int(rng.integers(2, 5))
            scale = 10.0 ** rng.uniform(-1, 1)
            sensors = rng.uniform(-scale, scale, size=(n, 2))
            rows = relative_rows(sensors, target)
            lams.append(np.linalg.eigvalsh(rows.T @ rows))
            configs.append(sensors)
        u2 = float(rng.uniform(0, 2)) ** 2
        (lmin, lmax), (lmin2, lmax2) = lams
        b_before = np.sqrt(lmin / (lmax + u2))
        b_after = np.sqrt(lmin2 / (lmax2 + u2))
        decreased = bool(b_after < b_before * (1 - 1e-12))
        ratio_up = lmin2 * lmax >= lmax2 * lmin
        smin_up = lmin2 >= lmin
        t1, t2 = theorem3_terms((lmin, lmax), (lmin2, lmax2), u2)
        holds = {
            "stated": ratio_up and smin_up,
            "printed": ratio_up and lmin2 >= lmax,
            "ratio only": ratio_up and not smin_up,
            "sigma_min only": smin_up and not ratio_up,
            "remark 2": t1 + t2 >= 0,
            "neither": not ratio_up and not smin_up,
        }
        if b_after > b_before * (1 + 1e-9) and not holds["remark 2"]:
            necessary_violations += 1
        if holds["printed"] and not holds["stated"]:
            printed_implies = False
        for k, h in holds.items():
            if h:
                counts[k][0] += 1
                if decreased:
                    counts[k][1] += 1
                    witnesses.setdefault(
                        k,
                        {
                            "before": configs[0].round(6).tolist(),
                            "after": configs[1].round(6).tolist(),
                            "u": round(float(np.sqrt(u2)), 6),
                            "bound_before": round(float(b_before), 6),
                            "bound_after": round(float(b_after), 6),
                        },
                    )
    return Theorem3Audit(
        n_trials=n_trials,
        counts={k: tuple(v) for k, v in counts.items()},
        witnesses=witnesses,
        printed_implies_stated=printed_implies,
        remark2_necessary_violations=necessary_violations,
    )


@dataclass(frozen=True)
class Remark1Audit:
    """Tightness of Theorem 1's bound: stationary target, and moving at full speed."""

    n_scenes: int
    max_stationary_error: float  #: max ``|C^{-2}(O(o, 0)) - lambda_min / lambda_max|``
    max_moving_error: float  #: max ``|C^{-1}(O(o, u*)) - bound(u_max)|`` with ``||u*|| = u_max``
    min_over_disc_gap: float  #: min over scenes of (grid minimum of ``C^{-1}`` over the disc) - bound


def remark1_audit(n_scenes: int, seed: int, n_radii: int = 8, n_angles: int = 64) -> Remark1Audit:
    """Check Remark 1 (the bound is exact for ``u_o = 0``) and its moving-target counterpart.

    For every scene: the exact ``C^{-1}`` of the stationary target (``O(o, 0)``, zero
    row included) against the bound in eigenvalue form with ``u_max = 0`` (``eigvalsh`` of
    ``O(o)^T O(o)``; compared as squares, since a tiny ``lambda_min`` is only known to
    ``eps * lambda_max``); the exact ``C^{-1}`` at the worst-case control (norm ``u_max`` along
    the principal eigenvector) against :func:`lower_bound`; and the minimum of the exact value
    over a polar grid of the disc, which can only approach the bound from above.
    """
    stat = 0.0
    moving = 0.0
    gap = np.inf
    for sc in random_scenes(n_scenes, seed, kinds=("generic", "spread")):
        rows = relative_rows(sc.sensors, sc.target)
        lam = np.linalg.eigvalsh(rows.T @ rows)
        exact0 = inverse_condition_number(sc.sensors, sc.target, np.zeros(2))
        stat = max(stat, abs(exact0**2 - lam[0] / lam[1]))
        b = lower_bound(sc.sensors, sc.target, sc.u_max)
        u_star = worst_case_control(sc.sensors, sc.target, sc.u_max)
        moving = max(moving, abs(inverse_condition_number(sc.sensors, sc.target, u_star) - b))
        grid = inverse_condition_number(
            sc.sensors, sc.target, disc_controls(sc.u_max, n_radii, n_angles)
        )
        gap = min(gap, float(grid.min() - b))
    return Remark1Audit(
        n_scenes=n_scenes,
        max_stationary_error=float(stat),
        max_moving_error=float(moving),
        min_over_disc_gap=float(gap),
    )

"""Section III's audits (obslib.studies.model_and_bound) against scene-by-scene loops over the
public functions."""

import numpy as np
import pytest

import obslib as ob
from obslib.controls import disc_controls
from obslib.observability import relative_rows
from obslib.scenes import SCENE_KINDS, random_scene_batch
from obslib.studies import model_and_bound


def _unit_disc_draws(n_scenes, n_controls, seed):
    rng = np.random.default_rng(seed + 1)
    return rng.uniform(size=(n_scenes, n_controls)), rng.uniform(
        0, 2 * np.pi, size=(n_scenes, n_controls)
    )


def test_theorem1_audit_equals_a_scene_by_scene_loop():
    """The batched audit against lower_bound / worst_case_control / inverse_condition_number per
    scene."""
    n, m, seed = 300, 16, 4
    a = model_and_bound.theorem1_audit(n, m, seed)
    batch = random_scene_batch(n, seed)
    r, phi = _unit_disc_draws(n, m, seed)
    n_viol, worst, attain, slack = 0, -np.inf, 0.0, {}
    for k in range(n):
        sc = batch.scene(k)
        bound = ob.lower_bound(sc.sensors, sc.target, sc.u_max)
        rad = sc.u_max * np.sqrt(r[k])
        u = np.vstack([np.column_stack([rad * np.cos(phi[k]), rad * np.sin(phi[k])]),
                       ob.worst_case_control(sc.sensors, sc.target, sc.u_max)])
        excess = bound - ob.inverse_condition_number(sc.sensors, sc.target, u)
        n_viol += int((excess > model_and_bound.ATOL).sum())
        worst = max(worst, excess.max())
        attain = max(attain, abs(excess[-1]))
        slack[sc.kind] = min(slack.get(sc.kind, np.inf), (-excess).min())
    # Both paths share the closed form of C^-1; summed in another order they agree to rounding
    # (~1e-14 for nearly isotropic O^T O), far inside the audit's decision tolerance.
    assert a.n_scenes == n and a.n_evaluations == n * (m + 1) and a.n_violations == n_viol == 0
    assert a.worst_excess == pytest.approx(worst, abs=model_and_bound.ATOL)
    assert a.max_attainment_error == pytest.approx(attain, abs=model_and_bound.ATOL)
    assert list(a.min_slack_by_kind) == list(SCENE_KINDS)
    for kind, v in slack.items():
        assert a.min_slack_by_kind[kind] == pytest.approx(v, abs=model_and_bound.ATOL)


def test_theorem2_audit_equals_a_scene_by_scene_loop():
    n, seed = 300, 5
    a = model_and_bound.theorem2_audit(n, seed)
    batch = random_scene_batch(n, seed, n_sensors=(1, 1), kinds=("generic", "spread"))
    rng = np.random.default_rng(seed + 2)
    mag, ang = rng.uniform(size=n), rng.uniform(0, 2 * np.pi, size=n)
    exact, rel, bound = [], 0.0, 0.0
    for k in range(n):
        sc = batch.scene(k)
        rows = relative_rows(sc.sensors, sc.target)
        lam = np.linalg.eigvalsh(rows.T @ rows)
        rel = max(rel, abs(lam[0]) / lam[1])
        bound = max(bound, np.sqrt(max(lam[0], 0.0) / (lam[1] + sc.u_max**2)))
        u = sc.u_max * mag[k] * np.array([np.cos(ang[k]), np.sin(ang[k])])
        exact.append(ob.inverse_condition_number(sc.sensors, sc.target, u))
    assert a.max_relative_lambda_min < 1e-14 and rel < 1e-14
    assert a.max_bound < 1e-7 and bound < 1e-7
    assert a.exact_range == pytest.approx((min(exact), max(exact)), rel=1e-12)


def test_theorem3_audit_equals_a_trial_by_trial_loop():
    """The same draws as theorem3_audit, decided one trial at a time from relative_rows and
    eigvalsh."""
    n, seed = 3000, 6
    a = model_and_bound.theorem3_audit(n, seed)
    rng = np.random.default_rng(seed)
    counts_n = rng.integers(2, 5, size=(n, 2))
    scale = 10.0 ** rng.uniform(-1, 1, size=(n, 2))
    pts = rng.uniform(-1, 1, size=(n, 2, 4, 2)) * scale[..., None, None]
    speed = rng.uniform(0, 2, size=n)
    counts = {k: [0, 0] for k in a.counts}
    first = {}
    necessary = 0
    for i in range(n):
        lam = []
        for side in range(2):
            rows = relative_rows(pts[i, side, : counts_n[i, side]], np.zeros(2))
            lam.append(np.linalg.eigvalsh(rows.T @ rows))
        (l0, l1), (m0, m1) = lam
        u2 = speed[i] ** 2
        before, after = np.sqrt(l0 / (l1 + u2)), np.sqrt(m0 / (m1 + u2))
        ratio_up, smin_up = m0 * l1 >= m1 * l0, m0 >= l0
        holds = {"stated": ratio_up and smin_up, "printed": ratio_up and m0 >= l1,
                 "ratio only": ratio_up and not smin_up, "sigma_min only": smin_up and not ratio_up,
                 "remark 2": (m0 * l1 - m1 * l0) + u2 * (m0 - l0) >= 0,
                 "neither": not ratio_up and not smin_up}
        necessary += after > before * (1 + 1e-9) and not holds["remark 2"]
        for k, h in holds.items():
            if h:
                counts[k][0] += 1
                if after < before * (1 - 1e-12):
                    counts[k][1] += 1
                    first.setdefault(k, i)
    assert a.counts == {k: tuple(v) for k, v in counts.items()}
    assert a.remark2_necessary_violations == necessary == 0 and a.printed_implies_stated
    assert set(a.witnesses) == set(first)
    for k, i in first.items():
        w = a.witnesses[k]
        assert w["before"] == pts[i, 0, : counts_n[i, 0]].round(6).tolist()
        assert w["u"] == round(float(speed[i]), 6)


def test_remark1_audit_equals_a_scene_by_scene_loop():
    n, seed = 200, 7
    a = model_and_bound.remark1_audit(n, seed, n_radii=4, n_angles=16)
    batch = random_scene_batch(n, seed, kinds=("generic", "spread"))
    stat, moving, gap = 0.0, 0.0, np.inf
    for k in range(n):
        sc = batch.scene(k)
        rows = relative_rows(sc.sensors, sc.target)
        lam = np.linalg.eigvalsh(rows.T @ rows)
        stat = max(stat, abs(ob.inverse_condition_number(sc.sensors, sc.target, np.zeros(2)) ** 2
                             - lam[0] / lam[1]))
        b = ob.lower_bound(sc.sensors, sc.target, sc.u_max)
        u_star = ob.worst_case_control(sc.sensors, sc.target, sc.u_max)
        moving = max(moving, abs(ob.inverse_condition_number(sc.sensors, sc.target, u_star) - b))
        grid = ob.inverse_condition_number(sc.sensors, sc.target, disc_controls(sc.u_max, 4, 16))
        gap = min(gap, grid.min() - b)
    assert a.max_stationary_error < 1e-12 and stat < 1e-12
    assert a.max_moving_error < 1e-12 and moving < 1e-12
    assert a.min_over_disc_gap == pytest.approx(gap, abs=1e-13)

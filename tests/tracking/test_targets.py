"""Many targets in closed loop (obslib.tracking.targets, .assigners): the engine against
filterpy at every step, a unique-pair run against a plain re-implementation, each assignment
against an independent computation, and the named errors."""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest
from filterpy.kalman import ExtendedKalmanFilter

import obslib as ob
from obslib import tracking as tr
from obslib.tracking import assigners, code_logdet

LATER = tr.LATER_MULTI_TARGET
MODELS = {"half-squared-range": (tr.range_jacobian, tr.half_squared_range),
          "range": (tr.euclidean_range_jacobian, tr.euclidean_range)}


def _filters(setup):
    out = []
    for x0 in setup.estimate0:
        f = ExtendedKalmanFilter(dim_x=2, dim_z=1)
        f.x = np.array(x0, dtype=float)[:, None]
        f.P = np.array(setup.cov0, dtype=float)
        f.F, f.Q = np.eye(2), np.array(setup.Q, dtype=float)
        out.append(f)
    return out


def _filterpy_step(setup, filters, teams, k, table):
    """Predict every filter, then update each with its team's measurements (filterpy)."""
    jac, hx = MODELS[setup.measurement]
    S, truth = setup.sensor_array, setup.truth_array
    for l, f in enumerate(filters):
        f.predict()
        team = list(teams[l])
        if team:
            ps = S[team]
            z = hx(truth[k, l], ps) + table[k, team]
            f.update(z[:, None], jac, hx, R=setup.R * np.eye(len(team)), args=(ps,),
                     hx_args=(ps,))


def _assert_same_states(r, est, cov, tol=1e-9):
    np.testing.assert_allclose(r.estimate, est, rtol=0, atol=tol)
    np.testing.assert_allclose(r.cov, cov, rtol=0, atol=tol)


@pytest.mark.parametrize("seed", [0, 3])
def test_unique_pair_run_equals_a_plain_reimplementation(seed):
    """Written here step by step: Algorithm 1 from geometry on the filters' estimates
    (``greedy_pair_assignment``), then filterpy's EKF per target with the ranges of its pair.
    The same pairs at every step and the same states to rounding."""
    su = LATER
    table = tr.noise_table(su, seed)
    r = tr.simulate_targets(su, "unique-pairs", seed=seed)
    filters = _filters(su)
    est, cov = np.empty((su.steps, 3, 2)), np.empty((su.steps, 3, 2, 2))
    for k in range(su.steps):
        x = np.array([f.x[:, 0] for f in filters])
        est[k], cov[k] = x, [f.P for f in filters]
        a = ob.greedy_pair_assignment(sensors=su.sensor_array, targets=x, u_max=su.u_max)
        teams = [None] * 3
        for i, j, l in a.triples:
            teams[l] = (i, j)
        assert r.teams[k] == tuple(teams), k
        _filterpy_step(su, filters, teams, k, table)
    _assert_same_states(r, est, cov)
    truth = su.truth_array[:-1]
    np.testing.assert_allclose(r.error, np.hypot(*(est - truth).transpose(2, 0, 1)),
                               rtol=0, atol=1e-9)
    np.testing.assert_allclose(r.trace_cov, np.trace(cov, axis1=2, axis2=3), rtol=0, atol=1e-9)


SCENE = tr.network_scene(12, 4, steps=30, seed=5)
HALF = SCENE.replace(measurement="half-squared-range", metric="mahalanobis", R=0.25,
                     noise_std=0.5)


@pytest.mark.parametrize("setup", [LATER, SCENE, HALF], ids=["later", "scene", "half-squared"])
@pytest.mark.parametrize("assignment", tr.ASSIGNMENTS)
def test_every_assignment_s_run_equals_filterpy_at_every_step(setup, assignment):
    """The engine's filters against filterpy's, one filter per target, with the teams the
    engine logged (any size, none included): the same states at every step to rounding."""
    su = setup.first(30)
    r = tr.simulate_targets(su, assignment, seed=2)
    filters = _filters(su)
    est = np.empty((su.steps, su.n_targets, 2))
    cov = np.empty((su.steps, su.n_targets, 2, 2))
    for k in range(su.steps):
        est[k] = [f.x[:, 0] for f in filters]
        cov[k] = [f.P for f in filters]
        _filterpy_step(su, filters, r.teams[k], k, r.noise)
    _assert_same_states(r, est, cov)
    np.testing.assert_allclose(r.estimate_end, [f.x[:, 0] for f in filters], rtol=0, atol=1e-9)


def test_teams_are_valid_assignments():
    runs = tr.simulate_targets_batch(LATER.first(40), list(tr.ASSIGNMENTS), seeds=[0, 1])
    for name, b in runs.items():
        lab = b.labels
        assert lab.min() >= -1 and lab.max() < 3, name
        if name in tr.PAIR_ASSIGNMENTS:
            assert (b.team_sizes == 2).all(), name
        else:
            assert (lab >= 0).all(), name  # teams use every sensor


def test_batch_runs_equal_single_runs_and_share_the_noise():
    su = LATER.first(40)
    names = ["unique-pairs", "random", "logdet-teams", "d-optimal-teams"]
    runs = tr.simulate_targets_batch(su, names, seeds=[4, 5])
    for name in names:
        np.testing.assert_array_equal(runs[name].noise, runs["unique-pairs"].noise)
        for b, seed in enumerate([4, 5]):
            one = tr.simulate_targets(su, name, seed=seed)
            np.testing.assert_array_equal(runs[name].labels[b], one.labels)
            # 1e-12: stacked products of other shapes (see tests/tracking/test_batch.py)
            np.testing.assert_allclose(runs[name].estimate[b], one.estimate, rtol=0, atol=1e-12)
            assert runs[name].run(b).teams == one.teams


def test_noise_entry_is_keyed_by_step_and_sensor():
    """Changing the noise of a sensor no target uses at a step changes nothing."""
    su = LATER.first(30)
    table = tr.noise_table(su, 3)
    r = tr.simulate_targets(su, "unique-pairs", noise=table)
    unused = r.labels < 0
    t2 = table + np.where(unused, 5.0, 0.0)
    r2 = tr.simulate_targets(su, "unique-pairs", noise=t2)
    np.testing.assert_array_equal(r2.estimate, r.estimate)
    assert r2.seed is None and r.seed is None


# --------------------------------------------------------------------------------------------
# The code's log det: its arithmetic, its maximum, its teams
# --------------------------------------------------------------------------------------------


def _round(q: Fraction) -> float:
    return float(q)  # Fraction -> float rounds to nearest, ties to even


def _exact_lu_det(a11, a12, a21, a22):
    """LAPACK's LU determinant of a 2 x 2 matrix with the update rounded once (a fused
    multiply-add), from exact rationals."""
    swap = abs(a21) > abs(a11)
    if swap:
        a11, a12, a21, a22 = a21, a22, a11, a12
    if a11 == 0:
        return 0.0
    lm = a21 * (1.0 / a11)
    u = _round(Fraction(a22) - Fraction(lm) * Fraction(a12))
    det = a11 * u
    return -det if swap else det


def test_code_determinant_is_lapack_s_lu_with_one_rounding_of_the_update():
    rng = np.random.default_rng(0)
    for _ in range(400):
        x, y = rng.normal(0, 3, 2)
        g00, g01, g11 = x * x, x * y, y * y  # one row: singular, the residue decides
        got = float(code_logdet.code_logdet_det(g00, g01, g11))
        assert got == _exact_lu_det(g00, g01, g01, g11)
        if rng.random() < 0.5:  # two rows: a regular matrix
            u, v = rng.normal(0, 3, 2)
            g00, g01, g11 = g00 + u * u, g01 + u * v, g11 + v * v
            got = float(code_logdet.code_logdet_det(g00, g01, g11))
            assert got == pytest.approx(_exact_lu_det(g00, g01, g01, g11), rel=1e-15)


def test_fused_multiply_add_is_exactly_rounded_where_it_cancels():
    rng = np.random.default_rng(1)
    a, b = rng.normal(0, 10, 500), rng.normal(0, 10, 500)
    c = -(a * b) * (1 + rng.uniform(-0.4, 0.4, 500))  # within a factor 2 of -ab
    got = code_logdet.fused_multiply_add(a, b, c)
    want = [_round(Fraction(x) * Fraction(y) + Fraction(z)) for x, y, z in zip(a, b, c)]
    np.testing.assert_array_equal(got, want)


def test_the_round_maximum_follows_matlab_s_rules():
    m = code_logdet.matlab_table_max
    re = np.array([[[np.nan, -1.0], [-5.0, 0.5]]])  # NaN ignored
    assert m(re, np.zeros_like(re)).tolist() == [3]
    re = np.array([[[-np.inf, np.inf], [1.0, 2.0]]])
    im = np.array([[[0.0, 0.0], [np.pi, 0.0]]])  # complex: by magnitude, then angle
    assert m(re, im).tolist() == [0]  # -inf (angle pi) over +inf (angle 0), then over 1 + pi i
    re = np.array([[[-np.inf, 3.0], [np.inf, 1.0]]])
    im = np.array([[[0.0, 0.0], [0.0, np.pi]]])
    assert m(re, im).tolist() == [2]  # column maxima -inf and +inf, both real: by value
    re = np.array([[[-np.inf, -np.inf], [-np.inf, -np.inf]]])
    assert m(re, np.zeros_like(re)).tolist() == [0]  # all equal: the first in column order


def _matlab_max(values, real):
    """MATLAB's max of numbers of one array: NaN ignored; by value if the array is real, else
    by abs, then angle; the first of the maxima."""
    vals = [v for v in values if not np.isnan(v.real)]
    if not vals:
        return complex(np.nan, 0.0)
    if real:
        return max(vals, key=lambda v: v.real)
    return max(vals, key=lambda v: (abs(v), np.angle(v)))


def test_the_round_maximum_equals_a_plain_two_stage_max():
    """``find(T == max(max(T)))``, written entry by entry, on random tables with the values the
    code's gains take: NaN, infinities, zeros (taken sensors), and complex entries."""
    rng = np.random.default_rng(6)
    pool = [np.nan, np.inf, -np.inf, 0.0, 37.1, -35.2, 2.5]
    for _ in range(300):
        N, L = rng.integers(1, 6, size=2)
        re = rng.choice(pool + list(rng.normal(0, 30, 5)), size=(1, L, N))
        im = np.where(rng.random((1, L, N)) < 0.2, rng.choice([np.pi, -np.pi], (1, L, N)), 0.0)
        im[np.isnan(re)] = 0.0
        T = re + 1j * im  # T[0, l, i]: column l, row i
        real = not (im != 0).any()  # the array is complex if any entry is
        cols = [_matlab_max(list(T[0, l]), real) for l in range(L)]
        v = _matlab_max(cols, all(c.imag == 0 for c in cols))  # zero parts dropped
        hits = [l * N + i for l in range(L) for i in range(N)
                if T[0, l, i].real == v.real and T[0, l, i].imag == v.imag]
        if hits:  # a table of NaN only has no maximum (MATLAB's find then finds nothing)
            assert code_logdet.matlab_table_max(re, im).tolist() == [hits[0]]


def test_exact_arithmetic_gives_the_first_target_every_sensor():
    r = tr.simulate_targets(LATER, "logdet-teams-exact", seed=0)
    assert (r.labels == 0).all()
    growth = np.diff(r.trace_cov[:, 1:], axis=0)
    np.testing.assert_allclose(growth, np.trace(np.array(LATER.Q)), rtol=0, atol=1e-12)


def test_the_code_s_teams_reproduce_the_saved_second_step():
    """The trace after the first update depends on the first teams, not on the noise: the
    code's arithmetic with its reading of the teams (rounds as sensors) gives the saved run's
    numbers, to the six digits saved, at every seed; the teams it picked do not."""
    from obslib.later_experiment import saved_run

    for name in ("unique-pairs", "logdet-teams-as-run"):
        saved = saved_run(name).trace_cov[1]
        for seed in (0, 1):
            ours = tr.simulate_targets(LATER.first(3), name, seed=seed).trace_cov[1]
            np.testing.assert_allclose(ours, saved, rtol=5e-6)
    picked = tr.simulate_targets(LATER.first(3), "logdet-teams").trace_cov[1]
    assert not np.allclose(picked, saved_run("logdet-teams-as-run").trace_cov[1], rtol=1e-3)


# --------------------------------------------------------------------------------------------
# The other assignments against independent computations
# --------------------------------------------------------------------------------------------


def _random_state(rng, su):
    x = rng.uniform(-2, 6, size=(su.n_targets, 2))
    A = rng.normal(size=(su.n_targets, 2, 2))
    return x, 0.3 * (A @ np.swapaxes(A, 1, 2)) + 0.05 * np.eye(2)


@pytest.mark.parametrize("criterion", ["d-optimal-teams", "a-optimal-teams", "e-optimal-teams"])
def test_information_gains_equal_linear_algebra(criterion):
    rng = np.random.default_rng(2)
    value = {"d-optimal-teams": lambda J: np.log(np.linalg.det(J)),
             "a-optimal-teams": lambda J: -np.trace(np.linalg.inv(J)),
             "e-optimal-teams": lambda J: np.linalg.eigvalsh(J)[0]}[criterion]
    for _ in range(200):
        A = rng.normal(size=(2, 2))
        J = A @ A.T + 0.1 * np.eye(2)
        h = rng.normal(size=2)
        got = assigners._information_gain(criterion, J[0, 0], J[0, 1], J[1, 1], h[0], h[1])
        want = value(J + np.outer(h, h)) - value(J)
        assert got == pytest.approx(want, rel=1e-8, abs=1e-12)
    iso = assigners._information_gain("e-optimal-teams", 2.0, 0.0, 2.0, 0.3, 0.4)
    assert iso == 0.0  # one row never raises the smallest eigenvalue of an isotropic J


@pytest.mark.parametrize("criterion", ["d-optimal-teams", "a-optimal-teams", "e-optimal-teams"])
def test_information_teams_equal_a_plain_greedy(criterion):
    """N rounds, each giving a free sensor to the target whose criterion of
    J = (Sigma + Q)^-1 + sum h h^T / R grows most, evaluated with numpy.linalg."""
    value = {"d-optimal-teams": lambda J: np.log(np.linalg.det(J)),
             "a-optimal-teams": lambda J: -np.trace(np.linalg.inv(J)),
             "e-optimal-teams": lambda J: np.linalg.eigvalsh(J)[0]}[criterion]
    rng = np.random.default_rng(3)
    su = LATER
    for _ in range(5):
        x, P = _random_state(rng, su)
        J = [np.linalg.inv(P[l] + np.array(su.Q)) for l in range(3)]
        H = tr.euclidean_range_jacobian(x, su.sensor_array[None]) / np.sqrt(su.R)
        free, labels = set(range(8)), [-1] * 8
        for _ in range(8):
            best = max((value(J[l] + np.outer(H[l, i], H[l, i])) - value(J[l]), -i, -l)
                        for i in free for l in range(3))
            i, l = -best[1], -best[2]
            labels[i] = l
            free.remove(i)
            J[l] = J[l] + np.outer(H[l, i], H[l, i])
        assert tr.assign_targets(su, criterion, x, P).tolist() == labels


def test_optimal_pairs_is_the_optimum_of_problem_1():
    """Enumeration against branch and bound (optimal_pair_assignment) on the same weights, and
    never below the greedy."""
    rng = np.random.default_rng(4)
    su = LATER
    for _ in range(6):
        x, P = _random_state(rng, su)
        W = ob.pair_bounds(su.sensor_array, x, su.u_max)
        lab = tr.assign_targets(su, "optimal-pairs", x, P)
        triples = [(*np.flatnonzero(lab == l), l) for l in range(3)]
        value = sum(W[i, j, l] for i, j, l in triples)
        assert value == pytest.approx(ob.optimal_pair_assignment(W).value, rel=1e-12)
        assert value >= ob.greedy_pair_assignment(W).value - 1e-12
    assert assigners.assignment_count(8, 3) == len(assigners._enumerated(8, 3)) == 2520


def test_the_logdet_prior_teams_are_the_team_greedy_of_fig_9():
    rng = np.random.default_rng(5)
    x, P = _random_state(rng, LATER)
    teams = ob.greedy_team_assignment(LATER.sensor_array, x, "logdet", eps=LATER.eps)
    lab = tr.assign_targets(LATER, "logdet-teams-prior", x, P)
    assert [sorted(np.flatnonzero(lab == l).tolist()) for l in range(3)] == [sorted(t)
                                                                           for t in teams]


def test_random_assignments_are_drawn_from_the_seed():
    su = LATER.first(30)
    a = tr.simulate_targets(su, "random", seed=7)
    b = tr.simulate_targets(su, "random", noise=tr.noise_table(su, 7), seed=7)
    np.testing.assert_array_equal(a.labels, b.labels)
    perm = assigners.random_draws(7, su.steps, 8)
    for k in range(su.steps):
        assert a.teams[k] == tuple(tuple(sorted(perm[k, 2 * l:2 * l + 2].tolist()))
                                   for l in range(3))


def test_a_network_scene_is_smooth_and_bounded():
    su = tr.network_scene(200, 50, steps=100, seed=3)
    step = np.diff(su.truth_array, axis=0)
    speed = np.hypot(step[..., 0], step[..., 1])
    assert (speed <= su.u_max * (1 + 1e-12)).all() and (speed >= su.u_max / 3 * (1 - 1e-12)).all()
    turn = np.abs(np.diff(np.unwrap(np.arctan2(step[..., 1], step[..., 0]), axis=0), axis=0))
    assert turn.max() < 0.5  # the heading turns by less than half a radian per step
    assert tr.network_scene(200, 50, seed=3) == tr.network_scene(200, 50, seed=3)
    assert su.sensor_array.max() <= 50.0 and su.sensor_array.min() >= 0.0


# --------------------------------------------------------------------------------------------
# Bad input
# --------------------------------------------------------------------------------------------


def test_bad_input_is_named():
    few = tr.network_scene(5, 3, steps=5)
    for name in tr.PAIR_ASSIGNMENTS:
        with pytest.raises(ValueError, match="two free sensors per target, N >= 2 L = 6"):
            tr.simulate_targets(few, name)
    tr.simulate_targets(few, "d-optimal-teams")  # teams need no pairs
    with pytest.raises(ValueError, match=r"noise table must have shape \(100, 8\)"):
        tr.simulate_targets(LATER, "unique-pairs", noise=np.zeros((100, 7)))
    with pytest.raises(ValueError, match="unknown assignment 'greedy'"):
        tr.simulate_targets(LATER, "greedy")
    with pytest.raises(ValueError, match="unknown name 'greedy'"):
        tr.simulate_targets_batch(LATER, ["greedy"], seeds=[0])
    with pytest.raises(ValueError, match="assignments must be a list of names"):
        tr.simulate_targets_batch(LATER, "unique-pairs", seeds=[0])
    with pytest.raises(ValueError, match="random assignment draws from the run's seed"):
        tr.simulate_targets_batch(LATER, ["random"], noise=np.zeros((1, 100, 8)))
    with pytest.raises(ValueError, match="either seeds or noise"):
        tr.simulate_targets_batch(LATER, ["unique-pairs"])
    with pytest.raises(ValueError, match="setup must be a TargetsSetup"):
        tr.simulate_targets(tr.PAPER_CIRCLE, "unique-pairs")
    with pytest.raises(ValueError, match=r"estimate0 must have shape \(3, 2\)"):
        LATER.replace(estimate0=((0.0, 0.0),))
    with pytest.raises(ValueError, match="sensors 0 and 1 coincide|coincid"):
        LATER.replace(sensors=((0.0, 0.0), (0.0, 0.0)))
    with pytest.raises(ValueError, match="unknown measurement"):
        LATER.replace(measurement="bearing")
    with pytest.raises(ValueError, match="R must be finite and positive"):
        LATER.replace(R=0.0)
    with pytest.raises(ValueError, match="steps must be at most"):
        LATER.first(101)


def test_scenes_run_together_equal_each_scene_alone():
    scenes = [tr.network_scene(14, 4, steps=25, seed=s) for s in (3, 4, 5)]
    names = ["unique-pairs", "logdet-teams", "e-optimal-teams", "random"]
    runs = tr.simulate_targets_scenes(scenes, names, seeds=[3, 4, 5])
    for name in names:
        for b, su in enumerate(scenes):
            one = tr.simulate_targets(su, name, seed=3 + b)
            np.testing.assert_array_equal(runs[name].labels[b], one.labels)
            np.testing.assert_allclose(runs[name].estimate[b], one.estimate, rtol=0, atol=1e-12)
            np.testing.assert_array_equal(runs[name].truth[b], one.truth)
            assert runs[name].run(b).setup is su
    with pytest.raises(ValueError, match="differ in u_max"):
        tr.simulate_targets_scenes([scenes[0], scenes[1].replace(u_max=0.2)], names, [0, 1])
    with pytest.raises(ValueError, match="one seed per scene"):
        tr.simulate_targets_scenes(scenes, names, [0])

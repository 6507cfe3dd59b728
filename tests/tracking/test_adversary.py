"""The adversarial target (obslib.tracking.adversary): the first minimiser of the exact C^-1."""

from __future__ import annotations

import numpy as np
import pytest

import obslib as ob
from obslib import tracking as tr
from obslib.controls import disc_controls
from obslib.tracking.adversary import adversary_moves, screened_moves  # the worker too

CIRCLE = tr.PAPER_CIRCLE
ADV = tr.PAPER_ADVERSARIAL


@pytest.mark.parametrize("adversary", tr.ADVERSARIES)
def test_adversary_picks_the_first_minimising_control(adversary):
    setup = ADV.replace(steps=60, adversary=adversary)
    r = tr.simulate(setup, "best-pair", seed=2)
    s, ctrl = setup.sensor_array, setup.control_array
    nxt_pairs = np.vstack([r.pairs[1:], r.next_pair[None]])
    for k in range(r.steps):
        pair = r.pairs[k] if adversary == "current-pair" else nxt_pairs[k]
        vals = np.array([ob.inverse_condition_number(s[pair], r.truth[k] + u, u) for u in ctrl])
        gap = np.hypot(*(ctrl - r.control[k]).T)  # control = o_{k+1} - o_k, to rounding
        chosen = int(np.argmin(gap))
        assert gap[chosen] < 1e-12
        assert vals[chosen] <= vals.min() + 1e-12
        assert chosen == int(np.argmin(vals)) or vals[chosen] - vals.min() < 1e-12
        assert r.objective[k] == pytest.approx(
            ob.inverse_condition_number(s[r.pairs[k]], r.truth[k] + r.control[k], r.control[k]),
            abs=1e-12,
        )


@pytest.mark.parametrize("controls", ["paper", "disc"])
def test_adversary_moves_equal_argmin_of_target_objective(controls):
    """The screened pick is exactly the first minimiser of target_objective, also where the
    target stands on a pair's baseline (C^-1 = 0 for several controls) or ties by symmetry."""
    rng = np.random.default_rng(3)
    s = CIRCLE.sensor_array
    u = tr.paper_controls(0.1) if controls == "paper" else disc_controls(0.1, 10, 180)
    n = 400
    pairs = np.array([rng.choice(6, 2, replace=False) for _ in range(n)])
    ps = s[pairs]
    o = rng.normal([2.0, 2.0], 2.5, size=(n, 2))
    t = rng.random(n // 4)[:, None]  # on the baseline between (or beyond) the two sensors
    o[: n // 4] = ps[: n // 4, 0] + (2 * t - 0.5) * (ps[: n // 4, 1] - ps[: n // 4, 0])
    mid = 0.5 * (ps[n // 4 : n // 2, 0] + ps[n // 4 : n // 2, 1])  # symmetric positions
    o[n // 4 : n // 2] = mid
    got = adversary_moves(ps, o, u)
    want = np.argmin(tr.target_objective(ps, o, u), axis=1)
    np.testing.assert_array_equal(got, want)


def test_adversary_moves_by_block_equal_the_barred_union():
    """The batch engine screens runs with different control sets block by block; each pick
    equals the pick over the union of the sets with the other blocks barred (both against the
    first minimiser of target_objective over the run's own set)."""
    rng = np.random.default_rng(5)
    s = CIRCLE.sensor_array
    sets = [tr.paper_controls(0.1), disc_controls(0.1, 4, 36), disc_controls(0.3, 2, 12)]
    union = np.concatenate(sets)
    edges = np.cumsum([0] + [len(c) for c in sets])
    n = 90
    block = rng.integers(0, len(sets), n)
    ps = s[np.array([rng.choice(6, 2, replace=False) for _ in range(n)])]
    o = rng.normal([2.0, 2.0], 2.5, size=(n, 2))
    barred = np.full((n, len(union)), np.inf)
    for r, b in enumerate(block):
        barred[r, edges[b] : edges[b + 1]] = 0.0
    joint = screened_moves(ps, o, union, barred=barred)
    for b, c in enumerate(sets):
        rows = np.flatnonzero(block == b)
        own = adversary_moves(ps[rows], o[rows], c)
        np.testing.assert_array_equal(joint[rows], edges[b] + own)
        want = np.argmin(tr.target_objective(ps[rows], o[rows], c), axis=1)
        np.testing.assert_array_equal(own, want)


def test_bad_adversary_arguments_are_named():
    ps = np.array([[[0.0, 0.0], [4.0, 0.0]]])
    with pytest.raises(ValueError, match="position must have shape"):
        adversary_moves(ps, [[1.0, 1.0], [2.0, 2.0]], [[0.0, 0.1]])
    with pytest.raises(ValueError, match="controls must be finite"):
        adversary_moves(ps, [[1.0, 1.0]], [[np.nan, 0.1]])
    with pytest.raises(ValueError, match="pair_sensors must have shape"):
        adversary_moves(ps[0], [[1.0, 1.0]], [[0.0, 0.1]])

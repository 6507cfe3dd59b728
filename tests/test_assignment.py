"""Pair assignment: greedy vs the literal Algorithm 1, exact solvers vs brute force, Theorem 6."""

import itertools

import numpy as np
import pytest

import obslib as ob
from obslib.assignment import (
    assignment_value,
    greedy_pair_assignment,
    greedy_pair_assignment_literal,
    greedy_pairs_batch,
    optimal_pair_assignment,
    relaxed_pair_assignment,
)


def random_instance(rng, L, extra, grid=False):
    """A random instance; with ``grid``, points on a coarse grid, so many weights tie exactly.

    The grid has 5 x 5 = 25 sensor cells (multiples of 25 in [0, 100]) and sensors take distinct
    cells drawn without replacement, so every draw is legal (no retry loop); targets sit at the
    cell centres, offset by 12.5, so none is on a sensor. Equal distances and angles on the grid
    give exactly equal pair weights, which exercises the tie-breaking rule.
    """
    N = 2 * L + extra
    if grid:
        cells = np.array([(a, b) for a in range(5) for b in range(5)], dtype=float) * 25.0
        if N > cells.shape[0]:
            raise ValueError(f"the 25-cell grid holds at most 25 sensors, not {N}")
        S = cells[rng.choice(cells.shape[0], size=N, replace=False)]
        T = np.round(rng.uniform(0, 100, size=(L, 2)) / 25) * 25 + 12.5
    else:
        S = rng.uniform(0, 100, size=(N, 2))
        T = rng.uniform(0, 100, size=(L, 2))
    return S, T, ob.pair_bounds(S, T, 1.0)


def brute_force(W, unique_sensors=True):
    """Best total over all ways to give each target one pair or none, enumerated exhaustively."""
    n, _, L = W.shape
    pairs = list(itertools.combinations(range(n), 2))
    best = 0.0

    def rec(l, used_sensors, used_pairs, total):
        nonlocal best
        if l == L:
            best = max(best, total)
            return
        rec(l + 1, used_sensors, used_pairs, total)
        for p in pairs:
            if p in used_pairs or (
                unique_sensors and (p[0] in used_sensors or p[1] in used_sensors)
            ):
                continue
            rec(l + 1, used_sensors | set(p), used_pairs | {p}, total + W[p[0], p[1], l])

    rec(0, frozenset(), frozenset(), 0.0)
    return best


@pytest.mark.parametrize("grid", [False, True])
def test_greedy_equals_literal_on_thousands_of_instances(grid):
    rng = np.random.default_rng(1 if grid else 0)
    for _ in range(1500):
        L = int(rng.integers(1, 6))
        S, T, W = random_instance(rng, L, int(rng.integers(0, 5)), grid)
        k = int(rng.integers(1, 6))  # tiny candidate lists force many refills
        lit = greedy_pair_assignment_literal(W)
        assert greedy_pair_assignment(W, k=k).triples == lit.triples
        assert greedy_pair_assignment(sensors=S, targets=T, u_max=1.0, k=k).triples == lit.triples
        if k == 1:  # the literal algorithm recomputing weights each round agrees too
            assert (
                greedy_pair_assignment_literal(sensors=S, targets=T, u_max=1.0).triples
                == lit.triples
            )


def greedy_by_enumeration(W):
    """Algorithm 1 replayed round by round in plain Python: every remaining triple (i < j) is
    listed, the heaviest taken, ties to the smallest (i, j, l)."""
    n, _, L = W.shape
    free, open_, picks = set(range(n)), set(range(L)), []
    while open_ and len(free) >= 2:
        best = max((W[i, j, l], (-i, -j, -l)) for i in free for j in free if i < j for l in open_)
        i, j, l = (-v for v in best[1])
        picks.append((i, j, l))
        free -= {i, j}
        open_.discard(l)
    return picks


def test_batched_kernel_equals_the_literal_algorithm_and_enumeration_with_ties():
    """The kernel of every greedy in obslib on batches of instances (integer weights: many
    exact ties) against the vectorised literal Algorithm 1 and the plain enumeration."""
    rng = np.random.default_rng(21)
    for n, L in [(2, 1), (4, 2), (5, 2), (7, 3), (8, 4), (9, 3)]:
        W = rng.integers(0, 3, size=(40, n, n, L)).astype(float)
        W = W + W.transpose(0, 2, 1, 3)
        ii, jj = np.triu_indices(n, 1)
        picks, weights = greedy_pairs_batch(W[:, ii, jj], n)
        for b in range(40):
            got = [tuple(t) for t in picks[b].tolist()]
            assert got == greedy_pair_assignment_literal(W[b]).triples
            assert got == greedy_by_enumeration(W[b])
            assert weights[b].tolist() == [W[b][t] for t in got]


def test_batched_kernel_rejects_bad_input():
    with pytest.raises(ValueError, match="shape"):
        greedy_pairs_batch(np.zeros((1, 5, 1)), 4)
    with pytest.raises(ValueError, match="N >= 2L"):
        greedy_pairs_batch(np.zeros((1, 6, 3)), 4)
    with pytest.raises(ValueError, match="finite"):
        greedy_pairs_batch(np.full((1, 6, 1), np.nan), 4)


def test_greedy_from_geometry_equals_literal_on_larger_scenes():
    """The pruned search from geometry against the literal algorithm (which weighs every
    remaining triple each round) where most pairs are never weighed: uniform scenes, a grid
    (exact ties) and Mahalanobis distances."""
    rng = np.random.default_rng(22)
    for n, L, kind in [(160, 80, "uniform"), (144, 60, "grid"), (120, 50, "cov")]:
        S, T = rng.uniform(0, 100, (n, 2)), rng.uniform(0, 100, (L, 2))
        cov = None
        if kind == "grid":
            side = int(np.ceil(np.sqrt(n)))
            S = np.array([(a, b) for a in range(side) for b in range(side)], float)[:n] * 8.0
            T = np.round(T / 8.0) * 8.0 + 4.0
        elif kind == "cov":
            A = rng.normal(size=(L, 2, 2))
            cov = A @ A.transpose(0, 2, 1) + 0.5 * np.eye(2)
        fast = greedy_pair_assignment(sensors=S, targets=T, u_max=1.0, cov=cov)
        lit = greedy_pair_assignment_literal(sensors=S, targets=T, u_max=1.0, cov=cov)
        assert fast.triples == lit.triples and fast.value == lit.value
        assert fast.n_evaluations < 0.05 * lit.n_evaluations


def test_greedy_from_geometry_with_mahalanobis_equals_weights():
    rng = np.random.default_rng(5)
    S, T = rng.uniform(0, 100, (12, 2)), rng.uniform(0, 100, (4, 2))
    cov = np.array([[[2.0, 0.3], [0.3, 1.0]]] * 4)
    W = ob.pair_bounds(S, T, 1.0, cov=cov)
    assert greedy_pair_assignment(sensors=S, targets=T, u_max=1.0, cov=cov).triples == (
        greedy_pair_assignment_literal(W).triples
    )


def test_greedy_picks_are_feasible_and_valued():
    rng = np.random.default_rng(2)
    S, T, W = random_instance(rng, 6, 3)
    g = greedy_pair_assignment(W)
    used = [s for i, j, _ in g.triples for s in (i, j)]
    assert len(used) == len(set(used)) and all(i < j for i, j, _ in g.triples)
    assert sorted(l for *_, l in g.triples) == list(range(6))
    assert g.value == pytest.approx(sum(W[i, j, l] for i, j, l in g.triples))
    # pick order: weights never increase from one round to the next
    w = [W[i, j, l] for i, j, l in g.triples]
    assert all(a >= b for a, b in zip(w, w[1:]))


def test_exact_solvers_equal_brute_force_and_greedy_is_within_a_third():
    rng = np.random.default_rng(3)
    for _ in range(60):
        L = int(rng.integers(1, 4))
        _, _, W = random_instance(rng, L, int(rng.integers(0, 3)))
        opt = optimal_pair_assignment(W)
        assert opt.value == pytest.approx(brute_force(W), abs=1e-12)
        assert relaxed_pair_assignment(W).value == pytest.approx(
            brute_force(W, unique_sensors=False), abs=1e-12
        )
        g = greedy_pair_assignment(W)
        assert g.value >= opt.value / 3 - 1e-12  # Theorem 6
        assert relaxed_pair_assignment(W).value >= opt.value - 1e-12


def test_ordered_relaxation_may_reuse_a_pair():
    # one excellent pair for two targets: the ordered relaxation uses it twice
    S = np.array([[0.0, 1.0], [1.0, 0.0], [50.0, 50.0], [60.0, 0.0]])
    T = np.array([[0.0, 0.0], [0.0, 0.0]])
    W = ob.pair_bounds(S, T[:1], 1.0)
    W = np.concatenate([W, W], axis=2)
    plain, ordered = relaxed_pair_assignment(W), relaxed_pair_assignment(W, ordered=True)
    assert ordered.value == pytest.approx(2 * W[0, 1, 0])
    assert ordered.value > plain.value
    assert len({(i, j) for i, j, _ in plain.triples}) == len(plain.triples)


@pytest.mark.parametrize(
    "W, message",
    [
        (np.zeros((3, 3, 2)), "N >= 2L"),
        (np.zeros((4, 3, 1)), "shape"),
        (np.zeros((4, 4)), "shape"),
        (np.zeros((4, 4, 0)), "at least one target"),
        (np.full((4, 4, 1), np.nan), "not finite"),
        (np.arange(16.0).reshape(4, 4, 1), "symmetric"),
    ],
)
def test_bad_weights(W, message):
    for solver in (greedy_pair_assignment, greedy_pair_assignment_literal, optimal_pair_assignment):
        with pytest.raises(ValueError, match=message):
            solver(W)


def test_bad_geometry_for_greedy():
    with pytest.raises(ValueError, match="N >= 2L"):
        greedy_pair_assignment(
            sensors=[[0, 0], [1, 1], [2, 0]], targets=[[5, 5], [6, 6]], u_max=1.0
        )
    with pytest.raises(ValueError, match="sensor 1 has a non-finite"):
        greedy_pair_assignment(sensors=[[0, 0], [np.nan, 1]], targets=[[5, 5]], u_max=1.0)
    with pytest.raises(ValueError, match="either W or"):
        greedy_pair_assignment(np.zeros((2, 2, 1)), sensors=[[0, 0], [1, 1]], targets=[[5, 5]])
    with pytest.raises(ValueError, match="u_max"):
        greedy_pair_assignment(sensors=[[0, 0], [1, 1]], targets=[[5, 5]])


def full_matching_value(W, ordered=False) -> float:
    """Problem 3's optimum by a dense assignment over every pair (``i < j``, and ``j > i`` too
    when ``ordered``): no pruning, another algorithm than the library's sparse matching."""
    from scipy.optimize import linear_sum_assignment

    ii, jj = np.triu_indices(W.shape[0], 1)
    cost = W[ii, jj, :].T
    if ordered:
        cost = np.concatenate([cost, cost], axis=1)
    r, c = linear_sum_assignment(cost, maximize=True)
    return float(cost[r, c].sum())


def test_pruned_relaxation_equals_the_full_matching():
    # the solver matches only each target's L best pairs; a dense assignment sees every pair
    from obslib.assignment import relaxed_from_geometry

    rng = np.random.default_rng(11)
    for _ in range(300):
        L, extra = int(rng.integers(1, 9)), int(rng.integers(0, 5))
        S, T, W = random_instance(rng, L, extra, grid=bool(rng.integers(2)))
        plain, ordered = relaxed_from_geometry(S, T, 1.0)
        for res, flag in ((plain, False), (ordered, True), (relaxed_pair_assignment(W), False),
                          (relaxed_pair_assignment(W, ordered=True), True)):
            assert res.value == pytest.approx(full_matching_value(W, flag), rel=1e-12, abs=1e-15)
        assert plain.value == pytest.approx(sum(W[i, j, l] for i, j, l in plain.triples), rel=1e-12)
        assert len({(i, j) for i, j, _ in plain.triples}) == L and sorted(
            l for *_, l in plain.triples
        ) == list(range(L))
        assert all(i < j for i, j, _ in ordered.triples)


def test_problem_3_has_one_solver_for_weights_and_geometry():
    # from weights or from geometry, the same candidates and matching: the same triples
    rng = np.random.default_rng(12)
    for _ in range(50):
        S, T, W = random_instance(rng, int(rng.integers(1, 7)), int(rng.integers(0, 4)))
        for ordered in (False, True):
            a = relaxed_pair_assignment(W, ordered)
            b = relaxed_pair_assignment(sensors=S, targets=T, u_max=1.0, ordered=ordered)
            assert a.triples == b.triples and a.value == pytest.approx(b.value, rel=1e-12)
    # fewer pairs than targets: every pair serves one target, the heaviest assignment of them
    W = np.zeros((2, 2, 3))
    W[0, 1] = W[1, 0] = [0.2, 0.7, 0.5]
    assert relaxed_pair_assignment(W).triples == [(0, 1, 1)]
    assert relaxed_pair_assignment(W, ordered=True).triples == [(0, 1, 1), (0, 1, 2)]


def test_pruned_relaxation_skips_most_weights_on_large_instances():
    rng = np.random.default_rng(0)
    S, T = rng.uniform(0, 100, (300, 2)), rng.uniform(0, 100, (150, 2))
    res = relaxed_pair_assignment(sensors=S, targets=T, u_max=1.0)
    assert res.n_evaluations < 0.5 * 300 * 299 // 2 * 150


# --------------------------------------------------------------------------------------------
# The exact solver's branch and bound against brute force and the plain HiGHS 0-1 program
# --------------------------------------------------------------------------------------------


def _symmetric(rng, n, L, values):
    """Random symmetric weights drawn from ``values`` (zeros and exact ties when few values)."""
    W = rng.choice(values, size=(L, n, n))
    W = np.triu(W, 1)
    return (W + W.transpose(0, 2, 1)).transpose(1, 2, 0)


def _feasible(result, n, L):
    used = [s for i, j, _ in result.triples for s in (i, j)]
    targets = [l for *_, l in result.triples]
    return (len(used) == len(set(used)) and all(0 <= s < n for s in used)
            and len(targets) == len(set(targets)) and all(0 <= l < L for l in targets)
            and all(i < j for i, j, _ in result.triples))


def test_exact_solver_equals_brute_force_with_ties_zeros_and_spare_sensors():
    from obslib.studies.hardness import random_3dm, three_dm_weights

    rng = np.random.default_rng(11)
    for k in range(120):
        L, extra = int(rng.integers(1, 4)), int(rng.integers(0, 4))
        n = 2 * L + extra
        if k % 4 == 0:
            _, _, W = random_instance(rng, L, extra)
        elif k % 4 == 1:
            _, _, W = random_instance(rng, L, min(extra, 25 - 2 * L), grid=True)
        elif k % 4 == 2:
            W = _symmetric(rng, n, L, [0.0, 0.0, 1.0, 2.0, 3.0])
        else:
            q = L + 1
            W = three_dm_weights(q, random_3dm(q, int(rng.integers(q, 3 * q + 1)), rng))
        opt = optimal_pair_assignment(W)
        assert _feasible(opt, W.shape[0], W.shape[2])
        assert opt.value == sum(W[i, j, l] for i, j, l in opt.triples)
        assert opt.value == pytest.approx(brute_force(W), rel=1e-12, abs=1e-12)


def _highs(W):
    """Value of the plain HiGHS 0-1 program (proven optimum, zero gap)."""
    from obslib._exact_pairs import milp

    return assignment_value(W, milp(np.asarray(W, float)))


def test_exact_solver_equals_plain_highs_program():
    rng = np.random.default_rng(12)
    for k in range(40):
        L, extra = int(rng.integers(4, 11)), int(rng.integers(0, 5))
        n = 2 * L + extra
        if k % 3 == 0:
            _, _, W = random_instance(rng, L, extra)
        elif k % 3 == 1:
            W = _symmetric(rng, n, L, rng.uniform(0, 1, 50))
        else:
            W = _symmetric(rng, n, L, [0.0, 1.0, 1.0, 2.0])
        opt = optimal_pair_assignment(W)
        assert _feasible(opt, n, L)
        assert opt.value == pytest.approx(_highs(W), rel=1e-9)


def test_exact_solver_at_the_reach_sizes_equals_highs():
    # the instances of the exact-solver reach study at L = 15 (N = 2L), where HiGHS takes seconds
    from obslib._exact_pairs import milp

    rng = np.random.default_rng([0, 15])
    S, T = rng.uniform(0, 100, (30, 2)), rng.uniform(0, 100, (15, 2))
    W = ob.pair_bounds(S, T, 1.0)
    opt, ref = optimal_pair_assignment(W), milp(W)
    assert opt.value == pytest.approx(assignment_value(W, ref), rel=1e-12)
    assert opt.triples == ref  # a unique optimum (no ties in random geometry)


def test_exact_solver_hands_large_searches_to_highs(monkeypatch):
    from obslib import _exact_pairs as exact_pairs

    reference = exact_pairs.milp
    calls = []

    def counted(*args, **kwargs):
        calls.append(args)
        return reference(*args, **kwargs)

    monkeypatch.setattr(exact_pairs, "MAX_NODES", 0)  # every search that branches goes to HiGHS
    monkeypatch.setattr(exact_pairs, "milp", counted)
    rng = np.random.default_rng(13)
    for _ in range(10):
        L, extra = int(rng.integers(2, 6)), int(rng.integers(0, 3))
        _, _, W = random_instance(rng, L, extra)
        want = brute_force(W) if L <= 3 else assignment_value(W, reference(W))
        assert optimal_pair_assignment(W).value == pytest.approx(want, rel=1e-9)
    assert calls  # the hand-over happened


def test_exact_solver_honours_a_tiny_time_limit_at_L_100():
    """At L = 100, N = 200 (2 million pair-target variables) the call stops within its limit
    plus 1 s with the best assignment found, at least Algorithm 1's, and the LP bound once it
    is known."""
    import time

    import scipy.optimize  # noqa: F401  (the clock starts after this import)

    from obslib.assignment import OptimumNotProven

    rng = np.random.default_rng([0, 100])
    W = ob.pair_bounds(rng.uniform(0, 100, (200, 2)), rng.uniform(0, 100, (100, 2)), 1.0)
    greedy = greedy_pair_assignment(W).value
    for limit in (0.2, 2.0):
        t0 = time.perf_counter()
        with pytest.raises(OptimumNotProven, match="no proven optimum within time_limit") as err:
            optimal_pair_assignment(W, time_limit=limit)
        assert time.perf_counter() - t0 < limit + 1.0
        best = err.value.best
        assert _feasible(best, 200, 100) and sorted(l for *_, l in best.triples) == list(range(100))
        assert best.value == assignment_value(W, best.triples) >= greedy
        assert err.value.bound is None or best.value <= err.value.bound + 1e-9


def test_exact_solver_refuses_what_would_not_fit_in_memory(monkeypatch):
    from obslib import _exact_pairs as exact_pairs
    from obslib import assignment
    from obslib.assignment import OptimumNotProven

    rng = np.random.default_rng(14)
    _, _, W = random_instance(rng, 5, 0)
    # 45 * 5 variables do not fit in what leaves room for 56
    monkeypatch.setattr(assignment, "MAX_EXACT_BYTES",
                        exact_pairs.SEARCH_BYTES + 56 * exact_pairs.BYTES_PER_VARIABLE)
    with pytest.raises(ValueError, match=r"over the limit .* fits up to 56 variables"):
        optimal_pair_assignment(W)
    monkeypatch.undo()
    # the 0-1 program a large search hands over runs only within the limit: every search that
    # branches is handed over (no node allowed), and no program fits
    monkeypatch.setattr(exact_pairs, "MAX_NODES", 0)
    monkeypatch.setattr(exact_pairs, "MAX_BYTES", exact_pairs.memory_bytes(10, 5))
    stopped = 0
    for _ in range(20):
        _, _, W = random_instance(rng, 5, 0)
        want = _highs(W)
        try:
            assert optimal_pair_assignment(W).value == pytest.approx(want, rel=1e-9)
        except OptimumNotProven as err:
            assert "GiB" in str(err)
            assert err.best.value <= want + 1e-12 <= err.bound + 2e-12
            stopped += 1
    assert stopped


def test_exact_solver_time_limit_and_zero_weights():
    rng = np.random.default_rng([0, 20])
    W = ob.pair_bounds(rng.uniform(0, 100, (40, 2)), rng.uniform(0, 100, (20, 2)), 1.0)
    with pytest.raises(RuntimeError, match="proven optimum"):
        optimal_pair_assignment(W, time_limit=1e-6)
    for bad in (0, -1.0, float("inf")):
        with pytest.raises(ValueError, match="time_limit"):
            optimal_pair_assignment(W, time_limit=bad)
    assert optimal_pair_assignment(np.zeros((4, 4, 2))).triples == []


def test_progress_bars_go_to_stderr_and_change_nothing(capsys):
    rng = np.random.default_rng(15)
    S, T, W = random_instance(rng, 6, 2)
    runs = [
        (lambda p: greedy_pair_assignment(sensors=S, targets=T, u_max=1.0, progress=p), "greedy"),
        (lambda p: greedy_pair_assignment(W, progress=p), "greedy"),
        (lambda p: relaxed_pair_assignment(sensors=S, targets=T, u_max=1.0, progress=p),
         "candidate pairs"),
        (lambda p: relaxed_pair_assignment(W, progress=p), "matching"),
        (lambda p: optimal_pair_assignment(W, progress=p), "exact optimum"),
        (lambda p: greedy_pair_assignment_literal(W, progress=p), "literal Algorithm 1"),
    ]
    for run, label in runs:
        quiet = run(False)
        assert capsys.readouterr().err == ""
        shown = run(True)
        out = capsys.readouterr()
        assert label in out.err and out.out == ""
        assert shown == quiet
    with pytest.raises(ValueError, match="progress"):
        greedy_pair_assignment(W, progress="yes")


def test_pair_search_returns_every_pair_down_to_its_floor():
    """PairSearch.best against all pairs weighed: the pairs it returns are exactly those at or
    above the floor it reports (at least k of them), with the kernel's weights, from any first
    threshold, on uniform scenes, a grid (ties) and clustered sensors."""
    from obslib._pair_search import PairSearch, target_rows

    rng = np.random.default_rng(23)
    scenes = [(rng.uniform(0, 100, (300, 2)), rng.uniform(0, 100, (4, 2))),
              (np.array([(a, b) for a in range(18) for b in range(18)], float) * 5.0,
               np.array([[42.5, 42.5], [2.5, 87.5], [120.0, -10.0]])),
              (rng.normal(50, 3, (250, 2)), np.array([[50.5, 50.5], [90.0, 50.0]]))]
    for S, T in scenes:
        x, y, u2 = target_rows(S, T, 1.0, None)
        search = PairSearch(x, y, u2)
        ii, jj = np.triu_indices(S.shape[0], 1)
        for l in range(T.shape[0]):
            every = search.weights(l, ii, jj)
            for k, tau in [(1, None), (16, None), (40, 0.999), (16, 0.2)]:
                idx = np.sort(rng.choice(S.shape[0], size=S.shape[0] - 7, replace=False))
                a, b, w, floor = search.best(l, idx, k, tau)
                inside = np.isin(ii, idx) & np.isin(jj, idx)
                want = {(i, j) for i, j in zip(ii[inside & (every >= floor)].tolist(),
                                               jj[inside & (every >= floor)].tolist())}
                got = {(min(p, q), max(p, q)) for p, q in zip(a.tolist(), b.tolist())}
                assert got == want and len(got) == a.size
                assert floor == -np.inf or a.size >= k
                W = {(i, j): v for i, j, v in zip(ii.tolist(), jj.tolist(), every.tolist())}
                assert all(W[min(p, q), max(p, q)] == v for p, q, v in zip(a, b, w))


def test_geometry_solvers_refuse_what_does_not_fit_before_allocating():
    # a million sensors and a thousand targets: 15 GiB of rows, refused with the size and what
    # fits, having allocated little more than the input (measured: tracemalloc's peak)
    import tracemalloc

    from obslib._memory import MAX_GEOMETRY_BYTES, geometry_bytes

    rng = np.random.default_rng(0)
    S, T = rng.uniform(0, 1e6, (1_000_000, 2)), rng.uniform(0, 1e6, (1_000, 2))
    calls = {
        "greedy_pair_assignment": lambda: greedy_pair_assignment(sensors=S, targets=T, u_max=1.0),
        "relaxed_pair_assignment": lambda: relaxed_pair_assignment(sensors=S, targets=T,
                                                                   u_max=1.0),
        "upper_pair_weight_blocks": lambda: ob.assignment.upper_pair_weight_blocks(S, T, 1.0),
    }
    for name, call in calls.items():
        tracemalloc.start()
        with pytest.raises(ValueError) as exc:
            call()
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
        message = str(exc.value)
        assert message.startswith(f"{name} from geometry needs about ") and "GiB" in message
        assert "N = 1,000,000 sensors and L = 1,000 targets" in message and "fit" in message
        assert peak < 200 * 2**20, (name, peak)  # the input is 16 MB; the rows would be 15 GiB
    # what the message says fits does fit, and one more does not
    import re

    n_fit, l_fit = (int(v.replace(",", "")) for v in re.search(
        r"at most N = ([\d,]+) sensors with these 1,000 targets or L = ([\d,]+) targets",
        str(exc.value)).groups())
    for (n, L), more in (((n_fit, 1000), (n_fit + 1, 1000)), ((1_000_000, l_fit),
                                                             (1_000_000, l_fit + 1))):
        assert geometry_bytes(n, L, "greedy") <= MAX_GEOMETRY_BYTES < geometry_bytes(*more,
                                                                                     "greedy")
    with pytest.raises(ValueError, match=r"\(L, P\) = \(2, 199990000\) array of pair weights "
                       r"needs 3.0 GiB.*upper_pair_weight_blocks"):
        ob.assignment.upper_pair_weights(S[:20_000], T[:2], 1.0)


def test_the_geometry_memory_estimate_bounds_the_measured_peak():
    # the estimate is an upper bound of what the solvers take (tracemalloc counts NumPy's arrays)
    import tracemalloc

    from obslib._memory import geometry_bytes

    rng = np.random.default_rng(1)
    for n, L in ((1000, 500), (20_000, 10)):
        S, T = rng.uniform(0, 100, (n, 2)), rng.uniform(0, 100, (L, 2))
        for what, call in (
            ("greedy", lambda: greedy_pair_assignment(sensors=S, targets=T, u_max=1.0)),
            ("relaxed", lambda: relaxed_pair_assignment(sensors=S, targets=T, u_max=1.0)),
            ("relaxed, both", lambda: ob.assignment.relaxed_from_geometry(S, T, 1.0)),
        ):
            tracemalloc.start()
            call()
            peak = tracemalloc.get_traced_memory()[1]
            tracemalloc.stop()
            assert peak <= geometry_bytes(n, L, what), (what, n, L, peak)

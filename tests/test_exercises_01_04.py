"""The solutions of the exercises of chapters 1-4, recomputed another way.

Each chapter module of :mod:`obsbook.chapters` computes the numbers its exercises and their
solutions glue (``exercise_numbers``); here they are recomputed by hand formulas (eigenvalues of
a 2 x 2 matrix, Theorem 4's expression written out, determinants), by brute force (every
assignment of pairs to targets, every subset of a team) or on the same random instances with
the library's public functions, and compared.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

import obslib as ob
from obsbook.chapters import greedy_unique_pairs as ch03
from obsbook.chapters import model_and_bound as ch01
from obsbook.chapters import pair_closed_form as ch02
from obsbook.chapters import submodularity as ch04

# ------------------------------------------------------------------------------- helpers


def _eig2(rows) -> tuple[float, float]:
    """The eigenvalues (ascending) of R^T R for rows R of a 2 x 2 problem, by the formula
    tr/2 -+ sqrt((a - c)^2 / 4 + b^2)."""
    R = np.asarray(rows, dtype=float)
    a, b, c = (R[:, 0] ** 2).sum(), (R[:, 0] * R[:, 1]).sum(), (R[:, 1] ** 2).sum()
    half = math.sqrt((a - c) ** 2 / 4 + b * b)
    return (a + c) / 2 - half, (a + c) / 2 + half


def _bound_by_hand(rows, u_max: float) -> float:
    """Theorem 1's bound sqrt(lambda_min / (lambda_max + u^2)) from the eigenvalue formula."""
    lo, hi = _eig2(rows)
    return math.sqrt(max(lo, 0.0) / (hi + u_max**2))


def _pair_bound_printed(alpha, theta, q) -> float:
    """Eq. (9) as printed, with its square roots written out."""
    S = math.sqrt(1 + alpha**4 + 2 * alpha**2 * math.cos(2 * theta))
    return math.sqrt((1 + alpha**2 - S) / (1 + alpha**2 + S + 2 * q * q))


def _greedy_by_hand(W) -> tuple[float, list]:
    """Algorithm 1 as printed: every round, the heaviest free triple (ties to the smallest)."""
    n, _, L = W.shape
    free_s, free_t, picks = set(range(n)), set(range(L)), []
    while free_t:
        best = max(((W[i, j, t], -i, -j, -t) for i, j in itertools.combinations(sorted(free_s), 2)
                    for t in free_t))
        i, j, t = -best[1], -best[2], -best[3]
        picks.append((i, j, t))
        free_s -= {i, j}
        free_t -= {t}
    return sum(W[p] for p in picks), picks


def _optimum_by_enumeration(W) -> float:
    """Problem 1 by trying every assignment of disjoint pairs to the targets in order."""
    n, _, L = W.shape
    best = -math.inf

    def go(t, used, total):
        nonlocal best
        if t == L:
            best = max(best, total)
            return
        for i, j in itertools.combinations([s for s in range(n) if s not in used], 2):
            go(t + 1, used | {i, j}, total + W[i, j, t])

    go(0, frozenset(), 0.0)
    return best


# ------------------------------------------------------------------------------- chapter 1


@pytest.fixture(scope="module")
def scene01():
    S = np.array(ob.tracking.PAPER_CIRCLE.sensors)[[1, 2, 3]]
    T = np.array(ob.tracking.PAPER_CIRCLE.center)
    return S, T


def test_01_bound_by_hand(scene01):
    x = ch01.exercise_numbers(*scene01, u_max=1.0)["by_hand"]
    rows = np.array(ch01.EXERCISE_ROWS)
    lengths = sorted(np.linalg.norm(rows, axis=1))  # orthogonal rows: the singular values
    assert float(rows[0] @ rows[1]) == 0.0
    assert x["sigma_min"] == pytest.approx(lengths[0], rel=1e-12)
    assert x["sigma_max"] == pytest.approx(lengths[1], rel=1e-12)
    u = ch01.EXERCISE_U_MAX
    assert x["bound"] == pytest.approx(lengths[0] / math.hypot(lengths[1], u), rel=1e-12)
    # the worst control runs along the longer row, at full speed, and attains the bound
    longer = rows[np.argmax(np.linalg.norm(rows, axis=1))]
    np.testing.assert_allclose(x["u_star"], u * np.abs(longer) / np.linalg.norm(longer),
                               atol=1e-12)
    full = np.vstack([rows, x["u_star"]])
    s = np.linalg.svd(full, compute_uv=False)
    assert x["exact_at_star"] == pytest.approx(s[-1] / s[0], rel=1e-12)
    assert x["exact_at_star"] == pytest.approx(x["bound"], rel=1e-12)


def test_01_faster_target_is_a_little_lower_and_still_attained(scene01):
    S, T = scene01
    x = ch01.exercise_numbers(S, T, u_max=1.0)["rerun"]
    rows = T - S
    assert x["bound"] == pytest.approx(_bound_by_hand(rows, 1.0), rel=1e-12)
    u2 = ch01.EXERCISE_U_RERUN
    assert x["bound_rerun"] == pytest.approx(_bound_by_hand(rows, u2), rel=1e-12)
    assert x["sigma_max"] == pytest.approx(math.sqrt(_eig2(rows)[1]), rel=1e-12)
    # the exact value over a fine circle of controls of length u2 has its minimum at the bound
    phi = np.linspace(0, 2 * np.pi, 20001)
    U = u2 * np.stack([np.cos(phi), np.sin(phi)], axis=1)
    exact = ob.inverse_condition_number(S, T, U)
    assert exact.min() == pytest.approx(x["exact_rerun"], rel=1e-6)
    assert x["exact_rerun"] == pytest.approx(x["bound_rerun"], rel=1e-12)
    assert x["bound_rerun"] < x["bound"] and x["bound_rerun"] > 0.8 * x["bound"]  # "a little"


def test_01_ratio_up_bound_down(scene01):
    c = ch01.exercise_numbers(*scene01, u_max=1.0)["counter"]
    for key, rows in ch01.EXERCISE_SHRINK.items():
        lo, hi = _eig2(rows)
        assert c[key]["icn"] == pytest.approx(math.sqrt(lo / hi), rel=1e-12)
        assert c[key]["sigma_min"] == pytest.approx(math.sqrt(lo), rel=1e-12)
        assert c[key]["bound"] == pytest.approx(_bound_by_hand(rows, ch01.EXERCISE_U_MAX),
                                                rel=1e-12)
    assert c["after"]["icn"] > c["before"]["icn"]  # the ratio rises ...
    assert c["after"]["sigma_min"] < c["before"]["sigma_min"]  # ... sigma_min falls ...
    assert c["after"]["bound"] < c["before"]["bound"]  # ... and so does the bound


# ------------------------------------------------------------------------------- chapter 2


def test_02_bound_by_hand():
    x = ch02.exercise_numbers(1.0, 1.0)["by_hand"]
    e = ch02.EXERCISE_PAIR
    assert x["S"] == pytest.approx(math.sqrt(1 + e["alpha"] ** 4), rel=1e-12)  # cos 2 theta = 0
    assert x["bound"] == pytest.approx(_pair_bound_printed(e["alpha"], e["theta"], e["q"]),
                                       rel=1e-12)
    # the same pair from positions: sensor i at (1, 0), sensor j at alpha (cos th, sin th)
    sensors = np.array([[1.0, 0.0], [e["alpha"] * math.cos(e["theta"]),
                                     e["alpha"] * math.sin(e["theta"])]])
    assert x["bound"] == pytest.approx(ob.lower_bound(sensors, [0.0, 0.0], e["q"]), rel=1e-12)


@pytest.mark.parametrize("u_max, d_io", [(1.0, 1.0), (0.5, 2.0)])
def test_02_faster_target_peak_stays_and_sinks(u_max, d_io):
    r = ch02.exercise_numbers(u_max, d_io)["rerun"]
    q, q2 = u_max / d_io, ch02.EXERCISE_U_RERUN / d_io
    assert r["peak"] == pytest.approx(1 / math.sqrt(1 + q * q), rel=1e-12)
    assert r["peak_rerun"] == pytest.approx(1 / math.sqrt(1 + q2 * q2), rel=1e-12)
    a = ch02.EXERCISE_ALPHA_UNEQUAL  # at a right angle and alpha >= 1: 1 / sqrt(a^2 + q^2)
    assert r["unequal"] == pytest.approx(1 / math.sqrt(a * a + q * q), rel=1e-12)
    assert r["unequal_rerun"] == pytest.approx(1 / math.sqrt(a * a + q2 * q2), rel=1e-12)
    # the peak of Fig. 2 on a fine grid at the rerun's speed sits at alpha = 1, theta = pi/2
    alpha = np.linspace(0.01, 5, 500)[:, None]
    theta = np.linspace(0.01, np.pi - 0.01, 315)[None, :]
    S = np.sqrt(1 + alpha**4 + 2 * alpha**2 * np.cos(2 * theta))
    Z = np.sqrt(np.clip(1 + alpha**2 - S, 0, None) / (1 + alpha**2 + S + 2 * q2 * q2))
    i, j = np.unravel_index(np.argmax(Z), Z.shape)
    assert abs(alpha[i, 0] - 1) < 0.02 and abs(theta[0, j] - np.pi / 2) < 0.02
    assert Z.max() <= r["peak_rerun"] + 1e-12
    # less in proportion for the unequal pair
    assert r["unequal_rerun"] / r["unequal"] > r["peak_rerun"] / r["peak"]


def test_02_best_partner_by_a_dense_search():
    c = ch02.exercise_numbers(1.0, 1.0)["counter"]
    th = ch02.EXERCISE_PAIR["theta"]
    alpha = np.linspace(0.5, 3.0, 250001)
    for q, star in ((c["q"], c["alpha_star"]), (0.0, c["alpha_star_q0"])):
        S = np.sqrt(1 + alpha**4 + 2 * alpha**2 * np.cos(2 * th))
        Z = np.sqrt((1 + alpha**2 - S) / (1 + alpha**2 + S + 2 * q * q))
        assert star == pytest.approx(alpha[np.argmax(Z)], abs=2e-5)
    assert c["alpha_star_q0"] == pytest.approx(1.0, abs=1e-9)
    assert c["at_star"] == pytest.approx(_pair_bound_printed(c["alpha_star"], th, c["q"]),
                                         rel=1e-9)
    assert c["at_one"] == pytest.approx(_pair_bound_printed(1.0, th, c["q"]), rel=1e-12)
    assert c["at_star"] > c["at_one"]


# ------------------------------------------------------------------------------- chapter 3


@pytest.fixture(scope="module")
def numbers03():
    return ch03.exercise_numbers(60, 0, 2, 4, 2, 1.0)


@pytest.mark.parametrize("key, negative", [("by_hand", False), ("negative", True)])
def test_03_greedy_and_optimum_by_brute_force(numbers03, key, negative):
    W = ch03.exercise_weights(negative)
    assert np.array_equal(W, W.transpose(1, 0, 2))
    greedy, picks = _greedy_by_hand(W)
    x = numbers03[key]
    assert x["greedy"] == pytest.approx(greedy, abs=1e-12)
    assert x["greedy_triples"] == [tuple(map(int, p)) for p in picks]
    assert x["optimum"] == pytest.approx(_optimum_by_enumeration(W), abs=1e-12)
    opt_total = sum(W[i, j, t] for i, j, t in x["optimal_triples"])
    assert opt_total == pytest.approx(x["optimum"], abs=1e-12)


def test_03_the_exercises_show_what_their_solutions_say(numbers03):
    h, n = numbers03["by_hand"], numbers03["negative"]
    assert 1 / 3 <= h["greedy"] / h["optimum"] < 1  # the greedy loses, within its guarantee
    assert n["greedy"] / n["optimum"] < 1 / 3  # one negative value breaks the guarantee
    first = h["greedy_triples"][0]
    blocked = [t for t in h["optimal_triples"] if set(t[:2]) & set(first[:2]) or t[2] == first[2]]
    assert len(blocked) == 2  # the first pick blocks both triples of the optimum
    assert ch03.exercise_weights(False).min() >= 0


def test_03_spare_sensors_recomputed_on_the_same_instances(numbers03):
    from obslib.studies import greedy_unique_pairs

    for key, extra in (("spare", 2), ("no_spare", 0)):
        ratios = []
        for _, _, idx, S, T in greedy_unique_pairs.pair_instances(60, 0, (2, 4), (0, extra)):
            for k in range(len(idx)):
                W = ob.pair_bounds(S[k], T[k], 1.0)
                greedy, _ = _greedy_by_hand(W)
                ratios.append(greedy / _optimum_by_enumeration(W))
        r = np.array(ratios)
        assert numbers03[key]["optimal"] == pytest.approx(np.mean(r >= 1 - 1e-12), abs=1e-12)
        assert numbers03[key]["mean"] == pytest.approx(r.mean(), rel=1e-9)
        assert numbers03[key]["min"] == pytest.approx(r.min(), rel=1e-9)


# ------------------------------------------------------------------------------- chapter 4

P04 = np.array([[0.0, 3.0], [3.0, 0.0], [5.0, 0.0]])  # the intuition's sensors


def test_04_gains_by_determinants():
    x = ch04.exercise_numbers(P04, np.zeros(2), 1.0, 1.0, 20, 0, 2)["by_hand"]
    rows = {k: np.array(v) for k, v in ch04.EXERCISE_ROWS.items()}

    def logdet(names):
        G = np.eye(2) + sum(np.outer(rows[k], rows[k]) for k in names)
        return math.log(np.linalg.det(G))

    assert x["logdet"]["at_a"] == pytest.approx(logdet("ac") - logdet("a"), rel=1e-12)
    assert x["logdet"]["at_ab"] == pytest.approx(logdet("abc") - logdet("ab"), rel=1e-12)
    assert x["logdet"]["at_a"] > x["logdet"]["at_ab"]  # diminishing returns
    c2 = float(rows["c"] @ rows["c"])
    assert x["trace"]["at_a"] == pytest.approx(c2) and x["trace"]["at_ab"] == pytest.approx(c2)


def test_04_fewer_sensors_by_brute_force():
    from obslib.studies import submodularity as sm

    n, N = 30, ch04.EXERCISE_N_SENSORS
    r = ch04.exercise_numbers(P04, np.zeros(2), 1.0, 1.0, n, 0, 2)["rerun"]
    S, T = sm.random_instances(n, N, 0, "generic")
    n_mono = n_sub = 0
    for k in range(n):
        teams = [frozenset(c) for m in range(2, N + 1) for c in itertools.combinations(range(N), m)]
        w = {A: float(ob.lower_bound(S[k][sorted(A)], T[k], 1.0)) for A in teams}
        tol = 1e-9 * max(w.values())
        mono = any(w[A | {x}] < w[A] - tol for A in teams for x in range(N) if x not in A)
        sub = any(w[B | {x}] - w[B] > w[A | {x}] - w[A] + tol
                  for A in teams for B in teams if A < B for x in range(N) if x not in B)
        n_mono += mono
        n_sub += sub
    assert (r["n"], r["not_monotone"], r["not_submodular"]) == (n, n_mono, n_sub)


def test_04_no_third_sensor_raises_a_perfect_cross():
    c = ch04.exercise_numbers(P04, np.zeros(2), 1.0, 1.0, 20, 0, 2)["cross"]
    d = 3.0  # both rows have length 3 and are orthogonal
    assert c["pair"] == pytest.approx(d / math.sqrt(d * d + 1.0), rel=1e-12)
    for third, w in zip(ch04.EXERCISE_THIRDS, c["with"]):
        v2 = float(np.dot(third, third))  # the row of a sensor at p is o - p = -p
        assert w == pytest.approx(d / math.sqrt(d * d + v2 + 1.0), rel=1e-12)
        assert w < c["pair"]
    # and no sensor anywhere on a grid raises it
    g = np.linspace(-6, 6, 61)
    best = max(float(ob.lower_bound(np.vstack([P04[:2], [x, y]]), np.zeros(2), 1.0))
               for x in g for y in g
               if (x, y) not in {(0.0, 0.0), tuple(P04[0]), tuple(P04[1])})
    assert best < c["pair"]

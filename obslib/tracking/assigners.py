"""Assignments of sensors to many targets, re-made at every step from the filters' estimates
:math:`\\hat x_l` and covariances :math:`\\Sigma_l` (:data:`ASSIGNMENTS`).

Pairs, one per target, no sensor serving two targets (Problem 1 of the paper; at least two
sensors per target):

``"unique-pairs"``
    Algorithm 1, the greedy of Fig. 8, on Theorem 4's pair bound at the estimates with the
    setup's :math:`u_{\\max}` (Euclidean distances, or Mahalanobis ones in :math:`\\Sigma_l`,
    the setup's ``metric``); ties to the smallest ``(i, j, l)``;
``"d-optimal-pairs"``
    the same greedy on each pair's information gain for its target's filter,
    :math:`\\log\\det(I + H \\Sigma_l^- H^T / R)` with :math:`\\Sigma_l^- = \\Sigma_l + Q`
    and the measurement model's Jacobian rows ``H`` of the pair at :math:`\\hat x_l`
    (:math:`\\log\\det J_l(i, j) - \\log\\det (\\Sigma_l^-)^{-1}`, the D-optimal choice of
    chapter 10 made target by target);
``"optimal-pairs"``
    Problem 1 solved exactly at every step on the bound's weights: by enumeration of every
    assignment where there are at most :data:`MAX_ENUMERATED` (the first optimum in the order of
    the enumeration), else by :func:`obslib.optimal_pair_assignment` (branch and bound, within
    its memory limit);
``"random"``
    a uniformly random assignment: a random permutation of the sensors, target ``l`` taking its
    entries ``2l`` and ``2l + 1`` (drawn from ``numpy.random.default_rng([2, seed])``, a stream
    apart from the run's noise, unless the permutations are given).

Teams, every sensor given to one target (Problem 2), by the greedy of Fig. 9: ``N`` rounds, each
giving one free sensor to the target whose measure grows most. The paper's measure is
:math:`\\log\\det(O_l^T O_l)`, with the rows :math:`\\hat x_l - p_i` of the team and no prior. For
a team of fewer than two sensors :math:`O_l^T O_l` is singular, and what a greedy does then is a
matter of arithmetic:

``"logdet-teams"``
    the measure as the authors' code evaluates it in floating point
    (:mod:`~obslib.tracking.code_logdet`, :func:`~obslib.tracking.code_logdet.code_logdet_det`):
    the determinant of the rounded :math:`O_l^T O_l` by an LU factorisation with partial
    pivoting and a fused multiply-add, which leaves the rounding residue of a singular matrix
    (zero, a tiny positive number, or a tiny negative one, whose logarithm is complex); the
    logarithm of an empty team's determinant is 0 (MATLAB's :math:`\\det` of a 0 x 0 matrix is
    1); the table of gains of the sensors already taken holds zeros; and the round's pick is
    the first entry, in column order (smallest target, then smallest sensor), equal to
    MATLAB's ``max(max(table))``
    (:func:`~obslib.tracking.code_logdet.matlab_table_max`: by value among real numbers, by
    magnitude and phase angle in a table with complex entries). Which target gets a first
    sensor is then decided by those residues;
``"logdet-teams-as-run"``
    the same teams, read as the authors' experiment reads them: target ``l``'s filter measures
    with the sensors numbered by the *rounds* at which ``l`` won a sensor, not with the sensors
    it won (its script takes the column indices of the greedy's table of picks). This is what
    produced the saved run;
``"logdet-teams-exact"``
    the same greedy in exact arithmetic: a singular team's :math:`\\log\\det` is
    :math:`-\\infty`, so every first gain is :math:`-\\infty`, every second :math:`+\\infty`,
    and the first target takes every sensor;
``"logdet-teams-prior"``
    the greedy on :math:`\\log\\det(O_l^T O_l + \\varepsilon I)` with the setup's ``eps``
    (:func:`obslib.greedy_team_assignment`, the measure of Fig. 9 as this book evaluates it);
``"d-optimal-teams"``, ``"a-optimal-teams"``, ``"e-optimal-teams"``
    the greedy on the information each filter's next update would have,
    :math:`J_l(S) = (\\Sigma_l + Q)^{-1} + \\sum_{i \\in S} h_{il} h_{il}^T / R` with the
    measurement model's Jacobian rows :math:`h_{il}` at :math:`\\hat x_l`: maximising
    :math:`\\sum_l \\log\\det J_l`, :math:`-\\sum_l \\operatorname{tr} J_l^{-1}` or
    :math:`\\sum_l \\lambda_{\\min}(J_l)` (the criteria of chapter 10, one filter per target);
    ties to the smallest sensor, then the smallest target. One row never raises the smallest
    eigenvalue of an isotropic :math:`J_l`, so where every prior is isotropic (the later
    experiment's first step) every first gain of the E-criterion is zero, the first target takes
    the first sensor, and from then on only its gains are positive: the E-optimal greedy
    gives it every sensor, as exact arithmetic does with the log det.
"""

from __future__ import annotations

import math
from functools import lru_cache
from itertools import combinations

import numpy as np

from .._kernels import mahalanobis_rescale, normalise_rows, pair_kernel
from .._validate import as_choice, as_float_array, as_instance, as_int
from .code_logdet import logdet_labels

__all__ = ["ASSIGNMENTS", "PAIR_ASSIGNMENTS", "MAX_ENUMERATED", "assign_targets"]

#: The assignments :func:`~obslib.tracking.simulate_targets` accepts (see the module docstring).
ASSIGNMENTS = ("unique-pairs", "d-optimal-pairs", "optimal-pairs", "random", "logdet-teams",
               "logdet-teams-as-run", "logdet-teams-exact", "logdet-teams-prior",
               "d-optimal-teams", "a-optimal-teams", "e-optimal-teams")

#: The assignments of one pair per target (they need at least two sensors per target).
PAIR_ASSIGNMENTS = ("unique-pairs", "d-optimal-pairs", "optimal-pairs", "random")

#: Largest number of assignments ``"optimal-pairs"`` enumerates, ``N! / ((N - 2L)! 2^L)``;
#: beyond it each step is solved by branch and bound.
MAX_ENUMERATED = 200_000

#: Weights per block of runs for the batched greedy (0.5 MB); beyond one run's worth the
#: greedy runs from geometry, run by run, without the weights.
_BLOCK_WEIGHTS = 1 << 16


# --------------------------------------------------------------------------------------------
# Pairs
# --------------------------------------------------------------------------------------------


def pair_weights(S, x, P, u_max: float, maha: bool) -> np.ndarray:
    """Theorem 4's bound of every pair ``i < j`` (``numpy.triu_indices`` order) for every
    target of ``M`` runs, ``(M, N (N - 1) / 2, L)``: sensors ``S`` ``(N, 2)`` or one set per
    run ``(M, N, 2)``, estimates ``x`` ``(M, L, 2)``, covariances ``P`` ``(M, L, 2, 2)`` (used
    where ``maha``). The rows, their
    normalisation and the kernel of :func:`obslib.pair_bounds`, elementwise, so the weights are
    its numbers (exact ties stay ties: the later experiment's first step has one).

    Examples
    --------
    >>> import numpy as np
    >>> import obslib as ob
    >>> S = np.array([[0.0, 0.0], [4.0, 0.0], [1.0, 3.0]])
    >>> x = np.array([[[2.0, 1.0], [0.5, 0.5]]])
    >>> P = np.broadcast_to(np.eye(2), (1, 2, 2, 2))
    >>> w = pair_weights(S, x, P, 0.5, False)
    >>> W = ob.pair_bounds(S, x[0], 0.5)
    >>> bool((w[0] == W[[0, 0, 1], [1, 2, 2]]).all())
    True
    """
    M, L = x.shape[:2]
    N = S.shape[-2]
    ii, jj = np.triu_indices(N, 1)
    S = np.broadcast_to(S, (M, N, 2))
    d = (x[:, :, None, :] - S[:, None, :, :]).reshape(M * L, N, 2)  # rows o_l - p_i
    unit = 1.0
    if maha:
        v, unit = mahalanobis_rescale(d.transpose(1, 0, 2), P.reshape(M * L, 2, 2))
        dx, dy = v[..., 0].T, v[..., 1].T
    else:
        dx, dy = d[..., 0], d[..., 1]
    with np.errstate(over="ignore"):
        vx, vy, u2 = normalise_rows(dx, dy, u_max / unit)
    w = pair_kernel(vx[:, ii], vy[:, ii], vx[:, jj], vy[:, jj], u2[:, None])
    return np.ascontiguousarray(w.reshape(M, L, ii.size).transpose(0, 2, 1))


def pair_gain_weights(S, x, Ppred, r: float, measurement: str) -> np.ndarray:
    """The information gain of every pair ``i < j`` for every target of ``M`` runs,
    :math:`\\log\\det(I_2 + H \\Sigma^- H^T / r)`, ``(M, N (N - 1) / 2, L)``: sensors ``S``
    ``(N, 2)`` or ``(M, N, 2)``, estimates ``x`` ``(M, L, 2)``, predicted covariances ``Ppred``
    ``(M, L, 2, 2)``, the measurement model's rows ``H`` of the pair at the estimate.

    With :math:`a_i = h_i^T \\Sigma^- h_i / r` and :math:`c_{ij} = h_i^T \\Sigma^- h_j / r`
    (Sylvester's determinant identity), the gain is :math:`\\log((1 + a_i)(1 + a_j) -
    c_{ij}^2)`, :math:`\\log\\det J(i, j) - \\log\\det (\\Sigma^-)^{-1}` with
    :math:`J(i, j) = (\\Sigma^-)^{-1} + H^T H / r`.

    Examples
    --------
    >>> import numpy as np
    >>> S = np.array([[0.0, 0.0], [4.0, 0.0], [1.0, 3.0]])
    >>> x, Pm = np.array([[[2.0, 1.0]]]), np.array([[[[1.0, 0.2], [0.2, 0.5]]]])
    >>> g = pair_gain_weights(S, x, Pm, 0.25, "half-squared-range")
    >>> H = x[0, 0] - S[[0, 2]]  # the rows of the pair (0, 2)
    >>> J = np.linalg.inv(Pm[0, 0]) + H.T @ H / 0.25
    >>> gain = np.log(np.linalg.det(J) * np.linalg.det(Pm[0, 0]))
    >>> bool(np.isclose(g[0, 1, 0], gain))
    True
    """
    M, L = x.shape[:2]
    N = S.shape[-2]
    ii, jj = np.triu_indices(N, 1)
    S = np.broadcast_to(S, (M, N, 2))
    h = x[:, None, :, :] - S[:, :, None, :]  # (M, N, L, 2)
    if measurement == "range":
        h = h / np.hypot(h[..., 0], h[..., 1])[..., None]
    hx, hy = h[..., 0] / np.sqrt(r), h[..., 1] / np.sqrt(r)  # (M, N, L)
    p00, p01, p11 = (Ppred[:, None, :, a, b] for a, b in ((0, 0), (0, 1), (1, 1)))
    a = p00 * (hx * hx) + p01 * (hx * hy + hy * hx) + p11 * (hy * hy)  # c_ii, (M, N, L)
    xi, yi, xj, yj = hx[:, ii], hy[:, ii], hx[:, jj], hy[:, jj]
    c = p00 * (xi * xj) + p01 * (xi * yj + yi * xj) + p11 * (yi * yj)  # (M, P, L)
    det = (1 + a[:, ii]) * (1 + a[:, jj]) - c * c
    return np.log(det)


def _gain_pairs(S, x, Ppred, r, measurement) -> np.ndarray:
    from ..assignment import greedy_pairs_batch

    M, L = x.shape[:2]
    N = S.shape[1]
    per_run = N * (N - 1) // 2 * L
    block = max(1, _BLOCK_WEIGHTS // per_run)
    out = []
    for a in range(0, M, block):
        w = pair_gain_weights(S[a:a + block], x[a:a + block], Ppred[a:a + block], r,
                              measurement)
        picks, _ = greedy_pairs_batch(w, N)
        out.append(_labels_of_picks(picks, N))
    return np.concatenate(out)


def _labels_of_picks(picks, N) -> np.ndarray:
    """Labels ``(M, N)`` (the target of each sensor, -1 for none) of pair picks ``(M, L, 3)``."""
    M = picks.shape[0]
    labels = np.full((M, N), -1, dtype=np.int64)
    rows = np.arange(M)[:, None]
    labels[rows, picks[..., 0]] = picks[..., 2]
    labels[rows, picks[..., 1]] = picks[..., 2]
    return labels


def _unique_pairs(S, x, P, u_max, maha) -> np.ndarray:
    from ..assignment import greedy_pair_assignment, greedy_pairs_batch

    M, L = x.shape[:2]
    N = S.shape[1]
    per_run = N * (N - 1) // 2 * L
    if per_run > _BLOCK_WEIGHTS:  # from geometry, run by run: the weights are never built
        labels = np.full((M, N), -1, dtype=np.int64)
        for m in range(M):
            a = greedy_pair_assignment(sensors=S[m], targets=x[m], u_max=u_max,
                                       cov=P[m] if maha else None)
            for i, j, l in a.triples:
                labels[m, i] = labels[m, j] = l
        return labels
    out = []
    block = max(1, _BLOCK_WEIGHTS // per_run)
    for a in range(0, M, block):
        w = pair_weights(S[a:a + block], x[a:a + block], P[a:a + block], u_max, maha)
        picks, _ = greedy_pairs_batch(w, N)
        out.append(_labels_of_picks(picks, N))
    return np.concatenate(out)


def assignment_count(n: int, n_targets: int) -> int:
    """The number of assignments of disjoint pairs of ``n`` sensors to ``n_targets`` targets,
    :math:`n! / ((n - 2L)!\\, 2^L)`.

    Examples
    --------
    >>> assignment_count(8, 3)  # the later experiment
    2520
    """
    if n < 2 * n_targets:
        return 0
    return math.factorial(n) // math.factorial(n - 2 * n_targets) // 2**n_targets


@lru_cache(maxsize=8)
def _enumerated(n: int, n_targets: int) -> np.ndarray:
    """Every assignment as pair indices (``numpy.triu_indices(n, 1)`` order) per target,
    ``(A, L)``, target 0's pair varying slowest, each in increasing order."""
    index = {p: k for k, p in enumerate(zip(*np.triu_indices(n, 1)))}
    rows = [()]
    for _ in range(n_targets):
        nxt = []
        for row in rows:
            used = {i for p in row for i in p}
            free = [i for i in range(n) if i not in used]
            nxt += [row + (p,) for p in combinations(free, 2)]
        rows = nxt
    return np.array([[index[p] for p in row] for row in rows], dtype=np.int64)


def _optimal_pairs(S, x, P, u_max, maha) -> np.ndarray:
    from ..assignment import optimal_pair_assignment

    M, L = x.shape[:2]
    N = S.shape[1]
    ii, jj = np.triu_indices(N, 1)
    w = pair_weights(S, x, P, u_max, maha)  # (M, P, L)
    if assignment_count(N, L) <= MAX_ENUMERATED:
        table = _enumerated(N, L)  # (A, L)
        total = np.zeros((M, table.shape[0]))
        for l in range(L):
            total += w[:, table[:, l], l]
        best = table[total.argmax(axis=1)]  # (M, L): the first optimum
        picks = np.stack([ii[best], jj[best], np.broadcast_to(np.arange(L), best.shape)], -1)
        return _labels_of_picks(picks, N)
    labels = np.full((M, N), -1, dtype=np.int64)
    for m in range(M):
        W = np.zeros((N, N, L))
        W[ii, jj], W[jj, ii] = w[m], w[m]
        for i, j, l in optimal_pair_assignment(W).triples:
            labels[m, i] = labels[m, j] = l
    return labels


def random_draws(seed: int, steps: int, n_sensors: int) -> np.ndarray:
    """The ``"random"`` assignment's permutations of the sensors for the ``steps + 1`` choices
    of a run, ``(steps + 1, N)``, from ``numpy.random.default_rng([2, seed])``.

    Examples
    --------
    >>> d = random_draws(0, 3, 5)
    >>> d.shape, sorted(d[0].tolist())
    ((4, 5), [0, 1, 2, 3, 4])
    """
    rng = np.random.default_rng([2, int(seed)])
    return rng.permuted(np.tile(np.arange(n_sensors), (steps + 1, 1)), axis=1)


def _random_pairs(perm, n_targets) -> np.ndarray:
    M, N = perm.shape
    labels = np.full((M, N), -1, dtype=np.int64)
    rows = np.arange(M)[:, None]
    labels[rows, perm[:, : 2 * n_targets]] = np.repeat(np.arange(n_targets), 2)
    return labels


def _prior_logdet_teams(S, x, eps) -> np.ndarray:
    from ..teams import greedy_team_picks

    picks_i, picks_l = greedy_team_picks(S, x, "logdet", eps)
    labels = np.empty(picks_i.shape, dtype=np.int64)
    np.put_along_axis(labels, picks_i, picks_l, axis=1)
    return labels


# --------------------------------------------------------------------------------------------
# Teams by the filters' information
# --------------------------------------------------------------------------------------------


def _information_gain(criterion, j00, j01, j11, hx, hy):
    """The gain of adding the row ``h = (hx, hy)`` to the information ``J = [[j00, j01], [j01,
    j11]]`` (broadcasting): :math:`\\log\\det`, :math:`-\\operatorname{tr} J^{-1}` or
    :math:`\\lambda_{\\min}` of :math:`J + h h^T` minus that of :math:`J`, each from a
    closed form without cancellation (so a gain that is zero, such as a first row's
    :math:`\\lambda_{\\min}` gain on an isotropic ``J``, is exactly zero):
    :math:`\\log(1 + q)` and :math:`h^T J^{-2} h / (1 + q)` with :math:`q = h^T J^{-1} h`
    (Sherman-Morrison), and for :math:`\\lambda_{\\min}`
    :math:`2 h^T (\\operatorname{adj} J - \\lambda_{\\min} I) h / ((\\lambda_{\\max} -
    \\lambda_{\\min}) + \\lvert h \\rvert^2 + (\\mu_{\\max} - \\mu_{\\min}))` with
    :math:`\\mu` the eigenvalues of :math:`J + h h^T`.

    Examples
    --------
    >>> import numpy as np
    >>> J, h = np.array([[2.0, 0.5], [0.5, 1.0]]), np.array([0.3, -0.7])
    >>> new = J + np.outer(h, h)
    >>> got = [float(_information_gain(c, 2.0, 0.5, 1.0, 0.3, -0.7)) for c in
    ...        ("d-optimal-teams", "a-optimal-teams", "e-optimal-teams")]
    >>> inv = np.linalg.inv
    >>> want = [np.log(np.linalg.det(new) / np.linalg.det(J)),
    ...         np.trace(inv(J)) - np.trace(inv(new)),
    ...         np.linalg.eigvalsh(new)[0] - np.linalg.eigvalsh(J)[0]]
    >>> bool(np.allclose(got, want, rtol=1e-12))
    True
    """
    det = j00 * j11 - j01 * j01
    ux, uy = (j11 * hx - j01 * hy) / det, (j00 * hy - j01 * hx) / det  # J^{-1} h
    q = hx * ux + hy * uy
    if criterion == "d-optimal-teams":
        return np.log1p(q)
    if criterion == "a-optimal-teams":
        return (ux * ux + uy * uy) / (1.0 + q)
    half = 0.5 * (j00 - j11)
    r = np.hypot(half, j01)  # (lambda_max - lambda_min) / 2
    # adj J - lambda_min I = [[r - half, -j01], [-j01, r + half]], a rank-one square
    big = r + np.abs(half)
    small = np.where(big > 0, j01 * j01 / np.where(big > 0, big, 1.0), 0.0)
    m00 = np.where(half >= 0, small, big)
    m11 = np.where(half >= 0, big, small)
    root = np.sqrt(m00) * hx - np.sign(j01) * np.sqrt(m11) * hy
    n00, n01, n11 = j00 + hx * hx, j01 + hx * hy, j11 + hy * hy
    spread = 2.0 * r + (hx * hx + hy * hy) + 2.0 * np.hypot(0.5 * (n00 - n11), n01)
    return np.where(spread > 0, 2.0 * root * root / np.where(spread > 0, spread, 1.0), 0.0)


def _information_teams(S, x, Ppred, r, measurement, criterion) -> np.ndarray:
    """The greedy on the filters' information (module docstring) for ``M`` runs: labels
    ``(M, N)``. ``Ppred`` ``(M, L, 2, 2)`` is the predicted covariance :math:`\\Sigma + Q`."""
    from .kalman import measurement_rows

    M, L = x.shape[:2]
    N = S.shape[1]
    H, _ = measurement_rows(x.reshape(M * L, 2),
                            np.broadcast_to(S[:, None], (M, L, N, 2)).reshape(M * L, N, 2),
                            measurement)  # (M L, N, 2)
    H = H.reshape(M, L, N, 2).transpose(0, 2, 1, 3) / np.sqrt(r)  # (M, N, L, 2)
    hx, hy = H[..., 0], H[..., 1]
    p00, p01, p11 = Ppred[..., 0, 0], 0.5 * (Ppred[..., 0, 1] + Ppred[..., 1, 0]), Ppred[..., 1, 1]
    dp = p00 * p11 - p01 * p01
    j00, j01, j11 = p11 / dp, -p01 / dp, p00 / dp  # (M, L): the prior information
    rows = np.arange(M)

    def gains(ms, l):
        return _information_gain(criterion, j00[ms, l][:, None], j01[ms, l][:, None],
                                 j11[ms, l][:, None], hx[ms, :, l], hy[ms, :, l])

    g = np.empty((M, N, L))
    for l in range(L):
        g[:, :, l] = gains(rows, np.full(M, l))
    free = np.ones((M, N), dtype=bool)
    labels = np.empty((M, N), dtype=np.int64)
    for _ in range(N):
        masked = np.where(free[:, :, None], g, -np.inf).reshape(M, -1)
        i, l = np.divmod(masked.argmax(axis=1), L)  # C order: smallest sensor, then target
        labels[rows, i] = l
        free[rows, i] = False
        bx, by = hx[rows, i, l], hy[rows, i, l]
        j00[rows, l] += bx * bx
        j01[rows, l] += bx * by
        j11[rows, l] += by * by
        g[rows, :, l] = gains(rows, l)
    return labels


# --------------------------------------------------------------------------------------------
# The chooser of a pass, and one assignment by hand
# --------------------------------------------------------------------------------------------


class TeamChooser:
    """The assignments of ``R`` runs at once: row ``r`` follows ``kinds[r]`` (a name of
    :data:`ASSIGNMENTS`) among the sensors ``sensors[r % B]`` (``(B, N, 2)``: one set per
    scene, ``B`` 1 or the number of noise tables), with the parameters of ``setup``;
    ``seeds[r]`` draws the ``"random"`` rows' permutations, unless ``draws`` gives them (a
    ``(steps, N)`` table per noise table, row ``r`` taking ``draws[r % B]``). Calling it with
    the estimates ``x``
    ``(R, L, 2)``, covariances ``P`` ``(R, L, 2, 2)`` and the step ``k`` (0-based) returns the
    labels ``(R, N)``: the target each sensor measures at step ``k + 1`` (-1: none)."""

    def __init__(self, setup, kinds, seeds=None, sensors=None, draws=None):
        self.setup = setup
        self.S = setup.sensor_array[None] if sensors is None else np.asarray(sensors)
        kinds = np.asarray(kinds, dtype=object)
        self.groups = [(name, np.flatnonzero(kinds == name)) for name in ASSIGNMENTS
                       if (kinds == name).any()]
        self.draws = None
        rows = np.flatnonzero(kinds == "random")
        if rows.size:
            # given permutations (one table per noise table, row r uses draws[r % B]), or drawn
            self.draws = {int(r): (random_draws(seeds[r], setup.steps, setup.n_sensors)
                                   if draws is None else draws[r % len(draws)]) for r in rows}
        self.Q = np.asarray(setup.Q, dtype=float)

    def __call__(self, x, P, k: int) -> np.ndarray:
        su = self.setup
        R_, L = x.shape[:2]
        B, N = self.S.shape[:2]
        labels = np.empty((R_, N), dtype=np.int64)
        maha = su.metric == "mahalanobis"
        for name, rows in self.groups:
            xs, Ps, S = x[rows], P[rows], self.S[rows % B]
            if name == "unique-pairs":
                labels[rows] = _unique_pairs(S, xs, Ps, su.u_max, maha)
            elif name == "d-optimal-pairs":
                labels[rows] = _gain_pairs(S, xs, Ps + self.Q, su.R, su.measurement)
            elif name == "optimal-pairs":
                labels[rows] = _optimal_pairs(S, xs, Ps, su.u_max, maha)
            elif name == "random":
                perm = np.stack([self.draws[int(r)][k] for r in rows])
                labels[rows] = _random_pairs(perm, L)
            elif name.startswith("logdet-teams") and name != "logdet-teams-prior":
                picked, won = logdet_labels(S, xs, exact=name == "logdet-teams-exact")
                labels[rows] = won if name == "logdet-teams-as-run" else picked
            elif name == "logdet-teams-prior":
                labels[rows] = _prior_logdet_teams(S, xs, su.eps)
            else:
                labels[rows] = _information_teams(S, xs, Ps + self.Q, su.R, su.measurement,
                                                  name)
        return labels


def check_assignment(setup, assignment: str) -> str:
    """``assignment`` if it is a name of :data:`ASSIGNMENTS` that ``setup`` can run: the pair
    assignments need two free sensors per target (``N >= 2 L``)."""
    as_choice(assignment, ASSIGNMENTS, "assignment")
    if assignment in PAIR_ASSIGNMENTS and setup.n_sensors < 2 * setup.n_targets:
        raise ValueError(
            f"assignment {assignment!r} gives every target a pair of its own: it needs at least "
            f"two free sensors per target, N >= 2 L = {2 * setup.n_targets}, but the setup has "
            f"N = {setup.n_sensors} sensors for L = {setup.n_targets} targets"
        )
    return assignment


def assign_targets(setup, assignment: str, xhat, cov, seed: int = 0, step: int = 0):
    """One step's assignment: the target each sensor serves at the estimates ``xhat`` with
    covariances ``cov`` (what :func:`~obslib.tracking.simulate_targets` does at each step).

    Parameters
    ----------
    setup : TargetsSetup
    assignment : str
        A name of :data:`ASSIGNMENTS`.
    xhat : array_like, shape (L, 2)
        The targets' estimates.
    cov : array_like, shape (L, 2, 2) or (2, 2)
        Their covariances (before the step's prediction).
    seed, step : int
        The run's seed and the step (0-based) of a ``"random"`` assignment's draw.

    Returns
    -------
    ndarray of int, shape (N,)
        The target of each sensor, -1 for a sensor left out.

    Examples
    --------
    The later experiment's first step, from its initial estimates:

    >>> from obslib import tracking
    >>> su = tracking.LATER_MULTI_TARGET
    >>> x, cov = su.estimate0, su.cov0
    >>> tracking.assign_targets(su, "unique-pairs", x, cov).tolist()
    [0, 2, -1, 1, 2, -1, 0, 1]
    >>> tracking.assign_targets(su, "logdet-teams-exact", x, cov).tolist()
    [0, 0, 0, 0, 0, 0, 0, 0]
    """
    from .._validate import as_covariances, as_points
    from .setup import MAX_COV_SCALE, TargetsSetup

    as_instance(setup, TargetsSetup, "setup")
    check_assignment(setup, assignment)
    L = setup.n_targets
    x = as_points(as_float_array(xhat, "xhat"), "xhat")
    if x.shape != (L, 2) or not np.isfinite(x).all():
        raise ValueError(f"xhat must hold {L} finite estimates, shape ({L}, 2), got {x.shape}")
    c = as_covariances(cov, L, MAX_COV_SCALE)
    seed = as_int(seed, "seed", 0)
    step = as_int(step, "step", 0)
    if step > setup.steps:
        raise ValueError(f"step must be at most the setup's {setup.steps} steps, got {step}")
    d = x[:, None, :] - setup.sensor_array[None]
    if (d == 0).all(axis=-1).any():
        l, i = (int(v) for v in np.argwhere((d == 0).all(axis=-1))[0])
        raise ValueError(f"xhat: estimate {l} sits on sensor {i}")
    chooser = TeamChooser(setup, [assignment], [seed])
    return chooser(x[None], np.array(c)[None], step)[0]

"""Assigning teams of sensors to targets (Section IV-B, Problem 2).

Each sensor serves at most one target; target ``l`` values its team ``S_l`` with a Theorem 8
measure ``w_l(S_l)`` of ``O^T O + eps I`` (:mod:`obslib.measures`). For monotone submodular
``w_l`` the greedy below is a 1/2-approximation of the submodular welfare problem
(Fisher, Nemhauser and Wolsey; the paper's reference for it is Nemhauser et al. 1978).

``greedy_team_assignment``
    Each round gives the free sensor with the largest marginal gain to its target.
``optimal_team_assignment``
    Exhaustive search over all assignments, for tiny instances (tests and the 1/2 check).
"""

from __future__ import annotations

from itertools import product

import numpy as np

from ._kernels import lambda_max, measure_from_tr_det, pow2_scale
from ._validate import (
    as_eps,
    as_float_array,
    as_measure_name,
    as_points,
    as_rank_rtol,
    check_maximisable,
)
from .bounds import relative_vectors
from .measures import MEASURES, RANK_RTOL, measure_from_vectors, subset_masks

__all__ = [
    "greedy_team_assignment",
    "greedy_team_picks",
    "greedy_team_counts",
    "optimal_team_assignment",
    "best_team_labelling",
    "team_value",
    "MAXIMISABLE",
]

#: Measures that can only increase as sensors join a team (the greedy maximises one of these).
MAXIMISABLE = ("trace", "logdet", "rank", "neg_trace_inverse")

#: Largest instance :func:`optimal_team_assignment` enumerates, as the number of assignments.
MAX_ASSIGNMENTS = 2_000_000


def _scene_iv(sensors, targets, u):
    """The validated vectors ``o_l - p_i`` ``(N, L, 2)`` and the controls ``(L, 2)`` (finite) or
    ``None``."""
    v = relative_vectors(sensors, targets)  # (N, L, 2), validated
    if u is None:
        return v, None
    uu = as_float_array(u, "u")
    try:
        uu = np.broadcast_to(uu, (v.shape[1], 2))
    except ValueError:
        raise ValueError(
            f"u must have shape (2,) or ({v.shape[1]}, 2), got {uu.shape}"
        ) from None
    return v, as_points(uu, "u")


def _teams_iv(sensors, targets, measure, eps, u, rank_rtol, maximisable: bool) -> tuple:
    """``eps`` and the measure (one the greedy can maximise when ``maximisable``), ``rank_rtol``,
    then the scene (:func:`_scene_iv`) with at least one target: ``(v, uu, measure, eps,
    rank_rtol)``."""
    e = as_eps(eps)
    if maximisable:
        check_maximisable(measure, e, MEASURES, MAXIMISABLE)
    else:
        as_measure_name(measure, MEASURES)
    rank_rtol = as_rank_rtol(rank_rtol)
    v, uu = _scene_iv(sensors, targets, u)
    if maximisable and v.shape[1] < 1:
        raise ValueError("there must be at least one target")
    return v, uu, measure, e, rank_rtol


def greedy_team_assignment(sensors, targets, measure: str = "logdet", eps: float = 1.0, u=None,
                           rank_rtol: float = RANK_RTOL) -> list:
    """Greedy for Problem 2: repeatedly give the best free sensor to the target it helps most.

    Each round evaluates, for every free sensor ``i`` and target ``l``, the marginal gain
    ``w_l(S_l + i) - w_l(S_l)`` and takes the largest (ties: smallest ``i``, then smallest
    ``l``); it stops when every sensor is assigned. ``w_l`` is a Theorem 8 measure of
    ``G_l = O_l^T O_l + eps I`` (rows ``o_l - p_i`` of the team, and ``u`` if given). Only the
    chosen target's gains change between rounds; they are updated from the trace and the
    Cauchy-Binet determinant ``det(A + v v^T) = det A + sum_k (v x r_k)^2`` over the team's rows
    ``r_k``, a sum of non-negative terms that is exact for parallel rows (so ``rank`` is decided
    reliably); each sensor's sum is accumulated as the team grows, so a round costs ``O(N)``.
    The same code runs a batch of instances at once (:func:`greedy_team_counts`).

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
    targets : array_like, shape (L, 2)
    measure : str
        ``"logdet"`` (default, the paper's Fig. 9), ``"trace"``, ``"rank"`` or
        ``"neg_trace_inverse"``.
    eps : float
        Prior information ``eps I``; must be positive for ``logdet`` and ``neg_trace_inverse``,
        whose value is infinite for a team of fewer than two sensors otherwise.
    u : array_like, shape (2,) or (L, 2), optional
        A fixed known control row per target.

    Returns
    -------
    list of list of int
        The team of each target, sensors in the order they were assigned.

    Examples
    --------
    >>> S, T = [[0, 0], [2, 0], [10, 0], [12, 0]], [[1, 1], [11, 1]]
    >>> greedy_team_assignment(S, T, "rank")
    [[0, 1], [2, 3]]
    """
    v, uu, measure, e, rank_rtol = _teams_iv(sensors, targets, measure, eps, u, rank_rtol, True)
    picks_i, picks_l = _greedy_teams(
        v[None], uu[None] if uu is not None else None, measure, e, rank_rtol
    )
    teams: list[list[int]] = [[] for _ in range(v.shape[1])]
    for i, l in zip(picks_i[0].tolist(), picks_l[0].tolist()):
        teams[l].append(i)
    return teams


def greedy_team_picks(sensors, targets, measure: str = "logdet", eps: float = 1.0,
                      rank_rtol: float = RANK_RTOL) -> tuple[np.ndarray, np.ndarray]:
    """The picks of :func:`greedy_team_assignment` for a batch of instances, in the order made.

    ``sensors`` ``(K, N, 2)`` and ``targets`` ``(K, L, 2)``, each instance validated as in
    :func:`greedy_team_assignment`; the instances run together, round by round, with the same
    arithmetic, so each instance's picks equal the single-instance call's (the tests compare them).

    Returns
    -------
    (ndarray, ndarray), each of shape (K, N)
        Round ``r`` of instance ``k`` gave sensor ``picks_i[k, r]`` to target ``picks_l[k, r]``.

    Examples
    --------
    With ``rank``, sensor 0 gains 1 for either target (tie: target 0), sensor 1 then completes
    target 0's rank (gain 1; tie with target 1 again to target 0), and sensors 2, 3 gain only
    at target 1:

    >>> S, T = [[0, 0], [2, 0], [10, 0], [12, 0]], [[1, 1], [11, 1]]
    >>> picks_i, picks_l = greedy_team_picks([S], [T], "rank")
    >>> picks_i.tolist(), picks_l.tolist()
    ([[0, 1, 2, 3]], [[0, 0, 1, 1]])
    """
    v, measure, e, rank_rtol = _greedy_team_picks_iv(sensors, targets, measure, eps, rank_rtol)
    if v.shape[0] == 0:
        return np.zeros((0, v.shape[1]), np.int64), np.zeros((0, v.shape[1]), np.int64)
    return _greedy_teams(v, None, measure, e, rank_rtol)


def _greedy_team_picks_iv(sensors, targets, measure, eps, rank_rtol) -> tuple:
    """A maximisable measure, ``eps`` and ``rank_rtol``, and the validated vectors of every
    instance ``(K, N, L, 2)``, ``L >= 1``: ``(v, measure, eps, rank_rtol)``."""
    e = as_eps(eps)
    check_maximisable(measure, e, MEASURES, MAXIMISABLE)
    rank_rtol = as_rank_rtol(rank_rtol)
    S, T = as_float_array(sensors, "sensors"), as_float_array(targets, "targets")
    if S.ndim != 3 or T.ndim != 3 or S.shape[0] != T.shape[0]:
        raise ValueError(
            f"need sensors (K, N, 2) and targets (K, L, 2), got {S.shape} and {T.shape}"
        )
    if T.shape[1] < 1:
        raise ValueError("there must be at least one target")
    if S.shape[0] == 0:
        return np.zeros((0, S.shape[1], T.shape[1], 2)), measure, e, rank_rtol
    return _batch_vectors(S, T), measure, e, rank_rtol  # validated, (K, N, L, 2)


def _batch_vectors(S, T) -> np.ndarray:
    """``relative_vectors(S[k], T[k])`` of every instance, ``(K, N, L, 2)``.

    The differences of the whole batch at once, and the validation's checks (finite points and
    differences, distinct sensors, no sensor on a target) as a few array tests; only a batch that
    fails one goes instance by instance through :func:`obslib.bounds.relative_vectors`, which
    then raises its message (Fig. 9's 930 scenes: 0.01 s against 0.08 s one by one).
    """
    if S.ndim == 3 and T.ndim == 3 and S.shape[2] == 2 and T.shape[2] == 2:
        with np.errstate(over="ignore", invalid="ignore"):
            v = T[:, None, :, :] - S[:, :, None, :]
        n = S.shape[1]
        if (np.isfinite(S).all() and np.isfinite(T).all() and np.isfinite(v).all()
                and not (v == 0).all(axis=-1).any()
                and (S[:, :, None, :] == S[:, None, :, :]).all(axis=-1).sum() == S.shape[0] * n):
            return v
    return np.stack([relative_vectors(s, t) for s, t in zip(S, T)])


def greedy_team_counts(sensors, targets, measure: str = "logdet", eps: float = 1.0,
                       rank_rtol: float = RANK_RTOL) -> np.ndarray:
    """Team sizes of :func:`greedy_team_assignment` for a batch of instances, shape ``(K, L)``
    (from :func:`greedy_team_picks`, same arguments).

    Examples
    --------
    >>> S, T = [[0, 0], [2, 0], [10, 0], [12, 0]], [[1, 1], [11, 1]]
    >>> greedy_team_counts([S], [T], "rank")
    array([[2, 2]])
    """
    v, measure, e, rank_rtol = _greedy_team_picks_iv(sensors, targets, measure, eps, rank_rtol)
    n_targets = v.shape[2]
    picks_l = (_greedy_teams(v, None, measure, e, rank_rtol)[1] if v.shape[0]
               else np.zeros((0, v.shape[1]), np.int64))
    return (
        np.stack([np.bincount(p, minlength=n_targets) for p in picks_l])
        if len(picks_l)
        else np.zeros((0, n_targets), int)
    )


def _greedy_teams(v, uu, measure, e, rank_rtol):
    """The greedy of :func:`greedy_team_assignment` on a batch: ``v`` ``(K, N, L, 2)``, ``uu``
    ``(K, L, 2)`` or None. Returns the picked sensors and targets, each ``(K, N)``, in order.

    Each instance is computed in a unit of a power of two that keeps its rows (and ``eps``, a
    squared length) inside the safe range: 1 at ordinary scales (the arithmetic is then exactly
    the plain one); the picks do not depend on the unit. Every instance's picks are checked to
    use each sensor exactly once: teams come back valid or not at all.
    """
    top = np.abs(v).max(axis=(1, 2, 3), initial=0.0)
    if uu is not None:
        top = np.maximum(top, np.abs(uu).max(axis=(1, 2), initial=0.0))
    p = pow2_scale(top if measure == "rank" else np.maximum(top, np.sqrt(e)))  # rank: no eps
    if (p == p[:1]).all() if p.size else True:
        c = float(p[0]) if p.size else 1.0
        if c == 1.0:
            picks = _greedy_teams_unit(v, uu, measure, e, rank_rtol)
        else:
            if measure in ("logdet", "neg_trace_inverse") and e / c / c < 2.0**-1000:
                raise ValueError(
                    f"eps = {e!r} is negligible against the squared distances (distances about "
                    f"{c:.3g}): the {measure!r} gains of teams of fewer than two sensors "
                    "underflow; scale eps with the squared unit of length "
                    "(e.g. eps = 1e-6 * distance**2)"
                )
            picks = _greedy_teams_unit(
                v / c, None if uu is None else uu / c, measure, e / c / c, rank_rtol
            )
    else:  # instances in different units: one at a time
        parts = [
            _greedy_teams(
                v[q : q + 1], None if uu is None else uu[q : q + 1], measure, e, rank_rtol
            )
            for q in range(v.shape[0])
        ]
        picks = tuple(np.concatenate([part[z] for part in parts]) for z in (0, 1))
    n = v.shape[1]
    if n and not (np.sort(picks[0], axis=1) == np.arange(n)).all():
        raise RuntimeError("the greedy team assignment used a sensor twice (non-finite gains?)")
    return picks


def _greedy_teams_unit(v, uu, measure, e, rank_rtol):
    k, n, n_targets, _ = v.shape
    vx, vy = v[..., 0], v[..., 1]  # (K, N, L)
    # Per instance and target: tr and det of the team's A = sum r r^T, and for every sensor the
    # Cauchy-Binet increment C = sum over the team's rows r of (v x r)^2 (det(A + v v^T) = det + C).
    if uu is not None:
        tr = uu[..., 0] * uu[..., 0] + uu[..., 1] * uu[..., 1]
        cross = vx * uu[:, None, :, 1] - vy * uu[:, None, :, 0]
        C = cross * cross
    else:
        tr = np.zeros((k, n_targets))
        C = np.zeros((k, n, n_targets))
    det = np.zeros((k, n_targets))

    def value(tr_, det_):
        return measure_from_tr_det(measure, tr_, det_, lambda_max(tr_, det_), e, rank_rtol)

    g = value(tr[:, None, :] + vx * vx + vy * vy, det[:, None, :] + C) - value(tr, det)[:, None, :]
    if np.isnan(g).any():
        raise RuntimeError("a marginal gain of the greedy team assignment is NaN")
    rows = np.arange(k)
    free = np.ones((k, n), dtype=bool)
    picks_i = np.empty((k, n), dtype=np.int64)
    picks_l = np.empty((k, n), dtype=np.int64)
    for r in range(n):
        masked = np.where(free[:, :, None], g, -np.inf).reshape(k, -1)
        i, l = np.divmod(np.argmax(masked, axis=1), n_targets)  # C order: smallest i, then l
        picks_i[:, r], picks_l[:, r] = i, l
        free[rows, i] = False
        xi, yi = vx[rows, i, l], vy[rows, i, l]
        det[rows, l] = det[rows, l] + C[rows, i, l]
        tr[rows, l] = tr[rows, l] + xi * xi + yi * yi
        xl, yl = vx[rows, :, l], vy[rows, :, l]  # (K, N): every sensor's row for the chosen target
        cross = xl * yi[:, None] - yl * xi[:, None]
        C[rows, :, l] = C[rows, :, l] + cross * cross
        t_l, d_l = tr[rows, l], det[rows, l]
        g[rows, :, l] = (
            value(t_l[:, None] + xl * xl + yl * yl, d_l[:, None] + C[rows, :, l])
            - value(t_l, d_l)[:, None]
        )
    return picks_i, picks_l


def team_value(sensors, targets, teams, measure: str = "logdet", eps: float = 1.0, u=None,
               rank_rtol: float = RANK_RTOL) -> float:
    """Total ``sum_l w_l(S_l)`` of an assignment of teams (each sensor in at most one team).

    Examples
    --------
    >>> S, T = [[0, 0], [2, 0], [10, 0], [12, 0]], [[1, 1], [11, 1]]
    >>> team_value(S, T, [[0, 1], [2, 3]], "rank")  # both teams have rank 2
    4.0
    """
    v, uu, measure, e, rank_rtol, teams = _team_value_iv(sensors, targets, teams, measure, eps,
                                                         u, rank_rtol)
    total = 0.0
    for l, team in enumerate(teams):
        mask = np.zeros((1, v.shape[0]), dtype=bool)
        mask[0, list(team)] = True
        uu_l = uu[l] if uu is not None else None
        total += float(measure_from_vectors(v[:, l, :], mask, measure, e, uu_l, rank_rtol)[0])
    return total


def _team_value_iv(sensors, targets, teams, measure, eps, u, rank_rtol) -> tuple:
    """:func:`_teams_iv` (any measure), and one team per target of distinct sensors in range."""
    v, uu, measure, e, rank_rtol = _teams_iv(sensors, targets, measure, eps, u, rank_rtol, False)
    if len(teams) != v.shape[1]:
        raise ValueError(f"need one team per target ({v.shape[1]}), got {len(teams)}")
    members = [i for t in teams for i in t]
    if len(members) != len(set(members)) or any(not 0 <= i < v.shape[0] for i in members):
        raise ValueError("teams must use distinct sensor indices in range")
    return v, uu, measure, e, rank_rtol, teams


def optimal_team_assignment(sensors, targets, measure: str = "logdet", eps: float = 1.0, u=None,
                            rank_rtol: float = RANK_RTOL):
    """Problem 2 solved by exhaustive search: every way to give each sensor to one target.

    Feasible for tiny instances only (``L^N`` assignments, at most ``MAX_ASSIGNMENTS``). Sensors
    are all assigned, which loses nothing for the monotone measures of :data:`MAXIMISABLE`.

    Returns
    -------
    (list of list of int, float)
        An optimal assignment (the first in lexicographic order of the label vector) and its value.

    Examples
    --------
    >>> S, T = [[0, 0], [2, 0], [10, 0], [12, 0]], [[1, 1], [11, 1]]
    >>> optimal_team_assignment(S, T, "rank")
    ([[0, 1], [2, 3]], 4.0)
    """
    v, uu, measure, e, rank_rtol = _optimal_team_assignment_iv(sensors, targets, measure, eps,
                                                               u, rank_rtol)
    n, n_targets = v.shape[0], v.shape[1]
    masks = subset_masks(n)
    tables = np.stack(
        [
            measure_from_vectors(
                v[:, l, :], masks, measure, e, uu[l] if uu is not None else None, rank_rtol
            )
            for l in range(n_targets)
        ]
    )  # (L, 2^N), subset k = bitmask k
    labels, total = best_team_labelling(tables)
    teams = [[int(i) for i in np.flatnonzero(labels == l)] for l in range(n_targets)]
    return teams, float(total)


def _optimal_team_assignment_iv(sensors, targets, measure, eps, u, rank_rtol) -> tuple:
    """:func:`_teams_iv` (any measure), at least one target, and few enough assignments."""
    v, uu, measure, e, rank_rtol = _teams_iv(sensors, targets, measure, eps, u, rank_rtol, False)
    if v.shape[1] < 1:
        raise ValueError("there must be at least one target")
    _check_assignments(v.shape[0], v.shape[1])
    return v, uu, measure, e, rank_rtol


def best_team_labelling(tables) -> tuple[np.ndarray, np.ndarray]:
    """Problem 2 by exhaustive search over given team values: the best way to give each sensor to
    one target.

    Parameters
    ----------
    tables : array_like, shape (L, ..., 2**N)
        ``tables[l, ..., k]`` is target ``l``'s value ``w_l(S)`` of the team ``S`` whose sensors
        are the set bits of ``k`` (:func:`obslib.measures.subset_masks` order), for one instance
        or a batch (the middle axes). ``-inf`` is allowed, NaN is not.

    Returns
    -------
    labels : ndarray of int, shape (..., N)
        The target of each sensor in a best assignment, the first in lexicographic order of
        ``labels`` among the ``L^N`` assignments (at most ``MAX_ASSIGNMENTS``).
    total : ndarray, shape (...)
        Its value ``sum_l w_l(S_l)``.

    Examples
    --------
    Two sensors, two targets: target 0 values sensor 0 most, target 1 sensor 1.

    >>> labels, total = best_team_labelling([[0, 3, 1, 3], [0, 1, 2, 2]])
    >>> labels.tolist(), float(total)
    ([0, 1], 5.0)
    """
    t, n = _best_team_labelling_iv(tables)
    n_targets = t.shape[0]
    labels, team_masks = _labellings(n, n_targets)
    total = np.zeros(t.shape[1:-1] + (team_masks.shape[1],))
    for l, mask in enumerate(team_masks):
        total += t[l][..., mask]
    if np.isnan(total).any():
        raise RuntimeError("an assignment's total is NaN")
    best = np.argmax(total, axis=-1)
    return labels[best], np.take_along_axis(total, best[..., None], axis=-1)[..., 0]


def _best_team_labelling_iv(tables) -> tuple:
    """Tables ``(L, ..., 2**N)``, ``L >= 1``, without NaN and with few enough assignments, and
    ``N``."""
    t = as_float_array(tables, "tables")
    if t.ndim < 2 or t.shape[0] < 1:
        raise ValueError(f"tables must have shape (L, ..., 2**N) with L >= 1, got {t.shape}")
    n = int(t.shape[-1]).bit_length() - 1
    if t.shape[-1] != 1 << n:
        raise ValueError(
            f"the last axis of tables must have 2**N entries (one per team), got {t.shape[-1]}"
        )
    if np.isnan(t).any():
        raise ValueError("tables has a NaN entry")
    _check_assignments(n, t.shape[0])
    return t, n


def _check_assignments(n: int, n_targets: int) -> None:
    if n_targets**n > MAX_ASSIGNMENTS:
        raise ValueError(
            f"{n_targets}^{n} assignments is too many to enumerate (max {MAX_ASSIGNMENTS})"
        )


def _labellings(n: int, n_targets: int):
    """Every way to give each of ``n`` sensors to one of ``n_targets`` targets.

    Returns ``labels`` ``(A, N)`` (the target of each sensor, in lexicographic order) and
    ``team_masks`` ``(L, A)``: the bitmask of target ``l``'s team in each assignment.
    """
    labels = np.array(list(product(range(n_targets), repeat=n)), dtype=np.int64).reshape(
        n_targets**n, n
    )
    bits = 1 << np.arange(n, dtype=np.int64)
    return labels, np.stack([((labels == l) * bits).sum(axis=1) for l in range(n_targets)])

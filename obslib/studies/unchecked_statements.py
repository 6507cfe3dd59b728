"""Statements of the paper that it does not check itself: the notebook that shows them.

Most computations live in one module per topic (:mod:`obslib.studies.replay`,
:mod:`obslib.studies.greedy_tightness`, :mod:`obslib.studies.eq4`,
:mod:`obslib.studies.hardness`, :mod:`obslib.studies.fig9_measure`,
:mod:`obslib.studies.experiment_details`). This module names the notebook that
shows them (:data:`NOTEBOOK`) and holds the two small studies of statements about sensors and
teams:

- :func:`one_sensor_conditioning`: footnote 1 says that Theorems 2 and 3 show at least two
  sensors to be necessary when the measure is the inverse condition number. With a known
  control, one sensor's :math:`C^{-1}(O(o, u_o))` is not 0;
- :func:`team_constraint`: the introduction says that there is no restriction on the number of
  targets assigned to a sensor, while Problem 2 allows at most one. Without that constraint a
  monotone measure would put every sensor on every target;
- :func:`problem3_relaxations`: Fig. 8's relaxation with unordered pairs (Problem 3 as printed)
  and with ordered pairs (the authors' code), on Fig. 8's instances.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .._validate import as_eps, as_float_array, as_int, as_ints, as_nonnegative, as_positive
from ..bounds import relative_vectors
from ..observability import inverse_condition_number
from ..teams import greedy_team_assignment
from .general_assignment import fig9_geometry
from .greedy_vs_relaxed import fig8_sweep

__all__ = ["NOTEBOOK", "one_sensor_best", "one_sensor_conditioning",
           "team_constraint", "problem3_relaxations"]

NOTEBOOK = "11_unchecked_statements"


def one_sensor_best(distance, u_max):
    r"""The largest :math:`C^{-1}(O(o, u_o))` of one sensor at ``distance`` over the disc
    :math:`\lVert u_o\rVert \le u_{\max}`: :math:`\min(u_{\max}, d) / d`.

    With rows :math:`r = o - p` and :math:`u`, :math:`O^T O = r r^T + u u^T` has trace
    :math:`d^2 + b^2` and determinant :math:`d^2 b^2 \sin^2\phi` (:math:`b = \lVert u\rVert`,
    :math:`\phi` the angle between them); the ratio of its eigenvalues is largest at
    :math:`\phi = \pi/2`, where they are :math:`d^2` and :math:`b^2`, so the best control is
    perpendicular to :math:`r` with :math:`b = \min(u_{\max}, d)`.

    Examples
    --------
    >>> from obslib.studies.unchecked_statements import one_sensor_best
    >>> one_sensor_best([0.5, 2.0], 1.0).tolist()
    [1.0, 0.5]
    """
    d = as_float_array(distance, "distance")
    u_max = as_nonnegative(u_max, "u_max")
    if not (np.isfinite(d).all() and (d > 0).all()):
        raise ValueError("distances must be positive and finite")
    return np.minimum(u_max, d) / d


def one_sensor_conditioning(n_scenes: int, seed: int = 0, u_max: float = 1.0,
                            side: float = 3.0) -> dict:
    r"""One sensor and a target with a known control (footnote 1 of Sec. II).

    ``n_scenes`` scenes: the sensor and the target uniform in :math:`[0, \mathrm{side}]^2`, a
    control uniform in the disc :math:`\lVert u\rVert \le u_{\max}`. Theorem 2 says the *lower
    bound* (the worst case over the unknown control) is 0; the exact
    :math:`C^{-1}(O(o, u_o))` (:func:`obslib.inverse_condition_number`) with the control known
    is not.

    Returns
    -------
    dict
        ``exact`` (per scene, with the drawn control), ``best`` (per scene, the largest value over
        the disc, :func:`one_sensor_best`), ``share_above_half`` (scenes whose exact value exceeds
        1/2). Computed once per arguments (cached).

    Examples
    --------
    >>> from obslib.studies.unchecked_statements import one_sensor_conditioning
    >>> r = one_sensor_conditioning(50, seed=0)
    >>> bool((r["exact"] <= r["best"] + 1e-12).all()), float(r["best"].max())
    (True, 1.0)
    """
    if isinstance(n_scenes, bool) or not isinstance(n_scenes, (int, np.integer)) or n_scenes < 1:
        raise ValueError(f"n_scenes must be a positive integer, got {n_scenes!r}")
    return _one_sensor_conditioning(int(n_scenes), as_int(seed, "seed", 0),
                                    as_nonnegative(u_max, "u_max"), as_positive(side, "side"))


@lru_cache(maxsize=4)
def _one_sensor_conditioning(n_scenes: int, seed: int, u_max: float, side: float) -> dict:
    rng = np.random.default_rng([int(seed), 11])
    exact = np.empty(int(n_scenes))
    dist = np.empty(int(n_scenes))
    for k in range(int(n_scenes)):
        p, o = rng.uniform(0, side, (1, 2)), rng.uniform(0, side, 2)
        r, phi = u_max * np.sqrt(rng.uniform()), rng.uniform(0, 2 * np.pi)
        exact[k] = inverse_condition_number(p, o, [r * np.cos(phi), r * np.sin(phi)])
        dist[k] = float(np.hypot(*(o - p[0])))
    best = one_sensor_best(dist, u_max)
    return {"exact": exact, "best": best, "share_above_half": float(np.mean(exact > 0.5))}


def _logdet(rows, eps):
    G = eps * np.eye(2) + rows.T @ rows
    return float(np.linalg.slogdet(G)[1])


def team_constraint(N_values, trials: int, seed: int = 0, n_targets: int = 5, eps: float = 1.0,
                    side: float = 100.0) -> dict:
    r"""Problem 2 with and without its constraint "each sensor on at most one target".

    On the instances of Fig. 9 (:func:`obslib.studies.general_assignment.fig9_geometry`) the
    greedy team assignment (:func:`obslib.greedy_team_assignment`, measure
    :math:`\log\det(O^T O + \varepsilon I)`) gives every sensor one target. Without the
    constraint, a monotone measure is largest when every sensor serves every target; the
    function reports both totals.

    Returns
    -------
    dict
        Per ``N`` (lists in the order of ``N_values``): ``targets_per_sensor`` (the largest
        number of targets any sensor serves), ``team_min`` and ``team_max`` (team sizes),
        ``constrained`` and ``unconstrained`` (mean totals over the trials). Computed once per
        arguments (cached).

    Examples
    --------
    >>> from obslib.studies.unchecked_statements import team_constraint
    >>> r = team_constraint([10], trials=2)
    >>> r["targets_per_sensor"], r["constrained"][0] < r["unconstrained"][0]
    ([1], True)
    """
    N_values = as_ints(N_values, "N_values", 0)
    trials, seed = as_int(trials, "trials", 1), as_int(seed, "seed", 0)
    n_targets, eps = as_int(n_targets, "n_targets", 1), as_eps(eps)
    side = as_positive(side, "side")
    return _team_constraint(tuple(N_values), trials, seed, n_targets, eps, side)


@lru_cache(maxsize=4)
def _team_constraint(N_values, trials, seed, n_targets, eps, side) -> dict:
    out = {k: [] for k in ("targets_per_sensor", "team_min", "team_max", "constrained",
                           "unconstrained")}
    for n in N_values:
        per_sensor, lo, hi, con, unc = 0, n, 0, [], []
        for t in range(int(trials)):
            S, T = fig9_geometry(n, t, seed, n_targets, side)
            teams = greedy_team_assignment(S, T, "logdet", eps)
            served = np.bincount([i for team in teams for i in team], minlength=n)
            per_sensor = max(per_sensor, int(served.max()))
            sizes = [len(team) for team in teams]
            lo, hi = min(lo, min(sizes)), max(hi, max(sizes))
            v = relative_vectors(S, T)  # (N, L, 2)
            con.append(sum(_logdet(v[team, l], eps) for l, team in enumerate(teams)))
            unc.append(sum(_logdet(v[:, l], eps) for l in range(n_targets)))
        out["targets_per_sensor"].append(per_sensor)
        out["team_min"].append(lo)
        out["team_max"].append(hi)
        out["constrained"].append(float(np.mean(con)))
        out["unconstrained"].append(float(np.mean(unc)))
    return out


def problem3_relaxations(L_values, trials: int, seed: int = 0, u_max: float = 1.0) -> dict:
    """The relaxed optimum of Fig. 8 with unordered pairs (Problem 3 as printed) and with ordered
    pairs (the authors' code), on Fig. 8's instances
    (:func:`obslib.studies.greedy_vs_relaxed.fig8_sweep`), computed once per arguments (cached)
    for the chapter and the ledger.

    Returns
    -------
    dict
        ``L`` and, shape ``(len(L_values), trials)``, ``relaxed`` (unordered), ``relaxed_ordered``
        and ``excess`` (ordered over unordered, minus 1).

    Examples
    --------
    >>> from obslib.studies.unchecked_statements import problem3_relaxations
    >>> r = problem3_relaxations([1, 2], trials=3)
    >>> r["L"].tolist(), bool((r["excess"] >= -1e-12).all())
    ([1, 2], True)
    """
    L_values = as_ints(L_values, "L_values", 1)
    return _problem3_relaxations(tuple(L_values), as_int(trials, "trials", 1),
                                 as_int(seed, "seed", 0), as_nonnegative(u_max, "u_max"))


@lru_cache(maxsize=4)
def _problem3_relaxations(L_values, trials, seed, u_max) -> dict:
    s = fig8_sweep(list(L_values), trials, seed, u_max)
    return {"L": s["L"], "relaxed": s["relaxed"], "relaxed_ordered": s["relaxed_ordered"],
            "excess": s["relaxed_ordered"] / s["relaxed"] - 1}

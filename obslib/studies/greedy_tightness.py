"""How tight Theorem 6's 1/3 is on geometric instances, and how fragile the tight geometry is.

On random instances Algorithm 1 is near-optimal (notebook 03), but a local search over sensor and
target positions (:func:`obslib.studies.greedy_unique_pairs.worst_instance_search`) finds geometries
where it collects only about 0.34 of the optimum, close to the 1/3 guarantee. There the greedy's
first pick outweighs each of the three optimal triples it blocks by a small relative margin
(:func:`first_pick_margin`). :func:`jitter_ratios` measures how fragile this is: it moves every
point by Gaussian noise of standard deviation ``fraction * spread`` (``spread``: the root mean
square distance of the points from their centroid) and recomputes greedy / optimum.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .._validate import as_float_array, as_int, as_nonnegative, as_points
from ..assignment import greedy_pair_assignment, optimal_pair_assignment
from ..bounds import pair_bounds
from .batch_optimum import batch_pair_bounds, greedy_values, optimal_values
from .greedy_unique_pairs import charging, worst_instance_search

__all__ = ["tight_geometry", "TIGHT_SENSORS", "TIGHT_TARGETS", "TIGHT_U_MAX", "tight_witness",
           "spread", "first_pick_margin", "jitter_ratios", "witness_jitter_ratios",
           "jitter_summary"]

#: The tightest geometry the local search of :func:`tight_geometry` found at the paper's sizes
#: of notebook 03 (6 sensors, 3 targets, seed 0, 20 starts of 300 steps, ``u_max = 1``): there
#: Algorithm 1 collects 0.342 of the optimum. Stored (coordinates to full precision) so that every
#: profile re-evaluates the same witness instead of a search whose reach depends on its size.
TIGHT_SENSORS = (
    (-8.339475832238582, 21.333329564370416), (64.72094335661477, 99.157249837481),
    (39.61034811004262, 43.51023246911406), (84.70587194428593, 35.837367987404996),
    (124.99538781982929, 29.11427016069306), (74.21790067526166, 37.57831261060378),
)
TIGHT_TARGETS = (
    (90.1622910661433, 15.429663498738591), (40.59857605412964, 43.31311799183185),
    (-0.016777723790030175, 48.51374451326523),
)
TIGHT_U_MAX = 1.0


def tight_witness():
    """The stored tight geometry: ``(sensors (6, 2), targets (3, 2))``, fresh arrays.

    Examples
    --------
    >>> S, T = tight_witness()
    >>> round(first_pick_margin(S, T, TIGHT_U_MAX)["ratio"], 3)
    0.342
    """
    return np.array(TIGHT_SENSORS), np.array(TIGHT_TARGETS)


def tight_geometry(n_sensors: int = 6, n_targets: int = 3, seed: int = 0, n_starts: int = 20,
                   n_steps: int = 300, u_max: float = 1.0):
    """The worst geometry the local search of notebook 03 finds (Theorem 6, Sec. IV-A).

    Returns
    -------
    (float, ndarray, ndarray)
        Greedy / optimum there, the sensors ``(N, 2)`` and the targets ``(L, 2)``.

    Examples
    --------
    Theorem 6 guarantees at least 1/3 of the optimum:

    >>> from obslib.studies.greedy_tightness import tight_geometry
    >>> ratio, sensors, targets = tight_geometry(n_starts=1, n_steps=5)
    >>> sensors.shape, targets.shape, 1 / 3 <= ratio <= 1
    ((6, 2), (3, 2), True)
    """
    n_sensors, n_targets = as_int(n_sensors, "n_sensors", 1), as_int(n_targets, "n_targets", 1)
    n_starts, n_steps = as_int(n_starts, "n_starts", 1), as_int(n_steps, "n_steps", 0)
    seed, u_max = as_int(seed, "seed", 0), as_nonnegative(u_max, "u_max")
    if n_sensors < 2 * n_targets:
        raise ValueError(f"need n_sensors >= 2 n_targets, got {n_sensors} and {n_targets}")
    r, S, T = worst_instance_search(n_sensors, n_targets, seed, n_starts, n_steps, u_max)
    return r, S.copy(), T.copy()


def spread(sensors, targets) -> float:
    """Root mean square distance of all points (sensors and targets) from their centroid.

    Examples
    --------
    Points at distances 1, 1 and 0 from their centroid:

    >>> from obslib.studies.greedy_tightness import spread
    >>> round(spread([[0.0, 0.0], [2.0, 0.0]], [[1.0, 0.0]]) ** 2, 12)
    0.666666666667
    """
    P = np.vstack([as_points(sensors, "sensors"), as_points(targets, "targets")])
    if P.shape[0] == 0:
        raise ValueError("sensors and targets are both empty")
    return float(np.sqrt(((P - P.mean(axis=0)) ** 2).sum(axis=1).mean()))


def first_pick_margin(sensors, targets, u_max: float = 1.0) -> dict:
    """The greedy's first pick against the optimal triples it blocks (Theorem 6's charging).

    Returns
    -------
    dict
        ``pick`` and ``w`` (the greedy's first triple and weight), ``blocked`` (the optimal
        triples sharing a sensor or the target with it) and their weights ``blocked_w``,
        ``relative_margin`` ``(w - max(blocked_w)) / w``, ``ratio`` greedy / optimum.

    Examples
    --------
    The greedy takes the heaviest triple first, so the margin is not negative:

    >>> import numpy as np
    >>> from obslib.studies.greedy_tightness import first_pick_margin
    >>> rng = np.random.default_rng(1)
    >>> S, T = rng.uniform(0, 10, (6, 2)), rng.uniform(0, 10, (3, 2))
    >>> m = first_pick_margin(S, T)
    >>> m["relative_margin"] >= 0, 1 / 3 <= m["ratio"] <= 1
    (True, True)
    """
    W = pair_bounds(sensors, targets, u_max)
    g, o = greedy_pair_assignment(W), optimal_pair_assignment(W)
    rounds = charging(W, g.triples, o.triples)
    first = rounds[0]
    top = max(first["charged_w"]) if first["charged_w"] else 0.0
    return {
        "pick": first["pick"],
        "w": first["w"],
        "blocked": first["charged"],
        "blocked_w": first["charged_w"],
        "relative_margin": (first["w"] - top) / first["w"],
        "ratio": g.value / o.value,
    }


def _ratio_batch(S, T, u_max):
    W, valid = batch_pair_bounds(S, T, u_max)
    W[~valid] = 0.0
    opt = optimal_values(W)
    g = greedy_values(W)
    ok = valid & (opt > 0)
    return np.where(ok, g / np.where(ok, opt, 1.0), np.nan)


def jitter_ratios(sensors, targets, fractions, n_draws: int, seed: int = 0, u_max: float = 1.0):
    """Greedy / optimum after jittering every point by ``N(0, (fraction * spread)^2)``.

    Parameters
    ----------
    sensors, targets : array_like, shapes (N, 2), (L, 2)
    fractions : sequence of float
        Jitter sizes as fractions of :func:`spread`.
    n_draws : int
        Draws per fraction (one generator of ``seed``, fraction after fraction).

    Returns
    -------
    ndarray, shape (len(fractions), n_draws)
        The ratio per draw (NaN for the zero-probability draws where points coincide).

    Examples
    --------
    Without jitter every draw is the ratio of the geometry itself:

    >>> import numpy as np
    >>> from obslib.studies.greedy_tightness import (first_pick_margin,
    ...                                              jitter_ratios)
    >>> rng = np.random.default_rng(1)
    >>> S, T = rng.uniform(0, 10, (6, 2)), rng.uniform(0, 10, (3, 2))
    >>> r = jitter_ratios(S, T, [0.0, 0.1], n_draws=3)
    >>> r.shape, bool(np.allclose(r[0], first_pick_margin(S, T)["ratio"]))
    ((2, 3), True)
    """
    S = as_float_array(sensors, "sensors")
    T = as_float_array(targets, "targets")
    if S.ndim != 2 or S.shape[1] != 2 or T.ndim != 2 or T.shape[1] != 2:
        raise ValueError(f"need sensors (N, 2) and targets (L, 2), got {S.shape} and {T.shape}")
    if S.shape[0] < 2 * T.shape[0] or T.shape[0] < 1:
        raise ValueError(
            f"need at least one target and N >= 2 L, got N = {S.shape[0]}, L = {T.shape[0]}"
        )
    if not (np.isfinite(S).all() and np.isfinite(T).all()):
        raise ValueError("sensor and target positions must be finite")
    f = as_float_array(fractions, "fractions").reshape(-1)
    if f.size == 0 or not np.isfinite(f).all() or (f < 0).any():
        raise ValueError(f"fractions must be non-negative finite numbers, got {fractions!r}")
    if isinstance(n_draws, bool) or not isinstance(n_draws, (int, np.integer)) or n_draws < 1:
        raise ValueError(f"n_draws must be a positive integer, got {n_draws!r}")
    rng = np.random.default_rng(seed)
    sd = spread(S, T)
    n, m = S.shape[0], S.shape[0] + T.shape[0]
    P = np.vstack([S, T])
    out = np.empty((f.size, int(n_draws)))
    for a, frac in enumerate(f):
        Q = P[None] + rng.normal(0.0, frac * sd, size=(int(n_draws), m, 2))
        out[a] = _ratio_batch(Q[:, :n], Q[:, n:], u_max)
    return out


def witness_jitter_ratios(fractions, n_draws: int, seed: int = 0) -> np.ndarray:
    """:func:`jitter_ratios` of the stored witness (:func:`tight_witness`, ``u_max`` =
    :data:`TIGHT_U_MAX`), cached on the arguments (the array returned is read-only), so that
    the chapter and the ledger share one computation.

    Examples
    --------
    >>> from obslib.studies.greedy_tightness import witness_jitter_ratios
    >>> witness_jitter_ratios([1e-3], n_draws=4).shape
    (1, 4)
    """
    f = tuple(float(x) for x in as_float_array(fractions, "fractions").reshape(-1))
    if isinstance(n_draws, bool) or not isinstance(n_draws, (int, np.integer)) or n_draws < 1:
        raise ValueError(f"n_draws must be a positive integer, got {n_draws!r}")
    return _witness_jitter(f, int(n_draws), as_int(seed, "seed", 0))


@lru_cache(maxsize=4)
def _witness_jitter(fractions, n_draws, seed):
    out = jitter_ratios(*tight_witness(), list(fractions), n_draws, seed, TIGHT_U_MAX)
    out.setflags(write=False)
    return out


def jitter_summary(ratios, fractions) -> list[dict]:
    """Per fraction: median, 5 % and 95 % quantiles, min, and the share of draws below 1/2.

    Examples
    --------
    >>> from obslib.studies.greedy_tightness import jitter_summary
    >>> row = jitter_summary([[0.5, 1.0, 0.75]], [0.1])[0]
    >>> row["median"], row["min"], row["below_half"], round(row["q05"], 12)
    (0.75, 0.5, 0.0, 0.525)
    """
    r = as_float_array(ratios, "ratios")
    f = as_float_array(fractions, "fractions")
    if r.ndim != 2 or f.shape != (r.shape[0],) or not np.isfinite(f).all():
        raise ValueError(f"ratios (F, D) and fractions (F,) must match, got {r.shape}, {f.shape}")
    if not all(np.isfinite(row).any() for row in r):
        raise ValueError("ratios must hold a finite value for every fraction")
    rows = []
    for frac, row in zip(f, r):
        v = row[np.isfinite(row)]
        rows.append({
            "fraction": float(frac),
            "median": float(np.median(v)),
            "q05": float(np.quantile(v, 0.05)),
            "q95": float(np.quantile(v, 0.95)),
            "min": float(v.min()),
            "below_half": float(np.mean(v < 0.5)),
        })
    return rows

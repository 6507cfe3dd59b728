"""Fig. 9 with the paper's literal measure, log det(O^T O), and the book's log det(O^T O + eps I).

Section V-D runs the greedy team assignment with "log determinant of the symmetric observability
matrix", built from the sensors' rows only. For a team of fewer than two sensors that matrix is
singular and its log det is ``-inf``, so the greedy's first gains are ``-inf - (-inf)``, which is
undefined (NaN in floating point). The greedy is then decided by how the maximum treats NaN.
:func:`literal_logdet_counts` evaluates the literal measure exactly (the determinant by
Cauchy-Binet, ``det sum r r^T = sum_{a<b} (r_a x r_b)^2``, so a single row gives exactly 0) and
resolves NaN gains by a stated rule:

``"ignore"``
    NaN gains are skipped and, when every gain is NaN, the first (sensor, target) is taken: what
    MATLAB's ``max`` does, and the order of the paper's sensors and targets.
``"first"``
    A NaN counts as the largest gain and the first one is taken: what ``numpy.argmax`` does.
"""

from __future__ import annotations

import numpy as np

from . import teams as ts
from ..bounds import relative_vectors

__all__ = ["NAN_RULES", "literal_logdet_counts", "literal_fig9_sweep"]

NAN_RULES = ("ignore", "first")


def _value(det):
    with np.errstate(divide="ignore"):
        return np.where(det > 0, np.log(np.where(det > 0, det, 1.0)), -np.inf)


def literal_logdet_counts(sensors, targets, nan: str = "ignore") -> np.ndarray:
    """Team sizes of the greedy (Problem 2) with the literal measure ``log det(O_l^T O_l)``.

    Each round gives the free sensor with the largest gain ``w_l(S_l + i) - w_l(S_l)`` to its
    target (ties: smallest sensor, then smallest target), ``w_l = log det`` of the team's rows
    ``o_l - p_i`` (no control row, no prior), evaluated exactly; see the module docstring for
    ``nan``.

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
    targets : array_like, shape (L, 2)
    nan : {"ignore", "first"}

    Returns
    -------
    ndarray of int, shape (L,)

    Examples
    --------
    Under ``"ignore"`` every first gain is NaN, the first target gets a sensor, then every
    further gain on the first target is :math:`+\\\\infty`: all sensors join one team.

    >>> import numpy as np
    >>> from obslib.studies.fig9_measure import literal_logdet_counts
    >>> rng = np.random.default_rng(0)
    >>> S, T = rng.uniform(0, 10, (4, 2)), rng.uniform(0, 10, (2, 2))
    >>> literal_logdet_counts(S, T).tolist()
    [4, 0]
    """
    if nan not in NAN_RULES:
        raise ValueError(f"nan must be one of {NAN_RULES}, got {nan!r}")
    v = relative_vectors(sensors, targets)  # validated, (N, L, 2)
    n, n_targets = v.shape[0], v.shape[1]
    if n_targets < 1:
        raise ValueError("there must be at least one target")
    det = np.zeros(n_targets)
    C = np.zeros((n, n_targets))  # Cauchy-Binet increment of adding sensor i to team l
    free = np.ones(n, dtype=bool)
    counts = np.zeros(n_targets, dtype=int)
    for _ in range(n):
        with np.errstate(invalid="ignore"):
            g = _value(det[None, :] + C) - _value(det)[None, :]  # (N, L); -inf - -inf = NaN
        g[~free] = -np.inf
        flat = g.reshape(-1)
        isnan = np.isnan(flat)
        if nan == "first" and isnan.any():
            k = int(np.flatnonzero(isnan)[0])
        elif (~isnan & (flat > -np.inf)).any() or not isnan.any():
            k = int(np.argmax(np.where(isnan, -np.inf, flat)))
        else:  # every gain of a free sensor is NaN: the first free (sensor, target)
            k = int(np.flatnonzero(isnan)[0])
        i, l = divmod(k, n_targets)
        free[i] = False
        counts[l] += 1
        det[l] += C[i, l]
        cross = v[:, l, 0] * v[i, l, 1] - v[:, l, 1] * v[i, l, 0]
        C[:, l] += cross * cross
    return counts


def literal_fig9_sweep(N_values, trials: int, seed: int, n_targets: int = 5, side: float = 100.0,
                       nan: str = "ignore") -> np.ndarray:
    """Counts ``(len(N_values), trials, L)`` of the Fig. 9 sweep with the literal measure.

    The geometries are those of :func:`obslib.studies.teams.fig9_sweep` (same seeds), so the two
    measures are compared on the same instances.

    Examples
    --------
    >>> from obslib.studies.fig9_measure import literal_fig9_sweep
    >>> counts = literal_fig9_sweep([6, 8], trials=2, seed=0)
    >>> counts.shape, counts.sum(axis=2).tolist()
    ((2, 2, 5), [[6, 6], [8, 8]])
    """
    if nan not in NAN_RULES:
        raise ValueError(f"nan must be one of {NAN_RULES}, got {nan!r}")
    N_values = [int(n) for n in N_values]
    out = np.empty((len(N_values), int(trials), int(n_targets)), dtype=int)
    for a, n in enumerate(N_values):
        for t in range(int(trials)):
            S, T = ts.fig9_geometry(n, t, seed, n_targets, side)
            out[a, t] = literal_logdet_counts(S, T, nan)
    return out

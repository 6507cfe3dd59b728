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

from functools import lru_cache

import numpy as np

from .._validate import as_int, as_ints, as_positive, as_real, as_str
from ..bounds import relative_vectors
from .general_assignment import fig9_geometry, fig9_sweep

__all__ = ["NAN_RULES", "FIG9_U_MAX", "CONTROL_DIRECTIONS", "literal_logdet_counts",
           "literal_fig9_sweep", "control_row_fig9_sweep", "fig9_measure_sweeps"]

NAN_RULES = ("ignore", "first")

#: The norm of the control row ``u_o`` of the text's measure in the sweeps of Fig. 9: the paper
#: never states the control (nor ``u_max``) of Fig. 9; 1 is the ``u_max`` of its other
#: assignment experiment, Fig. 8.
FIG9_U_MAX = 1.0

#: The directions of the control row tried (radians, the same for every target); ``None`` draws
#: a direction per target (:func:`control_row_fig9_sweep`). ``u_o u_o^T`` is the same for
#: ``u_o`` and ``-u_o``, so these cover the half-turn.
CONTROL_DIRECTIONS = (None, 0.0, np.pi / 4, np.pi / 2, 3 * np.pi / 4)


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
    if as_str(nan, "nan") not in NAN_RULES:
        raise ValueError(f"nan must be one of {NAN_RULES}, got {nan!r}")
    v = relative_vectors(sensors, targets)  # validated, (N, L, 2)
    if v.shape[1] < 1:
        raise ValueError("there must be at least one target")
    return _counts(v[None], np.array([v.shape[0]]), np.array([nan == "first"]))[0]


def _counts(v, n_sensors, first, start=None) -> np.ndarray:
    """:func:`literal_logdet_counts` of ``B`` instances at once, ``(B, L)``.

    ``v`` is ``(B, N_max, L, 2)``, instance ``b`` using its first ``n_sensors[b]`` rows (the rest
    start as taken and are never chosen); ``first[b]`` selects the ``"first"`` NaN rule. Round by
    round every instance does what the single-instance greedy does, on the same elementwise
    values in the same (sensor, target) order, so the counts are those of one instance at a time
    (the 1860 greedies of Fig. 9's two literal sweeps in 0.25 s against 3.4 s one by one).
    ``start`` (``(B, L, 2)``), when given, is a row every team holds from the outset (a control
    row ``u_o``): it is never counted, but enters every determinant.
    """
    B, n_max, n_targets = v.shape[0], v.shape[1], v.shape[2]
    rows = np.arange(B)
    det = np.zeros((B, n_targets))
    C = np.zeros((B, n_max, n_targets))  # Cauchy-Binet increment of adding sensor i to team l
    if start is not None:  # every team starts with one row: det 0, increments (u x r)^2
        cross0 = v[..., 0] * start[:, None, :, 1] - v[..., 1] * start[:, None, :, 0]
        C += cross0 * cross0
    vdet = _value(det)  # (B, L)
    vnew = _value(C)  # _value(det + C), kept column by column as teams change
    free = np.arange(n_max)[None, :] < n_sensors[:, None]
    counts = np.zeros((B, n_targets), dtype=int)
    for r in range(int(n_sensors.max(initial=0))):
        with np.errstate(invalid="ignore"):
            g = vnew - vdet[:, None, :]  # (B, N, L); -inf - -inf = NaN
        g[~free] = -np.inf
        flat = g.reshape(B, -1)
        isnan = np.isnan(flat)
        any_nan = isnan.any(axis=1)
        first_nan = np.argmax(isnan, axis=1)
        masked = np.where(isnan, -np.inf, flat)
        best = np.argmax(masked, axis=1)
        any_real = (masked > -np.inf).any(axis=1)
        # "first": the first NaN if any; "ignore": the largest real gain, else the first NaN
        k = np.where(np.where(first, any_nan, ~any_real & any_nan), first_nan, best)
        act = rows[r < n_sensors]  # instances still choosing
        i, l = np.divmod(k[act], n_targets)
        free[act, i] = False
        counts[act, l] += 1
        det[act, l] += C[act, i, l]
        vl = v[act, :, l, :]  # (B', N, 2): team l's rows of each instance
        vi = v[act, i, l, :]  # (B', 2): the chosen row
        cross = vl[..., 0] * vi[:, None, 1] - vl[..., 1] * vi[:, None, 0]
        C[act, :, l] += cross * cross
        vdet[act, l] = _value(det[act, l])
        vnew[act, :, l] = _value(det[act, l][:, None] + C[act, :, l])
    return counts


def literal_fig9_sweep(N_values, trials: int, seed: int, n_targets: int = 5, side: float = 100.0,
                       nan: str = "ignore") -> np.ndarray:
    """Counts ``(len(N_values), trials, L)`` of the Fig. 9 sweep with the literal measure.

    The geometries are those of :func:`obslib.studies.general_assignment.fig9_sweep` (same seeds),
    so the two measures are compared on the same instances.

    Examples
    --------
    >>> from obslib.studies.fig9_measure import literal_fig9_sweep
    >>> counts = literal_fig9_sweep([6, 8], trials=2, seed=0)
    >>> counts.shape, counts.sum(axis=2).tolist()
    ((2, 2, 5), [[6, 6], [8, 8]])
    """
    if as_str(nan, "nan") not in NAN_RULES:
        raise ValueError(f"nan must be one of {NAN_RULES}, got {nan!r}")
    N_values = as_ints(N_values, "N_values", 0)
    trials, n_targets = as_int(trials, "trials", 1), as_int(n_targets, "n_targets", 1)
    seed, side = as_int(seed, "seed", 0), as_positive(side, "side")
    n_max = max(N_values, default=0)
    v = np.zeros((len(N_values), trials, n_max, n_targets, 2))
    for a, n in enumerate(N_values):
        for t in range(trials):
            S, T = fig9_geometry(n, t, seed, n_targets, side)
            v[a, t, :n] = relative_vectors(S, T)
    n_sensors = np.repeat(np.array(N_values, dtype=int), trials)
    out = _counts(
        v.reshape(-1, n_max, n_targets, 2), n_sensors, np.full(n_sensors.size, nan == "first")
    )
    return out.reshape(len(N_values), trials, n_targets)


def control_row_fig9_sweep(N_values, trials: int, seed: int, n_targets: int = 5,
                           side: float = 100.0, u_max: float = 1.0,
                           direction: float | None = None) -> np.ndarray:
    """Counts ``(len(N_values), trials, L)`` of the Fig. 9 sweep with the measure the text of
    Sec. V-D names, ``log det O(o, u_o)^T O(o, u_o)``: the team's rows and a control row ``u_o``.

    Each target gets a control of norm ``u_max``: in the direction ``direction`` (an angle in
    radians, the same for every target) when it is given, else in a direction drawn uniformly
    from ``default_rng([seed, N, trial, 1])`` for each target (the geometries are those of
    :func:`obslib.studies.general_assignment.fig9_sweep`). With the control row a team of one
    sensor is non-singular unless its row is parallel to ``u_o``, so the first gains are
    ``log((u x r)^2) - (-inf) = +inf``; ties are resolved as in :func:`literal_logdet_counts`
    (the first in (sensor, target) order), and the determinants are exact (Cauchy-Binet with the
    control row in every team).

    Examples
    --------
    The first rounds give each target one sensor (every first gain is infinite):

    >>> from obslib.studies.fig9_measure import control_row_fig9_sweep
    >>> counts = control_row_fig9_sweep([10], trials=3, seed=0)
    >>> counts.shape, bool((counts >= 1).all()), counts.sum(axis=2).tolist()
    ((1, 3, 5), True, [[10, 10, 10]])

    Every target's control along the x axis:

    >>> control_row_fig9_sweep([10], trials=3, seed=0, direction=0.0).shape
    (1, 3, 5)
    """
    N_values = as_ints(N_values, "N_values", 0)
    trials, n_targets = as_int(trials, "trials", 1), as_int(n_targets, "n_targets", 1)
    seed, side = as_int(seed, "seed", 0), as_positive(side, "side")
    u_max = as_positive(u_max, "u_max")
    if direction is not None:
        direction = as_real(direction, "direction")
    n_max = max(N_values, default=0)
    v = np.zeros((len(N_values), trials, n_max, n_targets, 2))
    u = np.zeros((len(N_values), trials, n_targets, 2))
    for a, n in enumerate(N_values):
        for t in range(trials):
            S, T = fig9_geometry(n, t, seed, n_targets, side)
            v[a, t, :n] = relative_vectors(S, T)
            if direction is None:
                phi = np.random.default_rng([seed, n, t, 1]).uniform(0, 2 * np.pi, n_targets)
            else:
                phi = np.full(n_targets, direction)
            u[a, t] = u_max * np.column_stack([np.cos(phi), np.sin(phi)])
    n_sensors = np.repeat(np.array(N_values, dtype=int), trials)
    out = _counts(v.reshape(-1, n_max, n_targets, 2), n_sensors,
                  np.zeros(n_sensors.size, dtype=bool), u.reshape(-1, n_targets, 2))
    return out.reshape(len(N_values), trials, n_targets)


def fig9_measure_sweeps(N_min: int, N_max: int, trials: int, seed: int, n_targets: int = 5,
                        eps: float = 1.0, side: float = 100.0,
                        u_max: float = FIG9_U_MAX) -> dict:
    """Fig. 9's sweep (``N = N_min..N_max``) with every measure the book compares, on the same
    instances, computed once (cached on the arguments) for the chapters and the ledger.

    Returns
    -------
    dict
        Counts ``(len(N), trials, L)`` per measure: ``"prior"``, the book's
        ``log det(O^T O + eps I)`` (:func:`obslib.studies.general_assignment.fig9_sweep`);
        ``"code"``, the authors' ``log det(O^T O)`` with undefined gains skipped
        (``nan="ignore"``, what their code's arithmetic does) and ``"code-first"`` with the first
        undefined gain taken; and ``"text"``: direction -> the text's measure with a control row
        of norm ``u_max`` in that direction, for each of :data:`CONTROL_DIRECTIONS`.

    Examples
    --------
    >>> from obslib.studies.fig9_measure import fig9_measure_sweeps
    >>> s = fig9_measure_sweeps(8, 9, trials=2, seed=0)
    >>> sorted(k for k in s if k != "text"), s["prior"].shape, len(s["text"])
    (['code', 'code-first', 'prior'], (2, 2, 5), 5)
    >>> fig9_measure_sweeps(8, 9, trials=2, seed=0) is s  # computed once
    True
    """
    N_min, N_max = as_int(N_min, "N_min", 1), as_int(N_max, "N_max", 1)
    if N_max < N_min:
        raise ValueError(f"N_max must be at least N_min, got {N_min} and {N_max}")
    return _fig9_measure_sweeps(N_min, N_max, as_int(trials, "trials", 1),
                                as_int(seed, "seed", 0), as_int(n_targets, "n_targets", 1),
                                as_positive(eps, "eps"), as_positive(side, "side"),
                                as_positive(u_max, "u_max"))


@lru_cache(maxsize=4)
def _fig9_measure_sweeps(N_min, N_max, trials, seed, n_targets, eps, side, u_max) -> dict:
    Ns = list(range(N_min, N_max + 1))
    return {
        "prior": fig9_sweep(Ns, trials, seed, n_targets, "logdet", eps, side),
        "code": literal_fig9_sweep(Ns, trials, seed, n_targets, side, nan="ignore"),
        "code-first": literal_fig9_sweep(Ns, trials, seed, n_targets, side, nan="first"),
        "text": {d: control_row_fig9_sweep(Ns, trials, seed, n_targets, side, u_max, d)
                 for d in CONTROL_DIRECTIONS},
    }

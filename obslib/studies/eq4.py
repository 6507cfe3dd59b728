"""Section III's observability matrix as derived (Eq. (4)), against its rewriting (Eq. (5)).

Section III computes the local nonlinear observability matrix with the Lie derivatives of every
measurement ``h_i`` (Eq. (4)): each sensor contributes its gradient row ``o - p_i``, a row
``u_o`` (the first Lie derivative's gradient) and zero rows. It then "rewrites" the matrix as
Eq. (5), ``[o - p_1; ...; o - p_N; u_o]``, keeping a single ``u_o`` row. The two have the same
rank, but not the same singular values: the derived matrix has
``O_d^T O_d = O(o)^T O(o) + N u u^T``, so ``u`` weighs ``sqrt(N)`` times as much. Theorem 1
bounds ``C^{-1}`` of Eq. (5); for the derived matrix the same argument gives the bound with
``u_max`` replaced by ``sqrt(N) u_max``:

.. math::

    \\min_{\\|u\\| \\le u_{\\max}} C^{-1}(O_d) = \\sqrt{\\frac{\\lambda_{\\min}}{\\lambda_{\\max}
    + N u_{\\max}^2}} < \\sqrt{\\frac{\\lambda_{\\min}}{\\lambda_{\\max} + u_{\\max}^2}}
    \\quad (N \\ge 2,\\ u_{\\max} > 0),

with ``lambda`` the eigenvalues of ``O(o)^T O(o)``, attained at ``u = u_max v_max``. The ratio of
the two is ``sqrt((lambda_max + u_max^2) / (lambda_max + N u_max^2))``, which tends to
``1 / sqrt(N)`` as ``lambda_max / u_max^2 -> 0``.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .._validate import as_float_array, as_int, as_nonnegative
from ..bounds import lower_bound, lower_bounds, pair_bounds
from ..observability import relative_rows

__all__ = [
    "derived_matrix",
    "derived_inverse_condition",
    "derived_bound",
    "worst_derived_on_disc",
    "bound_ratio",
    "random_scenes",
    "bound_ratios",
    "pair_choice_changes",
    "AUDIT_SIDES",
    "random_scene_audit",
]


def _u_max(u_max) -> float:
    try:
        v = float(u_max)
    except (TypeError, ValueError):
        raise ValueError(f"u_max must be a non-negative number, got {u_max!r}") from None
    if not np.isfinite(v) or v < 0:
        raise ValueError(f"u_max must be a non-negative finite number, got {u_max!r}")
    return v


def _control(u) -> np.ndarray:
    try:
        a = as_float_array(u, "u")
    except (TypeError, ValueError):
        raise ValueError(f"u must be a 2-vector, got {u!r}") from None
    if a.shape != (2,) or not np.isfinite(a).all():
        raise ValueError(f"u must be a finite 2-vector, got {u!r}")
    return a


def derived_matrix(sensors, target, u) -> np.ndarray:
    """The observability matrix as Section III derives it (Eq. (4)), zero rows dropped.

    Rows ``o - p_1, u, o - p_2, u, ..., o - p_N, u``: each sensor's zeroth and first Lie
    derivative gradients (the higher ones are zero). Shape ``(2N, 2)``.

    Examples
    --------
    >>> import numpy as np
    >>> from obslib.studies import eq4
    >>> sensors, target = np.array([[0.0, 0.0], [2.0, 0.0]]), np.array([1.0, 1.0])
    >>> eq4.derived_matrix(sensors, target, [0.5, 0.0]).tolist()
    [[1.0, 1.0], [0.5, 0.0], [-1.0, 1.0], [0.5, 0.0]]
    """
    rows = relative_rows(sensors, target)
    uu = _control(u)
    out = np.empty((2 * rows.shape[0], 2))
    out[0::2], out[1::2] = rows, uu
    return out


def derived_inverse_condition(sensors, target, u) -> float:
    """``sigma_min / sigma_max`` of :func:`derived_matrix` (by SVD).

    Examples
    --------
    Orthogonal rows of equal length and a static target: :math:`C^{-1} = 1`.

    >>> import numpy as np
    >>> from obslib.studies import eq4
    >>> sensors, target = np.array([[0.0, 0.0], [2.0, 0.0]]), np.array([1.0, 1.0])
    >>> round(eq4.derived_inverse_condition(sensors, target, [0.0, 0.0]), 12)
    1.0
    """
    sv = np.linalg.svd(derived_matrix(sensors, target, u), compute_uv=False)
    return float(sv[-1] / sv[0]) if sv[0] > 0 else 0.0


def derived_bound(sensors, target, u_max) -> float:
    """The worst case of :func:`derived_inverse_condition` over ``||u|| <= u_max``.

    Theorem 1's argument applied to ``O(o)^T O(o) + N u u^T``: ``sqrt(lambda_min / (lambda_max +
    N u_max^2))`` (attained along the principal eigenvector, at full norm).

    Examples
    --------
    Here :math:`O^T O = 2 I`, so the bound is :math:`\\\\sqrt{2 / (2 + 2 u_{\\\\max}^2)}`, which the
    grid search of :func:`worst_derived_on_disc` reaches:

    >>> import numpy as np
    >>> from obslib.studies import eq4
    >>> sensors, target = np.array([[0.0, 0.0], [2.0, 0.0]]), np.array([1.0, 1.0])
    >>> d = eq4.derived_bound(sensors, target, 1.0)
    >>> bool(np.isclose(d, np.sqrt(0.5), rtol=1e-12))
    True
    >>> worst, _ = eq4.worst_derived_on_disc(sensors, target, 1.0)
    >>> bool(np.isclose(worst, np.sqrt(0.5), rtol=1e-12))
    True
    """
    rows = relative_rows(sensors, target)
    lam = np.linalg.eigvalsh(rows.T @ rows)
    return float(np.sqrt(max(lam[0], 0.0) / (lam[1] + rows.shape[0] * _u_max(u_max) ** 2)))


def worst_derived_on_disc(sensors, target, u_max, n_radii: int = 20, n_angles: int = 360):
    """Numerical minimum of :func:`derived_inverse_condition` over a polar grid of the disc.

    Returns
    -------
    (float, ndarray)
        The smallest value found and the control reaching it.

    Examples
    --------
    >>> import numpy as np
    >>> from obslib.studies import eq4
    >>> sensors, target = np.array([[0.0, 0.0], [2.0, 0.0]]), np.array([1.0, 1.0])
    >>> value, u = eq4.worst_derived_on_disc(sensors, target, 1.0, n_radii=4,
    ...                                      n_angles=8)
    >>> d = eq4.derived_bound(sensors, target, 1.0)
    >>> round(value, 12) == round(d, 12), float(np.hypot(*u))
    (True, 1.0)
    """
    um = _u_max(u_max)
    for name, v in (("n_radii", n_radii), ("n_angles", n_angles)):
        if isinstance(v, bool) or not isinstance(v, (int, np.integer)) or v < 1:
            raise ValueError(f"{name} must be a positive integer, got {v!r}")
    rows = relative_rows(sensors, target)
    r = um * np.arange(1, n_radii + 1) / n_radii
    phi = 2 * np.pi * np.arange(n_angles) / n_angles
    U = (r[:, None, None] * np.stack([np.cos(phi), np.sin(phi)], -1)[None]).reshape(-1, 2)
    U = np.vstack([np.zeros((1, 2)), U])
    G = rows.T @ rows
    n = rows.shape[0]
    M = G[None] + n * U[:, :, None] * U[:, None, :]
    lam = np.linalg.eigvalsh(M)
    vals = np.sqrt(np.maximum(lam[:, 0], 0) / lam[:, 1])
    k = int(np.argmin(vals))
    return float(vals[k]), U[k]


def bound_ratio(sensors, target, u_max) -> float:
    """Worst ``C^{-1}`` of the derived matrix over Theorem 1's bound (for Eq. (5)); ``<= 1``.

    Examples
    --------
    With :math:`O^T O = 2 I` and :math:`u_{\\\\max} = 1`: :math:`\\\\sqrt{1/2} / \\\\sqrt{2/3} =
    \\\\sqrt{3}/2`.

    >>> import numpy as np
    >>> from obslib.studies import eq4
    >>> sensors, target = np.array([[0.0, 0.0], [2.0, 0.0]]), np.array([1.0, 1.0])
    >>> r = eq4.bound_ratio(sensors, target, 1.0)
    >>> bool(np.isclose(r, np.sqrt(3) / 2, rtol=1e-12))
    True
    """
    tb = lower_bound(sensors, target, u_max)
    return derived_bound(sensors, target, u_max) / tb if tb > 0 else 1.0


def random_scenes(n_scenes: int, rng, side: float = 1.0):
    """``n_scenes`` random scenes of 2 to 6 sensors and one target, uniform in ``[0, side]^2``.

    Each scene is drawn from ``rng`` (a ``numpy.random.Generator``) in turn: its number of
    sensors ``n`` (``rng.integers(2, 7)``), the sensors (``rng.uniform(0, side, (n, 2))``), then
    the target (``rng.uniform(0, side, 2)``).

    Returns
    -------
    rows : ndarray, shape (n_scenes, 6, 2)
        The rows ``o - p_i`` of each scene, padded with zero rows (which change no singular
        value).
    counts : ndarray, shape (n_scenes,)
        The number of sensors of each scene.

    Examples
    --------
    >>> import numpy as np
    >>> from obslib.studies import eq4
    >>> rows, counts = eq4.random_scenes(3, np.random.default_rng(0))
    >>> rows.shape, bool(np.all((counts >= 2) & (counts <= 6)))
    ((3, 6, 2), True)
    """
    if isinstance(n_scenes, bool) or not isinstance(n_scenes, (int, np.integer)) or n_scenes < 1:
        raise ValueError(f"n_scenes must be a positive integer, got {n_scenes!r}")
    if not isinstance(rng, np.random.Generator):
        raise ValueError(f"rng must be a numpy.random.Generator, got {type(rng).__name__}")
    rows, counts = np.zeros((int(n_scenes), 6, 2)), np.empty(int(n_scenes), dtype=int)
    for k in range(int(n_scenes)):
        n = int(rng.integers(2, 7))
        S, o = rng.uniform(0, side, (n, 2)), rng.uniform(0, side, 2)
        rows[k, :n], counts[k] = o - S, n
    return rows, counts


def bound_ratios(rows, counts, u_max) -> tuple[np.ndarray, np.ndarray]:
    """:func:`bound_ratio` of a stack of scenes, and the ``lambda_max`` of each.

    ``rows`` and ``counts`` as :func:`random_scenes` returns them. The derived matrix's worst
    case ``sqrt(lambda_min / (lambda_max + N u_max^2))`` from the batched eigenvalues of
    ``O(o)^T O(o)``, over Theorem 1's bound by :func:`obslib.bounds.lower_bounds` (batched SVD of
    ``O(o)``); 1 where that bound is 0, as :func:`bound_ratio`.

    Returns
    -------
    ratios, lambda_max : ndarray, shape (n_scenes,)

    Examples
    --------
    >>> import numpy as np
    >>> from obslib.studies import eq4
    >>> rows, counts = eq4.random_scenes(50, np.random.default_rng(1))
    >>> ratios, lam = eq4.bound_ratios(rows, counts, 1.0)
    >>> bool(np.all(ratios <= 1) and np.all(ratios >= 1 / np.sqrt(counts)))
    True
    """
    um = _u_max(u_max)
    r = as_float_array(rows, "rows")
    n = np.asarray(counts)
    if r.ndim != 3 or r.shape[-1] != 2 or n.shape != r.shape[:1] or not np.isfinite(r).all():
        raise ValueError(f"rows must be finite (n_scenes, rows, 2) with one count per scene, "
                         f"got {r.shape} and {n.shape}")
    lam = np.linalg.eigvalsh(np.swapaxes(r, -1, -2) @ r)
    derived = np.sqrt(np.maximum(lam[:, 0], 0.0) / (lam[:, 1] + n * um**2))
    tb = lower_bounds(r, um)
    return np.where(tb > 0, derived / np.where(tb > 0, tb, 1.0), 1.0), lam[:, 1]


def pair_choice_changes(n_scenes: int, n_sensors: int, u_max: float, seed: int = 0,
                        side: float = 10.0) -> float:
    """Share of random scenes where the best pair by Theorem 4 differs between Eq. (5)
    (``u_max``) and the derived matrix (``sqrt(2) u_max``: two sensors, two ``u`` rows).

    Sensors and one target uniform in ``[0, side]^2``, Euclidean distances.

    Examples
    --------
    >>> from obslib.studies import eq4
    >>> 0.0 <= eq4.pair_choice_changes(20, 4, 1.0) <= 1.0
    True
    >>> # without motion both matrices rank pairs alike
    >>> eq4.pair_choice_changes(20, 4, 0.0)
    0.0
    """
    if isinstance(n_scenes, bool) or not isinstance(n_scenes, (int, np.integer)) or n_scenes < 1:
        raise ValueError(f"n_scenes must be a positive integer, got {n_scenes!r}")
    if isinstance(n_sensors, bool) or not isinstance(n_sensors, (int, np.integer)) or n_sensors < 2:
        raise ValueError(f"n_sensors must be an integer >= 2, got {n_sensors!r}")
    um = _u_max(u_max)
    rng = np.random.default_rng(seed)
    ii, jj = np.triu_indices(int(n_sensors), 1)
    changed = 0
    for _ in range(int(n_scenes)):
        S = rng.uniform(0, side, size=(int(n_sensors), 2))
        o = rng.uniform(0, side, size=(1, 2))
        a = pair_bounds(S, o, um)[ii, jj, 0]
        b = pair_bounds(S, o, np.sqrt(2) * um)[ii, jj, 0]
        changed += int(np.argmax(a) != np.argmax(b))
    return changed / int(n_scenes)


#: Sides of the random scenes of :func:`random_scene_audit`. The ratio of the derived matrix's
#: worst case to Theorem 1's bound depends on ``lambda_max / u_max^2``, a squared length over a
#: squared speed bound, so on the scale of the scene.
AUDIT_SIDES = (1.0, 10.0, 100.0)


def random_scene_audit(n_geometries: int, n_refine: int, seed: int, u_max: float):
    """The matrix as derived (Eq. (4)) against Eq. (5) on random scenes of 2 to 6 sensors.

    ``n_geometries`` scenes of each side of :data:`AUDIT_SIDES` give the worst case of the
    derived matrix over the disc divided by Theorem 1's bound (:func:`bound_ratio`);
    ``n_refine`` scenes of side 1 check the closed-form worst case against a grid search of the
    disc and count the scenes where the grid search falls below Theorem 1's bound.

    Returns
    -------
    ratios : dict
        Side (1.0, 10.0, 100.0) -> ``(n_geometries,)`` ratios.
    grid_err : float
        Largest grid minimum minus closed form (non-negative up to the grid).
    below : int
        Scenes where the derived matrix's worst case is below Theorem 1's bound.

    Examples
    --------
    >>> from obslib.studies.eq4 import random_scene_audit
    >>> ratios, grid_err, below = random_scene_audit(5, 3, 0, 1.0)
    >>> sorted(ratios), bool(grid_err >= -1e-12), 0 <= below <= 3
    ([1.0, 10.0, 100.0], True, True)
    """
    return _random_scene_audit(
        as_int(n_geometries, "n_geometries", 1),
        as_int(n_refine, "n_refine", 1),
        as_int(seed, "seed", 0),
        as_nonnegative(u_max, "u_max"),
    )


@lru_cache(maxsize=4)
def _random_scene_audit(n_geometries, n_refine, seed, u_max):
    rng = np.random.default_rng(seed)
    out = {side: bound_ratios(*random_scenes(n_geometries, rng, side), u_max)[0]
           for side in AUDIT_SIDES}
    # the closed-form worst case against a grid search of the disc, and against Theorem 1
    grid_err, below = 0.0, 0
    for _ in range(n_refine):
        n = int(rng.integers(2, 7))
        S, o = rng.uniform(0, 1, (n, 2)), rng.uniform(0, 1, 2)
        num, _u = worst_derived_on_disc(S, o, u_max, 10, 360)
        cf = derived_bound(S, o, u_max)
        grid_err = max(grid_err, num - cf)
        below += int(num < lower_bound(S, o, u_max) * (1 - 1e-9))
    return out, grid_err, below

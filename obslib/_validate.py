"""Input validation shared by the public functions.

Every public function of :mod:`obslib` checks its input here, at the boundary, so that
bad input fails with a :class:`ValueError` that names the offending sensor or target
instead of propagating NaN or failing deep inside NumPy (DESIGN.md, "obslib").
"""

from __future__ import annotations

import numpy as np

__all__ = [
    "as_points",
    "as_point",
    "as_u_max",
    "as_cov",
    "check_spd2",
    "check_distinct",
    "check_not_on_targets",
]


def as_points(points, name: str = "sensors", *, min_count: int = 0) -> np.ndarray:
    """Return ``points`` as a float array of shape ``(n, 2)``.

    Raises
    ------
    ValueError
        If the array is not two-dimensional with two columns, has fewer than
        ``min_count`` rows, or any coordinate is NaN or infinite (the message names
        the first offending row).
    """
    try:
        arr = np.asarray(points, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} must be numeric, shape (n, 2): {exc}") from None
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise ValueError(f"{name} must have shape (n, 2), got {arr.shape}")
    if arr.shape[0] < min_count:
        raise ValueError(f"{name} needs at least {min_count} point(s), got {arr.shape[0]}")
    bad = ~np.isfinite(arr).all(axis=1)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        singular = name[:-1] if name.endswith("s") else name
        raise ValueError(f"{singular} {k} has a non-finite coordinate: {arr[k].tolist()}")
    return arr


def as_point(point, name: str = "target") -> np.ndarray:
    """Return one point as a float array of shape ``(2,)`` (finite)."""
    try:
        arr = np.asarray(point, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} must be numeric, shape (2,): {exc}") from None
    if arr.shape != (2,):
        raise ValueError(f"{name} must have shape (2,), got {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} has a non-finite coordinate: {arr.tolist()}")
    return arr


def as_u_max(u_max, n_targets: int | None = None) -> np.ndarray:
    """Return ``u_max`` as a float array (scalar, or one value per target).

    ``u_max`` is the bound on the target's control input, ``||u_o|| <= u_max``, so it must
    be finite and non-negative. With ``n_targets`` given, a vector of that length is accepted.
    """
    try:
        arr = np.asarray(u_max, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"u_max must be a non-negative number: {exc}") from None
    if arr.ndim == 1 and n_targets is not None:
        if arr.shape[0] != n_targets:
            raise ValueError(
                f"u_max must be a scalar or have one value per target ({n_targets}), "
                f"got shape {arr.shape}"
            )
    elif arr.ndim != 0:
        raise ValueError(f"u_max must be a scalar, got shape {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"u_max must be finite, got {arr.tolist()}")
    if (arr < 0).any():
        where = "" if arr.ndim == 0 else f" for target {int(np.flatnonzero(arr < 0)[0])}"
        raise ValueError(f"u_max must be non-negative{where}, got {arr.tolist()}")
    return arr


def as_cov(cov, n_targets: int) -> np.ndarray:
    """Return covariances as an array of shape ``(L, 2, 2)``, each symmetric positive definite.

    A single ``(2, 2)`` matrix is shared by all targets.
    """
    try:
        arr = np.asarray(cov, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"cov must be numeric, shape (2, 2) or (L, 2, 2): {exc}") from None
    if arr.shape == (2, 2):
        arr = np.broadcast_to(arr, (n_targets, 2, 2))
    if arr.shape != (n_targets, 2, 2):
        raise ValueError(f"cov must have shape (2, 2) or ({n_targets}, 2, 2), got {arr.shape}")
    # vectorised checks; on failure, the first offending target gets the detailed message
    finite = np.isfinite(arr).all(axis=(1, 2))
    sym = np.abs(arr[:, 0, 1] - arr[:, 1, 0]) <= 1e-12 * np.maximum(1.0, np.abs(arr).max(axis=(1, 2)))
    pd = (arr[:, 0, 0] > 0) & (arr[:, 0, 0] * arr[:, 1, 1] - arr[:, 0, 1] * arr[:, 1, 0] > 0)
    bad = ~(finite & sym & pd)
    if bad.any():
        l = int(np.flatnonzero(bad)[0])
        check_spd2(arr[l], f"cov of target {l}")
    return arr


def check_spd2(m: np.ndarray, name: str) -> None:
    """Raise unless the 2x2 array ``m`` is finite, symmetric and positive definite."""
    if not np.isfinite(m).all():
        raise ValueError(f"{name} has a non-finite entry: {m.tolist()}")
    if abs(m[0, 1] - m[1, 0]) > 1e-12 * max(1.0, abs(m).max()):
        raise ValueError(f"{name} is not symmetric: {m.tolist()}")
    # Sylvester's criterion for a 2x2 symmetric matrix.
    if not (m[0, 0] > 0 and m[0, 0] * m[1, 1] - m[0, 1] * m[1, 0] > 0):
        raise ValueError(f"{name} is not positive definite: {m.tolist()}")


def check_distinct(sensors: np.ndarray) -> None:
    """Raise if two sensors share a position (the paper assumes distinct sensors)."""
    n = sensors.shape[0]
    if n < 2:
        return
    order = np.lexsort((sensors[:, 1], sensors[:, 0]))
    s = sensors[order]
    same = (s[1:] == s[:-1]).all(axis=1)
    if same.any():
        k = int(np.flatnonzero(same)[0])
        i, j = sorted((int(order[k]), int(order[k + 1])))
        raise ValueError(f"sensors {i} and {j} coincide at {sensors[i].tolist()}")


def check_not_on_targets(diff: np.ndarray) -> None:
    """Raise if a sensor sits on a target; ``diff[i, l] = o_l - p_i`` has shape ``(N, L, 2)``."""
    on = (diff == 0).all(axis=-1)
    if on.any():
        i, l = (int(v) for v in np.argwhere(on)[0])
        raise ValueError(f"sensor {i} coincides with target {l} (zero distance)")

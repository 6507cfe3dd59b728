r"""The controls every exact-versus-bound comparison sweeps: a polar grid of the disc :math:`\|u\| \le u_{\max}`."""

from __future__ import annotations

import numpy as np

__all__ = ["disc_controls", "disc_mesh"]


def disc_controls(u_max: float, n_radii: int, n_angles: int) -> np.ndarray:
    """Polar grid of controls covering the disc ``||u|| <= u_max``, boundary included.

    Returns ``1 + n_radii * n_angles`` controls: ``u = 0`` and ``n_angles`` directions at each
    of ``n_radii`` radii spaced evenly up to ``u_max``.
    """
    radii = u_max * np.arange(1, n_radii + 1) / n_radii
    phi = 2 * np.pi * np.arange(n_angles) / n_angles
    ring = np.column_stack([np.cos(phi), np.sin(phi)])
    grid = (radii[:, None, None] * ring[None, :, :]).reshape(-1, 2)
    return np.vstack([np.zeros((1, 2)), grid])


def disc_mesh(controls, values, n_radii: int, n_angles: int):
    """Values on the grid of :func:`disc_controls` as a closed polar mesh, for ``contourf``.

    Parameters
    ----------
    controls : array_like, shape (1 + n_radii * n_angles, 2)
        The grid, as returned by :func:`disc_controls` (``u = 0`` first, then ring by ring).
    values : array_like, shape (1 + n_radii * n_angles,)
        A value per control (e.g. the exact ``C^{-1}``).

    Returns
    -------
    X, Y, Z : ndarray, shape (n_radii + 1, n_angles + 1)
        Row 0 is the centre ``u = 0``; the last column repeats the first direction, so the
        quadrilaterals cover the whole disc (the same points a triangulation would use).
    """
    c = np.asarray(controls, dtype=float)
    v = np.asarray(values, dtype=float)
    k = 1 + n_radii * n_angles
    if c.shape != (k, 2) or v.shape != (k,):
        raise ValueError(f"need controls ({k}, 2) and values ({k},), got {c.shape}, {v.shape}")
    pts = np.concatenate([np.broadcast_to(c[0], (1, n_angles, 2)),
                          c[1:].reshape(n_radii, n_angles, 2)])
    z = np.concatenate([np.full((1, n_angles), v[0]), v[1:].reshape(n_radii, n_angles)])
    pts = np.concatenate([pts, pts[:, :1]], axis=1)
    z = np.concatenate([z, z[:, :1]], axis=1)
    return pts[..., 0], pts[..., 1], z

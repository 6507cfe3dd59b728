r"""The controls every exact-versus-bound comparison sweeps: a polar grid of the disc :math:`\|u\|
\le u_{\max}`."""

from __future__ import annotations

import numpy as np

from ._validate import as_float_array, as_int, as_nonnegative

__all__ = ["disc_controls", "disc_mesh"]


def disc_controls(u_max: float, n_radii: int, n_angles: int) -> np.ndarray:
    r"""Polar grid of controls covering the disc :math:`\|u\| \le u_{\max}`, boundary included.

    Parameters
    ----------
    u_max : float
        Radius of the disc (non-negative), the speed bound of Theorem 1.
    n_radii, n_angles : int
        Number of radii, spaced evenly up to ``u_max``, and of directions on each.

    Returns
    -------
    ndarray, shape (1 + n_radii * n_angles, 2)
        :math:`u = 0` first, then ``n_angles`` directions :math:`2 \pi k / n_{angles}` at each
        radius, ring by ring.

    Examples
    --------
    >>> disc_controls(2.0, n_radii=2, n_angles=4).round(12) + 0.0
    array([[ 0.,  0.],
           [ 1.,  0.],
           [ 0.,  1.],
           [-1.,  0.],
           [ 0., -1.],
           [ 2.,  0.],
           [ 0.,  2.],
           [-2.,  0.],
           [ 0., -2.]])
    """
    u_max, n_radii, n_angles = _disc_controls_iv(u_max, n_radii, n_angles)
    radii = u_max * np.arange(1, n_radii + 1) / n_radii
    phi = 2 * np.pi * np.arange(n_angles) / n_angles
    ring = np.column_stack([np.cos(phi), np.sin(phi)])
    grid = (radii[:, None, None] * ring[None, :, :]).reshape(-1, 2)
    return np.vstack([np.zeros((1, 2)), grid])


def _disc_controls_iv(u_max, n_radii, n_angles) -> tuple:
    """``u_max >= 0`` and two counts of at least 1."""
    return (as_nonnegative(u_max, "u_max"), as_int(n_radii, "n_radii", 1),
            as_int(n_angles, "n_angles", 1))


def disc_mesh(controls, values, n_radii: int, n_angles: int):
    """Values on the grid of :func:`disc_controls` as a closed polar mesh, for ``contourf``.

    Parameters
    ----------
    controls : array_like, shape (1 + n_radii * n_angles, 2)
        The grid, as returned by :func:`disc_controls` (``u = 0`` first, then ring by ring).
    values : array_like, shape (1 + n_radii * n_angles,)
        A value per control (e.g. the exact :math:`C^{-1}`).
    n_radii, n_angles : int
        The grid's shape, as given to :func:`disc_controls`.

    Returns
    -------
    X, Y, Z : ndarray, shape (n_radii + 1, n_angles + 1)
        Row 0 is the centre ``u = 0``; the last column repeats the first direction, so the
        quadrilaterals cover the whole disc (the same points a triangulation would use).

    Examples
    --------
    >>> c = disc_controls(1.0, n_radii=1, n_angles=4)
    >>> X, Y, Z = disc_mesh(c, np.hypot(*c.T), 1, 4)
    >>> Z.round(12)
    array([[0., 0., 0., 0., 0.],
           [1., 1., 1., 1., 1.]])
    >>> X[1].round(12) + 0.0
    array([ 1.,  0., -1.,  0.,  1.])
    """
    c, v, n_radii, n_angles = _disc_mesh_iv(controls, values, n_radii, n_angles)
    pts = np.concatenate([np.broadcast_to(c[0], (1, n_angles, 2)),
                          c[1:].reshape(n_radii, n_angles, 2)])
    z = np.concatenate([np.full((1, n_angles), v[0]), v[1:].reshape(n_radii, n_angles)])
    pts = np.concatenate([pts, pts[:, :1]], axis=1)
    z = np.concatenate([z, z[:, :1]], axis=1)
    return pts[..., 0], pts[..., 1], z


def _disc_mesh_iv(controls, values, n_radii, n_angles) -> tuple:
    """The counts, then controls ``(k, 2)`` and values ``(k,)`` with ``k = 1 + n_radii
    n_angles``."""
    n_radii = as_int(n_radii, "n_radii", 1)
    n_angles = as_int(n_angles, "n_angles", 1)
    c = as_float_array(controls, "controls")
    v = as_float_array(values, "values")
    k = 1 + n_radii * n_angles
    if c.shape != (k, 2) or v.shape != (k,):
        raise ValueError(f"need controls ({k}, 2) and values ({k},), got {c.shape}, {v.shape}")
    return c, v, n_radii, n_angles

"""The measurement models, the circling target's path, the pair bound along a run and the
exact :math:`C^{-1}` the adversary minimises.

In Section V a sensor :math:`p_i` measures

.. math::

    z_i = h_i(o) + n_i, \\qquad h_i(o) = \\tfrac12 \\lVert p_i - o \\rVert^2,

so the filter's Jacobian rows are :math:`H_i = (\\hat x - p_i)^T`, the rows of the paper's
observability matrix :math:`O(o)` at the estimate. The authors' later multi-target experiment
measures the range itself, :math:`h_i(o) = \\lVert p_i - o \\rVert`, whose Jacobian rows are
those rows divided by their length (:func:`euclidean_range`,
:func:`euclidean_range_jacobian`).
"""

from __future__ import annotations

import numpy as np

from .. import _kernels
from .._validate import as_float_array, as_instance, broadcast
from ..bounds import relative_vectors

__all__ = [
    "half_squared_range",
    "range_jacobian",
    "euclidean_range",
    "euclidean_range_jacobian",
    "circle_truth",
    "pair_bound_series",
    "target_objective",
]


def circle_truth(setup) -> np.ndarray:
    """True positions :math:`o_k`, ``k = 1..steps + 1``, on the circle of Section V-A,
    ``(steps + 1, 2)``.

    :math:`o_k = c + r\\,(\\cos(\\omega (k - 1)), \\sin(\\omega (k - 1)))` with ``center``,
    ``radius`` and ``rate`` of the setup; the extra last row is the position the target moves
    to after the last step.

    Examples
    --------
    >>> from obslib.tracking import PAPER_CIRCLE
    >>> circle_truth(PAPER_CIRCLE.replace(steps=2)).round(4).tolist()
    [[5.0, 3.0], [4.9994, 3.06], [4.9976, 3.12]]
    """
    from .setup import TrackingSetup

    as_instance(setup, TrackingSetup, "setup")
    a = setup.rate * np.arange(setup.steps + 1)
    return np.asarray(setup.center) + setup.radius * np.column_stack([np.cos(a), np.sin(a)])


def _state_iv(x, pair_sensors, name="pair_sensors"):
    """Finite positions ``x`` (``(2, 1)``, filterpy's column, or ``(..., 2)``) and sensors
    ``(..., M, 2)`` whose leading shapes broadcast."""
    x = as_float_array(x, "x")
    ps = as_float_array(pair_sensors, name)
    if x.shape != (2, 1) and (x.ndim < 1 or x.shape[-1] != 2):
        raise ValueError(f"x must have shape (2, 1) or (..., 2), got {x.shape}")
    if ps.ndim < 2 or ps.shape[-1] != 2:
        raise ValueError(f"{name} must have shape (..., M, 2), got {ps.shape}")
    if not (np.isfinite(x).all() and np.isfinite(ps).all()):
        raise ValueError(f"x and {name} must be finite")
    if x.shape != (2, 1):
        broadcast({"x": x[..., None, :], name: ps})
    return x, ps


def half_squared_range(x, pair_sensors) -> np.ndarray:
    """Measurement function :math:`h(x) = \\tfrac12 \\lVert p_i - x \\rVert^2` for the rows
    :math:`p_i` of ``pair_sensors``.

    ``x`` may be a filterpy column ``(2, 1)`` (returns ``(m, 1)``) or a batch ``(..., 2)`` with
    ``pair_sensors`` ``(..., m, 2)`` (returns ``(..., m)``).

    Examples
    --------
    >>> half_squared_range([1.0, 2.0], [[0.0, 0.0], [4.0, 6.0]]).tolist()
    [2.5, 12.5]
    """
    x, ps = _state_iv(x, pair_sensors)
    if x.shape == (2, 1):
        d = ps - x[:, 0]
        return (0.5 * (d[:, 0] ** 2 + d[:, 1] ** 2))[:, None]
    d = ps - x[..., None, :]
    return 0.5 * (d[..., 0] ** 2 + d[..., 1] ** 2)


def range_jacobian(x, pair_sensors) -> np.ndarray:
    """Jacobian of :func:`half_squared_range`: rows :math:`H_i = (x - p_i)^T`, ``(..., m, 2)``.

    Examples
    --------
    >>> range_jacobian([1.0, 2.0], [[0.0, 0.0], [4.0, 6.0]]).tolist()
    [[1.0, 2.0], [-3.0, -4.0]]
    """
    x, ps = _state_iv(x, pair_sensors)
    if x.shape == (2, 1):
        return x[:, 0][None, :] - ps
    return x[..., None, :] - ps


def euclidean_range(x, sensors) -> np.ndarray:
    """Measurement function of the range model, :math:`h(x) = \\lVert p_i - x \\rVert` for the
    rows :math:`p_i` of ``sensors``.

    ``x`` may be a filterpy column ``(2, 1)`` (returns ``(m, 1)``) or a batch ``(..., 2)`` with
    ``sensors`` ``(..., m, 2)`` (returns ``(..., m)``).

    Examples
    --------
    >>> euclidean_range([1.0, 2.0], [[4.0, 6.0], [1.0, 0.0]]).tolist()
    [5.0, 2.0]
    """
    x, ps = _state_iv(x, sensors, "sensors")
    if x.shape == (2, 1):
        d = ps - x[:, 0]
        return np.hypot(d[:, 0], d[:, 1])[:, None]
    d = ps - x[..., None, :]
    return np.hypot(d[..., 0], d[..., 1])


def euclidean_range_jacobian(x, sensors) -> np.ndarray:
    """Jacobian of :func:`euclidean_range`: rows :math:`H_i = (x - p_i)^T / \\lVert x - p_i
    \\rVert`, ``(..., m, 2)``; a sensor on ``x`` (where it is undefined) is a ValueError.

    Examples
    --------
    >>> euclidean_range_jacobian([1.0, 2.0], [[4.0, 6.0], [1.0, 0.0]]).tolist()
    [[-0.6, -0.8], [0.0, 1.0]]
    """
    x, ps = _state_iv(x, sensors, "sensors")
    d = x[:, 0][None, :] - ps if x.shape == (2, 1) else x[..., None, :] - ps
    r = np.hypot(d[..., 0], d[..., 1])
    if (r == 0).any():
        raise ValueError("sensors: a sensor sits on x, where the range has no Jacobian")
    return d / r[..., None]


def pair_index(n: int):
    """Row and column of the pairs ``i < j`` of ``n`` sensors in ``(i, j)`` order.

    Examples
    --------
    >>> [a.tolist() for a in pair_index(3)]
    [[0, 0, 1], [1, 2, 2]]
    """
    return np.triu_indices(n, 1)


def pair_bound_series(setup, points, pairs, cov=None) -> np.ndarray:
    """Theorem 4's bound of the given pair at each point: ``W[pairs[k, 0], pairs[k, 1], k]``
    of :func:`obslib.pair_bounds`.

    Evaluates only the given pair at each point, with :func:`obslib.pair_bounds`'s own
    normalisation and kernel, so whole Monte Carlo batches can be passed at once.

    Parameters
    ----------
    points : array_like, shape (K, 2)
        Where to evaluate (e.g. a run's ``estimate`` or ``truth``).
    pairs : array_like of int, shape (K, 2)
    cov : array_like, shape (K, 2, 2), optional
        Mahalanobis distances in these covariances; Euclidean when omitted.

    Examples
    --------
    >>> from obslib.tracking import PAPER_CIRCLE
    >>> pair_bound_series(PAPER_CIRCLE, [[5.5, 3.5]], [[3, 5]]).round(4).tolist()
    [0.7855]
    """
    from .setup import TrackingSetup

    as_instance(setup, TrackingSetup, "setup")
    v = relative_vectors(setup.sensors, points, cov)  # validated, (N, K, 2)
    K = v.shape[1]
    pr = np.asarray(pairs)
    n = setup.n_sensors
    if pr.shape != (K, 2) or not np.issubdtype(pr.dtype, np.integer):
        raise ValueError(f"pairs must be integers of shape ({K}, 2), got {pr.dtype} {pr.shape}")
    if K and (pr.min() < 0 or pr.max() >= n):
        raise ValueError(f"pairs must be sensor indices in 0..{n - 1}")
    return _kernels.pair_series(v, pr, setup.u_max)


def inverse_condition(rows) -> np.ndarray:
    """Exact :math:`C^{-1} = \\sigma_{\\min} / \\sigma_{\\max}` of each stacked ``(m, 2)`` matrix
    of ``rows`` ``(..., m, 2)`` (the closed form of :func:`obslib.inverse_condition_number`,
    without validation).

    Examples
    --------
    >>> import numpy as np
    >>> from obslib.tracking.model import inverse_condition
    >>> rows = [[[1.0, 0.0], [0.0, 2.0]], [[1.0, 1.0], [2.0, 2.0]]]
    >>> inverse_condition(rows).round(12).tolist()
    [0.5, 0.0]
    """
    return _kernels.inverse_condition(as_float_array(rows, "rows"))


def target_objective(pair_sensors, position, controls) -> np.ndarray:
    """Exact :math:`C^{-1}` of :math:`[o' - p_i; o' - p_j; u]` at :math:`o' = o + u` for each
    control :math:`u`.

    The adversary of Section V-B minimises this over its control set.

    Parameters
    ----------
    pair_sensors : array_like, shape (..., 2, 2)
        The two sensors' positions (rows).
    position : array_like, shape (..., 2)
        The target's current position :math:`o`.
    controls : array_like, shape (K, 2)

    Returns
    -------
    ndarray, shape (..., K)

    Examples
    --------
    >>> target_objective([[0.0, 0.0], [4.0, 0.0]], [2.0, 2.0],
    ...                  [[0.0, 0.0], [0.1, 0.0]]).round(4)
    array([1.    , 0.9512])
    """
    ps = as_float_array(pair_sensors, "pair_sensors")
    o = as_float_array(position, "position")
    u = as_float_array(controls, "controls")
    for name, a, tail in (("pair_sensors", ps, "(..., 2, 2)"), ("position", o, "(..., 2)"),
                          ("controls", u, "(K, 2)")):
        if a.ndim < len(tail.split(",")) - tail.count("...") or a.shape[-1] != 2:
            raise ValueError(f"{name} must have shape {tail}, got {a.shape}")
        if not np.isfinite(a).all():
            raise ValueError(f"{name} must be finite")
    if ps.shape[-2] != 2:
        raise ValueError(f"pair_sensors must have shape (..., 2, 2), got {ps.shape}")
    broadcast({"position": o[..., None, None, :], "pair_sensors": ps[..., None, :, :]})
    nxt = o[..., None, :] + u  # (..., K, 2)
    rows = nxt[..., :, None, :] - ps[..., None, :, :]  # (..., K, 2, 2)
    uu = np.broadcast_to(u, nxt.shape)[..., None, :]  # (..., K, 1, 2)
    return _kernels.inverse_condition(np.concatenate([rows, uu], axis=-2))

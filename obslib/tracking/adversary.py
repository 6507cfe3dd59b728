r"""The adversarial target of Section V-B: which control it takes against a sensor pair.

Knowing its position :math:`o` and the pair :math:`(p_i, p_j)`, the target takes the control of
its set that minimises the exact inverse condition number

.. math::

    u^\star = \operatorname*{arg\,min}_{u \in U} C^{-1}\!\left(
    \begin{bmatrix} (o + u - p_i)^T \\ (o + u - p_j)^T \\ u^T \end{bmatrix}\right),

the first minimiser in the order of :math:`U`. The tracking engine moves its adversaries with
the worker of :func:`adversary_moves`, for all runs at once; the tests hold its picks to the
``argmin`` of :func:`~obslib.tracking.target_objective` over the whole set.
"""

from __future__ import annotations

import numpy as np

from .._kernels import matmul_rows
from .._validate import as_float_array
from .model import inverse_condition

__all__ = ["control_basis", "adversary_moves"]


def control_basis(controls) -> np.ndarray:
    """Monomials :math:`1, u_x, u_y, u_x^2, u_x u_y, u_y^2` of each control, ``(6, K)``.

    Examples
    --------
    >>> import numpy as np
    >>> from obslib.tracking.adversary import control_basis
    >>> control_basis(np.array([[1.0, 2.0]])).ravel().tolist()
    [1.0, 1.0, 2.0, 1.0, 2.0, 4.0]
    """
    return control_monomials(_controls_iv(controls))


def _controls_iv(controls) -> np.ndarray:
    c = as_float_array(controls, "controls")
    if c.ndim != 2 or c.shape[1] != 2 or not c.shape[0]:
        raise ValueError(f"controls must have shape (K, 2), K >= 1, got {c.shape}")
    if not np.isfinite(c).all():
        raise ValueError("controls must be finite")
    return c


def control_monomials(controls) -> np.ndarray:
    ux, uy = controls[:, 0], controls[:, 1]
    return np.stack([np.ones_like(ux), ux, uy, ux * ux, ux * uy, uy * uy])


def adversary_moves(pair_sensors, position, controls) -> np.ndarray:
    """Index of the control each adversary takes: the first minimiser over ``controls`` of
    :func:`~obslib.tracking.target_objective` (its exact values), ``(R,)``.

    With :math:`a = o - p_i`, :math:`b = o - p_j` and the rows :math:`a + u`, :math:`b + u`,
    :math:`u` of the matrix :math:`M`, the three 2 x 2 minors of :math:`M` are affine in :math:`u`
    (:math:`a \\times b + (a - b) \\times u`, :math:`a \\times u`, :math:`b \\times u`), so
    :math:`\\det(M^T M)` (their sum of squares, Cauchy-Binet) and :math:`\\operatorname{tr}(M^T M)`
    are quadratics in :math:`u`: one matrix product with the monomials of the controls
    (:func:`control_basis`) gives both for all runs and controls. :math:`C^{-1}(M)` is an
    increasing function of :math:`t = 4 \\det / \\operatorname{tr}^2` (:math:`C^{-2} =
    \\lambda_{\\min} / \\lambda_{\\max}` and :math:`t = 4 \\lambda_{\\min} \\lambda_{\\max} /
    (\\lambda_{\\min} + \\lambda_{\\max})^2`), so the controls whose
    :math:`\\det / \\operatorname{tr}^2` is within ``1e-11`` of the run's minimum contain the
    exact minimiser (the screen's rounding error is some 1e-15). Those few candidates (usually
    one) are evaluated with the arithmetic of :func:`~obslib.tracking.target_objective` and the
    first exact minimiser is taken, so the pick equals its ``argmin`` over the whole set (tests
    check it).

    The engine's worker (the same computation without the checks) also takes ``barred``
    (``(R, K)``, 0 or inf), which removes controls from a run's set: runs with different
    control sets share one call with the union of the sets, each run's own set a contiguous
    block of it in its own order.

    Parameters
    ----------
    pair_sensors : array_like, shape (R, 2, 2)
        The pair each adversary evaluates (rows the two sensors).
    position : array_like, shape (R, 2)
        The targets' positions :math:`o`.
    controls : array_like, shape (K, 2)
        The control set :math:`U`, in its order.

    Returns
    -------
    ndarray of int, shape (R,)

    Examples
    --------
    The pick is the first minimiser of :func:`~obslib.tracking.model.target_objective`:

    >>> import numpy as np
    >>> from obslib.tracking import paper_controls, target_objective
    >>> from obslib.tracking.adversary import adversary_moves
    >>> ps = np.array([[[0.0, 0.0], [4.0, 0.0]]])
    >>> o = np.array([[2.0, 2.0]])
    >>> ctrl = paper_controls(0.1)
    >>> best = np.argmin(target_objective(ps[0], o[0], ctrl))
    >>> int(adversary_moves(ps, o, ctrl)[0]) == int(best)
    True
    """
    ps = as_float_array(pair_sensors, "pair_sensors")
    o = as_float_array(position, "position")
    if ps.ndim != 3 or ps.shape[1:] != (2, 2):
        raise ValueError(f"pair_sensors must have shape (R, 2, 2), got {ps.shape}")
    if o.shape != (ps.shape[0], 2):
        raise ValueError(f"position must have shape ({ps.shape[0]}, 2), one per pair, got "
                         f"{o.shape}")
    if not (np.isfinite(ps).all() and np.isfinite(o).all()):
        raise ValueError("pair_sensors and position must be finite")
    c = _controls_iv(controls)
    return screened_moves(ps, o, c)


def screened_moves(eval_ps, o, controls, basis=None, barred=None) -> np.ndarray:
    """:func:`adversary_moves` without checks, for the engine: ``basis`` is
    ``control_monomials`` of the controls (computed once per run), ``barred`` the removed
    controls (see above)."""
    if basis is None:
        basis = control_monomials(controls)
    R_ = o.shape[0]
    ax, ay = o[:, 0] - eval_ps[:, 0, 0], o[:, 1] - eval_ps[:, 0, 1]
    bx, by = o[:, 0] - eval_ps[:, 1, 0], o[:, 1] - eval_ps[:, 1, 1]
    # minors as w0 + wx ux + wy uy: (a x b + (a - b) x u), (a x u), (b x u)
    w0 = np.stack([ax * by - ay * bx, np.zeros(R_), np.zeros(R_)])
    wx = np.stack([by - ay, -ay, -by])
    wy = np.stack([ax - bx, ax, bx])
    coef = np.empty((2 * R_, 6))
    coef[:R_, 0] = (w0 * w0).sum(axis=0)
    coef[:R_, 1] = 2 * (w0 * wx).sum(axis=0)
    coef[:R_, 2] = 2 * (w0 * wy).sum(axis=0)
    coef[:R_, 3] = (wx * wx).sum(axis=0)
    coef[:R_, 4] = 2 * (wx * wy).sum(axis=0)
    coef[:R_, 5] = (wy * wy).sum(axis=0)
    coef[R_:, 0] = ax * ax + ay * ay + bx * bx + by * by
    coef[R_:, 1] = 2 * (ax + bx)
    coef[R_:, 2] = 2 * (ay + by)
    coef[R_:, 3] = 3.0
    coef[R_:, 4] = 0.0
    coef[R_:, 5] = 3.0
    # (2R, K): det and trace, in products small enough that BLAS does not start threads (2000
    # runs x 64 controls: 0.08 ms against 2.6 ms on a busy machine; the screen's margin absorbs
    # the rounding of either)
    dt = matmul_rows(coef, basis)
    q = dt[:R_]
    q /= dt[R_:] * dt[R_:]
    if barred is not None:
        q += barred  # 0 or inf
    ar = np.arange(R_)
    ks = q.argmin(axis=1)  # the first screened minimum
    m = q[ar, ks]
    q[ar, ks] = np.inf
    near = q.min(axis=1) <= m + 1e-11  # another control within the screen's margin
    if not near.any():
        return ks
    q[ar, ks] = m
    amb = np.flatnonzero(near)
    rows, kk = np.nonzero(q[amb] <= m[amb, None] + 1e-11)
    rows = amb[rows]
    nxt = o[rows] + controls[kk]
    stack = np.concatenate([nxt[:, None, :] - eval_ps[rows], controls[kk][:, None, :]], axis=1)
    exact = inverse_condition(stack)
    order = np.lexsort((kk, exact, rows))  # by run, then value, then control index
    first = np.ones(order.size, dtype=bool)
    first[1:] = rows[order][1:] != rows[order][:-1]
    ks[rows[order[first]]] = kk[order[first]]
    return ks

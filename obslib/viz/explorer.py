"""The bound explorer of the pair closed-form chapter as a still figure, for print.

The explorer on the web page is a live map: the colour under each point is Theorem 1's bound
with one more sensor placed there, the star marks the best such point, the dashed circle holds
the controls of speed at most :math:`u_{\\max}`, and the dotted line through the target is the
worst direction (:func:`obslib.bounds.worst_case_control`). :func:`plot_explorer_view` draws the
same map for one state of the explorer (its first one in the book), with the bound and the exact
value for the drawn control in the title.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_float_array, as_int, as_point, as_points, as_u_max
from ..bounds import lower_bound, lower_bounds, worst_case_control
from ..observability import inverse_condition_number
from .style import OKABE_ITO, SEQUENTIAL, look

__all__ = ["plot_explorer_view", "candidate_bounds"]


def candidate_bounds(sensors, target, u_max, xs, ys) -> np.ndarray:
    """Theorem 1's bound with one more sensor at each point of the grid ``xs`` by ``ys``.

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        The sensors already placed.
    target : array_like, shape (2,)
        The target ``o``.
    u_max : float
        The speed bound.
    xs, ys : array_like, shape (nx,) and (ny,)
        The grid's coordinates.

    Returns
    -------
    ndarray, shape (ny, nx)
        Row ``k``, column ``m``: the bound of the sensors and one more at ``(xs[m], ys[k])``. A
        point on the target adds nothing (its row of ``O(o)`` is zero), so it gets the bound of
        the sensors alone.

    Examples
    --------
    One sensor at ``(-1, 0)``, the target at the origin, ``u_max = 0``: a second sensor at
    ``(0, 1)`` sees the target at a right angle from as far (bound 1), one at ``(1, 0)`` on the
    same line (bound 0).

    >>> candidate_bounds([[-1, 0]], [0, 0], 0.0, [0.0, 1.0], [1.0, 0.0]).round(6)
    array([[1.      , 0.381966],
           [0.      , 0.      ]])
    """
    s = as_points(sensors, "sensors")
    o = as_point(target, "target")
    u = float(as_u_max(u_max))
    gx, gy = np.meshgrid(_axis(xs, "xs"), _axis(ys, "ys"))
    extra = np.stack([gx, gy], axis=-1)  # (ny, nx, 2)
    rows = np.concatenate([np.broadcast_to(o - s, (*extra.shape[:2], *s.shape)),
                           (o - extra)[..., None, :]], axis=-2)
    return lower_bounds(rows, u)


def _axis(values, name: str) -> np.ndarray:
    arr = as_float_array(values, name)
    if arr.ndim != 1 or arr.size == 0 or not np.isfinite(arr).all():
        raise ValueError(f"{name} must be a non-empty list of finite numbers, got {arr.shape}")
    return arr


def plot_explorer_view(sensors, target, control, u_max, grid: int = 121):
    """The explorer's map for one state: the bound with one more sensor at every point, the
    best such point, the sensors, the target with its control and the disc of controls, and the
    worst direction. Returns the figure (7.5 in by 5.4 in).

    Parameters
    ----------
    sensors : array_like, shape (N, 2)
        The sensors (in metres, as the explorer's map).
    target : array_like, shape (2,)
        The target ``o``.
    control : array_like, shape (2,)
        The target's control ``u_o``, drawn as an arrow from the target.
    u_max : float
        The speed bound, the radius of the dashed disc.
    grid : int
        Points of the colour map per side (2 to 1000).

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")  # no window
    >>> sensors = [[-2.5, -1.5], [2.0, -2.0]]
    >>> fig = plot_explorer_view(sensors, [0.5, 1.0], [0.6, 0.3], 1.0, grid=11)
    >>> fig.axes[0].get_title()
    'Theorem 1 bound 0.735, exact value for the arrow 0.755'
    """
    import matplotlib.pyplot as plt

    s = as_points(sensors, "sensors", min_count=1)
    o = as_point(target, "target")
    u = as_point(control, "control")
    umax = float(as_u_max(u_max))
    grid = as_int(grid, "grid", 2)
    if grid > 1000:
        raise ValueError(f"grid: at most 1000 points per side, got {grid}")
    if np.hypot(*u) > umax * (1 + 1e-12):
        raise ValueError(f"control: its length {np.hypot(*u):.6g} exceeds u_max = {umax:.6g}")
    # the explorer's view: a square around the origin holding every point and the disc
    half = max(5.0, 1.12 * np.abs(np.vstack([s, o])).max(),
               1.12 * (np.abs(o).max() + umax))
    xs = ys = np.linspace(-half, half, grid)
    heat = candidate_bounds(s, o, umax, xs, ys)
    best = np.unravel_index(np.argmax(heat), heat.shape)
    bound = lower_bound(s, o, umax)
    exact = inverse_condition_number(s, o, u)

    fig, ax = plt.subplots(figsize=(7.5, 5.4), layout="constrained")
    im = ax.imshow(heat, origin="lower", extent=(-half, half, -half, half), cmap=SEQUENTIAL,
                   vmin=0.0, vmax=1.0, interpolation="bilinear")
    fig.colorbar(im, ax=ax, label="bound with one more sensor there")
    if umax > 0:
        w = worst_case_control(s, o, umax)
        ends = np.array([o - 1.6 * w, o + 1.6 * w])
        ax.plot(ends[:, 0], ends[:, 1], color="white", ls=":", lw=1.5,
                label="worst direction of the control")
        phi = np.linspace(0, 2 * np.pi, 200)
        ax.plot(o[0] + umax * np.cos(phi), o[1] + umax * np.sin(phi), color="white", ls="--",
                lw=1.2, label=r"controls of speed $\leq u_{\max}$")
    for p in s:
        ax.plot([o[0], p[0]], [o[1], p[1]], color="white", lw=0.8, alpha=0.8)
    ax.annotate("", xy=o + u, xytext=o,
                arrowprops={"arrowstyle": "-|>", "color": OKABE_ITO["orange"], "lw": 2})
    ax.plot(*s.T, **look("sensor").kw(color="white", mec="black", ms=11))
    ax.plot(*o, **look("target").kw(mec="white", ms=15))
    ax.plot(xs[best[1]], ys[best[0]], **look("maximum").kw(
        mec="white", ms=16, label="best place for one more sensor"))
    ax.set_xlim(-half, half)
    ax.set_ylim(-half, half)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title(f"Theorem 1 bound {bound:.3f}, exact value for the arrow {exact:.3f}")
    # white marks as on the map: on a grey ground, with white words
    fig.legend(*ax.get_legend_handles_labels(), loc="outside lower center", ncol=2,
               facecolor="#5a5a5a", edgecolor="none", framealpha=1.0, labelcolor="white")
    return fig

r"""Figures of the model and the lower bound (Sections II-III): what range sensors see, Theorem 1
on one scene, one sensor's disc of controls, and the bound's tightness.

Each ``plot_*`` function draws one figure of the chapter and returns it; it computes what it
draws from the scene (:func:`obslib.inverse_condition_number` over the polar grid of
:func:`obslib.controls.disc_controls`, :func:`obslib.lower_bound`,
:func:`obslib.worst_case_control`).
"""

from __future__ import annotations

import numpy as np

from .._validate import as_ints, as_point, as_points, as_positive
from ..bounds import lower_bound, worst_case_control
from ..controls import disc_controls, disc_mesh
from ..formatting import number
from ..observability import inverse_condition_number
from .style import OKABE_ITO, as_axes, look

__all__ = ["INTUITION_SCENES", "draw_rows", "plot_reading_rings", "plot_theorem1_scene",
           "plot_one_sensor", "plot_tightness"]

#: The three scenes of the intuition (sensor positions in m, the target at the origin).
INTUITION_SCENES = {
    "a cross": [[3.0, 0.0], [0.0, 3.0]],
    "nearly parallel": [[3.0, 0.0], [2.9, 0.78]],
    "one sensor": [[3.0, 0.0]],
}


def draw_rows(ax, sensors, target) -> None:
    """Each sensor's row :math:`o - p_i` as an arrow from the sensor to the target, then the
    sensors (triangles) and the target (a star), on ``ax``.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = Figure().add_subplot()
    >>> draw_rows(ax, [[3.0, 0.0], [0.0, 3.0]], [0.0, 0.0])
    >>> len(ax.texts), len(ax.lines)
    (2, 2)
    """
    as_axes(ax)
    sensors, o = as_points(sensors, "sensors"), as_point(target, "target")
    for p in sensors:
        ax.annotate("", o, p, arrowprops=dict(arrowstyle="->", lw=1.5, shrinkA=6, shrinkB=4,
                                              color=OKABE_ITO["blue"]))
    ax.plot(*sensors.T, **look("sensor").kw(ms=9, label=None))
    ax.plot(*o, **look("target").kw(ms=12, label=None))


def plot_reading_rings(error: float = 0.3):
    """What range sensors see: for each scene of :data:`INTUITION_SCENES`, each sensor's row and
    the ring of positions that agree with its reading up to ``error`` (m); the titles give the
    inverse condition number of :math:`O(o)`.

    Examples
    --------
    >>> fig = plot_reading_rings()
    >>> [ax.get_title().splitlines()[0] for ax in fig.axes]
    ['a cross', 'nearly parallel', 'one sensor']
    """
    import matplotlib.pyplot as plt
    from matplotlib.patches import Wedge

    error = as_positive(error, "error")
    o = np.zeros(2)
    fig, axes = plt.subplots(1, 3, figsize=(7.5, 3.3))
    for ax, (name, sensors) in zip(axes, INTUITION_SCENES.items()):
        sensors = np.array(sensors)
        for p in sensors:  # the ring of positions that agree with the reading of p
            d = np.linalg.norm(p - o)
            ax.add_patch(Wedge(p, d + error, 0, 360, width=2 * error, lw=0,
                               color=OKABE_ITO["sky blue"], alpha=0.35))
        draw_rows(ax, sensors, o)
        c_inv = inverse_condition_number(sensors, o)
        ax.set_title(f"{name}\n$C^{{-1}}(O(o))$ = {number(c_inv, 2)}")
        ax.set(xlim=(-1.5, 3.8), ylim=(-1.5, 3.8), aspect="equal", xlabel="x (m)")
    axes[0].set_ylabel("y (m)")
    return fig


def _scene_iv(sensors, target, u_max, n_radii, n_angles):
    """The scene checked, and the polar grid of the disc of controls."""
    sensors = as_points(sensors, "sensors", min_count=1)
    target = as_point(target, "target")
    as_positive(u_max, "u_max")
    return sensors, target, disc_controls(u_max, n_radii, n_angles)


def plot_theorem1_scene(sensors, target, u_max: float, n_radii: int, n_angles: int,
                        numbers=None):
    r"""Theorem 1 on one scene: the sensors, the target and the direction :math:`v_{\max}` of
    the worst control (left); the exact :math:`C^{-1}(O(o, u))` over the disc
    :math:`\|u\| \le u_{\max}` on a polar grid of ``n_radii`` by ``n_angles`` controls, the
    contour of the bound and the worst-case controls :math:`\pm u^*` (right).

    ``numbers`` are the sensors' numbers on the page (1-based; default ``1, 2, ...``).

    Examples
    --------
    >>> S = [[-3.0, 2.0], [0.0, 0.0], [4.0, 0.0]]
    >>> fig = plot_theorem1_scene(S, [2.0, 3.0], 1.0, 4, 36)
    >>> fig.axes[0].get_title()
    'scene'
    """
    import matplotlib.pyplot as plt

    S, target, controls = _scene_iv(sensors, target, u_max, n_radii, n_angles)
    n_radii, n_angles = int(n_radii), int(n_angles)
    numbers = list(range(1, len(S) + 1)) if numbers is None else as_ints(numbers, "numbers", 0)
    if len(numbers) != len(S):
        raise ValueError(f"numbers must give one number per sensor ({len(S)}), got {numbers}")
    exact = inverse_condition_number(S, target, controls)
    bound = lower_bound(S, target, u_max)
    u_star = worst_case_control(S, target, u_max)
    u_max = float(u_max)
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7.5, 3.6),
                                   gridspec_kw={"width_ratios": [1, 1.3]})
    ax0.plot(*S.T, **look("sensor").kw(ms=9, label=None))
    for k, p in zip(numbers, S):
        ax0.annotate(f"$s_{k}$", p, xytext=(0, -9), textcoords="offset points",
                     ha="center", va="top")
    ax0.plot(*target, **look("target").kw(ms=13, label=None))
    ax0.annotate("$o$", target, xytext=(-9, 0), textcoords="offset points",
                 ha="right", va="center")
    tip = target + 1.5 * u_star / u_max
    ax0.annotate("", tip, target, arrowprops=dict(arrowstyle="->", lw=2))
    ax0.text(*(target + 1.7 * u_star / u_max), "$v_{\\max}$", ha="center")
    ax0.set_xlim(min(S[:, 0].min(), tip[0]) - 1, max(S[:, 0].max(), tip[0]) + 1)
    ax0.set_ylim(min(S[:, 1].min(), tip[1]) - 1.5, max(S[:, 1].max(), tip[1]) + 1)
    ax0.set_aspect("equal")
    ax0.set_title("scene")
    ax0.set_xlabel("x (m)")
    ax0.set_ylabel("y (m)")
    X, Y, Z = disc_mesh(controls, exact, n_radii, n_angles)  # the polar grid, closed
    filled = ax1.contourf(X, Y, Z, levels=20, cmap="viridis")
    ax1.contour(X, Y, Z, levels=[bound + 1e-3], colors="w")
    worst = look("maximum").kw(ms=12, label=None, clip_on=False)
    ax1.plot(*np.array([u_star, -u_star]).T, **worst)
    for sgn, name in ((1, "$+u^*$"), (-1, "$-u^*$")):
        ax1.annotate(name, sgn * u_star, xytext=(16 * sgn, 0), textcoords="offset points",
                     color=worst["color"], ha="left" if sgn > 0 else "right", va="center")
    lim = 1.15 * u_max
    ax1.set_xlim(-lim, lim)
    ax1.set_ylim(-lim, lim)
    ax1.set_aspect("equal")
    ax1.set_xlabel("$u_x$ (m/s)")
    ax1.set_ylabel("$u_y$ (m/s)")
    ax1.set_title("exact $C^{-1}(O(o,u))$, $\\|u\\| \\leq u_{\\max}$")
    fig.colorbar(filled, ax=ax1, label="$C^{-1}$")
    return fig


def plot_one_sensor(sensor, target, u_max: float, n_radii: int, n_angles: int):
    r"""One sensor with a known control: the exact :math:`C^{-1}(O_i(o, u))` over the disc
    :math:`\|u\| \le u_{\max}` (a polar grid of ``n_radii`` by ``n_angles`` controls).

    Examples
    --------
    >>> fig = plot_one_sensor([0.0, 0.0], [2.0, 3.0], 1.0, 4, 36)
    >>> fig.axes[0].get_xlabel()
    '$u_x$ (m/s)'
    """
    import matplotlib.pyplot as plt

    one = as_point(sensor, "sensor")[None]
    _, target, controls = _scene_iv(one, target, u_max, n_radii, n_angles)
    vals = inverse_condition_number(one, target, controls)
    fig, ax = plt.subplots(figsize=(4.8, 3.9))
    filled = ax.contourf(*disc_mesh(controls, vals, int(n_radii), int(n_angles)), levels=20)
    ax.set(aspect="equal", xlabel="$u_x$ (m/s)", ylabel="$u_y$ (m/s)",
           title="one sensor: exact $C^{-1}$ over the disc")
    fig.colorbar(filled, ax=ax, label="$C^{-1}$")
    return fig


def plot_tightness(sensors, target, u_max: float):
    r"""The bound is tight: on circles of controls :math:`\|u\| = r` (a quarter, a half and all
    of ``u_max``), the exact :math:`C^{-1}` against the direction of the control, and the bound
    for :math:`u_{\max} = r` (dashed); dotted lines mark the directions :math:`\pm v_{\max}`.

    Examples
    --------
    >>> S = [[-3.0, 2.0], [0.0, 0.0], [4.0, 0.0]]
    >>> fig = plot_tightness(S, [2.0, 3.0], 1.0)
    >>> len(fig.axes[0].get_legend().get_texts())
    3
    """
    import matplotlib.pyplot as plt

    S, target = as_points(sensors, "sensors", min_count=1), as_point(target, "target")
    u_max = as_positive(u_max, "u_max")
    u_star = worst_case_control(S, target, u_max)
    phi = np.linspace(0, 2 * np.pi, 721)
    ring = np.column_stack([np.cos(phi), np.sin(phi)])
    fig, ax = plt.subplots(figsize=(7.5, 4.0))
    for r in (0.25 * u_max, 0.5 * u_max, u_max):
        exact_r = inverse_condition_number(S, target, r * ring)
        line, = ax.plot(phi, exact_r, **look("exact").kw(label=f"$\\|u\\| = {r:g}$ m/s"))
        ax.axhline(lower_bound(S, target, r), lw=1,
                   **look("bound").kw(color=line.get_color(), label=None))
    v_dir = np.arctan2(u_star[1], u_star[0]) % np.pi  # direction of v_max in [0, pi)
    for shift in (0, np.pi):
        ax.axvline(v_dir + shift, color="k", lw=0.8, ls=":")
    ax.set_xlabel("direction of the control (rad)")
    ax.set_ylabel("$C^{-1}$")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.17), ncol=3)
    return fig

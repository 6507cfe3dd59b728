"""Figures of general assignment and submodularity (Section IV-B): diminishing returns seen
through the information ellipse, and the two geometries of the paper's Fig. 3.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_eps, as_point, as_points
from ..formatting import number
from ..measures import measure
from ..observability import inverse_condition_number
from .style import look, sensor_label

__all__ = ["plot_diminishing_returns", "plot_fig3"]


def _information_ellipse(ax, rows, o, scale, color):
    """The ellipse with the singular values of the rows ``O`` as half-axes, along their
    directions, scaled by ``scale``."""
    from matplotlib.patches import Ellipse

    values, vectors = np.linalg.eigh(rows.T @ rows)
    half = scale * np.sqrt(np.maximum(values, 0))
    angle = np.degrees(np.arctan2(vectors[1, 1], vectors[0, 1]))
    ax.add_patch(Ellipse(o, 2 * half[1], 2 * half[0], angle=angle, fill=False, lw=2,
                         color=color))


def plot_diminishing_returns(sensors, target, eps: float):
    r"""Diminishing returns: the teams :math:`\{s_1, s_2\}` and :math:`\{s_1, s_2, s_3\}` of
    ``sensors`` around ``target``, each with its information ellipse (half-axes the singular
    values of its rows :math:`o - p_i`); the titles give :math:`C^{-1}` and
    :math:`\log\det(O^T O + \varepsilon I)`. The axes' limits fit the chapter's scene.

    Examples
    --------
    >>> P = [[0.0, 3.0], [3.0, 0.0], [5.0, 0.0]]
    >>> fig = plot_diminishing_returns(P, [0.0, 0.0], eps=1.0)
    >>> fig.axes[0].get_title().split(":")[0]
    '{s₁, s₂}'
    """
    import matplotlib.pyplot as plt

    P = as_points(sensors, "sensors", min_count=3)
    o = as_point(target, "target")
    eps = as_eps(eps)
    fig, axes = plt.subplots(1, 2, figsize=(7.5, 3.9), sharex=True, sharey=True)
    for ax, team in zip(axes, [(0, 1), (0, 1, 2)]):
        icn = inverse_condition_number(P[list(team)], o)
        logdet = measure(P[list(team)], o, "logdet", eps=eps)
        for i in team:
            ax.plot(*np.array([P[i], o]).T, color="0.6", lw=1.5, zorder=1)
        _information_ellipse(ax, P[list(team)] - o, o, 0.3, look("d-optimal").color)
        ax.plot(*P[list(team)].T, **look("sensor").kw(ms=10, zorder=3))
        ax.plot(*o, **look("target").kw(ms=14, zorder=3))
        for i in team:
            ax.annotate(sensor_label(i), P[i], textcoords="offset points", xytext=(0, 9),
                        ha="center")
        names = ", ".join(sensor_label(i) for i in team)
        ax.set_title(f"{{{names}}}: C⁻¹ = {number(icn, math=False)}, "
                     f"log det = {number(logdet, math=False)}")
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
    axes[0].set_xlim(-2.5, 6.5)
    axes[0].set_ylim(-2.5, 4.2)
    axes[0].set_ylabel("y (m)")
    return fig


def plot_fig3():
    """The paper's Fig. 3: the sensors and the target of its Case 1 (not monotone) and Case 2
    (not submodular), :data:`obslib.studies.submodularity.FIG3_CASES`.

    Examples
    --------
    >>> [ax.get_title() for ax in plot_fig3().axes]
    ['(a) Case 1', '(b) Case 2']
    """
    import matplotlib.pyplot as plt

    from ..studies.submodularity import FIG3_CASES, FIG3_TARGET

    fig, axes = plt.subplots(1, 2, figsize=(7.5, 4.6), width_ratios=[1, 1.43])
    for ax, (case, title) in zip(axes, [("case1", "(a) Case 1"), ("case2", "(b) Case 2")]):
        S, o = FIG3_CASES[case], FIG3_TARGET
        for k, p in enumerate(S):
            ax.plot([o[0], p[0]], [o[1], p[1]], color="0.7", lw=1, zorder=1)
            ax.annotate(sensor_label(k), p, textcoords="offset points", xytext=(7, -4))
        ax.plot(*S.T, **look("sensor").kw(ms=10, zorder=2))
        ax.plot(*o, **look("target").kw(ms=15, zorder=3, label="target t₁"))
        ax.annotate("t₁", o, textcoords="offset points", xytext=(-18, 6))
        ax.set_aspect("equal")
        ax.margins(0.15)
        ax.set_xlabel("x (m)")
        ax.set_title(title)
        ax.grid(alpha=0.3)
    axes[0].set_xlim(-4.5, 8.0)  # widen the tall Case 1 panel
    axes[0].set_ylabel("y (m)")
    axes[0].legend(loc="lower left")
    return fig

"""Figures of the pair closed form: the geometry of Fig. 1 and the four panels of Fig. 2."""

from __future__ import annotations

import numpy as np

from .._validate import positive_float

__all__ = ["plot_fig1", "plot_fig2"]


def plot_fig1(
    ax=None, d_io: float = 1.0, d_jo: float = 1.5, theta_i: float = 0.35, theta_j: float = 2.0
):
    r"""Fig. 1: sensors :math:`i, j` around the target in the polar coordinates of Eq. (8).

    The target is at the centre; sensor :math:`i` at distance :math:`d_{io}` and angle
    :math:`\theta_i`, sensor :math:`j` at :math:`d_{jo}` and :math:`\theta_j`;
    :math:`\theta_{ji} = \theta_j - \theta_i`. Returns the axes.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")  # no window
    >>> ax = plot_fig1(d_io=1.0, d_jo=1.5, theta_i=0.35, theta_j=2.0)
    >>> ax.get_aspect()
    1.0
    """
    import matplotlib.pyplot as plt

    d_io = positive_float("d_io", d_io)
    d_jo = positive_float("d_jo", d_jo)
    if not (np.isfinite(theta_i) and np.isfinite(theta_j)):
        raise ValueError("theta_i and theta_j must be finite")
    if ax is None:  # the frame's aspect is always 2 : 1.45, so one written-down layout fits it
        fig, ax = plt.subplots(figsize=(4.1, 3))
        fig.subplots_adjust(left=0.024, right=0.976, bottom=0.028, top=0.972)
    pi_ = d_io * np.array([np.cos(theta_i), np.sin(theta_i)])
    pj_ = d_jo * np.array([np.cos(theta_j), np.sin(theta_j)])
    lim = 1.25 * max(d_io, d_jo)
    ax.axhline(0, color="0.6", lw=0.8, ls="--")
    for p, th, name, d, col, side in ((pi_, theta_i, "i", "d_{io}", "C0", -1.0),
                                      (pj_, theta_j, "j", "d_{jo}", "C1", 1.0)):
        ax.plot([0, p[0]], [0, p[1]], color=col, lw=1.5)
        ax.plot(*p, marker="^", ms=12, color=col, ls="none")
        ax.annotate(f"sensor ${name}$: $p_{name}$", p, xytext=(6, 6), textcoords="offset points")
        normal = side * np.array([-np.sin(th), np.cos(th)])
        ax.text(*(0.7 * p + 0.09 * lim * normal), f"${d}$", color=col, ha="center", va="center")
    for r, t0, t1, label, col in (
        (0.22 * lim, 0.0, theta_i, r"$\theta_i$", "C0"),
        (0.34 * lim, 0.0, theta_j, r"$\theta_j$", "C1"),
        (0.5 * lim, theta_i, theta_j, r"$\theta_{ji}$", "k"),
    ):
        t = np.linspace(t0, t1, 60)
        ax.plot(r * np.cos(t), r * np.sin(t), color=col, lw=1)
        tm = t0 + 0.55 * (t1 - t0) if label != r"$\theta_i$" else t1 + 0.25
        rr = 1.15 * r if label != r"$\theta_i$" else 0.8 * r
        ax.text(rr * np.cos(tm), rr * np.sin(tm), label, color=col, ha="center", va="center")
    ax.plot(0, 0, marker="*", ms=16, color="k", ls="none")
    ax.annotate("target $o$", (0, 0), xytext=(6, -14), textcoords="offset points")
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-0.45 * lim, lim)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    return ax


def _even_stride(n: int, most: int = 80) -> int:
    """Smallest stride dividing ``n - 1`` that leaves at most ``most`` cells (else the rounded-up
    stride). Equal cells keep ``plot_surface``'s polygons equal in length: matplotlib fills the
    unused vertices of ragged polygons from ``np.empty``, which can raise spurious overflow
    warnings."""
    cells = max(n - 1, 1)
    for d in range(1, cells + 1):
        if cells % d == 0 and cells // d <= most:
            return d if cells // d > 1 or cells <= most else int(np.ceil(cells / most))
    return int(np.ceil(cells / most))


def plot_fig2(alpha, theta, Z, levels, title: str = "", mark=None, panels: str = "all"):
    r"""Fig. 2's four panels: surface (a) and contour (b) over :math:`(\alpha, \theta)`, surface (c)
    and contour (d) over :math:`(\alpha \cos\theta, \alpha \sin\theta)`.

    Parameters
    ----------
    alpha, theta : 1-D arrays
        Grid axes; ``Z`` has shape ``(len(theta), len(alpha))`` (:func:`obslib.pair_form.bound_surface`).
    levels : sequence of float
        Contour levels (Fig. 2: 0.1 ... 0.7).
    title : str
        Figure title.
    mark : GridMax, optional
        Grid maxima to mark with red stars.
    panels : {"all", "contour"}
        ``"contour"`` draws only the contour panels (b) and (d), side by side (the 3D surfaces
        take most of the rendering time and show nothing the contours do not).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")  # no window
    >>> from obslib.pair_form import bound_surface, fine_grid, grid_maximum
    >>> alpha, theta = fine_grid(alpha_max=5.0, alpha_per_unit=10, theta_quarter=8)
    >>> Z = bound_surface(alpha, theta, u_max=1.0, d_io=1.0)
    >>> mark = grid_maximum(alpha, theta, Z)
    >>> fig = plot_fig2(alpha, theta, Z, [0.1, 0.3, 0.5, 0.7], mark=mark,
    ...                 panels="contour")
    >>> [ax.get_title() for ax in fig.axes]
    ['(b) contour', '(d) contour']
    """
    import matplotlib as mpl
    import matplotlib.pyplot as plt

    if panels not in ("all", "contour"):
        raise ValueError(f"panels must be 'all' or 'contour', got {panels!r}")
    a = np.asarray(alpha, dtype=float)
    t = np.asarray(theta, dtype=float)
    Z = np.asarray(Z, dtype=float)
    if Z.shape != (t.size, a.size):
        raise ValueError(f"Z must have shape {(t.size, a.size)}, got {Z.shape}")
    A, T = np.meshgrid(a, t)
    X, Y = A * np.cos(T), A * np.sin(T)
    surfaces = panels == "all"
    if surfaces:  # 3-D panels (a), (c) on the left, contours (b), (d) on the right
        fig = plt.figure(figsize=(8.9, 8.1))  # at most 9 in: the book column
        grid = fig.add_gridspec(2, 2, width_ratios=[1, 1.534])
    else:  # (b) wide, (d) square
        fig = plt.figure(figsize=(8.9, 4.3))
        grid = fig.add_gridspec(1, 2, width_ratios=[1.45, 1])
    rows = (
        ("(a)", A, T, r"$\alpha = d_{jo}/d_{io}$", r"$\theta_{ji}$ (rad)"),
        ("(c)", X, Y, r"$\alpha\cos\theta_{ji}$", r"$\alpha\sin\theta_{ji}$"),
    )
    for row, (tag, P, R, xl, yl) in enumerate(rows):
        if surfaces:
            # 3-D axes keep Matplotlib's automatic title height (it clears the rotated box),
            # whatever axes.titley says (obslib.notebook.setup_figures fixes it for 2-D axes)
            with mpl.rc_context({"axes.titley": None}):
                ax3 = fig.add_subplot(grid[row, 0], projection="3d")
                ax3.set_title(f"{tag} surface")
            ax3.plot_surface(P, R, Z, cmap="viridis", rstride=_even_stride(t.size),
                             cstride=_even_stride(a.size), linewidth=0)
            ax3.set_xlabel(xl)
            ax3.set_ylabel(yl)
            ax3.set_zlabel(r"$\underline{C}^{-1}$")
        ax2 = fig.add_subplot(grid[row, 1] if surfaces else grid[0, row])
        cs = ax2.contour(P, R, Z, levels=list(levels), cmap="viridis")
        ax2.clabel(cs, fontsize=9, fmt="%.1f")
        ax2.set_xlabel(xl)
        ax2.set_ylabel(yl)
        ax2.set_title(f"({'b' if row == 0 else 'd'}) contour")
        if row == 1:
            ax2.set_aspect("equal")
        if mark is not None:
            pts = np.array(mark.points)
            if row == 0:
                ax2.plot(pts[:, 0], pts[:, 1], "r*", ms=10)
            else:
                ax2.plot(pts[:, 0] * np.cos(pts[:, 1]), pts[:, 0] * np.sin(pts[:, 1]), "r*", ms=10)
    if title:
        fig.suptitle(title)
    # The layout is written down (found once with tight_layout; the 3-D panels' margins by eye):
    # tight_layout or bbox_inches="tight" would draw the figure once more just to measure it.
    if surfaces:
        fig.subplots_adjust(left=0.005, right=0.985, bottom=0.070, top=0.921 if title else 0.955,
                            wspace=0.266, hspace=0.243)
    else:
        fig.subplots_adjust(left=0.067, right=0.986, bottom=0.131, top=0.851 if title else 0.932,
                            wspace=0.185)
    return fig

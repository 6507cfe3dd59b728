"""Figures of the pair closed form (Theorems 4 and 5): two sensors seen from the target, the
geometry of Fig. 1, the four panels of Fig. 2, the maximising distance ratio, the printed
derivative at :math:`\\theta_{ji} = \\pi/2`, the derivative in :math:`\\alpha` at a fixed
angle, and the bound at a glance (the front page's picture)."""

from __future__ import annotations

import numpy as np

from .._validate import as_float_array, as_int, as_nonnegative, as_positive, as_real, as_str
from ..bounds import pair_bound_polar
from ..pair_form import dbound_dalpha, maximising_alpha, maximising_alpha_closed
from .model_and_bound import draw_rows
from .style import OKABE_ITO, SEQUENTIAL, as_axes, look

__all__ = ["INTUITION_PAIRS", "plot_pair_intuition", "plot_fig1", "plot_fig2",
           "plot_maximising_alpha", "plot_halfpi_derivative", "plot_dalpha_minimum",
           "GLANCE_SPEEDS", "plot_bound_at_a_glance"]

#: The three pairs of the intuition: ``(alpha, theta_ji, theta_ji in TeX)``, by name.
INTUITION_PAIRS = {
    "a perfect cross": (1.0, np.pi / 2, r"\pi/2"),
    "unequal distances": (2.0, np.pi / 2, r"\pi/2"),
    "nearly collinear": (1.0, np.pi / 8, r"\pi/8"),
}


def plot_pair_intuition(d_io: float = 1.0, u_max: float = 1.0):
    r"""Two sensors seen from the target, for each pair of :data:`INTUITION_PAIRS` (sensor
    :math:`i` at distance ``d_io`` and angle 0, sensor :math:`j` at :math:`\alpha d_{io}`):
    their rows :math:`o - p_i` as arrows, and the ellipse whose half-axes are the singular values
    of :math:`O(o)` (scaled by one half); each panel gives the pair's bound for ``u_max``.

    Examples
    --------
    With :math:`q = u_{\max}/d_{io} = 1` the bounds are :math:`1/\sqrt 2`, :math:`1/\sqrt 5`
    and, with the eigenvalues :math:`1 \pm \cos\theta` of the third pair,
    :math:`\sqrt{(1 - \cos\theta)/(2 + \cos\theta)}` at :math:`\theta = \pi/8`:

    >>> fig = plot_pair_intuition(d_io=1.0, u_max=1.0)
    >>> [ax.texts[-1].get_text() for ax in fig.axes]
    ['bound 0.71', 'bound 0.45', 'bound 0.16']
    """
    import matplotlib.pyplot as plt

    d_io = as_positive(d_io, "d_io")
    q = as_nonnegative(u_max, "u_max") / d_io
    phi = np.linspace(0, 2 * np.pi, 200)
    circle = np.array([np.cos(phi), np.sin(phi)])
    o = np.zeros(2)
    fig, axes = plt.subplots(1, 3, figsize=(7.5, 3.4))
    for ax, (name, (alpha, theta, label)) in zip(axes, INTUITION_PAIRS.items()):
        sensors = d_io * np.array([[1, 0], [alpha * np.cos(theta), alpha * np.sin(theta)]])
        lam, vec = np.linalg.eigh((sensors - o).T @ (sensors - o))
        gains = vec @ (np.sqrt(lam)[:, None] * (vec.T @ circle))  # half-axes sigma
        ax.fill(*(0.5 * gains), color=OKABE_ITO["orange"], alpha=0.4, lw=0)
        draw_rows(ax, sensors, o)
        ax.set_title(f"{name}\n$\\alpha = {alpha:g}$, $\\theta_{{ji}} = {label}$")
        bound = pair_bound_polar(alpha, theta, q)
        ax.text(0.96, 0.04, f"bound {bound:.2f}", transform=ax.transAxes, ha="right")
        ax.set_xlim(-1.3, 2.3)
        ax.set_ylim(-1.3, 2.3)
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)")
    axes[0].set_ylabel("y (m)")
    return fig


def plot_fig1(
    ax=None, d_io: float = 1.0, d_jo: float = 1.5, theta_i: float = 0.35, theta_j: float = 2.0
):
    r"""Fig. 1: sensors :math:`i, j` around the target in the polar coordinates of Eq. (8).

    The target is at the centre; sensor :math:`i` at distance :math:`d_{io}` and angle
    :math:`\theta_i`, sensor :math:`j` at :math:`d_{jo}` and :math:`\theta_j`;
    :math:`\theta_{ji} = \theta_j - \theta_i`. Returns the axes.

    Examples
    --------
    >>> ax = plot_fig1(d_io=1.0, d_jo=1.5, theta_i=0.35, theta_j=2.0)
    >>> ax.get_aspect()
    1.0
    """
    import matplotlib.pyplot as plt

    d_io = as_positive(d_io, "d_io")
    d_jo = as_positive(d_jo, "d_jo")
    theta_i, theta_j = as_real(theta_i, "theta_i"), as_real(theta_j, "theta_j")
    if ax is not None:
        as_axes(ax)
    if ax is None:
        fig, ax = plt.subplots(figsize=(4.1, 3), layout="constrained")
    pi_ = d_io * np.array([np.cos(theta_i), np.sin(theta_i)])
    pj_ = d_jo * np.array([np.cos(theta_j), np.sin(theta_j)])
    lim = 1.25 * max(d_io, d_jo)
    sensor, target = look("sensor"), look("target")
    ax.axhline(0, color="0.6", lw=0.8, ls="--")
    for p, th, name, d, col, side in ((pi_, theta_i, "i", "d_{io}", OKABE_ITO["blue"], -1.0),
                                      (pj_, theta_j, "j", "d_{jo}", OKABE_ITO["vermillion"], 1.0)):
        ax.plot([0, p[0]], [0, p[1]], color=col, lw=1.5)
        ax.plot(*p, **sensor.kw(color=col, label=None, ms=12))
        ax.annotate(f"sensor ${name}$: $p_{name}$", p, xytext=(6, 6), textcoords="offset points")
        normal = side * np.array([-np.sin(th), np.cos(th)])
        ax.text(*(0.7 * p + 0.09 * lim * normal), f"${d}$", color=col, ha="center", va="center")
    for r, t0, t1, label, col in (
        (0.22 * lim, 0.0, theta_i, r"$\theta_i$", OKABE_ITO["blue"]),
        (0.34 * lim, 0.0, theta_j, r"$\theta_j$", OKABE_ITO["vermillion"]),
        (0.5 * lim, theta_i, theta_j, r"$\theta_{ji}$", "k"),
    ):
        t = np.linspace(t0, t1, 60)
        ax.plot(r * np.cos(t), r * np.sin(t), color=col, lw=1)
        tm = t0 + 0.55 * (t1 - t0) if label != r"$\theta_i$" else t1 + 0.25
        rr = 1.15 * r if label != r"$\theta_i$" else 0.8 * r
        ax.text(rr * np.cos(tm), rr * np.sin(tm), label, color=col, ha="center", va="center")
    ax.plot(0, 0, **target.kw(label=None, ms=16))
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


def _ray_hits(cs, start, direction) -> list:
    """For each level of the contour set ``cs``, the distance along the ray from ``start`` in
    the unit ``direction`` (data units) to its first crossing of that level's lines, or None
    where the ray never crosses them."""
    d = as_float_array(direction, "direction")
    hits = []
    for path in cs.get_paths():
        best = None
        for poly in path.to_polygons(closed_only=False):
            p, e = poly[:-1], np.diff(poly, axis=0)
            w = p - start
            den = d[0] * e[:, 1] - d[1] * e[:, 0]  # start + s d = p + t e, by cross products
            with np.errstate(divide="ignore", invalid="ignore"):
                s = (w[:, 0] * e[:, 1] - w[:, 1] * e[:, 0]) / den
                t = (w[:, 0] * d[1] - w[:, 1] * d[0]) / den
            ok = (den != 0) & (t >= 0) & (t <= 1) & (s > 0)
            if ok.any():
                best = min(float(s[ok].min()), np.inf if best is None else best)
        hits.append(best)
    return hits


def _label_along_ray(ax, cs, start, direction, box_in, fontsize: float = 10.0,
                     mark_pt: float = 12.0):
    """Label the contour lines of ``cs`` where a ray from ``start`` (a marked maximum) in
    ``direction`` first crosses them, so that the labels stand in a row beside the mark instead
    of piling up around it; the labels are upright, on a white ground that hides the line.

    A label is left out where it would come within about its own size (along the ray) of the
    previous one, or within 6 pt of the mark (``mark_pt`` across), distances in inches with the
    axes taken as ``box_in`` = (width, height) in inches; the nested lines it would name lie
    between labelled ones. Levels the ray never crosses, or crosses less than a text height
    from the axes' edge, are labelled where matplotlib puts them.
    """
    start = as_float_array(start, "start")
    d = as_float_array(direction, "direction") / np.hypot(*direction)
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    per_unit = np.array([box_in[0] / (x1 - x0), box_in[1] / (y1 - y0)])  # inches per data unit
    step = np.hypot(*(d * per_unit))  # inches per unit along the ray
    along = np.abs(d * per_unit) / step  # the ray's direction on paper
    gap = (along[0] * 2.0 + along[1] * 1.4) * fontsize / 72  # a label "0.5": 2 em by 1.4 em

    def inside(p):  # at least one text height from every edge of the axes
        return min(p[0] - x0, x1 - p[0], p[1] - y0, y1 - p[1]) >= 0 and min(
            min(p[0] - x0, x1 - p[0]) * per_unit[0],
            min(p[1] - y0, y1 - p[1]) * per_unit[1]) >= fontsize / 72

    keep, rest, last = [], [], 0.0
    clear = gap / 2 + (mark_pt / 2 + 6) / 72  # the first label's centre from the mark's
    for level, s in sorted(zip(cs.levels, _ray_hits(cs, start, d)),
                           key=lambda h: np.inf if h[1] is None else h[1]):
        if s is None or not inside(start + s * d):
            rest.append(level)
        elif (s - last) * step >= (gap if keep else clear):
            keep.append((level, start + s * d))
            last = s
    texts = []
    if keep:
        texts += ax.clabel(cs, [lv for lv, _ in keep], manual=[tuple(p) for _, p in keep],
                           inline=False, fontsize=fontsize, fmt="%.1f")
    if rest:
        texts += ax.clabel(cs, rest, inline=False, fontsize=fontsize, fmt="%.1f")
    for text in texts:
        text.set_rotation(0)
        text.set_bbox({"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none"})


def plot_fig2(alpha, theta, Z, levels, title: str = "", mark=None, panels: str = "all"):
    r"""Fig. 2's four panels: surface (a) and contour (b) over :math:`(\alpha, \theta)`, surface (c)
    and contour (d) over :math:`(\alpha \cos\theta, \alpha \sin\theta)`.

    The contour labels stand upright in a row beside the upper maximum (along
    :math:`\theta = \theta^*` in (b), straight up in (d)); where the lines crowd near the
    maximum some are left unlabelled, and they take their values in order between the labelled
    ones. The figure is
    7.5 in wide, laid out by matplotlib's constrained layout.

    Parameters
    ----------
    alpha, theta : 1-D arrays
        Grid axes; ``Z`` has shape ``(len(theta), len(alpha))``
        (:func:`obslib.pair_form.bound_surface`).
    levels : sequence of float
        Contour levels (Fig. 2: 0.1 ... 0.7).
    title : str
        Figure title.
    mark : GridMax, optional
        Grid maxima to mark with stars (the look ``maximum`` of :mod:`obslib.viz.style`).
    panels : {"all", "contour"}
        ``"contour"`` draws only the contour panels (b) and (d), side by side (the 3D surfaces
        take most of the rendering time and show nothing the contours do not).

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
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
    from matplotlib.ticker import MaxNLocator

    if as_str(panels, "panels") not in ("all", "contour"):
        raise ValueError(f"panels must be 'all' or 'contour', got {panels!r}")
    a = as_float_array(alpha, "alpha")
    t = as_float_array(theta, "theta")
    Z = as_float_array(Z, "Z")
    if Z.shape != (t.size, a.size) or a.ndim != 1 or t.ndim != 1:
        raise ValueError(f"Z must have shape (len(theta), len(alpha)) = {(t.size, a.size)}, "
                         f"got {Z.shape}")
    for name, x in (("alpha", a), ("theta", t), ("Z", Z)):
        if not np.isfinite(x).all():
            raise ValueError(f"{name} must be finite")
    levels = as_float_array(levels, "levels")
    if levels.ndim != 1 or not np.isfinite(levels).all() or (np.diff(levels) <= 0).any():
        raise ValueError("levels must be finite and increasing")
    as_str(title, "title")
    A, T = np.meshgrid(a, t)
    X, Y = A * np.cos(T), A * np.sin(T)
    if mark is not None:
        pts = np.array(mark.points, dtype=float)
    else:
        k = np.unravel_index(np.argmax(Z), Z.shape)
        pts = np.array([[a[k[1]], t[k[0]]]])
    top = pts[np.argmax(pts[:, 1])]  # the labels stand beside the upper maximum
    surfaces = panels == "all"
    width = 7.5  # the book's rule: at most 7.5 in wide (obsbook.figures)
    if surfaces:  # 3-D panels (a), (c) on the left, contours (b), (d) on the right
        fig = plt.figure(figsize=(width, 7.6), layout="constrained")
        grid = fig.add_gridspec(2, 2, width_ratios=[1, 1.15])
        boxes = ((3.3, 2.9), (2.9, 2.9))  # the contour axes' size, about (in)
    else:  # (b) wide, (d) square
        fig = plt.figure(figsize=(width, 3.7), layout="constrained")
        grid = fig.add_gridspec(1, 2, width_ratios=[1.45, 1])
        boxes = ((3.9, 2.9), (2.8, 2.8))
    rows = (
        ("(a)", A, T, r"$\alpha = d_{jo}/d_{io}$", r"$\theta_{ji}$ (rad)", top, (1.0, 0.0)),
        ("(c)", X, Y, r"$\alpha\cos\theta_{ji}$", r"$\alpha\sin\theta_{ji}$",
         top[0] * np.array([np.cos(top[1]), np.sin(top[1])]), (0.0, 1.0)),
    )
    star = look("maximum").kw(label=None, ms=12, mec="white", mew=0.8, zorder=5)
    for row, (tag, P, R, xl, yl, start, ray) in enumerate(rows):
        if surfaces:
            # 3-D axes keep Matplotlib's automatic title height (it clears the rotated box),
            # whatever axes.titley says (obsbook.setup fixes it for 2-D axes)
            with mpl.rc_context({"axes.titley": None}):
                ax3 = fig.add_subplot(grid[row, 0], projection="3d")
                ax3.set_title(f"{tag} surface of " + r"$\underline{C}^{-1}$")
            ax3.plot_surface(P, R, Z, cmap=SEQUENTIAL, rstride=_even_stride(t.size),
                             cstride=_even_stride(a.size), linewidth=0)
            ax3.set_xlabel(xl)
            ax3.set_ylabel(yl)
            for axis in (ax3.xaxis, ax3.yaxis, ax3.zaxis):  # few ticks: the axes are foreshortened
                axis.set_major_locator(MaxNLocator(4, steps=[1, 2, 5, 10]))
            # no z label: constrained layout leaves no room for the z label of 3-D axes, which
            # then runs into the contour panel's y label; the title names the quantity
        ax2 = fig.add_subplot(grid[row, 1] if surfaces else grid[0, row])
        cs = ax2.contour(P, R, Z, levels=list(levels), cmap=SEQUENTIAL)
        ax2.set_xlabel(xl)
        ax2.set_ylabel(yl)
        ax2.set_title(f"({'b' if row == 0 else 'd'}) contour")
        if row == 1:
            ax2.set_aspect("equal")
        _label_along_ray(ax2, cs, start, ray, boxes[row])
        if row == 0:
            ax2.plot(pts[:, 0], pts[:, 1], **star)
        else:
            ax2.plot(pts[:, 0] * np.cos(pts[:, 1]), pts[:, 0] * np.sin(pts[:, 1]), **star)
    if title:
        fig.suptitle(title)
    return fig


def plot_maximising_alpha(n_theta: int, u_over_d):
    r"""The distance ratio :math:`\alpha^*` that maximises the bound for a fixed angle
    :math:`\theta_{ji}`, for a stationary target and for each speed :math:`q = u_{\max}/d_{io}`
    of ``u_over_d``: the numerical root of Eq. (34) as lines, the closed form as dots, on the
    ``n_theta`` angles of :func:`obslib.studies.pair_closed_form.alpha_star_thetas`.

    Examples
    --------
    >>> fig = plot_maximising_alpha(23, [0.5, 1.0])
    >>> len(fig.axes[0].get_legend().get_texts())
    3
    """
    import matplotlib.pyplot as plt

    from ..studies.pair_closed_form import alpha_star_thetas

    theta_c = alpha_star_thetas(n_theta)  # the angles of the audit
    curves = as_float_array(u_over_d, "u_over_d")
    if curves.ndim != 1 or not np.isfinite(curves).all() or (curves < 0).any():
        raise ValueError("u_over_d must be a list of finite non-negative speeds")
    fig, ax = plt.subplots(figsize=(7.5, 4))
    for q in (0.0, *curves.tolist()):
        label = f"$u_{{max}}/d_{{io}} = {q:g}$"
        ax.plot(theta_c, maximising_alpha(theta_c, q), label=label)
        ax.plot(theta_c[::12], maximising_alpha_closed(theta_c[::12], q), "k.", ms=4)
    ax.set_xlabel(r"$\theta_{ji}$ (rad)")
    ax.set_ylabel(r"maximising $\alpha^* = d_{jo}/d_{io}$")
    ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return fig


def plot_halfpi_derivative(alpha_max: float = 4.0, n: int = 801):
    r"""The bound at :math:`\theta_{ji} = \pi/2`, :math:`q = 1`, over :math:`\alpha` from 0 to
    ``alpha_max`` (``n`` points; a corner at :math:`\alpha = 1`), and its derivative in
    :math:`\alpha` against the expression the proof prints.

    Examples
    --------
    >>> fig = plot_halfpi_derivative(n=41)
    >>> fig.axes[1].get_legend().get_texts()[1].get_text()
    'printed expression'
    """
    import matplotlib.pyplot as plt
    import sympy as sp

    from .. import symbolic

    alpha_line = np.linspace(0, as_positive(alpha_max, "alpha_max"), as_int(n, "n", 2))
    dC = sp.diff(symbolic.bound_halfpi_piecewise(), symbolic.ALPHA).subs(symbolic.Q, 1)
    true_d = symbolic.lambdify_expr(dC, (symbolic.ALPHA,))(alpha_line)
    printed = symbolic.printed_dbound_dalpha_halfpi().subs(symbolic.Q, 1)
    printed_d = symbolic.lambdify_expr(printed, (symbolic.ALPHA,))(alpha_line)
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(7.5, 3.6))
    ax0.plot(alpha_line, pair_bound_polar(alpha_line, np.pi / 2, 1.0))
    ax0.axvline(1, color="0.6", ls=":")
    ax0.set_xlabel(r"$\alpha = d_{jo}/d_{io}$")
    ax0.set_ylabel(r"$C(\alpha, \pi/2)$")
    ax0.set_title(r"$C(\alpha, \pi/2)$, $q = 1$: a corner at $\alpha = 1$")
    ax1.plot(alpha_line, true_d, label=r"true $\partial C/\partial\alpha$")
    ax1.plot(alpha_line, printed_d, "--", label="printed expression")
    ax1.axhline(0, color="0.6", lw=0.8)
    ax1.set_xlabel(r"$\alpha = d_{jo}/d_{io}$")
    ax1.set_ylabel(r"$\partial C/\partial\alpha$")
    ax1.legend(loc="lower right")
    ax1.set_title(r"derivative at $\theta = \pi/2$, $q = 1$")
    return fig


def plot_dalpha_minimum(theta: float = np.pi / 4, u_over_d=(0.0, 1.0), n: int = 800):
    r"""The derivative :math:`\partial C/\partial\alpha` of the pair bound over
    :math:`\alpha \in [10^{-2}, 10^{2}]` (``n`` points spaced evenly in :math:`\log\alpha`) at
    the angle ``theta``, one curve per speed :math:`q = u_{\max}/d_{io}` of ``u_over_d``: a dot
    where it crosses zero, at the maximiser :math:`\alpha^*` of the bound, and a cross at its
    smallest value on the grid.

    Examples
    --------
    >>> fig = plot_dalpha_minimum(n=200)
    >>> [t.get_text() for t in fig.axes[0].get_legend().get_texts()][:2]
    ['$q = 0$', '$q = 1$']
    """
    import matplotlib.pyplot as plt

    theta = as_real(theta, "theta")
    qs = as_float_array(u_over_d, "u_over_d")
    if qs.ndim != 1 or qs.size == 0 or not np.isfinite(qs).all() or (qs < 0).any():
        raise ValueError("u_over_d must be a non-empty list of finite non-negative speeds")
    a = np.geomspace(1e-2, 1e2, as_int(n, "n", 2))
    fig, ax = plt.subplots(figsize=(7.5, 3.8))
    for k, q in enumerate(qs.tolist()):
        d = dbound_dalpha(a, theta, q)
        colour = list(OKABE_ITO.values())[k % len(OKABE_ITO)]
        ax.semilogx(a, d, color=colour, label=f"$q = {q:g}$")
        star = float(maximising_alpha(theta, q))
        ax.plot(star, 0.0, "o", color=colour, ms=7)
        j = int(np.argmin(d))
        ax.plot(a[j], d[j], "x", color=colour, ms=9, mew=2)
    ax.axhline(0, color="0.6", lw=0.8)
    ax.plot([], [], "ko", ms=6, label=r"$\alpha^*$: $C$ largest")
    ax.plot([], [], "kx", ms=7, mew=2, label=r"$\partial C/\partial\alpha$ smallest")
    ax.set_xlabel(r"$\alpha = d_{jo}/d_{io}$")
    ax.set_ylabel(r"$\partial C/\partial\alpha$")
    ax.legend(loc="upper right")
    return fig


#: The speeds :math:`q = u_{\max}/d_{io}` of the front page's bound-against-angle panel.
GLANCE_SPEEDS = (0.0, 0.5, 1.0, 2.0)


def plot_bound_at_a_glance(theta: float = 2 * np.pi / 5, u_over_d=GLANCE_SPEEDS,
                           n: int = 361):
    r"""The idea of the bound at a glance. Left: a target with two range sensors at the same
    distance, the angle ``theta`` between them as the target sees them, and the disc of
    velocities the target may have, :math:`\lVert u_o\rVert \le u_{\max}` (drawn for
    :math:`q = 1`), with the worst one along the direction the sensors see best. Right: the
    pair bound (Theorem 4, :math:`\alpha = 1`) against the angle between the sensors for each
    speed :math:`q = u_{\max}/d_{io}` of ``u_over_d``, largest, :math:`1/\sqrt{1 + q^2}`, at a
    right angle (``n`` angles from 0 to 180 degrees).

    Examples
    --------
    >>> fig = plot_bound_at_a_glance(n=37)
    >>> fig.axes[1].get_xlabel()
    'angle between the sensors (degrees)'
    >>> round(float(max(fig.axes[1].lines[0].get_ydata())), 6)  # q = 0: a cross
    1.0
    """
    import matplotlib.pyplot as plt
    from matplotlib.patches import Arc, Circle

    theta = as_real(theta, "theta")
    if not 0 < theta < np.pi:
        raise ValueError(f"theta must lie in (0, pi), got {theta}")
    qs = as_float_array(u_over_d, "u_over_d")
    if qs.ndim != 1 or qs.size == 0 or not np.isfinite(qs).all() or (qs < 0).any():
        raise ValueError("u_over_d must be a non-empty list of finite non-negative speeds")
    n = as_int(n, "n", 3)
    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(6.4, 2.8),
                                   gridspec_kw={"width_ratios": (1.0, 1.25)})
    # left: the scene, two sensors at distance 1 seen at the angle theta from the target
    o = np.zeros(2)
    half = theta / 2
    sensors = np.array([[-np.cos(half), np.sin(half)], [-np.cos(half), -np.sin(half)]])
    radius = 0.45  # the disc of velocities, drawn to the scale of the scene
    ax0.add_patch(Circle(o, radius, color=OKABE_ITO["orange"], alpha=0.25, lw=0))
    ax0.add_patch(Circle(o, radius, fill=False, ls="--", color=OKABE_ITO["vermillion"], lw=1.2))
    draw_rows(ax0, sensors, o)
    rows = o - sensors
    v = np.linalg.eigh(rows.T @ rows)[1][:, -1]  # the direction the sensors see best
    v = v * (np.sign(v[0]) or 1.0)
    ax0.annotate("", radius * v, o, arrowprops=dict(arrowstyle="->", lw=1.8,
                                                    color=OKABE_ITO["vermillion"]))
    ax0.add_patch(Arc(o, 1.3, 1.3, theta1=180 - np.degrees(half), theta2=180 + np.degrees(half),
                      color="0.3", lw=1.0))
    ax0.text(-0.72, 0.0, r"$\theta_{ji}$", va="center", ha="right")
    ax0.text(0.62, 0.62, "unknown\nvelocity\n" + r"$|u_o| \leq u_{\max}$", ha="center",
             va="bottom", color=OKABE_ITO["vermillion"])
    for k, p in enumerate(sensors):
        ax0.text(*(1.18 * p), f"$s_{k + 1}$", ha="center", va="center")
    ax0.set_xlim(-1.25, 1.15)
    ax0.set_ylim(-1.1, 1.3)
    ax0.set_aspect("equal")
    ax0.set_xlabel("x (m)")
    ax0.set_ylabel("y (m)")
    ax0.set_title("two range sensors, one target")
    # right: the bound against the angle, equal distances
    ang = np.linspace(0.0, np.pi, n)
    for k, q in enumerate(qs.tolist()):
        colour = list(OKABE_ITO.values())[k % len(OKABE_ITO)]
        ax1.plot(np.degrees(ang), pair_bound_polar(1.0, ang, q), color=colour,
                 label=f"$q = {q:g}$")
        ax1.plot(90.0, 1 / np.sqrt(1 + q * q), "o", color=colour, ms=5)
    ax1.axvline(90.0, color="0.6", ls=":", lw=1.0)
    ax1.set_xticks([0, 45, 90, 135, 180])
    ax1.set_xlim(0, 180)
    ax1.set_ylim(0, 1.05)
    ax1.set_xlabel("angle between the sensors (degrees)")
    ax1.set_ylabel(r"bound on $C^{-1}$")
    ax1.set_title("the pair bound, equal distances")
    ax1.legend(title=r"$q = u_{\max}/d_{io}$", loc="upper right", fontsize=10)
    return fig

"""Drawings of tracking runs (Section V): the Fig. 4 snapshot, labelled sensors, covariance
ellipses, the animation player of a run, and the published runs of Figs. 4-7 drawn under their
replays (:func:`draw_published_overlay`, :func:`draw_pair_overlay`,
:func:`draw_switch_overlay`).

Nothing outside :mod:`obslib.viz` imports matplotlib; the functions here import it on first use.
"""

from __future__ import annotations

import numpy as np

from .._validate import (
    as_bool,
    as_float_array,
    as_instance,
    as_int,
    as_nonnegative,
    as_point,
    as_points,
    as_positive,
    as_str,
)
from ..tracking import TrackingResult
from .style import (
    LOOKS,
    PUBLISHED_STYLE,
    REPLAY_STYLE,
    as_axes,
    as_figsize,
    look,
    sensor_label,
)

__all__ = [
    "STRATEGY_LABELS",
    "CHI2_2DOF_9973",
    "cov_ellipse",
    "draw_sensors",
    "draw_snapshot",
    "RunAnimation",
    "animate",
    "animation_html",
    "PUBLISHED_STYLE",
    "REPLAY_STYLE",
    "draw_published_overlay",
    "draw_pair_overlay",
    "draw_switch_overlay",
]

#: How the figures and tables of Section V name the paper's three strategies.
STRATEGY_LABELS = {
    "best-pair": "(1) best pair",
    "best-partner": "(2) best partner of s₂",
    "fixed-pair": "(3) fixed pair (s₂, s₁)",
}

#: Chi-square quantile, 2 degrees of freedom, 99.73 % (the "3 sigma" ellipse of Fig. 4).
CHI2_2DOF_9973 = 11.82


def cov_ellipse(mean, cov, chi2: float = CHI2_2DOF_9973, n: int = 100) -> np.ndarray:
    """Boundary of :math:`\\{x : (x - \\mu)^T \\Sigma^{-1} (x - \\mu) \\le \\chi^2\\}` (``mean``,
    ``cov``, ``chi2``), ``(n, 2)`` points.

    The default ``chi2 = 11.82`` is the 99.73 % ellipse of Fig. 4.

    Examples
    --------
    With :math:`\\\\chi^2 = 1` the points satisfy :math:`x^2/4 + y^2 = 1` for
    :math:`\\\\Sigma = \\\\operatorname{diag}(4, 1)`:

    >>> import numpy as np
    >>> from obslib.viz.tracking import cov_ellipse
    >>> e = cov_ellipse([0.0, 0.0], np.diag([4.0, 1.0]), chi2=1.0, n=50)
    >>> e.shape, bool(np.allclose(e[:, 0] ** 2 / 4 + e[:, 1] ** 2, 1.0))
    ((50, 2), True)
    """
    mean = as_point(mean, "mean")
    cov = as_float_array(cov, "cov")
    if cov.shape != (2, 2) or not np.isfinite(cov).all():
        raise ValueError(f"cov must be a finite 2 x 2 matrix, got shape {cov.shape}")
    chi2, n = as_nonnegative(chi2, "chi2"), as_int(n, "n", 2)
    w, v = np.linalg.eigh(cov)
    t = np.linspace(0, 2 * np.pi, n)
    circle = np.column_stack([np.cos(t), np.sin(t)])
    return mean + (circle * np.sqrt(chi2 * np.clip(w, 0, None))) @ v.T


def draw_sensors(ax, sensors, *, ms: float = 8, label: str | None = None):
    """Sensors as triangles (the look ``sensor`` of :mod:`obslib.viz.style`) named
    ``s1..sN`` (:func:`~obslib.viz.style.sensor_label`) on ``ax``; ``label`` is their legend
    entry (none if None).

    The names stand above and right of the triangles, so the axes keep at least 12 % of their
    data height free above the highest point (``ax.set_ymargin``): the top sensor's name stays
    inside the axes, clear of the title.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> from obslib.viz.tracking import draw_sensors
    >>> fig, ax = plt.subplots()
    >>> draw_sensors(ax, [[0.0, 0.0], [1.0, 1.0]])
    >>> [t.get_text() for t in ax.texts]
    ['s₁', 's₂']
    >>> plt.close(fig)
    """
    as_axes(ax)
    s = as_points(sensors, "sensors")
    ms = as_positive(ms, "ms")
    if label is not None:
        as_str(label, "label")
    ax.plot(*s.T, **look("sensor").kw(ms=ms, label=label or "_sensors"))
    ax.set_ymargin(max(ax.get_ymargin(), 0.12))
    for n, p in enumerate(s):
        ax.annotate(sensor_label(n), p, textcoords="offset points", xytext=(4, 4), fontsize=10)


def draw_snapshot(ax, result, k: int, *, legend: bool = True, ellipse_scale=1.0):
    """Draw step ``k`` (1-based) of a run as in Fig. 4 on ``ax``.

    Sensors (labelled ``s1..sN``), the true path so far and the target, the estimate with its
    99.73 % covariance ellipse (scaled by ``ellipse_scale`` if wanted for visibility) and lines
    from the chosen pair to the estimate, each in its look of :mod:`obslib.viz.style` and each
    with a legend entry. Returns the axes.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> from obslib import tracking
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=5)
    >>> ax = Figure().add_subplot()
    >>> _ = draw_snapshot(ax, tracking.simulate(setup, "best-pair", seed=0), 3)
    >>> ax.get_title().startswith("k = 3"), len(ax.texts)
    (True, 6)
    """
    as_axes(ax)
    as_instance(result, TrackingResult, "result")
    k = as_int(k, "k", 1)
    if k > result.pairs.shape[0]:
        raise ValueError(f"k must be a step of the run, 1..{result.pairs.shape[0]}, got {k}")
    as_bool(legend, "legend")
    ellipse_scale = as_positive(ellipse_scale, "ellipse_scale")
    i = k - 1
    s = result.setup.sensor_array
    draw_sensors(ax, s, label="sensors")
    a, b = s[result.pairs[i]]
    e = result.estimate[i]
    ax.plot([a[0], e[0], b[0]], [a[1], e[1], b[1]], **look("chosen-pair").kw(lw=1))
    ax.plot(*result.truth[: i + 1].T, **look("truth").kw(lw=1))
    ax.plot(*result.truth[i], **look("target").kw(ms=9, label="target o\u2096"))
    ax.plot(*e, **look("estimate").kw(ms=7, label="estimate \u00f4\u2096"))
    ax.plot(*cov_ellipse(e, ellipse_scale**2 * result.cov[i]).T, **look("ellipse").kw(lw=1))
    ax.set_aspect("equal")
    i0, j0 = result.pairs[i]
    ax.set_title(f"k = {k}, pair ({sensor_label(i0)}, {sensor_label(j0)})", fontsize=10)
    if legend:
        ax.legend(loc="lower left")
    return ax


class RunAnimation:
    """An animation of a tracking run (:func:`animate`), rendered by blitting.

    The static part (axes, sensors, labels) is drawn once; each frame restores it and draws only
    the moving artists (chosen pair, true path, target, estimate, ellipse, caption), then keeps
    the canvas as a PNG. :meth:`to_jshtml` wraps the frames in matplotlib's JavaScript player
    (:class:`matplotlib.animation.HTMLWriter`), like ``FuncAnimation.to_jshtml``;
    :meth:`func_animation` gives a :class:`matplotlib.animation.FuncAnimation` of the same frames
    for other writers.

    Attributes
    ----------
    fig : matplotlib.figure.Figure
        The (closed) figure.
    frames : list of int
        The steps shown (1-based).
    interval : float
        Milliseconds per frame.
    """

    def __init__(self, fig, update, artists, frames, interval):
        self.fig = fig
        self.frames = list(frames)
        self.interval = float(interval)
        self._update = update
        self._artists = tuple(artists)
        self._html = None

    def draw(self, k: int):
        """Set the moving artists to step ``k``; returns them."""
        self._update(k)
        return self._artists

    def png_frames(self) -> list:
        """Every frame as PNG bytes (blitting on an Agg canvas)."""
        from io import BytesIO

        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from PIL import Image

        canvas = FigureCanvasAgg(self.fig)
        for a in self._artists:
            a.set_animated(True)
        canvas.draw()  # everything but the moving artists
        background = canvas.copy_from_bbox(self.fig.bbox)
        out = []
        for k in self.frames:
            self.draw(k)
            canvas.restore_region(background)
            for a in self._artists:
                self.fig.draw_artist(a)
            w, h = canvas.get_width_height(physical=True)
            img = Image.frombuffer("RGBA", (w, h), canvas.buffer_rgba(), "raw", "RGBA", 0, 1)
            # the figure is opaque; 64 colours (fast octree, no dithering) keep the frames sharp
            # and about three times smaller than full RGB, so the stored page stays small
            img = img.convert("RGB").quantize(64, method=Image.Quantize.FASTOCTREE,
                                              dither=Image.Dither.NONE)
            f = BytesIO()
            img.save(f, format="png", compress_level=6)
            out.append(f.getvalue())
        return out

    def to_jshtml(self, default_mode: str = "loop") -> str:
        """HTML/JS player with the frames embedded (matplotlib's ``HTMLWriter`` template)."""
        if self._html is None:
            import base64
            import tempfile
            from pathlib import Path

            from matplotlib.animation import HTMLWriter

            frames = self.png_frames()

            class _Writer(HTMLWriter):
                def grab_frame(self, **kwargs):
                    self._saved_frames.append(base64.encodebytes(frames.pop(0)).decode("ascii"))

            with tempfile.TemporaryDirectory() as tmp:
                path = Path(tmp, "anim.html")
                writer = _Writer(fps=1000.0 / self.interval, embed_frames=True,
                                 default_mode=default_mode)
                writer.setup(self.fig, path, dpi=self.fig.dpi)
                for _ in self.frames:
                    writer.grab_frame()
                writer.finish()
                self._html = path.read_text()
        return self._html

    def _repr_html_(self):
        return self.to_jshtml()

    def func_animation(self):
        """The same frames as a :class:`matplotlib.animation.FuncAnimation` (blitted)."""
        from matplotlib.animation import FuncAnimation

        return FuncAnimation(self.fig, self.draw, frames=self.frames, interval=self.interval,
                             blit=True)


def animate(result, every: int = 3, dpi: int = 100, figsize=(7.5, 3.6), interval=120):
    """An animation of a run (:class:`RunAnimation`): every ``every``-th step and the last.

    Left, the map: what :func:`draw_snapshot` draws (Fig. 4): sensors, the chosen pair's lines
    to the estimate, the true path so far and the target, the estimate and its 99.73 %
    covariance ellipse, with the step and pair as the title. Right, the lower bound on
    :math:`C^{-1}` of the chosen pair over the whole run (faint), the part played so far and a
    marker at the current step, in the colour of the run's strategy. The default size is 750 px
    wide (7.5 in at 100 dpi), laid out by constrained layout. Show it in
    a notebook with ``IPython.display.HTML(animation_html(anim))``; the figure is closed so that
    it is not also shown as a still.

    Examples
    --------
    Every second step and the last:

    >>> from obslib import tracking
    >>> from obslib.viz.tracking import animate
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=6)
    >>> r = tracking.simulate(setup, "best-pair", seed=0)
    >>> animate(r, every=2, dpi=30).frames
    [1, 3, 5, 6]
    """
    import matplotlib.pyplot as plt

    as_instance(result, TrackingResult, "result")
    every = as_int(every, "every", 1)
    dpi = as_positive(dpi, "dpi")
    figsize = as_figsize(figsize)
    interval = as_positive(interval, "interval")
    s = result.setup.sensor_array
    fig, (ax, axb) = plt.subplots(1, 2, figsize=figsize, dpi=dpi, layout="constrained",
                                  gridspec_kw={"width_ratios": [1, 1.15]})
    pts = np.vstack([s, result.truth, result.estimate])
    lo, hi = pts.min(axis=0) - 1.0, pts.max(axis=0) + 1.0
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal")
    ax.set_xlabel("x (length unit)")
    ax.set_ylabel("y (length unit)")
    draw_sensors(ax, s, ms=7)
    (links,) = ax.plot([], [], **look("chosen-pair").kw(lw=1))
    (path,) = ax.plot([], [], **look("truth").kw(lw=1))
    (target,) = ax.plot([], [], **look("target").kw(ms=8))
    (est,) = ax.plot([], [], **look("estimate").kw(ms=6))
    (ell,) = ax.plot([], [], **look("ellipse").kw(lw=1))
    title = ax.set_title(" ")
    steps = np.arange(1, result.steps + 1)
    bound = np.asarray(result.bound, dtype=float)
    strategy = getattr(result, "strategy", None)
    color = LOOKS[strategy].color if strategy in LOOKS else None
    (whole,) = axb.plot(steps, bound, "-", color=color, lw=0.8, alpha=0.25)
    (played,) = axb.plot([], [], "-", color=whole.get_color(), lw=1)
    (now,) = axb.plot([], [], "o", color=whole.get_color(), ms=6)
    axb.set_xlim(0, result.steps + 1)
    axb.set_ylim(0, 1.05 * max(1.0, float(np.nanmax(bound))))
    axb.set_xlabel("step k")
    axb.set_ylabel("lower bound on C\u207b\u00b9")
    axb.set_title("bound of the chosen pair")
    frames = list(range(1, result.steps + 1, int(every)))
    if frames[-1] != result.steps:
        frames.append(result.steps)

    def frame(k):
        i = k - 1
        e = result.estimate[i]
        a, b = s[result.pairs[i]]
        links.set_data([a[0], e[0], b[0]], [a[1], e[1], b[1]])
        path.set_data(*result.truth[: i + 1].T)
        target.set_data([result.truth[i, 0]], [result.truth[i, 1]])
        est.set_data([e[0]], [e[1]])
        ell.set_data(*cov_ellipse(e, result.cov[i]).T)
        played.set_data(steps[: i + 1], bound[: i + 1])
        now.set_data([k], [bound[i]])
        i0, j0 = result.pairs[i]
        title.set_text(f"k = {k}, pair ({sensor_label(i0)}, {sensor_label(j0)})")

    plt.close(fig)
    artists = (links, path, target, est, ell, played, now, title)
    return RunAnimation(fig, frame, artists, frames, interval)


def animation_html(anim, uid: str = "anim") -> str:
    """Self-contained, stable HTML/JS for an animation (``anim.to_jshtml()``): a
    :class:`RunAnimation` or a matplotlib animation.

    ``to_jshtml`` names its elements with a random id and links Font Awesome from a CDN for its
    buttons. The id is replaced by ``uid`` so the stored notebook does not change from run to
    run, and the external stylesheet is dropped so the page fetches nothing at view time (the
    book's theme ships Font Awesome itself).

    Examples
    --------
    >>> from obslib import tracking
    >>> from obslib.viz.tracking import animate, animation_html
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=3)
    >>> r = tracking.simulate(setup, "best-pair", seed=0)
    >>> html = animation_html(animate(r, dpi=30), uid="demo")
    >>> 'id="_anim_imgdemo"' in html, "//cdn" in html
    (True, False)
    """
    import re

    if not hasattr(anim, "to_jshtml"):
        raise ValueError(f"anim must be an animation (animate()), got {type(anim).__name__}")
    as_str(uid, "uid")
    fig = getattr(anim, "_fig", None)  # a matplotlib animation's figure
    canvas = None if fig is None else fig.canvas
    if canvas is not None and not hasattr(canvas, "get_renderer"):
        # plt.close(fig) leaves a bare FigureCanvasBase: then every frame's savefig, and every
        # renderer lookup while drawing it (contour labels, legend), builds a new Agg canvas and
        # renderer, so cached text metrics and parsed mathtext are lost at each frame. One Agg
        # canvas for all frames draws the same pixels (its draw_idle stays a no-op, as on the
        # closed figure); notebook 02's six-frame player: 0.75 s against 0.89 s.
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        class FrameCanvas(FigureCanvasAgg):
            def draw_idle(self, *args, **kwargs):
                pass

        FrameCanvas(fig)
    try:
        html = anim.to_jshtml()
    finally:
        if canvas is not None:
            fig.set_canvas(canvas)
    m = re.search(r'id="_anim_img([0-9a-f]+)"', html)
    if m is None:
        raise ValueError("not the HTML of matplotlib's to_jshtml: no _anim_img element")
    html = html.replace(m.group(1), uid)
    return re.sub(r'<link[^>]*href="(?:https?:)?//[^"]*"[^>]*>\s*', "", html)


def _float_array(a, name: str, ndim: tuple) -> np.ndarray:
    out = as_float_array(a, name)
    if out.ndim not in ndim:
        raise ValueError(f"{name} must have {' or '.join(map(str, ndim))} dimensions, "
                         f"got shape {out.shape}")
    return out


def _overlay_iv(published, replay, x):
    pub = _float_array(published, "published", (1, 2))
    if pub.ndim == 2 and pub.shape[1] != 2:
        raise ValueError(f"a path must have shape (n, 2), got published {pub.shape}")
    if pub.ndim == 1 and x is None:
        raise ValueError("a series (1-D published) needs x, e.g. the steps 1..n")
    rep = None if replay is None else _float_array(replay, "replay", (pub.ndim,))
    if rep is not None and rep.shape[1:] != pub.shape[1:]:
        raise ValueError(f"replay {rep.shape} does not match published {pub.shape}")
    if x is not None:
        x = _float_array(x, "x", (1,))
        if x.size < max(pub.shape[0], 0 if rep is None else rep.shape[0]):
            raise ValueError(f"x has {x.size} values, fewer than the series")
    return pub, rep, x


def draw_published_overlay(ax, published, replay=None, *, x=None, color=None, label=None):
    """Draw a published curve (wide and pale) and its replay (thin, same colour) on ``ax``.

    Where the replay with the published noise gives the logged numbers, the thin line runs
    inside the pale band; a difference shows as the thin line leaving it.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    published : (n,) or (n, 2) array_like
        A logged series (against ``x``) or a path of points ``(x, y)``.
    replay : array_like or None
        The replay's series or path (it may be shorter than ``published``); None draws the
        published curve alone.
    x : (n,) array_like, optional
        Abscissae of a series, e.g. the steps ``k = 1..n``; required for a series.
    color : color, optional
        Colour of both curves (default: the axes' next colour).
    label : str, optional
        Legend entries ``"<label>, published"`` and ``"<label>, replay"``.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = Figure().add_subplot()
    >>> y = [0.5, 0.7, 0.6]
    >>> ax = draw_published_overlay(ax, y, y, x=[1, 2, 3], label="bound")
    >>> [line.get_label() for line in ax.get_lines()]
    ['bound, published', 'bound, replay']
    """
    as_axes(ax)
    pub, rep, x = _overlay_iv(published, replay, x)

    def xy(a):
        return (x[: a.shape[0]], a) if a.ndim == 1 else (a[:, 0], a[:, 1])

    lab = (lambda w: None) if label is None else (lambda w: f"{label}, {w}")
    (wide,) = ax.plot(*xy(pub), "-", color=color, label=lab("published"), **PUBLISHED_STYLE)
    if rep is not None:
        ax.plot(*xy(rep), "-", color=wide.get_color(), label=lab("replay"), **REPLAY_STYLE)
    return ax


def _codes_iv(a, name, n=None):
    out = _float_array(a, name, (1,))
    if n is not None and out.size != n:
        raise ValueError(f"{name} has {out.size} steps, published has {n}")
    return out


def draw_pair_overlay(ax, published, replay=None, *, color=None, label=None):
    """The pair (or partner) chosen at each step, as in Fig. 5: the published choice as large
    pale open circles, the replay's as small dots of the same colour inside them.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    published, replay : (n,) array_like
        A code per step ``k = 1..n`` of the chosen pair (e.g. its index in a list of pairs, or
        the partner sensor); the caller labels the y ticks. ``replay`` may be None.
    color : color, optional
        Default: the look ``best-pair`` of :mod:`obslib.viz.style`.
    label : str, optional
        Legend entries ``"<label>, published"`` and ``"<label>, replay"``.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = draw_pair_overlay(Figure().add_subplot(), [3, 3, 5], [3, 3, 5])
    >>> [line.get_ydata().tolist() for line in ax.get_lines()]
    [[3.0, 3.0, 5.0], [3.0, 3.0, 5.0]]
    """
    as_axes(ax)
    pub = _codes_iv(published, "published")
    rep = None if replay is None else _codes_iv(replay, "replay", pub.size)
    k = np.arange(1, pub.size + 1)
    color = look("best-pair").color if color is None else color
    lab = (lambda w: None) if label is None else (lambda w: f"{label}, {w}")
    ax.plot(k, pub, "o", mfc="none", mec=color, ms=5, mew=1.0, alpha=0.45,
            label=lab("published"))
    if rep is not None:
        ax.plot(k, rep, ".", color=color, ms=2.5, label=lab("replay"))
    return ax


def draw_switch_overlay(ax, published, replay=None, *, y=0.0, color="k", label="pair switch"):
    """Pair switches as ticks at height ``y`` (Fig. 7): the published run's as long pale ticks,
    the replay's as short dark ticks over them.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
    published, replay : (n,) array_like of bool
        Whether the pair changed at transition ``k -> k + 1`` (index ``k - 1``), as
        :attr:`obslib.tracking.TrackingResult.switched`; a tick is drawn at step ``k + 1``.
        ``replay`` may be None.
    y : float
        Height of the ticks (data units).
    color : color
    label : str, optional
        Legend entries ``"<label>, published"`` and ``"<label>, replay"``.

    Returns
    -------
    matplotlib.axes.Axes

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = draw_switch_overlay(Figure().add_subplot(), [True, False, True])
    >>> ax.get_lines()[0].get_xdata().tolist()
    [2, 4]
    """
    pub = np.asarray(published)
    if pub.ndim != 1 or pub.dtype != bool:
        raise ValueError(f"published must be a 1-D array of bool, got {pub.dtype} {pub.shape}")
    rep = None if replay is None else np.asarray(replay)
    if rep is not None and (rep.dtype != bool or rep.shape != pub.shape):
        raise ValueError(f"replay must be bool of shape {pub.shape}, got {rep.dtype} {rep.shape}")
    try:
        y = float(y)
    except (TypeError, ValueError):
        y = np.nan
    if not np.isfinite(y):
        raise ValueError("y must be a finite number")
    lab = (lambda w: None) if label is None else (lambda w: f"{label}, {w}")
    sw = np.flatnonzero(pub) + 2
    ax.plot(sw, np.full(sw.size, float(y)), "|", color=color, ms=9, alpha=0.3,
            label=lab("published"))
    if rep is not None:
        sr = np.flatnonzero(rep) + 2
        ax.plot(sr, np.full(sr.size, float(y)), "|", color=color, ms=4, label=lab("replay"))
    return ax

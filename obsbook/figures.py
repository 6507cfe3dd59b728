"""How the book's figures are drawn and checked: one setup for every notebook, each figure shown
as a PNG that carries the positions and sizes of its texts, and the checks on them.

The rule, for anyone drawing a figure: **at most 7.5 in wide, text at least 10 pt**. The book's
column shows images up to :data:`COLUMN_PX` = 756 px wide (measured in Chromium at a 1400 px
window), and a figure is shown at :data:`DPI` = 100 px per inch, so a figure of 7.5 in (750 px)
is shown at its natural size and its 10 pt text stays 10 pt; a wider figure is scaled down, and
its text with it (an 8.9 in figure is shown at 85 %, so its 10 pt text reads as 8.5 pt).
:func:`setup` makes both the default: figures 7.5 in wide, tick labels and legends 10 pt, axis
labels and titles 11 pt, and the layout found by matplotlib's constrained layout, so that no
figure sets its margins by hand.

Each PNG holds :data:`DENSITY` = 2 image pixels per pixel shown (200 per inch), and says so to
the page (its output's ``width`` is the shown width, as Jupyter's own "retina" figures do): the
figure is sharp on a screen with two or more device pixels per CSS pixel (phones, most laptops),
when a reader zooms in, and in print.
"""

from __future__ import annotations

import base64
import math
from contextlib import contextmanager
from io import BytesIO

__all__ = ["COLUMN_PX", "DPI", "DENSITY", "MIN_PT", "MAX_WIDTH_IN", "RC", "METADATA_KEY", "setup",
           "render", "pack", "unpack", "png_with_texts", "overlaps", "displayed_scale",
           "small_texts", "outside_texts", "problems"]

#: Widest image the book's column shows unscaled (px), measured in Chromium at 1400 px.
COLUMN_PX = 756
#: Size at which the page shows a figure (px per inch): 7.5 in are 750 px.
DPI = 100
#: Image pixels per pixel shown: the PNG is drawn at ``DENSITY * DPI`` = 200 per inch.
DENSITY = 2
#: Smallest text size a reader sees (pt, at the displayed size).
MIN_PT = 10.0
#: Widest figure whose text is shown at its own size (in): ``COLUMN_PX / DPI`` rounded down.
MAX_WIDTH_IN = 7.5
#: Key of the figure's description in the PNG output's metadata.
METADATA_KEY = "obsbook"

#: The figure settings :func:`setup` applies (Okabe and Ito's colours as the colour cycle).
RC = {
    "figure.figsize": (MAX_WIDTH_IN, 4.2),
    "figure.dpi": DPI,
    "savefig.dpi": "figure",
    "figure.constrained_layout.use": True,
    "font.size": 11.0,
    "axes.titlesize": "medium",
    "axes.labelsize": "medium",
    "figure.titlesize": "large",
    "xtick.labelsize": 10.0,
    "ytick.labelsize": 10.0,
    "legend.fontsize": 10.0,
    "legend.title_fontsize": 10.0,
    "axes.titley": 1.0,
    "image.cmap": "viridis",
}


def _rc() -> dict:
    from cycler import cycler

    from obslib.viz.style import GREY, OKABE_ITO

    order = ("blue", "orange", "bluish green", "vermillion", "reddish purple", "sky blue",
             "black")
    return {**RC, "axes.prop_cycle": cycler(color=[OKABE_ITO[c] for c in order] + [GREY])}


def setup() -> None:
    """Draw the notebook's figures the book's way: inline PNG with the description of their
    texts (:func:`png_with_texts`), the settings :data:`RC` (constrained layout, 7.5 in wide,
    text at least 10 pt), and the objects imported so far frozen for the garbage collector.

    - Constrained layout finds every figure's margins at each draw, so no figure sets them by
      hand. It measures every text before the draw: on five of the book's figures (a line
      plot, Fig. 2 with and without its surfaces, six tracking snapshots, the criteria's box
      plots) drawing took 26-51 % longer than with margins written down (10-65 ms a figure),
      and recording the texts for the checks adds 5-12 %. Each figure is still drawn once
      (:func:`render`).
    - ``axes.titley = 1.0``: a title sits just above its axes. Matplotlib's default (``None``)
      lifts it over tick labels on top of the axes, which costs measuring every tick label at
      each draw (about 15 % of the book's drawing time); no 2-D axes of the book has top tick
      labels. 3-D axes keep the default (:func:`obslib.viz.pair_closed_form.plot_fig2`).
    - ``gc.freeze()``: the modules and tables imported so far live as long as the kernel; moved
      to the collector's permanent generation, Python's full collections stop walking them
      (notebook 02: 0.44 s of full collections against 0.14 s frozen). Nothing is computed
      differently; garbage made later is collected as before.

    Outside IPython only the settings apply.

    Examples
    --------
    >>> import matplotlib as mpl
    >>> from obsbook import setup
    >>> with mpl.rc_context():
    ...     setup()
    ...     mpl.rcParams["figure.constrained_layout.use"], mpl.rcParams["figure.figsize"]
    (True, [7.5, 4.2])
    >>> import gc; gc.unfreeze()
    """
    import gc

    import matplotlib as mpl

    mpl.rcParams.update(_rc())
    from IPython import get_ipython

    shell = get_ipython()
    if shell is not None:
        from matplotlib.figure import Figure
        from matplotlib_inline.backend_inline import set_matplotlib_formats

        set_matplotlib_formats("png")  # PNG only: drops the formatters of other formats
        shell.display_formatter.formatters["image/png"].for_type(Figure, png_with_texts)
    gc.freeze()


@contextmanager
def _recording_texts(found: dict, density: float = 1.0):
    """While active, every text drawn is recorded in ``found`` (``id -> entry``, see
    :func:`render`) with its extent as drawn, in pixels shown (the image's pixels over
    ``density``): tick labels outside the view, which matplotlib keeps but does not draw, are
    not, and 3-D labels are taken where they are projected."""
    from matplotlib.text import Text

    original = Text.draw

    def draw(self, renderer):
        original(self, renderer)
        if self.get_visible() and self.get_text().strip():
            found[id(self)] = _entry(self, renderer, density)

    Text.draw = draw
    try:
        yield
    finally:
        Text.draw = original


def _entry(text, renderer, density: float = 1.0) -> dict:
    """Text, size (pt), rotation and extent (px shown, y downwards) of a text being drawn by
    ``renderer``, which draws ``density`` image pixels per pixel shown."""
    from matplotlib.text import Text
    from matplotlib.transforms import IdentityTransform

    height = renderer.height
    box = Text.get_window_extent(text, renderer)  # the text alone, an annotation's arrow aside
    out = {
        "text": text.get_text()[:80],
        "pt": round(float(text.get_fontsize()), 2),
        "angle": round(float(text.get_rotation()) % 360, 1),
        "box": [round(v / density, 1)
                for v in (box.x0, height - box.y1, box.x1, height - box.y0)],
    }
    if abs(math.remainder(out["angle"], 90.0)) > 0.5:
        # the extent is the upright box around the turned text: keep the turned box itself,
        # from the text's size laid out upright, centred where the extent is centred
        upright = Text(0, 0, text.get_text())
        upright.update_from(text)
        upright.set_rotation(0)
        upright.set_transform(IdentityTransform())
        upright.set_figure(text.get_figure(root=True))
        ub = upright.get_window_extent(renderer)
        t = math.radians(text.get_rotation())
        c, s = math.cos(t), math.sin(t)
        cx, cy = (box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2
        w, h = ub.width / 2, ub.height / 2
        out["quad"] = [[round((cx + c * dx - s * dy) / density, 1),
                        round((height - (cy + s * dx + c * dy)) / density, 1)]
                       for dx, dy in ((-w, -h), (w, -h), (w, h), (-w, h))]
    return out


def render(fig, density: float = DENSITY) -> tuple[bytes, dict]:
    """``fig`` drawn once as PNG with ``density`` image pixels per pixel of its size, and its
    description: ``size`` (px shown: the figure's inches times its dpi), ``dpi``, ``density``
    and ``texts``, one entry per visible non-empty text drawn: ``text``, ``pt`` (font size),
    ``angle`` (degrees), ``box`` (its extent ``[left, top, right, bottom]`` in px shown, y
    downwards; the image's pixels over ``density``) and, for text turned by other than a right
    angle, ``quad`` (the four corners of the turned box).

    The Agg canvas prints the PNG itself, so the layout engine runs inside the figure's one
    draw. ``savefig`` (and the inline backend's formatter, even without ``"tight"``) draws a
    figure with a layout engine twice, the first time with drawing switched off only to run
    the engine; the image is the same byte for byte. On the book's 47 figures this takes
    drawing from 13.9 s to 12.8 s. The figure draws at ``density`` times its dpi as ``savefig``
    does with ``dpi=``, and keeps its own dpi afterwards.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> fig = Figure(figsize=(3, 2), dpi=100)
    >>> ax = fig.add_subplot()
    >>> _ = ax.set_xlabel("x")
    >>> png, d = render(fig)
    >>> png[:4], d["size"], d["density"], "x" in [t["text"] for t in d["texts"]]
    (b'\\x89PNG', [300, 200], 2, True)
    >>> fig.dpi == 100
    True
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    if isinstance(density, bool) or not isinstance(density, (int, float)) or not density > 0:
        raise ValueError(f"density must be a positive number, got {density!r}")
    found: dict = {}
    buf = BytesIO()
    canvas = fig.canvas if isinstance(fig.canvas, FigureCanvasAgg) else FigureCanvasAgg(fig)
    dpi = fig.dpi
    size = [int(round(fig.bbox.width)), int(round(fig.bbox.height))]
    fig.dpi = dpi * density
    try:
        with _recording_texts(found, density):
            canvas.print_png(buf)
    finally:
        fig.dpi = dpi
    return buf.getvalue(), {"size": size, "dpi": float(dpi), "density": density,
                            "texts": list(found.values())}


def pack(description: dict) -> dict:
    r""":func:`render`'s description with one line of text per text (the stored notebook puts
    every number of a list on a line of its own): ``"left top right bottom pt angle[ quad]"``,
    a tab, the text. :func:`unpack` reverses it.

    Examples
    --------
    >>> d = {"size": [300, 200], "dpi": 100.0, "texts": [
    ...     {"text": "a b", "pt": 10.0, "angle": 0.0, "box": [1.0, 2.0, 3.5, 4.0]}]}
    >>> pack(d)["texts"] == ["1.0 2.0 3.5 4.0 10.0 0.0\ta b"]
    True
    >>> unpack(pack(d)) == d
    True
    """
    def line(t):
        numbers = [*t["box"], t["pt"], t["angle"], *(v for p in t.get("quad", []) for v in p)]
        return " ".join(map(str, numbers)) + "\t" + t["text"].replace("\t", " ")

    return {**description, "texts": [line(t) for t in description["texts"]]}


def unpack(packed: dict) -> dict:
    """The description :func:`pack` stored (see there)."""
    texts = []
    for entry in packed["texts"]:
        numbers, text = entry.split("\t", 1)
        v = [float(x) for x in numbers.split()]
        t = {"text": text, "pt": v[4], "angle": v[5], "box": v[:4]}
        if len(v) > 6:
            t["quad"] = [v[k:k + 2] for k in range(6, 14, 2)]
        texts.append(t)
    return {**packed, "texts": texts}


def png_with_texts(fig):
    """IPython's PNG formatter of a figure: the base64 PNG of :func:`render` and its output
    metadata: the width at which to show it (px; the image has :data:`DENSITY` times as many
    pixels) and the description of :func:`render` (:func:`pack`-ed) under
    :data:`METADATA_KEY`; None for a figure without axes (as IPython's own formatter).

    Only the width is given: a page that narrows the image keeps its proportions."""
    if not fig.axes and not fig.lines:
        return None
    png, description = render(fig)
    return base64.b64encode(png).decode("ascii"), {"width": description["size"][0],
                                                   METADATA_KEY: pack(description)}


# ------------------------------------------------------------------------------------- checks

def _corners(t: dict):
    if "quad" in t:
        return [tuple(p) for p in t["quad"]]
    x0, y0, x1, y1 = t["box"]
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def _separated(a, b, tol: float) -> bool:
    """Whether convex polygons ``a`` and ``b`` are apart, or overlap by at most ``tol`` px,
    along one of their edges' normals (the separating axis theorem)."""
    for poly in (a, b):
        for (x0, y0), (x1, y1) in zip(poly, poly[1:] + poly[:1]):
            nx, ny = y0 - y1, x1 - x0
            norm = math.hypot(nx, ny)
            if norm == 0:
                continue
            pa = [(x * nx + y * ny) / norm for x, y in a]
            pb = [(x * nx + y * ny) / norm for x, y in b]
            if min(max(pa), max(pb)) - max(min(pa), min(pb)) <= tol:
                return True
    return False


def overlaps(description: dict, tol: float = 0.5) -> list[tuple[str, str]]:
    """Pairs of texts of a figure (:func:`render`'s description) whose boxes overlap by more
    than ``tol`` px; boxes that touch do not count. Turned texts are compared by their turned
    boxes, not by the upright extents around them.

    Examples
    --------
    >>> d = {"texts": [{"text": "a", "box": [0, 0, 10, 10]},
    ...                {"text": "b", "box": [10, 0, 20, 10]},
    ...                {"text": "c", "box": [5, 5, 15, 15]}]}
    >>> overlaps(d)
    [('a', 'c'), ('b', 'c')]
    """
    texts = description["texts"]
    out = []
    for i, a in enumerate(texts):
        ax0, ay0, ax1, ay1 = a["box"]
        for b in texts[i + 1:]:
            bx0, by0, bx1, by1 = b["box"]
            if min(ax1, bx1) - max(ax0, bx0) <= tol or min(ay1, by1) - max(ay0, by0) <= tol:
                continue  # the upright extents hold the texts, so they are apart
            if ("quad" in a or "quad" in b) and _separated(_corners(a), _corners(b), tol):
                continue
            out.append((a["text"], b["text"]))
    return out


def displayed_scale(description: dict, column_px: float = COLUMN_PX) -> float:
    """The factor by which the book's column scales the image: 1 up to ``column_px`` wide."""
    return min(1.0, column_px / description["size"][0])


def small_texts(description: dict, column_px: float = COLUMN_PX,
                min_pt: float = MIN_PT) -> list[tuple[str, float]]:
    """Texts whose size as shown, ``pt`` times :func:`displayed_scale`, is below ``min_pt``:
    ``(text, shown size)`` pairs.

    Examples
    --------
    >>> d = {"size": [890, 400], "texts": [{"text": "a", "pt": 10.0, "box": [0, 0, 9, 9]},
    ...                                    {"text": "b", "pt": 12.0, "box": [0, 0, 9, 9]}]}
    >>> small_texts(d)
    [('a', 8.49)]
    """
    scale = displayed_scale(description, column_px)
    return [(t["text"], round(t["pt"] * scale, 2)) for t in description["texts"]
            if t["pt"] * scale < min_pt - 1e-9]


def outside_texts(description: dict, tol: float = 0.5) -> list[str]:
    """Texts that reach beyond the image by more than ``tol`` px (cut off in the PNG)."""
    w, h = description["size"]
    return [t["text"] for t in description["texts"]
            if min(x for x, _ in _corners(t)) < -tol or min(y for _, y in _corners(t)) < -tol
            or max(x for x, _ in _corners(t)) > w + tol or max(y for _, y in _corners(t)) > h + tol]


def problems(description: dict, column_px: float = COLUMN_PX, min_pt: float = MIN_PT) -> list[str]:
    """Every defect of a figure's text, one sentence each: overlapping texts, texts shown
    smaller than ``min_pt``, texts cut off at the image's edge. Empty for a clean figure.

    Examples
    --------
    >>> d = {"size": [700, 400], "texts": [{"text": "a", "pt": 10, "box": [0, 0, 10, 10]},
    ...                                    {"text": "b", "pt": 9, "box": [5, 5, 15, 15]}]}
    >>> for p in problems(d):
    ...     print(p)
    'a' overlaps 'b'
    'b' is shown at 9 pt (at least 10 pt)
    """
    out = [f"{a!r} overlaps {b!r}" for a, b in overlaps(description)]
    out += [f"{t!r} is shown at {pt:g} pt (at least {min_pt:g} pt)"
            for t, pt in small_texts(description, column_px, min_pt)]
    out += [f"{t!r} is cut off at the edge of the image" for t in outside_texts(description)]
    return out

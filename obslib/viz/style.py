"""One look (colour, marker, line style, legend label) for each algorithm, strategy and kind of
object the book draws, so that a name looks the same in every figure.

The colours are Okabe and Ito's palette for colour-blind readers (:data:`OKABE_ITO`, without its
yellow, too pale for lines on white) and one grey. Eight colours cannot give every name its own,
so a colour is shared only by names that never meet in one figure, and then the marker differs:
no two names share both colour and marker.

=====================  ===========================================================================
group                  names
=====================  ===========================================================================
pair assignment        ``greedy`` (Algorithm 1), ``literal`` (its round-by-round pseudo-code),
                       ``relaxed`` (matching, Problem 3), ``optimal`` (exact), ``one-pass``
                       (every weight once), ``random``
tracking strategies    ``best-pair``, ``best-partner``, ``fixed-pair``, ``d-optimal``,
                       ``a-optimal``, ``e-optimal``, ``exact-icn``, ``random``
many targets           the assignments of :data:`obslib.tracking.ASSIGNMENTS`: pairs drawn
                       with squares, teams with circles (crosses where their greedy degenerates)
team measures          ``trace``, ``logdet`` (as ``d-optimal``), ``rank``, ``trace_inverse``
                       and ``neg_trace_inverse`` (as ``a-optimal``), the names of
                       :data:`obslib.measures.MEASURES`
objects on a map       ``sensor``, ``target``, ``truth`` (the true path), ``estimate``,
                       ``ellipse`` (its 99.73 % covariance ellipse), ``chosen-pair`` (lines from
                       the chosen sensors), ``maximum`` (a grid maximum), ``start``
kinds of curve         ``bound`` (dashed) against ``exact`` (solid), with the colour of whatever
                       they belong to; ``published`` (wide, pale) under ``replay`` (thin)
=====================  ===========================================================================

The greedy family is blue (the bound's best pair is the greedy choice for one target), exact
computations are black, random choices grey. Surfaces and contours use ``viridis``
(:data:`SEQUENTIAL`), which reads in grey and for colour-blind readers.
"""

from __future__ import annotations

from dataclasses import dataclass

from .._validate import as_int

__all__ = ["OKABE_ITO", "GREY", "SEQUENTIAL", "Look", "LOOKS", "look", "PUBLISHED_STYLE",
           "REPLAY_STYLE", "sensor_label", "pair_label", "target_label", "as_axes", "as_figsize"]

#: Okabe and Ito's colours (https://jfly.uni-koeln.de/color/), by their names.
OKABE_ITO = {
    "black": "#000000",
    "orange": "#E69F00",
    "sky blue": "#56B4E9",
    "bluish green": "#009E73",
    "yellow": "#F0E442",
    "blue": "#0072B2",
    "vermillion": "#D55E00",
    "reddish purple": "#CC79A7",
}
#: The neutral grey of random choices and of true paths.
GREY = "#7F7F7F"
#: Colour map of surfaces and contours.
SEQUENTIAL = "viridis"

_C = OKABE_ITO


@dataclass(frozen=True)
class Look:
    """How one name is drawn: ``color`` (None: the caller's), ``marker`` ('' for none),
    ``linestyle`` and the legend ``label``.

    Examples
    --------
    >>> from obslib.viz.style import look
    >>> kw = look("greedy").kw(ms=4)
    >>> kw["color"], kw["marker"], kw["label"], kw["ms"]
    ('#0072B2', 'o', 'greedy (Algorithm 1)', 4)
    >>> look("bound").kw(color="C0", label=None)["linestyle"]
    '--'
    """

    color: str | None
    marker: str = ""
    linestyle: str = "-"
    label: str = ""

    def kw(self, **override) -> dict:
        """Keyword arguments of ``Axes.plot`` for this look, updated by ``override``; entries
        that are None or empty are left out (matplotlib's defaults then apply)."""
        out = {"color": self.color, "marker": self.marker, "linestyle": self.linestyle,
               "label": self.label}
        out.update(override)
        return {k: v for k, v in out.items() if v is not None and v != ""}


#: Every name's look (see the module docstring for the groups).
LOOKS = {
    # pair assignment (Section IV)
    "greedy": Look(_C["blue"], "o", "-", "greedy (Algorithm 1)"),
    "literal": Look(_C["sky blue"], "s", "--", "literal Algorithm 1"),
    "relaxed": Look(_C["vermillion"], "^", "-", "relaxed matching (Problem 3)"),
    "optimal": Look(_C["black"], "D", "-", "exact optimum"),
    "one-pass": Look(GREY, "", ":", "one pass over all weights"),
    "random": Look(GREY, "x", "-", "random"),
    # tracking strategies (Section V and beyond)
    "best-pair": Look(_C["blue"], "o", "-", "best pair"),
    "best-partner": Look(_C["orange"], "v", "-", "best partner"),
    "fixed-pair": Look(_C["bluish green"], "s", "-", "fixed pair"),
    "d-optimal": Look(_C["reddish purple"], "D", "-", "D-optimal"),
    "a-optimal": Look(_C["sky blue"], "^", "-", "A-optimal"),
    "e-optimal": Look(_C["vermillion"], "P", "-", "E-optimal"),
    "exact-icn": Look(_C["black"], "h", "-", "exact C\u207b\u00b9"),
    # assignments of many targets in closed loop (the later experiment; "random" is above)
    "unique-pairs": Look(_C["blue"], "s", "-", "unique pairs (Algorithm 1)"),
    "d-optimal-pairs": Look(_C["reddish purple"], "s", "-", "D-optimal pairs"),
    "optimal-pairs": Look(_C["black"], "s", "-", "optimal pairs (Problem 1)"),
    "logdet-teams": Look(_C["orange"], "o", "-", "log-det teams, code's rounding"),
    "logdet-teams-as-run": Look(_C["orange"], "X", "-", "log-det teams as run"),
    "logdet-teams-exact": Look(_C["black"], "X", "-", "log-det teams, exact"),
    "logdet-teams-prior": Look(_C["bluish green"], "D", "-", "log-det teams with prior"),
    "d-optimal-teams": Look(_C["reddish purple"], "o", "-", "D-optimal teams"),
    "a-optimal-teams": Look(_C["sky blue"], "o", "-", "A-optimal teams"),
    "e-optimal-teams": Look(_C["vermillion"], "o", "-", "E-optimal teams"),
    # team measures of Theorem 8
    "trace": Look(_C["orange"], "<", "-", "trace"),
    "rank": Look(_C["bluish green"], ">", "-", "rank"),
    # objects on a map
    "sensor": Look("#404040", "^", "none", "sensors"),
    "target": Look(_C["black"], "*", "none", "target"),
    "truth": Look(GREY, "", "-", "true path"),
    "estimate": Look(_C["vermillion"], "x", "none", "estimate"),
    "ellipse": Look(_C["vermillion"], "", "-", "99.73 % ellipse"),
    "chosen-pair": Look(_C["bluish green"], "", "-", "chosen pair"),
    "maximum": Look(_C["vermillion"], "*", "none", "maximum"),
    "start": Look(_C["bluish green"], "o", "none", "start"),
    # kinds of curve
    "bound": Look(None, "", "--", "lower bound"),
    "exact": Look(None, "", "-", "exact"),
}
_ALIASES = {"logdet": "d-optimal", "trace_inverse": "a-optimal", "neg_trace_inverse": "a-optimal"}


def look(name: str) -> Look:
    """The :class:`Look` of ``name``: a key of :data:`LOOKS`, or a measure that a criterion
    optimises (``logdet``: ``d-optimal``; ``trace_inverse``, ``neg_trace_inverse``:
    ``a-optimal``).

    Examples
    --------
    >>> from obslib.viz.style import look
    >>> look("logdet") == look("d-optimal"), look("best-pair").color
    (True, '#0072B2')
    """
    key = _ALIASES.get(name, name) if isinstance(name, str) else None
    if key not in LOOKS:
        raise ValueError(f"name: no look for {name!r}; known: {', '.join([*LOOKS, *_ALIASES])}")
    return LOOKS[key]


#: The published log: a wide, pale line (or large open markers) that the replay is drawn over.
PUBLISHED_STYLE = {"lw": 4.0, "alpha": 0.3, "solid_capstyle": "round"}
#: The replay with the published noise: a thin line (or small dots) of the same colour on top.
REPLAY_STYLE = {"lw": 1.0}


_SUBSCRIPT = str.maketrans("0123456789", "".join(chr(0x2080 + d) for d in range(10)))


def sensor_label(i: int) -> str:
    """``"s"`` with the 1-based index of sensor ``i`` (0-based) as Unicode subscript digits:
    the figures' sensor names, plain text (no mathtext to parse).

    Examples
    --------
    >>> from obslib.viz.style import sensor_label
    >>> sensor_label(0), sensor_label(11)
    ('s₁', 's₁₂')
    """
    return "s" + str(as_int(i, "i", 0) + 1).translate(_SUBSCRIPT)


def pair_label(i: int, j: int) -> str:
    """The pair of sensors ``i``, ``j`` (0-based) as the figures and tables name it, in plain
    text with the names of :func:`sensor_label`.

    Examples
    --------
    >>> pair_label(1, 0), pair_label(0, 11)
    ('(s₂, s₁)', '(s₁, s₁₂)')
    """
    return f"({sensor_label(i)}, {sensor_label(j)})"


def target_label(l: int) -> str:
    """``"t"`` with the 1-based index of target ``l`` (0-based) as Unicode subscript digits, as
    :func:`sensor_label` names sensors.

    Examples
    --------
    >>> target_label(0)
    't₁'
    """
    return "t" + str(as_int(l, "l", 0) + 1).translate(_SUBSCRIPT)


def as_axes(ax, name: str = "ax"):
    """``ax`` if it is a matplotlib ``Axes``, else a ValueError naming ``name``.

    Examples
    --------
    >>> as_axes(None)
    Traceback (most recent call last):
    ...
    ValueError: ax must be a matplotlib Axes, got NoneType
    """
    from matplotlib.axes import Axes

    if not isinstance(ax, Axes):
        raise ValueError(f"{name} must be a matplotlib Axes, got {type(ax).__name__}")
    return ax


def as_figsize(figsize) -> tuple:
    """A figure size ``(width, height)`` in inches, both finite and positive.

    Examples
    --------
    >>> as_figsize([7.5, 3])
    (7.5, 3.0)
    """
    from .._validate import as_positive

    if isinstance(figsize, (str, bytes)) or not isinstance(figsize, (tuple, list)) or len(
            figsize) != 2:
        raise ValueError(f"figsize must be (width, height) in inches, got {figsize!r}")
    return tuple(as_positive(v, "figsize") for v in figsize)

"""How the prose names the paper's objects: sensors, pairs, teams, points and shares, written
the same way on every page.

Sensors and targets are numbered from 1 on the page, as in the paper, and from 0 in the code:
sensor ``i`` is :math:`s_{i+1}`. The names are MyST math (``$s_{1}$``) for the prose and the
tables; the figures name them in plain text with :func:`obslib.viz.style.sensor_label`.
"""

from __future__ import annotations

from obslib.formatting import number, percent, setting

__all__ = ["PUBLISHED_RUNS", "sensor_math", "pair_math", "triple_math", "set_math", "point",
           "share"]

#: How the prose names the published runs the authors saved (the names of
#: :data:`obslib.published_runs.RUN_NAMES` it refers to).
PUBLISHED_RUNS = {"best-pair": "strategy (1), Figs. 4-6",
                  "adversarial": "the adversarial run, Fig. 7"}


def sensor_math(i: int) -> str:
    """Sensor ``i`` (0-based) as the prose names it.

    Parameters
    ----------
    i : int
        The sensor's index, from 0.

    Returns
    -------
    str
        ``$s_{i+1}$``.

    Examples
    --------
    >>> sensor_math(0)
    '$s_{1}$'
    """
    return f"$s_{{{i + 1}}}$"


def pair_math(i: int, j: int) -> str:
    """The pair of sensors ``i, j`` (0-based) in one formula.

    Examples
    --------
    >>> pair_math(0, 3)
    '$s_{1}, s_{4}$'
    """
    return f"$s_{{{i + 1}}}, s_{{{j + 1}}}$"


def triple_math(triple) -> str:
    """A triple ``(i, j, l)`` of an assignment: the pair of sensors ``i, j`` for target ``l``.

    Examples
    --------
    >>> triple_math((0, 3, 1))
    '$s_{1}, s_{4}$ for $t_{2}$'
    """
    i, j, l = triple
    return f"{pair_math(i, j)} for $t_{{{l + 1}}}$"


def set_math(idx) -> str:
    """The set of sensors ``idx`` (0-based indices) as the paper writes it.

    Examples
    --------
    >>> set_math((0, 2))
    '$\\\\{s_{1}, s_{3}\\\\}$'
    """
    return "$\\{" + ", ".join(f"s_{{{i + 1}}}" for i in idx) + "\\}$"


def point(x, sig: int | None = None) -> str:
    """A point ``(x, y)`` as the prose writes it.

    Parameters
    ----------
    x : array_like
        The point's two coordinates.
    sig : int, optional
        Significant digits (:func:`obslib.formatting.number`); by default each coordinate is
        written as a setting (:func:`obslib.formatting.setting`), with the digits it has.

    Examples
    --------
    >>> point([3.0, 0.25]), point([1.23456, 2.5], 2)
    ('(3, 0.25)', '(1.2, 2.5)')
    """
    f = setting if sig is None else (lambda v: number(v, sig))
    return f"({f(float(x[0]))}, {f(float(x[1]))})"


def share(frac: float, total: int, noun: str) -> str:
    """A share of ``total`` things in words.

    Parameters
    ----------
    frac : float
        The share, from 0 to 1.
    total : int
        How many things there are.
    noun : str
        What they are, in the plural.

    Examples
    --------
    >>> share(1.0, 314, "steps"), share(0.0, 200, "runs"), share(0.939, 200, "runs")
    ('all 314 steps', 'none of the 200 runs', '93.9% of the runs')
    """
    if frac == 1:
        return f"all {number(total)} {noun}"
    if frac == 0:
        return f"none of the {number(total)} {noun}"
    return f"{percent(frac)} of the {noun}"

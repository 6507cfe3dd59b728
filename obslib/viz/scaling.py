"""Figures of how the assignment algorithms scale: the ceiling on a pair's bound, the pair bounds
each algorithm evaluates, and the measured wall times.
"""

from __future__ import annotations

from .._validate import as_mapping, as_real
from ._checks import as_series
from .style import GREY, look

__all__ = ["ALGORITHM_STYLES", "plot_pair_ceiling", "plot_work", "plot_wall_time"]

#: One look per algorithm of the scaling study, the same as on every page of the book.
ALGORITHM_STYLES = {
    "greedy (geometry)": look("greedy").kw(),
    "greedy (from W)": look("greedy").kw(linestyle="--", mfc="white",
                                         label="greedy (Algorithm 1), from the full weight table"),
    "literal Algorithm 1": look("literal").kw(),
    "relaxed matching": look("relaxed").kw(),
    "exact optimum": look("optimal").kw(),
    "one pass": look("one-pass").kw(),
}


def plot_pair_ceiling(ratio, bound, tenth: float):
    r"""Every pair's bound :math:`\omega(s_i, s_j, t)` for one target against the ratio of the
    pair's nearer to farther distance, its ceiling, and the target's ``tenth``-best bound: the
    pairs left of it cannot be among the ten best.

    Examples
    --------
    >>> fig = plot_pair_ceiling([0.2, 0.9], [0.1, 0.8], tenth=0.5)
    >>> fig.axes[0].get_ylabel()
    'bound $\\omega(s_i, s_j, t)$'
    """
    import matplotlib.pyplot as plt

    ratio = as_series(ratio, "ratio")
    bound = as_series(bound, "bound", ratio.size)
    tenth = as_real(tenth, "tenth")
    fig, ax = plt.subplots(figsize=(7.5, 3.8))
    ax.axvspan(0, tenth, color=GREY, alpha=0.15, lw=0, label="cannot be among the ten best")
    ax.plot(ratio, bound, ".", ms=2, alpha=0.4, color=look("greedy").color,
            label="a pair of sensors")
    ax.plot([0, 1], [0, 1], "k-", lw=1, label="ceiling: the ratio of the two distances")
    ax.axhline(tenth, color="k", ls=":", lw=1, label="the target's tenth-best bound")
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1.02)
    ax.set_xlabel("nearer over farther distance of the pair's sensors to the target")
    ax.set_ylabel("bound $\\omega(s_i, s_j, t)$")
    ax.legend(loc="upper left", markerscale=4)
    return fig


def _series_by_name(data, name: str, x: str, y: str, known_only: bool = True) -> dict:
    """``{algorithm: (x values, y values)}`` of equal lengths (``known_only``: for the
    algorithms of :data:`ALGORITHM_STYLES` only)."""
    out = {}
    for key, value in as_mapping(data, name).items():
        if not isinstance(key, str) or (known_only and key not in ALGORITHM_STYLES):
            raise ValueError(f"{name}: unknown algorithm {key!r}; known: {tuple(ALGORITHM_STYLES)}")
        pair = (value[x], value[y]) if isinstance(value, dict) else value
        if not isinstance(pair, (tuple, list)) or len(pair) != 2:
            raise ValueError(f"{name}[{key!r}] must be ({x}, {y})")
        xs = as_series(pair[0], name)
        out[key] = (xs, as_series(pair[1], name, xs.size))
    return out


def plot_work(counts: dict):
    """The pair bounds each algorithm evaluates against the number of sensors (log-log), from
    :func:`obslib.tools.bench.evaluation_counts` (``{algorithm: (N, counts)}``), for the literal
    Algorithm 1, one pass over all weights, the relaxed matching and the greedy.

    Examples
    --------
    >>> names = ("literal Algorithm 1", "one pass", "relaxed matching",
    ...          "greedy (geometry)")
    >>> counts = {k: ([10, 20], [100, 1000]) for k in names}
    >>> plot_work(counts).axes[0].get_ylabel()
    'pair bounds evaluated'
    """
    import matplotlib.pyplot as plt

    counts = _series_by_name(counts, "counts", "N", "count")
    drawn = ("literal Algorithm 1", "one pass", "relaxed matching", "greedy (geometry)")
    missing = [k for k in drawn if k not in counts]
    if missing:
        raise ValueError(f"counts lacks {missing}")
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    for name in drawn:
        n, c = counts[name]
        ax.loglog(n, c, **ALGORITHM_STYLES[name])
    ax.set_xlabel("sensors $N$ ($L = N/2$ targets)")
    ax.set_ylabel("pair bounds evaluated")
    sizes = counts["one pass"][0].astype(int)
    ax.minorticks_off()
    ax.set_xticks(sizes, [str(n) for n in sizes])
    ax.legend(loc="upper left")
    return fig


def plot_wall_time(times: dict):
    """The measured wall times against the number of sensors (log-log), one curve per algorithm
    (``times``: ``{algorithm: {"N": ..., "seconds": ...}}``, the ``"times"`` of
    ``book/data/scaling_times.json``); an algorithm without a look of
    :data:`ALGORITHM_STYLES` is drawn with circles.

    Examples
    --------
    >>> times = {"greedy (geometry)": {"N": [10, 100], "seconds": [0.01, 0.2]}}
    >>> plot_wall_time(times).axes[0].get_ylabel()
    'wall time (s), best of repeats'
    """
    import matplotlib.pyplot as plt

    times = _series_by_name(times, "times", "N", "seconds", known_only=False)
    fig, ax = plt.subplots(figsize=(7.5, 4.2))
    for name, (n, t) in times.items():
        ax.loglog(n, t, **ALGORITHM_STYLES.get(name, {"marker": "o", "label": name}))
    ax.set_xlabel("sensors $N$ ($L = N/2$ targets)")
    ax.set_ylabel("wall time (s), best of repeats")
    fig.legend(loc="outside lower center", ncols=2)
    return fig

"""Figures of notebook 10: the bound against the classical criteria in the tracking runs."""

from __future__ import annotations

import numpy as np

from .._validate import as_float_array, as_mapping, as_names, as_sequence, as_str
from .style import GREY, LOOKS, as_axes, as_figsize

__all__ = ["LABELS", "draw_boxes", "plot_run_errors"]

#: Axis labels of the strategies.
LABELS = {
    "best-pair": "bound\n(best pair)",
    "best-partner": "best\npartner",
    "fixed-pair": "fixed\npair",
    "d-optimal": "D-opt",
    "a-optimal": "A-opt",
    "e-optimal": "E-opt",
    "exact-icn": "exact\nC$^{-1}$",
    "random": "random",
}


def draw_boxes(ax, data, names, labels=None, looks=None):
    """Box plots of ``data`` (one array per name of ``names``) on a log axis: whiskers at the
    5th and 95th percentiles, each box filled in the colour of its name's look
    (:mod:`obslib.viz.style`; ``looks`` maps a name to the look's name where they differ), the
    x ticks named by ``labels`` (default: the names). Returns the axes.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = Figure().add_subplot()
    >>> ax = draw_boxes(ax, [[1.0, 2.0], [2.0, 4.0]], ["best-pair", "random"],
    ...                 labels={"best-pair": "bound"})
    >>> [t.get_text() for t in ax.get_xticklabels()], ax.get_yscale()
    (['bound', 'random'], 'log')
    """
    from matplotlib.colors import to_rgba
    from matplotlib.ticker import FormatStrFormatter, LogLocator

    as_axes(ax)
    names = as_names(names, "names")
    labels = {} if labels is None else as_mapping(labels, "labels")
    looks = {} if looks is None else as_mapping(looks, "looks")
    data = as_sequence(data, "data")
    if len(data) != len(names):
        raise ValueError(f"data has {len(data)} series for {len(names)} names")
    data = [as_float_array(d, "data") for d in data]
    if any(d.ndim != 1 or not np.isfinite(d).all() for d in data):
        raise ValueError("data must be finite 1-D series")
    parts = ax.boxplot(data, whis=(5, 95), patch_artist=True, flierprops={"ms": 2},
                       medianprops={"color": "k"})
    for box, flier, name in zip(parts["boxes"], parts["fliers"], names):
        key = looks.get(name, name)
        color = LOOKS[key].color if key in LOOKS else GREY
        box.set_facecolor(to_rgba(color, 0.45))
        box.set_edgecolor(color)
        flier.set_markeredgecolor(color)
    ax.set_xticks(np.arange(1, len(names) + 1), [labels.get(n, n) for n in names])
    ax.set_yscale("log")
    ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
    ax.yaxis.set_minor_locator(LogLocator(subs=(2.0, 5.0)))
    ax.yaxis.set_minor_formatter(FormatStrFormatter("%g"))
    ax.grid(axis="y", alpha=0.3)
    return ax


def plot_run_errors(study: dict, metric: str = "mahalanobis", figsize=(7.5, 6.0)):
    """Box plots of the per-run mean error (steps 2..) of every strategy, one row per setting.

    ``study`` is :func:`obslib.studies.criteria.tracking_study`'s result. Returns the figure
    (constrained layout). A box spans the middle half of the runs, its line is the median, the
    whiskers reach the 5th and 95th percentiles, and dots are the runs beyond them.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")  # no window
    >>> import matplotlib.pyplot as plt
    >>> from obslib import tracking
    >>> from obslib.viz.criteria import plot_run_errors
    >>> setup = tracking.PAPER_CIRCLE.replace(steps=10)
    >>> mc = {s: tracking.simulate_batch(setup, s, seeds=[0, 1])
    ...       for s in ("best-pair", "random")}
    >>> fig = plot_run_errors({("circle", "mahalanobis"): mc})
    >>> len(fig.axes)
    1
    >>> plt.close(fig)
    """
    import matplotlib.pyplot as plt

    study = as_mapping(study, "study")
    as_str(metric, "metric")
    figsize = as_figsize(figsize)
    settings = [s for s in ("circle", "adversary") if (s, metric) in study]
    if not settings:
        raise ValueError(f"the study has no runs with metric {metric!r}")
    fig, axes = plt.subplots(len(settings), 1, figsize=figsize, squeeze=False,
                             layout="constrained")
    titles = {"circle": "circle (Sec. V-A)", "adversary": "adversary (Sec. V-B)"}
    for ax, setting in zip(axes[:, 0], settings):
        mc = study[(setting, metric)]
        names = list(mc)
        draw_boxes(ax, [mc[n].error[:, 1:].mean(axis=1) for n in names], names, LABELS)
        ax.set_ylabel("per-run mean error\n(length units)")
        ax.set_title(f"{titles[setting]}, {metric}")
    return fig

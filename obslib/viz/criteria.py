"""Figures of the chapter on the criteria: what the filter already knows (two pairs and the
ellipses they leave), and the bound against the classical criteria in the tracking runs."""

from __future__ import annotations

import numpy as np

from .._validate import as_float_array, as_mapping, as_names, as_sequence, as_str
from .style import GREY, LOOKS, as_axes, as_figsize, look
from .tracking import cov_ellipse

__all__ = ["LABELS", "plot_criteria_intuition", "draw_boxes", "plot_run_errors"]

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


def _matrix(m, name: str) -> np.ndarray:
    """A finite 2 x 2 matrix."""
    m = as_float_array(m, name)
    if m.shape != (2, 2) or not np.isfinite(m).all():
        raise ValueError(f"{name} must be a finite 2 x 2 matrix, got shape {m.shape}")
    return m


def plot_criteria_intuition(pairs, prior, after):
    """What the filter already knows: the two candidate pairs ``A`` and ``B`` seen from the
    estimate at the origin (``pairs``: name -> the pair's two sensors), and the filter's
    covariance ellipse (:math:`\\chi^2 = 1`) before the update (``prior``) and after the update
    with each pair (``after``: name -> covariance).

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> pairs = {"A": [[-2.0, 0.0], [0.0, -2.0]], "B": [[-1.0, -1.9], [1.0, -1.9]]}
    >>> after = {"A": 0.1 * np.eye(2), "B": 0.2 * np.eye(2)}
    >>> fig = plot_criteria_intuition(pairs, np.diag([0.1, 2.0]), after)
    >>> [ax.get_title() for ax in fig.axes]
    ['the two pairs', "the filter's ellipse"]
    >>> plt.close("all")
    """
    import matplotlib.pyplot as plt

    pairs = {k: as_float_array(v, "pairs") for k, v in as_mapping(pairs, "pairs").items()}
    if set(pairs) != {"A", "B"} or any(v.shape != (2, 2) or not np.isfinite(v).all()
                                       for v in pairs.values()):
        raise ValueError("pairs must map A and B to two finite sensor positions each")
    prior = _matrix(prior, "prior")
    after = {k: _matrix(v, "after") for k, v in as_mapping(after, "after").items()}
    if set(after) != set(pairs):
        raise ValueError("after must hold a covariance for A and for B")
    fig, (geo, ell) = plt.subplots(1, 2, figsize=(7.5, 3.6))
    colour = {"A": look("best-pair").color, "B": look("d-optimal").color}
    name = {"A": "pair A (the bound's choice)", "B": "pair B (D, A and E's choice)"}
    for k, P in pairs.items():
        for p in P:
            geo.plot([0, p[0]], [0, p[1]], color=colour[k], lw=1)
        geo.plot(P[:, 0], P[:, 1], "^", color=colour[k], ms=9, label=name[k])
    geo.plot(0, 0, **look("target").kw(ms=12, label="estimate"))
    geo.set_xlim(-2.6, 1.2)
    geo.set_ylim(-2.4, 1.0)
    geo.legend(loc="upper left")
    geo.set_title("the two pairs")
    ell.plot(*cov_ellipse([0, 0], prior, chi2=1.0).T, color=GREY, ls="--", label="before")
    for k in pairs:
        ell.plot(*cov_ellipse([0, 0], after[k], chi2=1.0).T, color=colour[k],
                 label=f"after pair {k}")
    ell.set_xlim(-2.0, 2.0)
    ell.set_ylim(-1.6, 1.6)
    ell.legend(loc="lower right")
    ell.set_title("the filter's ellipse")
    for ax in (geo, ell):
        ax.set_aspect("equal")
        ax.set_xlabel("x (length units)")
    geo.set_ylabel("y (length units)")
    return fig


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

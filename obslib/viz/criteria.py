"""Figures of notebook 10: the bound against the classical criteria in the tracking runs."""

from __future__ import annotations

import numpy as np

__all__ = ["LABELS", "plot_run_errors"]

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


def plot_run_errors(study: dict, metric: str = "mahalanobis", figsize=(8.5, 5.6)):
    """Box plots of the per-run mean error (steps 2..) of every strategy, one row per setting.

    ``study`` is :func:`obslib.studies.criteria.tracking_study`'s result. Returns the figure.

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
    from matplotlib.ticker import FormatStrFormatter, LogLocator

    settings = [s for s in ("circle", "adversary") if (s, metric) in study]
    if not settings:
        raise ValueError(f"the study has no runs with metric {metric!r}")
    fig, axes = plt.subplots(len(settings), 1, figsize=figsize, squeeze=False)
    titles = {"circle": "circle (Sec. V-A)", "adversary": "adversary (Sec. V-B)"}
    for ax, setting in zip(axes[:, 0], settings):
        mc = study[(setting, metric)]
        names = list(mc)
        data = [mc[n].error[:, 1:].mean(axis=1) for n in names]
        ax.boxplot(data, whis=(5, 95), showfliers=True, flierprops={"ms": 2},
                   medianprops={"color": "C3"})
        ax.set_xticks(np.arange(1, len(names) + 1), [LABELS.get(n, n) for n in names], fontsize=9)
        ax.set_ylabel("per-run mean error\n(length units)")
        ax.set_yscale("log")
        ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
        ax.yaxis.set_minor_locator(LogLocator(subs=(2.0, 5.0)))
        ax.yaxis.set_minor_formatter(FormatStrFormatter("%g"))
        ax.tick_params(axis="y", which="minor", labelsize=9)
        ax.set_title(f"{titles[setting]}, {metric}", fontsize=10)
        ax.grid(axis="y", alpha=0.3)
    fig.subplots_adjust(left=0.1, right=0.99, bottom=0.1, top=0.95, hspace=0.55)
    return fig

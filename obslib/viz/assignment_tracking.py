"""Figures of the assignment-by-tracking experiment (notebook 10)."""

from __future__ import annotations

import numpy as np

__all__ = ["plot_assignment_errors"]

LABELS = {"bound": "bound\n(Algorithm 1)", "d-optimal": "D-optimal\n(greedy)", "random": "random"}


def plot_assignment_errors(runs: dict, figsize=(8.5, 3.4)):
    """Per ``L`` (one panel each), box plots over runs of the mean error summed over targets
    after each update, per assignment rule. ``runs`` is
    :func:`obslib.studies.criteria.assignment_study`'s result. Returns the figure.

    Examples
    --------
    Any object with ``run_mean_error()`` and ``setup.n_sensors`` stands for a rule's runs:

    >>> import matplotlib
    >>> matplotlib.use("Agg")  # no window
    >>> import matplotlib.pyplot as plt
    >>> from types import SimpleNamespace
    >>> import numpy as np
    >>> from obslib.viz.assignment_tracking import plot_assignment_errors
    >>> def runs_of(errors, n):
    ...     return SimpleNamespace(run_mean_error=lambda: np.asarray(errors),
    ...                            setup=SimpleNamespace(n_sensors=n))
    >>> runs = {L: {"bound": runs_of([1.0, 2.0], 2 * L),
    ...             "random": runs_of([2.0, 3.0], 2 * L)} for L in (2, 3)}
    >>> fig = plot_assignment_errors(runs)
    >>> [ax.get_title() for ax in fig.axes]
    ['L = 2 targets, N = 4 sensors', 'L = 3 targets, N = 6 sensors']
    >>> plt.close(fig)
    """
    import matplotlib.pyplot as plt
    from matplotlib.ticker import FormatStrFormatter, LogLocator

    if not runs:
        raise ValueError("no assignment runs to plot")
    Ls = list(runs)
    fig, axes = plt.subplots(1, len(Ls), figsize=figsize, squeeze=False)
    for ax, L in zip(axes[0], Ls):
        rules = list(runs[L])
        data = [runs[L][r].run_mean_error() for r in rules]
        ax.boxplot(data, whis=(5, 95), flierprops={"ms": 2}, medianprops={"color": "C3"})
        ax.set_xticks(np.arange(1, len(rules) + 1), [LABELS.get(r, r) for r in rules], fontsize=9)
        ax.set_yscale("log")
        ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
        ax.yaxis.set_minor_locator(LogLocator(subs=(2.0, 5.0)))
        ax.yaxis.set_minor_formatter(FormatStrFormatter("%g"))
        ax.tick_params(axis="y", which="minor", labelsize=9)
        n = runs[L][rules[0]].setup.n_sensors
        ax.set_title(f"L = {L} targets, N = {n} sensors", fontsize=10)
        ax.grid(axis="y", alpha=0.3)
    axes[0, 0].set_ylabel("error summed over targets\n(length units)")
    fig.subplots_adjust(left=0.1, right=0.99, bottom=0.2, top=0.9, wspace=0.22)
    return fig

"""Figures of the assignment-by-tracking experiment (notebook 10)."""

from __future__ import annotations

from .._validate import as_mapping
from .criteria import draw_boxes
from .style import as_figsize

__all__ = ["plot_assignment_errors"]

LABELS = {"bound": "bound\n(Algorithm 1)", "d-optimal": "D-optimal\n(greedy)", "random": "random"}
#: The looks (obslib.viz.style) of the rules: the bound's rule is Algorithm 1, the greedy.
LOOKS = {"bound": "greedy"}


def plot_assignment_errors(runs: dict, figsize=(7.5, 3.6)):
    """Per ``L`` (one panel each), box plots over runs of the mean error summed over targets
    after each update, per assignment rule (as :func:`obslib.viz.criteria.plot_run_errors`).
    ``runs`` is :func:`obslib.studies.criteria.assignment_study`'s result. Returns the figure
    (constrained layout).

    Examples
    --------
    Any object with ``run_mean_error()`` and ``setup.n_sensors`` stands for a rule's runs:

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

    runs = as_mapping(runs, "runs")
    for by_rule in runs.values():
        if not as_mapping(by_rule, "runs") or not all(
                hasattr(r, "run_mean_error") for r in by_rule.values()):
            raise ValueError("runs must map L to {rule: AssignmentRuns} (assignment_study)")
    figsize = as_figsize(figsize)
    if not runs:
        raise ValueError("no assignment runs to plot")
    Ls = list(runs)
    fig, axes = plt.subplots(1, len(Ls), figsize=figsize, squeeze=False, layout="constrained")
    for ax, L in zip(axes[0], Ls):
        rules = list(runs[L])
        draw_boxes(ax, [runs[L][r].run_mean_error() for r in rules], rules, LABELS, LOOKS)
        n = runs[L][rules[0]].setup.n_sensors
        ax.set_title(f"L = {L} targets, N = {n} sensors")
    axes[0, 0].set_ylabel("error summed over targets\n(length units)")
    return fig
